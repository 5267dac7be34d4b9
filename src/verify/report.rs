//! report/verification.md and report/verification.html: a summary line per case, then
//! each case with its table, its plots inline beside the numbers (image links relative
//! to the report directory, where the cases write them), and each tolerance's reason.
//! Both are made from the same rows, so they show the same values.

use super::{CaseResult, Status, ToleranceKind, VerificationReport};
use std::fmt::Write;

fn status(s: Status) -> &'static str {
    match s {
        Status::Pass => "pass",
        Status::Fail => "FAIL",
        Status::Error => "ERROR",
        Status::KnownDeviation => "known deviation",
        Status::UnexpectedPass => "UNEXPECTED PASS",
        Status::NotExpressible => "not expressible",
    }
}

/// Whether the report holds runs of more than one engine.
fn several_engines(r: &VerificationReport) -> bool {
    r.cases.iter().any(|c| c.engine != r.cases[0].engine)
}

/// A case's title in the report: its name, and its engine when there are several.
fn title(c: &CaseResult, several: bool) -> String {
    match several {
        true => format!("{} [{}]", c.name, c.engine),
        false => c.name.clone(),
    }
}

/// The anchor of a case's section.
fn anchor(c: &CaseResult, several: bool) -> String {
    let a = match several {
        true => format!("{}-{}", c.name, c.engine),
        false => c.name.clone(),
    };
    super::engine::safe_chars(&a.to_lowercase(), '_', '-')
}

/// The largest relative difference between a case's values on another engine and
/// tamp's values of the same quantities (absolute where tamp's value is 0).
fn difference_from_tamp(c: &CaseResult, r: &VerificationReport) -> Option<f64> {
    let tamp = r
        .cases
        .iter()
        .find(|t| t.name == c.name && t.engine == "tamp")?;
    c.quantities
        .iter()
        .filter_map(|q| {
            let t = tamp.quantities.iter().find(|t| t.name == q.name)?;
            let d = (q.value - t.value).abs();
            Some(if t.value == 0.0 { d } else { d / t.value.abs() })
        })
        .reduce(f64::max)
}

/// Cases down, engines across: each cell the case's status on that engine and, for
/// engines other than tamp, the largest relative difference from tamp's values.
/// `None` when the report holds one engine.
pub fn engine_matrix(r: &VerificationReport) -> Option<(Vec<String>, Vec<Vec<String>>)> {
    if !several_engines(r) {
        return None;
    }
    let mut engines: Vec<String> = Vec::new();
    let mut cases: Vec<String> = Vec::new();
    for c in &r.cases {
        if !engines.contains(&c.engine) {
            engines.push(c.engine.clone());
        }
        if !cases.contains(&c.name) {
            cases.push(c.name.clone());
        }
    }
    let rows = cases
        .iter()
        .map(|name| {
            let mut row = vec![name.clone()];
            for e in &engines {
                let cell = match r.cases.iter().find(|c| &c.name == name && &c.engine == e) {
                    None => "—".to_string(),
                    Some(c) => match (e.as_str(), difference_from_tamp(c, r)) {
                        ("tamp", _) | (_, None) => status(c.status).to_string(),
                        (_, Some(d)) => format!("{} (Δ {d:.1e})", status(c.status)),
                    },
                };
                row.push(cell);
            }
            row
        })
        .collect();
    Some((engines, rows))
}

/// Whether a status needs the reader's attention (shown in bold).
fn alarming(s: Status) -> bool {
    matches!(s, Status::Fail | Status::Error | Status::UnexpectedPass)
}

const COLUMNS: [&str; 10] = [
    "case",
    "quantity",
    "value",
    "reference",
    "error",
    "tolerance",
    "unit",
    "source",
    "status",
    "wall time (s)",
];

