//! Normal contact laws: the elastic, viscoelastic or plastic part of the normal force.
//! One file per law; `NormalLaw` is resolved from the scene once, at build time.
//! Laws with memory (Walton–Braun, Storåkers) keep the largest overlap δ_max in the
//! contact's history.

pub mod hertz;
pub mod hysteretic;
pub mod kuwabara_kono;
pub mod linear;
pub mod plastic_cylinder;
pub mod storakers;
pub mod walton_braun;

use crate::material::PairProperties;
use storakers::Storakers;

#[derive(Clone, Debug, PartialEq)]
pub enum NormalLaw {
    /// Zhong model I.
    Linear { stiffness: f64 },
    /// Zhong model II, Rojek eq 2.
    Hertz,
    /// Zhong model III; A is the dissipation time, s.
    KuwabaraKono { dissipation_time: f64 },
    /// Zhong model IV; k₁ loading, k₂ unloading, N/m.
    WaltonBraun {
        loading_stiffness: f64,
        unloading_stiffness: f64,
    },
    /// Zhong model V; γ dimensionless.
    Hysteretic { stiffness: f64, hysteresis: f64 },
    /// Rojek eqs 15–22, optionally capped by Hertz (Martin et al. 2003).
    Storakers { min_with_hertz: bool },
}

