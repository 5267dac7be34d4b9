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
//! History: δ_max (m). Stiffness for the time step (Rojek §3.4): the larger of the
//! current tangent (k_p while loading) and the elastic unloading tangent at
//! max(δ, δ_max), which a loading contact turns onto the step its overlap stops growing. Recoverable (stored) energy: 2/5 K [(δ − δ_res)^{5/2} − (−δ_res)₊^{5/2}].

use super::NormalLaw;
use super::hertz::{Hertz, hertz_force, hertz_stiffness};
use super::{NormalModel, NormalResponse};
use crate::contact::damping::Damping;
use crate::contact::model::Needs;
use crate::contact::registry::{self, NormalExample};
use crate::material::{Hollomon, PairProperties};

/// c^{2+m} of Storåkers' similarity solution, fitted by eq 17.
pub fn storakers_c_power(exponent: f64) -> f64 {
    1.43 * (-0.97 * exponent).exp()
}

/// The factor of eq 16's C that the pair's Hollomon constants alone set,
/// 2^{1−m/2} 3^{1−m} π c^{2+m} σ0 (C is it times R*^{1−m/2}). The pair table holds
/// it (`PairProperties::law_constant`, from `NormalModel::pair_constant`), so that a
/// contact's step does not evaluate its two powers and exponential again.
pub fn storakers_pair_constant(hollomon: Hollomon) -> f64 {
    let m = hollomon.exponent;
    2f64.powf(1.0 - 0.5 * m)
        * 3f64.powf(1.0 - m)
        * std::f64::consts::PI
        * storakers_c_power(m)
        * hollomon.strength
}

/// The constant C of F_p = C δ^{1+m/2} (eq 16).
pub fn storakers_prefactor(effective_radius: f64, hollomon: Hollomon) -> f64 {
    prefactor(
        storakers_pair_constant(hollomon),
        effective_radius,
        hollomon.exponent,
    )
}

/// C from the pair's factor: `pair_constant` R*^{1−m/2}.
fn prefactor(pair_constant: f64, effective_radius: f64, m: f64) -> f64 {
    pair_constant * effective_radius.powf(1.0 - 0.5 * m)
}

/// Plastic force and stiffness on the virgin branch (eqs 16, 22).
pub fn storakers_plastic(overlap: f64, effective_radius: f64, hollomon: Hollomon) -> (f64, f64) {
    plastic(
        overlap,
        storakers_prefactor(effective_radius, hollomon),
        hollomon.exponent,
    )
}

/// F_p = C δ^{1+m/2} and its slope (1 + m/2) C δ^{m/2}.
fn plastic(overlap: f64, c: f64, m: f64) -> (f64, f64) {
    let rise = overlap.powf(0.5 * m);
    (c * rise * overlap, (1.0 + 0.5 * m) * c * rise)
}

/// The Hertz branch K w^{3/2} and its slope at elastic overlap w = δ − δ_res (zero
/// once the contact has unloaded through δ_res).
fn elastic_branch(elastic: f64, k: f64) -> (f64, f64) {
    if elastic <= 0.0 {
        return (0.0, 0.0);
    }
    (k * elastic.powf(1.5), 1.5 * k * elastic.sqrt())
}

/// Inverse of eq 16: the overlap at which the plastic force equals `force`.
pub fn storakers_overlap_at_force(force: f64, effective_radius: f64, hollomon: Hollomon) -> f64 {
    let c = storakers_prefactor(effective_radius, hollomon);
    (force / c).powf(1.0 / (1.0 + 0.5 * hollomon.exponent))
}

/// The Storåkers law at one contact, with the pair's R*, E* and σ0*, m fixed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StorakersContact {
    /// Effective radius R*, m.
    pub effective_radius: f64,
    /// Effective modulus E* of the elastic (Hertz) unloading branch and cap, Pa.
    pub effective_modulus: f64,
    /// Effective Hollomon constants σ0* and m of the pair.
    pub hollomon: Hollomon,
    /// `storakers_pair_constant(hollomon)`.
    pub pair_constant: f64,
    /// Whether the loading force is min(F_p, F_Hertz).
    pub min_with_hertz: bool,
}

impl StorakersContact {
    /// C of eq 16 for this contact's R*.
    fn prefactor(&self) -> f64 {
        prefactor(
            self.pair_constant,
            self.effective_radius,
            self.hollomon.exponent,
        )
    }

    /// Force and stiffness on the virgin (loading) branch.
    pub fn loading(&self, overlap: f64) -> (f64, f64) {
        self.loading_with(self.prefactor(), overlap)
    }

