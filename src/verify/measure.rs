//! Measurements of recorded runs that more than one case makes: a collision between two
//! particles, or between a particle and a fixed plane or cylinder, read from the frames of every
//! step; the momenta and kinetic energy of a frame. The arithmetic is `collision::CollisionWatch`'s, the one a simulation uses as
//! it steps, so the tamp engine's recording gives the values of a live measurement to
//! the bit.

use crate::collision::{Collision, CollisionWatch};
use crate::error::{Result, TampError};
use crate::measure::region::ball_volume;
use crate::particles::Vec3;
use crate::verify::recording::{Frame, Recording};

/// The first collision between particles `i` and `j` (indices in the scene's order):
/// interpolated contact duration, refined and sampled largest overlap, and the
/// restitution of the normal relative speed, along the line of centres at step 0.
/// `max_force` is the force on `i`, when the recording has forces (else 0).
pub fn two_body(rec: &Recording, i: usize, j: usize) -> Result<Collision> {
    let frames = frames(rec, i.max(j), "a two-body collision")?;
    let first = &frames[0].bodies;
    let n = (first[i].position - first[j].position).normalize();
    let overlap = |f: &Frame| overlap(f, i, j);
    let approach = |f: &Frame| -(f.bodies[i].velocity - f.bodies[j].velocity).dot(&n);
    watch(
        rec,
        frames,
        &format!("particles {i} and {j}"),
        i,
        overlap,
        approach,
    )
}

/// The first collision of particle `i` with the fixed plane through `point` with unit
/// `normal`; the overlap is R_i − (x_i − point)·n.
pub fn plane(rec: &Recording, i: usize, point: Vec3, normal: Vec3) -> Result<Collision> {
    let frames = frames(rec, i, "a wall collision")?;
    let overlap = |f: &Frame| {
        let b = &f.bodies[i];
        b.radius - (b.position - point).dot(&normal)
    };
    let approach = |f: &Frame| -f.bodies[i].velocity.dot(&normal);
    watch(
        rec,
        frames,
        &format!("particle {i} and the plane"),
        i,
        overlap,
        approach,
    )
}

/// The first collision of particle `i` with the inside of the cylinder of `radius` R_c
/// about the line through `origin` along the unit `axis`; the overlap is
/// R_i − (R_c − ρ_i), ρ_i the distance of the centre from the axis, and the approach
/// speed the velocity along the outward radial direction.
pub fn cylinder_inside(
    rec: &Recording,
    i: usize,
    origin: Vec3,
    axis: Vec3,
    radius: f64,
) -> Result<Collision> {
    let frames = frames(rec, i, "a wall collision")?;
    let outward = |f: &Frame| {
        let d = f.bodies[i].position - origin;
        d - axis * d.dot(&axis)
    };
    let overlap = |f: &Frame| f.bodies[i].radius - (radius - outward(f).norm());
    let approach = |f: &Frame| f.bodies[i].velocity.dot(&outward(f).normalize());
    watch(
        rec,
        frames,
        &format!("particle {i} and the cylinder"),
        i,
        overlap,
        approach,
    )
}

/// The overlap R_i + R_j − |x_i − x_j| of particles `i` and `j` in a frame.
pub fn overlap(f: &Frame, i: usize, j: usize) -> f64 {
    let (a, b) = (&f.bodies[i], &f.bodies[j]);
    a.radius + b.radius - (a.position - b.position).norm()
}

/// |F_i|, the magnitude of the total force on particle `i` in a frame; an error when
/// the recording holds no forces.
pub fn force(f: &Frame, i: usize) -> Result<f64> {
    f.bodies[i].force.map(|v| v.norm()).ok_or_else(|| {
        TampError::Other(format!(
            "step {} holds no forces (the case must ask for them)",
            f.step
        ))
    })
}

/// Where `rising` first reaches `target`, between a frame where it is below and the next
/// recorded frame where it is at or above: `other` interpolated linearly in `rising`
/// there. The frames may be sparse; a case that needs the crossing between consecutive
/// steps records every step where it expects it (`RecordSpec::sparse_then_every_step`).
pub fn first_crossing(
    rec: &Recording,
    rising: impl Fn(&Frame) -> Result<f64>,
    other: impl Fn(&Frame) -> Result<f64>,
    target: f64,
    what: &str,
) -> Result<f64> {
    let mut frames = rec.frames.iter();
    let first = frames
        .next()
        .ok_or_else(|| TampError::Other(format!("{what} in an empty recording")))?;
    let mut prev = (rising(first)?, other(first)?);
    for f in frames {
        let now = (rising(f)?, other(f)?);
        if prev.0 < target && now.0 >= target {
            let w = (target - prev.0) / (now.0 - prev.0);
            return Ok(prev.1 + w * (now.1 - prev.1));
        }
        prev = now;
    }
    Err(TampError::Other(format!(
        "{what} never reached {target:e} in the {} recorded frames (up to step {})",
        rec.frames.len(),
        rec.frames.last().map_or(0, |f| f.step)
    )))
}

