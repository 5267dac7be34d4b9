//! The inverse of `tamp study accuracy-cost`: per case, the step and the wall time
//! a relative error of 1e-2 … 1e-5 needs, read off the case's measured sweep, beside
//! what `time_step.accuracy` would choose for it.
//!
//! The case's error at a step is the largest relative error |Q − Q_ref| / |Q_ref|
//! over its quantities with a nonzero reference (the measure the accuracy setting
//! promises). Error and wall time are both taken as power laws of Δt between two
//! neighbouring steps of the sweep, i.e. straight lines in log-log:
//!
//!   log Δt_a = log Δt_k + (log a − log e_k) · (log Δt_{k−1} − log Δt_k) / (log e_{k−1} − log e_k),
//!
//! with Δt_k the coarsest step at which it and every finer step are within a, and
//! Δt_{k−1} the next coarser; the wall time at Δt_a is interpolated the same way from
//! the wall times at Δt_k and Δt_{k−1}. Where even the finest step misses a, the
//! line through the two finest steps is extended (marked "extrapolated"), provided
//! the error falls as the step falls; where the coarsest step already meets a, that
//! step is given as a lower bound.
//!
//! The accuracy setting's prediction: the case's scene built with
//! `time_step = {"accuracy": a}` (its characteristic velocity kept), giving the step
//! the error model C (Δt/t_c)^p chooses; its wall time is the case's measured cost
//! at that step (interpolated as above). The plot draws the model's predicted error
//! max C (Δt/t_c)^p at each swept step against that step's measured wall time.

use super::accuracy_cost::Row;
use crate::accuracy::step::Choice;
use crate::error::Result;
use crate::plot::{Panel, Series, write_svg};
use crate::scene::schema::Scene;
use serde::{Deserialize, Serialize};
use std::fmt::Write as _;
use std::path::Path;

/// The accuracies of the table.
pub const TARGETS: [f64; 4] = [1e-2, 1e-3, 1e-4, 1e-5];

/// The smallest order (slope of log error against log Δt over the two finest steps)
/// that is extended beyond the sweep: a flatter error is near a floor, and its line
/// would give a step of zero.
const MIN_EXTRAPOLATED_ORDER: f64 = 0.5;

/// One step of a case's sweep.
#[derive(Clone, Copy, Debug)]
pub struct Point {
    pub dt: f64,
    pub wall_s: f64,
    /// None when the run did not finish (unstable or an error).
    pub error: Option<f64>,
}

/// The largest relative error over a run's quantities with a nonzero reference.
pub fn relative_error(rows: &[&Row]) -> Option<f64> {
    rows.iter()
        .filter_map(|r| {
            let (v, q) = (r.value?, r.reference?);
            (q != 0.0).then(|| (v - q).abs() / q.abs())
        })
        .reduce(f64::max)
}

/// One row of `accuracy-cost/accuracy_inverse.csv`.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct InverseRow {
    pub case: String,
    pub accuracy: f64,
    /// The step the measured sweep needs, s.
    pub dt: Option<f64>,
    /// Its wall time per run, s.
    pub wall_s: Option<f64>,
    /// interpolated, extrapolated, coarsest step (a lower bound on the step), or why none.
    pub how: String,
    /// The step `time_step.accuracy` chooses, s, and the measured wall time there.
    pub setting_dt: Option<f64>,
    pub setting_wall_s: Option<f64>,
    /// The error model it used, or why it chooses none.
    pub setting_model: String,
}

fn lerp_log(x: f64, (x0, y0): (f64, f64), (x1, y1): (f64, f64)) -> f64 {
    let t = (x.ln() - x0.ln()) / (x1.ln() - x0.ln());
    (y0.ln() + t * (y1.ln() - y0.ln())).exp()
}

/// The wall time at step `dt`, from the sweep's finished points (log-log, between
/// the two neighbouring steps, or along the end segment outside the sweep).
pub fn wall_at(points: &[Point], dt: f64) -> Option<f64> {
    let mut p: Vec<(f64, f64)> = points
        .iter()
        .filter(|p| p.wall_s > 0.0 && p.dt > 0.0)
        .map(|p| (p.dt, p.wall_s))
        .collect();
    p.sort_by(|a, b| a.0.total_cmp(&b.0));
    p.dedup_by(|a, b| a.0 == b.0);
    match p.len() {
        0 => None,
        1 => Some(p[0].1 * p[0].0 / dt), // one point: cost ∝ number of steps
        n => {
            let k = (1..n - 1).find(|&k| dt < p[k].0).unwrap_or(n - 1);
            Some(lerp_log(dt, p[k - 1], p[k]))
        }
    }
}

