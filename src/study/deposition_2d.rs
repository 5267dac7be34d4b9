//! The measurements behind the 2D ballistic deposition (Redanz & Fleck 2001 §2,
//! `generate::ballistic_2d`): the statistics docs/generation.md tabulates and the
//! tolerances of the `ballistic_deposition_2d` case rest on.
//!
//! - **survey**: at the paper's box W = H = 80R, seeds 1–20, both size laws (r = R and
//!   r uniform in [0.9R, 1.1R]), the lid rules `top` and `centre` and patiences K = 100,
//!   1000 and 10 000: the solid fraction D = Σπr²/W², the disc count N, the disc–disc
//!   contacts (gap below 1e-9 R), Z = 2 pairs/N, Z_b (floor and wall contacts counted as
//!   one end each), the floor and wall contacts, and the pairs whose gap lies in
//!   (1e-9, 1e-6] R (how sharp the contact threshold is);
//! - **interior**: the solid fraction of the window [10R, 70R]² away from the walls and
//!   the lid, the coordination of the discs centred in it, and the solid fraction of
//!   horizontal strips 10R high (how the floor and the lid order the packing);
//! - **width**: the whole-box solid fraction against W (H = W), both lid rules, with
//!   the number of seeds scaled so that each width samples about as many discs.
//!
//! Each row gives the mean and the sample standard deviation over the seeds. Writes
//! `<out>/deposition-2d/{survey,interior,width}.csv` and prints the tables.

use super::write_csv;
use crate::error::{Result, TampError};
use crate::generate::ballistic_2d::{BoxFill, Lid, boundary_contacts};
use crate::generate::distribution::SizeDistribution;
use crate::measure::sample::mean_sd;
use crate::quasistatic::{CylinderPacking, Vec2};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::fmt::Write as _;
use std::path::Path;

/// The paper's box width and height, in R.
const PAPER_WIDTH: f64 = 80.0;
const SEEDS: u64 = 20;
/// The patience of the verification case.
const PATIENCE: usize = 1000;
/// Contact: a gap below this fraction of R.
const CONTACT_GAP: f64 = 1e-9;

fn laws() -> [(&'static str, SizeDistribution); 2] {
    [
        ("mono", SizeDistribution::Mono { radius: 1.0 }),
        ("poly", SizeDistribution::Uniform { min: 0.9, max: 1.1 }),
    ]
}

fn lid_name(lid: Lid) -> &'static str {
    match lid {
        Lid::Top => "top",
        Lid::Centre => "centre",
    }
}

fn fill(
    width: f64,
    law: &SizeDistribution,
    lid: Lid,
    patience: usize,
    seed: u64,
) -> Result<CylinderPacking> {
    BoxFill {
        width,
        height: width,
        law: law.clone(),
        lid,
        patience,
    }
    .fill(&mut ChaCha8Rng::seed_from_u64(seed))
    .map_err(|e| TampError::Other(format!("2D deposition, seed {seed}: {e}")))
}

/// Solid fraction of the window [x0, x1] × [y0, y1], counted on a lattice of
/// spacing 0.02 R (its error is about 1e-4 over the windows used here).
fn window_density(p: &CylinderPacking, x: (f64, f64), y: (f64, f64)) -> f64 {
    let h = 0.02;
    let (nx, ny) = (((x.1 - x.0) / h) as usize, ((y.1 - y.0) / h) as usize);
    let mut covered = vec![false; nx * ny];
    for (c, r) in p.centres.iter().zip(&p.radii) {
        let i0 = ((c.x - r - x.0) / h).floor().max(0.0) as usize;
        let i1 = (((c.x + r - x.0) / h).ceil().max(0.0) as usize).min(nx);
        let j0 = ((c.y - r - y.0) / h).floor().max(0.0) as usize;
        let j1 = (((c.y + r - y.0) / h).ceil().max(0.0) as usize).min(ny);
        for i in i0..i1 {
            for j in j0..j1 {
                let q = Vec2::new(x.0 + (i as f64 + 0.5) * h, y.0 + (j as f64 + 0.5) * h);
                if (q - c).norm() < *r {
                    covered[i * ny + j] = true;
                }
            }
        }
    }
    covered.iter().filter(|b| **b).count() as f64 / covered.len() as f64
}

#[derive(serde::Serialize)]
pub struct SurveyRow {
    pub law: &'static str,
    pub lid: &'static str,
    pub patience: usize,
    pub seeds: u64,
    pub density: f64,
    pub density_sd: f64,
    pub count: f64,
    pub count_sd: f64,
    pub pairs: f64,
    pub pairs_sd: f64,
    pub coordination: f64,
    pub coordination_sd: f64,
    pub coordination_with_walls: f64,
    pub coordination_with_walls_sd: f64,
    pub floor_contacts: f64,
    pub floor_contacts_sd: f64,
    pub wall_contacts: f64,
    pub wall_contacts_sd: f64,
    /// Pairs with a gap in (1e-9, 1e-6] R.
    pub near_pairs: f64,
    pub seconds_per_fill: f64,
}

