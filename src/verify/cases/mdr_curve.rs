//! The paper's 1751-particle NiAl specimen (seed 1, the fill and flatten of
//! `nial_die_compaction`) pressed in LAMMPS 22 Jul 2025 under its `mdr` normal model
//! (Zunker & Kamrin 2024, a contact law made for compaction to high relative
//! density): NiAl's E and ν, yield stress 800 MPa, frictionless between particles,
//! μ = 0.02 at the walls, the punch driven down at a constant speed until the
//! particles push back 50 MPa (reference_data/lammps/nial_die_compaction_mdr).
//!
//! It is drawn beside tamp's laws in the plots of `nial_die_compaction` and
//! `liggghts_die_compaction`, where it compares models, and it is the reference of
//! tamp's own MDR pressing of the same specimen at 50 MPa
//! (`density_specimen_at_50MPa_mdr_minus_lammps`); reference_data/nial/README.md
//! says where the laws agree and why.

use crate::error::{Result, TampError};
use crate::plot::Series;
use serde::Deserialize;
use std::path::Path;

/// One thermo line of the recorded run (the columns the plots use).
#[derive(Debug, Deserialize)]
pub struct MdrRecord {
    /// Punch face height, m.
    pub height: f64,
    /// The particles' force on the punch over the die's cross-section, Pa.
    pub punch_pressure: f64,
    /// Solid volume of the particles over the die cylinder up to the punch.
    pub density_specimen: f64,
}

/// The recorded run, from `results.csv` of `reference_data/lammps/nial_die_compaction_mdr`
/// under `reference_data`.
pub fn load(reference_data: &Path) -> Result<Vec<MdrRecord>> {
    let path = reference_data.join("lammps/nial_die_compaction_mdr/results.csv");
    let bad = |what: String| TampError::Other(format!("{}: {what}", path.display()));
    let records: Vec<MdrRecord> = crate::verify::read_csv(&path)?;
    if records.len() < 2 {
        return Err(bad("the recorded run has fewer than two records".into()));
    }
    Ok(records)
}

/// The specimen density where the punch pressure first reaches `p` (Pa), linear
/// between the two thermo lines that bracket it.
pub fn density_at(records: &[MdrRecord], p: f64) -> Result<f64> {
    records
        .windows(2)
        .find_map(|w| {
            let (a, b) = (&w[0], &w[1]);
            (a.punch_pressure < p && p <= b.punch_pressure).then(|| {
                let s = (p - a.punch_pressure) / (b.punch_pressure - a.punch_pressure);
                a.density_specimen + s * (b.density_specimen - a.density_specimen)
            })
        })
        .ok_or_else(|| TampError::Other(format!("the recorded mdr run never reaches {p:e} Pa")))
}

/// The name the plots give the run.
const NAME: &str = "LAMMPS mdr (σy = 800 MPa), specimen, against its punch pressure";

/// Specimen density against the punch pressure in MPa.
pub fn density(records: &[MdrRecord]) -> Series {
    let points = records
        .iter()
        .map(|r| (r.punch_pressure / 1e6, r.density_specimen));
    Series::line(NAME, points.collect())
}

/// ΔH/H₀ against the punch pressure in MPa.
pub fn height_reduction(records: &[MdrRecord]) -> Series {
    let h0 = records[0].height;
    let points = records
        .iter()
        .map(|r| (r.punch_pressure / 1e6, (h0 - r.height) / h0));
    Series::line(NAME, points.collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The recorded run is the one its deck describes: it starts at the specimen's
    /// height and density (tamp's fill of seed 1, initial_density_specimen), ends
    /// at the 50 MPa its `fix halt` stops at, and the punch only moves down.
    #[test]
    fn the_recorded_mdr_run_starts_at_the_specimen_and_ends_at_50_mpa() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference_data");
        let records = load(&root).unwrap();
        let first = &records[0];
        // The deck prints H0 to 7 digits: 9.715894e-05 m of 9.71589445381175e-05 m.
        assert!((first.height - 9.71589445381175e-5).abs() < 1e-11);
        assert!((first.density_specimen - 0.6204908).abs() < 1e-6);
        let last = records.last().unwrap();
        assert!(last.punch_pressure > 50e6 && records[records.len() - 2].punch_pressure < 50e6);
        assert!(records.windows(2).all(|w| w[1].height < w[0].height));
        assert_eq!(density(&records).points.len(), records.len());
    }
}
