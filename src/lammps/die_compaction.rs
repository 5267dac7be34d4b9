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

use super::export::{pair_model, refusals};
use crate::error::Result;
use crate::liggghts::die_compaction::DieStroke;
use crate::peer_deck::{DUMP_COLUMNS, Exported, dump_format, neighbor_skin};
use crate::process::die_compaction_file::DieCompactionFile;
use crate::process::die_replay;
use crate::scene;
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
    out.extend(die_replay::cycle_refusals(file));
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

/// Fill, flatten and press `file` in tamp, then write the LAMMPS replay deck into
/// `out_dir`.
pub fn export_pressing(file: &DieCompactionFile, sha: &str, out_dir: &Path) -> Result<Exported> {
    let list = die_refusals(file);
    if !list.is_empty() {
        return Err(crate::error::cannot_export("LAMMPS", list));
    }
    let (scene, dc) = (file, &file.die_compaction);
    let solid = die_replay::solid_sphere_scene(file);
    let die_replay::Pressed {
        specimen,
        stroke,
        replay,
    } = die_replay::press_for_replay(file, &solid)?;
    let mut probe = replay.clone();
    if let Some(t) = probe.contact.tangential.as_mut() {
        t.friction_pairs.clear();
    }
    let model = pair_model(&probe).map_err(|l| crate::error::cannot_export("LAMMPS", l))?;
    let sim = scene::build(&replay)?.sim;
    crate::output::create_dir(out_dir)?;

    let radius = 0.5 * dc.die_diameter;
    let max_r = sim.state().particles.largest_radius();
    let side = radius + 2.0 * max_r;
    let bounds = [
        [-side, side],
        [-side, side],
        [-2.0 * max_r, specimen.h0 + 2.0 * max_r],
    ];
    let p = &sim.state().particles;
    let data = crate::output::data_file::particles_data(
        &sim,
        "LAMMPS",
        sha,
        &format!(": the flattened specimen of seed {}", scene.scene.seed),
        &bounds,
        "Atoms # sphere",
    );
    crate::output::write_atomic(&out_dir.join("particles.data"), data.as_bytes())?;
    DieStroke::write(out_dir, &stroke, dc)?;

    let particle = &dc.particles.material;
    let material = |name: &str| {
        scene
            .scene
            .materials
            .iter()
            .find(|m| m.name == name)
            .expect("validated material")
    };
    let line = |name: &str, mu: f64| {
        let m = material(name);
        model
            .replace("{E}", &g(m.youngs_modulus.unwrap_or(0.0)))
            .replace("{nu}", &g(m.poisson_ratio.unwrap_or(0.0)))
            .replace("{mu}", &g(mu))
    };
    let pair = line(
        particle,
        scene.scene.contact.friction_between(particle, particle),
    );
    let wall = line(
        &dc.wall_material,
        scene
            .scene
            .contact
            .friction_between(particle, &dc.wall_material),
    );
    let n = stroke.steps_per_record;
    let steps = n * stroke.heights.len() as u64;
    let mut deck = String::new();
    let notes = vec![
        format!(
            "the punch replays the stroke tamp pressed under the pressure ramp (h0 = {} m, {} records of {} steps of {} s)",
            g(specimen.h0),
            stroke.heights.len(),
            n,
            g(stroke.dt)
        ),
        "the die is LAMMPS's infinite zcylinder wall, its contacts with the wall radius -2 R_c (tamp's die_curvature mean); the floor a zplane; the punch a moving region plane".into(),
    ];
    let mut notes = notes;
    if let Some(r) = scene
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
    for note in &notes {
        let _ = writeln!(deck, "# note: {note}");
    }
    let _ = writeln!(
        deck,
        "# LAMMPS (22 Jul 2025) deck exported by tamp {} (commit {})\n# scene '{}', sha256 {sha}, seed {}\n# run: lmp -in in.tamp",
        crate::VERSION,
        crate::GIT_COMMIT,
        scene.scene.name.replace(['\n', '\r'], " "),
        scene.scene.seed
    );
    deck.push_str(
        "units        si\natom_style   sphere\natom_modify  map array\nboundary     f f f\n\
         newton       off\ncomm_modify  vel yes\nread_data    particles.data\n",
    );
    let _ = writeln!(
        deck,
        "neighbor     {} bin\nneigh_modify delay 0\n\
         # limit_damping is off (not written), as tamp's damping.\npair_style   granular\n\
         pair_coeff   * * {pair}\ntimestep     {}",
        g(neighbor_skin(&replay, &p.radius)),
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
    let _ = writeln!(
        deck,
        "fix          die all wall/gran granular {wall} zcylinder {} contacts\n\
         fix          floor all wall/gran granular {wall} zplane 0e0 NULL contacts\n\
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
         thermo       {n}",
        g(radius),
        punch_displacement(&stroke),
        g(specimen.h0),
        dump_format()
    );
    // One run for the whole stroke: LAMMPS's setup before a further `run` would
    // give the moving region the velocity 0 (Region::set_velocity at a repeated
    // step) and kick the particles with the forces of that state.
    let _ = writeln!(deck, "run          {steps}");
    crate::output::write_atomic(&out_dir.join("in.tamp"), deck.as_bytes())?;
    Ok(Exported {
        particles: p.len(),
        steps,
        dt: stroke.dt,
        files: vec![
            "in.tamp".into(),
            "particles.data".into(),
            "stroke.json".into(),
        ],
        notes,
    })
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
        // The replay stops at the peak: a press cycle is refused, not dropped.
        let mut cycle = scene("lammps_die_compaction_small");
        cycle.die_compaction.unload = Some(crate::process::press_cycle::UnloadSpec {
            speed: 0.05,
            record_interval: 1e-7,
        });
        let paths: Vec<String> = die_refusals(&cycle).into_iter().map(|(p, _)| p).collect();
        assert_eq!(paths, ["die_compaction.unload"]);
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