fn survey() -> Result<Vec<SurveyRow>> {
    let mut rows = Vec::new();
    for (law_name, law) in laws() {
        for (lid, patience) in [
            (Lid::Top, 100),
            (Lid::Top, PATIENCE),
            (Lid::Top, 10_000),
            (Lid::Centre, PATIENCE),
        ] {
            let started = std::time::Instant::now();
            let mut columns: [Vec<f64>; 8] = Default::default();
            for seed in 1..=SEEDS {
                let p = fill(PAPER_WIDTH, &law, lid, patience, seed)?;
                let n = p.len() as f64;
                let pairs = p.touching_pairs(CONTACT_GAP).len() as f64;
                let loose = p.touching_pairs(1e-6).len() as f64;
                let (floor, walls) = boundary_contacts(&p, CONTACT_GAP);
                let ends = (floor + walls) as f64;
                let values = [
                    p.density(),
                    n,
                    pairs,
                    2.0 * pairs / n,
                    (2.0 * pairs + ends) / n,
                    floor as f64,
                    walls as f64,
                    loose - pairs,
                ];
                for (c, v) in columns.iter_mut().zip(values) {
                    c.push(v);
                }
            }
            let s = columns.each_ref().map(|c| mean_sd(c));
            rows.push(SurveyRow {
                law: law_name,
                lid: lid_name(lid),
                patience,
                seeds: SEEDS,
                density: s[0].0,
                density_sd: s[0].1,
                count: s[1].0,
                count_sd: s[1].1,
                pairs: s[2].0,
                pairs_sd: s[2].1,
                coordination: s[3].0,
                coordination_sd: s[3].1,
                coordination_with_walls: s[4].0,
                coordination_with_walls_sd: s[4].1,
                floor_contacts: s[5].0,
                floor_contacts_sd: s[5].1,
                wall_contacts: s[6].0,
                wall_contacts_sd: s[6].1,
                near_pairs: s[7].0,
                seconds_per_fill: started.elapsed().as_secs_f64() / SEEDS as f64,
            });
        }
    }
    Ok(rows)
}

#[derive(serde::Serialize)]
pub struct InteriorRow {
    pub law: &'static str,
    /// The window, in R: `interior` is [10, 70]², `strip a-b` the full width at
    /// a ≤ y ≤ b.
    pub window: String,
    pub density: f64,
    pub density_sd: f64,
    /// The coordination of the discs centred in the window (interior only).
    pub coordination: Option<f64>,
    pub coordination_sd: Option<f64>,
}

fn interior() -> Result<Vec<InteriorRow>> {
    let mut rows = Vec::new();
    for (law_name, law) in laws() {
        let mut density = Vec::new();
        let mut coordination = Vec::new();
        let mut strips = vec![Vec::new(); 8];
        for seed in 1..=SEEDS {
            let p = fill(PAPER_WIDTH, &law, Lid::Top, PATIENCE, seed)?;
            density.push(window_density(&p, (10.0, 70.0), (10.0, 70.0)));
            // Every contact of a disc centred in the window counts, wherever its partner.
            let inside = |i: usize| {
                let c = p.centres[i];
                (10.0..=70.0).contains(&c.x) && (10.0..=70.0).contains(&c.y)
            };
            let ends: usize = p
                .touching_pairs(CONTACT_GAP)
                .into_iter()
                .map(|(i, j)| usize::from(inside(i)) + usize::from(inside(j)))
                .sum();
            let n = (0..p.len()).filter(|&i| inside(i)).count();
            coordination.push(ends as f64 / n as f64);
            for (k, strip) in strips.iter_mut().enumerate() {
                let y = 10.0 * k as f64;
                strip.push(window_density(&p, (0.0, PAPER_WIDTH), (y, y + 10.0)));
            }
        }
        let (d, d_sd) = mean_sd(&density);
        let (z, z_sd) = mean_sd(&coordination);
        rows.push(InteriorRow {
            law: law_name,
            window: "interior".into(),
            density: d,
            density_sd: d_sd,
            coordination: Some(z),
            coordination_sd: Some(z_sd),
        });
        for (k, strip) in strips.iter().enumerate() {
            let (d, d_sd) = mean_sd(strip);
            rows.push(InteriorRow {
                law: law_name,
                window: format!("strip {}-{}", 10 * k, 10 * (k + 1)),
                density: d,
                density_sd: d_sd,
                coordination: None,
                coordination_sd: None,
            });
        }
    }
    Ok(rows)
}

