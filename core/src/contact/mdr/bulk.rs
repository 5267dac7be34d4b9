//! The mean surface displacement that drives MDR's bulk response (Part II).
//!
//! Once a particle's free surface fraction ψ falls below ψ_b, each step's overlap
//! increment of a side splits: the particle's mean surface displacement increment
//!   dδ̄ = Σ_sides (A_c,side / A_con) dδ_side
//! goes to the bulk part δ_B (a uniform compression of the particle, force
//! κ A_con δ_B A_c / V_geo), and the rest, at most what brings the MDR part to δ, to
//! the MDR part. dδ̄ is summed over all of the particle's contacts before the forces,
//! from each side's overlap now against its overlap at the last step.

use super::contact::MdrContact;
use super::flat::Flat;
use super::particle::MdrParticles;

/// Add a pair contact's share to dδ̄ of its two particles; `sides` are the particle
/// indices of side 0 and side 1, `delta` the pair overlap now.
pub fn add_pair(c: &MdrContact, delta: f64, sides: [usize; 2], particles: &mut MdrParticles) {
    let flat = Flat {
        max_overlap: c.max_overlap.max(delta),
        plastic: [c.sides[0].plastic_overlap, c.sides[1].plastic_overlap],
    };
    let [i0, i1] = sides;
    let now = flat.displacement_sides(delta, particles.radius[i0], particles.radius[i1]);
    for (s, &i) in sides.iter().enumerate() {
        let a_con = particles.contact_area[i];
        if a_con != 0.0 {
            let increment = now[s] - c.sides[s].overlap;
            particles.mean_displacement_increment[i] += c.sides[s].area / a_con * increment;
        }
    }
}

/// Add a wall contact's share to dδ̄ of particle `i`, at overlap `delta` now.
pub fn add_wall(c: &MdrContact, delta: f64, i: usize, particles: &mut MdrParticles) {
    let a_con = particles.contact_area[i];
    if a_con != 0.0 {
        let increment = delta - c.sides[0].overlap;
        particles.mean_displacement_increment[i] += 1.0 * c.sides[0].area / a_con * increment;
    }
}
