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
//! - `Pressed`: a rigid punch of mass M loaded by a pressure p(t) on its area A
//!   that rises linearly to p_max over the ramp time and then holds, moving along
//!   `direction` by Newton's law: M dv/dt = p(t) A − R, with R the particles'
//!   reaction as for the servo. This is the plate of Rojek 2016 §5 ("loaded with a
//!   linearly rising pressure"). It is integrated by symplectic Euler with the
//!   particles' step, v ← v + Δt (p A − R)/M, then u ← u + Δt v, which is stable
//!   while Δt < 2/√(k_bed/M); a punch far heavier than the particles it touches
//!   meets that with the particles' own step. Unlike the servo there is no gain to
//!   tune: the punch follows the load with the lag its own inertia gives, M·a, which
//!   the run reports (applied load and reaction side by side).

use crate::expression::Expression;
use crate::particles::Vec3;

/// The translation u(t) of a wall: prescribed or driven by the particles' reaction.
#[derive(Clone, Debug)]
pub enum BoundaryMotion {
    /// Never moves: u = 0.
    Fixed,
    /// Constant velocity v, m/s: u(t) = v t.
    Velocity(Vec3),
    /// u(t) given per axis (x, y, z) as expressions of t, m.
    Displacement(Box<[Expression; 3]>),
    /// Speed set each step to drive the particles' reaction towards a target force.
    Servo(Servo),
    /// Punch of finite mass moved by a pressure load against the particles' reaction.
    Pressed(PressureLoad),
}

/// A rigid punch of mass M loaded by a pressure p(t) on its area A, ramped linearly
/// to its final value and then held; moves by M dv/dt = p(t) A − R.
#[derive(Clone, Debug, PartialEq)]
pub struct PressureLoad {
    /// Unit vector along which the punch presses on the particles.
    pub direction: Vec3,
    /// Final pressure, Pa.
    pub pressure: f64,
    /// Loaded area, m².
    pub area: f64,
    /// Time over which the pressure rises linearly from zero, s (0: applied at once).
    pub ramp_time: f64,
    /// Mass of the punch, kg.
    pub mass: f64,
}

impl PressureLoad {
    /// Pressure applied at time t.
    pub fn pressure_at(&self, t: f64) -> f64 {
        if t >= self.ramp_time {
            self.pressure
        } else {
            self.pressure * (t / self.ramp_time).max(0.0)
        }
    }

    /// Velocity after a step of dt from t, given the present velocity and the force
    /// the particles exert on the punch.
    pub fn velocity(&self, t: f64, dt: f64, velocity: &Vec3, force_on_boundary: &Vec3) -> Vec3 {
        let reaction = -force_on_boundary.dot(&self.direction);
        let load = self.pressure_at(t) * self.area;
        let speed = velocity.dot(&self.direction) + dt * (load - reaction) / self.mass;
        self.direction * speed
    }
}

/// A force-controlled wall: speed proportional to the error between a target force
/// and the particles' reaction, clamped to a largest speed.
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
    fn pressed_punch_follows_newtons_law_under_the_ramp() {
        let p = PressureLoad {
            direction: Vec3::new(0.0, 0.0, -1.0),
            pressure: 10.0,
            area: 2.0,
            ramp_time: 4.0,
            mass: 5.0,
        };
        assert_eq!(p.pressure_at(1.0), 2.5);
        assert_eq!(p.pressure_at(9.0), 10.0);
        // Load 2.5 Pa × 2 m² = 5 N down, reaction 1 N: a = 4/5 m/s² along −z.
        let v = p.velocity(1.0, 0.5, &Vec3::zeros(), &Vec3::new(0.0, 0.0, 1.0));
        assert!((v.z + 0.4).abs() < 1e-15, "{v:?}");
        // At balance the speed is kept.
        let v = p.velocity(1.0, 0.5, &v, &Vec3::new(0.0, 0.0, 5.0));
        assert!((v.z + 0.4).abs() < 1e-15, "{v:?}");
    }

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
