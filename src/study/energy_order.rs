//! The seed-to-seed spread of the `energy_conservation_elastic` case, which its two
//! tolerances rest on: the case's own measurement (the worst energy excursion at the
//! scene's step, and the order fitted over four halvings of it) repeated with other
//! seeds, which draw other radii and velocities. The trajectories are chaotic, so each
//! seed and step samples different collisions (docs/verification-notes.md).
//!
//! Writes `<out>/energy-order.csv` and prints the table.

use super::write_csv;
use crate::error::Result;
use crate::verify::cases::energy_conservation_elastic::drift_and_order;
use std::fmt::Write as _;
use std::path::Path;

/// The seeds of the measurement; the case itself runs the scene's own seed.
pub const SEEDS: [u64; 5] = [7, 8, 9, 10, 11];

#[derive(serde::Serialize)]
pub struct Row {
    pub seed: u64,
    /// max |E(t) − E(0)|/E(0) at the scene's step.
    pub energy_drift: f64,
    /// The least-squares slope of ln(drift) against ln(Δt).
    pub energy_drift_order: f64,
}

/// `tamp study energy-order`.
pub fn run(out: &Path) -> Result<u8> {
    let path = crate::verify::verification_dir().join("energy_conservation_elastic.scene.json");
    let (scene, _) = crate::scene::load(&path)?;
    crate::output::create_dir(out)?;
    let csv = out.join("energy-order.csv");
    let mut rows = Vec::new();
    for seed in SEEDS {
        let mut seeded = scene.clone();
        seeded.seed = seed;
        let (energy_drift, energy_drift_order) = drift_and_order(&seeded, |_, s, spec| {
            crate::verify::engine::tamp::record(s, spec)
        })?;
        eprintln!("seed {seed}: drift {energy_drift:.3e}, order {energy_drift_order:.3}");
        rows.push(Row {
            seed,
            energy_drift,
            energy_drift_order,
        });
        write_csv(&csv, &rows)?;
    }
    let mut table =
        String::from("| seed | worst excursion at the scene's step | order |\n|---|---|---|\n");
    for r in &rows {
        let _ = writeln!(
            table,
            "| {} | {:.2e} | {:.2} |",
            r.seed, r.energy_drift, r.energy_drift_order
        );
    }
    print!("{table}");
    eprintln!("wrote {}", csv.display());
    Ok(0)
}
