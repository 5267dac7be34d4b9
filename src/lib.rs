//! tamp: a verification-first discrete element method reference implementation for
//! powder packing and cold die compaction. See README.md and docs/architecture.md.

pub mod accuracy;
pub mod boundary;
pub mod checkpoint;
pub mod compare;
pub mod contact;
pub mod detect;
pub mod error;
pub mod expression;
pub mod generate;
pub mod growth;
pub mod integrate;
pub mod interrupt;
pub mod lammps;
pub mod liggghts;
pub mod material;
pub mod measure;
pub mod output;
pub mod particles;
pub mod process;
pub mod quadrature;
pub mod quasistatic;
pub mod run;
pub mod scene;
pub mod simulation;
pub mod space;
pub mod study;
pub mod timestep;
pub mod until;
pub mod verify;

pub use error::{Result, TampError};

/// Version and commit this binary was built from.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");
pub const GIT_COMMIT: &str = env!("TAMP_GIT_COMMIT");
/// Git objects of `src/` and `Cargo.lock` this build was made from (`-dirty` when they
/// had uncommitted changes): equal for two builds whose results must be equal.
pub const SOURCE_TREE: &str = env!("TAMP_SOURCE_TREE");
