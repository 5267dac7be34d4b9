//! The composed contact law: normal ∘ damping ∘ tangential, only the roles a scene
//! enables. Geometry is computed once per contact (by the caller, for pairs and
//! walls alike) and passed read-only; the law returns forces and never applies them.
//!
//! Sign convention for every law: `normal` points from the partner (particle j or
//! the wall) to particle i; overlap δ = R_i + R_j − |x_i − x_j| > 0 in contact
//! (Rojek's h = −δ); a positive normal force pushes i away from the partner.

pub mod damping;
pub mod history;
pub mod normal;
pub mod tangential;
pub mod van_der_waals;

use crate::material::PairProperties;
use crate::particles::Vec3;
use damping::Damping;
use history::ContactHistory;
use normal::NormalLaw;
use tangential::{TangentialInput, TangentialLaw};
use van_der_waals::VanDerWaals;

/// Geometry of one contact, computed once and shared by all roles.
#[derive(Clone, Copy, Debug)]
pub struct ContactGeometry {
    pub normal: Vec3,
    /// δ > 0 in contact; −δ is the surface gap when apart (cohesion acts across it).
    pub overlap: f64,
    pub effective_radius: f64,
    pub effective_mass: f64,
    /// Velocity of i's contact point relative to the partner's (includes spin when rotation is on).
    pub relative_velocity: Vec3,
}

impl ContactGeometry {
    /// dδ/dt: positive while the bodies approach.
    #[inline]
    pub fn overlap_rate(&self) -> f64 {
        -self.relative_velocity.dot(&self.normal)
    }

    #[inline]
    pub fn tangential_velocity(&self) -> Vec3 {
        self.relative_velocity - self.normal * self.normal.dot(&self.relative_velocity)
    }
}

/// Force on particle i (the partner receives the opposite).
#[derive(Clone, Copy, Debug, Default)]
pub struct ContactForce {
    /// Total normal force along `normal` (elastic + damping − cohesion), N.
    pub normal: f64,
    pub tangential: Vec3,
}

#[derive(Clone, Debug, PartialEq)]
pub struct ContactLaw {
    pub normal: NormalLaw,
    pub damping: Option<Damping>,
    pub tangential: Option<TangentialLaw>,
    pub cohesion: Option<VanDerWaals>,
}

impl ContactLaw {
    /// Whether contacts carry history (a tangential state or the normal law's δ_max).
    pub fn has_history(&self) -> bool {
        self.normal.has_memory() || self.tangential.is_some_and(|t| t.has_history())
    }

    /// How far beyond touching the law acts (the cohesion cut-off), m.
    pub fn reach(&self) -> f64 {
        self.cohesion.map_or(0.0, |c| c.cutoff)
    }

    fn tangential_input(
        &self,
        g: &ContactGeometry,
        pair: &PairProperties,
        normal_force: f64,
        normal_stiffness: f64,
        dt: f64,
    ) -> TangentialInput {
        TangentialInput {
            normal: g.normal,
            tangential_velocity: g.tangential_velocity(),
            dt,
            friction: pair.friction,
            normal_force,
            normal_stiffness,
            overlap: g.overlap,
            effective_radius: g.effective_radius,
            effective_shear_modulus: pair.effective_shear_modulus.unwrap_or(0.0),
            effective_mass: g.effective_mass,
        }
    }

    /// The tangential input of a stored contact state at rest (for energies and
    /// stiffnesses, which depend on the overlap but not on the motion).
    fn resting_input(
        &self,
        overlap: f64,
        effective_radius: f64,
        pair: &PairProperties,
        normal_stiffness: f64,
    ) -> TangentialInput {
        let g = ContactGeometry {
            normal: Vec3::z(),
            overlap,
            effective_radius,
            effective_mass: 0.0,
            relative_velocity: Vec3::zeros(),
        };
        self.tangential_input(&g, pair, 0.0, normal_stiffness, 0.0)
    }

