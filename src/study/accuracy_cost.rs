//! `tamp study accuracy-cost`: every verification case rerun with its time step
//! scaled (and, for beds large enough that detection matters, with each broad
//! phase), recording each quantity's error against the case's own reference and
//! the wall time the run took.
//!
//! The time step is the one knob every case shares: Δt = α·Δt_cr (Rojek 2016 eq 26),
//! or a fixed step, multiplied by the scale; `run.steps` is divided by it so the
//! simulated time is unchanged (`verify::Variant`). The integrator is not swept
//! (tamp has one, velocity Verlet), nor the damping form: in every case that has
//! damping, the form is part of the model the reference describes.
//!
//! The order of convergence is measured by self-convergence (Richardson): with the
//! quantity Q at steps h, 2h, 4h, p = log₂(|Q(4h) − Q(2h)| / |Q(2h) − Q(h)|). It needs
//! no exact solution, so it also works where the reference carries a model error
//! that no time step removes.

use crate::error::{Result, TampError};
use crate::scene::{self, schema::DetectorSpec};
use crate::verify::{self, CaseSpec, Status, Tier, Variant};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use std::time::Instant;

/// One quantity of one run of a case (the rows of `accuracy-cost/<case>.csv`).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Row {
    pub case: String,
    /// `step` (the time-step sweep) or `broad_phase` (the same step, another detector).
    pub sweep: String,
    pub detector: String,
    pub step_scale: f64,
    /// The step the case's scene runs at, s (empty when the scene cannot be built alone).
    pub dt: Option<f64>,
    /// Δt / Δt_cr (Rojek eq 26), when the scene has an estimate.
    pub alpha: Option<f64>,
    /// Mean wall time of one run of the case, s.
    pub wall_s: f64,
    pub repeats: u32,
    /// pass, fail, unstable or error (the run's status, the same on every row of it).
    pub status: String,
    /// Empty for a run that produced no quantities (then `note` says why).
    pub quantity: String,
    pub value: Option<f64>,
    pub reference: Option<f64>,
    pub error: Option<f64>,
    pub tolerance: Option<f64>,
    pub note: String,
    /// The tamp commit that ran it (a CSV may be older than the page).
    #[serde(default)]
    pub commit: String,
}

/// What `tamp study accuracy-cost` was asked to do.
pub struct Options {
    /// Cases by name; empty means every quick case.
    pub cases: Vec<String>,
    /// Time-step multipliers, largest first.
    pub scales: Vec<f64>,
    /// Directory that receives `accuracy-cost/<case>.csv`, the plots and the page.
    pub out: PathBuf,
    /// A run is repeated until it has taken this long in all, for a stable mean.
    pub min_wall_s: f64,
}

/// Beds with at least this many spheres are also run with each broad phase.
const DETECTOR_SWEEP_MIN_PARTICLES: usize = 200;

/// Cases whose reference is a recorded LIGGGHTS run (reference_data/liggghts/<case>),
/// made at the case's own step: another step would compare against a run that was
/// not made.
fn reference_fixes_the_step(dir: &Path, case: &str) -> bool {
    verify::reference_data_beside(dir)
        .join("liggghts")
        .join(case)
        .is_dir()
}

pub fn run(opts: &Options) -> Result<u8> {
    if opts.scales.is_empty() || opts.scales.iter().any(|s| !(s.is_finite() && *s > 0.0)) {
        return Err(TampError::input(
            "--scales",
            "must be a comma-separated list of positive numbers",
        ));
    }
    let dir = verify::verification_dir();
    let specs = verify::load_specs(&dir)?;
    for n in &opts.cases {
        if !specs.iter().any(|s| &s.name == n) {
            return Err(TampError::input("--case", format!("unknown case '{n}'")));
        }
    }
    let selected: Vec<&CaseSpec> = specs
        .iter()
        .filter(|s| s.scene.is_some())
        .filter(|s| {
            if opts.cases.is_empty() {
                s.tier == Tier::Quick
            } else {
                opts.cases.contains(&s.name)
            }
        })
        .collect();
    let data_dir = opts.out.join("accuracy-cost");
    crate::output::create_dir(&data_dir)?;
    let scratch = std::env::temp_dir().join(format!("tamp-accuracy-cost-{}", std::process::id()));
    crate::output::create_dir(&scratch)?;
    for spec in selected {
        let rows = sweep_case(spec, &dir, &scratch, opts)?;
        super::write_csv(&data_dir.join(format!("{}.csv", spec.name)), &rows)?;
    }
    let _ = std::fs::remove_dir_all(&scratch);
    super::page::write(&opts.out)?;
    Ok(0)
}

