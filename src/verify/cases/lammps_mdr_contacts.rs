//! MDR contacts under prescribed motion, in tamp's kernel (`tamp_core::contact::mdr`)
//! against LAMMPS 22 Jul 2025 (`pair granular mdr` with `fix GRANULAR/MDR`,
//! reference_data/lammps/lammps_mdr_contacts). Every sphere is moved by a prescribed
//! displacement (pressed, pulled back past separation, pressed again beyond the first
//! peak), so the forces, radii and free surfaces depend on the law alone. Each step is
//! evaluated as LAMMPS evaluates it: the particles' update (radius growth), the contact
//! penalty over triplets and the mean surface displacement first, then the pair forces
//! in the neighbour list's order, then the wall's.
//!
//! Five runs: two equal spheres without adhesion (`damping mdr 1`); unequal spheres with
//! adhesion (`damping mdr 2`); equal spheres with the bulk trigger at 0.99 (the bulk
//! response on); a sphere against a plane wall (the wall side and its force magnifier);
//! three spheres whose outer contact is screened by the middle one (the penalty).
//!
//! Each run is also a scene with `"law": "mdr"`, run through the force loop with its
//! spheres moved by prescribed velocities that turn at the decks' steps.
//!
//! Checked: the kernel's forces, apparent radii and free-surface fractions against
//! LAMMPS at every recorded step (equal to the bit), and the scene's positions, forces
//! and radii (apart by the running sum of its prescribed motion); against the closed
//! forms of Zunker & Kamrin Part I, the elastic branch against Hertz with its first
//! correction, and the plastic loading branch against the yield pressure times the
//! contact area.

use crate::contact::mdr::damping::{MdrDamping, MdrDampingForm};
use crate::contact::mdr::side::{self, hertz_mean_pressure, yield_pressure};
use crate::contact::mdr::{
    Mdr, MdrContact, MdrParticles, PairSides, SideHistory, WallSide, bulk, penalty,
};
use crate::contact::normal::NormalLaw;
use crate::error::{Result, TampError};
use crate::particles::Vec3;
use crate::scene::Scene;
use crate::verify::recording::RecordSpec;
use crate::verify::{CaseContext, Measured};
use serde::Deserialize;
use serde_json::json;
use std::f64::consts::PI;
use std::fmt::Write as _;

/// The decks' common settings (`parameters` of the case file).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Parameters {
    youngs_modulus: f64,
    poisson_ratio: f64,
    yield_stress: f64,
    density: f64,
    /// Displacement of a moving sphere per step, m (its speed times the step).
    step_displacement: f64,
    /// Its speed, m/s.
    speed: f64,
    /// Last step of the first pressing, of the pull, of the second pressing.
    turns: [u64; 3],
    runs: Vec<Run>,
}

/// One of the recorded runs.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Run {
    label: String,
    spheres: Vec<Sphere>,
    /// A plane wall x = `wall` with its normal along +x, m.
    #[serde(default)]
    wall: Option<f64>,
    surface_energy: f64,
    /// The wall's surface energy where it differs from the particles' (`Mdr`).
    #[serde(default)]
    wall_surface_energy: Option<f64>,
    bulk_trigger: f64,
    damping: MdrDamping,
}

/// A sphere of the deck, its atom id its place in the list (from 1).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Sphere {
    radius: f64,
    /// Its start as LAMMPS reads it from the deck, m.
    start: [f64; 3],
    /// The axis (0, 1, 2) along which it is moved towards −, or none (at rest).
    #[serde(default)]
    moves: Option<usize>,
}

/// A results.csv row.
#[derive(Debug, Deserialize)]
struct Row {
    run: String,
    step: u64,
    gap: f64,
    force_x_1: f64,
    force_y_1: f64,
    force_x_2: f64,
    radius_1: f64,
    radius_2: f64,
    radius_3: f64,
    free_surface_1: f64,
    free_surface_2: f64,
    free_surface_3: f64,
}

