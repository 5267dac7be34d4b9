//! The measurements behind the 3D ballistic (steepest-descent) deposition,
//! `generate::ballistic`: the bulk statistics docs/generation.md tabulates and the
//! test `generate_monodisperse_bulk_matches_visscher_bolsterli` takes its tolerances
//! from, and the stress run of wide and bimodal size laws.
//!
//! - **survey**: equal spheres (d = 1) deposited on a periodic square footprint. For
//!   N = 10⁴ on 12 d × 12 d (16 seeds) and N = 2·10⁴ on 16 d × 16 d (8 seeds): the bulk
//!   solid fraction φ and coordination Z, and the spheres off the floor that do not
//!   rest on exactly three earlier ones (a steepest-descent deposit has none), and the
//!   wall time of each deposit.
//! - **stress**: five laws where small spheres fall through the pores of large ones
//!   (log-normal s = 0.5 and 0.8, uniform over 0.1–1, bidisperse with size ratios 6
//!   and 10), 40 seeds × 5000 spheres each: every deposit must succeed with no overlap
//!   beyond 1e-9 of the contact distance and no unsupported sphere. Any failure makes
//!   the study exit 1 and is listed.
//!
//! The bulk is the slab from 5 d above the floor (below it the floor orders the
//! packing: φ ≈ 0.54 in the first two diameters) to 10 d below the highest centre (the
//! rough surface); moving either face 5 d further in changes φ by less than the
//! seed-to-seed spread. φ counts each sphere's exact volume inside the slab; Z is the
//! mean number of contacts (gap below 1e-9) of the spheres centred in it.
//!
//! Writes `<out>/deposition-3d/{survey,seeds,stress}.csv` and prints the tables.

use super::write_csv;
use crate::error::{Result, TampError};
use crate::generate::distribution::SizeDistribution;
use crate::generate::{ballistic, measure};
use crate::measure::sample::mean_sd;
use crate::measure::{Region, packing::packing_fraction};
use crate::particles::Vec3;
use crate::space::Space;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::fmt::Write as _;
use std::path::Path;

/// Contact: a gap below this fraction of the diameter.
const CONTACT_GAP: f64 = 1e-9;

/// `n` spheres of diameter 1 deposited on the periodic footprint `width` × `width`.
pub fn pile(n: usize, width: f64, seed: u64) -> Result<(Vec<Vec3>, Vec<f64>, Space)> {
    let space = Space {
        periodic: [Some((0.0, width)), Some((0.0, width)), None],
    };
    let radii = vec![0.5; n];
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let p = ballistic::deposit(&radii, ([0.0, 0.0], [width, width]), 0.0, &space, &mut rng)
        .map_err(|e| TampError::Other(format!("3D deposition of {n}, seed {seed}: {e}")))?;
    Ok((p, radii, space))
}

/// The bulk of an equal-sphere deposit (see the module header).
#[derive(Clone, Copy, Debug)]
pub struct Bulk {
    pub solid_fraction: f64,
    pub coordination: f64,
    /// Spheres off the floor whose number of contacts with earlier spheres is not 3.
    pub not_three_supports: usize,
}

pub fn bulk(p: &[Vec3], radii: &[f64], space: &Space) -> Result<Bulk> {
    let top = p.iter().map(|x| x[2]).fold(0.0, f64::max);
    let (lo, hi) = (5.0, top - 10.0);
    let pairs = measure::contact_pairs(p, radii, space, CONTACT_GAP);
    let mut contacts = vec![0usize; p.len()];
    let mut earlier = vec![0usize; p.len()];
    for &(i, j, _) in &pairs {
        contacts[i] += 1;
        contacts[j] += 1;
        earlier[j] += 1;
    }
    let inside: Vec<usize> = (0..p.len())
        .filter(|&i| p[i][2] > lo && p[i][2] < hi)
        .collect();
    Ok(Bulk {
        solid_fraction: packing_fraction(p, radii, &Region::Slab { axis: 2, lo, hi }, space)?,
        coordination: inside.iter().map(|&i| contacts[i] as f64).sum::<f64>() / inside.len() as f64,
        not_three_supports: (0..p.len())
            .filter(|&i| (p[i][2] - radii[i]).abs() > 1e-12 && earlier[i] != 3)
            .count(),
    })
}

