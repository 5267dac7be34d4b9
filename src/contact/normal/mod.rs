//! Normal contact laws: the elastic (or plastic) part of the normal force.
//! One file per law; `NormalLaw` is resolved from the scene once, at build time.

pub mod hertz;
pub mod linear;

use crate::material::PairProperties;

#[derive(Clone, Debug, PartialEq)]
pub enum NormalLaw {
    Linear { stiffness: f64 },
    Hertz,
}

/// Elastic normal force and its tangent stiffness at one overlap.
#[derive(Clone, Copy, Debug)]
pub struct NormalResponse {
    pub force: f64,
    pub stiffness: f64,
}

impl NormalLaw {
    pub fn name(&self) -> &'static str {
        match self {
            NormalLaw::Linear { .. } => "linear",
            NormalLaw::Hertz => "hertz",
        }
    }

    #[inline]
    pub fn response(
        &self,
        overlap: f64,
        effective_radius: f64,
        pair: &PairProperties,
    ) -> NormalResponse {
        match *self {
            NormalLaw::Linear { stiffness } => NormalResponse {
                force: linear::linear_force(stiffness, overlap),
                stiffness,
            },
            NormalLaw::Hertz => {
                let e = pair.effective_modulus.unwrap_or(0.0);
                NormalResponse {
                    force: hertz::hertz_force(overlap, effective_radius, e),
                    stiffness: hertz::hertz_stiffness(overlap, effective_radius, e),
                }
            }
        }
    }

    pub fn energy(&self, overlap: f64, effective_radius: f64, pair: &PairProperties) -> f64 {
        match *self {
            NormalLaw::Linear { stiffness } => linear::linear_energy(stiffness, overlap),
            NormalLaw::Hertz => hertz::hertz_energy(
                overlap,
                effective_radius,
                pair.effective_modulus.unwrap_or(0.0),
            ),
        }
    }

    /// Normal stiffness expected in a head-on impact at `speed`, used for the
    /// critical time step before any contact exists (Rojek eq 9 at δ_max).
    pub fn impact_stiffness(
        &self,
        effective_mass: f64,
        speed: f64,
        effective_radius: f64,
        pair: &PairProperties,
    ) -> f64 {
        match *self {
            NormalLaw::Linear { stiffness } => stiffness,
            NormalLaw::Hertz => {
                let e = pair.effective_modulus.unwrap_or(0.0);
                let d = hertz::hertz_max_overlap(effective_mass, speed, effective_radius, e);
                hertz::hertz_stiffness(d, effective_radius, e)
            }
        }
    }
}