#[derive(serde::Serialize)]
pub struct WidthRow {
    /// W = H, in R.
    pub width: f64,
    pub seeds: u64,
    pub density_top: f64,
    pub density_top_sd: f64,
    pub density_centre: f64,
    pub density_centre_sd: f64,
}

fn width_dependence() -> Result<Vec<WidthRow>> {
    let law = SizeDistribution::Uniform { min: 0.9, max: 1.1 };
    let mut rows = Vec::new();
    for width in [20.0f64, 40.0, 80.0, 160.0] {
        // About as many discs per width as 20 boxes of 80R.
        let seeds = ((PAPER_WIDTH * PAPER_WIDTH / (width * width) * SEEDS as f64) as u64).max(5);
        let density = |lid| -> Result<(f64, f64)> {
            let v = (1..=seeds)
                .map(|seed| Ok(fill(width, &law, lid, PATIENCE, seed)?.density()))
                .collect::<Result<Vec<f64>>>()?;
            Ok(mean_sd(&v))
        };
        let (top, centre) = (density(Lid::Top)?, density(Lid::Centre)?);
        rows.push(WidthRow {
            width,
            seeds,
            density_top: top.0,
            density_top_sd: top.1,
            density_centre: centre.0,
            density_centre_sd: centre.1,
        });
    }
    Ok(rows)
}

/// The three measurements as Markdown tables.
fn tables(survey: &[SurveyRow], interior: &[InteriorRow], width: &[WidthRow]) -> String {
    let mut s = String::from(
        "| law | lid | K | D | N | pairs | Z | Z_b | floor | walls | pairs, gap in (1e-9, 1e-6] R | s per fill |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for r in survey {
        let _ = writeln!(
            s,
            "| {} | {} | {} | {:.4} ± {:.4} | {:.1} ± {:.1} | {:.1} ± {:.1} | {:.4} ± {:.4} | {:.4} ± {:.4} | {:.1} ± {:.1} | {:.1} ± {:.1} | {:.1} | {:.4} |",
            r.law,
            r.lid,
            r.patience,
            r.density,
            r.density_sd,
            r.count,
            r.count_sd,
            r.pairs,
            r.pairs_sd,
            r.coordination,
            r.coordination_sd,
            r.coordination_with_walls,
            r.coordination_with_walls_sd,
            r.floor_contacts,
            r.floor_contacts_sd,
            r.wall_contacts,
            r.wall_contacts_sd,
            r.near_pairs,
            r.seconds_per_fill
        );
    }
    s.push_str("\n| law | window (R) | D | Z |\n|---|---|---|---|\n");
    for r in interior {
        let z = match (r.coordination, r.coordination_sd) {
            (Some(z), Some(sd)) => format!("{z:.4} ± {sd:.4}"),
            _ => String::new(),
        };
        let _ = writeln!(
            s,
            "| {} | {} | {:.4} ± {:.4} | {z} |",
            r.law, r.window, r.density, r.density_sd
        );
    }
    s.push_str("\n| W = H (R) | seeds | D, lid top | D, lid centre |\n|---|---|---|---|\n");
    for r in width {
        let _ = writeln!(
            s,
            "| {} | 1–{} | {:.4} ± {:.4} | {:.4} ± {:.4} |",
            r.width,
            r.seeds,
            r.density_top,
            r.density_top_sd,
            r.density_centre,
            r.density_centre_sd
        );
    }
    s
}

/// `tamp study deposition-2d`.
pub fn run(out: &Path) -> Result<u8> {
    let dir = out.join("deposition-2d");
    crate::output::create_dir(&dir)?;
    let survey = survey()?;
    write_csv(&dir.join("survey.csv"), &survey)?;
    let interior = interior()?;
    write_csv(&dir.join("interior.csv"), &interior)?;
    let width = width_dependence()?;
    write_csv(&dir.join("width.csv"), &width)?;
    print!("{}", tables(&survey, &interior, &width));
    eprintln!("wrote {}", dir.display());
    Ok(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The lattice count against exact areas: one disc inside the window, and a disc
    /// cut in half by the window's edge.
    #[test]
    fn window_density_counts_disc_areas() {
        let packing = |centres: Vec<Vec2>| CylinderPacking {
            width: 20.0,
            height: 20.0,
            radii: vec![1.0; centres.len()],
            centres,
        };
        let whole = window_density(
            &packing(vec![Vec2::new(5.0, 5.0)]),
            (0.0, 10.0),
            (0.0, 10.0),
        );
        assert!(
            (whole - std::f64::consts::PI / 100.0).abs() < 1e-4,
            "{whole}"
        );
        let half = window_density(
            &packing(vec![Vec2::new(10.0, 5.0)]),
            (0.0, 10.0),
            (0.0, 10.0),
        );
        assert!(
            (half - 0.5 * std::f64::consts::PI / 100.0).abs() < 1e-4,
            "{half}"
        );
    }
}