impl Row {
    fn forces(&self) -> [f64; 3] {
        [self.force_x_1, self.force_y_1, self.force_x_2]
    }
    fn radii(&self) -> [f64; 3] {
        [self.radius_1, self.radius_2, self.radius_3]
    }
    fn free_surfaces(&self) -> [f64; 3] {
        [
            self.free_surface_1,
            self.free_surface_2,
            self.free_surface_3,
        ]
    }
}

/// tamp's values at one step, in the columns of a row, and what the closed forms need.
#[derive(Clone, Copy, Debug, Default)]
struct State {
    gap: f64,
    forces: [f64; 3],
    radii: [f64; 3],
    free_surfaces: [f64; 3],
    /// The first pair's normal force without the dashpot, N.
    normal: f64,
    /// The first pair's side 0 after the step.
    side: SideHistory,
}

impl Parameters {
    /// The run as a tamp scene: the law `mdr` in the force loop, the spheres moved by
    /// prescribed velocities that turn at the deck's steps, frictionless (the decks'
    /// μ is 0), a plane wall where the run has one.
    fn scene(&self, run: &Run) -> Result<Scene> {
        let dt = self.step_displacement / self.speed;
        let [t1, t2, steps] = self.turns;
        let law = self.law(run);
        let particles: Vec<serde_json::Value> = run
            .spheres
            .iter()
            .map(|s| {
                let along = |v: f64| {
                    let mut u = [0.0; 3];
                    if let Some(a) = s.moves {
                        u[a] = v;
                    }
                    u
                };
                let mut p = json!({
                    "position": s.start, "radius": s.radius, "material": "NiAl",
                    "prescribed_velocity": along(-self.speed),
                });
                if s.moves.is_some() {
                    p["prescribed_velocity_changes"] = json!([
                        {"time": t1 as f64 * dt, "velocity": along(self.speed)},
                        {"time": t2 as f64 * dt, "velocity": along(-self.speed)},
                    ]);
                }
                p
            })
            .collect();
        let mut scene = json!({
            "name": format!("lammps_mdr_contacts, run {}", run.label),
            "materials": [{"name": "NiAl", "density": self.density}],
            "contact": {"normal": serde_json::to_value(NormalLaw::Mdr(law)).expect("a law serialises")},
            "particles": particles,
            "time_step": {"fixed": dt},
            "run": {"steps": steps},
            // The triplet's small sphere is pressed past half its radius.
            "stability": {"max_overlap_fraction": 0.75},
        });
        if let Some(x) = run.wall {
            scene["walls"] = json!([{"name": "wall", "material": "NiAl",
                "shape": {"kind": "plane", "point": [x, 0.0, 0.0], "normal": [1.0, 0.0, 0.0]}}]);
        }
        crate::scene::parse(&scene.to_string())
    }

    /// A moving sphere's displacement and velocity along its axis at `step` (the decks'
    /// `v_d`, `v_w`).
    fn motion(&self, step: u64) -> (f64, f64) {
        let (c, k) = (-self.step_displacement, step as f64);
        let [t1, t2, _] = self.turns;
        if step <= t1 {
            (c * k, -self.speed)
        } else if step <= t2 {
            (c * (2.0 * t1 as f64 - k), self.speed)
        } else {
            (c * (k - 2.0 * (t2 - t1) as f64), -self.speed)
        }
    }

    fn law(&self, run: &Run) -> Mdr {
        Mdr {
            youngs_modulus: self.youngs_modulus,
            poisson_ratio: self.poisson_ratio,
            yield_stress: self.yield_stress,
            surface_energy: run.surface_energy,
            wall_surface_energy: run.wall_surface_energy,
            bulk_trigger: run.bulk_trigger,
            damping: run.damping,
        }
    }

