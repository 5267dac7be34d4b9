//! `tamp export-liggghts` of a die-compaction file: the pressing stage as a
//! LIGGGHTS-PUBLIC 3.8 deck that replays the punch stroke tamp pressed.
//!
//! tamp fills and flattens the specimen (`process::die_compaction::prepare`) and
//! presses it under the file's pressure ramp (`press`); the deck starts from the
//! flattened specimen (positions, radii, velocities, spins in `particles.data`) and
//! moves the punch along the heights tamp recorded (`process::die_replay`), so the
//! two codes compress the same bed along the same path and the forces they need to
//! do it compare. Why the stroke is replayed and not the load: LIGGGHTS 3.8 moves a
//! mesh only kinematically (`fix move/mesh`) or by `mesh/surface/stress/servo`, a
//! velocity controller v = −v_max (k_p e + k_i ∫e + k_d ė)/|F_target| with no mass;
//! it accepts a time-dependent target (`target_val v_name`, an equal-style
//! variable, never zero), but the punch it drives lags the target by what its gains
//! give, not by tamp's M a, so the pressures at a record would differ by the
//! controllers and not by the contact physics.
//!
//! The deck:
//! - the die as the primitive `zcylinder` of the die's radius (infinite in
//!   LIGGGHTS, tamp's ends above the punch: the same while no particle leaves),
//!   whose contacts LIGGGHTS takes as flat (R* = R_i, normal_model_hertz.h `is_wall`;
//!   docs/liggghts.md), so a die with `"die_curvature": "mean"` is refused;
//! - floor and punch as two-triangle STL squares with `fix mesh/surface/stress`,
//!   whose force vectors (`f_floor[3]`, `f_punch[3]`) thermo prints at every
//!   record; the punch moved by `fix move/mesh linear/variable` at the speed of
//!   the stroke's segment, one `run N` per record;
//! - a frame of every particle at every record (`dump.liggghts`), from which
//!   `tamp import-liggghts-dump --die-stroke stroke.json` measures the densities;
//! - `stroke.json`: the stroke, the die and RVE diameters.
//!   Everything else (contact model, damping, friction, rotation, refusals) is the
//!   ordinary export's (`export`).

use super::export::{
    contact_model, deck_head, g, particles_data, plane_triangles, refusals, refuse_all, stl,
};
use crate::error::Result;
use crate::particles::Vec3;
use crate::peer_deck::{DUMP_COLUMNS, Exported, dump_format};
use crate::process::die_compaction_file::{DieCompactionFile, DieCompactionSpec};
use crate::process::die_replay::{self, Stroke};
use crate::scene;
use crate::scene::walls::Curvature;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

/// What `import-liggghts-dump --die-stroke` needs besides the frames.
#[derive(Debug, Serialize, Deserialize)]
pub struct DieStroke {
    pub stroke: Stroke,
    pub die_diameter: f64,
    pub rve_diameter: f64,
    /// Under MDR, each particle's material radius by atom id: the dumped radius is
    /// the apparent one, which outgrows it, and the densities are mass fractions
    /// (`State::material_radius`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub material_radius: Option<BTreeMap<u64, f64>>,
}

impl DieStroke {
    /// Writes `DIR/stroke.json`, the punch stroke a replay deck follows and the
    /// diameters the importer measures the specimen and RVE with.
    pub fn write(
        out_dir: &Path,
        stroke: &Stroke,
        dc: &DieCompactionSpec,
        material_radius: Option<BTreeMap<u64, f64>>,
    ) -> Result<()> {
        let file = DieStroke {
            stroke: stroke.clone(),
            die_diameter: dc.die_diameter,
            rve_diameter: dc.rve_diameter,
            material_radius,
        };
        let json = serde_json::to_vec_pretty(&file).expect("stroke serialises");
        crate::output::write_atomic(&out_dir.join("stroke.json"), &json)
    }
}

/// The die-compaction fields LIGGGHTS's replay cannot express (the law's are the
/// ordinary export's `refusals`): a die with its curvature, since LIGGGHTS's wall
/// contacts take R* = R_i.
fn die_refusals(file: &DieCompactionFile) -> Vec<(String, String)> {
    match &file.die_compaction {
        dc if dc.die_curvature != Curvature::Flat => vec![(
            "die_compaction.die_curvature".into(),
            "LIGGGHTS's zcylinder wall gives the die contact R* = R_i (normal_model_hertz.h, is_wall), a flat wall; set \"die_curvature\": \"flat\"".into(),
        )],
        _ => Vec::new(),
    }
}

