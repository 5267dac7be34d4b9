//! The inputs of a two-sphere case as its references need them: the effective mass,
//! radius and modulus of particles 0 and 1 and their normal approach speed, taken from
//! the scene as tamp builds it (materials mixed once, masses from densities), before
//! any step. The references never read what an engine recorded.

use crate::error::{Result, TampError};
use crate::material::{effective_mass, effective_radius};
use crate::scene::{self, Scene};

/// Particles 0 and 1 of a scene, at t = 0.
#[derive(Clone, Copy, Debug)]
pub struct Pair {
    /// m* = m₀m₁/(m₀ + m₁), kg.
    pub m_eff: f64,
    /// R* = R₀R₁/(R₀ + R₁), m.
    pub r_eff: f64,
    /// E* of the pair's materials, Pa, when the law needs one.
    pub e_eff: Option<f64>,
    /// −(v₀ − v₁)·n, n from particle 1 to 0: the speed at which they close, m/s.
    pub approach: f64,
}

impl Pair {
    /// The pair of `scene`, which must have at least two particles.
    pub fn of(scene: &Scene) -> Result<Pair> {
        let sim = scene::build(scene)?.sim;
        let p = &sim.state.particles;
        if p.len() < 2 {
            return Err(TampError::Other(
                "a two-body case needs two particles".into(),
            ));
        }
        Ok(Pair {
            m_eff: effective_mass(p.mass[0], p.mass[1]),
            r_eff: effective_radius(p.radius[0], p.radius[1]),
            e_eff: sim
                .model
                .pair_table
                .get(p.material[0], p.material[1])
                .effective_modulus,
            approach: -(p.velocity[0] - p.velocity[1])
                .dot(&(p.position[0] - p.position[1]).normalize()),
        })
    }

    /// E*, or an error when the scene's materials give none.
    pub fn effective_modulus(&self) -> Result<f64> {
        self.e_eff.ok_or_else(|| {
            TampError::Other(
                "the pair's materials give no E* (youngs_modulus, poisson_ratio)".into(),
            )
        })
    }
}