    /// Step the spheres through the deck's motion; the state at every step.
    fn simulate(&self, run: &Run) -> Vec<State> {
        let law = self.law(run);
        let moduli = law.moduli();
        let n = run.spheres.len();
        let radii: Vec<f64> = run.spheres.iter().map(|s| s.radius).collect();
        let mass: Vec<f64> = radii
            .iter()
            .map(|&r| 4.0 * PI / 3.0 * r * r * r * self.density)
            .collect();
        let mut particles = MdrParticles::new(&radii);
        // The half neighbour list of LAMMPS's serial run: (i, j), i < j, ascending.
        let pairs: Vec<(usize, usize)> = (0..n)
            .flat_map(|i| (i + 1..n).map(move |j| (i, j)))
            .collect();
        let list: Vec<(u32, u32)> = pairs.iter().map(|&(i, j)| (i as u32, j as u32)).collect();
        let mut contacts = vec![MdrContact::default(); pairs.len()];
        let mut walls = vec![MdrContact::default(); n];
        let mut states = Vec::new();
        for step in 0..=self.turns[2] {
            let update = step > 0;
            let (d, w) = if update {
                self.motion(step)
            } else {
                (0.0, 0.0)
            };
            let mut x = vec![Vec3::zeros(); n];
            let mut v = vec![Vec3::zeros(); n];
            for (k, s) in run.spheres.iter().enumerate() {
                x[k] = Vec3::from(s.start);
                if let Some(a) = s.moves {
                    x[k][a] = s.start[a] + d;
                    v[k][a] = w;
                }
            }
            if update {
                particles.begin_step(law.bulk_trigger);
                contacts.iter_mut().for_each(|c| c.penalty = 0.0);
                penalty::screen(
                    &list,
                    |a, b| x[b] - x[a],
                    &particles.radius,
                    |c, p| contacts[c].penalty += p,
                );
                for (c, &(i, j)) in contacts.iter_mut().zip(&pairs) {
                    let dx = x[i] - x[j];
                    let rsq = dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2];
                    let radsum = particles.radius[i] + particles.radius[j];
                    if rsq < radsum * radsum {
                        let sides = PairSides::of(i, j, i as u64 + 1, j as u64 + 1);
                        bulk::add_pair(c, radsum - rsq.sqrt(), sides.0, &mut particles);
                    } else {
                        *c = MdrContact::default();
                    }
                }
                if let Some(plane) = run.wall {
                    for (i, c) in walls.iter_mut().enumerate() {
                        let dot = x[i][0] - plane;
                        if dot < particles.radius[i] && dot >= 0.0 {
                            bulk::add_wall(c, particles.radius[i] - dot, i, &mut particles);
                        } else {
                            *c = MdrContact::default();
                        }
                    }
                }
            }
            let mut f = vec![Vec3::zeros(); n];
            let mut first = (0.0, SideHistory::default());
            for (k, (c, &(i, j))) in contacts.iter_mut().zip(&pairs).enumerate() {
                let dx = x[i] - x[j];
                let rsq = dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2];
                let radsum = particles.radius[i] + particles.radius[j];
                if rsq >= radsum * radsum {
                    *c = MdrContact::default();
                    continue;
                }
                let r = rsq.sqrt();
                let rinv = 1.0 / r;
                let normal = dx * rinv;
                let sides = PairSides::of(i, j, i as u64 + 1, j as u64 + 1);
                let meff = mass[i] * mass[j] / (mass[i] + mass[j]);
                let out = c.pair(
                    &law,
                    &moduli,
                    radsum - r,
                    sides,
                    &mut particles,
                    normal,
                    meff,
                    update,
                );
                let vr = v[i] - v[j];
                let vnnr = vr[0] * normal[0] + vr[1] * normal[1] + vr[2] * normal[2];
                let total = out.force + -out.damping * vnnr;
                f[i] += normal * total;
                f[j] -= normal * total;
                if k == 0 {
                    first = (out.force, c.sides[0]);
                }
            }
            if let Some(plane) = run.wall {
                for (i, c) in walls.iter_mut().enumerate() {
                    let dot = x[i][0] - plane;
                    if !(dot < particles.radius[i] && dot >= 0.0) {
                        *c = MdrContact::default();
                        continue;
                    }
                    let normal = Vec3::new(dot * (1.0 / dot), 0.0, 0.0);
                    let out = c.wall(
                        &law.at_wall(),
                        &moduli,
                        particles.radius[i] - dot,
                        WallSide(i),
                        &mut particles,
                        normal,
                        mass[i],
                        update,
                    );
                    let vnnr = v[i][0] * normal[0] + v[i][1] * normal[1] + v[i][2] * normal[2];
                    f[i] += normal * (out.force + -out.damping * vnnr);
                }
            }
            let gap = match run.wall {
                Some(plane) => x[0][0] - plane,
                None => x[n - 1][0] - x[0][0],
            };
            let at = |a: &[f64], k: usize| a.get(k).copied().unwrap_or(0.0);
            states.push(State {
                gap,
                forces: [f[0][0], f[0][1], f.get(1).map_or(0.0, |f| f[0])],
                radii: [0, 1, 2].map(|k| at(&particles.radius, k)),
                free_surfaces: [0, 1, 2].map(|k| at(&particles.free_surface, k)),
                normal: first.0,
                side: first.1,
            });
        }
        states
    }
}

