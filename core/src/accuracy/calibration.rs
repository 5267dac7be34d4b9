//! The calibration of the error model: the impacts `tamp study accuracy-calibration`
//! runs, and the constants it measured from them, checked in. Two equal steel
//! spheres (R = 1 mm, ρ = 7800 kg/m³, E = 200 GPa, ν = 0.3) meet head-on at 1 m/s;
//! the linear laws take k = 10⁶ N/m (Walton–Braun k₂/k₁ = 1.25, 2, 4 and 10), the
//! damped linear law restitutions 0.9, 0.5 and 0.1, the damped Hertz law the ξ that
//! LIGGGHTS's relation gives for 0.9, 0.5 and 0.1, Hertz with a constant γ_n and
//! Kuwabara–Kono the γ_n and A whose impact rebounds at 0.9, 0.5 and 0.1. Storåkers with
//! `min_with_hertz` is calibrated on two 10 µm NiAl spheres (Rojek 2016 Table 2) at
//! v/v* = 0.5, 1.5, 3 and 10, v* the speed at which the loading leaves Hertz's curve.
//! The case `accuracy_on_demand` checks the model on impacts this calibration did not
//! use.

use super::damped_hertz::{Dashpot, c_for_restitution};
use super::model::{ErrorModel, ErrorTerm, LARGEST_RATIO};
use super::trial::{Partner, Trial};
use crate::contact::damping::liggghts::LiggghtsModel;
use crate::contact::normal::linear::LinearCollision;
use crate::error::Result;
use serde_json::json;

const RADIUS: f64 = 1e-3;

/// The smallest restitution of the damped linear calibration: a damped contact below
/// it is beyond the model (its first-order error grows with the damping).
pub const DAMPED_RESTITUTION_MIN: f64 = 0.1;
/// The stiffness ratios k₂/k₁ of the Walton–Braun calibration. Its step is measured in
/// the stiffer branch's π√(m*/k₂) (`Impact::time_scale`), so the constants hold across
/// ratios; the largest calibrated is the largest the model covers.
pub const WALTON_BRAUN_RATIOS: [f64; 4] = [1.25, 2.0, 4.0, 10.0];
pub const WALTON_BRAUN_RATIO_MAX: f64 = 10.0;

/// The strongest damping of the damped Hertz calibration: the ξ LIGGGHTS's relation
/// gives for e = 0.1 (the law's own rebound is then 0.1: that relation is the law's,
/// `damped_hertz`).
pub fn hertz_damped_xi_max() -> f64 {
    LiggghtsModel::Hertz.critical_fraction(DAMPED_RESTITUTION_MIN)
}
const DENSITY: f64 = 7800.0;
const STIFFNESS: f64 = 1e6;

/// Thornton's limiting contact pressure of the calibration, Pa: about a hardened
/// steel's (v_y = 2.3 cm/s for the calibration's spheres).
pub const THORNTON_YIELD_PRESSURE: f64 = 1e9;
/// The approach speeds of the Thornton calibration over the yield velocity: one elastic
/// (Hertz) impact and plastic ones over the range of `thornton_restitution`.
pub const THORNTON_SPEED_RATIOS: [f64; 5] = [0.5, 1.5, 3.0, 10.0, 30.0];
/// The largest v/v_y calibrated: beyond it an explicit accuracy is refused.
pub const THORNTON_SPEED_RATIO_MAX: f64 = 30.0;

/// The approach speeds of the Storåkers (`min_with_hertz`) calibration over the speed
/// v* at which the loading leaves Hertz's curve (`StorakersContact::hertz_crossing_speed`):
/// one Hertz impact and plastic ones up to δ_max ≈ 0.26 R*.
pub const STORAKERS_SPEED_RATIOS: [f64; 4] = [0.5, 1.5, 3.0, 10.0];
/// The largest v/v* calibrated: beyond it an explicit accuracy is refused.
pub const STORAKERS_SPEED_RATIO_MAX: f64 = 10.0;

/// The largest Δt/t_c a law's model gives: `model::LARGEST_RATIO`, except for the laws
/// whose dashpot grows with the overlap or the damping is strong at the speed-dependent
/// end of their calibration (Kuwabara–Kono, Hertz with a constant γ_n): at t_c/8 their
/// explicit dashpot is near its stability limit (Kuwabara–Kono at e = 0.1 rebounds
/// faster than it arrived), at t_c/4 a constant γ_n can hold the bodies together, so
/// their models stop at t_c/16, where the errors are on the power law.
pub fn largest_ratio(law: &str) -> f64 {
    match law {
        "kuwabara_kono" | "hertz_constant_damped" => 0.5 * LARGEST_RATIO,
        _ => LARGEST_RATIO,
    }
}

