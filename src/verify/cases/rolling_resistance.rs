//! Rolling resistance (`contact.rolling`, LAMMPS's `rolling sds`): solid spheres roll
//! on a plane under gravity while the tangential spring sticks. On the slider the
//! resistance is F_r = μ_r F_n against the roll, with the torque R* n × F_r (R* = R on
//! a plane), and F_n = m g at rest on the floor. With rolling without slip (v = ωR),
//!   m a = F_t,   I a/R = −R F_t − R μ_r m g   ⇒   a = −μ_r g/(1 + I/(mR²)) = −(5/7) μ_r g,
//! whatever the speed (a sphere of I = 2/5 m R²). The deceleration is the least-squares
//! slope of v_x over the middle of each roll, [0.2, 0.8] of the stopping time v₀/a,
//! where the spring is on the slider (it gets there in μ_r m g/(k_r v₀), under 2 % of
//! that time here). The rolling constraint v_x = ω_y R over the same window checks that
//! the friction sticks; with LAMMPS's lever arms (R at a wall) it holds to the
//! tangential spring's small oscillation.
//!
//! Two more spheres roll head-on into each other: their contact points meet with no
//! relative sliding, and only the pair's rolling resistance acts there (the relative
//! spin 2ω about the contact's tangent). Its kinetic energy from the last frame before
//! the spheres touch to the first after they part is bounded by 0 and the energy it
//! came in with; the value carries the pair's rolling torques into the agreement with
//! LAMMPS.

use crate::contact::rolling::RollingLaw;
use crate::error::{Result, TampError};
use crate::verify::recording::{Frame, RecordSpec};
use crate::verify::{CaseContext, Measured, measure};

/// Frames every this many steps.
const EVERY: u64 = 10;
/// The part of a roll's stopping time over which the deceleration is fitted.
const WINDOW: (f64, f64) = (0.2, 0.8);

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let s = ctx.scene()?;
    let Some(RollingLaw::Sds(law)) = s.contact.rolling else {
        return Err(TampError::Other(
            "the scene must name a rolling law (sds)".into(),
        ));
    };
    let g = s
        .gravity
        .map(|g| g[2].abs())
        .ok_or_else(|| TampError::Other("the scene must have gravity along z".into()))?;
    let density = s.materials[0]
        .density
        .ok_or_else(|| TampError::Other("the spheres' material must give its density".into()))?;
    if s.particles.len() != 4 {
        return Err(TampError::Other(
            "the scene must place four spheres: two rolling alone, two rolling into each other"
                .into(),
        ));
    }
    let deceleration = 5.0 / 7.0 * law.friction * g;
    let rec = ctx.record("rolling", &s, RecordSpec::every(EVERY, false))?;
    let mut out = Vec::new();
    for (i, label) in [(0, "fast"), (1, "slow")] {
        let v0 = rec.frames[0].bodies[i].velocity.x;
        let stop = v0 / deceleration;
        // Time as step · Δt, the same on every engine (an engine's own clock may have
        // summed its steps).
        let time = |f: &Frame| f.step as f64 * rec.dt;
        let window: Vec<&Frame> = rec
            .frames
            .iter()
            .filter(|f| time(f) >= WINDOW.0 * stop && time(f) <= WINDOW.1 * stop)
            .collect();
        if window.len() < 100 {
            return Err(TampError::Other(format!(
                "sphere {}: the run holds {} frames of its roll's window [{}, {}] s; it must run to {} s",
                i + 1,
                window.len(),
                WINDOW.0 * stop,
                WINDOW.1 * stop,
                WINDOW.1 * stop
            )));
        }
        let (t, v): (Vec<f64>, Vec<f64>) = window
            .iter()
            .map(|f| (time(f), f.bodies[i].velocity.x))
            .unzip();
        out.push(Measured::new(
            &format!("deceleration_{label}"),
            -slope(&t, &v),
            deceleration,
        ));
        let (rolled, spun) = window.iter().fold((0.0, 0.0), |(x, w), f| {
            let b = &f.bodies[i];
            (x + b.velocity.x, w + b.omega.y * b.radius)
        });
        out.push(Measured::new(
            &format!("rolling_without_slip_{label}"),
            rolled / spun,
            1.0,
        ));
    }
    let gap = |f: &Frame| -measure::overlap(f, 2, 3);
    let pair = |f: &Frame| Frame {
        bodies: f.bodies[2..4].to_vec(),
        ..f.clone()
    };
    let before = rec.frames.iter().take_while(|f| gap(f) > 0.0).last();
    let touched = rec.frames.iter().position(|f| gap(f) <= 0.0);
    let after = touched.and_then(|k| rec.frames[k..].iter().find(|f| gap(f) > 0.0));
    let (Some(before), Some(after)) = (before, after) else {
        return Err(TampError::Other(
            "spheres 3 and 4 must meet and part within the run".into(),
        ));
    };
    let came_in = measure::kinetic_energy(&pair(before), density);
    out.push(Measured::between(
        "pair_collision_energy_ratio",
        measure::kinetic_energy(&pair(after), density) / came_in,
        0.0,
        1.0,
    ));
    Ok(out)
}

/// The least-squares slope of y over x.
fn slope(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len() as f64;
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let (sxy, sxx) = x.iter().zip(y).fold((0.0, 0.0), |(sxy, sxx), (a, b)| {
        (sxy + (a - mx) * (b - my), sxx + (a - mx) * (a - mx))
    });
    sxy / sxx
}
