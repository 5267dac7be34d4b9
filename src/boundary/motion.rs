//! How a boundary moves. Boundaries are rigid and only translate: the die punches,
//! lids and shaken containers of powder processing need no rotation, and a
//! translating body keeps its shape's acceleration structures valid.
//!
//! - `Fixed`: never moves.
//! - `Velocity`: constant velocity v; u(t) = v t.
//! - `Displacement`: u(t) given per axis as expressions of t. Over a step the
//!   boundary moves exactly from u(t) to u(t + Δt); its velocity during the step is
//!   the chord (u(t + Δt) − u(t))/Δt, which is what the particles feel and what the
//!   work of the boundary is computed with.
//! - `Servo`: holds a target force (or pressure × area) that the particles exert on
//!   the boundary along a direction, like LIGGGHTS' `servo` walls: the boundary moves
//!   along `direction` (the way it presses) with speed
//!   v = clamp(gain · (F_target − R), −v_max, v_max), where R = −F_on_boundary · direction
//!   is the particles' reaction. Near equilibrium the bed pushes back like a spring
//!   k_bed with a dashpot c_bed (the contact damping), and the controller is stable
//!   only when gain·(k_bed·Δt + c_bed) < 1: a gain above 1/c_bed makes the lid chatter
//!   between pressing and backing off, because the damping force it feels grows with
//!   the speed it chose (found in `tests/boundaries.rs`). The run reports the
//!   reaction in the series, so the user sees convergence.

use crate::expression::Expression;
use crate::particles::Vec3;

#[derive(Clone, Debug)]
pub enum BoundaryMotion {
    Fixed,
    Velocity(Vec3),
    Displacement(Box<[Expression; 3]>),
    Servo(Servo),
}

#[derive(Clone, Debug, PartialEq)]
pub struct Servo {
    /// Unit vector along which the boundary presses on the particles.
    pub direction: Vec3,
    /// Target reaction of the particles, N.
    pub target_force: f64,
    /// Speed per newton of force error, m/(s·N).
    pub gain: f64,
    /// Largest speed, m/s.
    pub max_speed: f64,
}

impl Servo {
    /// Velocity for the next step, given the force the particles exert on the boundary.
    pub fn velocity(&self, force_on_boundary: &Vec3) -> Vec3 {
        let reaction = -force_on_boundary.dot(&self.direction);
        let speed =
            (self.gain * (self.target_force - reaction)).clamp(-self.max_speed, self.max_speed);
        self.direction * speed
    }
}

impl BoundaryMotion {
    /// Displacement at time t for the kinds given as functions of time.
    pub fn displacement_at(&self, t: f64) -> Option<Vec3> {
        match self {
            BoundaryMotion::Displacement(u) => {
                let c = |k: usize| u[k].eval(&[t]).unwrap_or(f64::NAN);
                Some(Vec3::new(c(0), c(1), c(2)))
            }
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn servo_moves_towards_the_target_and_saturates() {
        let s = Servo {
            direction: Vec3::new(0.0, 0.0, -1.0),
            target_force: 10.0,
            gain: 0.01,
            max_speed: 0.05,
        };
        // Particles push up on a lid pressing down: force on the lid is +z.
        let v = s.velocity(&Vec3::new(0.0, 0.0, 4.0));
        assert!((v.z + 0.06f64.min(0.05)).abs() < 1e-15);
        let v = s.velocity(&Vec3::new(0.0, 0.0, 12.0));
        assert!(
            (v.z - 0.02).abs() < 1e-15,
            "too much force: the lid backs off"
        );
    }
}
