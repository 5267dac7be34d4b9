//! The error model of the accuracy setting: for each law with an impact closed form,
//! the relative error of each impact quantity after one head-on impact integrated
//! with step Δt,
//!
//!   error ≈ C (Δt/t_c)^p,   t_c the closed-form contact duration,
//!
//! with p and C measured by `tamp study accuracy-calibration` (the table and the
//! command that wrote it: docs/accuracy-cost.md). C is the envelope over the
//! calibration's runs (the largest error/(Δt/t_c)^p over its steps and the places
//! first touch falls in a step), so the model bounds the error it was fitted to
//! rather than averaging it. p ≈ 2 where the force is smooth at first touch (velocity
//! Verlet is second order); p ≈ 1 where it jumps (a dashpot's γ v at first touch).

use crate::contact::ContactLaw;

/// The largest Δt/t_c the model gives: the calibration's coarser steps are not yet
/// on the power law (some laws stop earlier: `calibration::largest_ratio`).
pub const LARGEST_RATIO: f64 = 0.125;

/// One law's error for one quantity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErrorTerm {
    /// The impact quantity, one of [`QUANTITIES`](super::impact::QUANTITIES).
    pub quantity: &'static str,
    /// C: the envelope of error / (Δt/t_c)^p over the calibration's runs.
    pub c: f64,
    /// p: the order of the error in Δt/t_c (about 2 for a smooth force at first touch,
    /// about 1 for a jump).
    pub p: f64,
}

impl ErrorTerm {
    /// The step over the contact duration at which this term equals `accuracy`.
    pub fn step_ratio(&self, accuracy: f64) -> f64 {
        (accuracy / self.c).powf(1.0 / self.p)
    }
}

/// The calibrated model of one law (with its damping, if any).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErrorModel {
    /// How `tamp study accuracy-calibration` names it.
    pub law: &'static str,
    /// One term per impact quantity, in the order of [`QUANTITIES`](super::impact::QUANTITIES).
    pub terms: [ErrorTerm; 4],
}

impl ErrorModel {
    /// The largest Δt/t_c at which every quantity is within `accuracy`.
    pub fn step_ratio(&self, accuracy: f64) -> f64 {
        self.terms
            .iter()
            .map(|t| t.step_ratio(accuracy))
            .fold(super::calibration::largest_ratio(self.law), f64::min)
    }

    /// The predicted error of each quantity at Δt/t_c = `ratio`.
    pub fn predicted(&self, ratio: f64) -> [f64; 4] {
        self.terms.map(|t| t.c * ratio.powf(t.p))
    }
}

/// The model of the scene's law, as its normal law names it beside the damping
/// (`NormalModel::error_model`); `None` where the calibration has none (laws with no
/// impact closed form, pure Storåkers, cohesion). Friction does not enter: it does not
/// change a head-on impact.
pub fn for_law(law: &ContactLaw) -> Option<&'static ErrorModel> {
    // The error models are calibrated on dashpots that pull at the end of a contact;
    // the clamp ends the contact earlier, at another restitution.
    if law.no_pull {
        return None;
    }
    if law.cohesion.is_some() {
        return None;
    }
    let name = law.normal.error_model(law.damping.as_ref())?;
    super::calibration::MODELS.iter().find(|m| m.law == name)
}
