//! The recorded LAMMPS run of a case is of the deck tamp exports from the case's scene
//! now: the same lines but comments (`deck_sha256`), so a record cannot belong to
//! another scene or another exporter.

use crate::error::{Result, TampError};
use crate::scene::Scene;
use crate::verify::CaseContext;
use crate::verify::engine::peer_record::deck_sha256;
use std::path::Path;

/// Export `scene` into the report directory and compare it with `recorded/deck`; the
/// error names the script that re-records it.
pub fn check(ctx: &CaseContext, scene: &Scene, recorded: &Path) -> Result<()> {
    let fresh = ctx.report_dir.join(format!("{}_deck", ctx.spec.name));
    if fresh.exists() {
        std::fs::remove_dir_all(&fresh)
            .map_err(|e| TampError::io(format!("clearing {}", fresh.display()), e))?;
    }
    crate::lammps::export::export(scene, "", &fresh, None)?;
    let deck = recorded.join("deck");
    if deck_sha256(&fresh)? != deck_sha256(&deck)? {
        return Err(TampError::Other(format!(
            "{}: the recorded deck is not the one tamp exports from {} now ({}); re-record it with {}/regenerate.sh",
            deck.display(),
            ctx.spec.scene.as_deref().unwrap_or_default(),
            fresh.display(),
            recorded.display()
        )));
    }
    Ok(())
}
