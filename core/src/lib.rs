//! tamp-core: the discrete element method of tamp, a verification-first reference
//! implementation for powder packing and cold die compaction. A scene file becomes a
//! [`simulation::Simulation`], which steps particles under contact laws, walls and
//! gravity; a process (die compaction) is a sequence of such runs. What checks this
//! crate against closed forms, papers and peer codes lives in the `tamp` crate, which
//! depends on this one and never the other way. See docs/architecture.md.

#![warn(missing_docs)]

pub mod accuracy;
pub mod bins;
pub mod boundary;
pub mod checkpoint;
pub mod collision;
pub mod contact;
pub mod decimal;
pub mod detect;
pub mod document;
pub mod error;
pub mod expression;
pub mod generate;
pub mod growth;
pub mod integrate;
pub mod interrupt;
pub mod material;
pub mod measure;
pub mod output;
pub mod particles;
pub mod process;
pub mod progress;
pub mod quadrature;
pub mod quasistatic;
pub mod run;
pub mod scene;
pub mod simulation;
pub mod space;
pub mod timestep;
pub mod until;

pub use error::{Result, TampError};

/// Version and commit this binary was built from.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");
/// Commit of the working tree this build was made from (`-dirty` with uncommitted changes).
pub const GIT_COMMIT: &str = env!("TAMP_GIT_COMMIT");
/// Git objects of the code that decides results (`core/`, `src/`, `Cargo.lock`; `-dirty`
/// when they had uncommitted changes): equal for two builds whose results must be equal.
pub const SOURCE_TREE: &str = env!("TAMP_SOURCE_TREE");
