//! The flattened specimen of a die-compaction scene, filled and flattened once per
//! verification run. `nial_die_compaction_small` and the peer replays
//! `liggghts_die_compaction_small` and `lammps_die_compaction_small` press the same
//! specimen (same particles, seed, fill and flatten) under different laws, and the
//! fill and flatten are a large part of each case's time; the first case to ask
//! fills it, a case asking at the same time waits for that one, later ones take a
//! copy. Filling is deterministic, so the copy is the specimen the case would have
//! filled itself, bit for bit.
//!
//! What the fill and flatten read (`die_compaction::prepare`) is the scene without
//! its name, its contact law (the stages run under `die_compaction.fill.contact`),
//! the press stage's settings (`die_compaction.press`) and the pressing die's
//! curvature (`die_compaction.die_curvature`: the fill's die is flat); scenes equal
//! in everything else share one specimen.

use crate::error::{Result, TampError};
use crate::process::die_compaction::{self, Specimen};
use crate::process::die_compaction_file::DieCompactionFile;
use std::collections::BTreeMap;
use std::sync::{Arc, Mutex, PoisonError};

type Slot = Arc<Mutex<Option<Specimen>>>;

/// `die_compaction::prepare(file, true)`, once per process for each fill.
pub fn prepare(file: &DieCompactionFile) -> Result<Specimen> {
    static FILLED: Mutex<BTreeMap<String, Slot>> = Mutex::new(BTreeMap::new());
    let slot: Slot = FILLED
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
        .entry(fill_key(file)?)
        .or_default()
        .clone();
    // Held while filling: a second case with the same fill waits for this one.
    let mut slot = slot.lock().unwrap_or_else(PoisonError::into_inner);
    if let Some(specimen) = slot.as_ref() {
        return Ok(specimen.clone());
    }
    let specimen = die_compaction::prepare(file, true)?;
    *slot = Some(specimen.clone());
    Ok(specimen)
}

/// The file as the fill and flatten read it.
fn fill_key(file: &DieCompactionFile) -> Result<String> {
    let mut v = serde_json::to_value(file)
        .map_err(|e| TampError::Other(format!("serialising the scene: {e}")))?;
    if let Some(o) = v.as_object_mut() {
        o.remove("name");
        o.remove("contact");
        if let Some(dc) = o.get_mut("die_compaction").and_then(|d| d.as_object_mut()) {
            dc.remove("press");
            dc.remove("die_curvature");
        }
    }
    Ok(v.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::checked_in_die_compaction as scene;

    #[test]
    fn the_three_small_die_cases_share_a_fill_and_other_seeds_or_fills_do_not() {
        let nial = fill_key(&scene("nial_die_compaction_small")).unwrap();
        let liggghts = fill_key(&scene("liggghts_die_compaction_small")).unwrap();
        let lammps = fill_key(&scene("lammps_die_compaction_small")).unwrap();
        assert_eq!(nial, liggghts);
        // The LAMMPS scene presses with "die_curvature": "mean", the others flat.
        assert_eq!(nial, lammps);
        let mut other = scene("lammps_die_compaction_small");
        other.scene.seed = 2;
        assert_ne!(fill_key(&other).unwrap(), lammps);
        let mut other = scene("lammps_die_compaction_small");
        other.die_compaction.fill.gravity_scale *= 10.0;
        assert_ne!(fill_key(&other).unwrap(), lammps);
        let mut other = scene("lammps_die_compaction_small");
        other.scene.rotation = None;
        assert_ne!(fill_key(&other).unwrap(), lammps);
    }
}
