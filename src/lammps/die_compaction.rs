//! `tamp export-lammps` of a die-compaction file: the pressing stage as a LAMMPS
//! (22 Jul 2025) deck that replays the punch stroke tamp pressed, the same replay
//! the LIGGGHTS export writes (`liggghts::die_compaction`, `process::die_replay`):
//! tamp fills, flattens and presses the specimen, records the punch heights, and
//! both codes move the punch through them at one fixed step.
//!
//! The deck (walls written here, not by the general export, because a die is a
//! cylinder and the punch moves):
//! - the particles of the flattened specimen (`particles.data`: id, type, diameter,
//!   density, position; velocities and spins), the pair model of the scene's law
//!   (`pair granular`, `lammps::export::pair_model`), μ between particles;
//! - the die as `fix wall/gran granular … zcylinder R` (LAMMPS's cylinder about the
//!   z axis, infinite; tamp's ends above the punch: the same while no particle
//!   leaves), the floor as `zplane 0 NULL`, both fixed. LAMMPS gives a zcylinder
//!   contact the wall radius r_w = −2R inside (+2R outside), tamp's
//!   `"die_curvature": "mean"`, so a flat die is refused;
//! - the punch as `fix wall/gran/region` on a `region plane` whose `move` is the
//!   displacement variable `dz`, the piecewise linear stroke tamp's replay evaluates
//!   (`Stroke::displacement`) written as a table lookup (`punch_displacement`);
//!   LAMMPS gives a moving region the velocity (dz(t) − dz(t − Δt))/Δt, the chord
//!   over the step, as tamp's displacement motion does;
//! - the walls' friction μ_w is the scene's for (particle material, wall material);
//!   LAMMPS gives the wall the sphere's E and ν, so the wall material must have the
//!   particles' (refused otherwise);
//! - `contacts` on the three walls: per-atom contact forces, summed (`compute
//!   reduce`) into the particles' force on punch and floor printed by thermo at
//!   every record, and a frame of every particle per record (`dump.lammps`), from
//!   which `tamp import-liggghts-dump --die-stroke stroke.json` measures densities.

use super::export::{pair_model, refusals, surface_energy};
use crate::error::Result;
use crate::liggghts::die_compaction::DieStroke;
use crate::peer_deck::{DUMP_COLUMNS, Exported, dump_format, neighbor_skin};
use crate::process::die_compaction_file::DieCompactionFile;
use crate::process::{cycle_replay, die_replay};
use crate::scene::walls::Curvature;
use std::fmt::Write as _;
use std::path::Path;

use crate::decimal::g;

/// Every field of the die-compaction `scene` its LAMMPS replay cannot express.
/// The walls are written here (die, floor, punch), so the general export's wall
/// rules do not apply; its rules for the law, rotation and materials do.
pub fn die_refusals(file: &DieCompactionFile) -> Vec<(String, String)> {
    let mut probe = die_replay::solid_sphere_scene(file).shared_scene();
    if let Some(t) = probe.contact.tangential.as_mut() {
        t.friction_pairs.clear();
    }
    let mut out = refusals(&probe);
    let (scene, dc) = (file, &file.die_compaction);
    let particle = &dc.particles.material;
    let wall = &dc.wall_material;
    if let Some(t) = &scene.scene.contact.tangential {
        for (k, p) in t.friction_pairs.iter().enumerate() {
            let known = [particle.as_str(), wall.as_str()];
            if !(known.contains(&p.materials[0].as_str())
                && known.contains(&p.materials[1].as_str()))
            {
                out.push((
                    format!("contact.tangential.friction_pairs[{k}]"),
                    "the replay knows one particle material and one wall material; a pair of others has no LAMMPS counterpart here".into(),
                ));
            }
        }
    }
    let elastic = |name: &str| {
        scene
            .scene
            .materials
            .iter()
            .find(|m| m.name == name)
            .map(|m| (m.youngs_modulus, m.poisson_ratio))
    };
    if elastic(particle) != elastic(wall) {
        out.push((
            "die_compaction.wall_material".into(),
            "LAMMPS's fix wall/gran takes one E and ν for the wall and the sphere; give the wall material the particles' E and ν".into(),
        ));
    }
    if dc.die_curvature != Curvature::Mean {
        out.push((
            "die_compaction.die_curvature".into(),
            "LAMMPS's zcylinder wall gives the die contact the effective radius R r_w/(R + r_w) with r_w = -2 R_c (fix_wall_gran.cpp); tamp's default \"flat\" die takes R, a different Hertz stiffness; set \"die_curvature\": \"mean\" for LAMMPS's contact".into(),
        ));
    }
    if dc.unload.is_some() && dc.eject.is_none() {
        out.push((
            "die_compaction.unload".into(),
            "the cycle's deck replays tamp's cycle through the ejection: give die_compaction.eject too, or leave unload out to export the pressing".into(),
        ));
    }
    if dc.relax.is_some() {
        out.push((
            "die_compaction.relax".into(),
            "the cycle's deck ends when the compact has left the die; leave relax out".into(),
        ));
    }
    out
}

