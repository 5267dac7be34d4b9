//! The initial packings of Redanz & Fleck 2001 §2.2 (Fig 3): cylinders of radius R
//! (monosized) or uniform in [0.9R, 1.1R] (polydispersed) deposited ballistically by
//! steepest descent (`generate::ballistic_2d`) into a square box of side W = 80R with
//! a floor and two side walls, filled until 1000 consecutive discs would rest with
//! their tops above the lid (they are discarded).
//!
//! The paper shows one packing of each kind; tamp averages seeds 1–20 of each, so the
//! mean is compared with a single realisation and the tolerances carry the spread of
//! one packing (docs/generation.md gives the survey behind them).
//!
//! Measured, over the whole box as the paper defines them: the relative density (total
//! cylinder area / W²), the number of cylinders, and the coordination number
//! Z = 2 × touching pairs / N (pairs with a gap below 1e-9 R; wall and floor
//! contacts are not elements of the paper's network and are not counted).
//!
//! References, recomputed from the paper's own counts (Fig 3 caption) where its
//! stated values disagree with them (docs/paper-discrepancies.md §22): density
//! N π⟨r²⟩ / W² with 1683 (mono) and 1644 (poly) cylinders, ⟨r²⟩ = R² and
//! (b³ − a³)/(3(b − a)) = 1.00333 R² (stated: 0.823 and 0.814); coordination
//! 2 × 3183 elements / 1644 nodes (stated: 4.0); count 1644.
//!
//! Writes the contact network of the seed-1 polydispersed packing (Fig 3b) as
//! `ballistic_deposition_2d.svg`, that packing as `ballistic_deposition_2d.csv`
//! (x, y, r in units of R) and per-seed statistics as
//! `ballistic_deposition_2d_seeds.csv`, all in the report directory.

use crate::error::{Result, TampError};
use crate::generate::ballistic_2d::{BoxFill, Lid, boundary_contacts};
use crate::generate::distribution::SizeDistribution;
use crate::plot::write_segments_svg;
use crate::quasistatic::CylinderPacking;
use crate::verify::{CaseContext, Measured};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::fmt::Write;

/// The paper's radius scale; every length below is in units of it.
const R: f64 = 1.0;
/// Box side W = 80 R (R/W = 1.25e-2, Fig 3 caption).
const WIDTH: f64 = 80.0 * R;
/// Consecutive discards that end a fill: the density is the same to 2e-4 for
/// K = 100, 1000 and 10000 (docs/generation.md).
const PATIENCE: usize = 1000;
/// Seeds averaged per radius law.
const SEEDS: std::ops::RangeInclusive<u64> = 1..=20;
/// Pairs closer than this count as touching.
const GAP: f64 = 1e-9 * R;

/// Fig 3 caption: nodes (cylinders) and elements (contacts) of the two packings.
const MONO_NODES: f64 = 1683.0;
const POLY_NODES: f64 = 1644.0;
const POLY_ELEMENTS: f64 = 3183.0;

struct Sample {
    law: &'static str,
    seed: u64,
    packing: CylinderPacking,
    pairs: Vec<(usize, usize)>,
}

/// One W = 80R box filled with radii from `law` (also the specimen of the 2D compaction
/// cases).
pub(super) fn fill(law: &SizeDistribution, seed: u64) -> Result<CylinderPacking> {
    fill_box(law, seed, WIDTH)
}

/// The same fill in a square box of side `width` (the quick 2D compaction cases).
pub(super) fn fill_box(law: &SizeDistribution, seed: u64, width: f64) -> Result<CylinderPacking> {
    let fill = BoxFill {
        width,
        height: width,
        law: law.clone(),
        lid: Lid::Top,
        patience: PATIENCE,
    };
    fill.fill(&mut ChaCha8Rng::seed_from_u64(seed))
        .map_err(|e| TampError::Other(format!("ballistic deposition, seed {seed}: {e}")))
}

