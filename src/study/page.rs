//! `accuracy-cost.md`: the page the two studies write from their CSV files, so a
//! rerun of one case (or of the stable-α search) rebuilds the whole page from what
//! is recorded, never from memory.

use super::accuracy_cost::{Row, observed_order};
use super::stable_alpha::StableRow;
use crate::error::{Result, TampError};
use crate::plot::{Panel, Series, write_svg};
use crate::verify::read_csv;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

/// One run of a case: its rows (one per quantity).
struct Run<'a> {
    rows: Vec<&'a Row>,
}

impl Run<'_> {
    fn first(&self) -> &Row {
        self.rows[0]
    }
    /// Largest error / tolerance over the quantities (what decides pass or fail).
    fn worst(&self) -> Option<f64> {
        self.rows
            .iter()
            .filter_map(|r| Some(r.error? / r.tolerance?))
            .reduce(f64::max)
    }
    fn value(&self, quantity: &str) -> Option<f64> {
        self.rows
            .iter()
            .find(|r| r.quantity == quantity)
            .and_then(|r| r.value)
    }
}

fn runs(rows: &[Row]) -> Vec<Run<'_>> {
    let mut out: Vec<Run> = Vec::new();
    for r in rows {
        match out.last_mut() {
            Some(run)
                if run.first().sweep == r.sweep
                    && run.first().step_scale == r.step_scale
                    && run.first().detector == r.detector =>
            {
                run.rows.push(r)
            }
            _ => out.push(Run { rows: vec![r] }),
        }
    }
    out
}

fn sci(x: Option<f64>) -> String {
    x.map(|v| format!("{v:.3e}")).unwrap_or_else(|| "—".into())
}

/// α and the like: fixed point down to 0.01, scientific below (α = 1e-4 happens).
fn fixed(x: Option<f64>, digits: usize) -> String {
    x.map(|v| {
        if v != 0.0 && v.abs() < 0.01 {
            format!("{v:.2e}")
        } else {
            format!("{v:.digits$}")
        }
    })
    .unwrap_or_else(|| "—".into())
}

/// What one case's sweep says, for the summary table.
struct Finding {
    /// The step sweep, coarsest first, for the inverse table.
    points: Vec<super::accuracy_inverse::Point>,
    setting_alpha: Option<f64>,
    setting_dt: Option<f64>,
    recommended: Option<Recommended>,
    order: String,
}

/// The cheapest passing step and its wall-time gain over the case's own step.
struct Recommended {
    dt: Option<f64>,
    alpha: Option<f64>,
    gain: f64,
}

/// The cheapest step of the sweep such that it and every finer step pass.
fn recommend<'a>(step_runs: &[&'a Run<'a>]) -> Option<&'a Run<'a>> {
    let mut best = None;
    for run in step_runs.iter().rev() {
        // finest first: stop at the first failure
        if run.first().status != "pass" {
            break;
        }
        best = Some(*run);
    }
    best
}

/// The quantity that moves most (relative to its tolerance) between the two finest
/// steps, and its observed order.
fn order_of(step_runs: &[&Run]) -> String {
    let n = step_runs.len();
    if n < 3 || step_runs[n - 3..].iter().any(|r| r.worst().is_none()) {
        return "— (fewer than three finished steps)".into();
    }
    let (h, h2, h4) = (step_runs[n - 1], step_runs[n - 2], step_runs[n - 3]);
    let mut best: Option<(f64, &str)> = None;
    for r in &h.rows {
        let (Some(q1), Some(q2), Some(tol)) = (r.value, h2.value(&r.quantity), r.tolerance) else {
            continue;
        };
        let moved = (q2 - q1).abs() / tol;
        if best.is_none_or(|b| moved > b.0) {
            best = Some((moved, &r.quantity));
        }
    }
    let Some((moved, name)) = best else {
        return "—".into();
    };
    if moved == 0.0 {
        return "no quantity depends on the step".into();
    }
    let q = |run: &Run| run.value(name).unwrap_or(f64::NAN);
    match observed_order([q(h), q(h2), q(h4)]) {
        Some(p) if p.is_infinite() => format!("`{name}`: exact to round-off at the finer steps"),
        Some(p) => format!("`{name}`: p = {p:.2}"),
        None => format!("`{name}`: none (differences do not shrink: chaotic or pre-asymptotic)"),
    }
}