/// The deck lines defining `dz`, the punch face's displacement at step s of the
/// one-run replay: on segment j = ⌊s/N⌋ (N steps per record),
///   dz(s) = d_j + c_j (s − jN),  d_j = H_j − H₀,  c_j = (H_{j+1} − H_j)/N,
/// the stroke linear between records and exactly the recorded height at each
/// (dz(jN) = d_j, a number of the deck). d and c are LAMMPS vector-style variables
/// of constant lists (parsed once); `seg` = 1 + ⌊s/N⌋ indexes them (LAMMPS vectors
/// count from 1; the run's last step, s = nN, takes the extra entry d_n, c_n = 0).
/// Why a lookup: LAMMPS re-parses an equal-style formula at every step, and the
/// sum over the 50 segments (Σ_k v_k clamp(t − t_k, 0, T)) cost ~9 times the
/// contact forces, its ramp form Σ_k (v_k − v_{k−1})(t − t_k)(t > t_k) still
/// twice the lookup (docs/lammps.md).
fn punch_displacement(stroke: &die_replay::Stroke) -> String {
    let (d, c) = displacement_table(stroke);
    let list = |v: &[f64]| v.iter().map(|&x| g(x)).collect::<Vec<_>>().join(",");
    let n = stroke.steps_per_record;
    format!(
        "# the punch face's displacement (m) at each record and per step after it\n\
         variable     dzd vector [{}]\n\
         variable     dzc vector [{}]\n\
         variable     seg equal 1+floor(step/{n})\n\
         variable     dz equal v_dzd[v_seg]+v_dzc[v_seg]*(step-{n}*(v_seg-1))\n",
        list(&d),
        list(&c)
    )
}

/// d_j = H_j − H₀ and c_j = (H_{j+1} − H_j)/N for j = 0 … n (H_0 = H₀; c_n = 0).
fn displacement_table(stroke: &die_replay::Stroke) -> (Vec<f64>, Vec<f64>) {
    let heights: Vec<f64> = std::iter::once(stroke.h0)
        .chain(stroke.heights.iter().copied())
        .collect();
    let n = stroke.steps_per_record as f64;
    let d = heights.iter().map(|h| h - stroke.h0).collect();
    let c = heights
        .windows(2)
        .map(|w| (w[1] - w[0]) / n)
        .chain(std::iter::once(0.0))
        .collect();
    (d, c)
}

