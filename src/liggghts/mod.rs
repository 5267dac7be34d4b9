//! LIGGGHTS-PUBLIC 3.8, tamp's main peer code: writing a deck for a tamp scene
//! (`export`), reading the dumps such a deck writes (`dump`), and running the
//! recorded cross-check cases against LIGGGHTS (`crosscheck`). The contact physics
//! both codes share, and where they differ, is in docs/liggghts.md.

pub mod crosscheck;
pub mod die_compaction;
pub mod dump;
pub mod export;
pub mod import;
