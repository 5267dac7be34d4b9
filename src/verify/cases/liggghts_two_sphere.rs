//! Cross-check against LIGGGHTS 3.8.0: two equal spheres meet head-on, damping from a
//! restitution coefficient (`liggghts_restitution`), once per restitution that
//! LIGGGHTS was run with. The reference values are read from
//! `reference_data/liggghts/<case>/results.csv` (written by
//! `reference_data/liggghts/run_two_sphere.sh` from the LIGGGHTS dumps); the case
//! refuses to compare when the scene and the recorded LIGGGHTS inputs disagree.
//! tamp's side is measured with the same definitions as `two_sphere_extract.py`:
//! interpolated overlap zero crossings, largest sampled overlap, full-step velocities.

use super::liggghts_inputs::Mismatches;
use super::probe::against_peer;
use crate::collision::binary_collision;
use crate::contact::damping::liggghts::hooke_stiffness;
use crate::contact::damping::{Damping, LiggghtsRestitution};
use crate::contact::normal::{Linear, NormalLaw};
use crate::error::Result;
use crate::material::{Material, effective_mass, effective_modulus, effective_radius};
use crate::measure::region::ball_volume;
use crate::scene::{self, Scene};
use crate::verify::{CaseContext, Measured};
use serde::Deserialize;

/// One LIGGGHTS run, as `two_sphere_extract.py` writes it (`steps_in_contact` is for
/// people and is not read).
#[derive(Debug, Deserialize)]
struct Row {
    model: String,
    restitution_in: f64,
    time_step: f64,
    youngs_modulus: f64,
    poisson_ratio: f64,
    density: f64,
    radius: f64,
    relative_speed: f64,
    initial_gap: f64,
    characteristic_velocity: f64,
    restitution: f64,
    contact_duration: f64,
    max_overlap: f64,
}

pub fn hertz(ctx: &CaseContext) -> Result<Vec<Measured>> {
    run(ctx, "hertz")
}

pub fn hooke(ctx: &CaseContext) -> Result<Vec<Measured>> {
    run(ctx, "hooke")
}

/// Differences between the scene and the inputs LIGGGHTS ran with.
fn mismatches(scene: &Scene, row: &Row, model: &str) -> Mismatches {
    let mut out = Mismatches::default();
    if row.model != model {
        out.0
            .push(format!("model: case {model}, LIGGGHTS {}", row.model));
    }
    out.check_material_and_step(
        scene,
        row.density,
        row.youngs_modulus,
        row.poisson_ratio,
        row.time_step,
    );
    out.check_head_on_pair(scene, row.radius, row.initial_gap, row.relative_speed);
    if let NormalLaw::Linear(Linear { stiffness }) = scene.contact.normal {
        // model hooke: the scene's k_n must be LIGGGHTS's stiffness at characteristicVelocity.
        let steel = Material {
            name: "LIGGGHTS type 1".into(),
            density: Some(row.density),
            rigid: false,
            youngs_modulus: Some(row.youngs_modulus),
            poisson_ratio: Some(row.poisson_ratio),
            hollomon: None,
        };
        let mass = row.density * ball_volume(row.radius);
        let k = hooke_stiffness(
            effective_mass(mass, mass),
            effective_radius(row.radius, row.radius),
            effective_modulus(&steel, &steel).expect("both elastic constants are given"),
            row.characteristic_velocity,
        );
        out.check(
            "contact.normal.stiffness vs model hooke's k_n",
            stiffness,
            k,
        );
    }
    out
}

fn run(ctx: &CaseContext, model: &str) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    let mut out = Vec::new();
    for row in ctx.liggghts_results()? {
        mismatches(&base, &row, model).refuse_any(&format!("e = {}", row.restitution_in))?;
        let mut s = base.clone();
        s.contact.damping = Some(Damping::LiggghtsRestitution(LiggghtsRestitution {
            restitution: row.restitution_in,
        }));
        let mut sim = scene::build(&s)?.sim;
        let c = binary_collision(&mut sim, 0, 1, 1_000_000)?;
        out.extend(against_peer(
            &c,
            &format!("e{}", row.restitution_in),
            [row.restitution, row.contact_duration, row.max_overlap],
        ));
    }
    Ok(out)
}
