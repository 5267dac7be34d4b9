//! `die_press_cycle`: the whole press cycle (`process::press_cycle`) of a small NiAl
//! compact, checked against the force balances that hold whatever the packing:
//! - **Janssen** at the peak, for the scene's specimen and one of twice as many
//!   particles in the same die (twice the H/D): the pressure transmission ratio
//!   p_lower/p_upper against exp(−4 μ_w K H/D), with K = σ_r/σ̄_z measured from the die
//!   wall's radial force and the two punches;
//! - **Coulomb at the die wall**: the wall's axial friction never exceeds μ_w times
//!   its radial force;
//! - **ejection onset**: the largest push of the lower punch (averaged over 100 steps),
//!   the breakaway, against μ_w times the die wall's residual radial force once the
//!   upper punch is released, plus the compact's weight and its mass times the punch's
//!   acceleration on its speed ramp (the force balance on the compact when every wall
//!   contact slides).
//!
//! - **unloading returns what was stored**: the same specimen pressed as a frictionless,
//!   damped Hertz compact and released; the work the particles do on the withdrawing
//!   punch against the energy its contacts stored at the peak, less what they still
//!   store and what the dashpots took (the energy book), with the change of the
//!   particles' kinetic energy.
//!
//! The cycle is a process of stage changes (a punch released from its load, another
//! set moving) that a resolved scene cannot state, so the case runs on tamp.

use crate::contact::normal::{Hertz, NormalLaw};
use crate::error::{Result, TampError};
use crate::process::die_compaction::{self, Specimen};
use crate::process::die_compaction_file::DieCompactionFile;
use crate::process::press_cycle::{self, Cycle, Stage};
use crate::scene::schema::ContactSpec;
use crate::verify::{CaseContext, Measured};
use std::f64::consts::PI;

/// Fill, flatten, press and go through the cycle.
fn cycle(file: &DieCompactionFile) -> Result<(Specimen, Cycle)> {
    let specimen = die_compaction::prepare(file, true)?;
    let fixed = die_compaction::press_scene(file, &specimen)?
        .time_step
        .fixed;
    let (pressing, sim) = die_compaction::press(file, &specimen, true, None, 0, &mut |_| Ok(()))?;
    let cycle = press_cycle::run(file, &specimen, &pressing, sim, fixed, true)?;
    Ok((specimen, cycle))
}

/// The cycle's records as CSV, each row labelled with its specimen.
fn write_series(ctx: &CaseContext, runs: &[(&str, &Cycle)]) -> Result<()> {
    crate::output::write_atomic(
        &ctx.report_dir.join(format!("{}_series.csv", ctx.spec.name)),
        press_cycle::labelled_series_csv("specimen", runs).as_bytes(),
    )
}

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let file = ctx.die_compaction()?;
    if file.die_compaction.eject.is_none() {
        return Err(TampError::Other(
            "die_press_cycle: the scene must eject the compact".into(),
        ));
    }
    // Twice the particles in the same die, pressed and released: its ejection, the
    // longest stage, measures nothing the case checks.
    let mut tall = file.clone();
    tall.die_compaction.particles.count *= 2;
    tall.die_compaction.eject = None;
    tall.die_compaction.relax = None;
    // The same specimen pressed and released as a frictionless, damped Hertz compact.
    let mut elastic = file.clone();
    elastic.scene.contact = ContactSpec {
        normal: NormalLaw::Hertz(Hertz {}),
        tangential: None,
        ..file.scene.contact.clone()
    };
    elastic.die_compaction.eject = None;
    elastic.die_compaction.relax = None;
    elastic.validate()?;
    let runs = ctx.map(&[&file, &tall, &elastic], |f| cycle(f));
    let mut done = Vec::new();
    for r in runs {
        done.push(r?);
    }
    let (short, tall_run, hertz) = (&done[0], &done[1], &done[2]);
    write_series(
        ctx,
        &[
            ("short", &short.1),
            ("tall", &tall_run.1),
            ("frictionless_hertz", &hertz.1),
        ],
    )?;

    let dc = &file.die_compaction;
    let mu_w = file
        .scene
        .contact
        .friction_between(&dc.particles.material, &dc.wall_material);
    let area = PI * (0.5 * dc.die_diameter).powi(2);
    let mut out = Vec::new();
    for (label, (_, c)) in [("short", short), ("tall", tall_run)] {
        let s = &c.summary;
        let h_over_d = s.peak_height / dc.die_diameter;
        out.push(Measured::new(
            &format!("janssen_transmission_ratio_{label}"),
            s.transmission_ratio,
            (-4.0 * mu_w * s.radial_to_axial_ratio * h_over_d).exp(),
        ));
        let peak = c
            .records
            .iter()
            .rfind(|r| r.stage == Stage::Press)
            .ok_or_else(|| TampError::Other("die_press_cycle: no pressing records".into()))?;
        out.push(Measured::new(
            &format!("wall_friction_over_coulomb_{label}"),
            peak.die_friction * area / (mu_w * peak.die_radial_force),
            1.0,
        ));
    }
    let s = &short.1.summary;
    let missing = || TampError::Other("die_press_cycle: the cycle did not eject".into());
    let mass = {
        let density = file
            .scene
            .materials
            .iter()
            .find(|m| m.name == dc.particles.material)
            .and_then(|m| m.density)
            .unwrap_or(0.0);
        let p = &short.0.particles;
        p.iter()
            .map(|x| density * 4.0 / 3.0 * PI * x.radius.powi(3))
            .sum::<f64>()
    };
    let g = file.scene.gravity.map_or(0.0, |g| g[2].abs());
    // The punch's acceleration where the push was largest: speed/ramp while its speed
    // rises, which the sliding compact follows.
    let eject = dc.eject.as_ref().ok_or_else(missing)?;
    let ramp = eject.ramp(short.0.h0);
    let peak_at = s.peak_ejection_at.ok_or_else(missing)?;
    let acceleration = match ramp > 0.0 && peak_at < 0.5 * eject.speed * ramp {
        true => eject.speed / ramp,
        false => 0.0,
    };
    out.push(Measured::new(
        "ejection_onset_force",
        s.peak_ejection_force.ok_or_else(missing)?,
        mu_w * s.residual_radial_force.ok_or_else(missing)? + mass * (g + acceleration),
    ));
    // What the frictionless Hertz compact gives back to the withdrawing punch: what its
    // contacts stored at the peak, less what they still store and what the dashpots
    // took (the energy book), with the change of the particles' kinetic energy.
    let h = &hertz.1.summary;
    let missing = || TampError::Other("die_press_cycle: the Hertz compact was not released".into());
    out.push(Measured::new(
        "unloading_work_frictionless_hertz",
        h.unloading_work.ok_or_else(missing)?,
        h.returned_by_book().ok_or_else(missing)?,
    ));
    Ok(out)
}
