//! The composed contact law: normal ∘ damping ∘ tangential, only the roles a scene
//! enables. Geometry is computed once per contact (by the caller, for pairs and
//! walls alike) and passed read-only; the law returns forces and never applies them.
//!
//! Sign convention for every law: `normal` points from the partner (particle j or
//! the wall) to particle i; overlap δ = R_i + R_j − |x_i − x_j| > 0 in contact
//! (Rojek's h = −δ); a positive normal force pushes i away from the partner.

pub mod damping;
pub mod normal;
pub mod tangential;

use crate::material::PairProperties;
use crate::particles::Vec3;
use damping::Damping;
use normal::NormalLaw;
use tangential::{TangentialLaw, cundall_strack::cundall_strack_force};

/// Geometry of one contact, computed once and shared by all roles.
#[derive(Clone, Copy, Debug)]
pub struct ContactGeometry {
    pub normal: Vec3,
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
}

/// Force on particle i (the partner receives the opposite).
#[derive(Clone, Copy, Debug, Default)]
pub struct ContactForce {
    /// Total normal force along `normal` (elastic + damping), N.
    pub normal: f64,
    pub tangential: Vec3,
}

#[derive(Clone, Debug, PartialEq)]
pub struct ContactLaw {
    pub normal: NormalLaw,
    pub damping: Option<Damping>,
    pub tangential: Option<TangentialLaw>,
}

impl ContactLaw {
    /// Whether contacts carry history (the tangential spring).
    pub fn has_history(&self) -> bool {
        self.tangential.is_some()
    }

    /// Evaluate the enabled roles in their fixed order. `spring` is the contact's
    /// tangential history; it is `None` exactly when friction is off.
    #[inline]
    pub fn evaluate(
        &self,
        g: &ContactGeometry,
        pair: &PairProperties,
        spring: Option<&mut Vec3>,
        dt: f64,
    ) -> ContactForce {
        let elastic = self.normal.response(g.overlap, g.effective_radius, pair);
        let mut normal = elastic.force;
        if let Some(d) = &self.damping {
            normal += d.coefficient(g.effective_mass, elastic.stiffness) * g.overlap_rate();
        }
        let tangential = match (&self.tangential, spring) {
            (Some(TangentialLaw::CundallStrack { stiffness }), Some(spring)) => {
                let v_t = g.relative_velocity - g.normal * g.normal.dot(&g.relative_velocity);
                cundall_strack_force(
                    spring,
                    &g.normal,
                    &v_t,
                    dt,
                    *stiffness,
                    pair.friction,
                    normal,
                )
            }
            _ => Vec3::zeros(),
        };
        ContactForce { normal, tangential }
    }

    /// Energy stored in the contact's springs (normal and tangential), J.
    pub fn stored_energy(
        &self,
        overlap: f64,
        effective_radius: f64,
        pair: &PairProperties,
        spring: Option<&Vec3>,
    ) -> f64 {
        let tangential = match (&self.tangential, spring) {
            (Some(t), Some(s)) => 0.5 * t.stiffness() * s.norm_squared(),
            _ => 0.0,
        };
        self.normal.energy(overlap, effective_radius, pair) + tangential
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
        }
    }

    fn pair() -> PairProperties {
        PairProperties {
            effective_modulus: Some(1e9),
            effective_shear_modulus: Some(4e8),
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
        let (mut s1, mut s2) = (Vec3::zeros(), Vec3::zeros());
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
        let f = law().evaluate(&g, &pair(), Some(&mut Vec3::zeros()), 1e-6);
        assert!(f.normal.abs() < 1e-300 && f.tangential.norm() == 0.0);
    }
}
