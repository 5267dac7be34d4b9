//! The verification report shows every plot its cases wrote, and nothing else: each
//! image link of verification.md and verification.html resolves to a file in the
//! report directory, and each SVG there is linked from both, under its own case.
//! (.ci/check-report-html checks the same page in a headless browser.)

mod common;

use std::collections::BTreeSet;
use std::path::Path;

/// The targets of `open … close` in `text`, e.g. `](` … `)` for markdown images.
fn links(text: &str, open: &str, close: char) -> Vec<String> {
    text.match_indices(open)
        .map(|(k, _)| {
            let rest = &text[k + open.len()..];
            rest[..rest.find(close).expect("a closed link")].to_string()
        })
        .collect()
}

#[test]
fn report_links_every_plot_and_only_existing_files() {
    let dir = tempfile::tempdir().unwrap();
    let report = dir.path().join("report");
    // Two cases that write plots (one SVG each) and one that writes none.
    let cases = [
        "two_sphere_compression",
        "affine_closed_die_yield",
        "hertz_yield_onset",
    ];
    let mut args = vec!["verify".to_string()];
    for c in cases {
        args.extend(["--case".to_string(), c.to_string()]);
    }
    args.extend(["--report".to_string(), report.to_str().unwrap().to_string()]);
    let o = common::tamp().args(&args).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));

    let svgs: BTreeSet<String> = std::fs::read_dir(&report)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|n| n.ends_with(".svg"))
        .collect();
    assert_eq!(
        svgs,
        BTreeSet::from([
            "affine_closed_die_yield.svg".to_string(),
            "two_sphere_compression.svg".to_string()
        ])
    );
    let md = std::fs::read_to_string(report.join("verification.md")).unwrap();
    let html = std::fs::read_to_string(report.join("verification.html")).unwrap();
    for (name, found) in [
        ("verification.md", links(&md, "](", ')')),
        ("verification.html", links(&html, "<img src=\"", '"')),
    ] {
        // Markdown's section links (`](#case)`) are anchors, not files.
        let images: Vec<&String> = found.iter().filter(|l| !l.starts_with('#')).collect();
        for l in &images {
            assert!(
                !l.contains('/') && Path::new(&report).join(l).is_file(),
                "{name}: dangling image link {l}"
            );
        }
        let linked: BTreeSet<String> = images.into_iter().cloned().collect();
        assert_eq!(
            linked, svgs,
            "{name} links {linked:?}, the report has {svgs:?}"
        );
    }
    // Each plot sits under its own case's heading, after that case's table and
    // before the next case.
    for case in ["two_sphere_compression", "affine_closed_die_yield"] {
        let at = md.find(&format!("### {case}\n")).unwrap();
        let section = &md[at..];
        let section = &section[..section[4..].find("\n### ").map_or(section.len(), |k| k + 4)];
        let table = section.find(&format!("| {case} |")).unwrap();
        let image = section.find(&format!("![{case}.svg]({case}.svg)")).unwrap();
        assert!(table < image, "{case}: the plot comes before its table");
        let at = html.find(&format!("<h3 id=\"{case}\">")).unwrap();
        let section = &html[at..];
        let section = &section[..section[4..].find("<h3 ").map_or(section.len(), |k| k + 4)];
        assert!(section.contains(&format!("<img src=\"{case}.svg\"")));
    }
    assert!(html.starts_with("<!DOCTYPE html>") && html.trim_end().ends_with("</html>"));
    assert!(md.contains("| hertz_yield_onset | F_Y_table2 |"));
}
