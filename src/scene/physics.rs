//! The scene-wide physics a scene may switch on: `gravity`, `periodic` axes,
//! `rotation` of the particles and a `growth` stage (Zhong 2009 §6.1). Each is absent
//! unless the scene asks for it, and then costs only the scene that does.
//!
//! ```json
//! "gravity": [0, 0, -9.81], "periodic": {"x": [0, 0.02], "y": [0, 0.02]},
//! "rotation": {"inertia_scale": 10}
//! ```

use super::schema::Scene;
use crate::error::Errors;
use serde::{Deserialize, Serialize};

/// Periodic axes, each `[lo, hi]` in m; absent axes are open.
#[derive(Clone, Debug, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct PeriodicSpec {
    /// The period along x, `[lo, hi]`, m.
    #[serde(default)]
    pub x: Option<[f64; 2]>,
    /// The period along y, `[lo, hi]`, m.
    #[serde(default)]
    pub y: Option<[f64; 2]>,
    /// The period along z, `[lo, hi]`, m.
    #[serde(default)]
    pub z: Option<[f64; 2]>,
}

impl PeriodicSpec {
    /// The three axes in the order x, y, z.
    pub fn axes(&self) -> [Option<[f64; 2]>; 3] {
        [self.x, self.y, self.z]
    }
}

/// Growth stage of Zhong 2009 §6.1: radii grow to their targets, gravity off.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct GrowthSpec {
    /// Time over which radii grow to their targets, s.
    pub duration: f64,
    /// Starting radius as a fraction of the target, in [0, 1).
    #[serde(default)]
    pub initial_fraction: f64,
}

/// Rotational degrees of freedom of the particles.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct RotationSpec {
    /// Multiplies every moment of inertia (Rojek 2016 §3.4 uses 10).
    #[serde(default = "one")]
    pub inertia_scale: f64,
}

fn one() -> f64 {
    1.0
}

/// Gravity finite, periods of positive length, growth and rotation in range.
pub fn validate(scene: &Scene, e: &mut Errors) {
    if let Some(g) = &scene.gravity {
        e.finite3("gravity", g);
    }
    if let Some(per) = &scene.periodic {
        for (a, axis) in per.axes().iter().enumerate() {
            let name = ["x", "y", "z"][a];
            if let Some([lo, hi]) = axis
                && !(lo.is_finite() && hi.is_finite() && hi > lo)
            {
                e.push(
                    format!("periodic.{name}"),
                    format!("must be [lo, hi] with hi > lo, finite, got [{lo:e}, {hi:e}]"),
                );
            }
        }
        if per.axes().iter().all(Option::is_none) {
            e.push("periodic", "must name at least one axis (x, y or z)");
        }
    }
    if let Some(g) = &scene.growth {
        e.positive("growth.duration", g.duration);
        if !(g.initial_fraction >= 0.0 && g.initial_fraction < 1.0) {
            e.push(
                "growth.initial_fraction",
                format!("must be in [0, 1), got {}", g.initial_fraction),
            );
        }
    }
    if let Some(r) = &scene.rotation {
        e.positive("rotation.inertia_scale", r.inertia_scale);
    }
}