/// Fill, flatten and press `file` in tamp (and take it through its press cycle, when
/// the file has one), then write the LAMMPS replay deck into `out_dir`.
pub fn export_pressing(file: &DieCompactionFile, sha: &str, out_dir: &Path) -> Result<Exported> {
    let list = die_refusals(file);
    if !list.is_empty() {
        return Err(crate::error::cannot_export("LAMMPS", list));
    }
    let solid = die_replay::solid_sphere_scene(file);
    let (specimen, replay) = match file.die_compaction.unload {
        None => {
            let die_replay::Pressed {
                specimen,
                stroke,
                replay,
            } = die_replay::press_for_replay(file, &solid)?;
            (specimen, Replay::Pressing(stroke, replay))
        }
        Some(_) => {
            let (specimen, cycle) = cycle_replay::cycle_for_replay(file)?;
            let scene = die_replay::replay_scene(&solid, &specimen, &cycle.press)?;
            (specimen, Replay::Cycle(cycle, scene))
        }
    };
    let (stroke, scene) = match &replay {
        Replay::Pressing(stroke, scene) => (stroke, scene),
        Replay::Cycle(cycle, scene) => (&cycle.press, scene),
    };
    let mut probe = scene.clone();
    if let Some(t) = probe.contact.tangential.as_mut() {
        t.friction_pairs.clear();
    }
    let model = pair_model(&probe).map_err(|l| crate::error::cannot_export("LAMMPS", l))?;
    let sim = crate::scene::build(scene)?.sim;
    crate::output::create_dir(out_dir)?;

    let dc = &file.die_compaction;
    let radius = 0.5 * dc.die_diameter;
    let max_r = sim.state().particles.largest_radius();
    let side = radius + 2.0 * max_r;
    // The cycle's lower punch lifts the compact out of the die, and its upper punch
    // goes above it.
    let top = match &replay {
        Replay::Pressing(..) => specimen.h0 + 2.0 * max_r,
        Replay::Cycle(cycle, _) => specimen.h0 + cycle.punch_away() + 2.0 * max_r,
    };
    let bounds = [[-side, side], [-side, side], [-2.0 * max_r, top]];
    let p = &sim.state().particles;
    let data = crate::output::data_file::particles_data(
        &sim,
        "LAMMPS",
        sha,
        &format!(": the flattened specimen of seed {}", file.scene.seed),
        &bounds,
        "Atoms # sphere",
    );
    crate::output::write_atomic(&out_dir.join("particles.data"), data.as_bytes())?;
    let mdr = file.scene.contact.normal.mdr().is_some();
    let material_radius = mdr.then(|| {
        let state = sim.state();
        state
            .particles
            .id
            .iter()
            .copied()
            .zip(state.material_radius().iter().copied())
            .collect()
    });
    DieStroke::write(out_dir, stroke, dc, material_radius)?;

    let particle = &dc.particles.material;
    let material = |name: &str| {
        file.scene
            .materials
            .iter()
            .find(|m| m.name == name)
            .expect("validated material")
    };
    let line = |name: &str, mu: f64, wall: bool| {
        let m = material(name);
        surface_energy(&model, &file.scene, wall)
            .replace("{E}", &g(m.youngs_modulus.unwrap_or(0.0)))
            .replace("{nu}", &g(m.poisson_ratio.unwrap_or(0.0)))
            .replace("{mu}", &g(mu))
    };
    let contact = &file.scene.contact;
    let pair = line(
        particle,
        contact.friction_between(particle, particle),
        false,
    );
    let wall = line(
        &dc.wall_material,
        contact.friction_between(particle, &dc.wall_material),
        true,
    );
    let n = stroke.steps_per_record;
    let mut notes = vec![format!(
        "the punch replays the stroke tamp pressed under the pressure ramp (h0 = {} m, {} records of {} steps of {} s)",
        g(specimen.h0),
        stroke.heights.len(),
        n,
        g(stroke.dt)
    )];
    let (walls, steps, files) = match &replay {
        Replay::Pressing(..) => {
            notes.push(match mdr {
                false => "the die is LAMMPS's infinite zcylinder wall, its contacts with the wall radius -2 R_c (tamp's die_curvature mean); the floor a zplane; the punch a moving region plane".into(),
                true => "LAMMPS's mdr takes region walls only: the die is a region cylinder from the floor to the specimen's height H0, its ends open (the punch stays below H0), the floor and the punch region planes".into(),
            });
            (
                pressing_walls(&wall, radius, specimen.h0, stroke, mdr),
                n * stroke.heights.len() as u64,
                vec!["in.tamp", "particles.data", "stroke.json"],
            )
        }
        Replay::Cycle(cycle, _) => {
            notes.extend(cycle_notes(cycle));
            write_cycle(out_dir, cycle, dc.die_diameter)?;
            (
                cycle_walls(&wall, radius, cycle),
                cycle.steps(),
                vec!["in.tamp", "particles.data", "stroke.json", "cycle.json"],
            )
        }
    };
    if let Some(r) = file
        .scene
        .rotation
        .as_ref()
        .filter(|r| r.inertia_scale != 1.0)
    {
        notes.push(format!(
            "tamp filled, flattened and pressed with rotation.inertia_scale {}; LAMMPS's fix nve/sphere has the solid sphere's only, so the replay uses 1",
            r.inertia_scale
        ));
    }
    let mut deck = String::new();
    for note in &notes {
        let _ = writeln!(deck, "# note: {note}");
    }
    let _ = writeln!(
        deck,
        "# LAMMPS (22 Jul 2025) deck exported by tamp {} (commit {})\n# scene '{}', sha256 {sha}, seed {}\n# run: lmp -in in.tamp",
        crate::VERSION,
        crate::GIT_COMMIT,
        file.scene.name.replace(['\n', '\r'], " "),
        file.scene.seed
    );
    // The ejected compact is free to spread beyond the die, so the cycle's box is
    // shrink-wrapped (m): with fixed bounds, LAMMPS would drop a particle that left.
    let boundary = match &replay {
        Replay::Pressing(..) => "f f f",
        Replay::Cycle(..) => "m m m",
    };
    // MDR's apparent radii change every step: `sphere 1` sends them to the ghosts.
    let atom_style = match mdr {
        true => "sphere 1",
        false => "sphere",
    };
    let _ = write!(
        deck,
        "units        si\natom_style   {atom_style}\natom_modify  map array\nboundary     {boundary}\n\
         newton       off\ncomm_modify  vel yes\nread_data    particles.data\n",
    );
    let _ = writeln!(
        deck,
        "neighbor     {} bin\nneigh_modify delay 0\n\
         # limit_damping is off (not written), as tamp's damping.\npair_style   granular\n\
         pair_coeff   * * {pair}\ntimestep     {}",
        g(neighbor_skin(scene, &p.radius)),
        g(stroke.dt)
    );
    if let Some(gv) = sim.model().gravity.filter(|gv| gv.norm() > 0.0) {
        let d = gv / gv.norm();
        let _ = writeln!(
            deck,
            "fix          gravi all gravity {} vector {} {} {}",
            g(gv.norm()),
            g(d.x),
            g(d.y),
            g(d.z)
        );
    }
    deck.push_str(&walls);
    // One run for the whole replay: LAMMPS's setup before a further `run` would
    // give the moving regions the velocity 0 (Region::set_velocity at a repeated
    // step) and kick the particles with the forces of that state.
    let _ = writeln!(deck, "run          {steps}");
    crate::output::write_atomic(&out_dir.join("in.tamp"), deck.as_bytes())?;
    Ok(Exported {
        particles: p.len(),
        steps,
        dt: stroke.dt,
        files: files.into_iter().map(String::from).collect(),
        notes,
    })
}