#[derive(serde::Serialize)]
pub struct SeedRow {
    pub spheres: usize,
    pub footprint: f64,
    pub seed: u64,
    pub solid_fraction: f64,
    pub coordination: f64,
    pub not_three_supports: usize,
    pub seconds: f64,
}

#[derive(serde::Serialize)]
pub struct SurveyRow {
    pub spheres: usize,
    pub footprint: f64,
    pub seeds: usize,
    pub solid_fraction: f64,
    pub solid_fraction_sd: f64,
    pub coordination: f64,
    pub coordination_sd: f64,
    pub seconds_per_deposit: f64,
}

#[derive(serde::Serialize)]
pub struct StressRow {
    pub law: String,
    pub seeds: u64,
    pub spheres: usize,
    pub failures: usize,
    /// The deepest overlap over the seeds, relative to the contact distance (≤ 0).
    pub deepest_gap: f64,
    pub unsupported: usize,
}

fn survey() -> Result<(Vec<SeedRow>, Vec<SurveyRow>)> {
    let mut seeds_rows = Vec::new();
    let mut rows = Vec::new();
    for (n, width, seeds) in [(10_000usize, 12.0, 16u64), (20_000, 16.0, 8)] {
        let mut of_this = Vec::new();
        for seed in 1..=seeds {
            let started = std::time::Instant::now();
            let (p, radii, space) = pile(n, width, seed)?;
            let seconds = started.elapsed().as_secs_f64();
            let b = bulk(&p, &radii, &space)?;
            eprintln!(
                "N {n} on {width} d: seed {seed}: φ {:.5}, Z {:.4}, {} spheres off the floor without exactly 3 supports, {seconds:.2} s",
                b.solid_fraction, b.coordination, b.not_three_supports
            );
            of_this.push(SeedRow {
                spheres: n,
                footprint: width,
                seed,
                solid_fraction: b.solid_fraction,
                coordination: b.coordination,
                not_three_supports: b.not_three_supports,
                seconds,
            });
        }
        let column = |f: fn(&SeedRow) -> f64| of_this.iter().map(f).collect::<Vec<f64>>();
        let (phi, phi_sd) = mean_sd(&column(|r| r.solid_fraction));
        let (z, z_sd) = mean_sd(&column(|r| r.coordination));
        let (seconds, _) = mean_sd(&column(|r| r.seconds));
        rows.push(SurveyRow {
            spheres: n,
            footprint: width,
            seeds: of_this.len(),
            solid_fraction: phi,
            solid_fraction_sd: phi_sd,
            coordination: z,
            coordination_sd: z_sd,
            seconds_per_deposit: seconds,
        });
        seeds_rows.extend(of_this);
    }
    Ok((seeds_rows, rows))
}

