//! Storåkers rigid-plastic contact with Hollomon hardening, regularised by elastic
//! Hertz unloading and reloading (Rojek 2016 eqs 15–22, after Storåkers et al. 1999
//! and Olsson & Larsson 2013).
//!
//! Plastic loading, on the virgin branch δ = δ_max (eq 16, 17, 22):
//!   F_p = C δ^{1+m/2},  C = 2^{1−m/2} 3^{1−m} π c^{2+m} σ0* R*^{1−m/2},  c^{2+m} = 1.43 e^{−0.97 m}
//!   k_p = (1 + m/2) C δ^{m/2}
//! σ0* mixes the two materials' Hollomon constants by eq 18 (`crate::material`).
//! With `min_with_hertz` the loading branch is min(F_p, F_Hertz) (Martin et al. 2003,
//! discussed in Rojek §4), which removes the unphysical plastic force above the
//! elastic one at very small overlaps.
//!
//! Unloading and reloading (δ < δ_max), eqs 19–20: dF/dδ = k_unl = ∛(6 R* E*² F).
//! This is the Hertz tangent written in terms of the force, so the increments
//! integrate exactly to the Hertz curve through the turning point (δ_max, F_max):
//!   F = K (δ − δ_res)^{3/2},  K = 4/3 E* √R*,  δ_res = δ_max − (F_max/K)^{2/3}
//! We evaluate this closed form instead of summing eq 19 step by step: the same law
//! without the O(Δδ) drift of the forward sum, and reloading meets (δ_max, F_max)
//! exactly, as Rojek §3.3 requires. δ_res is the permanent set. When the virgin
//! branch lies above the Hertz curve (pure Storåkers at tiny overlaps) δ_res < 0 and
//! the contact opens with a residual force, which is then lost: a property of the
//! law as published, which `min_with_hertz` avoids.
//! History: δ_max (m). Stiffness for the time step (Rojek §3.4): k_p while loading,
//! k_unl otherwise. Recoverable (stored) energy: 2/5 K [(δ − δ_res)^{5/2} − (−δ_res)₊^{5/2}].

use super::NormalLaw;
use super::hertz::{Hertz, hertz_force, hertz_stiffness};
use super::{NormalModel, NormalResponse, PeakOverlap};
use crate::contact::model::Needs;
use crate::contact::registry::{self, NormalExample};
use crate::material::{Hollomon, PairProperties};

/// c^{2+m} of Storåkers' similarity solution, fitted by eq 17.
pub fn storakers_c_power(exponent: f64) -> f64 {
    1.43 * (-0.97 * exponent).exp()
}

/// The constant C of F_p = C δ^{1+m/2} (eq 16).
pub fn storakers_prefactor(effective_radius: f64, hollomon: Hollomon) -> f64 {
    let m = hollomon.exponent;
    2f64.powf(1.0 - 0.5 * m)
        * 3f64.powf(1.0 - m)
        * std::f64::consts::PI
        * storakers_c_power(m)
        * hollomon.strength
        * effective_radius.powf(1.0 - 0.5 * m)
}

/// Plastic force and stiffness on the virgin branch (eqs 16, 22).
pub fn storakers_plastic(overlap: f64, effective_radius: f64, hollomon: Hollomon) -> (f64, f64) {
    let m = hollomon.exponent;
    let c = storakers_prefactor(effective_radius, hollomon);
    let rise = overlap.powf(0.5 * m);
    (c * rise * overlap, (1.0 + 0.5 * m) * c * rise)
}

