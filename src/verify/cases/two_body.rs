//! The inputs of a two-sphere case as its references need them: the effective mass,
//! radius and modulus of particles 0 and 1, their gap and normal approach speed, taken
//! from the scene as tamp builds it (materials mixed once, masses from densities),
//! before any step. The references never read what an engine recorded.
//!
//! Also the length of the run a case hands an engine, from the same inputs: a
//! collision needs the gap closed at the approach speed and then the contact, whose
//! duration scales as Hertz's (Johnson 1985 §11.4),
//!   T_H = 3.2145 (m*/k̃)^{2/5} v^{−1/5},  k̃ = 4/3 E* √R*;
//! a displacement-driven compression to the overlap h reaches it at step (h + gap)/(v Δt).

use crate::accuracy::damped_hertz::{Dashpot, Unit, critical_fraction_c};
use crate::collision::Collision;
use crate::contact::damping::liggghts::LiggghtsModel;
use crate::contact::damping::{Damping, LiggghtsRestitution};
use crate::error::{Result, TampError};
use crate::material::{effective_mass, effective_radius};
use crate::scene::contact::DampingSpec;
use crate::scene::schema::RunSpec;
use crate::scene::{self, Scene};
use crate::verify::recording::RecordSpec;
use crate::verify::{CaseContext, Measured, measure};

/// Particles 0 and 1 of a scene, at t = 0.
#[derive(Clone, Copy, Debug)]
pub struct Pair {
    /// m* = m₀m₁/(m₀ + m₁), kg.
    pub m_eff: f64,
    /// R* = R₀R₁/(R₀ + R₁), m.
    pub r_eff: f64,
    /// E* of the pair's materials, Pa, when the law needs one.
    pub e_eff: Option<f64>,
    /// −(v₀ − v₁)·n, n from particle 1 to 0: the speed at which they close, m/s.
    pub approach: f64,
    /// |x₀ − x₁| − R₀ − R₁, m: negative when they overlap at t = 0.
    pub gap: f64,
    /// The scene's time step, s.
    pub dt: f64,
}

impl Pair {
    /// The pair of `scene`, which must have at least two particles.
    pub fn of(scene: &Scene) -> Result<Pair> {
        let sim = scene::build(scene)?.sim;
        let p = &sim.state().particles;
        if p.len() < 2 {
            return Err(TampError::Other(
                "a two-body case needs two particles".into(),
            ));
        }
        Ok(Pair {
            m_eff: effective_mass(p.mass[0], p.mass[1]),
            r_eff: effective_radius(p.radius[0], p.radius[1]),
            e_eff: sim
                .model()
                .pair_table
                .get(p.material[0], p.material[1])
                .effective_modulus,
            approach: -(p.velocity[0] - p.velocity[1])
                .dot(&(p.position[0] - p.position[1]).normalize()),
            gap: (p.position[0] - p.position[1]).norm() - p.radius[0] - p.radius[1],
            dt: sim.dt(),
        })
    }

    /// E*, or an error when the scene's materials give none.
    pub fn effective_modulus(&self) -> Result<f64> {
        self.e_eff.ok_or_else(|| {
            TampError::Other(
                "the pair's materials give no E* (youngs_modulus, poisson_ratio)".into(),
            )
        })
    }

    /// δ_s = (m* v²/K)^{2/5}, K = 4/3 E* √R*: the overlap unit of the dimensionless Hertz
    /// impact (`accuracy::damped_hertz`) at the approach speed, m.
    pub fn hertz_overlap_scale(&self) -> Result<f64> {
        let k = 4.0 / 3.0 * self.effective_modulus()? * self.r_eff.sqrt();
        let v = self.approach;
        Ok((self.m_eff * v * v / k).powf(0.4))
    }

    /// Steps that close the gap and then last `contacts` Hertz contact durations at the
    /// approach speed: a run through one collision of any law whose contact lasts a
    /// few times Hertz's at most (the measurement says so when it did not end).
    pub fn steps_through_collision(&self, contacts: f64) -> Result<u64> {
        let k = 4.0 / 3.0 * self.effective_modulus()? * self.r_eff.sqrt();
        let hertz = 3.2145 * (self.m_eff / k).powf(0.4) * self.approach.powf(-0.2);
        Ok(((self.gap.max(0.0) / self.approach + contacts * hertz) / self.dt).ceil() as u64)
    }