    /// Evaluate the enabled roles in their fixed order: normal, damping, tangential
    /// (limited by the contact's normal force), cohesion. `history` is `None` exactly
    /// when the law has none; it is reset while the bodies are apart.
    // `always`: with plain `inline` the compiler kept it a call in the pair loop, and
    // inlining it there measured 3 % less CPU on the LAMMPS chute (docs/performance.md).
    #[inline(always)]
    pub fn evaluate(
        &self,
        g: &ContactGeometry,
        pair: &PairProperties,
        history: Option<&mut ContactHistory>,
        dt: f64,
    ) -> ContactForce {
        let mut scratch = ContactHistory::default();
        let history = history.unwrap_or(&mut scratch);
        let mut force = ContactForce::default();
        if g.overlap > 0.0 {
            let rate = g.overlap_rate();
            let elastic = self.normal.response(
                g.overlap,
                rate,
                g.effective_radius,
                pair,
                &mut history.max_overlap,
            );
            force.normal = elastic.force;
            if let Some(d) = &self.damping {
                force.normal += d.coefficient(g.effective_mass, elastic.stiffness) * rate;
            }
            if let Some(t) = &self.tangential {
                let input = self.tangential_input(g, pair, force.normal, elastic.stiffness, dt);
                force.tangential = t.force(&input, history);
            }
        } else {
            *history = ContactHistory::default();
        }
        if let Some(c) = &self.cohesion {
            force.normal -= c.force(-g.overlap, g.effective_radius);
        }
        force
    }

    /// Energy stored in the contact (recoverable normal and tangential energy, and
    /// the cohesive potential), J.
    pub fn stored_energy(
        &self,
        overlap: f64,
        effective_radius: f64,
        pair: &PairProperties,
        history: Option<&ContactHistory>,
    ) -> f64 {
        let cohesion = self
            .cohesion
            .map_or(0.0, |c| c.energy(-overlap, effective_radius));
        if overlap <= 0.0 {
            return cohesion;
        }
        let none = ContactHistory::default();
        let history = history.unwrap_or(&none);
        let normal = self
            .normal
            .energy(overlap, effective_radius, pair, history.max_overlap);
        let tangential = self.tangential.map_or(0.0, |t| {
            let k_n = self
                .normal
                .stiffness(overlap, effective_radius, pair, history.max_overlap);
            t.energy(
                &self.resting_input(overlap, effective_radius, pair, k_n),
                history,
            )
        });
        normal + tangential + cohesion
    }

    /// Largest tangent stiffness (normal, and tangential with θ = 1) of a stored
    /// contact state, N/m, for the critical time step (Rojek §3.4).
    pub fn stiffness(
        &self,
        overlap: f64,
        effective_radius: f64,
        pair: &PairProperties,
        history: Option<&ContactHistory>,
    ) -> (f64, f64) {
        let max_overlap = history.map_or(0.0, |h| h.max_overlap);
        let k_n = self
            .normal
            .time_step_stiffness(overlap, effective_radius, pair, max_overlap);
        let k_t = self.tangential.map_or(0.0, |t| {
            t.stiffness(&self.resting_input(overlap, effective_radius, pair, k_n))
        });
        (k_n, k_t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn law() -> ContactLaw {
        ContactLaw {
            normal: NormalLaw::Hertz,
            damping: Some(Damping::CriticalFraction { xi: 0.3 }),
            tangential: Some(TangentialLaw::CundallStrack { stiffness: 1e5 }),
            cohesion: None,
        }
    }

    fn pair() -> PairProperties {
        PairProperties {
            effective_modulus: Some(1e9),
            effective_shear_modulus: Some(4e8),
            hollomon: None,
            friction: 0.5,
        }
    }

    #[test]
    fn swapping_bodies_reverses_force() {
        let g = ContactGeometry {
            normal: Vec3::new(0.0, 0.6, 0.8),
            overlap: 1e-5,
            effective_radius: 1e-3,
            effective_mass: 1e-3,
            relative_velocity: Vec3::new(0.1, -0.2, -0.05),
        };
        let swapped = ContactGeometry {
            normal: -g.normal,
            relative_velocity: -g.relative_velocity,
            ..g
        };
        let (mut s1, mut s2) = (ContactHistory::default(), ContactHistory::default());
        let f1 = law().evaluate(&g, &pair(), Some(&mut s1), 1e-6);
        let f2 = law().evaluate(&swapped, &pair(), Some(&mut s2), 1e-6);
        let total1 = g.normal * f1.normal + f1.tangential;
        let total2 = swapped.normal * f2.normal + f2.tangential;
        assert!((total1 + total2).norm() <= 1e-12 * total1.norm());
    }

    #[test]
    fn force_is_continuous_at_first_touch() {
        let g = ContactGeometry {
            normal: Vec3::z(),
            overlap: 1e-300,
            effective_radius: 1e-3,
            effective_mass: 1e-3,
            relative_velocity: Vec3::zeros(),
        };
        let f = law().evaluate(&g, &pair(), Some(&mut ContactHistory::default()), 1e-6);
        assert!(f.normal.abs() < 1e-300 && f.tangential.norm() == 0.0);
    }
}