/// Normal force (without a separate damping role) and its tangent stiffness.
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
            NormalLaw::KuwabaraKono { .. } => "kuwabara_kono",
            NormalLaw::WaltonBraun { .. } => "walton_braun",
            NormalLaw::Hysteretic { .. } => "hysteretic",
            NormalLaw::Storakers {
                min_with_hertz: false,
            } => "storakers",
            NormalLaw::Storakers {
                min_with_hertz: true,
            } => "storakers_min_hertz",
        }
    }

    /// Whether the law keeps δ_max in the contact history.
    pub fn has_memory(&self) -> bool {
        matches!(
            self,
            NormalLaw::WaltonBraun { .. } | NormalLaw::Storakers { .. }
        )
    }

    /// Whether the law needs E* (and so elastic constants on every material).
    pub fn needs_elastic_constants(&self) -> bool {
        matches!(
            self,
            NormalLaw::Hertz | NormalLaw::KuwabaraKono { .. } | NormalLaw::Storakers { .. }
        )
    }

    /// Whether the law dissipates by itself (a separate damping role is then refused).
    pub fn has_own_dissipation(&self) -> bool {
        matches!(
            self,
            NormalLaw::KuwabaraKono { .. } | NormalLaw::Hysteretic { .. }
        )
    }

    fn storakers(min_with_hertz: bool, effective_radius: f64, pair: &PairProperties) -> Storakers {
        Storakers {
            effective_radius,
            effective_modulus: pair.effective_modulus.unwrap_or(0.0),
            hollomon: pair.hollomon.unwrap_or(crate::material::Hollomon {
                strength: 0.0,
                exponent: 0.0,
            }),
            min_with_hertz,
        }
    }

    /// Force and stiffness at this step; updates δ_max for laws with memory. Only the
    /// rate-dependent laws differ from the stored state (`state`) of their contact.
    #[inline]
    pub fn response(
        &self,
        overlap: f64,
        overlap_rate: f64,
        effective_radius: f64,
        pair: &PairProperties,
        max_overlap: &mut f64,
    ) -> NormalResponse {
        let (force, stiffness) = match *self {
            NormalLaw::KuwabaraKono { dissipation_time } => {
                let e = pair.effective_modulus.unwrap_or(0.0);
                (
                    kuwabara_kono::kuwabara_kono_force(
                        overlap,
                        overlap_rate,
                        effective_radius,
                        e,
                        dissipation_time,
                    ),
                    hertz::hertz_stiffness(overlap, effective_radius, e),
                )
            }
            NormalLaw::Hysteretic {
                stiffness,
                hysteresis,
            } => (
                hysteretic::hysteretic_force(overlap, overlap_rate, stiffness, hysteresis),
                stiffness * (1.0 + hysteresis),
            ),
            NormalLaw::WaltonBraun { .. } | NormalLaw::Storakers { .. } => {
                *max_overlap = max_overlap.max(overlap);
                self.state(overlap, effective_radius, pair, *max_overlap)
            }
            NormalLaw::Linear { .. } | NormalLaw::Hertz => {
                self.state(overlap, effective_radius, pair, *max_overlap)
            }
        };
        NormalResponse { force, stiffness }
    }

    /// Force and stiffness of the stored state (no update); for rate-dependent laws
    /// the elastic part and the largest stiffness.
    #[inline]
    fn state(
        &self,
        overlap: f64,
        effective_radius: f64,
        pair: &PairProperties,
        max_overlap: f64,
    ) -> (f64, f64) {
        let e = pair.effective_modulus.unwrap_or(0.0);
        match *self {
            NormalLaw::Linear { stiffness } => {
                (linear::linear_force(stiffness, overlap), stiffness)
            }
            NormalLaw::Hertz | NormalLaw::KuwabaraKono { .. } => (
                hertz::hertz_force(overlap, effective_radius, e),
                hertz::hertz_stiffness(overlap, effective_radius, e),
            ),
            NormalLaw::Hysteretic {
                stiffness,
                hysteresis,
            } => (stiffness * overlap, stiffness * (1.0 + hysteresis)),
            NormalLaw::WaltonBraun {
                loading_stiffness,
                unloading_stiffness,
            } => walton_braun::walton_braun_response(
                overlap,
                max_overlap,
                loading_stiffness,
                unloading_stiffness,
            ),
            NormalLaw::Storakers { min_with_hertz } => {
                Self::storakers(min_with_hertz, effective_radius, pair)
                    .response(overlap, max_overlap)
            }
        }
    }

    /// Tangent stiffness of a stored contact state, for the critical time step.
    pub fn stiffness(
        &self,
        overlap: f64,
        effective_radius: f64,
        pair: &PairProperties,
        max_overlap: f64,
    ) -> f64 {
        self.state(overlap, effective_radius, pair, max_overlap.max(overlap))
            .1
    }

    /// Stiffness the critical time step must resolve (Rojek §3.4): the current
    /// branch's tangent, and for a contact on a loading branch also the unloading
    /// branch it turns onto the step its overlap stops growing. Without the second,
    /// a dense bed estimated while loading under-resolves its first unloading: the
    /// stable-α study (docs/accuracy-cost.md) found a Walton–Braun lattice with
    /// k₂ = 2k₁ unstable at α = 0.93 where the linear one held to 1.15.
    pub fn time_step_stiffness(
        &self,
        overlap: f64,
        effective_radius: f64,
        pair: &PairProperties,
        max_overlap: f64,
    ) -> f64 {
        let current = self.stiffness(overlap, effective_radius, pair, max_overlap);
        let max_overlap = max_overlap.max(overlap);
        let turning = match *self {
            NormalLaw::WaltonBraun {
                unloading_stiffness,
                ..
            } if overlap > 0.0 => unloading_stiffness,
            NormalLaw::Storakers { min_with_hertz } if overlap > 0.0 => {
                Self::storakers(min_with_hertz, effective_radius, pair)
                    .unloading_stiffness(max_overlap)
            }
            _ => 0.0,
        };
        current.max(turning)
    }

    /// Energy the contact would give back on elastic unloading, J.
    pub fn energy(
        &self,
        overlap: f64,
        effective_radius: f64,
        pair: &PairProperties,
        max_overlap: f64,
    ) -> f64 {
        let e = pair.effective_modulus.unwrap_or(0.0);
        match *self {
            NormalLaw::Linear { stiffness } => linear::linear_energy(stiffness, overlap),
            NormalLaw::Hertz | NormalLaw::KuwabaraKono { .. } => {
                hertz::hertz_energy(overlap, effective_radius, e)
            }
            NormalLaw::Hysteretic {
                stiffness,
                hysteresis,
            } => 0.5 * stiffness * (1.0 - hysteresis) * overlap * overlap,
            NormalLaw::WaltonBraun {
                loading_stiffness,
                unloading_stiffness,
            } => walton_braun::walton_braun_energy(
                overlap,
                max_overlap,
                loading_stiffness,
                unloading_stiffness,
            ),
            NormalLaw::Storakers { min_with_hertz } => {
                Self::storakers(min_with_hertz, effective_radius, pair).energy(overlap, max_overlap)
            }
        }
    }

    /// Normal stiffness expected in a head-on impact at `speed`, used for the
    /// critical time step before any contact exists: the tangent stiffness at the
    /// largest overlap, and for Storåkers the stiffer of plastic loading (eq 22) and
    /// elastic unloading (eq 20) there.
    pub fn impact_stiffness(
        &self,
        effective_mass: f64,
        speed: f64,
        effective_radius: f64,
        pair: &PairProperties,
    ) -> f64 {
        let e = pair.effective_modulus.unwrap_or(0.0);
        match *self {
            NormalLaw::Linear { stiffness } => stiffness,
            NormalLaw::Hysteretic {
                stiffness,
                hysteresis,
            } => stiffness * (1.0 + hysteresis),
            NormalLaw::WaltonBraun {
                unloading_stiffness,
                ..
            } => unloading_stiffness,
            NormalLaw::Hertz | NormalLaw::KuwabaraKono { .. } => {
                let d = hertz::hertz_max_overlap(effective_mass, speed, effective_radius, e);
                hertz::hertz_stiffness(d, effective_radius, e)
            }
            NormalLaw::Storakers { min_with_hertz } => {
                let s = Self::storakers(min_with_hertz, effective_radius, pair);
                // Kinetic energy absorbed by the plastic branch C δ^p: ½ m v² = C δ^{p+1}/(p+1).
                let p = 1.0 + 0.5 * s.hollomon.exponent;
                let c = storakers::storakers_prefactor(effective_radius, s.hollomon);
                let d =
                    ((p + 1.0) * 0.5 * effective_mass * speed * speed / c).powf(1.0 / (p + 1.0));
                let k_plastic = s.loading(d).1;
                let k_unloading = s.unloading_stiffness(d);
                // With the Hertz cap the contact may load elastically all the way: take
                // the Hertz impact stiffness too, whichever is larger.
                let k_hertz = if min_with_hertz {
                    NormalLaw::Hertz.impact_stiffness(effective_mass, speed, effective_radius, pair)
                } else {
                    0.0
                };
                k_plastic.max(k_unloading).max(k_hertz)
            }
        }
    }
}
