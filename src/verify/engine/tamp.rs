//! The tamp engine: the scene built and stepped in-process, its frames kept in memory.
//! The run is `tamp run`'s (the same build, step count and end-of-run energy check)
//! without its files, and the frames hold the simulation's own clock, so a case
//! measures here exactly what it would from the simulation itself.

use crate::error::Result;
use crate::scene::{self, Scene};
use crate::simulation::Simulation;
use crate::verify::recording::{Body, Frame, RecordSpec, Recording, WallState};

/// Run `scene` to its end, recording the frames `spec` asks for.
pub fn record(scene: &Scene, spec: RecordSpec) -> Result<Recording> {
    let built = scene::build(scene)?;
    let mut sim = built.sim;
    let mut frames = vec![frame(&sim, spec)];
    while sim.state().step < built.steps {
        sim.step()?;
        if spec.records(sim.state().step, built.steps) {
            frames.push(frame(&sim, spec));
        }
    }
    sim.check_energy_at_end()?;
    Ok(Recording {
        dt: sim.dt(),
        frames,
    })
}

/// The particles now, in id order, and the walls when `spec` asks for them.
fn frame(sim: &Simulation, spec: RecordSpec) -> Frame {
    let forces = spec.forces;
    let p = &sim.state().particles;
    let mut order: Vec<usize> = (0..p.len()).collect();
    order.sort_by_key(|&i| p.id[i]);
    Frame {
        step: sim.state().step,
        time: sim.state().time,
        bodies: order
            .into_iter()
            .map(|i| Body {
                radius: p.radius[i],
                position: p.position[i],
                velocity: p.velocity[i],
                omega: p.omega[i],
                force: forces.then(|| p.force[i]),
            })
            .collect(),
        walls: match spec.walls {
            true => (sim.state().walls.iter().zip(&sim.state().wall_force))
                .map(|(pose, force)| WallState {
                    displacement: pose.displacement,
                    force: *force,
                })
                .collect(),
            false => Vec::new(),
        },
    }
}
