//! LAMMPS (22 Jul 2025, `pair_style granular`), tamp's second peer code: writing a deck
//! for a tamp scene (`export`). Its dumps are read by the LIGGGHTS reader
//! (`liggghts::dump`, the same `dump custom` format, atoms sorted by id whatever rank
//! wrote them), and its recorded cross-check cases run through `verify::crosscheck`.
//! What each law is in LAMMPS is declared by the law (contact/lammps.rs);
//! docs/lammps.md has the mapping and the comparisons.

pub mod die_compaction;
pub mod export;
pub mod formula;