fn stress_laws() -> [(&'static str, SizeDistribution); 5] {
    [
        (
            "log-normal, median 0.3, s 0.5, in [0.05, 1]",
            SizeDistribution::LogNormal {
                median: 0.3,
                sigma: 0.5,
                min: Some(0.05),
                max: Some(1.0),
            },
        ),
        (
            "bidisperse 0.1 and 0.6 (90 % small)",
            SizeDistribution::Discrete {
                radii: vec![0.1, 0.6],
                number_fractions: vec![0.9, 0.1],
            },
        ),
        (
            "uniform over [0.1, 1]",
            SizeDistribution::Uniform { min: 0.1, max: 1.0 },
        ),
        (
            "bidisperse 0.06 and 0.6 (95 % small)",
            SizeDistribution::Discrete {
                radii: vec![0.06, 0.6],
                number_fractions: vec![0.95, 0.05],
            },
        ),
        (
            "log-normal, median 0.2, s 0.8, in [0.02, 1]",
            SizeDistribution::LogNormal {
                median: 0.2,
                sigma: 0.8,
                min: Some(0.02),
                max: Some(1.0),
            },
        ),
    ]
}

fn stress() -> Vec<StressRow> {
    const SEEDS: u64 = 40;
    const SPHERES: usize = 5000;
    let width = 12.0;
    let space = Space {
        periodic: [Some((0.0, width)), Some((0.0, width)), None],
    };
    let mut rows = Vec::new();
    for (name, law) in stress_laws() {
        let mut row = StressRow {
            law: name.to_string(),
            seeds: SEEDS,
            spheres: SPHERES,
            failures: 0,
            deepest_gap: 0.0,
            unsupported: 0,
        };
        for seed in 0..SEEDS {
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            let radii: Vec<f64> = (0..SPHERES).map(|_| law.sample(&mut rng)).collect();
            match ballistic::deposit(&radii, ([0.0, 0.0], [width, width]), 0.0, &space, &mut rng) {
                Ok(p) => {
                    let pairs = measure::contact_pairs(&p, &radii, &space, CONTACT_GAP);
                    let deepest = pairs.iter().map(|c| c.2).fold(0.0, f64::min);
                    let loose = measure::unsupported(&p, &radii, &space, 0.0, CONTACT_GAP);
                    if deepest < -CONTACT_GAP || !loose.is_empty() {
                        eprintln!(
                            "{name}, seed {seed}: deepest gap {deepest:e}, unsupported {loose:?}"
                        );
                    }
                    row.deepest_gap = row.deepest_gap.min(deepest);
                    row.unsupported += loose.len();
                }
                Err(e) => {
                    eprintln!("{name}, seed {seed}: {e}");
                    row.failures += 1;
                }
            }
        }
        rows.push(row);
    }
    rows
}

fn tables(survey: &[SurveyRow], stress: &[StressRow]) -> String {
    let mut s = String::from(
        "| N | footprint (d) | seeds | bulk φ (mean ± sd) | bulk Z (mean ± sd) | s per deposit |\n\
         |---|---|---|---|---|---|\n",
    );
    for r in survey {
        let _ = writeln!(
            s,
            "| {} | {} × {} | {} | {:.4} ± {:.4} | {:.4} ± {:.4} | {:.2} |",
            r.spheres,
            r.footprint,
            r.footprint,
            r.seeds,
            r.solid_fraction,
            r.solid_fraction_sd,
            r.coordination,
            r.coordination_sd,
            r.seconds_per_deposit
        );
    }
    s.push_str("\n| law | deposits | failed | deepest gap / contact distance | unsupported |\n|---|---|---|---|---|\n");
    for r in stress {
        let _ = writeln!(
            s,
            "| {} | {} × {} | {} | {:.1e} | {} |",
            r.law, r.seeds, r.spheres, r.failures, r.deepest_gap, r.unsupported
        );
    }
    s
}

/// `tamp study deposition-3d`: 1 when a stress deposit failed, overlapped or left a
/// sphere unsupported.
pub fn run(out: &Path) -> Result<u8> {
    let dir = out.join("deposition-3d");
    crate::output::create_dir(&dir)?;
    let (seeds, survey) = survey()?;
    write_csv(&dir.join("seeds.csv"), &seeds)?;
    write_csv(&dir.join("survey.csv"), &survey)?;
    let stress = stress();
    write_csv(&dir.join("stress.csv"), &stress)?;
    print!("{}", tables(&survey, &stress));
    eprintln!("wrote {}", dir.display());
    let bad = stress
        .iter()
        .any(|r| r.failures > 0 || r.deepest_gap < -CONTACT_GAP || r.unsupported > 0);
    Ok(u8::from(bad))
}
