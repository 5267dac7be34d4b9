//! Cross-check against LIGGGHTS 3.8.0: two equal spheres meet obliquely, so the
//! `liggghts_history` tangential law (shear spring, Coulomb test on the total normal
//! force, tangential damping) and the spins take part. One run per (model, e, μ) that
//! LIGGGHTS was run with; the reference values are the final velocity and spin of the
//! first sphere, read from `reference_data/liggghts/liggghts_two_sphere_oblique/results.csv`
//! (written by `reference_data/liggghts/run_two_sphere_oblique.sh`). `model hooke` rows
//! run tamp's `linear` law with LIGGGHTS's k_n (`hooke_stiffness`). The case refuses to
//! compare when the scene and the recorded LIGGGHTS inputs disagree.

use super::liggghts_inputs::Mismatches;
use crate::contact::damping::liggghts::hooke_stiffness;
use crate::contact::damping::{Damping, LiggghtsRestitution};
use crate::contact::normal::{Hertz, Linear, NormalLaw};
use crate::error::{Result, TampError};
use crate::material::{Material, effective_mass, effective_modulus, effective_radius};
use crate::measure::region::ball_volume;
use crate::scene::{self, Scene};
use crate::verify::{CaseContext, Measured};
use serde::Deserialize;

/// One LIGGGHTS run, as `two_sphere_oblique_extract.py` writes it (`final_overlap` is
/// for people and is not read).
#[derive(Debug, Deserialize)]
struct Row {
    model: String,
    restitution_in: f64,
    friction: f64,
    time_step: f64,
    steps: u64,
    youngs_modulus: f64,
    poisson_ratio: f64,
    density: f64,
    radius: f64,
    normal_speed: f64,
    tangential_speed: f64,
    initial_gap: f64,
    characteristic_velocity: f64,
    vx: f64,
    vy: f64,
    omega_z: f64,
}

/// Differences between the scene and the inputs LIGGGHTS ran with.
fn mismatches(scene: &Scene, row: &Row) -> Mismatches {
    let mut out = Mismatches::default();
    out.check_material_and_step(
        scene,
        row.density,
        row.youngs_modulus,
        row.poisson_ratio,
        row.time_step,
    );
    out.check_history_runs(scene);
    if scene.particles.len() != 2 {
        out.0.push("particles: LIGGGHTS ran two spheres".into());
        return out;
    }
    let [a, b] = [&scene.particles[0], &scene.particles[1]];
    out.check("radius of particles[0]", a.radius, row.radius);
    out.check("radius of particles[1]", b.radius, row.radius);
    // LIGGGHTS puts the centres at ∓(R + gap/2) on x and the velocities at ±(v0, vt0, 0).
    let x = row.radius + 0.5 * row.initial_gap;
    let v = [0.5 * row.normal_speed, 0.5 * row.tangential_speed, 0.0];
    let (va, vb) = (
        a.velocity.unwrap_or([0.0; 3]),
        b.velocity.unwrap_or([0.0; 3]),
    );
    for (k, axis) in ["x", "y", "z"].iter().enumerate() {
        let x_k = if k == 0 { x } else { 0.0 };
        out.check(
            &format!("particles[0].position.{axis}"),
            a.position[k],
            -x_k,
        );
        out.check(&format!("particles[1].position.{axis}"), b.position[k], x_k);
        out.check(&format!("particles[0].velocity.{axis}"), va[k], v[k]);
        out.check(&format!("particles[1].velocity.{axis}"), vb[k], -v[k]);
    }
    out
}

/// The scene of one LIGGGHTS row: its restitution, friction and normal model.
fn scene_of(base: &Scene, row: &Row) -> Result<Scene> {
    let mut s = base.clone();
    s.contact.damping = Some(Damping::LiggghtsRestitution(LiggghtsRestitution {
        restitution: row.restitution_in,
    }));
    if let Some(t) = s.contact.tangential.as_mut() {
        t.friction = row.friction;
    }
    s.contact.normal = match row.model.as_str() {
        "hertz" => NormalLaw::Hertz(Hertz {}),
        "hooke" => {
            // model hooke: k_n from the materials and characteristicVelocity.
            let steel = Material {
                name: "LIGGGHTS type 1".into(),
                density: Some(row.density),
                rigid: false,
                youngs_modulus: Some(row.youngs_modulus),
                poisson_ratio: Some(row.poisson_ratio),
                hollomon: None,
            };
            let mass = row.density * ball_volume(row.radius);
            NormalLaw::Linear(Linear {
                stiffness: hooke_stiffness(
                    effective_mass(mass, mass),
                    effective_radius(row.radius, row.radius),
                    effective_modulus(&steel, &steel).expect("both elastic constants are given"),
                    row.characteristic_velocity,
                ),
            })
        }
        other => {
            return Err(TampError::Other(format!(
                "LIGGGHTS model '{other}' has no tamp counterpart in this case"
            )));
        }
    };
    Ok(s)
}

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    let mut out = Vec::new();
    for row in ctx.liggghts_results::<Row>()? {
        let tag = format!("{}_e{}_mu{}", row.model, row.restitution_in, row.friction);
        mismatches(&base, &row).refuse_any(&tag)?;
        let mut sim = scene::build(&scene_of(&base, &row)?)?.sim;
        for _ in 0..row.steps {
            sim.step()?;
        }
        let p = &sim.state.particles;
        out.push(Measured::new(&format!("{tag}_vx"), p.velocity[0].x, row.vx));
        out.push(Measured::new(&format!("{tag}_vy"), p.velocity[0].y, row.vy));
        out.push(Measured::new(
            &format!("{tag}_omega_z"),
            p.omega[0].z,
            row.omega_z,
        ));
    }
    Ok(out)
}
