//! Closed forms of one head-on impact, for the laws whose source gives them. They
//! are what the accuracy setting's error model is calibrated and checked against
//! (`tamp study accuracy-calibration`, the case `accuracy_on_demand`), so they are
//! written from the laws' sources, not from tamp's integration:
//!
//! - linear spring (Zhong 2009 model I, eqs 7–9): t_c = π/ω, e = exp(−β t_c) and
//!   δ_max of δ(t) = (v/ω) e^{−βt} sin ωt, ω = √(k/m* − β²), β = γ_n/(2m*);
//!   F(t) = k δ + γ_n dδ/dt, largest at first touch (γ_n v) or where dF/dt = 0;
//! - Hertz (Johnson 1985 §11.4): δ_max = (15 m* v²/(16 E* √R*))^{2/5},
//!   t_c = 3.2180655 (m*/k̃)^{2/5} v^{−1/5}, F_max = 4/3 E* √R* δ_max^{3/2}, e = 1;
//! - Hertz with the dashpot ξ · 2√(m* k_n) (`critical_fraction`, and the
//!   `liggghts_restitution` and `tsuji` kinds that run as one): the four quantities
//!   scale with δ_s = (m* v²/K)^{2/5}, δ_s/v and K δ_s^{3/2} (K = 4/3 E*√R*), times
//!   numbers that depend on ξ alone, from the dimensionless equation of
//!   `damped_hertz` (no closed form exists; that module says how it is solved);
//! - Hertz with a constant γ_n, and Kuwabara–Kono (F = K(δ^{3/2} + 3/2 A δ^{1/2} δ'),
//!   clamped at 0): the same units, times numbers that depend on one parameter per
//!   impact, c = γ_n δ_s/(m* v) and c = (3/2) A v/δ_s, from the same equation with
//!   the dashpots' powers of δ (`damped_hertz`);
//! - Storåkers with `min_with_hertz` (Rojek 2016 eqs 16–20): the energy balance on the
//!   loading branch min(C δ^{1+m/2}, K δ^{3/2}) gives δ_max and F_max, the loading time
//!   is a quadrature, and unloading is Hertz through (δ_max, F_max): rebound and
//!   unloading time in closed form, then the flight through the permanent set
//!   (`StorakersContact::impact`);
//! - Walton–Braun (Zhong eq 16): δ_max = v √(m*/k₁), F_max = k₁ δ_max,
//!   e = √(k₁/k₂); the force lasts a quarter period on each branch,
//!   (π/2)(√(m*/k₁) + √(m*/k₂)), and ends at the permanent set δ₀ = δ_max (1 − k₁/k₂),
//!   which the bodies then leave at e v: the overlap lasts δ₀/(e v) longer;
//! - Thornton 1997 (elastic–perfectly-plastic, `unloading: thornton_1997`), with
//!   V = v/v_y: δ_max/δ_y = 1/3 + (2√5/15)√(6V² − 1), F_max = F_y (3x − 1)/2 on the
//!   plastic line, e = Thornton's printed formula (Hertz for V ≤ 1); its duration has
//!   no closed form, it is the sum of four phases on the law's own curves, one of them
//!   a quadrature (`ThorntonContact::impact_duration`).
//!
//! The contact duration is the time the overlap is positive (what the probe measures).

use super::damped_hertz::{Dashpot, critical_fraction_c, unit_impact};
use crate::contact::ContactLaw;
use crate::contact::damping::{Damping, critical_damping};
use crate::contact::normal::hertz::{hertz_contact_duration, hertz_force, hertz_max_overlap};
use crate::contact::normal::linear::LinearCollision;
use crate::contact::normal::thornton::{
    Thornton, Unloading, thornton_1997_restitution, yield_velocity,
};
use crate::contact::normal::{KuwabaraKono, Linear, NormalLaw, Storakers, WaltonBraun};
use crate::material::PairProperties;
use std::f64::consts::PI;

/// The impact quantities the accuracy setting promises.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Impact {
    /// The time the error model measures the step in, s: the contact duration, except
    /// for Walton–Braun, where it is the stiffer branch's π√(m*/k₂) (that branch is
    /// the shortest part of the contact, and the step must resolve it at any k₂/k₁).
    pub time_scale: f64,
    /// From first touch to separation, s.
    pub duration: f64,
    /// Largest overlap δ_max, m.
    pub max_overlap: f64,
    /// Largest normal contact force, N.
    pub max_force: f64,
    /// Normal rebound speed over approach speed.
    pub restitution: f64,
}

/// The names of `Impact`'s quantities, in the order of `Impact::values`.
pub const QUANTITIES: [&str; 4] = [
    "max_overlap",
    "max_force",
    "contact_duration",
    "rebound_velocity",
];

impl Impact {
    /// The quantities in the order of [`QUANTITIES`].
    pub fn values(&self) -> [f64; 4] {
        [
            self.max_overlap,
            self.max_force,
            self.duration,
            self.restitution,
        ]
    }

