//! report/verification.md: one table row per quantity, then each tolerance's reason.

use super::{Status, ToleranceKind, VerificationReport};
use std::fmt::Write;

fn status(s: Status) -> &'static str {
    match s {
        Status::Pass => "pass",
        Status::Fail => "**FAIL**",
        Status::Error => "**ERROR**",
        Status::KnownDeviation => "known deviation",
        Status::UnexpectedPass => "**UNEXPECTED PASS**",
    }
}

pub fn markdown(r: &VerificationReport) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# tamp verification report\n");
    let _ = writeln!(s, "tamp {} (commit `{}`).\n", r.tamp_version, r.git_commit);
    let _ = writeln!(
        s,
        "| case | quantity | value | reference | error | tolerance | unit | source | status | wall time (s) |\n|---|---|---|---|---|---|---|---|---|---|"
    );
    for c in &r.cases {
        if let Some(e) = &c.error {
            let _ = writeln!(
                s,
                "| {} | — | — | — | — | — | — | {} | {} | {:.2} |",
                c.name,
                e.replace('|', "/"),
                status(c.status),
                c.wall_s
            );
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
            let _ = writeln!(
                s,
                "| {} | {} | {:.6e} | {reference} | {:.2e} | {:.1e} ({kind}) | {} | {} | {} | {:.2} |",
                c.name,
                q.name,
                q.value,
                q.error,
                q.tolerance,
                q.unit,
                q.source,
                status(q.status),
                c.wall_s
            );
        }
    }
    let _ = writeln!(s, "\n## Cases, tolerances and paper values\n");
    for c in &r.cases {
        let _ = writeln!(s, "### {}\n\n{}\n", c.name, c.description);
        for q in &c.quantities {
            let paper = q
                .paper_value
                .map(|p| format!(" The paper states {p:e}."))
                .unwrap_or_default();
            let deviation = q
                .known_deviation
                .as_deref()
                .map(|d| format!(" tamp departs from this reference, as {d} records."))
                .unwrap_or_default();
            let _ = writeln!(s, "- `{}`: {}{}{}", q.name, q.why, paper, deviation);
        }
        for plot in &c.plots {
            let _ = writeln!(s, "\n![{plot}]({plot})");
        }
        let _ = writeln!(s);
    }
    s
}
