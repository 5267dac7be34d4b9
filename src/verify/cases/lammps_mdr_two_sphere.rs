//! MDR's single contact: two spheres moved by prescribed displacements (pressed,
//! pulled apart past separation, pressed again beyond the first peak), the contact
//! evaluated by tamp's MDR kernel (`tamp_core::contact::mdr`) step by step as LAMMPS
//! evaluates `pair granular mdr` with `fix GRANULAR/MDR`: the radius update and mean
//! surface displacement at the start of every step, then the force. Two runs: equal
//! spheres without adhesion (`damping mdr 1`), and unequal ones with adhesion
//! (`damping mdr 2`), recorded in reference_data/lammps/lammps_mdr_two_sphere.
//!
//! Checked: the force, both apparent radii and both free-surface fractions against
//! LAMMPS at every recorded step; against the closed forms of Zunker & Kamrin Part I,
//! the elastic branch against Hertz with its first correction, and the plastic
//! loading branch against the yield pressure times the contact area.

use crate::contact::mdr::damping::{MdrDamping, MdrDampingForm};
use crate::contact::mdr::side::{self, hertz_mean_pressure, yield_pressure};
use crate::contact::mdr::{Mdr, MdrContact, MdrParticles, PairSides, SideHistory, bulk};
use crate::error::{Result, TampError};
use crate::particles::Vec3;
use crate::verify::{CaseContext, Measured};
use serde::Deserialize;
use std::f64::consts::PI;
use std::fmt::Write as _;

/// The deck's common settings (`parameters` of the case file).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Parameters {
    youngs_modulus: f64,
    poisson_ratio: f64,
    yield_stress: f64,
    bulk_trigger: f64,
    density: f64,
    /// Displacement of sphere 2 per step, m (its speed times the step).
    step_displacement: f64,
    /// Its speed, m/s.
    speed: f64,
    /// Last step of the first pressing, of the pull, of the second pressing.
    turns: [u64; 3],
    runs: Vec<Run>,
}

/// One of the deck's runs.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Run {
    label: String,
    radii: [f64; 2],
    surface_energy: f64,
    damping: MdrDamping,
    /// The start of sphere 2 as LAMMPS reads it from the deck, m.
    start: f64,
}

/// A results.csv row.
#[derive(Debug, Deserialize)]
struct Row {
    run: String,
    step: u64,
    gap: f64,
    force: f64,
    radius_1: f64,
    radius_2: f64,
    free_surface_1: f64,
    free_surface_2: f64,
}

/// tamp's values at one step, and what the closed forms need.
#[derive(Clone, Copy, Debug, Default)]
struct State {
    gap: f64,
    force: f64,
    radius: [f64; 2],
    free_surface: [f64; 2],
    /// The normal force without the dashpot, N.
    normal: f64,
    /// Side 0 after the step.
    side: SideHistory,
}

impl Parameters {
    /// Sphere 2's displacement and velocity at `step` (the deck's `v_dx`, `v_vx`).
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

    /// Step the pair through the deck's motion; the state at every step.
    fn simulate(&self, run: &Run) -> Vec<State> {
        let law = Mdr {
            youngs_modulus: self.youngs_modulus,
            poisson_ratio: self.poisson_ratio,
            yield_stress: self.yield_stress,
            surface_energy: run.surface_energy,
            bulk_trigger: self.bulk_trigger,
            damping: run.damping,
        };
        let moduli = law.moduli();
        let mass = run.radii.map(|r| 4.0 * PI / 3.0 * r * r * r * self.density);
        let effective_mass = mass[0] * mass[1] / (mass[0] + mass[1]);
        let mut particles = MdrParticles::new(&run.radii);
        let mut contact = MdrContact::default();
        // LAMMPS's side 0 is the larger atom id: sphere 2.
        let sides = PairSides::of(0, 1, 1, 2);
        let mut states = Vec::new();
        let last = self.turns[2];
        for step in 0..=last {
            let update = step > 0;
            let (dx, v2) = if update {
                self.motion(step)
            } else {
                (0.0, 0.0)
            };
            let x2 = run.start + dx;
            if update {
                particles.begin_step(law.bulk_trigger);
            }
            // x_1 − x_2, with sphere 1 at the origin.
            let delx = 0.0 - x2;
            let r = (delx * delx).sqrt();
            let radsum = particles.radius[0] + particles.radius[1];
            let touching = r * r < radsum * radsum;
            if update {
                if touching {
                    bulk::add_pair(&contact, radsum - r, sides.0, &mut particles);
                } else {
                    contact = MdrContact::default();
                }
            }
            let (mut force, mut normal_force) = (0.0, 0.0);
            if touching {
                let rinv = 1.0 / r;
                let delta = radsum - r;
                let nx = delx * rinv;
                let normal = Vec3::new(nx, 0.0, 0.0);
                let f = contact.pair(
                    &law,
                    &moduli,
                    delta,
                    sides,
                    &mut particles,
                    normal,
                    effective_mass,
                    update,
                );
                let vnnr = (0.0 - v2) * nx;
                let total = f.force + -f.damping * vnnr;
                normal_force = f.force;
                force = -(total * nx);
            } else {
                contact = MdrContact::default();
            }
            states.push(State {
                gap: x2 - 0.0,
                force,
                radius: [particles.radius[0], particles.radius[1]],
                free_surface: [particles.free_surface[0], particles.free_surface[1]],
                normal: normal_force,
                side: contact.sides[0],
            });
        }
        states
    }
}

