//! What a LIGGGHTS deck and a LAMMPS deck share, whichever peer reads it: the scene
//! file read with an optional new seed, the neighbour skin, the interval between
//! dumped frames, the dump's columns and number format, the choice between a scene and
//! a die-compaction file, and what an export reports. Each peer's own commands are in
//! `liggghts::export` and `lammps::export`.

use crate::document::Document;
use crate::error::Result;
use crate::process::die_compaction_file::DieCompactionFile;
use crate::scene::Scene;
use std::path::Path;

/// Columns of every dump a deck writes (`liggghts::dump::Frame` reads them back, from
/// either peer: both write `dump custom` the same way).
pub const DUMP_COLUMNS: &str = "id type radius mass x y z vx vy vz omegax omegay omegaz fx fy fz";

/// The `dump_modify format` of `DUMP_COLUMNS`: the two integers, then every number to
/// the last bit.
pub fn dump_format() -> String {
    std::iter::once("%d %d")
        .chain(std::iter::repeat_n("%.17g", 14))
        .collect::<Vec<_>>()
        .join(" ")
}

/// What an export wrote.
#[derive(Debug)]
pub struct Exported {
    pub particles: usize,
    pub steps: u64,
    pub dt: f64,
    pub files: Vec<String>,
    /// Differences the deck cannot avoid (printed, and written into the deck).
    pub notes: Vec<String>,
}

/// The scene or die-compaction file and its hash, with `--seed` replacing the file's
/// seed (a new random placement, the same scene otherwise).
pub fn load_with_seed(path: &Path, seed: Option<u64>) -> Result<(Document, String)> {
    let (mut document, sha) = crate::document::load(path)?;
    if let Some(seed) = seed {
        match &mut document {
            Document::Scene(s) => s.seed = seed,
            Document::DieCompaction(d) => d.seed = seed,
        }
    }
    Ok((document, sha))
}

/// The peer's neighbour skin: the scene's skin fraction of the smallest radius.
pub fn neighbor_skin(scene: &Scene, radius: &[f64]) -> f64 {
    let min_r = radius.iter().copied().fold(f64::INFINITY, f64::min);
    if min_r.is_finite() {
        scene.broad_phase.skin_fraction * min_r
    } else {
        1e-3
    }
}

/// Steps between dumped frames when none is asked for: as the scene's own
/// trajectory.csv (else series.csv) has them, so the two compare row by row.
pub fn frame_every(scene: &Scene, steps: u64) -> u64 {
    match (scene.output.trajectory_every, scene.output.series_every) {
        (0, 0) => (steps / 100).max(1),
        (0, n) | (n, _) => n,
    }
}

/// Write a peer's deck for the file at `path` into `out_dir`: a scene through
/// `scene`, a die-compaction file through `pressing`. A die-compaction file's particles
/// exist only after tamp's fill and flatten, so what is exported is its pressing,
/// replaying tamp's stroke.
pub fn export_file(
    path: &Path,
    out_dir: &Path,
    (dump_every, seed): (Option<u64>, Option<u64>),
    scene: impl FnOnce(&Scene, &str, &Path, Option<u64>) -> Result<Exported>,
    pressing: impl FnOnce(&DieCompactionFile, &str, &Path) -> Result<Exported>,
) -> Result<Exported> {
    match load_with_seed(path, seed)? {
        (Document::Scene(s), sha) => scene(&s, &sha, out_dir, dump_every),
        (Document::DieCompaction(file), sha) => pressing(&file, &sha, out_dir),
    }
}
