//! The step that delivers a requested accuracy: Δt = (Δt/t_c)_a · min t_c, with
//! (Δt/t_c)_a from the law's error model (`model`) and t_c the time scale of the
//! closed form (`impact`: the contact duration, for Walton–Braun the stiffer branch's
//! π√(m*/k₂)) of the shortest impact the scene can have at its characteristic
//! velocity: each body against an identical one (m* = m/2, R* = R/2; the shortest
//! of its pairs, since t_c grows with m*) and against each wall (m* = m, R* = R),
//! bodies still to be poured at their smallest radius.
//! The step never exceeds the default α = 0.2 times the critical step (Rojek eq 26):
//! at a loose accuracy, stability and not accuracy sets it.

use super::calibration::{
    DAMPED_RESTITUTION_MIN, STORAKERS_SPEED_RATIO_MAX, THORNTON_SPEED_RATIO_MAX,
    WALTON_BRAUN_RATIO_MAX, hertz_damped_xi_max,
};
use super::impact::{closed_form, hertz_dashpot_fraction};
use super::model::{ErrorModel, for_law};
use crate::contact::normal::thornton::yield_velocity;
use crate::contact::normal::{NormalLaw, Storakers, WaltonBraun};
use crate::material::PairProperties;
use crate::simulation::Simulation;

/// The accuracy of a scene that states no time step.
pub const DEFAULT_ACCURACY: f64 = 1e-3;

/// The safety factor the step never exceeds (the default `time_step.alpha`).
pub const STABILITY_ALPHA: f64 = crate::timestep::DEFAULT_ALPHA;

/// Wall time of one particle-step of a small collision scene on the machine that
/// measured it (docs/accuracy-cost.md: "Cost of a step"), s: the prediction of a
/// run's wall time is steps × particles × this.
pub const COST_PER_PARTICLE_STEP: f64 = 7.2e-8;

/// What the accuracy setting chose.
#[derive(Clone, Copy, Debug)]
pub struct Choice {
    /// The time step Δt chosen, s.
    pub dt: f64,
    /// The shortest closed-form contact duration, s.
    pub contact_duration: f64,
    /// The shortest time scale of the error model (`Impact::time_scale`), s.
    pub time_scale: f64,
    /// The error model of the scene's law.
    pub model: &'static ErrorModel,
    /// True when α = 0.2 times the critical step is smaller than the accuracy's step.
    pub stability_bound: bool,
}

impl Choice {
    /// Steps in the shortest closed-form contact, t_c / Δt.
    pub fn steps_per_contact(&self) -> f64 {
        self.contact_duration / self.dt
    }
}