/// Each law's calibration impacts, by the law's name in `MODELS`.
pub fn trials() -> Result<Vec<(&'static str, Trial)>> {
    let steel = json!([{"name": "steel", "density": DENSITY, "youngs_modulus": 2e11, "poisson_ratio": 0.3}]);
    let trial = |name, contact| Trial {
        name,
        materials: steel.clone(),
        contact,
        radius: RADIUS,
        partner: Partner::Sphere(RADIUS),
        speed: 1.0,
    };
    let m_eff = 0.5 * DENSITY * 4.0 / 3.0 * std::f64::consts::PI * RADIUS.powi(3);
    let damped = |name, e: f64| {
        let gamma_n = LinearCollision::gamma_for_restitution(STIFFNESS, m_eff, e);
        trial(
            name,
            json!({"normal": {"law": "linear", "stiffness": STIFFNESS},
                   "damping": {"kind": "constant", "gamma_n": gamma_n}}),
        )
    };
    let walton_braun = |name, ratio: f64| {
        trial(
            name,
            json!({"normal": {"law": "walton_braun", "loading_stiffness": STIFFNESS,
                              "unloading_stiffness": ratio * STIFFNESS}}),
        )
    };
    let hertz_damped = |name, e: f64| {
        trial(
            name,
            json!({"normal": {"law": "hertz"},
                   "damping": {"kind": "critical_fraction",
                               "xi": LiggghtsModel::Hertz.critical_fraction(e)}}),
        )
    };
    let thornton = |name, v_over_vy| {
        trial(
            name,
            json!({"normal": {"law": "thornton", "yield_pressure": THORNTON_YIELD_PRESSURE}}),
        )
        .at_yield_ratio(v_over_vy)
    };
    // The speed-dependent dashpots at the c whose unit impact rebounds at e, for the
    // calibration's pair at 1 m/s (δ_s = (m* v²/K)^{2/5}).
    let e_star = 2e11 / (2.0 * (1.0 - 0.3f64.powi(2)));
    let k_hertz = 4.0 / 3.0 * e_star * (0.5 * RADIUS).sqrt();
    let overlap_scale = (m_eff / k_hertz).powf(0.4);
    let kuwabara_kono = |name, e: f64| {
        let c = c_for_restitution(Dashpot::KuwabaraKono, e, 20.0);
        trial(
            name,
            json!({"normal": {"law": "kuwabara_kono",
                              "dissipation_time": c * overlap_scale / 1.5}}),
        )
    };
    let hertz_constant = |name, e: f64| {
        let c = c_for_restitution(Dashpot::Constant, e, 1.2);
        trial(
            name,
            json!({"normal": {"law": "hertz"},
                   "damping": {"kind": "constant", "gamma_n": c * m_eff / overlap_scale}}),
        )
    };
    // NiAl, Rojek Table 2 (clippy mistakes ν = 0.318 for 1/π).
    #[allow(clippy::approx_constant)]
    let nial = json!([{"name": "NiAl", "density": 5910.0, "youngs_modulus": 183e9,
                       "poisson_ratio": 0.318,
                       "hollomon": {"exponent": 0.2, "yield_stress": 800e6}}]);
    let storakers = |name, ratio| {
        Trial {
            name,
            materials: nial.clone(),
            contact: json!({"normal": {"law": "storakers", "min_with_hertz": true}}),
            radius: 1e-5,
            partner: Partner::Sphere(1e-5),
            speed: 1.0,
        }
        .at_hertz_crossing_ratio(ratio)
    };
    let [s0, s1, s2, s3] = STORAKERS_SPEED_RATIOS;
    let [r0, r1, r2, r3] = WALTON_BRAUN_RATIOS;
    let [t0, t1, t2, t3, t4] = THORNTON_SPEED_RATIOS;
    Ok(vec![
        (
            "linear",
            trial(
                "linear",
                json!({"normal": {"law": "linear", "stiffness": STIFFNESS}}),
            ),
        ),
        ("linear_damped", damped("linear, e = 0.9", 0.9)),
        ("linear_damped", damped("linear, e = 0.5", 0.5)),
        (
            "linear_damped",
            damped("linear, e = 0.1", DAMPED_RESTITUTION_MIN),
        ),
        ("hertz", trial("hertz", json!({"normal": {"law": "hertz"}}))),
        (
            "walton_braun",
            walton_braun("walton_braun, k2 = 1.25 k1", r0),
        ),
        ("walton_braun", walton_braun("walton_braun, k2 = 2 k1", r1)),
        ("walton_braun", walton_braun("walton_braun, k2 = 4 k1", r2)),
        ("walton_braun", walton_braun("walton_braun, k2 = 10 k1", r3)),
        ("hertz_damped", hertz_damped("hertz, xi for e = 0.9", 0.9)),
        ("hertz_damped", hertz_damped("hertz, xi for e = 0.5", 0.5)),
        (
            "hertz_damped",
            hertz_damped("hertz, xi for e = 0.1", DAMPED_RESTITUTION_MIN),
        ),
        ("thornton", thornton("thornton, v = 0.5 v_y", t0)?),
        ("thornton", thornton("thornton, v = 1.5 v_y", t1)?),
        ("thornton", thornton("thornton, v = 3 v_y", t2)?),
        ("thornton", thornton("thornton, v = 10 v_y", t3)?),
        ("thornton", thornton("thornton, v = 30 v_y", t4)?),
        (
            "kuwabara_kono",
            kuwabara_kono("kuwabara_kono, A for e = 0.9", 0.9),
        ),
        (
            "kuwabara_kono",
            kuwabara_kono("kuwabara_kono, A for e = 0.5", 0.5),
        ),
        (
            "kuwabara_kono",
            kuwabara_kono("kuwabara_kono, A for e = 0.1", DAMPED_RESTITUTION_MIN),
        ),
        (
            "hertz_constant_damped",
            hertz_constant("hertz, constant gamma_n for e = 0.9", 0.9),
        ),
        (
            "hertz_constant_damped",
            hertz_constant("hertz, constant gamma_n for e = 0.5", 0.5),
        ),
        (
            "hertz_constant_damped",
            hertz_constant(
                "hertz, constant gamma_n for e = 0.1",
                DAMPED_RESTITUTION_MIN,
            ),
        ),
        (
            "storakers_min_hertz",
            storakers("storakers min_with_hertz, NiAl, v = 0.5 v*", s0)?,
        ),
        (
            "storakers_min_hertz",
            storakers("storakers min_with_hertz, NiAl, v = 1.5 v*", s1)?,
        ),
        (
            "storakers_min_hertz",
            storakers("storakers min_with_hertz, NiAl, v = 3 v*", s2)?,
        ),
        (
            "storakers_min_hertz",
            storakers("storakers min_with_hertz, NiAl, v = 10 v*", s3)?,
        ),
    ])
}