/// The overlap of particles `i` and `j` where the force on `i` first reaches `target`,
/// in a displacement-driven compression recorded with forces.
pub fn overlap_where_force_reaches(
    rec: &Recording,
    i: usize,
    j: usize,
    target: f64,
) -> Result<f64> {
    first_crossing(
        rec,
        |f| force(f, i),
        |f| Ok(overlap(f, i, j)),
        target,
        &format!("the force on particle {i}"),
    )
}

/// Mass and moment of inertia of a solid sphere of `radius` and `density`.
fn sphere(radius: f64, density: f64) -> (f64, f64) {
    let mass = density * ball_volume(radius);
    (mass, 0.4 * mass * radius * radius)
}

/// Σ m v, solid spheres of one density.
pub fn linear_momentum(frame: &Frame, density: f64) -> Vec3 {
    frame.bodies.iter().fold(Vec3::zeros(), |sum, b| {
        sum + sphere(b.radius, density).0 * b.velocity
    })
}

/// Σ m x × v + I ω about the origin, solid spheres of one density.
pub fn angular_momentum(frame: &Frame, density: f64) -> Vec3 {
    frame.bodies.iter().fold(Vec3::zeros(), |sum, b| {
        let (mass, inertia) = sphere(b.radius, density);
        sum + mass * b.position.cross(&b.velocity) + inertia * b.omega
    })
}

/// Σ ½ m v² + ½ I ω², solid spheres of one density.
pub fn kinetic_energy(frame: &Frame, density: f64) -> f64 {
    frame.bodies.iter().fold(0.0, |sum, b| {
        let (mass, inertia) = sphere(b.radius, density);
        sum + 0.5 * (mass * b.velocity.norm_squared() + inertia * b.omega.norm_squared())
    })
}

/// The consecutive frames, which must hold particle `last`.
fn frames<'a>(rec: &'a Recording, last: usize, what: &str) -> Result<&'a [Frame]> {
    let frames = rec.consecutive(what)?;
    match frames.first() {
        Some(f) if f.bodies.len() > last => Ok(frames),
        Some(f) => Err(TampError::Other(format!(
            "{what} of particle {last} in a recording of {} particles",
            f.bodies.len()
        ))),
        None => Err(TampError::Other(format!("{what} in an empty recording"))),
    }
}

fn watch(
    rec: &Recording,
    frames: &[Frame],
    bodies: &str,
    i: usize,
    overlap: impl Fn(&Frame) -> f64,
    approach: impl Fn(&Frame) -> f64,
) -> Result<Collision> {
    let mut watch = CollisionWatch::new(overlap(&frames[0]), approach(&frames[0]));
    let mut last = &frames[0];
    for f in &frames[1..] {
        last = f;
        let force = || f.bodies[i].force.map_or(0.0, |v| v.norm());
        if watch.observe(f.time, rec.dt, overlap(f), force) {
            break;
        }
    }
    watch.finish(approach(last)).ok_or_else(|| {
        TampError::Other(format!(
            "{bodies} did not complete a collision in the {} recorded steps (up to step {})",
            frames.len() - 1,
            last.step
        ))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collision::binary_collision;
    use crate::scene;
    use crate::verify::recording::RecordSpec;

    /// The recorded measurement of the tamp engine equals the live one to the bit.
    #[test]
    fn a_recorded_collision_is_measured_as_the_live_one() {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("verification/hertz_collision_time.scene.json");
        let scene = scene::load(&path).unwrap().0;
        let live =
            binary_collision(&mut scene::build(&scene).unwrap().sim, 0, 1, 10_000_000).unwrap();
        let rec = crate::verify::engine::tamp::record(&scene, RecordSpec::EVERY_STEP).unwrap();
        let recorded = two_body(&rec, 0, 1).unwrap();
        assert_eq!(live.duration.to_bits(), recorded.duration.to_bits());
        assert_eq!(live.max_overlap.to_bits(), recorded.max_overlap.to_bits());
        assert_eq!(live.restitution.to_bits(), recorded.restitution.to_bits());
        let mut gap = rec.clone();
        gap.frames.remove(5);
        let e = two_body(&gap, 0, 1).unwrap_err().to_string();
        assert!(e.contains("jumps from step 4 to 6"), "{e}");
    }
}