    /// The step at which the pair, closing at its prescribed approach speed, reaches
    /// the overlap `h`.
    pub fn step_at_overlap(&self, h: f64) -> f64 {
        (h + self.gap) / (self.approach * self.dt)
    }
}

/// `scene` run for `steps` steps.
pub fn with_steps(scene: &Scene, steps: u64) -> Scene {
    Scene {
        run: RunSpec {
            steps: Some(steps),
            ..RunSpec::default()
        },
        ..scene.clone()
    }
}

/// A displacement-driven compression of particles 0 and 1 of `scene` past the overlap
/// `h` it is expected to cross a value at: the run ends 2 % past the step of `h`, and is
/// recorded every `every` steps with forces, and at every step from 2 % before it,
/// where the crossing is found between consecutive steps.
pub fn compression_past(scene: &Scene, h: f64, every: u64) -> Result<(Scene, RecordSpec)> {
    let k = Pair::of(scene)?.step_at_overlap(h);
    let spec = RecordSpec::sparse_then_every_step(every, (0.98 * k).floor() as u64, true);
    Ok((with_steps(scene, (1.02 * k).ceil() as u64), spec))
}

/// A measured collision against its references, as the quantities `restitution`,
/// `contact_duration` and `max_overlap`, each name followed by `suffix`.
pub fn collision_quantities(
    suffix: &str,
    c: &Collision,
    restitution: f64,
    duration: f64,
    max_overlap: f64,
) -> [Measured; 3] {
    [
        Measured::new(&format!("restitution{suffix}"), c.restitution, restitution),
        Measured::new(&format!("contact_duration{suffix}"), c.duration, duration),
        Measured::new(&format!("max_overlap{suffix}"), c.max_overlap, max_overlap),
    ]
}

/// The case file's `parameters` of a case that runs one collision per restitution e of
/// LIGGGHTS's damping relation (`liggghts_restitution`).
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct Restitutions {
    restitutions: Vec<f64>,
}

/// `base` once per restitution e of the case file's `parameters`, each with LIGGGHTS's
/// restitution damping at that e.
pub fn each_restitution(ctx: &CaseContext, base: &Scene) -> Result<Vec<(f64, Scene)>> {
    Ok(ctx
        .parameters::<Restitutions>()?
        .restitutions
        .into_iter()
        .map(|e| {
            let mut s = base.clone();
            // The scene's clamp (`contact.damping.limit`) stays as the base scene has it.
            s.contact.damping = Some(DampingSpec {
                kind: Damping::LiggghtsRestitution(LiggghtsRestitution { restitution: e }),
                limit: base.contact.damping.is_some_and(|d| d.limit),
            });
            (e, s)
        })
        .collect())
}

/// One head-on Hertz collision per restitution e of the case file (`each_restitution`),
/// run on the case's engine and measured from its recording, beside the reference
/// `unit` gives for LIGGGHTS's ξ of that e (`accuracy::damped_hertz`), scaled to the
/// pair: restitution, contact duration and largest overlap.
pub struct HertzImpact {
    pub e: f64,
    pub measured: Collision,
    pub restitution: f64,
    pub duration: f64,
    pub max_overlap: f64,
}

/// `HertzImpact` for each restitution of the case file, the run labelled
/// `collision_e<e>`; the scene must use the Hertz law.
pub fn each_hertz_impact(
    ctx: &CaseContext,
    base: &Scene,
    unit: fn(Dashpot, f64) -> Option<Unit>,
) -> Result<Vec<HertzImpact>> {
    if !matches!(
        base.contact.normal,
        crate::contact::normal::NormalLaw::Hertz(_)
    ) {
        return Err(TampError::Other("the scene must use hertz".into()));
    }
    let mut out = Vec::new();
    for (e, s) in each_restitution(ctx, base)? {
        let pair = Pair::of(&s)?;
        let (v, delta_s) = (pair.approach, pair.hertz_overlap_scale()?);
        let xi = LiggghtsModel::Hertz.critical_fraction(e);
        let reference =
            unit(Dashpot::CriticalFraction, critical_fraction_c(xi)).ok_or_else(|| {
                TampError::Other(format!("e = {e}: the reference impact does not end"))
            })?;
        let rec = ctx.record(&format!("collision_e{e}"), &s, RecordSpec::EVERY_STEP)?;
        out.push(HertzImpact {
            e,
            measured: measure::two_body(&rec, 0, 1)?,
            restitution: reference.restitution,
            duration: reference.duration * delta_s / v,
            max_overlap: reference.max_overlap * delta_s,
        });
    }
    Ok(out)
}