/// Largest |a − b| over the recorded rows, each column scaled by `scale`.
fn largest_difference(
    rows: &[&Row],
    states: &[State],
    column: impl Fn(&Row, &State) -> (f64, f64),
    scale: f64,
) -> f64 {
    rows.iter()
        .map(|row| {
            let (a, b) = column(row, &states[row.step as usize]);
            (a - b).abs() / scale
        })
        .fold(0.0, f64::max)
}

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let p: Parameters = ctx.parameters()?;
    let rows: Vec<Row> = ctx.peer_results("lammps")?;
    let mut measured = Vec::new();
    let mut table = String::from(
        "run,step,gap,force_tamp,force_lammps,radius_1_tamp,radius_1_lammps,radius_2_tamp,radius_2_lammps\n",
    );
    for run in &p.runs {
        let states = p.simulate(run);
        let recorded: Vec<&Row> = rows.iter().filter(|r| r.run == run.label).collect();
        if recorded.is_empty() {
            return Err(TampError::Other(format!(
                "lammps_mdr_two_sphere: results.csv has no rows of run '{}'",
                run.label
            )));
        }
        if let Some(row) = recorded.iter().find(|r| r.step as usize >= states.len()) {
            return Err(TampError::Other(format!(
                "lammps_mdr_two_sphere: results.csv row at step {} lies past the deck's last step {}",
                row.step,
                states.len() - 1
            )));
        }
        let peak = recorded.iter().map(|r| r.force.abs()).fold(0.0, f64::max);
        let label = &run.label;
        measured.push(Measured::new(
            &format!("gap_difference_{label}"),
            largest_difference(&recorded, &states, |r, s| (r.gap, s.gap), run.radii[0]),
            0.0,
        ));
        measured.push(Measured::new(
            &format!("force_difference_{label}"),
            largest_difference(&recorded, &states, |r, s| (r.force, s.force), peak),
            0.0,
        ));
        measured.push(Measured::new(
            &format!("radius_difference_{label}"),
            largest_difference(
                &recorded,
                &states,
                |r, s| (r.radius_1, s.radius[0]),
                run.radii[0],
            )
            .max(largest_difference(
                &recorded,
                &states,
                |r, s| (r.radius_2, s.radius[1]),
                run.radii[1],
            )),
            0.0,
        ));
        measured.push(Measured::new(
            &format!("free_surface_difference_{label}"),
            largest_difference(
                &recorded,
                &states,
                |r, s| (r.free_surface_1, s.free_surface[0]),
                1.0,
            )
            .max(largest_difference(
                &recorded,
                &states,
                |r, s| (r.free_surface_2, s.free_surface[1]),
                1.0,
            )),
            0.0,
        ));
        for r in &recorded {
            let s = &states[r.step as usize];
            let _ = writeln!(
                table,
                "{label},{},{:e},{:e},{:e},{:e},{:e},{:e},{:e}",
                r.step, r.gap, s.force, r.force, s.radius[0], r.radius_1, s.radius[1], r.radius_2
            );
        }
        if run.surface_energy == 0.0 {
            measured.push(plastic_loading(&p, &states));
        }
    }
    measured.push(hertz_limit(&p));
    crate::output::create_dir(&ctx.report_dir)?;
    crate::output::write_atomic(
        &ctx.report_dir.join("lammps_mdr_two_sphere.csv"),
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
            let (d, r) = (s.side.mdr_overlap, s.radius[1]);
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
        bulk_trigger: p.bulk_trigger,
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