    /// `loading` with C given.
    fn loading_with(&self, c: f64, overlap: f64) -> (f64, f64) {
        let plastic = plastic(overlap, c, self.hollomon.exponent);
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
        self.residual_with(self.prefactor(), self.hertz_constant(), max_overlap)
    }

    /// `residual_overlap` with C and K given.
    fn residual_with(&self, c: f64, k: f64, max_overlap: f64) -> f64 {
        let peak = self.loading_with(c, max_overlap).0;
        max_overlap - (peak / k).powf(2.0 / 3.0)
    }

    /// Tangent of the elastic branch at its top, where unloading from `max_overlap`
    /// starts: k_unl = ∛(6 R* E*² F_max) (eq 20).
    pub fn unloading_stiffness(&self, max_overlap: f64) -> f64 {
        let peak = self.loading(max_overlap).0;
        (6.0 * self.effective_radius * self.effective_modulus.powi(2) * peak).cbrt()
    }

    /// Force and tangent stiffness at `overlap` given the largest overlap so far
    /// (the step of `StorakersHistory` with nothing derived yet).
    pub fn response(&self, overlap: f64, max_overlap: f64) -> (f64, f64) {
        Derived::default().response(self, overlap, max_overlap)
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

/// One head-on impact on a Storåkers contact, from its curves (`StorakersContact::impact`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StorakersImpact {
    /// Largest overlap δ_max of the impact, m.
    pub max_overlap: f64,
    /// Largest normal force F_max of the impact, N.
    pub max_force: f64,
    /// From first touch until the overlap closes, s.
    pub duration: f64,
    /// Rebound speed over approach speed.
    pub restitution: f64,
}

/// Simpson intervals of the impact's quadratures: the loading integrand has a kink
/// where `min_with_hertz` changes branch, so the rule is second order there; 20 000
/// intervals leave 1e-9 (the test `impact_below_the_crossing_is_hertz`).
const IMPACT_INTERVALS: usize = 20_000;

impl StorakersContact {
    /// The overlap δ* where the plastic force C δ^{1+m/2} meets Hertz's K δ^{3/2}:
    /// δ* = (C/K)^{2/(1−m)} (the plastic force is the larger below it). `None` for
    /// m ≥ 1, where the curves do not cross that way.
    pub fn hertz_crossing_overlap(&self) -> Option<f64> {
        let m = self.hollomon.exponent;
        (m < 1.0).then(|| {
            let c = storakers_prefactor(self.effective_radius, self.hollomon);
            (c / self.hertz_constant()).powf(2.0 / (1.0 - m))
        })
    }

    /// The approach speed at which a head-on impact of effective mass `mass` reaches
    /// δ* on Hertz's curve: ½ m* v*² = 2/5 K δ*^{5/2}. Below it a `min_with_hertz`
    /// impact is Hertz's.
    pub fn hertz_crossing_speed(&self, mass: f64) -> Option<f64> {
        let d = self.hertz_crossing_overlap()?;
        Some((0.8 * self.hertz_constant() * d.powf(2.5) / mass).sqrt())
    }

    /// Work done on the loading branch from touch to `overlap`, and the work from
    /// `overlap` to `max_overlap` (the kinetic energy left there), the latter written so
    /// that it keeps its digits as `overlap` nears `max_overlap`.
    fn loading_work(&self, overlap: f64, max_overlap: f64) -> (f64, f64) {
        let n = 2.0 + 0.5 * self.hollomon.exponent;
        let c = storakers_prefactor(self.effective_radius, self.hollomon);
        let k = self.hertz_constant();
        // ∫_a^b x^p dx = b^{p+1}/(p+1) · (1 − (a/b)^{p+1}), with expm1 for a → b.
        let between = |a: f64, b: f64, power: f64| {
            if b <= a {
                0.0
            } else {
                b.powf(power) / power * -(power * (a / b).ln()).exp_m1()
            }
        };
        let plastic = |a: f64, b: f64| c * between(a, b, n);
        let hertz = |a: f64, b: f64| k * between(a, b, 2.5);
        let crossing = if self.min_with_hertz {
            self.hertz_crossing_overlap().unwrap_or(f64::INFINITY)
        } else {
            0.0
        };
        let work = |a: f64, b: f64| {
            hertz(a.min(crossing), b.min(crossing)) + plastic(a.max(crossing), b.max(crossing))
        };
        (work(0.0, overlap), work(overlap, max_overlap))
    }

