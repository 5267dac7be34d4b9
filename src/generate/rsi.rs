//! Random sequential insertion (RSI): a sphere's centre is drawn uniformly in an
//! axis-aligned box shrunk by its radius, so the whole sphere lies inside, and the
//! draw is kept only if the sphere is clear of every sphere already present and of
//! the boundaries; otherwise it is drawn again. RSI jams near φ ≈ 0.38 for equal
//! spheres (Widom 1966; Torquato, Uche & Stillinger 2006 give 0.3841), so dense beds
//! are made by inserting small (a growth stage) or by pouring and settling.
//!
//! `scale` multiplies the radii in the clearance test: 1 for spheres placed at full
//! size, the initial fraction f₀ for a growth stage (0: any position is accepted, as
//! in Zhong 2009 §6.1 where particles start from zero radius).

use crate::particles::Vec3;
use crate::space::Space;
use rand::RngExt;
use rand_chacha::ChaCha8Rng;

/// An insertion region: the box [lower, upper] that must contain whole spheres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InsertionBox {
    pub lower: Vec3,
    pub upper: Vec3,
}

impl InsertionBox {
    /// A centre drawn uniformly where a sphere of radius r fits; on an axis narrower
    /// than the sphere the centre sits midway.
    pub fn draw(&self, r: f64, rng: &mut ChaCha8Rng) -> Vec3 {
        Vec3::from_fn(|a, _| {
            let (from, to) = (self.lower[a] + r, self.upper[a] - r);
            if from < to {
                rng.random_range(from..=to)
            } else {
                0.5 * (self.lower[a] + self.upper[a])
            }
        })
    }
}

/// Try up to `attempts` positions for a sphere of radius r; `None` when none is clear.
#[allow(clippy::too_many_arguments)]
pub fn place(
    r: f64,
    region: &InsertionBox,
    position: &[Vec3],
    radius: &[f64],
    clear_of_boundaries: &dyn Fn(&Vec3, f64) -> bool,
    space: &Space,
    scale: f64,
    rng: &mut ChaCha8Rng,
    attempts: usize,
) -> Option<Vec3> {
    (0..attempts).find_map(|_| {
        let x = region.draw(r, rng);
        let clear = scale == 0.0
            || (position
                .iter()
                .zip(radius)
                .all(|(q, rq)| space.displacement(&x, q).norm() >= scale * (r + rq))
                && clear_of_boundaries(&x, scale * r));
        clear.then_some(x)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    #[test]
    fn placed_spheres_are_inside_and_apart() {
        let region = InsertionBox {
            lower: Vec3::zeros(),
            upper: Vec3::new(1.0, 1.0, 1.0),
        };
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let (mut pos, mut rad) = (Vec::new(), Vec::new());
        for _ in 0..200 {
            let x = place(
                0.05,
                &region,
                &pos,
                &rad,
                &|_, _| true,
                &Space::open(),
                1.0,
                &mut rng,
                10_000,
            )
            .expect("φ ≈ 0.1 is far from jamming");
            pos.push(x);
            rad.push(0.05);
        }
        for (i, a) in pos.iter().enumerate() {
            assert!(a.iter().all(|c| (0.05..=0.95).contains(c)));
            for b in &pos[..i] {
                assert!((a - b).norm() >= 0.1);
            }
        }
    }
}