/// Fill, flatten and press `file` in tamp, then write the replay deck into `out_dir`.
pub fn export_pressing(file: &DieCompactionFile, sha: &str, out_dir: &Path) -> Result<Exported> {
    let solid = die_replay::solid_sphere_scene(file);
    let mut list = refusals(&solid.shared_scene());
    list.extend(die_refusals(file));
    list.extend(die_replay::cycle_refusals(file));
    if !list.is_empty() {
        return Err(refuse_all(list));
    }
    let dc = &file.die_compaction;
    let die_replay::Pressed {
        specimen,
        stroke,
        replay,
    } = die_replay::press_for_replay(file, &solid)?;
    let sim = scene::build(&replay)?.sim;
    let model = contact_model(&replay, &sim)?;
    crate::output::create_dir(out_dir)?;
    crate::output::create_dir(&out_dir.join("meshes"))?;

    // A fixed box around the die, its floor and the punch's start.
    let radius = 0.5 * dc.die_diameter;
    let max_r = sim.state().particles.largest_radius();
    // LIGGGHTS 3.8 refuses a mesh whose coordinates span less than 1e-4 length
    // units (multi_node_mesh_parallel_I.h, initalSetup): the squares reach past
    // the die, where no particle goes.
    let half = (1.1 * radius).max(1e-4);
    let side = 1.5 * half + 2.0 * max_r;
    let bounds = [
        [-side, side],
        [-side, side],
        [-2.0 * max_r, specimen.h0 + 2.0 * max_r],
    ];
    let data = particles_data(&sim, sha, &bounds);
    crate::output::write_atomic(&out_dir.join("particles.data"), data.as_bytes())?;
    let mut files = vec!["in.tamp".to_string(), "particles.data".to_string()];
    for (name, z, normal) in [("floor", 0.0, 1.0), ("punch", specimen.h0, -1.0)] {
        let triangles =
            plane_triangles(&Vec3::new(0.0, 0.0, z), &Vec3::new(0.0, 0.0, normal), half);
        let file = format!("meshes/{name}.stl");
        crate::output::write_atomic(&out_dir.join(&file), stl(name, &triangles).as_bytes())?;
        files.push(file);
    }
    DieStroke::write(out_dir, &stroke, dc, None)?;
    files.push("stroke.json".into());

    let mut deck = deck_head(&replay, sha, &sim, &["f", "f", "f"], &model);
    let wall_type = sim.model().walls[0].material + 1;
    let wall = &model.pair_style;
    let n = stroke.steps_per_record;
    let format = dump_format();
    let _ = writeln!(
        deck,
        "fix          die all wall/gran {wall} primitive type {wall_type} zcylinder {} 0 0",
        g(radius)
    );
    for name in ["floor", "punch"] {
        let _ = writeln!(
            deck,
            "fix          {name} all mesh/surface/stress file meshes/{name}.stl type {wall_type}"
        );
    }
    let _ = writeln!(
        deck,
        "fix          walls all wall/gran {wall} mesh n_meshes 2 meshes floor punch\n\
         variable     vx equal 0\nvariable     vy equal 0\nvariable     vz equal 0\n\
         fix          stroke all move/mesh mesh punch linear/variable v_vx v_vy v_vz\n\
         fix          integr all nve/sphere\n\
         dump         dmp all custom {n} dump.liggghts {DUMP_COLUMNS}\n\
         dump_modify  dmp format \"{format}\" sort id\n\
         # the particles' force on punch and floor (N) and the punch's displacement (m)\n\
         thermo_style custom step time f_punch[3] f_floor[3] f_punch[9]\n\
         thermo_modify norm no lost ignore format float %.17g\n\
         thermo       {n}"
    );
    for k in 0..stroke.heights.len() {
        let _ = writeln!(
            deck,
            "# record {}: tamp pressed {} Pa, punch face at {} m\nvariable     vz equal {}\nrun          {n}",
            k + 1,
            g(stroke.pressures[k]),
            g(stroke.heights[k]),
            g(stroke.speed(k))
        );
    }
    let mut notes = vec![
        format!(
            "the punch replays the stroke tamp pressed under the pressure ramp (h0 = {} m, {} records of {} steps of {} s)",
            g(specimen.h0),
            stroke.heights.len(),
            n,
            g(stroke.dt)
        ),
        "the die is LIGGGHTS's infinite zcylinder primitive; floor and punch are STL squares (run LIGGGHTS with its screen output on: 3.8 crashes reading an STL mesh without a screen)".into(),
    ];
    if let Some(r) = file
        .scene
        .rotation
        .as_ref()
        .filter(|r| r.inertia_scale != 1.0)
    {
        notes.push(format!(
            "tamp filled, flattened and pressed with rotation.inertia_scale {}; LIGGGHTS's fix nve/sphere has the solid sphere's only, so the replay uses 1",
            r.inertia_scale
        ));
    }
    for note in notes.iter().rev() {
        deck.insert_str(0, &format!("# note: {note}\n"));
    }
    crate::output::write_atomic(&out_dir.join("in.tamp"), deck.as_bytes())?;
    Ok(Exported {
        particles: sim.state().particles.len(),
        steps: n * stroke.heights.len() as u64,
        dt: stroke.dt,
        files,
        notes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::checked_in_die_compaction as scene;

    #[test]
    fn a_die_with_its_curvature_is_refused_and_a_flat_one_is_not() {
        assert!(die_refusals(&scene("liggghts_die_compaction_small")).is_empty());
        let paths: Vec<String> = die_refusals(&scene("lammps_die_compaction_small"))
            .into_iter()
            .map(|(p, _)| p)
            .collect();
        assert_eq!(paths, ["die_compaction.die_curvature"]);
    }
}
