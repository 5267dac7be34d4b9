//! The case registry: scene name → function. Adding a case = its JSON file in
//! `verification/` + one file here + one line in `CASES`.

mod energy_conservation_elastic;
mod hertz_collision_time;
mod hertz_yield_onset;
mod hollomon_constants;
mod linear_restitution;
mod momentum_conservation;
pub mod probe;
mod rojek_models;
mod three_sphere_compression;
mod two_sphere_compression;

use super::CaseFn;

pub const CASES: &[(&str, CaseFn)] = &[
    ("linear_restitution", linear_restitution::run),
    ("hertz_collision_time", hertz_collision_time::run),
    ("hertz_yield_onset", hertz_yield_onset::run),
    (
        "energy_conservation_elastic",
        energy_conservation_elastic::run,
    ),
    ("momentum_conservation", momentum_conservation::run),
    ("two_sphere_compression", two_sphere_compression::run),
    ("three_sphere_compression", three_sphere_compression::run),
    ("hollomon_constants", hollomon_constants::run),
];

pub fn find(name: &str) -> Option<CaseFn> {
    CASES.iter().find(|(n, _)| *n == name).map(|(_, f)| *f)
}