/// The step and wall time the sweep (`points` coarsest first) needs for `target`.
pub fn needed(points: &[Point], target: f64) -> (Option<f64>, Option<f64>, String) {
    let n = points.len();
    let within = |p: &Point| p.error.is_some_and(|e| e <= target);
    let Some(k) = (0..n).find(|&k| points[k..].iter().all(within)) else {
        let done: Vec<&Point> = points.iter().filter(|p| p.error.is_some()).collect();
        if let [.., a, b] = done[..]
            && let (Some(ea), Some(eb)) = (a.error, b.error)
            && eb > 0.0
            && (ea / eb).ln() / (a.dt / b.dt).ln() >= MIN_EXTRAPOLATED_ORDER
        {
            let dt = lerp_log(target, (ea, a.dt), (eb, b.dt));
            return (Some(dt), wall_at(points, dt), "extrapolated".into());
        }
        return (
            None,
            None,
            "not reached: the error does not fall with the step at the finest steps".into(),
        );
    };
    if k == 0 {
        let p = points[0];
        return (
            Some(p.dt),
            Some(p.wall_s),
            "met at the coarsest step swept (a lower bound)".into(),
        );
    }
    let (coarse, fine) = (points[k - 1], points[k]);
    match (coarse.error, fine.error) {
        (Some(ec), Some(ef)) if ef > 0.0 && ec > ef => {
            let dt = lerp_log(target, (ef, fine.dt), (ec, coarse.dt));
            let wall = lerp_log(dt, (fine.dt, fine.wall_s), (coarse.dt, coarse.wall_s));
            (Some(dt), Some(wall), "interpolated".into())
        }
        _ => (
            Some(fine.dt),
            Some(fine.wall_s),
            "the swept step (the next coarser one misses or did not finish)".into(),
        ),
    }
}

/// What `time_step.accuracy = a` chooses for the scene: the scene with its step
/// replaced by the accuracy (its characteristic velocity kept).
pub fn setting(base: &Scene, accuracy: f64) -> std::result::Result<Choice, String> {
    let mut scene = base.clone();
    scene.time_step.alpha = None;
    scene.time_step.fixed = None;
    scene.time_step.accuracy = Some(accuracy);
    match crate::scene::build(&scene) {
        Ok(b) => b
            .accuracy
            .ok_or_else(|| "the accuracy did not set the step".into()),
        Err(e) => Err(e.to_string()),
    }
}

/// The inverse rows of one case; `points` coarsest first.
pub fn rows(case: &str, points: &[Point], base: Option<&Scene>) -> Vec<InverseRow> {
    TARGETS
        .iter()
        .map(|&a| {
            let (dt, wall_s, how) = needed(points, a);
            let choice = base.map_or(Err("the case's scene cannot be built alone".into()), |s| {
                setting(s, a)
            });
            let (setting_dt, setting_wall_s, setting_model) = match choice {
                Ok(c) => (
                    Some(c.dt),
                    wall_at(points, c.dt),
                    format!(
                        "{}{}",
                        c.model.law,
                        if c.stability_bound {
                            " (bounded by stability)"
                        } else {
                            ""
                        }
                    ),
                ),
                Err(why) => (None, None, first_clause(&why)),
            };
            InverseRow {
                case: case.into(),
                accuracy: a,
                dt,
                wall_s,
                how,
                setting_dt,
                setting_wall_s,
                setting_model,
            }
        })
        .collect()
}

/// Why the setting chooses no step, short enough for a table cell: the rule without
/// the field name and the advice.
fn first_clause(why: &str) -> String {
    let s = why.trim_start_matches("error: ");
    let s = s.strip_prefix("time_step.accuracy: ").unwrap_or(s);
    let s = s.split([';', ':']).next().unwrap_or(s);
    format!("none: {}", s.replace('|', "/").trim())
}

/// The measured error and the model's predicted one against wall time, for a case
/// whose law the error model covers; `None` otherwise.
pub fn panel_series(points: &[Point], base: Option<&Scene>) -> Option<Vec<Series>> {
    let choice = setting(base?, TARGETS[0]).ok()?;
    let mut measured = Series::points(
        "measured: largest relative error",
        points
            .iter()
            .filter_map(|p| Some((p.wall_s, p.error?)))
            .collect(),
    );
    measured.line = true;
    let model = Series::line(
        &format!(
            "model {}: max C (Δt/t_c)^p at the swept steps",
            choice.model.law
        ),
        points
            .iter()
            .map(|p| {
                let ratio = p.dt / choice.contact_duration;
                let e = choice
                    .model
                    .predicted(ratio)
                    .into_iter()
                    .fold(0.0, f64::max);
                (p.wall_s, e)
            })
            .collect(),
    );
    let requested = Series::points(
        "time_step.accuracy = a: a at its step's wall time",
        TARGETS
            .iter()
            .filter_map(|&a| {
                let c = setting(base?, a).ok()?;
                Some((wall_at(points, c.dt)?, a))
            })
            .collect(),
    );
    Some(vec![measured, model, requested])
}

