//! The scene-wide physics a scene may switch on: `gravity`, `periodic` axes,
//! `rotation` of the particles and a `growth` stage (Zhong 2009 §6.1). Each is absent
//! unless the scene asks for it, and then costs only the scene that does.
//!
//! ```json
//! "gravity": [0, 0, -9.81], "periodic": {"x": [0, 0.02], "y": [0, 0.02]},
//! "rotation": {"inertia_scale": 10, "inertia_radius": "current"}
//! ```

use super::schema::Scene;
use crate::contact::ContactLaw;
use crate::error::{Errors, Result, TampError};
use crate::generate::pour::Source;
pub use crate::particles::InertiaRadius;
use crate::particles::Particles;
use crate::space::Space;
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
    /// The radius of the moment of inertia 2/5 m R² when radii change during the run.
    #[serde(default, skip_serializing_if = "InertiaRadius::is_initial")]
    pub inertia_radius: InertiaRadius,
}

fn one() -> f64 {
    1.0
}

/// The factor on every moment of inertia: the scene's, or 1 (also without rotation,
/// where the inertia is never used).
pub fn inertia_scale(rotation: Option<&RotationSpec>) -> f64 {
    rotation.map_or(1.0, |r| r.inertia_scale)
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

/// The periodic space of the scene (open along every axis it does not name).
pub fn space(periodic: Option<&PeriodicSpec>) -> Space {
    let mut space = Space::open();
    for (a, axis) in periodic
        .iter()
        .flat_map(|p| p.axes().into_iter().enumerate())
    {
        space.periodic[a] = axis.map(|[lo, hi]| (lo, hi - lo));
    }
    space
}

/// The minimum-image convention needs every interaction range below half the
/// period: L > 2 (2 R_max + skin + reach), R_max counting particles still to be
/// poured. Particles must start inside the periodic interval.
pub fn check_period(
    space: &Space,
    p: &Particles,
    sources: &[Source],
    law: &ContactLaw,
    skin: f64,
) -> Result<()> {
    let r_max = p
        .radius
        .iter()
        .cloned()
        .chain(sources.iter().map(|s| s.radius.max_radius()))
        .fold(0.0, f64::max);
    let range = 2.0 * r_max + skin + law.reach();
    for (a, axis) in space.periodic.iter().enumerate() {
        let Some((lo, length)) = *axis else { continue };
        let name = ["x", "y", "z"][a];
        if length <= 2.0 * range {
            return Err(TampError::input(
                format!("periodic.{name}"),
                format!(
                    "the period {length:e} m must exceed twice the interaction range 2·R_max + skin + cohesion reach = {range:e} m"
                ),
            ));
        }
        let hi = lo + length;
        if let Some(i) = (0..p.len()).find(|&i| !(p.position[i][a] >= lo && p.position[i][a] < hi))
        {
            return Err(TampError::input(
                format!("periodic.{name}"),
                format!(
                    "particle {i} starts outside [{lo:e}, {hi:e}) at {name} = {:e}",
                    p.position[i][a]
                ),
            ));
        }
    }
    Ok(())
}