/// The steps of the sweep, as Δt/t_c: 1/4 to 1/1024 by halves.
pub fn step_ratios() -> Vec<f64> {
    (2..=10).map(|k| 0.5f64.powi(k)).collect()
}

/// Where first touch falls within a step, as the initial gap in steps of travel.
pub const TOUCH_PHASES: [f64; 4] = [1.0, 1.25, 1.5, 1.75];

const fn term(quantity: &'static str, c: f64, p: f64) -> ErrorTerm {
    ErrorTerm { quantity, c, p }
}

/// Measured by `tamp study accuracy-calibration --out docs` (docs/accuracy-cost.md).
pub const MODELS: [ErrorModel; 9] = [
    ErrorModel {
        law: "linear",
        terms: [
            term("max_overlap", 1.274, 2.001),
            term("max_force", 1.274, 2.001),
            term("contact_duration", 4.27e-1, 2.002),
            term("rebound_velocity", 1.985, 2.996),
        ],
    },
    ErrorModel {
        law: "linear_damped",
        terms: [
            term("max_overlap", 3.055, 1.001),
            term("max_force", 3.295, 1.0),
            term("contact_duration", 6.856e-1, 1.027),
            term("rebound_velocity", 6.439, 0.997),
        ],
    },
    ErrorModel {
        law: "hertz",
        terms: [
            term("max_overlap", 6.591e-1, 2.04),
            term("max_force", 9.903e-1, 2.04),
            term("contact_duration", 5.839e-1, 2.012),
            term("rebound_velocity", 8.674e-1, 2.523),
        ],
    },
    ErrorModel {
        law: "walton_braun",
        terms: [
            term("max_overlap", 9.954e-1, 2.001),
            term("max_force", 1.277, 2.008),
            term("contact_duration", 6.893e-1, 1.995),
            term("rebound_velocity", 1.121, 1.971),
        ],
    },
    ErrorModel {
        law: "hertz_damped",
        terms: [
            term("max_overlap", 2.457, 1.052),
            term("max_force", 9.082, 1.151),
            term("contact_duration", 1.015, 1.135),
            term("rebound_velocity", 4.247, 1.017),
        ],
    },
    ErrorModel {
        law: "thornton",
        terms: [
            term("max_overlap", 2.406, 2.165),
            term("max_force", 6.467, 1.975),
            term("contact_duration", 4.154, 2.091),
            term("rebound_velocity", 6.784, 2.137),
        ],
    },
    ErrorModel {
        law: "kuwabara_kono",
        terms: [
            term("max_overlap", 5.357, 1.057),
            term("max_force", 2.442e1, 1.228),
            term("contact_duration", 3.645, 1.12),
            term("rebound_velocity", 4.831, 1.071),
        ],
    },
    ErrorModel {
        law: "hertz_constant_damped",
        terms: [
            term("max_overlap", 2.202, 1.0),
            term("max_force", 5.891, 1.265),
            term("contact_duration", 8.626e-1, 1.048),
            term("rebound_velocity", 7.093, 0.972),
        ],
    },
    ErrorModel {
        law: "storakers_min_hertz",
        terms: [
            term("max_overlap", 1.314, 2.06),
            term("max_force", 2.869, 1.983),
            term("contact_duration", 1.166, 2.024),
            term("rebound_velocity", 1.054, 1.916),
        ],
    },
];
