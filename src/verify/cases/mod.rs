//! The case registry: scene name → function. Adding a case = its JSON file in
//! `verification/` + one file here + one line in `CASES`.

mod accuracy_on_demand;
mod affine_yield_2d;
mod ballistic_deposition_2d;
mod binary_packing;
mod compacted_deposit;
mod compaction_2d;
mod cylinder_wall_impact;
mod density_segregation;
mod die_compaction_replay;
mod die_press_cycle;
mod die_specimen;
pub(crate) mod energy_conservation_elastic;
mod hertz_collision_time;
mod hertz_damped_collision;
mod hertz_dashpot_forms;
mod hertz_rigid_wall_impact;
mod hertz_yield_onset;
mod hollomon_constants;
mod kuwabara_kono_restitution;
mod lammps_die_press_cycle;
mod lammps_mdr_contacts;
mod lammps_mdr_deep_pair;
mod lammps_mdr_tableting;
mod lammps_mdr_triaxial;
mod linear_damped_collision;
mod linear_restitution;
mod mdr_curve;
mod momentum_conservation;
mod nial_die_compaction;
mod nial_die_compaction_dense;
mod nial_die_compaction_small;
mod no_pull_restitution;
mod oblique_impact;
mod one_material;
pub mod probe;
mod recorded_deck;
mod restitution_laws;
mod rojek_models;
mod rolling_resistance;
mod scott_random_packing;
mod settled_packing;
mod sliding_oblique_impact;
mod storakers_unloading;
mod thornton_restitution;
mod three_sphere_compression;
mod three_sphere_impact;
mod two_body;
mod two_sphere_compression;
mod van_der_waals_force;
mod yield_surface_2d;

use super::CaseFn;

pub const CASES: &[(&str, CaseFn)] = &[
    ("linear_restitution", linear_restitution::run),
    ("linear_damped_collision", linear_damped_collision::run),
    ("accuracy_on_demand", accuracy_on_demand::run),
    ("hertz_collision_time", hertz_collision_time::run),
    ("hertz_damped_collision", hertz_damped_collision::run),
    ("hertz_no_pull_restitution", no_pull_restitution::hertz),
    ("linear_no_pull_restitution", no_pull_restitution::linear),
    ("hertz_dashpot_forms", hertz_dashpot_forms::run),
    ("hertz_rigid_wall_impact", hertz_rigid_wall_impact::run),
    ("hertz_yield_onset", hertz_yield_onset::run),
    (
        "energy_conservation_elastic",
        energy_conservation_elastic::run,
    ),
    ("momentum_conservation", momentum_conservation::run),
    ("two_sphere_compression", two_sphere_compression::run),
    ("three_sphere_compression", three_sphere_compression::run),
    ("hollomon_constants", hollomon_constants::run),
    ("storakers_unloading", storakers_unloading::run),
    ("walton_braun_restitution", restitution_laws::walton_braun),
    ("hysteretic_restitution", restitution_laws::hysteretic),
    ("kuwabara_kono_restitution", kuwabara_kono_restitution::run),
    ("thornton_restitution", thornton_restitution::run),
    ("thornton_liggghts_restitution", thornton_restitution::run),
    ("sliding_oblique_impact", sliding_oblique_impact::run),
    ("rolling_resistance_lammps", rolling_resistance::run),
    ("oblique_wall_impact_liggghts", oblique_impact::wall),
    ("oblique_wall_impact_lammps_mindlin", oblique_impact::wall),
    ("oblique_wall_impact_lammps_linear", oblique_impact::wall),
    ("cylinder_wall_impact_liggghts", cylinder_wall_impact::run),
    ("cylinder_wall_impact_lammps", cylinder_wall_impact::run),
    ("moving_cylinder_impact_lammps", cylinder_wall_impact::run),
    ("moving_wall_impact_liggghts", oblique_impact::wall),
    ("moving_wall_impact_lammps", oblique_impact::wall),
    ("oblique_pair_impact_liggghts", oblique_impact::pair),
    ("oblique_pair_impact_lammps", oblique_impact::pair),
    ("three_sphere_impact_liggghts", three_sphere_impact::run),
    ("three_sphere_impact_lammps", three_sphere_impact::run),
    (
        "three_sphere_impact_lammps_classic",
        three_sphere_impact::run,
    ),
    ("three_sphere_impact_lammps_gran", three_sphere_impact::run),
    ("van_der_waals_force", van_der_waals_force::run),
    ("nial_die_compaction_small", nial_die_compaction_small::run),
    ("die_press_cycle", die_press_cycle::run),
    ("nial_die_compaction", nial_die_compaction::full),
    ("nial_die_compaction_dense", nial_die_compaction_dense::full),
    ("scott_random_packing_quick", scott_random_packing::run),
    ("scott_random_packing", scott_random_packing::run),
    ("density_segregation", density_segregation::run),
    ("binary_packing_ratio10_quick", binary_packing::run),
    ("binary_packing_ratio10", binary_packing::run),
    ("ballistic_deposition_2d", ballistic_deposition_2d::run),
    ("affine_closed_die_yield", affine_yield_2d::closed_die),
    ("affine_hydrostatic_yield", affine_yield_2d::hydrostatic),
    (
        "hydrostatic_compaction_2d_quick",
        compaction_2d::hydrostatic,
    ),
    ("hydrostatic_compaction_2d", compaction_2d::hydrostatic),
    ("closed_die_compaction_2d_quick", compaction_2d::closed_die),
    ("closed_die_compaction_2d", compaction_2d::closed_die),
    ("yield_surface_2d_quick", yield_surface_2d::run),
    ("yield_surface_2d", yield_surface_2d::run),
    ("liggghts_settled_packing", settled_packing::liggghts),
    (
        "liggghts_die_compaction_small",
        die_compaction_replay::liggghts,
    ),
    ("liggghts_die_compaction", die_compaction_replay::liggghts),
    ("lammps_die_compaction_small", die_compaction_replay::lammps),
    (
        "lammps_die_compaction_small_mdr",
        die_compaction_replay::lammps,
    ),
    ("lammps_die_press_cycle", lammps_die_press_cycle::run),
    ("lammps_mdr_contacts", lammps_mdr_contacts::run),
    ("lammps_mdr_deep_pair", lammps_mdr_deep_pair::run),
    ("lammps_mdr_tableting", lammps_mdr_tableting::run),
    ("lammps_mdr_triaxial", lammps_mdr_triaxial::run),
    ("lammps_settled_packing", settled_packing::lammps),
];

pub fn find(name: &str) -> Option<CaseFn> {
    CASES.iter().find(|(n, _)| *n == name).map(|(_, f)| *f)
}
