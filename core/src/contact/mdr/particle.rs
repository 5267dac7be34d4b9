//! The state MDR keeps per particle (LAMMPS's `fix GRANULAR/MDR` arrays), and its
//! update at the start of every step, before the forces.
//!
//! The force pass sums over each particle's contact sides: the cap volumes V_caps,
//! the contact areas A_con, the area change Σ (A_c − 2πR(δ_max + δ_B)), the mean
//! strain ε̄ = Σ f·b/(3κV_elas), and the numerator and denominator of the radius
//! increment. At the start of the next step:
//!   V_geo = min(4/3 πR³ − V_caps, V₀),  V_elas = V₀(1 + ε̄),
//!   A_tot = 4πR² + Σ(A_c − 2πR(δ_max + δ_B)),  ψ = (A_tot − A_con)/A_tot,
//! and while ψ > ψ_b the apparent radius grows: the increment
//!   dR = max(w N/(D − 4πR²), 0),  w = 1/(1 + e^{−75(ψ − 0.2)}) (0 for ψ ≤ 0.1),
//! is smoothed over ten steps (dR̄ += (dR − dR̄)/10) and R += dR̄ while R + dR < 1.5 R₀.
//! N sums, over plastic sides on their loading branch, the volume the flat displaces
//! beyond the elastic strain; D the area over which it spreads (Part I's volume
//! conservation of the plastic flow).

use crate::particles::Vec3;
use std::f64::consts::PI;

/// The radius grows while below this multiple of the initial radius.
const RADIUS_LIMIT: f64 = 1.5;
/// Steps over which the radius increment is smoothed.
const WINDOW: f64 = 10.0;

/// MDR's per-particle arrays, indexed like the particles.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct MdrParticles {
    /// Apparent radius R, m.
    pub radius: Vec<f64>,
    /// Initial radius R₀, m.
    pub initial_radius: Vec<f64>,
    /// Geometric volume V_geo, m³.
    pub geometric_volume: Vec<f64>,
    /// Volume from the mean elastic strain V_elas, m³.
    pub elastic_volume: Vec<f64>,
    /// Σ of the sides' cap volumes, m³ (summed by the force pass).
    pub cap_volume: Vec<f64>,
    /// Mean strain ε̄ (summed by the force pass).
    pub mean_strain: Vec<f64>,
    /// Numerator of the radius increment, m³ (summed by the force pass).
    pub radius_numerator: Vec<f64>,
    /// Denominator of the radius increment, m² (summed by the force pass).
    pub radius_denominator: Vec<f64>,
    /// Contact area A_con of the last step, m².
    pub contact_area: Vec<f64>,
    /// Contact area being summed by this step's force pass, m².
    pub contact_area_next: Vec<f64>,
    /// Total area A_tot, m².
    pub total_area: Vec<f64>,
    /// Σ(A_c − 2πR(δ_max + δ_B)) (summed by the force pass), m².
    pub area_change_sum: Vec<f64>,
    /// This step's mean surface displacement increment, m.
    pub mean_displacement_increment: Vec<f64>,
    /// Free surface fraction ψ.
    pub free_surface: Vec<f64>,
    /// Diagonal of the mean stress (summed by the force pass), Pa; an output only.
    pub stress: Vec<Vec3>,
    /// Smoothed radius increment dR̄, m.
    pub radius_increment: Vec<f64>,
}

impl MdrParticles {
    /// The state of particles of radii `radii` with no contact yet: R₀ = R, ψ = 1.
    pub fn new(radii: &[f64]) -> Self {
        let mut p = MdrParticles::default();
        for &r in radii {
            p.push(r);
        }
        p
    }

