//! LIGGGHTS-PUBLIC 3.8, tamp's main peer code: writing a deck for a tamp scene
//! (`export`) and reading the dumps such a deck writes (`dump`, `import`); the recorded
//! cross-checks against both peers run in `verify::crosscheck`. The contact physics
//! both codes share, and where they differ, is in docs/liggghts.md.

pub mod die_compaction;
pub mod dump;
pub mod export;
pub mod import;