    /// The head-on impact at approach speed `speed` of bodies of effective mass `mass`
    /// (Rojek eqs 16–20): δ_max where the loading work reaches ½ m* v²; loading time
    /// ∫ dδ/δ' with δ' = √(2 W_left(δ)/m*), by Simpson's rule after δ = δ_max (1 − s²),
    /// which removes the 1/√ at the turning point; unloading along Hertz through
    /// (δ_max, F_max) of elastic overlap w = δ − δ_res from w_max = (F_max/K)^{2/3}:
    /// rebound ½ m* (e v)² = 2/5 K (w_max^{5/2} − w_end^{5/2}) and time ∫ dw/w', where
    /// w_end = max(−δ_res, 0) (the contact opens at δ = 0 with force left when
    /// δ_res < 0); then the flight through the permanent set, δ_res/(e v).
    /// `None` when the law gives no finite impact (no modulus or no Hollomon constants).
    pub fn impact(&self, mass: f64, speed: f64) -> Option<StorakersImpact> {
        let k = self.hertz_constant();
        if !(k > 0.0 && self.hollomon.strength > 0.0 && speed > 0.0 && mass > 0.0) {
            return None;
        }
        let energy = 0.5 * mass * speed * speed;
        // Bisection on the loading work (monotone in δ), from a bracket that holds it.
        let mut hi = (energy / k).powf(0.4).max(1e-300);
        while self.loading_work(hi, hi).0 < energy {
            hi *= 2.0;
        }
        let mut lo = 0.0;
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if self.loading_work(mid, mid).0 < energy {
                lo = mid
            } else {
                hi = mid
            }
        }
        let max_overlap = 0.5 * (lo + hi);
        let max_force = self.loading(max_overlap).0;
        let loading_time = crate::quadrature::simpson(
            |s| {
                if s == 0.0 {
                    // The limit of 2 δ_max s/√(2 W_left/m*): W_left → F_max δ_max s².
                    return 2.0 * max_overlap * (mass / (2.0 * max_force * max_overlap)).sqrt();
                }
                let left = self
                    .loading_work(max_overlap * (1.0 - s * s), max_overlap)
                    .1;
                2.0 * max_overlap * s / (2.0 * left / mass).sqrt()
            },
            0.0,
            1.0,
            IMPACT_INTERVALS,
        );
        let elastic_max = (max_force / k).powf(2.0 / 3.0);
        let residual = max_overlap - elastic_max;
        let elastic_end = (-residual).max(0.0);
        let rebound = (0.8 * k * (elastic_max.powf(2.5) - elastic_end.powf(2.5)) / mass).sqrt();
        // w = w_max (1 − s²) from s = 0 to s_end; 0.4 K w_max^{5/2}(1 − (1 − s²)^{5/2}) is
        // the kinetic energy gained by s.
        let s_end = (1.0 - elastic_end / elastic_max).sqrt();
        let unloading_time = crate::quadrature::simpson(
            |s| {
                let gained = 0.4 * k * elastic_max.powf(2.5) * -(2.5 * (-s * s).ln_1p()).exp_m1();
                if s == 0.0 {
                    return 2.0 * elastic_max * (mass / (2.0 * max_force * elastic_max)).sqrt();
                }
                2.0 * elastic_max * s / (2.0 * gained / mass).sqrt()
            },
            0.0,
            s_end,
            IMPACT_INTERVALS,
        );
        Some(StorakersImpact {
            max_overlap,
            max_force,
            duration: loading_time + unloading_time + residual.max(0.0) / rebound,
            restitution: rebound / speed,
        })
    }
}

/// What a Storåkers contact remembers: δ_max. It also carries what the step derives
/// from δ_max and the pair (C, K and δ_res), which change far less often than the
/// overlap: a contact that unloads then costs one power a step instead of four.
/// Only δ_max is saved; the rest is derived again on the first step after a restore.
#[derive(Clone, Copy, Debug, Default, serde::Serialize, serde::Deserialize)]
pub struct StorakersHistory {
    /// Largest overlap δ_max reached so far, m.
    pub max_overlap: f64,
    #[serde(skip)]
    derived: Derived,
}

impl StorakersHistory {
    /// A contact that has reached `max_overlap` and derived nothing yet.
    pub fn new(max_overlap: f64) -> Self {
        StorakersHistory {
            max_overlap,
            derived: Derived::default(),
        }
    }
}

/// Two histories are the same contact state when their δ_max agree; what is derived
/// from it is a cache.
impl PartialEq for StorakersHistory {
    fn eq(&self, other: &Self) -> bool {
        self.max_overlap == other.max_overlap
    }
}

impl crate::contact::model::ContactState for StorakersHistory {}

