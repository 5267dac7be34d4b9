//! tamp: what checks tamp's DEM core (the `tamp-core` crate) and connects it to other
//! codes: verification cases with independent references, studies of accuracy and cost,
//! the LIGGGHTS and LAMMPS exports and cross-checks, comparison of dumps, plots and
//! pictures. See README.md and docs/architecture.md.
//!
//! The core's modules are re-exported under their own names, so `tamp::scene` and
//! `crate::scene` name the same module as `tamp_core::scene`.

pub use tamp_core::{
    GIT_COMMIT, Result, SOURCE_TREE, TampError, VERSION, accuracy, bins, boundary, checkpoint,
    collision, contact, decimal, detect, document, error, expression, generate, growth, integrate,
    interrupt, material, measure, output, particles, process, progress, quadrature, quasistatic,
    run, scene, simulation, space, timestep, until,
};
pub use tamp_core::{each_normal, each_tangential};

pub mod compare;
pub mod impact_trial;
pub mod lammps;
pub mod liggghts;
pub mod peer_deck;
pub mod plot;
pub mod study;
pub mod verify;
pub mod views;

/// The checked-in die-compaction file `verification/<name>.scene.json`, for unit tests.
/// It lives at the crate's root so that the exporters' tests need not import `verify`,
/// which imports them.
#[cfg(test)]
pub(crate) fn checked_in_die_compaction(
    name: &str,
) -> process::die_compaction_file::DieCompactionFile {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("verification")
        .join(format!("{name}.scene.json"));
    process::die_compaction_file::DieCompactionFile::load(&path)
        .expect("a valid die-compaction file")
        .0
}
