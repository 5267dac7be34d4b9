//! Building blocks for generating initial particle packings: radius distributions,
//! 3D ballistic deposition by steepest descent, its 2D form for cylinders in a box,
//! and measurements on the result.
//! See docs/generation.md.

pub mod ballistic;
pub mod ballistic_2d;
pub mod distribution;
pub mod grid;
pub mod measure;
pub mod pour;
pub mod rsi;

use crate::particles::Vec3;
use rand::RngExt;
use rand_chacha::ChaCha8Rng;

/// A direction drawn uniformly on the unit sphere (rejection from the cube).
pub fn random_unit(rng: &mut ChaCha8Rng) -> Vec3 {
    loop {
        let v = Vec3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        );
        let n2 = v.norm_squared();
        if n2 > 1e-6 && n2 <= 1.0 {
            return v / n2.sqrt();
        }
    }
}