/// What the deck replays: the pressing alone, or the whole cycle; each with the
/// press stage tamp replays it in.
enum Replay {
    Pressing(die_replay::Stroke, crate::scene::Scene),
    Cycle(cycle_replay::CycleStroke, crate::scene::Scene),
}

/// The pressing's walls: the die an infinite zcylinder and the floor a zplane, both
/// fixed, the punch a region plane moved by the stroke; thermo and a dump per record.
/// Under MDR (`mdr`), whose LAMMPS walls are regions only, the die is a region cylinder
/// from the floor to the specimen's height `h0` with open ends and the floor a region
/// plane: the same contacts while the particles stay below the punch.
fn pressing_walls(
    wall: &str,
    radius: f64,
    h0: f64,
    stroke: &die_replay::Stroke,
    mdr: bool,
) -> String {
    let n = stroke.steps_per_record;
    let fixed = match mdr {
        false => format!(
            "fix          die all wall/gran granular {wall} zcylinder {} contacts\n\
             fix          floor all wall/gran granular {wall} zplane 0e0 NULL contacts\n",
            g(radius)
        ),
        true => format!(
            "region       die cylinder z 0 0 {} 0 {} side in open 1 open 2 units box\n\
             region       floor plane 0 0 0 0 0 1 side in units box\n\
             fix          die all wall/gran/region granular {wall} region die contacts\n\
             fix          floor all wall/gran/region granular {wall} region floor contacts\n",
            g(radius),
            g(h0)
        ),
    };
    format!(
        "{fixed}\
         {}\
         region       punch plane 0 0 {} 0 0 -1 side in move NULL NULL v_dz units box\n\
         fix          punch all wall/gran/region granular {wall} region punch contacts\n\
         fix          integr all nve/sphere\n\
         # the particles' force on punch and floor (N): minus the walls' forces on them\n\
         compute      fpunch all reduce sum f_punch[4]\n\
         compute      ffloor all reduce sum f_floor[4]\n\
         variable     punch_fz equal -c_fpunch\n\
         variable     floor_fz equal -c_ffloor\n\
         dump         dmp all custom {n} dump.lammps {DUMP_COLUMNS}\n\
         dump_modify  dmp format line \"{}\" sort id\n\
         thermo_style custom step time v_punch_fz v_floor_fz v_dz\n\
         thermo_modify norm no lost ignore format float %.17g\n\
         thermo       {n}\n",
        punch_displacement(stroke),
        g(h0),
        dump_format()
    )
}

