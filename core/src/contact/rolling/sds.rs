//! LAMMPS's rolling resistance `rolling sds k_r γ_r μ_r` (spring–dashpot–slider),
//! reproduced operation for operation from LAMMPS 22 Jul 2025,
//! src/GRANULAR/gran_sub_mod_rolling.cpp `GranSubModRollingSDS::calculate_forces`, with
//! the rolling velocity and the torque from granular_model.cpp `calculate_forces`. The
//! rolling velocity is Wang et al.'s (Particuology 23, 49, 2015, eq 31), which LAMMPS
//! takes instead of the Bagi–Kuhn form of Marshall's papers (J. Comput. Phys. 228,
//! 1541, 2009). With `normal` n from the partner to particle i, R* the contact's
//! effective radius (a curved wall's for a wall), ω_j = 0 for a wall, and F_n the
//! normal force the friction limit reads (`set_fncrit`), per step:
//!
//! ```text
//!   v_r = R* (ω_i − ω_j) × n                  (rolling velocity)
//!   F_r,crit = μ_r |F_n|
//!   if k_r |ξ·n| > 1e-10 F_r,crit:  ξ ← (ξ − (ξ·n) n) · |ξ| / |ξ − (ξ·n) n|
//!   ξ ← ξ + v_r Δt
//!   F_r = −k_r ξ − γ_r v_r
//!   if |F_r| > F_r,crit and |ξ| ≠ 0:  ξ ← −(F_r,crit F_r/|F_r| + γ_r v_r)/k_r,
//!                                      F_r ← F_r,crit F_r/|F_r|
//!   if |F_r| > F_r,crit and |ξ| = 0:  F_r ← 0
//!   torque on i:  R* n × F_r,   on j:  −R* n × F_r
//! ```
//!
//! ξ (m) is the rolling displacement, kept per contact beside the sliding history: it
//! starts at zero when a contact forms and is dropped when it ends. The torque does not
//! depend on the scene's lever arms (LAMMPS adds it after the tangential torque), and it
//! acts in pairs with no force, so linear momentum is untouched. On the slider a
//! rolling sphere feels the constant resisting moment R* μ_r |F_n|: on a plane with
//! sticking friction a sphere of radius R and mass m rolling under gravity g then
//! decelerates at μ_r g R*²/(R² + I/m) = (5/7) μ_r g (R* = R).
//!
//! LAMMPS works on a copy of ξ and stores it back only on a step that updates histories,
//! so the set-up force of a `run` command reads the stored ξ without the step's growth
//! (where its 22 Jul 2025 code leaves the copy unset, docs/lammps.md); tamp evaluates
//! every step as a regular step.

use crate::contact::tangential::lammps_mindlin::turn_above_threshold;
use crate::error::Errors;
use crate::particles::Vec3;

/// `{"law": "sds", "stiffness": k_r, "damping": γ_r, "friction": μ_r}`.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Sds {
    /// k_r, N/m.
    pub stiffness: f64,
    /// γ_r, N·s/m.
    pub damping: f64,
    /// μ_r: the slider's limit over |F_n|.
    pub friction: f64,
}

/// What the rolling resistance reads from one contact.
#[derive(Clone, Copy, Debug)]
pub struct RollingInput {
    /// Unit normal n from the partner to particle i.
    pub normal: Vec3,
    /// Rolling velocity v_r = R* (ω_i − ω_j) × n, m/s.
    pub velocity: Vec3,
    /// Time step Δt, s.
    pub dt: f64,
    /// The normal force the friction limit reads (elastic plus damping), N.
    pub normal_force: f64,
}

impl Sds {
    /// LAMMPS's rule: k_r > 0 (the slider divides by it), γ_r ≥ 0, μ_r ≥ 0.
    pub fn check(&self, path: &str, errors: &mut Errors) {
        errors.positive(format!("{path}.stiffness"), self.stiffness);
        errors.non_negative(format!("{path}.damping"), self.damping);
        errors.non_negative(format!("{path}.friction"), self.friction);
    }

    /// The rolling resistance F_r on i this step; advances ξ.
    #[inline(always)]
    pub fn force(&self, input: &RollingInput, xi: &mut Vec3) -> Vec3 {
        let (k, gamma) = (self.stiffness, self.damping);
        let limit = self.friction * input.normal_force.abs();
        let v = input.velocity;
        turn_above_threshold(xi, &input.normal, k, limit);
        *xi += v * input.dt;
        let mut f = *xi * -k + v * -gamma;
        let magnitude = f.norm();
        if magnitude > limit {
            if xi.norm() != 0.0 {
                let (k_inv, magnitude_inv) = (1.0 / k, 1.0 / magnitude);
                *xi = f * (-limit * k_inv * magnitude_inv) + v * (-gamma * k_inv);
                f *= limit * magnitude_inv;
            } else {
                f = Vec3::zeros();
            }
        }
        f
    }

    /// ½ k_r |ξ|², J.
    pub fn energy(&self, xi: &Vec3) -> f64 {
        0.5 * self.stiffness * xi.norm_squared()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn law() -> Sds {
        Sds {
            stiffness: 100.0,
            damping: 0.0,
            friction: 0.5,
        }
    }

    fn rolling(velocity: Vec3) -> RollingInput {
        RollingInput {
            normal: Vec3::z(),
            velocity,
            dt: 1e-3,
            normal_force: 2.0,
        }
    }

    /// Within the slider's limit the spring holds the rolling displacement: ξ = v_r Δt
    /// and F_r = −k_r ξ.
    #[test]
    fn the_spring_resists_a_small_roll() {
        let mut xi = Vec3::zeros();
        let f = law().force(&rolling(Vec3::x()), &mut xi);
        assert_eq!(xi, Vec3::x() * 1e-3);
        assert_eq!(f, Vec3::x() * -0.1);
        assert_eq!(law().energy(&xi), 0.5 * 100.0 * 1e-6);
    }

    /// Past the limit the force is μ_r |F_n| against the roll and the spring is set to
    /// hold exactly that.
    #[test]
    fn the_slider_caps_the_resistance() {
        let mut xi = Vec3::zeros();
        let f = law().force(&rolling(Vec3::x() * 100.0), &mut xi);
        assert!((f + Vec3::x()).norm() < 1e-15, "{f}");
        assert!((xi * -100.0 - f).norm() < 1e-15, "{xi}");
    }

    /// A spring left along the normal by a turning contact is turned back into the
    /// contact plane with its length kept.
    #[test]
    fn the_displacement_is_turned_into_the_contact_plane() {
        let mut xi = Vec3::new(3e-4, 0.0, 4e-4);
        law().force(&rolling(Vec3::zeros()), &mut xi);
        assert!((xi - Vec3::x() * 5e-4).norm() < 1e-18, "{xi}");
    }
}
