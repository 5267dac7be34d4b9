//! The case registry: scene name → function. Adding a case = its JSON file in
//! `verification/` + one file here + one line in `CASES`.

mod energy_conservation_elastic;
mod hertz_collision_time;
mod hertz_yield_onset;
mod linear_restitution;
mod momentum_conservation;
pub mod probe;

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
];

pub fn find(name: &str) -> Option<CaseFn> {
    CASES.iter().find(|(n, _)| *n == name).map(|(_, f)| *f)
}
