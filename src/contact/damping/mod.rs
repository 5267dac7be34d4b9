//! Viscous normal damping: F_n^d = c_n · dδ/dt (Rojek 2016 eq 6, Zhong 2009 eq 6),
//! positive (repulsive) while the overlap grows. Without a force limit the damped
//! force turns attractive near the end of a contact, as in the closed forms of
//! Zhong eqs 7–9 and LIGGGHTS's default `limitForce off`.
//!
//! Two forms of c_n:
//! - `CriticalFraction`: c_n = ξ · 2√(m* k_n) (Rojek eqs 7–8), with k_n the
//!   tangent stiffness of the normal law at the current overlap (eq 9, eq 10);
//! - `Constant`: c_n = γ_n (Zhong eq 6).
//!
//! The scene kind `liggghts_restitution` is not a third form: `liggghts.rs` turns
//! LIGGGHTS's restitution coefficient into the `CriticalFraction` ξ that gives
//! LIGGGHTS's γ_n for the scene's normal law, once, when the scene is built.

pub mod liggghts;

pub use crate::contact::model::DampingModel;

/// c_n = ξ · 2√(m* k_n), Rojek eqs 6–10.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CriticalFraction {
    pub xi: f64,
}

impl DampingModel for CriticalFraction {
    const ACTIVE: bool = true;
    #[inline(always)]
    fn coefficient(&self, effective_mass: f64, stiffness: f64) -> f64 {
        self.xi * critical_damping(effective_mass, stiffness)
    }
    fn ratio(&self, _: f64, _: f64) -> f64 {
        self.xi
    }
}

/// c_n = γ_n, Zhong eq 6 (N·s/m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Constant {
    pub gamma_n: f64,
}

impl DampingModel for Constant {
    const ACTIVE: bool = true;
    #[inline(always)]
    fn coefficient(&self, _: f64, _: f64) -> f64 {
        self.gamma_n
    }
    fn ratio(&self, effective_mass: f64, stiffness: f64) -> f64 {
        self.gamma_n / critical_damping(effective_mass, stiffness)
    }
}

/// The scene's damping role.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Damping {
    CriticalFraction(CriticalFraction),
    Constant(Constant),
}

/// `each_damping!(damping, d => expr)`: `expr` with `d` bound to the form's own type.
#[macro_export]
macro_rules! each_damping {
    ($damping:expr, $d:ident => $body:expr) => {
        match $damping {
            $crate::contact::damping::Damping::CriticalFraction($d) => $body,
            $crate::contact::damping::Damping::Constant($d) => $body,
        }
    };
}

impl Damping {
    #[inline]
    pub fn coefficient(&self, effective_mass: f64, stiffness: f64) -> f64 {
        each_damping!(self, d => d.coefficient(effective_mass, stiffness))
    }

    /// Damping ratio ξ of a contact with this mass and stiffness (for eq 28).
    pub fn ratio(&self, effective_mass: f64, stiffness: f64) -> f64 {
        each_damping!(self, d => d.ratio(effective_mass, stiffness))
    }
}

/// Rojek eq 8: C_cr = 2 √(m_i m_j k_n / (m_i + m_j)) = 2 √(m* k_n).
pub fn critical_damping(effective_mass: f64, stiffness: f64) -> f64 {
    2.0 * (effective_mass * stiffness).sqrt()
}