/// C and K of one contact, and δ_res for one δ_max: the law's step in one place,
/// for a contact that carries them and for one computed afresh alike.
#[derive(Clone, Copy, Debug)]
struct Derived {
    /// R*, E*, the pair constant and m they were derived for (NaN: not yet).
    key: [f64; 4],
    prefactor: f64,
    hertz_constant: f64,
    /// The δ_max that `residual` belongs to (NaN: not yet).
    residual_at: f64,
    residual: f64,
}

impl Default for Derived {
    fn default() -> Self {
        Derived {
            key: [f64::NAN; 4],
            prefactor: f64::NAN,
            hertz_constant: f64::NAN,
            residual_at: f64::NAN,
            residual: f64::NAN,
        }
    }
}

impl Derived {
    /// Force and tangent stiffness at `overlap` given δ_max: the virgin branch at
    /// δ ≥ δ_max, else the Hertz branch through (δ_max, F_max). C, K and δ_res are
    /// derived only when what they depend on has changed (a NaN key never matches,
    /// so a fresh state derives them).
    #[inline(always)]
    fn response(&mut self, law: &StorakersContact, overlap: f64, max_overlap: f64) -> (f64, f64) {
        let key = [
            law.effective_radius,
            law.effective_modulus,
            law.pair_constant,
            law.hollomon.exponent,
        ];
        if key != self.key {
            *self = Derived {
                key,
                prefactor: law.prefactor(),
                hertz_constant: law.hertz_constant(),
                ..Derived::default()
            };
        }
        if overlap >= max_overlap {
            return law.loading_with(self.prefactor, overlap);
        }
        if self.residual_at != max_overlap {
            self.residual = law.residual_with(self.prefactor, self.hertz_constant, max_overlap);
            self.residual_at = max_overlap;
        }
        elastic_branch(overlap - self.residual, self.hertz_constant)
    }
}

/// The Storåkers law; `min_with_hertz` caps the plastic force by Hertz (Martin et
/// al. 2003). The Hollomon constants σ0* and m come from the pair.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Storakers {
    /// Cap the plastic loading force by the Hertz force (default false).
    #[serde(default)]
    pub min_with_hertz: bool,
}

impl Storakers {
    /// The law at one contact: R*, E* and the pair's Hollomon constants.
    pub fn at(&self, effective_radius: f64, pair: &PairProperties) -> StorakersContact {
        let hollomon = pair.hollomon.unwrap_or(Hollomon {
            strength: 0.0,
            exponent: 0.0,
        });
        StorakersContact {
            effective_radius,
            effective_modulus: pair.effective_modulus.unwrap_or(0.0),
            hollomon,
            pair_constant: pair
                .law_constant
                .unwrap_or_else(|| storakers_pair_constant(hollomon)),
            min_with_hertz: self.min_with_hertz,
        }
    }
}

