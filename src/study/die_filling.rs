//! The two fillings of a die-compaction scene side by side: for
//! each seed, the specimen is filled as a settled column and poured through the
//! funnel (`die_compaction.fill.method`), flattened, and its densities measured as
//! the press stage starts from them (Rojek §5: the specimen, and the central sphere
//! of `rve_diameter`, the RVE).
//!
//! Each row also carries what decides whether the RVE reading is tamp's error or the
//! packing's:
//! - `density_rve_monte_carlo`: the RVE density counted by random points instead of
//!   the exact sphere–sphere lenses, each point counted once per particle it lies in
//!   (the mass-based convention of `measure::packing`); its standard error
//!   √(φ(1 − φ)/n) is in `density_rve_monte_carlo_se`;
//! - `density_core_half`: a central sphere of half the RVE's diameter, which no wall
//!   layer reaches;
//! - `density_shell`: the specimen outside the RVE, (solid of specimen − solid of
//!   RVE)/(V_specimen − V_RVE).
//!
//! With `--sigma s` the scene's log-normal size law is narrowed (or widened) to s,
//! its median re-solved so the mean particle volume, and with it the solid volume
//! of the specimen, stays that of the scene (the bounds are kept).
//!
//! Writes `<out>/die-filling/<scene name>[_sigma<s>].csv` and prints the table.

use crate::error::{Result, TampError};
use crate::generate::distribution::SizeDistribution;
use crate::measure::region::{Region, ball_volume};
use crate::particles::Vec3;
use crate::process::die_compaction;
use crate::process::die_compaction_file::{DieCompactionFile, FillMethod};
use crate::scene::schema::RadiusSpec;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::Serialize;
use std::f64::consts::PI;
use std::fmt::Write;
use std::time::Instant;

/// Random points of the Monte Carlo RVE count: standard error ≤ 0.5/√n = 2.5e-4.
const MC_POINTS: usize = 4_000_000;

#[derive(Clone, Debug, Serialize)]
pub struct FillRow {
    pub seed: u64,
    pub method: String,
    pub sigma: Option<f64>,
    pub median: Option<f64>,
    pub particles: usize,
    pub h0: f64,
    pub density_specimen: f64,
    pub density_rve: f64,
    pub density_rve_monte_carlo: f64,
    pub density_rve_monte_carlo_se: f64,
    pub density_core_half: f64,
    pub density_shell: f64,
    pub fill_time: f64,
    pub fill_at_rest: bool,
    pub fill_steps: u64,
    pub wall_s: f64,
    pub commit: String,
}

pub struct Options {
    pub scene: std::path::PathBuf,
    pub seeds: Vec<u64>,
    pub methods: Vec<FillMethod>,
    pub sigma: Option<f64>,
    pub out: std::path::PathBuf,
}

/// The truncated log-normal of standard deviation `sigma` (of ln r) with the bounds
/// of `law` and the median that keeps its mean volume.
pub fn narrowed(law: &SizeDistribution, sigma: f64) -> Result<SizeDistribution> {
    let SizeDistribution::LogNormal { min, max, .. } = *law else {
        return Err(TampError::input(
            "die_compaction.particles.radius",
            "--sigma needs a log_normal size law",
        ));
    };
    let target = law.mean_volume();
    let with = |median: f64| SizeDistribution::LogNormal {
        median,
        sigma,
        min,
        max,
    };
    // The mean volume rises with the median; bisect in ln m between the bounds.
    let (mut lo, mut hi) = (
        min.unwrap_or(1e-3 * law.max_radius()).ln(),
        max.unwrap_or(1e3 * law.min_radius()).ln(),
    );
    if !(with(lo.exp()).mean_volume() <= target && with(hi.exp()).mean_volume() >= target) {
        return Err(TampError::input(
            "--sigma",
            format!("no median within the bounds keeps the mean volume at sigma {sigma}"),
        ));
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if with(mid.exp()).mean_volume() < target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let law = with((0.5 * (lo + hi)).exp());
    law.validate()
        .map_err(|rule| TampError::input("--sigma", rule))?;
    Ok(law)
}

/// Σ over particles of the number of MC points inside each, over the points: the
/// RVE's mass-based solid fraction by counting, and its standard error.
fn monte_carlo_sphere(positions: &[Vec3], radii: &[f64], centre: Vec3, radius: f64) -> (f64, f64) {
    let mut rng = ChaCha8Rng::seed_from_u64(0x5eed);
    // Only particles that reach the sphere matter.
    let near: Vec<(Vec3, f64)> = positions
        .iter()
        .zip(radii)
        .filter(|(x, r)| (**x - centre).norm() < radius + **r)
        .map(|(x, r)| (*x, *r))
        .collect();
    let cell = 2.0 * near.iter().map(|p| p.1).fold(0.0, f64::max);
    let grid = crate::generate::grid::CellGrid::new(&crate::space::Space::open(), cell, 0.0);
    let mut grid = grid;
    for (k, (x, _)) in near.iter().enumerate() {
        grid.insert(x, k);
    }
    let mut found = Vec::new();
    let mut hits = 0u64;
    let mut drawn = 0usize;
    while drawn < MC_POINTS {
        let p = Vec3::new(
            rng.random_range(-radius..radius),
            rng.random_range(-radius..radius),
            rng.random_range(-radius..radius),
        );
        if p.norm_squared() > radius * radius {
            continue;
        }
        drawn += 1;
        let p = p + centre;
        grid.near(&p, 0.5 * cell, &mut found);
        hits += found
            .iter()
            .filter(|&&k| (p - near[k].0).norm_squared() <= near[k].1 * near[k].1)
            .count() as u64;
    }
    let phi = hits as f64 / MC_POINTS as f64;
    (phi, (phi * (1.0 - phi).max(0.0) / MC_POINTS as f64).sqrt())
}

fn method_name(m: FillMethod) -> &'static str {
    match m {
        FillMethod::SettledColumn => "settled_column",
        FillMethod::Funnel => "funnel",
    }
}