/// Inverse of eq 16: the overlap at which the plastic force equals `force`.
pub fn storakers_overlap_at_force(force: f64, effective_radius: f64, hollomon: Hollomon) -> f64 {
    let c = storakers_prefactor(effective_radius, hollomon);
    (force / c).powf(1.0 / (1.0 + 0.5 * hollomon.exponent))
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StorakersContact {
    pub effective_radius: f64,
    pub effective_modulus: f64,
    pub hollomon: Hollomon,
    pub min_with_hertz: bool,
}

impl StorakersContact {
    /// Force and stiffness on the virgin (loading) branch.
    pub fn loading(&self, overlap: f64) -> (f64, f64) {
        let plastic = storakers_plastic(overlap, self.effective_radius, self.hollomon);
        if self.min_with_hertz {
            let hertz = hertz_force(overlap, self.effective_radius, self.effective_modulus);
            if hertz < plastic.0 {
                let k = hertz_stiffness(overlap, self.effective_radius, self.effective_modulus);
                return (hertz, k);
            }
        }
        plastic
    }

    fn hertz_constant(&self) -> f64 {
        4.0 / 3.0 * self.effective_modulus * self.effective_radius.sqrt()
    }

    /// Permanent set δ_res after unloading from `max_overlap`.
    pub fn residual_overlap(&self, max_overlap: f64) -> f64 {
        let peak = self.loading(max_overlap).0;
        max_overlap - (peak / self.hertz_constant()).powf(2.0 / 3.0)
    }

    /// Tangent of the elastic branch at its top, where unloading from `max_overlap`
    /// starts: k_unl = ∛(6 R* E*² F_max) (eq 20).
    pub fn unloading_stiffness(&self, max_overlap: f64) -> f64 {
        let peak = self.loading(max_overlap).0;
        (6.0 * self.effective_radius * self.effective_modulus.powi(2) * peak).cbrt()
    }

    /// Force and tangent stiffness at `overlap` given the largest overlap so far.
    pub fn response(&self, overlap: f64, max_overlap: f64) -> (f64, f64) {
        if overlap >= max_overlap {
            return self.loading(overlap);
        }
        let elastic = overlap - self.residual_overlap(max_overlap);
        if elastic <= 0.0 {
            return (0.0, 0.0);
        }
        let k = self.hertz_constant();
        (k * elastic.powf(1.5), 1.5 * k * elastic.sqrt())
    }

    /// Energy recoverable by elastic unloading from the current state: the Hertz
    /// branch integrated down to where the force vanishes or the contact opens
    /// (δ = 0, when δ_res < 0; the energy below is lost at separation).
    pub fn energy(&self, overlap: f64, max_overlap: f64) -> f64 {
        let residual = self.residual_overlap(max_overlap.max(overlap));
        let elastic = overlap - residual;
        if elastic <= 0.0 {
            return 0.0;
        }
        let lost = (-residual).max(0.0);
        0.4 * self.hertz_constant() * (elastic.powf(2.5) - lost.powf(2.5))
    }
}

/// The Storåkers law; `min_with_hertz` caps the plastic force by Hertz (Martin et
/// al. 2003). The Hollomon constants σ0* and m come from the pair.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Storakers {
    #[serde(default)]
    pub min_with_hertz: bool,
}

impl Storakers {
    /// The law at one contact: R*, E* and the pair's Hollomon constants.
    pub fn at(&self, effective_radius: f64, pair: &PairProperties) -> StorakersContact {
        StorakersContact {
            effective_radius,
            effective_modulus: pair.effective_modulus.unwrap_or(0.0),
            hollomon: pair.hollomon.unwrap_or(Hollomon {
                strength: 0.0,
                exponent: 0.0,
            }),
            min_with_hertz: self.min_with_hertz,
        }
    }
}

impl NormalModel for Storakers {
    type State = PeakOverlap;

