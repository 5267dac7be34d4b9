//! Load, unload and reload one Storåkers contact (Rojek 2016 eqs 16, 19–20), and
//! load and unload one Hertz contact, which keeps no permanent set: two
//! NiAl spheres driven together to δ_max, pulled back past the point where the force
//! vanishes, and pushed back through δ_max. The elastic branch of eq 19–20 integrates
//! to the Hertz curve through the turning point, so the permanent set is
//!   δ_res = δ_max − (F_max/K)^{2/3},  F_max = C δ_max^{1+m/2},  K = 4/3 E* √R*
//! with C from eq 16 (written out here independently of `crate::contact`), and
//! reloading must meet F_max again at δ_max (Rojek §3.3).
//!
//! The spheres are driven, so the overlap is known at every step before any run: the
//! scene turns their prescribed velocities back (`prescribed_velocity_changes`) at
//! the step that reaches `MAX_OVERLAP`, and again where the overlap is half the
//! permanent set the closed form predicts, still in contact whatever the law does
//! after its force vanished. Two runs of that one scene are recorded: to the second
//! turn, every step where the force is expected to vanish, and to just past δ_max
//! again, every step where reloading crosses it.

use super::two_body::{Pair, with_steps};
use crate::contact::normal::{Hertz, NormalLaw};
use crate::error::{Result, TampError};
use crate::scene::Scene;
use crate::scene::schema::VelocityChangeSpec;
use crate::verify::recording::{Frame, RecordSpec, Recording};
use crate::verify::{CaseContext, Measured, measure};

/// Beyond the Hertz crossover (1.6e-7 m for m = 0.2), so that δ_res > 0.
const MAX_OVERLAP: f64 = 3e-7;

/// The constants of eq 16 and the elastic stiffness of the pair, from the inputs.
struct Storakers {
    /// F = C δ^{1+m/2} on loading.
    c: f64,
    /// F = K δ_e^{3/2} on the elastic branch.
    k: f64,
    m: f64,
}

impl Storakers {
    fn of(scene: &Scene, r_eff: f64) -> Result<Storakers> {
        let mat = &scene.materials[0];
        let (e, nu) = (
            mat.youngs_modulus.unwrap_or(0.0),
            mat.poisson_ratio.unwrap_or(0.0),
        );
        let h = mat
            .hollomon
            .as_ref()
            .ok_or_else(|| TampError::Other("the material needs hollomon constants".into()))?;
        let m = h.exponent;
        let sigma0 = h.yield_stress.unwrap_or(0.0).powf(1.0 - m) * e.powf(m);
        let c = 2f64.powf(1.0 - m / 2.0)
            * 3f64.powf(1.0 - m)
            * std::f64::consts::PI
            * 1.43
            * (-0.97 * m).exp()
            * 2f64.powf(-m)
            * sigma0
            * r_eff.powf(1.0 - m / 2.0);
        let k = 4.0 / 3.0 * e / (2.0 * (1.0 - nu * nu)) * r_eff.sqrt();
        Ok(Storakers { c, k, m })
    }

    /// The permanent set after unloading from `delta_max`.
    fn residual(&self, delta_max: f64) -> f64 {
        let f_max = self.c * delta_max.powf(1.0 + self.m / 2.0);
        delta_max - (f_max / self.k).powf(2.0 / 3.0)
    }
}

/// The repulsive force on particle 0 along the line from particle 1.
fn normal_force(f: &Frame) -> Result<f64> {
    let n = (f.bodies[0].position - f.bodies[1].position).normalize();
    let force = f.bodies[0]
        .force
        .ok_or_else(|| TampError::Other(format!("step {} holds no forces", f.step)))?;
    Ok(force.dot(&n))
}

/// The frame at `step`, which the recording must hold.
fn at(rec: &Recording, step: u64) -> Result<&Frame> {
    rec.frames.iter().find(|f| f.step == step).ok_or_else(|| {
        TampError::Other(format!("storakers_unloading: step {step} was not recorded"))
    })
}