fn measure(
    scene: &DieCompactionFile,
    seed: u64,
    method: FillMethod,
    sigma: Option<f64>,
) -> Result<FillRow> {
    let mut s = scene.clone();
    s.scene.seed = seed;
    let dc = &mut s.die_compaction;
    dc.fill.method = method;
    if method == FillMethod::SettledColumn {
        dc.fill.funnel = None;
    }
    let median = match sigma {
        Some(sigma) => {
            let law = narrowed(&dc.particles.radius.distribution(), sigma)?;
            let SizeDistribution::LogNormal { median, .. } = law else {
                unreachable!("narrowed returns a log-normal")
            };
            dc.particles.radius = RadiusSpec::Law(law);
            Some(median)
        }
        None => None,
    };
    s.validate()?;
    let dc = s.die_compaction.clone();
    let started = Instant::now();
    let specimen = die_compaction::prepare(&s, true)?;
    let wall_s = started.elapsed().as_secs_f64();
    let positions: Vec<Vec3> = specimen
        .particles
        .iter()
        .map(|p| Vec3::from(p.position))
        .collect();
    let radii: Vec<f64> = specimen.particles.iter().map(|p| p.radius).collect();
    let centre = Vec3::new(0.0, 0.0, 0.5 * specimen.h0);
    let rve_radius = 0.5 * dc.rve_diameter;
    let (mc, se) = monte_carlo_sphere(&positions, &radii, centre, rve_radius);
    let space = crate::space::Space::open();
    let half = Region::Sphere {
        centre,
        radius: 0.5 * rve_radius,
    };
    let core_half = crate::measure::packing::packing_fraction(&positions, &radii, &half, &space)?;
    let v_specimen = PI * (0.5 * dc.die_diameter).powi(2) * specimen.h0;
    let v_rve = ball_volume(rve_radius);
    let shell = (specimen.density_specimen * v_specimen - specimen.density_rve * v_rve)
        / (v_specimen - v_rve);
    Ok(FillRow {
        seed,
        method: method_name(method).into(),
        sigma,
        median,
        particles: specimen.particles.len(),
        h0: specimen.h0,
        density_specimen: specimen.density_specimen,
        density_rve: specimen.density_rve,
        density_rve_monte_carlo: mc,
        density_rve_monte_carlo_se: se,
        density_core_half: core_half,
        density_shell: shell,
        fill_time: specimen.fill_time,
        fill_at_rest: specimen.fill_at_rest,
        fill_steps: specimen.steps[0],
        wall_s,
        commit: crate::GIT_COMMIT.to_string(),
    })
}

pub fn run(o: &Options) -> Result<u8> {
    let (scene, _) = DieCompactionFile::load(&o.scene)?;
    let stem = o
        .scene
        .file_name()
        .and_then(|n| n.to_str())
        .map_or("scene", |n| {
            n.trim_end_matches(".json").trim_end_matches(".scene")
        })
        .to_string();
    let name = match o.sigma {
        Some(s) => format!("{stem}_sigma{s}"),
        None => stem,
    };
    let dir = o.out.join("die-filling");
    crate::output::create_dir(&dir)?;
    let path = dir.join(format!("{name}.csv"));
    let mut rows = Vec::new();
    for &seed in &o.seeds {
        for &method in &o.methods {
            let row = measure(&scene, seed, method, o.sigma)?;
            eprintln!(
                "seed {seed} {}: specimen {:.4}, RVE {:.4} (Monte Carlo {:.4} ± {:.4}), {:.0} s",
                row.method,
                row.density_specimen,
                row.density_rve,
                row.density_rve_monte_carlo,
                row.density_rve_monte_carlo_se,
                row.wall_s
            );
            rows.push(row);
            // Written after every row: a long study keeps what it has measured.
            super::write_csv(&path, &rows)?;
        }
    }
    print!("{}", table(&rows));
    eprintln!("wrote {}", path.display());
    Ok(0)
}