    fn name(&self) -> &'static str {
        if self.min_with_hertz {
            "storakers_min_hertz"
        } else {
            "storakers"
        }
    }

    /// Loading: F = c δ^{1+m/2}, c = 2^{1−m/2} 3^{1−m} π c^{2+m} σ0 R*^{1−m/2} with
    /// c^{2+m} = 1.43 e^{−0.97m} (Rojek eqs 16–17); with `min_with_hertz`, the smaller of
    /// that and (4/3) E* √R* δ^{3/2}.
    fn examples() -> Vec<NormalExample> {
        let (r, m) = (registry::EFFECTIVE_RADIUS, registry::HOLLOMON.exponent);
        let c = 2f64.powf(1.0 - m / 2.0)
            * 3f64.powf(1.0 - m)
            * std::f64::consts::PI
            * 1.43
            * (-0.97 * m).exp()
            * registry::HOLLOMON.strength
            * r.powf(1.0 - m / 2.0);
        let k_hertz = 4.0 / 3.0 * registry::EFFECTIVE_MODULUS * r.sqrt();
        let mut out = Vec::new();
        for min_with_hertz in [false, true] {
            for overlap in [1e-8f64, 1e-7, 1e-6, 5e-6] {
                let plastic = c * overlap.powf(1.0 + m / 2.0);
                out.push(NormalExample {
                    law: NormalLaw::Storakers(Storakers { min_with_hertz }),
                    overlap,
                    rate: 0.01,
                    force: if min_with_hertz {
                        plastic.min(k_hertz * overlap.powf(1.5))
                    } else {
                        plastic
                    },
                });
            }
        }
        out
    }

    fn needs(&self) -> Needs {
        Needs {
            elastic: Some(" (elastic unloading, Rojek eq 20)"),
            hollomon: true,
            rotation: None,
        }
    }

    #[inline(always)]
    fn response(
        &self,
        overlap: f64,
        _: f64,
        r: f64,
        pair: &PairProperties,
        state: &mut PeakOverlap,
    ) -> NormalResponse {
        state.max_overlap = state.max_overlap.max(overlap);
        let (force, stiffness) = self.at(r, pair).response(overlap, state.max_overlap);
        NormalResponse { force, stiffness }
    }

    fn stiffness(&self, overlap: f64, r: f64, pair: &PairProperties, state: &PeakOverlap) -> f64 {
        self.at(r, pair)
            .response(overlap, state.max_overlap.max(overlap))
            .1
    }

    /// k_p while loading, and the elastic unloading tangent the contact turns onto
    /// the step its overlap stops growing (Rojek §3.4; see `walton_braun`).
    fn time_step_stiffness(
        &self,
        overlap: f64,
        r: f64,
        pair: &PairProperties,
        state: &PeakOverlap,
    ) -> f64 {
        let current = self.stiffness(overlap, r, pair, state);
        let turning = if overlap > 0.0 {
            self.at(r, pair)
                .unloading_stiffness(state.max_overlap.max(overlap))
        } else {
            0.0
        };
        current.max(turning)
    }

    fn energy(&self, overlap: f64, r: f64, pair: &PairProperties, state: &PeakOverlap) -> f64 {
        self.at(r, pair).energy(overlap, state.max_overlap)
    }

    /// The stiffer of plastic loading (eq 22) and elastic unloading (eq 20) at the
    /// largest overlap of a head-on impact.
    fn impact_stiffness(&self, mass: f64, speed: f64, r: f64, pair: &PairProperties) -> f64 {
        let s = self.at(r, pair);
        // Kinetic energy absorbed by the plastic branch C δ^p: ½ m v² = C δ^{p+1}/(p+1).
        let p = 1.0 + 0.5 * s.hollomon.exponent;
        let c = storakers_prefactor(r, s.hollomon);
        let d = ((p + 1.0) * 0.5 * mass * speed * speed / c).powf(1.0 / (p + 1.0));
        let k_plastic = s.loading(d).1;
        let k_unloading = s.unloading_stiffness(d);
        // With the Hertz cap the contact may load elastically all the way: take
        // the Hertz impact stiffness too, whichever is larger.
        let k_hertz = if self.min_with_hertz {
            Hertz {}.impact_stiffness(mass, speed, r, pair)
        } else {
            0.0
        };
        k_plastic.max(k_unloading).max(k_hertz)
    }

    fn stiffness_depends_on_speed(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn nial(m: f64, min_with_hertz: bool) -> StorakersContact {
        let e = 183e9;
        // NiAl, Rojek Table 2 (clippy mistakes 0.318 for 1/π).
        #[allow(clippy::approx_constant)]
        let nu: f64 = 0.318;
        StorakersContact {
            effective_radius: 5e-6,
            effective_modulus: e / (2.0 * (1.0 - nu * nu)),
            hollomon: Hollomon {
                strength: 800e6 * (e / 800e6).powf(m) * 2f64.powf(-m),
                exponent: m,
            },
            min_with_hertz,
        }
    }

    #[test]
    fn stiffness_is_the_derivative_of_the_force() {
        for m in [0.0, 0.1, 0.2] {
            let s = nial(m, false);
            let d = 5e-8;
            let h = 1e-6 * d;
            let numeric = (s.loading(d + h).0 - s.loading(d - h).0) / (2.0 * h);
            assert_relative_eq!(s.loading(d).1, numeric, max_relative = 1e-7);
        }
    }

    #[test]
    fn unloading_stiffness_at_the_top_is_the_elastic_branch_tangent() {
        let s = nial(0.2, false);
        let top = 1e-7;
        let below = s.response(top * (1.0 - 1e-9), top).1;
        assert_relative_eq!(s.unloading_stiffness(top), below, max_relative = 1e-6);
    }

    #[test]
    fn unloading_stiffness_is_eq20() {
        let s = nial(0.2, false);
        let (dm, d) = (1e-7, 0.9e-7);
        let (f, k) = s.response(d, dm);
        let eq20 = (6.0 * s.effective_radius * s.effective_modulus.powi(2) * f).cbrt();
        assert_relative_eq!(k, eq20, max_relative = 1e-12);
    }

    #[test]
    fn reloading_meets_the_turning_point() {
        // Beyond the crossover with Hertz (1.41e-7 m for m = 0.1), so δ_res > 0.
        let s = nial(0.1, false);
        let dm = 3e-7;
        assert!(s.residual_overlap(dm) > 0.0);
        let peak = s.loading(dm).0;
        assert_relative_eq!(
            s.response(dm * (1.0 - 1e-13), dm).0,
            peak,
            max_relative = 1e-9
        );
        assert_eq!(s.response(s.residual_overlap(dm) * 0.999, dm).0, 0.0);
    }

    /// Work of loading along the virgin branch, by the trapezoidal rule.
    fn loading_work(s: &StorakersContact, dm: f64) -> f64 {
        let n = 100_000;
        let h = dm / n as f64;
        (0..n)
            .map(|k| 0.5 * h * (s.loading(k as f64 * h).0 + s.loading((k + 1) as f64 * h).0))
            .sum()
    }

    #[test]
    fn unloading_returns_less_than_loading_took_beyond_the_passivity_threshold() {
        // For NiAl pairs (R* = 5 µm) the threshold is 6.0e-8 to 8.0e-8 m for m = 0 to
        // 0.2 (docs/models/storakers.md); above it the law dissipates.
        for m in [0.0, 0.1, 0.2] {
            let s = nial(m, false);
            for dm in [1.0e-7f64, 1.3e-7, 3e-7] {
                assert!(s.energy(dm, dm) <= loading_work(&s, dm), "m {m} dm {dm}");
            }
        }
    }

    #[test]
    fn pure_storakers_gives_back_more_than_it_took_at_small_overlaps() {
        // The published law (plastic loading above Hertz, Hertz unloading) is not
        // passive at small overlaps; capping by Hertz restores passivity.
        for m in [0.0, 0.1, 0.2] {
            let dm = 1e-8;
            let pure = nial(m, false);
            assert!(pure.energy(dm, dm) > 1.3 * loading_work(&pure, dm), "m {m}");
            let capped = nial(m, true);
            assert!(capped.energy(dm, dm) <= loading_work(&capped, dm) * (1.0 + 1e-9));
        }
    }

    #[test]
    fn min_with_hertz_is_never_above_either_law() {
        let s = nial(0.0, true);
        for d in [1e-12, 1e-10, 1e-9, 1e-8, 1e-7] {
            let f = s.loading(d).0;
            assert!(f <= storakers_plastic(d, s.effective_radius, s.hollomon).0);
            assert!(f <= hertz_force(d, s.effective_radius, s.effective_modulus) * (1.0 + 1e-15));
        }
    }
}
