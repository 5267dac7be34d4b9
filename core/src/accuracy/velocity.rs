//! The characteristic velocity a scene implies when it does not give one: the
//! largest normal approach speed its contacts can see, bounded from what the scene
//! states at t = 0. Particles are named by their scene id (1-based, as
//! trajectory.csv prints them). For two bodies it is their relative speed (the normal part of it
//! at impact is at most this); a scene can fix it with
//! `time_step.characteristic_velocity`. The candidates, the largest of which is used:
//!
//! - the largest relative speed of two particles' initial or prescribed velocities
//!   (exact over all pairs up to `EXACT_PAIRS` particles, else the bound 2 max|v|);
//! - a prescribed velocity that changes during the run: twice its later speeds;
//! - a particle against a wall: |v_i − v_wall| with the wall's constant velocity;
//! - poured particles: twice the sources' entry speed (two poured spheres meeting);
//! - free fall under gravity over the domain's height H along g (the extent of the
//!   particles, the sources' boxes and the planes' points): √(v² + 2|g|H), v the
//!   largest of the speeds above.
//!
//! - a punch loaded by a pressure ramp p(t) = p_max min(t/t_r, 1) on its area A
//!   (mass M, from rest): the larger of two speeds. Its free flight across the gap g
//!   to the nearest particle, F = M x'' with nothing resisting, gives the speed at
//!   first touch exactly: x = p_max A t³/(6 M t_r) and v = p_max A t²/(2 M t_r) while
//!   t ≤ t_r, then constant acceleration p_max A/M. Once on the bed its speed comes
//!   from the bed's response, which only the run knows; the estimate is the mean
//!   speed that closes the bed's whole height H (the particles' extent along the
//!   punch's direction) within the ramp, H/t_r, an upper bound of the mean speed of
//!   a pressing that ends with the ramp (a bed never compresses to nothing), though
//!   a collapse of the bed can be faster for a moment.
//!
//! A wall driven by a displacement expression or a servo is not a candidate: its speed
//! is known only while the run goes.

use crate::boundary::BoundaryMotion;
use crate::boundary::motion::PressureLoad;
use crate::boundary::shape::Shape;
use crate::particles::Vec3;
use crate::simulation::Simulation;

/// Beyond this many particles the pairwise search gives way to the bound 2 max|v|.
const EXACT_PAIRS: usize = 2000;

/// The implied characteristic velocity and which candidate gave it.
#[derive(Clone, Debug, PartialEq)]
pub struct Implied {
    /// The characteristic velocity, m/s.
    pub speed: f64,
    /// Which candidate gave it, in words, for messages.
    pub source: String,
}

