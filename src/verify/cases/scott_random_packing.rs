//! Random close packing of equal spheres, the anchor of Zhong 2009 §6.1 (Fig 4 at
//! N_s = 0): monodisperse frictionless spheres with Zhong's Table 1 contact
//! parameters (linear hysteretic law, k_n = 1e7 N/m, γ_n = 0.7; ρ = 7800 kg/m³;
//! R = 5 cm, his large spheres) are placed at random in a 1:1:2 container of twice
//! their volume with periodic side faces and a floor, grown without gravity for
//! 0.2 s, then settled under gravity until t = 3 s. Zhong grows from zero radius;
//! here the spheres start at half size from non-overlapping positions, because two
//! random centres that nearly coincide overlap by more than half a radius as they
//! grow, and tamp's overlap guard stops such a run (it did, with 10⁴ spheres:
//! docs/paper-discrepancies.md §18).
//!
//! Measured from the last recorded frame (centres and radii) and the scene's periodic
//! faces: the packing fraction of the interior slab, 4 diameters above the floor
//! (where the wall-induced layering has died out) to 4 diameters below the highest
//! sphere top (the loose surface), counted exactly per periodic cell
//! (`measure::packing`). Reference: Scott & Kilgour 1969 (J. Phys. D 2, 863),
//! 0.637 for shaken, extrapolated beds; Zhong reports 0.636 with 10⁴ spheres.
//!
//! The same scene is rerun with Cundall–Strack friction μ = 0.5 (k_s = 1e7 N/m as in
//! Table 1) and rotation. Friction arrests the bed before it reaches close packing,
//! so its fraction must lie between random loose packing (0.555, Onoda & Liniger
//! 1990, the limit of vanishing gravity) and random close packing (0.637).

use crate::contact::tangential::{CundallStrack, TangentialLaw};
use crate::error::Result;
use crate::measure::{Region, packing::packing_fraction};
use crate::particles::Vec3;
use crate::scene::Scene;
use crate::scene::physics::space;
use crate::scene::schema::{FrictionSpec, RotationSpec};
use crate::verify::{CaseContext, Measured};

/// Packing fraction of the interior of the bed settled in run `label`.
fn interior_packing_fraction(ctx: &CaseContext, label: &str, scene: &Scene) -> Result<f64> {
    let (_, last) = ctx.first_and_last(label, scene)?;
    let position: Vec<Vec3> = last.bodies.iter().map(|b| b.position).collect();
    let radius: Vec<f64> = last.bodies.iter().map(|b| b.radius).collect();
    let d = 2.0 * radius.iter().copied().fold(0.0, f64::max);
    let top = last
        .bodies
        .iter()
        .map(|b| b.position.z + b.radius)
        .fold(f64::NEG_INFINITY, f64::max);
    let region = Region::Slab {
        axis: 2,
        lo: 4.0 * d,
        hi: top - 4.0 * d,
    };
    packing_fraction(&position, &radius, &region, &space(scene.periodic.as_ref()))
}

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let scene = ctx.scene()?;
    let frictionless = interior_packing_fraction(ctx, "frictionless", &scene)?;
    let mut frictional = scene.clone();
    frictional.contact.tangential = Some(FrictionSpec {
        law: TangentialLaw::CundallStrack(CundallStrack { stiffness: 1e7 }),
        friction: 0.5,
        friction_pairs: Vec::new(),
    });
    frictional.rotation = Some(RotationSpec {
        inertia_scale: 1.0,
        inertia_radius: Default::default(),
    });
    let with_friction = interior_packing_fraction(ctx, "frictional", &frictional)?;
    Ok(vec![
        Measured::new("packing_fraction", frictionless, 0.637),
        // The interval [0.555, 0.637] as its centre and half-width (see the JSON).
        Measured::new("frictional_packing_fraction", with_friction, 0.596),
    ])
}