/// The notes a cycle deck carries: its stages and where LAMMPS's die differs from
/// tamp's.
fn cycle_notes(cycle: &cycle_replay::CycleStroke) -> Vec<String> {
    vec![
        format!(
            "then the punch rises {} m per step for {} steps (tamp's unloading to release), jumps {} m up, and the floor rises at up to {} m/s (ramp {} s) to the die's mouth in {} steps",
            g(cycle.unload_rise_per_step),
            cycle.unload_steps,
            g(cycle.punch_away()),
            g(cycle.eject_speed),
            g(cycle.eject_ramp),
            cycle.eject_steps
        ),
        "the die is a region cylinder from the floor's rest level to the mouth H0, its ends open: its contacts take the wall radius -2 R_c (tamp's die_curvature mean); a particle whose centre is above the mouth has none, where tamp's die has a rim".into(),
    ]
}

/// `cycle.json`: the cycle a deck replays, which the verification case replays in
/// tamp and checks the recorded deck against.
fn write_cycle(out_dir: &Path, cycle: &cycle_replay::CycleStroke, die_diameter: f64) -> Result<()> {
    let json = serde_json::to_vec_pretty(&serde_json::json!({
        "cycle": cycle,
        "die_diameter": die_diameter,
    }))
    .expect("the cycle serialises");
    crate::output::write_atomic(&out_dir.join("cycle.json"), &json)
}