/// The characteristic velocity implied by the scene at t = 0: the largest of the
/// module comment's candidates.
pub fn implied(sim: &Simulation) -> Implied {
    let p = &sim.state.particles;
    let mut best = Implied {
        speed: 0.0,
        source: "nothing in the scene moves".into(),
    };
    fn offer_to(best: &mut Implied, speed: f64, source: String) {
        if speed > best.speed {
            *best = Implied { speed, source };
        }
    }
    let n = p.len();
    if n <= EXACT_PAIRS {
        for i in 0..n {
            for j in i + 1..n {
                offer_to(
                    &mut best,
                    (p.velocity[i] - p.velocity[j]).norm(),
                    format!(
                        "the relative speed of particles {} and {}",
                        p.id[i], p.id[j]
                    ),
                );
            }
        }
    } else if let Some((i, v)) = (0..n)
        .map(|i| (i, p.velocity[i].norm()))
        .max_by(|a, b| a.1.total_cmp(&b.1))
    {
        offer_to(
            &mut best,
            2.0 * v,
            format!(
                "twice the fastest particle's speed (particle {}; {n} particles, too many to pair)",
                p.id[i]
            ),
        );
    }
    for change in &sim.model.velocity_changes {
        offer_to(
            &mut best,
            2.0 * change.velocity.norm(),
            format!(
                "twice the speed particle {} is prescribed from step {}",
                change.id, change.step
            ),
        );
    }
    for w in &sim.model.walls {
        let wall = match w.motion {
            BoundaryMotion::Fixed => Vec3::zeros(),
            BoundaryMotion::Velocity(v) => v,
            _ => continue,
        };
        for i in 0..n {
            offer_to(
                &mut best,
                (p.velocity[i] - wall).norm(),
                format!(
                    "the speed of particle {} relative to wall '{}'",
                    p.id[i], w.name
                ),
            );
        }
    }
    for (w, pose) in sim.model.walls.iter().zip(&sim.state.walls) {
        let BoundaryMotion::Pressed(load) = &w.motion else {
            continue;
        };
        let ahead: Vec<f64> = (0..n).map(|i| p.position[i].dot(&load.direction)).collect();
        let Some(front) = (0..n).map(|i| ahead[i] - p.radius[i]).reduce(f64::min) else {
            continue;
        };
        let back = (0..n)
            .map(|i| ahead[i] + p.radius[i])
            .fold(f64::NEG_INFINITY, f64::max);
        if let Shape::Plane(plane) = &w.shape {
            let face = (plane.point + pose.displacement).dot(&load.direction);
            let gap = front - face;
            if gap > 0.0 {
                offer_to(
                    &mut best,
                    punch_speed_after(load, gap),
                    format!(
                        "the speed punch '{}' reaches in free flight across the gap {gap:.3e} m to the particles",
                        w.name
                    ),
                );
            }
        }
        if load.ramp_time > 0.0 {
            let height = back - front;
            offer_to(
                &mut best,
                height / load.ramp_time,
                format!(
                    "the mean speed at which punch '{}' would close the bed's height {height:.3e} m within its ramp of {:.3e} s",
                    w.name, load.ramp_time
                ),
            );
        }
    }
    for (k, (s, at)) in sim.model.sources.iter().zip(&sim.state.sources).enumerate() {
        if at.remaining > 0 {
            offer_to(
                &mut best,
                2.0 * s.speed,
                format!("twice the entry speed of insert source {k}"),
            );
        }
    }
    if let Some(g) = sim.model.gravity.filter(|g| g.norm() > 0.0) {
        let down = g.normalize();
        let mut heights: Vec<f64> = p.position.iter().map(|x| x.dot(&down)).collect();
        for s in &sim.model.sources {
            for c in 0..8 {
                let pick = |k: usize, a: f64, b: f64| if c >> k & 1 == 0 { a } else { b };
                let (lo, hi) = (s.region.lower, s.region.upper);
                let corner = Vec3::new(
                    pick(0, lo.x, hi.x),
                    pick(1, lo.y, hi.y),
                    pick(2, lo.z, hi.z),
                );
                heights.push(corner.dot(&down));
            }
        }
        for (w, pose) in sim.model.walls.iter().zip(&sim.state.walls) {
            if let Shape::Plane(plane) = &w.shape {
                heights.push((plane.point + pose.displacement).dot(&down));
            }
        }
        let (lo, hi) = heights
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |a, &h| {
                (a.0.min(h), a.1.max(h))
            });
        if hi > lo {
            let height = hi - lo;
            let v = best.speed;
            offer_to(
                &mut best,
                (v * v + 2.0 * g.norm() * height).sqrt(),
                format!(
                    "free fall under gravity over the domain's height {height:.3e} m{}",
                    if v > 0.0 {
                        format!(" from {v:.3e} m/s")
                    } else {
                        String::new()
                    }
                ),
            );
        }
    }
    best
}

/// The speed of a punch after a free flight of `gap` from rest under its load ramp.
pub fn punch_speed_after(load: &PressureLoad, gap: f64) -> f64 {
    let a = load.pressure * load.area / load.mass;
    let t_r = load.ramp_time;
    // Within the ramp x = a t³/(6 t_r): the gap is crossed at t_g = (6 t_r g/a)^{1/3}.
    let t_g = (6.0 * t_r * gap / a).cbrt();
    if t_g <= t_r {
        0.5 * a * t_g * t_g / t_r
    } else {
        let (x_r, v_r) = (a * t_r * t_r / 6.0, 0.5 * a * t_r);
        (v_r * v_r + 2.0 * a * (gap - x_r)).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The closed form against the punch's equation of motion integrated directly
    /// (velocity Verlet at 1e6 steps over the flight, the force known in time), on both
    /// sides of the ramp's end.
    #[test]
    fn punch_free_flight_matches_its_equation_of_motion() {
        let load = PressureLoad {
            direction: Vec3::new(0.0, 0.0, -1.0),
            pressure: 50e6,
            area: 8.1e-10,
            ramp_time: 1e-4,
            mass: 1e-9,
        };
        let a = |t: f64| load.pressure_at(t) * load.area / load.mass;
        for gap in [1e-7, 1e-5, 2e-1] {
            let closed = punch_speed_after(&load, gap);
            // March until x reaches the gap, with a step of 1e-6 of the flight time.
            let flight = gap / closed * 3.0;
            let h = flight * 1e-6;
            let (mut t, mut x, mut v) = (0.0f64, 0.0f64, 0.0f64);
            while x < gap {
                let v_half = v + 0.5 * h * a(t);
                let x_next = x + h * v_half;
                let v_next = v_half + 0.5 * h * a(t + h);
                if x_next >= gap {
                    // Linear in the last step: an O(h) fraction of one step's change.
                    v = v + (v_next - v) * (gap - x) / (x_next - x);
                    break;
                }
                (t, x, v) = (t + h, x_next, v_next);
            }
            assert!(
                (v / closed - 1.0).abs() < 1e-5,
                "gap {gap}: integrated {v}, closed form {closed}"
            );
        }
    }
}