/// Largest |a − b| over the recorded rows and the given columns, scaled by `scale`.
fn largest_difference(
    rows: &[&Row],
    states: &[State],
    columns: impl Fn(&Row, &State) -> ([f64; 3], [f64; 3]),
    scale: f64,
) -> f64 {
    rows.iter()
        .flat_map(|row| {
            let (a, b) = columns(row, &states[row.step as usize]);
            (0..3).map(move |k| (a[k] - b[k]).abs() / scale)
        })
        .fold(0.0, f64::max)
}

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let p: Parameters = ctx.parameters()?;
    let rows: Vec<Row> = ctx.peer_results("lammps")?;
    let mut measured = Vec::new();
    let mut table = String::from(
        "run,step,gap,force_x_1_tamp,force_x_1_lammps,radius_1_tamp,radius_1_lammps,radius_2_tamp,radius_2_lammps\n",
    );
    for run in &p.runs {
        let states = p.simulate(run);
        let label = &run.label;
        let bad = |what: String| TampError::Other(format!("lammps_mdr_contacts: {what}"));
        let recorded: Vec<&Row> = rows.iter().filter(|r| &r.run == label).collect();
        if recorded.is_empty() {
            return Err(bad(format!("results.csv has no rows of run '{label}'")));
        }
        if let Some(row) = recorded.iter().find(|r| r.step as usize >= states.len()) {
            return Err(bad(format!(
                "run '{label}': results.csv row at step {} lies past the deck's last step {}",
                row.step,
                states.len() - 1
            )));
        }
        let peak = recorded
            .iter()
            .flat_map(|r| r.forces())
            .fold(0.0, |m: f64, f| m.max(f.abs()));
        let r0 = run.spheres[0].radius;
        let gap = recorded
            .iter()
            .map(|r| (r.gap - states[r.step as usize].gap).abs() / r0)
            .fold(0.0, f64::max);
        measured.push(Measured::new(&format!("gap_difference_{label}"), gap, 0.0));
        let force = largest_difference(&recorded, &states, |r, s| (r.forces(), s.forces), peak);
        measured.push(Measured::new(
            &format!("force_difference_{label}"),
            force,
            0.0,
        ));
        let radius = largest_difference(&recorded, &states, |r, s| (r.radii(), s.radii), r0);
        measured.push(Measured::new(
            &format!("radius_difference_{label}"),
            radius,
            0.0,
        ));
        let free = largest_difference(
            &recorded,
            &states,
            |r, s| (r.free_surfaces(), s.free_surfaces),
            1.0,
        );
        measured.push(Measured::new(
            &format!("free_surface_difference_{label}"),
            free,
            0.0,
        ));
        // The same run as a scene, through the force loop.
        let scene = p.scene(run)?;
        let rec = ctx.record(label, &scene, RecordSpec::every(10, true))?;
        let frame_at = |step: u64| rec.frames.iter().find(|f| f.step == step);
        let (mut scene_gap, mut scene_force, mut scene_radius) = (0.0f64, 0.0f64, 0.0f64);
        for r in &recorded {
            let f = frame_at(r.step).ok_or_else(|| {
                bad(format!(
                    "run '{label}': the scene's run has no frame at step {}",
                    r.step
                ))
            })?;
            let gap = match run.wall {
                Some(plane) => f.bodies[0].position[0] - plane,
                None => f.bodies[f.bodies.len() - 1].position[0] - f.bodies[0].position[0],
            };
            scene_gap = scene_gap.max((gap - r.gap).abs() / r0);
            let force = |k: usize| f.bodies.get(k).and_then(|b| b.force).unwrap_or_default();
            let forces = [force(0)[0], force(0)[1], force(1)[0]];
            for (a, b) in forces.iter().zip(r.forces()) {
                scene_force = scene_force.max((a - b).abs() / peak);
            }
            for (k, b) in r.radii().iter().enumerate().take(f.bodies.len()) {
                scene_radius = scene_radius.max((f.bodies[k].radius - b).abs() / r0);
            }
        }
        measured.push(Measured::new(
            &format!("scene_gap_difference_{label}"),
            scene_gap,
            0.0,
        ));
        measured.push(Measured::new(
            &format!("scene_force_difference_{label}"),
            scene_force,
            0.0,
        ));
        measured.push(Measured::new(
            &format!("scene_radius_difference_{label}"),
            scene_radius,
            0.0,
        ));
        for r in &recorded {
            let s = &states[r.step as usize];
            let _ = writeln!(
                table,
                "{label},{},{:e},{:e},{:e},{:e},{:e},{:e},{:e}",
                r.step,
                r.gap,
                s.forces[0],
                r.force_x_1,
                s.radii[0],
                r.radius_1,
                s.radii[1],
                r.radius_2
            );
        }
        if label == "equal" {
            measured.push(plastic_loading(&p, &states));
        }
    }
    measured.push(hertz_limit(&p));
    crate::output::create_dir(&ctx.report_dir)?;
    crate::output::write_atomic(
        &ctx.report_dir.join("lammps_mdr_contacts.csv"),
        table.as_bytes(),
    )?;
    Ok(measured)
}

