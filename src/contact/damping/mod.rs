//! Viscous normal damping: F_n^d = c_n · dδ/dt (Rojek 2016 eq 6, Zhong 2009 eq 6),
//! positive (repulsive) while the overlap grows. Without a force limit the damped
//! force turns attractive near the end of a contact, as in the closed forms of
//! Zhong eqs 7–9 and LIGGGHTS's default `limitForce off`.
//!
//! Two forms of c_n:
//! - `CriticalFraction { xi }`: c_n = ξ · 2√(m* k_n) (Rojek eqs 7–8), with k_n the
//!   tangent stiffness of the normal law at the current overlap (eq 9, eq 10);
//! - `Constant { gamma_n }`: c_n = γ_n (Zhong eq 6).
//!
//! The scene kind `liggghts_restitution` is not a third form: `liggghts.rs` turns
//! LIGGGHTS's restitution coefficient into the `CriticalFraction` ξ that gives
//! LIGGGHTS's γ_n for the scene's normal law, once, when the scene is built.

pub mod liggghts;

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Damping {
    CriticalFraction { xi: f64 },
    Constant { gamma_n: f64 },
}

impl Damping {
    #[inline]
    pub fn coefficient(&self, effective_mass: f64, stiffness: f64) -> f64 {
        match *self {
            Damping::CriticalFraction { xi } => xi * critical_damping(effective_mass, stiffness),
            Damping::Constant { gamma_n } => gamma_n,
        }
    }

    /// Damping ratio ξ of a contact with this mass and stiffness (for eq 28).
    pub fn ratio(&self, effective_mass: f64, stiffness: f64) -> f64 {
        match *self {
            Damping::CriticalFraction { xi } => xi,
            Damping::Constant { gamma_n } => gamma_n / critical_damping(effective_mass, stiffness),
        }
    }
}

/// Rojek eq 8: C_cr = 2 √(m_i m_j k_n / (m_i + m_j)) = 2 √(m* k_n).
pub fn critical_damping(effective_mass: f64, stiffness: f64) -> f64 {
    2.0 * (effective_mass * stiffness).sqrt()
}