fn case_section(page: &mut String, img_dir: &Path, case: &str, rows: &[Row]) -> Result<Finding> {
    let all = runs(rows);
    let mut step_runs: Vec<&Run> = all.iter().filter(|r| r.first().sweep == "step").collect();
    step_runs.sort_by(|a, b| b.first().step_scale.total_cmp(&a.first().step_scale));
    let setting = step_runs.iter().find(|r| r.first().step_scale == 1.0);
    let _ = writeln!(page, "### {case}\n");
    let _ = writeln!(
        page,
        "| step scale | Δt (s) | α = Δt/Δt_cr | wall time per run (s) | worst error / tolerance | status |"
    );
    let _ = writeln!(page, "|---|---|---|---|---|---|");
    for run in &step_runs {
        let f = run.first();
        let _ = writeln!(
            page,
            "| {} | {} | {} | {:.4} | {} | {}{} |",
            f.step_scale,
            sci(f.dt),
            fixed(f.alpha, 4),
            f.wall_s,
            sci(run.worst()),
            f.status,
            if f.note.is_empty() {
                String::new()
            } else {
                format!(": {}", f.note.replace('|', "/").replace('\n', " "))
            }
        );
    }
    let broad: Vec<&Run> = all
        .iter()
        .filter(|r| r.first().sweep == "broad_phase")
        .collect();
    if !broad.is_empty() {
        let _ = writeln!(
            page,
            "\nBroad phase at the case's step (the first row is the case's own):\n"
        );
        let _ = writeln!(
            page,
            "| detector | wall time per run (s) | worst error / tolerance | status |"
        );
        let _ = writeln!(page, "|---|---|---|---|");
        for run in setting.into_iter().chain(broad.iter()) {
            let f = run.first();
            let _ = writeln!(
                page,
                "| {} | {:.3} | {} | {} |",
                f.detector,
                f.wall_s,
                sci(run.worst()),
                f.status
            );
        }
    }
    let order = order_of(&step_runs);
    let rec = recommend(&step_runs);
    let recommended = rec.zip(setting).map(|(r, s)| Recommended {
        dt: r.first().dt,
        alpha: r.first().alpha,
        gain: s.first().wall_s / r.first().wall_s,
    });
    // The commit that ran the sweep is provenance of the data: it stays in the CSV.
    let _ = writeln!(
        page,
        "\nObserved order (most step-sensitive quantity): {order}. Rerun with `tamp study accuracy-cost --case {case} --out docs`.\n"
    );
    let line = match (rec, setting, &recommended) {
        _ if step_runs.len() < 2 => {
            "Recommendation: keep the case's step; its reference is a run at that step.".to_string()
        }
        (Some(r), Some(s), _) if r.first().step_scale == s.first().step_scale => {
            "Recommendation: keep the case's step; the next coarser one leaves the tolerance."
                .to_string()
        }
        (Some(r), _, Some(best)) => format!(
            "Recommendation: step scale {} (Δt = {}, α = {}), the cheapest within tolerance; {:.1}× less wall time than the case's setting.",
            r.first().step_scale,
            sci(best.dt),
            fixed(best.alpha, 3),
            best.gain
        ),
        _ => "Recommendation: none of the swept steps passes at and below it; the case's own step is needed."
            .to_string(),
    };
    let _ = writeln!(page, "{line}\n");
    let worst_vs = |x: &dyn Fn(&Row) -> Option<f64>| -> Vec<(f64, f64)> {
        step_runs
            .iter()
            .filter_map(|r| Some((x(r.first())?, r.worst()?)))
            .collect()
    };
    let by_dt = worst_vs(&|f: &Row| f.dt.or(Some(f.step_scale)));
    let by_time = worst_vs(&|f: &Row| Some(f.wall_s));
    let line_at_one = |pts: &[(f64, f64)]| {
        let lo = pts.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
        let hi = pts.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
        Series::line("tolerance", vec![(lo, 1.0), (hi, 1.0)])
    };
    if by_dt.iter().any(|p| p.1 > 0.0) {
        let mut a = Series::points("worst error / tolerance", by_dt.clone());
        a.line = true;
        let mut b = Series::points("worst error / tolerance", by_time.clone());
        b.line = true;
        let left = [a, line_at_one(&by_dt)];
        let right = [b, line_at_one(&by_time)];
        let file = format!("{case}.svg");
        write_svg(
            &img_dir.join(&file),
            &[
                Panel {
                    title: &format!("{case}: error vs step"),
                    x_label: "time step (s)",
                    y_label: "worst error / tolerance",
                    log_x: true,
                    log_y: true,
                    series: &left,
                },
                Panel {
                    title: "error vs wall time",
                    x_label: "wall time per run (s)",
                    y_label: "worst error / tolerance",
                    log_x: true,
                    log_y: true,
                    series: &right,
                },
            ],
        )?;
        let _ = writeln!(page, "![{case}](img/accuracy-cost/{file})\n");
    }
    let points = step_runs
        .iter()
        .filter_map(|r| {
            Some(super::accuracy_inverse::Point {
                dt: r.first().dt?,
                wall_s: r.first().wall_s,
                error: super::accuracy_inverse::relative_error(&r.rows),
            })
        })
        .collect();
    Ok(Finding {
        points,
        setting_alpha: setting.and_then(|s| s.first().alpha),
        setting_dt: setting.and_then(|s| s.first().dt),
        recommended,
        order,
    })
}