/// The cycle's walls, all regions moved by step-indexed variables
/// (`cycle_replay`): the die a cylinder from 0 to H₀ with open ends, the floor a
/// plane rising by `fz`, the punch a plane following `dz`. Thermo every K steps
/// gives what `cycle_replay::CycleReplayRecord` holds; no dump.
fn cycle_walls(wall: &str, radius: f64, cycle: &cycle_replay::CycleStroke) -> String {
    let stroke = &cycle.press;
    let (np, nu, ne) = (cycle.press_steps(), cycle.unload_steps, cycle.unload_end());
    let n = stroke.steps_per_record;
    let k = cycle.record_steps;
    let dt = stroke.dt;
    let h0 = g(stroke.h0);
    let (d, c) = displacement_table(stroke);
    let list = |v: &[f64]| v.iter().map(|&x| g(x)).collect::<Vec<_>>().join(",");
    // LAMMPS's min() and max() are reductions of vectors, not of two numbers: the
    // clamps are written with ternary().
    let (tr, v) = (cycle.eject_ramp, cycle.eject_speed);
    let rise = match tr > 0.0 {
        true => format!(
            "ternary(v_te<{},{}*v_te^2,{}*(v_te-{}))",
            g(tr),
            g(0.5 * v / tr),
            g(v),
            g(0.5 * tr)
        ),
        false => format!("{}*v_te", g(v)),
    };
    format!(
        "# the punch face's displacement (m): the stroke (a lookup, as the pressing's deck),\n\
         # the unloading's rise per step, and the jump away after step {ne}\n\
         variable     dzd vector [{}]\n\
         variable     dzc vector [{}]\n\
         variable     sp equal ternary(step<{np},step,{np})\n\
         variable     seg equal 1+floor(v_sp/{n})\n\
         variable     su equal ternary(step<{ne},step-v_sp,{nu})\n\
         variable     dz equal v_dzd[v_seg]+v_dzc[v_seg]*(v_sp-{n}*(v_seg-1))+{}*v_su+{}*(step>{ne})\n\
         # the floor's rise (m): the ejection's speed ramped over {} s, up to the mouth\n\
         variable     te equal ternary(step>{ne},(step-{ne})*{},0)\n\
         variable     rise equal {rise}\n\
         variable     fz equal ternary(v_rise<{h0},v_rise,{h0})\n\
         region       die cylinder z 0 0 {} 0 {} side in open 1 open 2 units box\n\
         region       floor plane 0 0 0 0 0 1 side in move NULL NULL v_fz units box\n\
         region       punch plane 0 0 {} 0 0 -1 side in move NULL NULL v_dz units box\n\
         fix          die all wall/gran/region granular {wall} region die contacts\n\
         fix          floor all wall/gran/region granular {wall} region floor contacts\n\
         fix          punch all wall/gran/region granular {wall} region punch contacts\n\
         fix          integr all nve/sphere\n\
         # the particles' forces on the walls (N): minus the walls' on them\n\
         compute      fpunch all reduce sum f_punch[4]\n\
         compute      ffloor all reduce sum f_floor[4]\n\
         compute      fdie all reduce sum f_die[4]\n\
         variable     punch_fz equal -c_fpunch\n\
         variable     floor_push equal c_ffloor\n\
         variable     die_fz equal -c_fdie\n\
         # the die's outward radial load, the compact's spread <rho^2> and its top\n\
         variable     radial atom -(f_die[2]*x+f_die[3]*y)/sqrt(x*x+y*y)\n\
         variable     rho2 atom x*x+y*y\n\
         variable     top atom z+radius\n\
         compute      fradial all reduce sum v_radial\n\
         compute      spread all reduce ave v_rho2\n\
         compute      ctop all reduce max v_top\n\
         # the floor's push averaged over the {k} steps up to each record\n\
         fix          pushmean all ave/time 1 {k} {k} v_floor_push\n\
         thermo_style custom step v_dz v_fz v_punch_fz v_floor_push f_pushmean v_die_fz c_fradial c_spread c_ctop\n\
         thermo_modify norm no lost error format float %.17g\n\
         thermo       {k}\n",
        list(&d),
        list(&c),
        g(cycle.unload_rise_per_step),
        g(cycle.punch_away()),
        g(cycle.eject_ramp),
        g(dt),
        g(radius),
        g(stroke.h0),
        g(stroke.h0),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::checked_in_die_compaction as scene;

    #[test]
    fn the_lammps_die_scene_is_expressible_and_the_paper_law_is_refused_by_field() {
        assert!(die_refusals(&scene("lammps_die_compaction_small")).is_empty());
        // Rojek's law as nial_die_compaction_small writes it: Mindlin–Deresiewicz
        // has no pair granular model, and its lever arms are not LAMMPS's.
        let paths: Vec<String> = die_refusals(&scene("nial_die_compaction_small"))
            .into_iter()
            .map(|(p, _)| p)
            .collect();
        // ... and its die is flat, where LAMMPS's zcylinder has the wall's curvature.
        assert_eq!(
            paths,
            [
                "contact.tangential.law",
                "contact.lever_arm",
                "die_compaction.die_curvature"
            ]
        );
        let mut other = scene("lammps_die_compaction_small");
        other.scene.materials[1].youngs_modulus = Some(2e11);
        let paths: Vec<String> = die_refusals(&other).into_iter().map(|(p, _)| p).collect();
        assert_eq!(paths, ["die_compaction.wall_material"]);
        let mut flat = scene("lammps_die_compaction_small");
        flat.die_compaction.die_curvature = Curvature::Flat;
        let paths: Vec<String> = die_refusals(&flat).into_iter().map(|(p, _)| p).collect();
        assert_eq!(paths, ["die_compaction.die_curvature"]);
        // A cycle without its ejection is refused, not cut short.
        let mut cycle = scene("lammps_die_compaction_small");
        cycle.die_compaction.unload = Some(crate::process::press_cycle::UnloadSpec {
            speed: 0.05,
            record_interval: 1e-7,
        });
        let paths: Vec<String> = die_refusals(&cycle).into_iter().map(|(p, _)| p).collect();
        assert_eq!(paths, ["die_compaction.unload"]);
        // The cycle's deck goes through the ejection and ends there.
        let mut cycle = scene("lammps_die_press_cycle");
        assert!(die_refusals(&cycle).is_empty());
        cycle.die_compaction.relax = Some(crate::process::press_cycle::RelaxSpec {
            duration: 1e-6,
            records: 1,
        });
        let paths: Vec<String> = die_refusals(&cycle).into_iter().map(|(p, _)| p).collect();
        assert_eq!(paths, ["die_compaction.relax"]);
    }

    /// The replay's die is the pressing's: a cylinder of the die's radius with the
    /// scene's curvature, which is what the deck's zcylinder line stands for.
    #[test]
    fn the_replayed_die_has_the_scenes_curvature() {
        let s = scene("lammps_die_compaction_small");
        let dc = &s.die_compaction;
        assert_eq!(dc.die_curvature, Curvature::Mean);
        let specimen = crate::process::die_compaction::Specimen {
            h0: 6e-5,
            density_specimen: 0.6,
            density_rve: 0.7,
            particles: vec![crate::scene::schema::ParticleSpec {
                position: [0.0, 0.0, 3e-6],
                radius: 2e-6,
                material: "NiAl".into(),
                velocity: None,
                omega: None,
                prescribed_velocity: None,
                prescribed_velocity_changes: Vec::new(),
            }],
            fill_time: 0.0,
            fill_at_rest: true,
            steps: [0, 0],
            dt: [0.0, 0.0],
        };
        let stroke = die_replay::Stroke {
            h0: 6e-5,
            interval: 2e-6,
            steps_per_record: 10,
            dt: 2e-7,
            heights: vec![5.9e-5, 5.8e-5],
            pressures: vec![1e6, 2e6],
        };
        let replay = die_replay::replay_scene(&s, &specimen, &stroke).unwrap();
        let crate::scene::walls::ShapeSpec::Cylinder {
            radius, curvature, ..
        } = &replay.walls[0].shape
        else {
            panic!("the die is the first wall, a cylinder");
        };
        assert_eq!(
            (*radius, *curvature),
            (0.5 * dc.die_diameter, Curvature::Mean)
        );
    }

    /// LAMMPS's value of `dz` at step `s`, read back from the deck's lines: the
    /// vectors' numbers as LAMMPS parses them, `seg` and `dz` as it evaluates them.
    fn lammps_dz(lines: &str, s: u64) -> f64 {
        let list = |name: &str| -> Vec<f64> {
            let l = lines
                .lines()
                .find(|l| l.starts_with(&format!("variable     {name} vector [")))
                .expect("the vector's line");
            l[l.find('[').unwrap() + 1..l.len() - 1]
                .split(',')
                .map(|x| x.parse().unwrap())
                .collect()
        };
        let n: f64 = lines
            .lines()
            .find_map(|l| l.strip_prefix("variable     seg equal 1+floor(step/"))
            .and_then(|l| l.strip_suffix(')'))
            .expect("the seg line")
            .parse()
            .unwrap();
        let (d, c) = (list("dzd"), list("dzc"));
        let seg = 1.0 + (s as f64 / n).floor();
        let k = seg as usize - 1;
        d[k] + c[k] * (s as f64 - n * (seg - 1.0))
    }

    #[test]
    fn the_punch_displacement_is_the_stroke_at_and_between_the_records() {
        let stroke = die_replay::Stroke {
            h0: 6.282354800248903e-5,
            interval: 2e-6,
            steps_per_record: 15453,
            dt: 2e-6 / 15453.0,
            heights: vec![
                6.228688733219735e-5,
                6.0857285812429805e-5,
                6.020743200563283e-5,
                5.999492148214831e-5,
                5.999492148214831e-5,
                5.9946389877823e-5,
            ],
            pressures: vec![1e6; 6],
        };
        let lines = punch_displacement(&stroke);
        assert!(
            lines
                .contains("variable     dz equal v_dzd[v_seg]+v_dzc[v_seg]*(step-15453*(v_seg-1))")
        );
        let n = stroke.steps_per_record;
        let tamp = crate::expression::Expression::parse(&stroke.displacement(), &["t"]).unwrap();
        let heights: Vec<f64> = std::iter::once(stroke.h0)
            .chain(stroke.heights.iter().copied())
            .collect();
        let ulp = f64::EPSILON * stroke.h0;
        for j in 0..heights.len() {
            // At each record: the recorded height, to the rounding of H_j − H₀.
            let at = stroke.h0 + lammps_dz(&lines, j as u64 * n);
            assert!((at - heights[j]).abs() <= ulp, "record {j}: {at:e}");
            let Some(&next) = heights.get(j + 1) else {
                break;
            };
            // Between records: linear, and the displacement tamp's replay moves by.
            for i in [1, 2, n / 3, n / 2, n - 1] {
                let s = j as u64 * n + i;
                let dz = lammps_dz(&lines, s);
                let linear = heights[j] + (next - heights[j]) * i as f64 / n as f64;
                assert!((stroke.h0 + dz - linear).abs() <= 2.0 * ulp, "step {s}");
                let t = s as f64 * stroke.dt;
                assert!(
                    (dz - tamp.eval(&[t]).unwrap()).abs() <= 4.0 * ulp,
                    "step {s}"
                );
            }
        }
    }

    #[test]
    fn walls_take_the_particle_wall_friction_and_particles_their_own() {
        let s = scene("lammps_die_compaction_small");
        assert_eq!(s.scene.contact.friction_between("NiAl", "NiAl"), 0.0);
        assert_eq!(s.scene.contact.friction_between("NiAl", "die"), 0.02);
        assert_eq!(s.scene.contact.friction_between("die", "NiAl"), 0.02);
    }
}
