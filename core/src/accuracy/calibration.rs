//! The calibration of the error model: the setting of the impacts `tamp study
//! accuracy-calibration` runs (the impacts themselves are the checking crate's
//! `impact_trial::calibration_trials`), and the constants it measured from them,
//! checked in. Two equal steel
//! spheres (R = 1 mm, ρ = 7800 kg/m³, E = 200 GPa, ν = 0.3) meet head-on at 1 m/s;
//! the linear laws take k = 10⁶ N/m (Walton–Braun k₂/k₁ = 1.25, 2, 4 and 10), the
//! damped linear law restitutions 0.9, 0.5 and 0.1, the damped Hertz law the ξ that
//! LIGGGHTS's relation gives for 0.9, 0.5 and 0.1, Hertz with a constant γ_n and
//! Kuwabara–Kono the γ_n and A whose impact rebounds at 0.9, 0.5 and 0.1. Storåkers with
//! `min_with_hertz` is calibrated on two 10 µm NiAl spheres (Rojek 2016 Table 2) at
//! v/v* = 0.5, 1.5, 3 and 10, v* the speed at which the loading leaves Hertz's curve.
//! The case `accuracy_on_demand` checks the model on impacts this calibration did not
//! use.

use super::model::{ErrorModel, ErrorTerm, LARGEST_RATIO};
use crate::contact::damping::liggghts::LiggghtsModel;

/// Radius of the calibration's steel spheres, m.
pub const RADIUS: f64 = 1e-3;

/// The smallest restitution of the damped linear calibration: a damped contact below
/// it is beyond the model (its first-order error grows with the damping).
pub const DAMPED_RESTITUTION_MIN: f64 = 0.1;
/// The stiffness ratios k₂/k₁ of the Walton–Braun calibration. Its step is measured in
/// the stiffer branch's π√(m*/k₂) (`Impact::time_scale`), so the constants hold across
/// ratios; the largest calibrated is the largest the model covers.
pub const WALTON_BRAUN_RATIOS: [f64; 4] = [1.25, 2.0, 4.0, 10.0];
/// The largest k₂/k₁ calibrated: beyond it an explicit accuracy is refused.
pub const WALTON_BRAUN_RATIO_MAX: f64 = 10.0;

/// The strongest damping of the damped Hertz calibration: the ξ LIGGGHTS's relation
/// gives for e = 0.1 (the law's own rebound is then 0.1: that relation is the law's,
/// `damped_hertz`).
pub fn hertz_damped_xi_max() -> f64 {
    LiggghtsModel::Hertz.critical_fraction(DAMPED_RESTITUTION_MIN)
}

/// Density of the calibration's steel, kg/m³.
pub const DENSITY: f64 = 7800.0;
/// Stiffness of the calibration's linear laws, N/m.
pub const STIFFNESS: f64 = 1e6;

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