/// One table row per quantity of a case (one for its error, if it stopped), as text
/// cells, and the row's status.
fn rows(c: &CaseResult) -> Vec<([String; 10], Status)> {
    let mut out = Vec::new();
    if let Some(e) = &c.error {
        let dash = || "—".to_string();
        out.push((
            [
                c.name.clone(),
                dash(),
                dash(),
                dash(),
                dash(),
                dash(),
                dash(),
                e.clone(),
                status(c.status).to_string(),
                format!("{:.2}", c.wall_s),
            ],
            c.status,
        ));
    }
    for q in &c.quantities {
        let kind = match q.tolerance_kind {
            ToleranceKind::Relative => "rel",
            ToleranceKind::Absolute => "abs",
            ToleranceKind::Below => "at most ref +",
            ToleranceKind::Between => "outside the interval",
        };
        let reference = if q.half_width > 0.0 {
            format!("{:.6e} ± {:.2e}", q.reference, q.half_width)
        } else {
            format!("{:.6e}", q.reference)
        };
        out.push((
            [
                c.name.clone(),
                q.name.clone(),
                format!("{:.6e}", q.value),
                reference,
                format!("{:.2e}", q.error),
                format!("{:.1e} ({kind})", q.tolerance),
                q.unit.clone(),
                q.source.clone(),
                status(q.status).to_string(),
                format!("{:.2}", c.wall_s),
            ],
            q.status,
        ));
    }
    out
}

/// The reasons of a case's tolerances, one sentence list item per quantity.
fn reasons(c: &CaseResult) -> Vec<(String, String)> {
    c.quantities
        .iter()
        .map(|q| {
            let paper = q
                .paper_value
                .map(|p| format!(" The paper states {p:e}."))
                .unwrap_or_default();
            let deviation = q
                .known_deviation
                .as_deref()
                .map(|d| format!(" tamp departs from this reference, as {d} records."))
                .unwrap_or_default();
            (q.name.clone(), format!("{}{}{}", q.why, paper, deviation))
        })
        .collect()
}

/// Counts of a case's quantities that pass, deviate as recorded, and fail.
fn summary(c: &CaseResult) -> String {
    let count = |s: Status| c.quantities.iter().filter(|q| q.status == s).count();
    format!(
        "{} quantities: {} pass, {} known deviation, {} fail",
        c.quantities.len(),
        count(Status::Pass),
        count(Status::KnownDeviation),
        c.quantities.len() - count(Status::Pass) - count(Status::KnownDeviation)
    )
}

pub fn markdown(r: &VerificationReport) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# tamp verification report\n");
    let _ = writeln!(s, "tamp {} (commit `{}`).\n", r.tamp_version, r.git_commit);
    let _ = writeln!(
        s,
        "An HTML version with the same content is `verification.html` beside this file.\n"
    );
    let several = several_engines(r);
    if let Some((engines, rows)) = engine_matrix(r) {
        let _ = writeln!(
            s,
            "## Engines\n\nEach case's status on each engine; beside another engine's status, Δ is the largest relative difference of its values from tamp's (docs/engines.md).\n"
        );
        let _ = writeln!(
            s,
            "| case | {} |\n|---|{}",
            engines.join(" | "),
            "---|".repeat(engines.len())
        );
        for row in rows {
            let _ = writeln!(s, "| {} |", row.join(" | ").replace('\n', " "));
        }
        let _ = writeln!(s);
    }
    let _ = writeln!(
        s,
        "| case | status | quantities | wall time (s) |\n|---|---|---|---|"
    );
    for c in &r.cases {
        let st = status(c.status);
        let st = if alarming(c.status) {
            format!("**{st}**")
        } else {
            st.to_string()
        };
        let _ = writeln!(
            s,
            "| [{}](#{}) | {st} | {} | {:.2} |",
            title(c, several),
            anchor(c, several),
            summary(c),
            c.wall_s
        );
    }
    let _ = writeln!(s, "\n## Cases: values, plots, tolerances and paper values");
    for c in &r.cases {
        let _ = writeln!(s, "\n### {}\n\n{}\n", title(c, several), c.description);
        let _ = writeln!(
            s,
            "| {} |\n|{}",
            COLUMNS.join(" | "),
            "---|".repeat(COLUMNS.len())
        );
        for (cells, st) in rows(c) {
            let mut cells = cells.map(|x| x.replace('|', "/"));
            if alarming(st) {
                cells[8] = format!("**{}**", cells[8]);
            }
            let _ = writeln!(s, "| {} |", cells.join(" | "));
        }
        for plot in &c.plots {
            let _ = writeln!(s, "\n![{plot}]({plot})");
        }
        let reasons = reasons(c);
        if !reasons.is_empty() {
            let _ = writeln!(s);
        }
        for (name, why) in reasons {
            let _ = writeln!(s, "- `{name}`: {why}");
        }
    }
    s
}

/// Text as HTML: the five characters with a meaning there escaped.
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for ch in text.chars() {
        match ch {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(ch),
        }
    }
    out
}

