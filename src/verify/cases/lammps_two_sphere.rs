//! Cross-check against LAMMPS 22 Jul 2025 (update 4), `pair_style granular`: two equal
//! spheres meet head-on, `hertz/material` with `damping coeff_restitution` (tamp's
//! `liggghts_restitution`: LAMMPS derives the same γ_n from e as LIGGGHTS,
//! contact/damping/mod.rs `CriticalFraction::lammps`) and with `damping tsuji` (tamp's
//! `tsuji`, contact/damping/tsuji.rs), once per restitution LAMMPS was run with, and
//! with `damping mass_velocity` and `viscoelastic` (the kinds of their names,
//! contact/damping/viscous.rs: a pair's m* and R*, where the oblique wall impacts check a
//! wall's). The
//! reference values are read from `reference_data/lammps/<case>/results.csv` (written by
//! `reference_data/lammps/run_two_sphere.sh` from the LAMMPS dumps, with the LIGGGHTS
//! case's extractor); the case refuses to compare when the scene and the recorded
//! LAMMPS inputs disagree. tamp's side is measured with the extractor's definitions:
//! interpolated overlap zero crossings, largest sampled overlap, full-step velocities.

use super::liggghts_inputs::Mismatches;
use super::probe::against_peer;
use crate::collision::binary_collision;
use crate::contact::damping::{Damping, LiggghtsRestitution, MassVelocity, Tsuji, Viscoelastic};
use crate::error::{Result, TampError};
use crate::scene::{self, Scene};
use crate::verify::{CaseContext, Measured};
use serde::Deserialize;

/// One LAMMPS run, as `two_sphere_extract.py` writes it: `model` is the LAMMPS damping
/// model (`characteristic_velocity` and `steps_in_contact` are not read).
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
    restitution: f64,
    contact_duration: f64,
    max_overlap: f64,
}

/// Differences between the scene and the inputs LAMMPS ran with.
fn mismatches(scene: &Scene, row: &Row) -> Mismatches {
    let mut out = Mismatches::default();
    out.check_material_and_step(
        scene,
        row.density,
        row.youngs_modulus,
        row.poisson_ratio,
        row.time_step,
    );
    out.check_head_on_pair(scene, row.radius, row.initial_gap, row.relative_speed);
    out
}

/// tamp's damping for a LAMMPS damping model with `damp` in the normal model's damp
/// slot (e for `coeff_restitution` and `tsuji`, η_n0 for `mass_velocity` and
/// `viscoelastic`), and the quantities' tag.
fn damping(model: &str, damp: f64) -> Result<(Damping, String)> {
    let restitution = damp;
    match model {
        "coeff_restitution" => Ok((
            Damping::LiggghtsRestitution(LiggghtsRestitution { restitution }),
            format!("{model}_e{damp}"),
        )),
        "tsuji" => Ok((
            Damping::Tsuji(Tsuji { restitution }),
            format!("{model}_e{damp}"),
        )),
        "mass_velocity" => Ok((
            Damping::MassVelocity(MassVelocity { eta_n0: damp }),
            format!("{model}_eta{damp:e}"),
        )),
        "viscoelastic" => Ok((
            Damping::Viscoelastic(Viscoelastic { eta_n0: damp }),
            format!("{model}_eta{damp:e}"),
        )),
        other => Err(TampError::Other(format!(
            "results.csv: LAMMPS damping model '{other}' has no tamp law in this case"
        ))),
    }
}

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    let mut out = Vec::new();
    for row in ctx.peer_results::<Row>("lammps")? {
        let (law, tag) = damping(&row.model, row.restitution_in)?;
        let run = format!("damping {} {}", row.model, row.restitution_in);
        mismatches(&base, &row).refuse_any(&run)?;
        let mut s = base.clone();
        s.contact.damping = Some(law);
        let mut sim = scene::build(&s)?.sim;
        let c = binary_collision(&mut sim, 0, 1, 1_000_000)?;
        out.extend(against_peer(
            &c,
            &tag,
            [row.restitution, row.contact_duration, row.max_overlap],
        ));
    }
    Ok(out)
}
