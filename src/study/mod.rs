//! Studies: sweeps over the numerical settings of existing scenes that answer "what
//! does accuracy cost, and where does the integration stop being stable". They
//! write CSV data and a page (docs/accuracy-cost.md when run with `--out docs`).

pub mod accuracy_calibration;
pub mod accuracy_cost;
pub mod accuracy_inverse;
pub mod deposition_2d;
pub mod deposition_3d;
pub mod die_compaction;
pub mod die_filling;
pub mod energy_order;
pub mod page;
pub mod stable_alpha;

use crate::error::{Result, TampError};
use std::path::Path;

/// The scene a case file names, as the step sweeps read it: a plain scene as it stands,
/// a die-compaction file as the scene its stages share (its time step and detector).
fn case_scene(path: &Path) -> Result<crate::scene::Scene> {
    Ok(match crate::document::load(path)?.0 {
        crate::document::Document::Scene(scene) => *scene,
        crate::document::Document::DieCompaction(file) => file.shared_scene(),
    })
}

/// Rows as CSV with a header, written atomically (studies are rerun case by case, so a
/// file is either the old one or the whole new one).
fn write_csv<T: serde::Serialize>(path: &Path, rows: &[T]) -> Result<()> {
    let bad = |e: String| TampError::Other(format!("{}: {e}", path.display()));
    let mut writer = csv::Writer::from_writer(Vec::new());
    for r in rows {
        writer.serialize(r).map_err(|e| bad(e.to_string()))?;
    }
    let bytes = writer.into_inner().map_err(|e| bad(e.to_string()))?;
    crate::output::write_atomic(path, &bytes)
}