fn mean(values: impl Iterator<Item = f64>) -> f64 {
    let (sum, n) = values.fold((0.0, 0usize), |(s, n), v| (s + v, n + 1));
    sum / n as f64
}

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let (a, b) = (0.9 * R, 1.1 * R);
    let laws = [
        ("mono", SizeDistribution::Mono { radius: R }),
        ("poly", SizeDistribution::Uniform { min: a, max: b }),
    ];
    let mut samples = Vec::new();
    for (name, law) in &laws {
        for seed in SEEDS {
            let packing = fill(law, seed)?;
            let pairs = packing.touching_pairs(GAP);
            samples.push(Sample {
                law: name,
                seed,
                packing,
                pairs,
            });
        }
    }
    let of = |law: &'static str| samples.iter().filter(move |s| s.law == law);
    let density = |law| mean(of(law).map(|s| s.packing.density()));
    let count = mean(of("poly").map(|s| s.packing.len() as f64));
    let coordination =
        mean(of("poly").map(|s| 2.0 * s.pairs.len() as f64 / s.packing.len() as f64));

    write_artefacts(ctx, &samples)?;

    let area = std::f64::consts::PI / (WIDTH * WIDTH);
    let mean_r2_poly = (b.powi(3) - a.powi(3)) / (3.0 * (b - a));
    Ok(vec![
        Measured::new(
            "initial_density_mono",
            density("mono"),
            MONO_NODES * R * R * area,
        ),
        Measured::new(
            "initial_density_poly",
            density("poly"),
            POLY_NODES * mean_r2_poly * area,
        ),
        Measured::new(
            "coordination_poly",
            coordination,
            2.0 * POLY_ELEMENTS / POLY_NODES,
        ),
        Measured::new("particle_count_poly", count, POLY_NODES),
    ])
}

fn write_artefacts(ctx: &CaseContext, samples: &[Sample]) -> Result<()> {
    let name = &ctx.spec.name;
    crate::output::create_dir(&ctx.report_dir)?;
    let mut seeds = String::from(
        "law,seed,cylinders,density,pairs,coordination,floor_contacts,wall_contacts\n",
    );
    for s in samples {
        let p = &s.packing;
        let (floor, walls) = boundary_contacts(p, GAP);
        let _ = writeln!(
            seeds,
            "{},{},{},{:.6},{},{:.6},{},{}",
            s.law,
            s.seed,
            p.len(),
            p.density(),
            s.pairs.len(),
            2.0 * s.pairs.len() as f64 / p.len() as f64,
            floor,
            walls
        );
    }
    crate::output::write_atomic(
        &ctx.report_dir.join(format!("{name}_seeds.csv")),
        seeds.as_bytes(),
    )?;

    let shown = samples
        .iter()
        .find(|s| s.law == "poly")
        .ok_or_else(|| TampError::Other("no polydispersed packing".into()))?;
    let p = &shown.packing;
    let mut csv = String::from("x,y,r\n");
    for (c, r) in p.centres.iter().zip(&p.radii) {
        let _ = writeln!(csv, "{:.12},{:.12},{:.12}", c.x, c.y, r);
    }
    crate::output::write_atomic(&ctx.report_dir.join(format!("{name}.csv")), csv.as_bytes())?;
    let segments: Vec<([(f64, f64); 2], u32)> = shown
        .pairs
        .iter()
        .map(|&(i, j)| {
            let (u, v) = (p.centres[i], p.centres[j]);
            ([(u.x, u.y), (v.x, v.y)], 1)
        })
        .collect();
    write_segments_svg(
        &ctx.report_dir.join(format!("{name}.svg")),
        &format!(
            "Contacts, r = R[0.9, 1.1], W = 80R, seed {}: {} cylinders, {} contacts, D = {:.4} (Fig 3b)",
            shown.seed,
            p.len(),
            shown.pairs.len(),
            p.density()
        ),
        (0.0, p.width, 0.0, p.height),
        &segments,
    )
}