    /// |measured − exact| / exact, quantity by quantity (the rebound velocity's
    /// relative error is the restitution's).
    pub fn relative_errors(&self, exact: &Impact) -> [f64; 4] {
        let (m, e) = (self.values(), exact.values());
        std::array::from_fn(|q| ((m[q] - e[q]) / e[q]).abs())
    }
}

/// The closed form of a head-on impact at approach speed `v` for bodies of effective
/// mass `m` and radius `r` (`None`: the law, or its combination with damping or
/// cohesion, has none here).
pub fn closed_form(
    law: &ContactLaw,
    m: f64,
    r: f64,
    pair: &PairProperties,
    v: f64,
) -> Option<Impact> {
    if law.cohesion.is_some() {
        return None;
    }
    match (law.normal, law.damping) {
        (NormalLaw::Linear(Linear { stiffness: k }), damping) => {
            let gamma = match damping {
                None => 0.0,
                Some(Damping::Constant(c)) => c.gamma_n,
                Some(Damping::MassVelocity(c)) => c.eta_n0 * m,
                Some(Damping::CriticalFraction(c)) => c.xi * critical_damping(m, k),
                Some(_) => return None,
            };
            let c = LinearCollision::new(k, m, gamma);
            if c.beta >= c.omega0 || c.beta.is_nan() {
                return None; // overdamped: no rebound
            }
            Some(Impact {
                time_scale: c.contact_duration(),
                duration: c.contact_duration(),
                max_overlap: c.max_overlap(v),
                max_force: linear_max_force(&c, k, gamma, v),
                restitution: c.restitution(),
            })
        }
        (NormalLaw::Hertz(_), None) => {
            let e = pair.effective_modulus?;
            let max_overlap = hertz_max_overlap(m, v, r, e);
            Some(Impact {
                time_scale: hertz_contact_duration(m, v, r, e),
                duration: hertz_contact_duration(m, v, r, e),
                max_overlap,
                max_force: hertz_force(max_overlap, r, e),
                restitution: 1.0,
            })
        }
        (
            NormalLaw::WaltonBraun(WaltonBraun {
                loading_stiffness: k1,
                unloading_stiffness: k2,
            }),
            None,
        ) => {
            let max_overlap = v * (m / k1).sqrt();
            let restitution = (k1 / k2).sqrt();
            let set = max_overlap * (1.0 - k1 / k2);
            Some(Impact {
                time_scale: PI * (m / k1.max(k2)).sqrt(),
                duration: PI / 2.0 * ((m / k1).sqrt() + (m / k2).sqrt()) + set / (restitution * v),
                max_overlap,
                max_force: k1 * max_overlap,
                restitution,
            })
        }
        (NormalLaw::Hertz(_), Some(d @ (Damping::Constant(_) | Damping::MassVelocity(_)))) => {
            let gamma_n = match d {
                Damping::MassVelocity(d) => d.eta_n0 * m,
                Damping::Constant(d) => d.gamma_n,
                _ => unreachable!("matched above"),
            };
            let k = 4.0 / 3.0 * pair.effective_modulus? * r.sqrt();
            let overlap = (m * v * v / k).powf(0.4);
            damped_hertz(
                Dashpot::Constant,
                gamma_n * overlap / (m * v),
                k,
                overlap,
                v,
            )
        }
        (NormalLaw::Hertz(_), Some(_)) => {
            let xi = hertz_dashpot_fraction(law)?;
            let k = 4.0 / 3.0 * pair.effective_modulus? * r.sqrt();
            let overlap = (m * v * v / k).powf(0.4);
            damped_hertz(
                Dashpot::CriticalFraction,
                critical_fraction_c(xi),
                k,
                overlap,
                v,
            )
        }
        (NormalLaw::KuwabaraKono(KuwabaraKono { dissipation_time }), None) => {
            let k = 4.0 / 3.0 * pair.effective_modulus? * r.sqrt();
            let overlap = (m * v * v / k).powf(0.4);
            let c = 1.5 * dissipation_time * v / overlap;
            damped_hertz(Dashpot::KuwabaraKono, c, k, overlap, v)
        }
        (
            NormalLaw::Storakers(
                law @ Storakers {
                    min_with_hertz: true,
                },
            ),
            None,
        ) => {
            pair.effective_modulus?;
            pair.hollomon?;
            let i = law.at(r, pair).impact(m, v)?;
            Some(Impact {
                time_scale: i.duration,
                duration: i.duration,
                max_overlap: i.max_overlap,
                max_force: i.max_force,
                restitution: i.restitution,
            })
        }
        (
            NormalLaw::Thornton(
                law @ Thornton {
                    unloading: Unloading::Thornton1997,
                    ..
                },
            ),
            None,
        ) => {
            pair.effective_modulus?;
            let c = law.at(r, pair);
            let v_y = yield_velocity(c.yield_pressure, c.effective_modulus, r, m);
            let max_overlap = c.impact_max_overlap(m, v);
            let duration = c.impact_duration(m, v);
            Some(Impact {
                time_scale: duration,
                duration,
                max_overlap,
                max_force: c.loading(max_overlap).0,
                restitution: thornton_1997_restitution(v / v_y),
            })
        }
        _ => None,
    }
}