/// The rows as a Markdown table, then each method's mean and sample standard
/// deviation over the seeds.
pub fn table(rows: &[FillRow]) -> String {
    let mut s = String::from(
        "| seed | filling | H₀ (µm) | specimen | RVE | RVE, Monte Carlo | core (½ RVE) | outside the RVE | fill steps |\n\
         |---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let _ = writeln!(
            s,
            "| {} | {} | {:.2} | {:.4} | {:.4} | {:.4} ± {:.4} | {:.4} | {:.4} | {} |",
            r.seed,
            r.method,
            r.h0 * 1e6,
            r.density_specimen,
            r.density_rve,
            r.density_rve_monte_carlo,
            r.density_rve_monte_carlo_se,
            r.density_core_half,
            r.density_shell,
            r.fill_steps
        );
    }
    let mut methods: Vec<&str> = rows.iter().map(|r| r.method.as_str()).collect();
    methods.dedup();
    methods.sort();
    methods.dedup();
    for m in methods {
        let of = |f: fn(&FillRow) -> f64| -> (f64, f64) {
            let v: Vec<f64> = rows.iter().filter(|r| r.method == m).map(f).collect();
            let n = v.len() as f64;
            let mean = v.iter().sum::<f64>() / n;
            let var = v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0);
            (mean, var.sqrt())
        };
        let (sp, sps) = of(|r| r.density_specimen);
        let (rv, rvs) = of(|r| r.density_rve);
        let (co, cos) = of(|r| r.density_core_half);
        let (sh, shs) = of(|r| r.density_shell);
        let _ = writeln!(
            s,
            "| mean ± sd | {m} | | {sp:.4} ± {sps:.4} | {rv:.4} ± {rvs:.4} | | {co:.4} ± {cos:.4} | {sh:.4} ± {shs:.4} | |"
        );
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The narrowed law keeps the mean volume (so the specimen's solid volume) and
    /// its bounds.
    #[test]
    fn narrowing_keeps_the_mean_volume() {
        let law = SizeDistribution::LogNormal {
            median: 1.99e-6,
            sigma: 0.4723,
            min: Some(0.75e-6),
            max: Some(9.25e-6),
        };
        let narrow = narrowed(&law, 0.2).unwrap();
        let rel = (narrow.mean_volume() / law.mean_volume() - 1.0).abs();
        assert!(rel < 1e-12, "{rel}");
        assert_eq!(narrow.radius_range(), law.radius_range());
    }

    /// An FCC lattice of spheres has the solid fraction π/√18 = 0.74048; the exact
    /// lens sum over a sphere many lattice spacings wide (the RVE measure) and its
    /// Monte Carlo count must both find it, to within the boundary's fluctuation (the
    /// surface cuts cells at random: relative (a/R)² ≈ 1e-3 here, a bound on the lattice
    /// sum's remainder), and must agree with each other within four standard errors of
    /// the count (they count the same particles).
    #[test]
    fn monte_carlo_finds_the_fcc_fraction() {
        let a = 1.0;
        let r = a / 8f64.sqrt();
        let basis = [
            Vec3::zeros(),
            Vec3::new(0.5, 0.5, 0.0),
            Vec3::new(0.5, 0.0, 0.5),
            Vec3::new(0.0, 0.5, 0.5),
        ];
        let mut x = Vec::new();
        for i in -14..=14 {
            for j in -14..=14 {
                for k in -14..=14 {
                    for b in &basis {
                        x.push(Vec3::new(i as f64, j as f64, k as f64) * a + b);
                    }
                }
            }
        }
        let radii = vec![r; x.len()];
        let centre = Vec3::new(0.1, 0.2, 0.3);
        let (phi, se) = monte_carlo_sphere(&x, &radii, centre, 12.0);
        let fcc = PI / 18f64.sqrt();
        let exact = crate::measure::packing::packing_fraction(
            &x,
            &radii,
            &Region::Sphere {
                centre,
                radius: 12.0,
            },
            &crate::space::Space::open(),
        )
        .unwrap();
        assert!((exact - fcc).abs() < 1e-3, "{exact} vs {fcc}");
        assert!((phi - exact).abs() < 4.0 * se, "{phi} ± {se} vs {exact}");
    }
}