/// The largest divisor of `n` up to 1000: frames that far apart include step `n`.
fn sparse_every(n: u64) -> u64 {
    (1..=1000.min(n))
        .rev()
        .find(|k| n.is_multiple_of(*k))
        .unwrap_or(1)
}

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    let pair = Pair::of(&base)?;
    let law = Storakers::of(&base, pair.r_eff)?;
    let [v0, v1] = [0, 1].map(|k| base.particles[k].prescribed_velocity.unwrap_or([0.0; 3]));
    // The turns, from the kinematics of the driven pair.
    let turn = pair.step_at_overlap(MAX_OVERLAP).ceil() as u64;
    let predicted = law.residual(MAX_OVERLAP);
    let back =
        (pair.step_at_overlap(MAX_OVERLAP) - pair.step_at_overlap(0.5 * predicted)).round() as u64;
    let (second_turn, end) = (turn + back, turn + 2 * back + 3);
    let mut scene = base.clone();
    for (k, v) in [(0, v0), (1, v1)] {
        let reversed = v.map(|c| -c);
        scene.particles[k].prescribed_velocity_changes = vec![
            VelocityChangeSpec {
                time: turn as f64 * pair.dt,
                velocity: reversed,
            },
            VelocityChangeSpec {
                time: second_turn as f64 * pair.dt,
                velocity: v,
            },
        ];
    }
    let every = sparse_every(turn);
    // Every step from 1.5 times the predicted permanent set on the way back.
    let unload_from =
        turn + (pair.step_at_overlap(MAX_OVERLAP) - pair.step_at_overlap(1.5 * predicted)) as u64;
    let unloading = ctx.record(
        "unload",
        &with_steps(&scene, second_turn),
        RecordSpec::sparse_then_every_step(every, unload_from, true),
    )?;
    let reloading = ctx.record(
        "reload",
        &with_steps(&scene, end),
        RecordSpec::sparse_then_every_step(every, end - 10, true),
    )?;

    let delta_max = measure::overlap(at(&unloading, turn)?, 0, 1);
    // The first recorded step after the turn without a repulsive force, and the
    // overlap midway between it and the step before.
    let after_turn: Vec<&Frame> = unloading.frames.iter().filter(|f| f.step >= turn).collect();
    let mut residual = None;
    for w in after_turn.windows(2) {
        if normal_force(w[0])? > 0.0 && normal_force(w[1])? <= 0.0 {
            residual = Some(0.5 * (measure::overlap(w[0], 0, 1) + measure::overlap(w[1], 0, 1)));
            break;
        }
    }
    let residual = residual.ok_or_else(|| {
        TampError::Other(format!(
            "storakers_unloading: the force never vanished on unloading (up to step {second_turn})"
        ))
    })?;

    let reload_max = measure::overlap(at(&reloading, turn)?, 0, 1);
    let reload = Recording {
        dt: reloading.dt,
        frames: reloading
            .frames
            .iter()
            .filter(|f| f.step >= second_turn)
            .cloned()
            .collect(),
    };
    let reload_force = measure::first_crossing(
        &reload,
        |f| Ok(measure::overlap(f, 0, 1)),
        normal_force,
        reload_max,
        "the overlap on reloading",
    )?;
    let f_max = law.c * reload_max.powf(1.0 + law.m / 2.0);
    Ok(vec![
        Measured::new(
            "residual_overlap_after_unload",
            residual,
            law.residual(delta_max),
        ),
        Measured::new(
            "reload_force_error",
            (reload_force - f_max).abs() / f_max,
            0.0,
        ),
        Measured::new(
            "hertz_residual_overlap_after_unload",
            hertz_residual(ctx, &base, &pair, turn)?,
            0.0,
        ),
    ])
}

/// The same pair under Hertz's law, driven to δ_max and pulled apart to −δ_max/10: an
/// elastic contact keeps no permanent set, so its force vanishes where the overlap
/// does. The overlap midway between the last step with a repulsive force and the
/// first without.
fn hertz_residual(ctx: &CaseContext, base: &Scene, pair: &Pair, turn: u64) -> Result<f64> {
    let mut scene = base.clone();
    scene.contact.normal = NormalLaw::Hertz(Hertz {});
    let [v0, v1] = [0, 1].map(|k| base.particles[k].prescribed_velocity.unwrap_or([0.0; 3]));
    for (k, v) in [(0, v0), (1, v1)] {
        scene.particles[k].prescribed_velocity_changes = vec![VelocityChangeSpec {
            time: turn as f64 * pair.dt,
            velocity: v.map(|c| -c),
        }];
    }
    let at_max = pair.step_at_overlap(MAX_OVERLAP);
    let apart = turn + (at_max - pair.step_at_overlap(-0.1 * MAX_OVERLAP)).round() as u64;
    let from = turn + (at_max - pair.step_at_overlap(0.1 * MAX_OVERLAP)) as u64;
    let rec = ctx.record(
        "hertz_unload",
        &with_steps(&scene, apart),
        RecordSpec::sparse_then_every_step(sparse_every(turn), from, true),
    )?;
    let after_turn: Vec<&Frame> = rec.frames.iter().filter(|f| f.step >= turn).collect();
    for w in after_turn.windows(2) {
        if normal_force(w[0])? > 0.0 && normal_force(w[1])? <= 0.0 {
            return Ok(0.5 * (measure::overlap(w[0], 0, 1) + measure::overlap(w[1], 0, 1)));
        }
    }
    Err(TampError::Other(format!(
        "storakers_unloading: the Hertz force never vanished on unloading (up to step {apart})"
    )))
}