/// On the first pressing after yield (equal spheres: both sides alike), the largest
/// relative departure of the normal force from p_Y A_c, the yield pressure over the
/// contact area A_c = π(2δR − δ²) + c_A at the side's overlap.
fn plastic_loading(p: &Parameters, states: &[State]) -> Measured {
    let worst = states[1..=p.turns[0] as usize]
        .iter()
        .filter(|s| s.side.yielded && s.side.mdr_overlap == s.side.max_mdr_overlap)
        .map(|s| {
            let (d, r) = (s.side.mdr_overlap, s.radii[1]);
            let area = PI * (2.0 * d * r - d * d) + s.side.area_intercept;
            let closed = yield_pressure(p.yield_stress, d, r) * area;
            (s.normal - closed).abs() / closed
        })
        .fold(0.0, f64::max);
    Measured::new("plastic_loading_pressure_area", worst, 0.0)
}

/// The elastic side of a sphere on a flat at δ/R = 1e-3 against Hertz's
/// 4/3 E* √R δ^{3/2} with the indenter's first correction (1 − 3δ/(40R)).
fn hertz_limit(p: &Parameters) -> Measured {
    let law = Mdr {
        youngs_modulus: p.youngs_modulus,
        poisson_ratio: p.poisson_ratio,
        yield_stress: 1e30,
        surface_energy: 0.0,
        wall_surface_energy: None,
        bulk_trigger: 0.5,
        damping: MdrDamping {
            coefficient: 0.0,
            form: MdrDampingForm::Stiffness,
        },
    };
    let moduli = law.moduli();
    let radius = 2e-6;
    let delta = 1e-3 * radius;
    let mut particles = MdrParticles::new(&[radius]);
    let mut h = SideHistory::default();
    let f = side::evaluate(
        &law,
        &moduli,
        &mut h,
        delta,
        0,
        &mut particles,
        1.0,
        Vec3::x(),
        true,
    );
    let e = moduli.plane_strain;
    let hertz = 4.0 / 3.0 * e * radius.sqrt() * delta.powf(1.5);
    debug_assert!(hertz_mean_pressure(e, delta, radius) < law.yield_stress);
    let ratio = f.force / (hertz * (1.0 - 3.0 * delta / (40.0 * radius)));
    Measured::new("hertz_limit_ratio", ratio, 1.0)
}
