//! The characteristic velocity a scene implies when it does not give one: the
//! largest normal approach speed its contacts can see, bounded from what the scene
//! states at t = 0. Particles are named by their scene id (1-based, as
//! trajectory.csv prints them). For two bodies it is their relative speed (the normal part of it
//! at impact is at most this); a scene can fix it with
//! `time_step.characteristic_velocity`. The candidates, the largest of which is used:
//!
//! - the largest relative speed of two particles' initial or prescribed velocities
//!   (exact over all pairs up to `EXACT_PAIRS` particles, else the bound 2 max|v|);
//! - a particle against a wall: |v_i − v_wall| with the wall's constant velocity;
//! - poured particles: twice the sources' entry speed (two poured spheres meeting);
//! - free fall under gravity over the domain's height H along g (the extent of the
//!   particles, the sources' boxes and the planes' points): √(v² + 2|g|H), v the
//!   largest of the speeds above.
//!
//! A wall driven by a displacement expression, a servo or a pressure is not a
//! candidate: its speed is known only while the run goes.

use crate::boundary::BoundaryMotion;
use crate::boundary::shape::Shape;
use crate::particles::Vec3;
use crate::simulation::Simulation;

/// Beyond this many particles the pairwise search gives way to the bound 2 max|v|.
const EXACT_PAIRS: usize = 2000;

/// The implied characteristic velocity and which candidate gave it.
#[derive(Clone, Debug, PartialEq)]
pub struct Implied {
    pub speed: f64,
    pub source: String,
}

pub fn implied(sim: &Simulation) -> Implied {
    let p = &sim.particles;
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
    for w in &sim.walls {
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
    for (k, s) in sim.sources.iter().enumerate() {
        if s.remaining > 0 {
            offer_to(
                &mut best,
                2.0 * s.speed,
                format!("twice the entry speed of insert source {k}"),
            );
        }
    }
    if let Some(g) = sim.gravity.filter(|g| g.norm() > 0.0) {
        let down = g.normalize();
        let mut heights: Vec<f64> = p.position.iter().map(|x| x.dot(&down)).collect();
        for s in &sim.sources {
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
        for w in &sim.walls {
            if let Shape::Plane(plane) = &w.shape {
                heights.push((plane.point + w.displacement).dot(&down));
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