const INTRO: &str = "# What accuracy costs in time

Written by `tamp study accuracy-cost` and `tamp study stable-alpha` (do not edit by
hand: rerun them). Every quick verification case is rerun with its time step scaled
by each factor of the sweep: Δt = α·Δt_cr (Rojek 2016 eq 26) or the case's fixed
step, times the scale, with the number of steps divided by it so the simulated time
is the same. Each run is judged exactly as `tamp verify` judges it, against the
case's own independent reference and tolerance (verification/<case>.json); *worst
error / tolerance* is the largest over the case's quantities, so a run passes when
it is at most 1. α is the step over the critical step tamp estimates for the scene
at t = 0 (core/src/timestep.rs); it is blank when the scene gives a fixed step and the
law's stiffness needs a characteristic velocity the scene does not give.

The *observed order* is Richardson's self-convergence order p = log₂(|Q(4h) − Q(2h)|
/ |Q(2h) − Q(h)|) at the three finest steps, for the quantity that moves most
relative to its tolerance; it needs no exact solution. Velocity Verlet is second
order for smooth forces; contact onset and release are not smooth (the force jumps
in slope, or in value with damping), which lowers the order of quantities that
depend on when a contact starts or ends to one.

The *recommendation* is the cheapest step such that it and every finer step of the
sweep pass. It is a statement about the case, not a licence: a scene with a
different loading or more contacts per particle needs its own check. Cases whose
reference is a LIGGGHTS run recorded at the case's step (reference_data/liggghts/<case>)
are run at that step only. Packing beds of at least 200 spheres are also run with each broad phase at the
case's step (the detector changes the order in which contacts are summed, so a
chaotic packing may land on another, equally valid, final state).

Wall times are of one run on the machine that wrote the page (two cores, shared; a
run of a cheap case is repeated for at least 0.2 s and the mean is shown); compare
rows with each other, not with another machine.
";

/// Each verification case's scene, by case name (those that load).
fn case_scenes() -> Vec<(String, crate::scene::schema::Scene)> {
    let dir = crate::verify::verification_dir();
    let Ok(specs) = crate::verify::load_specs(&dir) else {
        return Vec::new();
    };
    specs
        .into_iter()
        .filter_map(|s| {
            let scene = super::case_scene(&dir.join(s.scene.as_deref()?)).ok()?;
            Some((s.name, scene))
        })
        .collect()
}