    /// Add a particle of radius `radius` with no contact yet (LAMMPS's set-up of a new
    /// atom: its sums zero, then its volumes, area and ψ = 1 from them).
    pub fn push(&mut self, radius: f64) {
        self.radius.push(radius);
        self.initial_radius.push(radius);
        self.stress.push(Vec3::zeros());
        for array in [
            &mut self.geometric_volume,
            &mut self.elastic_volume,
            &mut self.cap_volume,
            &mut self.mean_strain,
            &mut self.radius_numerator,
            &mut self.radius_denominator,
            &mut self.contact_area,
            &mut self.contact_area_next,
            &mut self.total_area,
            &mut self.area_change_sum,
            &mut self.mean_displacement_increment,
            &mut self.free_surface,
            &mut self.radius_increment,
        ] {
            array.push(0.0);
        }
        self.update(self.len() - 1, f64::INFINITY);
    }

    /// Number of particles.
    pub fn len(&self) -> usize {
        self.radius.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.radius.is_empty()
    }

    /// The start of a step: volumes, areas, ψ and the radius from the sums of the
    /// last force pass, then the sums cleared for this one. `bulk_trigger` is ψ_b.
    pub fn begin_step(&mut self, bulk_trigger: f64) {
        for i in 0..self.len() {
            self.update(i, bulk_trigger);
        }
        self.mean_displacement_increment.fill(0.0);
        self.cap_volume.fill(0.0);
        self.mean_strain.fill(0.0);
        self.radius_numerator.fill(0.0);
        self.radius_denominator.fill(0.0);
        self.contact_area_next.fill(0.0);
        self.area_change_sum.fill(0.0);
        self.stress.fill(Vec3::zeros());
    }

    /// One particle's update, in LAMMPS's arithmetic (`FixGranularMDR::pre_force`);
    /// the radius grows only if ψ > `bulk_trigger` (never for a new particle, whose
    /// sums are zero).
    fn update(&mut self, i: usize, bulk_trigger: f64) {
        let r = self.radius[i];
        let r_sq = r * r;
        let ro = self.initial_radius[i];
        let vo = 4.0 / 3.0 * PI * (ro * ro * ro);
        let v_geo = 4.0 / 3.0 * PI * r_sq * r - self.cap_volume[i];
        self.geometric_volume[i] = v_geo.min(vo);
        self.elastic_volume[i] = vo * (1.0 + self.mean_strain[i]);
        self.total_area[i] = 4.0 * PI * r_sq + self.area_change_sum[i];
        let psi = (self.total_area[i] - self.contact_area_next[i]) / self.total_area[i];
        self.free_surface[i] = psi;
        if bulk_trigger < psi {
            let confinement = if psi > 0.1 {
                1.0 / (1.0 + (-75.0 * (psi - 0.2)).exp())
            } else {
                0.0
            };
            let dr = self.radius_numerator[i] / (self.radius_denominator[i] - 4.0 * PI * r_sq)
                * confinement;
            let dr = if dr > 0.0 { dr } else { 0.0 };
            if dr > 0.0 {
                self.radius_increment[i] += (dr - self.radius_increment[i]) / WINDOW;
            }
            if r + dr < RADIUS_LIMIT * ro && dr > 0.0 {
                self.radius[i] += self.radius_increment[i];
            }
        }
        self.contact_area[i] = self.contact_area_next[i];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fresh particle has its whole surface free and its own volume; sums of a
    /// force pass that displaced plastic volume grow the radius, smoothed.
    #[test]
    fn the_radius_grows_with_displaced_volume() {
        let mut p = MdrParticles::new(&[1e-6]);
        assert_eq!(p.free_surface[0], 1.0);
        let vo = 4.0 / 3.0 * PI * 1e-18;
        assert!((p.geometric_volume[0] - vo).abs() < 1e-15 * vo);
        p.radius_numerator[0] = -1e-21;
        p.radius_denominator[0] = 1e-13;
        p.begin_step(0.5);
        let dr = 1e-21 / (4.0 * PI * 1e-12 - 1e-13) / (1.0 + (-75.0f64 * 0.8).exp());
        assert!((p.radius_increment[0] - dr / 10.0).abs() < 1e-12 * dr);
        assert!(p.radius[0] > 1e-6);
        // Below the bulk trigger the radius stays.
        let mut q = MdrParticles::new(&[1e-6]);
        q.radius_numerator[0] = -1e-21;
        q.begin_step(1.0);
        assert_eq!(q.radius[0], 1e-6);
    }
}
