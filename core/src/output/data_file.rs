//! The `read_data` file both peers read: LAMMPS's `atom_style sphere` layout, which
//! LIGGGHTS 3.8 shares. A header naming tamp's version, commit and the scene's hash,
//! the box, one atom per particle (scene id, type = material + 1, diameter, density,
//! position), then the velocities and spins. Every number is written in the shortest
//! form that reads back to the same double, so the peer starts from tamp's state
//! exactly.

use crate::decimal::g;
use crate::simulation::Simulation;
use std::fmt::Write as _;

/// The data file of `sim`'s particles. `peer` names the format in the header
/// ("LAMMPS", "LIGGGHTS"), `about` follows the scene hash there (empty or ": …"),
/// `bounds` is the box per axis and `atoms` the section's title line (`Atoms` or
/// `Atoms # sphere`).
pub fn particles_data(
    sim: &Simulation,
    peer: &str,
    sha: &str,
    about: &str,
    bounds: &[[f64; 2]; 3],
    atoms: &str,
) -> String {
    let p = &sim.state.particles;
    let mut data = format!(
        "{peer} data file exported by tamp {} ({}) from scene sha256 {sha}{about}\n\n{} atoms\n{} atom types\n\n",
        crate::VERSION,
        crate::GIT_COMMIT,
        p.len(),
        sim.model.materials.len()
    );
    for (axis, [lo, hi]) in ["x", "y", "z"].iter().zip(bounds) {
        let _ = writeln!(data, "{} {} {axis}lo {axis}hi", g(*lo), g(*hi));
    }
    let _ = write!(data, "\n{atoms}\n\n");
    for i in 0..p.len() {
        let x = p.position[i];
        let density = sim.model.materials[p.material[i]].particle_density();
        let _ = writeln!(
            data,
            "{} {} {} {} {} {} {}",
            p.id[i],
            p.material[i] + 1,
            g(2.0 * p.radius[i]),
            g(density),
            g(x.x),
            g(x.y),
            g(x.z)
        );
    }
    data.push_str("\nVelocities\n\n");
    for i in 0..p.len() {
        let (v, w) = (p.velocity[i], p.omega[i]);
        let _ = writeln!(
            data,
            "{} {} {} {} {} {} {}",
            p.id[i],
            g(v.x),
            g(v.y),
            g(v.z),
            g(w.x),
            g(w.y),
            g(w.z)
        );
    }
    data
}
