//! Load, unload and reload one Storåkers contact (Rojek 2016 eqs 16, 19–20): two
//! NiAl spheres driven together to δ_max, pulled back until the force vanishes, and
//! pushed back to δ_max. The elastic branch of eq 19–20 integrates to the Hertz
//! curve through the turning point, so the permanent set is
//!   δ_res = δ_max − (F_max/K)^{2/3},  F_max = C δ_max^{1+m/2},  K = 4/3 E* √R*
//! with C from eq 16 (written out here independently of `crate::contact`), and
//! reloading must meet F_max again at δ_max (Rojek §3.3).

use crate::error::{Result, TampError};
use crate::particles::Vec3;
use crate::scene;
use crate::simulation::Simulation;
use crate::verify::{CaseContext, Measured};

/// Beyond the Hertz crossover (1.6e-7 m for m = 0.2), so that δ_res > 0.
const MAX_OVERLAP: f64 = 3e-7;

fn drive(sim: &mut Simulation, speed: f64) {
    for (i, sign) in [(0, 1.0), (1, -1.0)] {
        let v = Vec3::new(sign * speed, 0.0, 0.0);
        sim.state.particles.prescribe(i, v);
    }
}

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let scene = ctx.scene()?;
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
    let r_eff = 0.5 * scene.particles[0].radius;
    let speed = scene.particles[0]
        .prescribed_velocity
        .map_or(0.0, |v| v[0].abs());
    let mut sim = scene::build(&scene)?.sim;
    let limit = 10_000_000;
    let fail = |what: &str| TampError::Other(format!("storakers_unloading: {what}"));

    let mut steps = 0;
    while sim.overlap(0, 1) < MAX_OVERLAP {
        sim.step()?;
        steps += 1;
        if steps > limit {
            return Err(fail("never reached the turning point"));
        }
    }
    let delta_max = sim.overlap(0, 1);

    drive(&mut sim, -speed);
    let mut last_loaded = delta_max;
    loop {
        sim.step()?;
        let overlap = sim.overlap(0, 1);
        if sim.state.particles.force[0].norm() == 0.0 {
            break;
        }
        last_loaded = overlap;
        steps += 1;
        if steps > 2 * limit {
            return Err(fail("the force never vanished on unloading"));
        }
    }
    let residual = 0.5 * (last_loaded + sim.overlap(0, 1));

    drive(&mut sim, speed);
    let mut prev = (sim.overlap(0, 1), sim.state.particles.force[0].norm());
    let reload_force = loop {
        sim.step()?;
        let now = (sim.overlap(0, 1), sim.state.particles.force[0].norm());
        if now.0 >= delta_max {
            let w = (delta_max - prev.0) / (now.0 - prev.0);
            break prev.1 + w * (now.1 - prev.1);
        }
        prev = now;
        steps += 1;
        if steps > 3 * limit {
            return Err(fail("reloading never reached the turning point"));
        }
    };

    let c = 2f64.powf(1.0 - m / 2.0)
        * 3f64.powf(1.0 - m)
        * std::f64::consts::PI
        * 1.43
        * (-0.97 * m).exp()
        * 2f64.powf(-m)
        * sigma0
        * r_eff.powf(1.0 - m / 2.0);
    let f_max = c * delta_max.powf(1.0 + m / 2.0);
    let k = 4.0 / 3.0 * e / (2.0 * (1.0 - nu * nu)) * r_eff.sqrt();
    let residual_exact = delta_max - (f_max / k).powf(2.0 / 3.0);
    Ok(vec![
        Measured::new("residual_overlap_after_unload", residual, residual_exact),
        Measured::new(
            "reload_force_error",
            (reload_force - f_max).abs() / f_max,
            0.0,
        ),
    ])
}
