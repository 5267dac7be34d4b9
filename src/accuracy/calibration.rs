//! The calibration of the error model: the impacts `tamp study accuracy-calibration`
//! runs, and the constants it measured from them, checked in. Two equal steel
//! spheres (R = 1 mm, ρ = 7800 kg/m³, E = 200 GPa, ν = 0.3) meet head-on at 1 m/s;
//! the linear laws take k = 10⁶ N/m (Walton–Braun k₂ = 2k₁), the damped linear law
//! restitutions 0.9, 0.5 and 0.1. The case `accuracy_on_demand` checks the model on
//! impacts this calibration did not use.

use super::model::{ErrorModel, ErrorTerm};
use super::trial::{Partner, Trial};
use crate::contact::normal::linear::LinearCollision;
use serde_json::json;

const RADIUS: f64 = 1e-3;

/// The smallest restitution of the damped linear calibration: a damped contact below
/// it is beyond the model (its first-order error grows with the damping).
pub const DAMPED_RESTITUTION_MIN: f64 = 0.1;
/// The stiffness ratio k₂/k₁ of the Walton–Braun calibration, also the largest the
/// model covers: a stiffer unloading branch is a shorter part of the contact, stepped
/// fewer times than the calibration's (at k₂ = 4 k₁ and a requested 1e-2 the peak
/// force came out 1.4e-2 off).
pub const WALTON_BRAUN_RATIO_MAX: f64 = 2.0;
const DENSITY: f64 = 7800.0;
const STIFFNESS: f64 = 1e6;

/// Each law's calibration impacts, by the law's name in `MODELS`.
pub fn trials() -> Vec<(&'static str, Trial)> {
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
    vec![
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
            trial(
                "walton_braun",
                json!({"normal": {"law": "walton_braun", "loading_stiffness": STIFFNESS,
                                  "unloading_stiffness": WALTON_BRAUN_RATIO_MAX * STIFFNESS}}),
            ),
        ),
    ]
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
pub const MODELS: [ErrorModel; 4] = [
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
            term("contact_duration", 3.311e-1, 1.739),
            term("rebound_velocity", 8.657e-1, 2.522),
        ],
    },
    ErrorModel {
        law: "walton_braun",
        terms: [
            term("max_overlap", 1.464, 2.001),
            term("max_force", 2.295, 1.947),
            term("contact_duration", 8.989e-1, 1.988),
            term("rebound_velocity", 2.296, 2.013),
        ],
    },
];