/// The report as one HTML page, no script or style from elsewhere; the plots are
/// `<img>` links relative to the report directory. A small script marks the body
/// with how many images the browser loaded (`data-images-loaded` of `data-images`),
/// which `.ci/check-report-html` reads back from a headless browser.
pub fn html(r: &VerificationReport) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>tamp verification report</title>\n<style>\nbody {{ font-family: sans-serif; margin: 2em; max-width: 1400px; }}\ntable {{ border-collapse: collapse; margin: 1em 0; font-size: 0.9em; }}\nth, td {{ border: 1px solid #999; padding: 0.25em 0.5em; text-align: left; vertical-align: top; }}\nth {{ background: #eee; }}\n.alarm {{ color: #b00; font-weight: bold; }}\nimg {{ display: block; max-width: 100%; margin: 1em 0; border: 1px solid #ccc; }}\n</style>\n</head>"
    );
    let images: usize = r.cases.iter().map(|c| c.plots.len()).sum();
    let _ = writeln!(
        s,
        "<body data-images=\"{images}\" data-images-loaded=\"pending\">\n<h1>tamp verification report</h1>\n<p>tamp {} (commit <code>{}</code>).</p>",
        escape(&r.tamp_version),
        escape(&r.git_commit)
    );
    let several = several_engines(r);
    if let Some((engines, rows)) = engine_matrix(r) {
        let _ = writeln!(
            s,
            "<h2>Engines</h2>\n<p>Each case's status on each engine; beside another engine's status, &Delta; is the largest relative difference of its values from tamp's (docs/engines.md).</p>\n<table>\n<tr><th>case</th>{}</tr>",
            engines
                .iter()
                .map(|e| format!("<th>{}</th>", escape(e)))
                .collect::<String>()
        );
        for row in rows {
            let _ = writeln!(
                s,
                "<tr>{}</tr>",
                row.iter()
                    .map(|x| format!("<td>{}</td>", escape(x)))
                    .collect::<String>()
            );
        }
        let _ = writeln!(s, "</table>");
    }
    let _ = writeln!(
        s,
        "<table>\n<tr><th>case</th><th>status</th><th>quantities</th><th>wall time (s)</th></tr>"
    );
    for c in &r.cases {
        let class = if alarming(c.status) {
            " class=\"alarm\""
        } else {
            ""
        };
        let _ = writeln!(
            s,
            "<tr><td><a href=\"#{4}\">{0}</a></td><td{class}>{1}</td><td>{2}</td><td>{3:.2}</td></tr>",
            escape(&title(c, several)),
            status(c.status),
            summary(c),
            c.wall_s,
            anchor(c, several)
        );
    }
    let _ = writeln!(
        s,
        "</table>\n<h2>Cases: values, plots, tolerances and paper values</h2>"
    );
    for c in &r.cases {
        let _ = writeln!(
            s,
            "<h3 id=\"{3}\">{0}</h3>\n<p>{1}</p>\n<table>\n<tr>{2}</tr>",
            escape(&title(c, several)),
            escape(&c.description),
            COLUMNS
                .iter()
                .map(|h| format!("<th>{h}</th>"))
                .collect::<String>(),
            anchor(c, several)
        );
        for (cells, st) in rows(c) {
            let cells: Vec<String> = cells
                .iter()
                .enumerate()
                .map(|(k, x)| {
                    if k == 8 && alarming(st) {
                        format!("<td class=\"alarm\">{}</td>", escape(x))
                    } else {
                        format!("<td>{}</td>", escape(x))
                    }
                })
                .collect();
            let _ = writeln!(s, "<tr>{}</tr>", cells.concat());
        }
        let _ = writeln!(s, "</table>");
        for plot in &c.plots {
            let _ = writeln!(s, "<img src=\"{0}\" alt=\"{0}\">", escape(plot));
        }
        let reasons = reasons(c);
        if !reasons.is_empty() {
            let _ = writeln!(s, "<ul>");
            for (name, why) in reasons {
                let _ = writeln!(
                    s,
                    "<li><code>{}</code>: {}</li>",
                    escape(&name),
                    escape(&why)
                );
            }
            let _ = writeln!(s, "</ul>");
        }
    }
    let _ = writeln!(
        s,
        "<script>\nwindow.addEventListener('load', function () {{\n  var images = Array.prototype.slice.call(document.images);\n  var loaded = images.filter(function (i) {{ return i.complete && i.naturalWidth > 0; }}).length;\n  document.body.setAttribute('data-images-loaded', String(loaded));\n}});\n</script>\n</body>\n</html>"
    );
    s
}