pub fn write(out: &Path) -> Result<()> {
    let data_dir = out.join("accuracy-cost");
    let img_dir = out.join("img").join("accuracy-cost");
    crate::output::create_dir(&img_dir)?;
    let mut files: Vec<_> = std::fs::read_dir(&data_dir)
        .map_err(|e| TampError::io(format!("reading {}", data_dir.display()), e))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "csv"))
        .collect();
    files.sort();
    let mut by_case: BTreeMap<String, Vec<Row>> = BTreeMap::new();
    let mut stable: Vec<StableRow> = Vec::new();
    let mut die: Vec<super::die_compaction::DieRow> = Vec::new();
    let mut calibration: Vec<super::accuracy_calibration::CalibrationRow> = Vec::new();
    for f in &files {
        if f.file_stem().is_some_and(|s| s == "accuracy_calibration") {
            calibration = read_csv(f)?;
        } else if f.file_stem().is_some_and(|s| s == "stable_alpha") {
            stable = read_csv(f)?;
        } else if f.file_stem().is_some_and(|s| s == "accuracy_inverse") {
            // written below from the case files
        } else if f.file_stem().is_some_and(|s| s == "die_compaction") {
            die = read_csv(f)?;
        } else {
            for r in read_csv::<Row>(f)? {
                by_case.entry(r.case.clone()).or_default().push(r);
            }
        }
    }
    let mut body = String::new();
    let mut summary = String::from(
        "| case | case's step (α) | cheapest step within tolerance (α) | wall-time gain | observed order |\n|---|---|---|---|---|\n",
    );
    let scenes = case_scenes();
    let mut inverse = Vec::new();
    let mut plots = Vec::new();
    // Sweeps of cases that no longer exist are not shown.
    let names: Vec<String> = crate::verify::load_specs(&crate::verify::verification_dir())?
        .into_iter()
        .map(|s| s.name)
        .collect();
    by_case.retain(|case, _| names.contains(case));
    for (case, rows) in &by_case {
        let f = case_section(&mut body, &img_dir, case, rows)?;
        let scene = scenes.iter().find(|(n, _)| n == case).map(|(_, s)| s);
        inverse.extend(super::accuracy_inverse::rows(case, &f.points, scene));
        if let Some(series) = super::accuracy_inverse::panel_series(&f.points, scene) {
            plots.push((case.clone(), series));
        }
        let _ = writeln!(
            summary,
            "| [{case}](#{case}) | {} ({}) | {} | {} | {} |",
            sci(f.setting_dt),
            fixed(f.setting_alpha, 3),
            f.recommended
                .as_ref()
                .map(|r| format!("{} ({})", sci(r.dt), fixed(r.alpha, 3)))
                .unwrap_or_else(|| "—".into()),
            f.recommended
                .as_ref()
                .map(|r| format!("{:.1}×", r.gain))
                .unwrap_or_else(|| "—".into()),
            f.order
        );
    }
    let mut page = String::from(INTRO);
    let _ = writeln!(
        page,
        "\nWritten by tamp {}; the commit that ran each sweep is in its CSV under docs/accuracy-cost/.\n",
        crate::VERSION
    );
    if !calibration.is_empty() {
        page.push_str(&super::accuracy_calibration::section(&calibration));
    }
    if !stable.is_empty() {
        page.push_str(&super::stable_alpha::section(&stable));
    }
    if !die.is_empty() {
        page.push_str(&super::die_compaction::section(&die));
    }
    let _ = writeln!(page, "## Summary per case\n\n{summary}");
    if !inverse.is_empty() {
        super::write_csv(&data_dir.join("accuracy_inverse.csv"), &inverse)?;
        page.push_str(&super::accuracy_inverse::section(
            &inverse, &plots, &img_dir,
        )?);
    }
    let _ = writeln!(page, "## Per case\n\n{body}");
    crate::output::write_atomic(&out.join("accuracy-cost.md"), page.as_bytes())
}