impl NormalModel for Storakers {
    type State = StorakersHistory;

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
        state: &mut StorakersHistory,
    ) -> NormalResponse {
        state.max_overlap = state.max_overlap.max(overlap);
        let (force, stiffness) =
            state
                .derived
                .response(&self.at(r, pair), overlap, state.max_overlap);
        NormalResponse { force, stiffness }
    }

    fn stiffness(
        &self,
        overlap: f64,
        r: f64,
        pair: &PairProperties,
        state: &StorakersHistory,
    ) -> f64 {
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
        state: &StorakersHistory,
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

    fn energy(&self, overlap: f64, r: f64, pair: &PairProperties, state: &StorakersHistory) -> f64 {
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

    /// Calibrated with the Hertz cap only: pure Storåkers has no impact closed form.
    fn pair_constant(&self, pair: &PairProperties) -> Option<f64> {
        pair.hollomon.map(storakers_pair_constant)
    }

    fn error_model(&self, damping: Option<&Damping>) -> Option<&'static str> {
        (self.min_with_hertz && damping.is_none()).then_some("storakers_min_hertz")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn nial(m: f64, min_with_hertz: bool) -> StorakersContact {
        let e: f64 = 183e9;
        // NiAl, Rojek Table 2 (clippy mistakes 0.318 for 1/π).
        #[allow(clippy::approx_constant)]
        let nu: f64 = 0.318;
        let hollomon = Hollomon {
            strength: 800e6 * (e / 800e6).powf(m) * 2f64.powf(-m),
            exponent: m,
        };
        StorakersContact {
            effective_radius: 5e-6,
            effective_modulus: e / (2.0 * (1.0 - nu * nu)),
            hollomon,
            pair_constant: storakers_pair_constant(hollomon),
            min_with_hertz,
        }
    }

    /// The step through the history's cache gives the same bits as a step with
    /// nothing derived yet, over loading, unloading past δ_res, reloading, and a change
    /// of R* (the cache must notice it), for both variants and m = 0, 0.1, 0.2.
    #[test]
    fn the_history_cache_keeps_every_bit() {
        use proptest::prelude::*;
        let overlaps = proptest::collection::vec(0.0f64..3e-7, 1..60);
        proptest!(|(steps in overlaps, m in 0usize..3, capped: bool, switch in 0usize..60)| {
            let reference = nial(0.1 * m as f64, capped);
            let pair = PairProperties {
                effective_modulus: Some(reference.effective_modulus),
                effective_shear_modulus: None,
                hollomon: Some(reference.hollomon),
                law_constant: Some(reference.pair_constant),
                friction: 0.0,
            };
            let law = Storakers { min_with_hertz: capped };
            let mut state = StorakersHistory::default();
            for (k, &overlap) in steps.iter().enumerate() {
                let r = if k < switch { 5e-6 } else { 2e-6 };
                let cached = law.response(overlap, 0.0, r, &pair, &mut state);
                let afresh = law.at(r, &pair).response(overlap, state.max_overlap);
                prop_assert_eq!(cached.force.to_bits(), afresh.0.to_bits());
                prop_assert_eq!(cached.stiffness.to_bits(), afresh.1.to_bits());
            }
        });
    }

    /// The effective mass of two 10 µm NiAl spheres, kg.
    fn nial_mass() -> f64 {
        0.5 * 5910.0 * 4.0 / 3.0 * std::f64::consts::PI * 1e-5f64.powi(3)
    }

    /// Below the crossing speed a `min_with_hertz` impact never leaves Hertz's curve:
    /// Johnson's δ_max and duration (hertz.rs), e = 1, within the quadratures' 1e-9.
    #[test]
    fn impact_below_the_crossing_is_hertz() {
        use crate::contact::normal::hertz::{hertz_contact_duration, hertz_max_overlap};
        let s = nial(0.2, true);
        let m = nial_mass();
        let v = 0.5 * s.hertz_crossing_speed(m).unwrap();
        let i = s.impact(m, v).unwrap();
        let (r, e) = (s.effective_radius, s.effective_modulus);
        assert_relative_eq!(
            i.max_overlap,
            hertz_max_overlap(m, v, r, e),
            max_relative = 1e-12
        );
        assert_relative_eq!(
            i.duration,
            hertz_contact_duration(m, v, r, e),
            max_relative = 1e-9
        );
        assert_relative_eq!(i.restitution, 1.0, max_relative = 1e-12);
    }

    /// Above it, the loading work and the unloading's return balance as the law says:
    /// ½ m* v² = W(δ_max), and the rebound's energy is the Hertz branch's 2/5 K w^{5/2}.
    #[test]
    fn impact_above_the_crossing_balances_energy() {
        let s = nial(0.2, true);
        let m = nial_mass();
        let v = 5.0 * s.hertz_crossing_speed(m).unwrap();
        let i = s.impact(m, v).unwrap();
        assert_relative_eq!(
            s.loading_work(i.max_overlap, i.max_overlap).0,
            0.5 * m * v * v,
            max_relative = 1e-12
        );
        let w = i.max_overlap - s.residual_overlap(i.max_overlap);
        let k = s.hertz_constant();
        assert_relative_eq!(
            0.5 * m * (i.restitution * v).powi(2),
            0.4 * k * w.powf(2.5),
            max_relative = 1e-12
        );
        assert!(i.restitution < 1.0 && s.residual_overlap(i.max_overlap) > 0.0);
    }

    /// Pure Storåkers rebounds faster than it arrives below about the crossing speed:
    /// its Hertz unloading through (δ_max, F_max) is softer than the loading, and
    /// returns more work than the loading took. As v → 0 the unloading force stays near
    /// F_max (w_max ≫ δ_max) while the loading took F_max δ_max/(2 + m/2), so
    /// e → √(2 + m/2) = 1.449 for m = 0.2.
    #[test]
    fn pure_storakers_rebounds_faster_than_it_arrives() {
        let s = nial(0.2, false);
        let m = nial_mass();
        let v_star = s.hertz_crossing_speed(m).unwrap();
        assert!(s.impact(m, 0.3 * v_star).unwrap().restitution > 1.0);
        let slow = s.impact(m, 1e-6 * v_star).unwrap().restitution;
        assert!((slow / 2.1f64.sqrt() - 1.0).abs() < 0.05, "e = {slow}");
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
