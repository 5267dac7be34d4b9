//! `die_compaction.fill.method` and `die_compaction.fill.funnel`: how the particles
//! reach the die.
//!
//! Rojek et al. 2016 §5: "A set of 1751 loose particles … randomly distributed in
//! space has been generated and poured through a funnel (Fig. 13a) to a cylindrical
//! container of diameter 58 µm", frictionless Hertz between particles and μ = 0.02 on
//! the walls. The text gives neither the funnel's shape, nor its outlet, nor where it
//! stands, nor a feed rate: the particles are generated at once and the outlet
//! meters them. tamp's funnel therefore has these dimensions, each a field whose
//! default is a choice stated in docs/scene-format.md (D the die diameter):
//!
//! - `outlet_diameter` (0.75 D): the tube must pass the largest particle and fit
//!   inside the die;
//! - `outlet_length` (0.25 D): a short tube below the cone;
//! - `top_diameter` (2 D) and `cone_angle` (60°, the included angle of the Hall
//!   flowmeter funnel of ASTM B212/B213 with which metal powders' poured densities
//!   are measured); the cone must be wider than the die at the top, because the
//!   funnel rests in the die's mouth: the die wall rises to where the cone's radius
//!   equals the die's, so die and funnel close the space the particles fall through;
//! - `outlet_height` (the height of the particles' expected solid volume spread over
//!   the die's cross-section at solid fraction 0.3): where the tube ends above the
//!   floor, which the settled bed must stay below.

use super::die_compaction_file::DieCompactionSpec;
use crate::error::Errors;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// How the particles reach the die in the fill stage (`fill.method`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FillMethod {
    /// A loose column inside the die, settled under gravity.
    #[default]
    SettledColumn,
    /// A loose cloud above a funnel in the die's mouth, poured through it.
    Funnel,
}

impl FillMethod {
    /// Whether this is the default method, which a serialised scene leaves out.
    pub fn is_default(&self) -> bool {
        *self == FillMethod::default()
    }
}

/// The funnel as written; absent fields take the defaults of the module comment.
#[derive(Clone, Debug, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct FunnelSpec {
    /// Inner diameter of the outlet tube, m.
    #[serde(default)]
    pub outlet_diameter: Option<f64>,
    /// Length of the outlet tube, m.
    #[serde(default)]
    pub outlet_length: Option<f64>,
    /// Diameter of the cone's upper rim, m.
    #[serde(default)]
    pub top_diameter: Option<f64>,
    /// Included angle of the cone, degrees.
    #[serde(default)]
    pub cone_angle: Option<f64>,
    /// Height of the outlet's lower end above the die floor, m.
    #[serde(default)]
    pub outlet_height: Option<f64>,
}

/// The funnel's dimensions with the defaults filled in, m and degrees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Funnel {
    /// Inner diameter of the outlet tube, m.
    pub outlet_diameter: f64,
    /// Length of the outlet tube, m.
    pub outlet_length: f64,
    /// Diameter of the cone's upper rim, m.
    pub top_diameter: f64,
    /// Included angle of the cone, degrees.
    pub cone_angle: f64,
    /// Height of the outlet's lower end above the die floor, m.
    pub outlet_height: f64,
}

/// Solid fraction at which the expected solid volume, spread over the die's
/// cross-section, sets the default outlet height (a settled bed is denser, so the
/// outlet clears it).
const OUTLET_CLEAR_FRACTION: f64 = 0.3;

impl Funnel {
    /// The funnel of a die compaction, each absent dimension at its default (module comment).
    pub fn of(dc: &DieCompactionSpec) -> Funnel {
        let f = dc.fill.funnel.clone().unwrap_or_default();
        let d = dc.die_diameter;
        let solid = dc.particles.count as f64 * dc.particles.radius.distribution().mean_volume();
        Funnel {
            outlet_diameter: f.outlet_diameter.unwrap_or(0.75 * d),
            outlet_length: f.outlet_length.unwrap_or(0.25 * d),
            top_diameter: f.top_diameter.unwrap_or(2.0 * d),
            cone_angle: f.cone_angle.unwrap_or(60.0),
            outlet_height: f
                .outlet_height
                .unwrap_or(solid / (OUTLET_CLEAR_FRACTION * 0.25 * PI * d * d)),
        }
    }

    /// Height of the cone, from the outlet tube to the upper rim.
    pub fn cone_height(&self) -> f64 {
        0.5 * (self.top_diameter - self.outlet_diameter)
            / (0.5 * self.cone_angle.to_radians()).tan()
    }

    /// Where the tube meets the cone.
    pub fn knee(&self) -> f64 {
        self.outlet_height + self.outlet_length
    }

    /// Height of the cone's upper rim.
    pub fn top(&self) -> f64 {
        self.knee() + self.cone_height()
    }

    /// Height at which the cone is as wide as the die: the top of the die wall.
    pub fn die_top(&self, die_diameter: f64) -> f64 {
        self.knee()
            + self.cone_height() * (die_diameter - self.outlet_diameter)
                / (self.top_diameter - self.outlet_diameter)
    }
}

pub(super) fn validate(dc: &DieCompactionSpec, e: &mut Errors) {
    let at = |f: &str| format!("die_compaction.fill.funnel.{f}");
    match dc.fill.method {
        FillMethod::SettledColumn => {
            if dc.fill.funnel.is_some() {
                e.push(
                    "die_compaction.fill.funnel",
                    "applies only to fill.method \"funnel\"; set the method or remove the block",
                );
            }
        }
        FillMethod::Funnel => {
            let f = Funnel::of(dc);
            let d = dc.die_diameter;
            let largest = 2.0 * dc.particles.radius.distribution().max_radius();
            if !(f.outlet_diameter > largest && f.outlet_diameter < d) {
                e.push(
                    at("outlet_diameter"),
                    format!(
                        "must exceed the largest particle diameter ({largest:e} m) and be smaller than the die ({d:e} m), got {:e}",
                        f.outlet_diameter
                    ),
                );
            }
            if !(f.top_diameter > d && f.top_diameter.is_finite()) {
                e.push(
                    at("top_diameter"),
                    format!(
                        "must exceed the die diameter ({d:e} m): the funnel rests in the die's mouth, got {:e}",
                        f.top_diameter
                    ),
                );
            }
            if !(f.cone_angle > 0.0 && f.cone_angle < 180.0) {
                e.push(
                    at("cone_angle"),
                    format!(
                        "must be in (0, 180) degrees (included angle of the cone), got {}",
                        f.cone_angle
                    ),
                );
            }
            e.positive(at("outlet_length"), f.outlet_length);
            e.positive(at("outlet_height"), f.outlet_height);
        }
    }
}
