//! Memory a scene will need, estimated from the scene before anything is allocated,
//! against the memory this process may still use. A scene that cannot fit is refused
//! with exit 2 naming the field that asks for most of it; without the check, an
//! allocation failure aborts the process with no message a user can act on.
//!
//! The estimate is an upper bound by design (a refusal must be right; a run that
//! fits must never be refused for want of a tighter figure):
//! - per particle, `BYTES_PER_PARTICLE`, about three times the peak resident size
//!   per particle of a dense deposited bed with frictional history
//!   (docs/scene-format.md, "Memory"), which covers vectors that grew by doubling;
//! - per height-field cell, two triangles with their bounds and grid entries;
//! - per `trajectory.csv` row (kept in memory until the run ends), the longest row
//!   17-digit numbers give.
//!
//! Available memory is the least of what the kernel reports as available, the
//! cgroup's limit less its use, and the address-space limit (`ulimit -v`) less the
//! process's size; where none can be read (not Linux), no scene is refused.

use super::schema::Scene;
use super::walls::ShapeSpec;
use crate::error::{Result, TampError};

const BYTES_PER_PARTICLE: f64 = 2048.0;
const BYTES_PER_HEIGHT_CELL: f64 = 512.0;
const BYTES_PER_TRAJECTORY_ROW: f64 = 12.0 * 25.0;

/// One field's share of the estimate.
struct Share {
    path: String,
    bytes: f64,
}

/// The shares of the fields whose size the scene sets; `steps` once it is known
/// (the outputs kept in memory grow with it), and the particles a process adds
/// (`process`: the field that sets their count, and the count).
fn shares(scene: &Scene, steps: Option<u64>, process: Option<(&str, usize)>) -> Vec<Share> {
    let mut shares = Vec::new();
    let mut particles = scene.particles.len() as f64;
    if !scene.particles.is_empty() {
        shares.push(Share {
            path: "particles".into(),
            bytes: particles * BYTES_PER_PARTICLE,
        });
    }
    for (k, ins) in scene.insert.iter().enumerate() {
        particles += ins.count as f64;
        shares.push(Share {
            path: format!("insert[{k}].count"),
            bytes: ins.count as f64 * BYTES_PER_PARTICLE,
        });
    }
    for (k, dep) in scene.deposit.iter().enumerate() {
        particles += dep.count as f64;
        shares.push(Share {
            path: format!("deposit[{k}].count"),
            bytes: dep.count as f64 * BYTES_PER_PARTICLE,
        });
    }
    if let Some((path, count)) = process {
        particles += count as f64;
        shares.push(Share {
            path: path.into(),
            bytes: count as f64 * BYTES_PER_PARTICLE,
        });
    }
    for (k, wall) in scene.walls.iter().enumerate() {
        if let ShapeSpec::HeightField {
            cells: Some([nx, ny]),
            ..
        } = wall.shape
        {
            shares.push(Share {
                path: format!("walls[{k}].shape.cells"),
                bytes: nx as f64 * ny as f64 * BYTES_PER_HEIGHT_CELL,
            });
        }
    }
    let every = scene.output.trajectory_every;
    if let (Some(steps), true) = (steps, every > 0) {
        let dense = scene
            .output
            .trajectory_every_step_from
            .map_or(0, |from| steps.saturating_sub(from));
        let records = (steps / every) as f64 + dense as f64 + 2.0;
        shares.push(Share {
            path: "output.trajectory_every".into(),
            bytes: records * particles * BYTES_PER_TRAJECTORY_ROW,
        });
    }
    shares
}

/// Refuse the scene when its estimate exceeds the memory available now.
pub fn check(scene: &Scene, steps: Option<u64>) -> Result<()> {
    check_with(scene, steps, None)
}

/// `check` of the scene a process's stages share, with the particles the process adds
/// (the field that sets their count, and the count).
pub fn check_with(scene: &Scene, steps: Option<u64>, process: Option<(&str, usize)>) -> Result<()> {
    let Some(available) = available_bytes() else {
        return Ok(());
    };
    check_against(scene, steps, process, available)
}