fn sweep_case(spec: &CaseSpec, dir: &Path, scratch: &Path, opts: &Options) -> Result<Vec<Row>> {
    let scene_file = dir.join(spec.scene.as_deref().unwrap_or_default());
    let base = super::case_scene(&scene_file)?;
    let particles = scene::build(&base)
        .map(|b| b.sim.state().particles.len() + b.sim.state().still_to_pour())
        .unwrap_or(0);
    let mut variants: Vec<Variant> = if reference_fixes_the_step(dir, &spec.name) {
        vec![Variant::default()]
    } else {
        opts.scales
            .iter()
            .map(|&step_scale| Variant {
                step_scale,
                detector: None,
            })
            .collect()
    };
    if particles >= DETECTOR_SWEEP_MIN_PARTICLES {
        for kind in [DetectorSpec::Cells, DetectorSpec::Multigrid] {
            if kind != base.broad_phase.kind {
                variants.push(Variant {
                    step_scale: 1.0,
                    detector: Some(kind),
                });
            }
        }
    }
    let mut rows = Vec::new();
    for variant in variants {
        eprint!(
            "{:<32} scale {:<6} {:<10}",
            spec.name,
            variant.step_scale,
            detector_name(variant.detector.unwrap_or(base.broad_phase.kind))
        );
        let mut scene = base.clone();
        variant.apply(&mut scene);
        let built = scene::build(&scene).ok();
        let dt = built.as_ref().map(|b| b.sim.dt());
        let alpha = built.as_ref().and_then(|b| {
            b.dt_estimate
                .map(|est| b.sim.dt() / (est / scene.time_step.alpha()))
        });
        drop(built);
        let (result, wall_s, repeats) = timed(spec, dir, scratch, variant, opts.min_wall_s);
        let status = status_of(&result);
        eprintln!(" {status:<8} {wall_s:.3} s");
        let common = Row {
            case: spec.name.clone(),
            sweep: if variant.detector.is_some() {
                "broad_phase"
            } else {
                "step"
            }
            .into(),
            detector: detector_name(variant.detector.unwrap_or(base.broad_phase.kind)).into(),
            step_scale: variant.step_scale,
            dt,
            alpha,
            wall_s,
            repeats,
            status: status.into(),
            quantity: String::new(),
            value: None,
            reference: None,
            error: None,
            tolerance: None,
            note: result.error.clone().unwrap_or_default(),
            commit: crate::GIT_COMMIT.to_string(),
        };
        if result.quantities.is_empty() {
            rows.push(common.clone());
        }
        for q in &result.quantities {
            rows.push(Row {
                quantity: q.name.clone(),
                value: Some(q.value),
                reference: Some(q.reference),
                error: Some(q.error),
                tolerance: Some(q.tolerance),
                ..common.clone()
            });
        }
    }
    Ok(rows)
}

/// Run the case until `min_wall_s` has passed (at least once, at most 1000 times):
/// the cheap cases take microseconds, below what one clock reading resolves.
fn timed(
    spec: &CaseSpec,
    dir: &Path,
    scratch: &Path,
    variant: Variant,
    min_wall_s: f64,
) -> (verify::CaseResult, f64, u32) {
    let started = Instant::now();
    let mut repeats = 0u32;
    loop {
        let result = verify::run_case(
            spec,
            dir,
            scratch,
            None,
            variant,
            &verify::engine::Engine::Tamp,
            verify::engine::peer_record::PeerRuns::Recorded,
            verify::default_jobs(),
        );
        repeats += 1;
        let elapsed = started.elapsed().as_secs_f64();
        if elapsed >= min_wall_s || repeats >= 1000 || result.status == Status::Error {
            return (result, elapsed / repeats as f64, repeats);
        }
    }
}

fn status_of(result: &verify::CaseResult) -> &'static str {
    match result.status {
        Status::Pass => "pass",
        Status::KnownDeviation => "known deviation",
        Status::Fail | Status::UnexpectedPass => "fail",
        Status::Error
            if result
                .error
                .as_deref()
                .is_some_and(|e| e.contains("unstable at step")) =>
        {
            "unstable"
        }
        Status::Error => "error",
        Status::NotExpressible => "not expressible",
    }
}

pub fn detector_name(kind: DetectorSpec) -> &'static str {
    match kind {
        DetectorSpec::Brute => "brute",
        DetectorSpec::Cells => "cells",
        DetectorSpec::Multigrid => "multigrid",
    }
}

/// Richardson's observed order from a quantity at steps h < 2h < 4h
/// (`values[0]` at h). `None` when the differences do not shrink (outside the
/// asymptotic range, or chaotic); `Some(inf)` when the quantity does not change
/// with the step beyond round-off.
pub fn observed_order(values: [f64; 3]) -> Option<f64> {
    let fine = (values[1] - values[0]).abs();
    let coarse = (values[2] - values[1]).abs();
    let scale = values.iter().map(|v| v.abs()).fold(0.0, f64::max);
    if coarse <= 1e-12 * scale {
        return Some(f64::INFINITY);
    }
    if fine <= 1e-13 * scale {
        // The coarse pair differs, the fine pair does not: faster than any order we
        // can resolve.
        return Some(f64::INFINITY);
    }
    let p = (coarse / fine).log2();
    (p.is_finite() && p > 0.0).then_some(p)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn second_order_sequence_reads_two() {
        // Q(h) = 1 + h²: differences 3h²·… shrink by four per halving.
        let q = |h: f64| 1.0 + h * h;
        assert_relative_eq!(
            observed_order([q(0.1), q(0.2), q(0.4)]).unwrap(),
            2.0,
            max_relative = 1e-12
        );
    }

    #[test]
    fn noise_has_no_order_and_constants_are_exact() {
        assert_eq!(observed_order([1.0, 1.1, 1.05]), None);
        assert_eq!(observed_order([2.0, 2.0, 2.0]), Some(f64::INFINITY));
    }
}