/// The impact of a Hertz spring K δ^{3/2} and a dashpot of parameter `c`, from its
/// unit impact in the units δ_s = `overlap`, δ_s/v and K δ_s^{3/2}.
fn damped_hertz(dashpot: Dashpot, c: f64, k: f64, overlap: f64, v: f64) -> Option<Impact> {
    let u = unit_impact(dashpot, c)?;
    Some(Impact {
        time_scale: u.duration * overlap / v,
        duration: u.duration * overlap / v,
        max_overlap: u.max_overlap * overlap,
        max_force: u.max_force * k * overlap.powf(1.5),
        restitution: u.restitution,
    })
}

/// ξ of a Hertz law's dashpot ξ · 2√(m* k_n), whichever kind the scene wrote it as
/// (`None`: no such dashpot; a constant γ_n is not a fraction of critical: its
/// parameter c = γ_n δ_s/(m* v) depends on the impact).
pub fn hertz_dashpot_fraction(law: &ContactLaw) -> Option<f64> {
    match (law.normal, law.damping?) {
        (NormalLaw::Hertz(_), Damping::CriticalFraction(c)) => Some(c.xi),
        (NormalLaw::Hertz(_), Damping::LiggghtsRestitution(d)) => {
            Some(d.with(&law.normal).ok()?.xi)
        }
        (NormalLaw::Hertz(_), Damping::Tsuji(d)) => Some(d.with(&law.normal).ok()?.xi),
        _ => None,
    }
}

/// Largest of F(t) = k δ + γ dδ/dt over the contact: at first touch (γ v) when F
/// falls from there, else at the root of dF/dt = k δ' + γ δ'' in the first half
/// period, found by bisection.
fn linear_max_force(c: &LinearCollision, k: f64, gamma: f64, v: f64) -> f64 {
    let (w, b) = (c.damped_frequency(), c.beta);
    // δ' = v e^{−βt}(cos ωt − (β/ω) sin ωt); δ'' = v e^{−βt}(−2β cos ωt + (β²−ω²)/ω sin ωt).
    let d1 = |t: f64| v * (-b * t).exp() * ((w * t).cos() - b / w * (w * t).sin());
    let d2 = |t: f64| {
        v * (-b * t).exp() * (-2.0 * b * (w * t).cos() + (b * b - w * w) / w * (w * t).sin())
    };
    let d0 = |t: f64| v / w * (-b * t).exp() * (w * t).sin();
    let force = |t: f64| k * d0(t) + gamma * d1(t);
    let slope = |t: f64| k * d1(t) + gamma * d2(t);
    let at_touch = gamma * v;
    if slope(0.0) <= 0.0 {
        return at_touch;
    }
    // dF/dt > 0 at touch and < 0 at the quarter period of the undamped part.
    let (mut lo, mut hi) = (0.0, PI / w);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if slope(mid) > 0.0 { lo = mid } else { hi = mid }
    }
    force(0.5 * (lo + hi)).max(at_touch)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn law(normal: NormalLaw, damping: Option<Damping>) -> ContactLaw {
        ContactLaw::new(normal, damping, None, None)
    }

    fn pair() -> PairProperties {
        crate::contact::registry::pair()
    }

    #[test]
    fn undamped_linear_force_peaks_at_k_times_max_overlap() {
        let l = law(NormalLaw::Linear(Linear { stiffness: 4.0 }), None);
        let i = closed_form(&l, 1.0, 1.0, &pair(), 3.0).unwrap();
        // ω = 2: δ_max = v/ω = 1.5, F_max = 6, t_c = π/2.
        assert_relative_eq!(i.max_overlap, 1.5, max_relative = 1e-15);
        assert_relative_eq!(i.max_force, 6.0, max_relative = 1e-12);
        assert_relative_eq!(i.duration, PI / 2.0, max_relative = 1e-15);
        assert_eq!(i.restitution, 1.0);
    }

    /// The damped peak force against the peak of F(t) sampled finely.
    #[test]
    fn damped_linear_force_peak_matches_sampling() {
        use crate::contact::damping::Constant;
        for gamma in [0.1, 1.0, 3.0] {
            let (k, m, v) = (4.0, 1.0, 3.0);
            let l = law(
                NormalLaw::Linear(Linear { stiffness: k }),
                Some(Damping::Constant(Constant { gamma_n: gamma })),
            );
            let i = closed_form(&l, m, 1.0, &pair(), v).unwrap();
            let c = LinearCollision::new(k, m, gamma);
            let (w, b) = (c.damped_frequency(), c.beta);
            let sampled = (0..=200_000)
                .map(|n| {
                    let t = n as f64 / 200_000.0 * PI / w;
                    let d = v / w * (-b * t).exp() * (w * t).sin();
                    let dd = v * (-b * t).exp() * ((w * t).cos() - b / w * (w * t).sin());
                    k * d + gamma * dd
                })
                .fold(f64::MIN, f64::max);
            assert_relative_eq!(i.max_force, sampled, max_relative = 1e-9);
        }
    }
}