fn sci(x: Option<f64>) -> String {
    x.map(|v| format!("{v:.3e}")).unwrap_or_else(|| "—".into())
}

/// The page's section and the plot of the cases with an error model.
pub fn section(
    rows: &[InverseRow],
    plots: &[(String, Vec<Series>)],
    img_dir: &Path,
) -> Result<String> {
    let mut s = String::from(
        "## Accuracy on demand: the step and wall time each accuracy needs

Per case, the step and the wall time per run at which the case's largest relative
error |Q − Q_ref| / |Q_ref| (over its quantities with a nonzero reference) reaches
each accuracy, read off the step sweep below: error and wall time are taken as
power laws of Δt between the two neighbouring swept steps (straight lines in
log-log), at the coarsest step from which every finer step is within the accuracy.
*extrapolated*: the finest step still misses it and the line through the two finest
steps is extended; *lower bound*: the coarsest step swept already meets it; *not
reached*: the error stops falling (the reference carries a model error, or the
quantity is chaotic). Beside it, the step `time_step.accuracy` chooses for the
case's scene (core/src/accuracy/; its characteristic velocity kept) and the measured wall
time at that step; *none* where the scene's law has no error model. The data are in
`accuracy-cost/accuracy_inverse.csv`.

| case | accuracy | step needed (s) | wall time (s) | how | `time_step.accuracy` step (s) | its wall time (s) | error model |
|---|---|---|---|---|---|---|---|
",
    );
    for r in rows {
        let _ = writeln!(
            s,
            "| {} | {:.0e} | {} | {} | {} | {} | {} | {} |",
            r.case,
            r.accuracy,
            sci(r.dt),
            sci(r.wall_s),
            r.how,
            sci(r.setting_dt),
            sci(r.setting_wall_s),
            r.setting_model
        );
    }
    if !plots.is_empty() {
        let panels: Vec<Panel> = plots
            .iter()
            .map(|(case, series)| Panel {
                title: case,
                x_label: "wall time per run (s)",
                y_label: "relative error",
                log_x: true,
                log_y: true,
                series,
            })
            .collect();
        write_svg(&img_dir.join("error_vs_wall_time.svg"), &panels)?;
        let _ = writeln!(
            s,
            "\nError against wall time, with the error model's prediction max C (Δt/t_c)^p at each swept step (t_c the case's shortest closed-form contact, as `time_step.accuracy` takes it) and the accuracy setting's choices for 1e-2 … 1e-5 placed at their measured wall time (a point below the measured curve means the setting delivers its promise at that cost or better):\n\n![error against wall time](img/accuracy-cost/error_vs_wall_time.svg)\n"
        );
    }
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sweep(p: f64) -> Vec<Point> {
        // error = (dt/1e-6)^p, wall = 1e-9 / dt: coarsest first
        [8e-7, 4e-7, 2e-7, 1e-7]
            .iter()
            .map(|&dt| Point {
                dt,
                wall_s: 1e-9 / dt,
                error: Some((dt / 1e-6f64).powf(p)),
            })
            .collect()
    }

    #[test]
    fn a_power_law_is_inverted_exactly_inside_and_beyond_the_sweep() {
        for (target, how) in [(1e-1, "interpolated"), (1e-3, "extrapolated")] {
            let (dt, wall, said) = needed(&sweep(2.0), target);
            let exact = 1e-6 * target.sqrt();
            assert_eq!(said, how);
            assert!((dt.unwrap() / exact - 1.0).abs() < 1e-12);
            assert!((wall.unwrap() / (1e-9 / exact) - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn a_floor_is_not_reached_and_a_loose_target_is_a_lower_bound() {
        let mut p = sweep(2.0);
        for q in &mut p {
            q.error = Some(0.5);
        }
        assert!(needed(&p, 1e-2).2.starts_with("not reached"));
        assert!(needed(&p, 0.6).2.contains("lower bound"));
        // Nearly flat at the finest steps: no line is extended to a step of zero.
        p[3].error = Some(0.499);
        assert!(needed(&p, 1e-3).2.starts_with("not reached"));
    }

    #[test]
    fn an_unstable_coarse_step_is_not_interpolated_across() {
        let mut p = sweep(2.0);
        p[0].error = None;
        let (dt, _, how) = needed(&p, 0.5);
        assert_eq!(dt, Some(4e-7));
        assert!(how.starts_with("the swept step"));
    }
}