fn check_against(
    scene: &Scene,
    steps: Option<u64>,
    process: Option<(&str, usize)>,
    available: f64,
) -> Result<()> {
    let shares = shares(scene, steps, process);
    let total: f64 = shares.iter().map(|s| s.bytes).sum();
    if total <= available {
        return Ok(());
    }
    let largest = shares
        .iter()
        .max_by(|a, b| a.bytes.total_cmp(&b.bytes))
        .expect("a positive total has a share");
    Err(TampError::input(
        largest.path.clone(),
        format!(
            "the scene needs about {} of memory ({} of it for this field), more than the {} this process can still use; make the scene smaller or run it on a larger machine",
            gib(total),
            gib(largest.bytes),
            gib(available)
        ),
    ))
}

fn gib(bytes: f64) -> String {
    format!("{:.3} GiB", bytes / f64::from(1u32 << 30))
}

/// The least of the limits this process can read; `None` when it can read none.
fn available_bytes() -> Option<f64> {
    let read = |path: &str| std::fs::read_to_string(path).ok();
    let field = |text: &str, key: &str| -> Option<f64> {
        let line = text.lines().find(|l| l.starts_with(key))?;
        let kib: f64 = line[key.len()..].split_whitespace().next()?.parse().ok()?;
        Some(kib * 1024.0)
    };
    let mut limits = Vec::new();
    if let Some(meminfo) = read("/proc/meminfo") {
        limits.extend(field(&meminfo, "MemAvailable:"));
    }
    if let (Some(max), Some(current)) = (
        read("/sys/fs/cgroup/memory.max"),
        read("/sys/fs/cgroup/memory.current"),
    ) && let (Ok(max), Ok(current)) = (max.trim().parse::<f64>(), current.trim().parse::<f64>())
    {
        limits.push(max - current);
    }
    if let (Some(limits_text), Some(status)) =
        (read("/proc/self/limits"), read("/proc/self/status"))
        && let Some(line) = limits_text
            .lines()
            .find(|l| l.starts_with("Max address space"))
        && let Some(soft) = line.split_whitespace().nth(3)
        && let Ok(soft) = soft.parse::<f64>()
    {
        let size = field(&status, "VmSize:").unwrap_or(0.0);
        limits.push(soft - size);
    }
    limits.into_iter().reduce(f64::min)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene(json: &str) -> Scene {
        crate::scene::parse(json).unwrap()
    }

    const BASE: &str = r#"{"name": "m", "materials": [{"name": "a", "density": 1000, "youngs_modulus": 1e7, "poisson_ratio": 0.3}],
        "contact": {"normal": {"law": "hertz"}}, "time_step": {"characteristic_velocity": 1},
        "insert": [{"count": COUNT, "radius": 0.01, "material": "a", "region": {"lower": [0, 0, 0], "upper": [1e3, 1e3, 1e3]}}],
        "run": {"steps": 10}}"#;

    #[test]
    fn a_billion_particles_do_not_fit_in_a_gigabyte() {
        let s = scene(&BASE.replace("COUNT", "1000000000"));
        let err = check_against(&s, None, None, 1e9).unwrap_err().to_string();
        assert!(err.contains("insert[0].count"), "{err}");
        assert!(err.contains("1907.349 GiB"), "{err}");
        assert!(err.contains("0.931 GiB"), "{err}");
    }

    #[test]
    fn a_thousand_particles_fit() {
        let s = scene(&BASE.replace("COUNT", "1000"));
        assert!(check_against(&s, Some(10), None, 1e9).is_ok());
    }

    #[test]
    fn this_machine_reports_its_memory() {
        if cfg!(target_os = "linux") {
            let bytes = available_bytes().expect("Linux has /proc/meminfo");
            assert!(bytes > 0.0 && bytes.is_finite());
        }
    }
}