/// The step for `accuracy` at impact speed `speed`; `critical` is the critical step
/// estimate (Rojek eq 28) at that speed. Err: why no step can be chosen.
pub fn choose(
    sim: &Simulation,
    accuracy: f64,
    speed: f64,
    critical: Option<f64>,
) -> Result<Choice, String> {
    let law = &sim.model.law;
    if let NormalLaw::Storakers(Storakers {
        min_with_hertz: false,
    }) = law.normal
    {
        return Err(
            "the storakers law without min_with_hertz has no error model: its impacts have closed forms, but below the speed at which the loading meets Hertz's curve its Hertz unloading returns more work than the loading took (the rebound exceeds the approach, up to sqrt(2 + m/2) times), and pressed contacts gain energy at any step (docs/accuracy-cost.md); set contact.normal.min_with_hertz, or give time_step.alpha or time_step.fixed".into(),
        );
    }
    let model = for_law(law).ok_or_else(|| {
        format!(
            "the contact law ({}{}{}{}) has no error model: only linear (undamped, or with constant or critical_fraction damping), hertz (undamped, or with critical_fraction, liggghts_restitution, tsuji or constant damping), kuwabara_kono, walton_braun, thornton (unloading thornton_1997) and storakers with min_with_hertz, without cohesion and without contact.damping.limit, are calibrated (docs/accuracy-cost.md); give time_step.alpha or time_step.fixed",
            law.normal.name(),
            law.damping.map_or(String::new(), |d| format!(" + {} damping", d.name())),
            if law.no_pull { " limited to no pull" } else { "" },
            law.cohesion.map_or("", |_| " + cohesion"),
        )
    })?;
    if law.normal.stiffness_depends_on_speed() && (speed.is_nan() || speed <= 0.0) {
        return Err(format!(
            "the {} law's contact duration depends on the impact speed, and nothing in the scene moves: give time_step.characteristic_velocity",
            law.normal.name()
        ));
    }
    if let NormalLaw::WaltonBraun(WaltonBraun {
        loading_stiffness: k1,
        unloading_stiffness: k2,
    }) = law.normal
        && k2 > WALTON_BRAUN_RATIO_MAX * k1
    {
        return Err(format!(
            "the walton_braun unloading_stiffness is {:.3} times the loading_stiffness, above {WALTON_BRAUN_RATIO_MAX}, the largest ratio the error model is calibrated for (docs/accuracy-cost.md); give time_step.alpha or time_step.fixed",
            k2 / k1
        ));
    }
    let p = &sim.state.particles;
    let mut bodies: Vec<(f64, f64, usize)> = Vec::new();
    for i in 0..p.len() {
        let b = (p.mass[i], p.radius[i], p.material[i]);
        if !bodies.contains(&b) {
            bodies.push(b);
        }
    }
    for s in sim.pouring_sources() {
        let r = s.radius.min_radius();
        let m = sim.model.materials[s.material].particle_density() * 4.0 / 3.0
            * std::f64::consts::PI
            * r.powi(3);
        bodies.push((m, r, s.material));
    }
    if model.law == "hertz_damped"
        && let Some(xi) = hertz_dashpot_fraction(law)
        && xi > hertz_damped_xi_max()
    {
        return Err(format!(
            "the damping is xi = {xi:.4} of critical beside hertz, above {:.4}, the strongest damping the error model is calibrated for (LIGGGHTS's xi for e = {DAMPED_RESTITUTION_MIN}; docs/accuracy-cost.md); give time_step.alpha or time_step.fixed",
            hertz_damped_xi_max()
        ));
    }
    let duration = |m: f64, r: f64, pair: &PairProperties| {
        closed_form(law, m, r, pair, speed).map(|i| {
            if let NormalLaw::Thornton(t) = law.normal {
                let c = t.at(r, pair);
                let ratio = speed / yield_velocity(c.yield_pressure, c.effective_modulus, r, m);
                if ratio > THORNTON_SPEED_RATIO_MAX {
                    return Err(format!(
                        "the thornton impact of a body of radius {r:e} m at {speed:e} m/s is {ratio:.1} times its yield velocity, above {THORNTON_SPEED_RATIO_MAX}, the fastest the error model is calibrated for (docs/accuracy-cost.md); give time_step.alpha or time_step.fixed"
                    ));
                }
            }
            if let NormalLaw::Storakers(s) = law.normal {
                let v_star = s.at(r, pair).hertz_crossing_speed(m).unwrap_or(f64::NAN);
                // Written so that a NaN v* (no crossing) is refused too.
                let calibrated = speed <= STORAKERS_SPEED_RATIO_MAX * v_star;
                if !calibrated {
                    return Err(format!(
                        "the storakers impact of a body of radius {r:e} m at {speed:e} m/s is {:.1} times the speed at which its loading leaves Hertz's curve, above {STORAKERS_SPEED_RATIO_MAX}, the fastest the error model is calibrated for (docs/accuracy-cost.md); give time_step.alpha or time_step.fixed",
                        speed / v_star
                    ));
                }
            }
            let damped = matches!(
                model.law,
                "linear_damped" | "hertz_constant_damped" | "kuwabara_kono"
            );
            if damped && i.restitution < DAMPED_RESTITUTION_MIN {
                Err(format!(
                    "the damping gives a restitution of {:.3} to a body of radius {r:e} m at {speed:e} m/s, below {DAMPED_RESTITUTION_MIN}, the strongest damping the error model is calibrated for (docs/accuracy-cost.md); give time_step.alpha or time_step.fixed",
                    i.restitution
                ))
            } else {
                Ok((i.time_scale, i.duration))
            }
        })
    };
    // A lone particle meets only walls.
    let pairs = p.len() + sim.state.still_to_pour() > 1;
    let (mut shortest, mut shortest_contact) = (f64::INFINITY, f64::INFINITY);
    for &(m, r, material) in &bodies {
        let mut candidates = Vec::new();
        if pairs {
            candidates.push(duration(
                0.5 * m,
                0.5 * r,
                sim.model.pair_table.get(material, material),
            ));
        }
        for w in &sim.model.walls {
            candidates.push(duration(
                m,
                r,
                sim.model.pair_table.get(material, w.material),
            ));
        }
        for t in candidates {
            match t.transpose()? {
                Some((t, c)) if t > 0.0 && t.is_finite() => {
                    shortest = shortest.min(t);
                    shortest_contact = shortest_contact.min(c);
                }
                _ if matches!(model.law, "hertz_constant_damped" | "kuwabara_kono") => {
                    return Err(format!(
                        "the damping keeps a body of radius {r:e} m at {speed:e} m/s from rebounding (overdamped: below a restitution of {DAMPED_RESTITUTION_MIN}, the strongest damping the error model is calibrated for; docs/accuracy-cost.md); give time_step.alpha or time_step.fixed"
                    ));
                }
                _ => {
                    return Err(format!(
                        "the {} law gives no finite contact duration for a body of radius {r:e} m and mass {m:e} kg at {speed:e} m/s: check the materials' youngs_modulus, poisson_ratio and density",
                        law.normal.name()
                    ));
                }
            }
        }
    }
    if !shortest.is_finite() {
        return Err("the scene has no particle to size the step for".into());
    }
    let by_accuracy = model.step_ratio(accuracy) * shortest;
    let by_stability = critical.map_or(f64::INFINITY, |c| STABILITY_ALPHA * c);
    Ok(Choice {
        dt: by_accuracy.min(by_stability),
        contact_duration: shortest_contact,
        time_scale: shortest,
        model,
        stability_bound: by_stability < by_accuracy,
    })
}
