//! Reading LIGGGHTS (and LAMMPS) `dump custom` text files: a sequence of frames,
//!
//! ```text
//! ITEM: TIMESTEP
//! 1200
//! ITEM: NUMBER OF ATOMS
//! 2
//! ITEM: BOX BOUNDS pp pp fm
//! xlo xhi
//! ylo yhi
//! zlo zhi
//! ITEM: ATOMS id type radius mass x y z vx vy vz omegax omegay omegaz fx fy fz
//! 1 1 0.001 ...
//! ```
//!
//! Columns are found by name, so any dump holding at least `id x y z` and a radius
//! (`radius` or `diameter`) is read; the deck tamp exports writes the columns of
//! `peer_deck::DUMP_COLUMNS`. A boundary flag starting with `p` marks a periodic axis.

use crate::error::{Result, TampError};
use crate::particles::Vec3;
use crate::space::Space;
use std::path::Path;

/// One snapshot. Atoms are sorted by id.
#[derive(Clone, Debug, Default)]
pub struct Frame {
    pub step: u64,
    /// Per axis [lo, hi] of the simulation box.
    pub bounds: [[f64; 2]; 3],
    pub periodic: [bool; 3],
    pub id: Vec<u64>,
    pub atom_type: Vec<u32>,
    pub radius: Vec<f64>,
    pub position: Vec<Vec3>,
    /// Zero when the dump has no `vx vy vz`.
    pub velocity: Vec<Vec3>,
    /// Zero when the dump has no `omegax omegay omegaz`.
    pub omega: Vec<Vec3>,
    /// Zero when the dump has no `mass`.
    pub mass: Vec<f64>,
    /// Total force on the atom (pair, wall and body forces); zero without `fx fy fz`.
    pub force: Vec<Vec3>,
    /// Whether the dump has the columns `fx fy fz` (else `force` holds zeros).
    pub has_force: bool,
}

impl Frame {
    /// The periodic axes of the box, as tamp's `Space`.
    pub fn space(&self) -> Space {
        let mut space = Space::open();
        for a in 0..3 {
            if self.periodic[a] {
                let [lo, hi] = self.bounds[a];
                space.periodic[a] = Some((lo, hi - lo));
            }
        }
        space
    }
}

/// One atom line, before the frame is sorted by id.
struct Atom {
    id: u64,
    atom_type: u32,
    radius: f64,
    position: Vec3,
    velocity: Vec3,
    omega: Vec3,
    mass: f64,
    force: Vec3,
}

fn bad(path: &Path, line: usize, rule: impl Into<String>) -> TampError {
    TampError::input(format!("{}:{line}", path.display()), rule)
}

/// Every frame of the dump file at `path`.
pub fn read(path: &Path) -> Result<Vec<Frame>> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| TampError::io(format!("reading dump {}", path.display()), e))?;
    parse(&text, path)
}

/// Parse dump text; `path` only names the source in messages.
pub fn parse(text: &str, path: &Path) -> Result<Vec<Frame>> {
    let lines: Vec<&str> = text.lines().collect();
    let mut frames = Vec::new();
    let mut k = 0;
    let expect = |k: usize, item: &str| -> Result<()> {
        match lines.get(k) {
            Some(l) if l.starts_with(item) => Ok(()),
            Some(l) => Err(bad(path, k + 1, format!("expected '{item}', found '{l}'"))),
            None => Err(bad(
                path,
                k + 1,
                format!("expected '{item}', found the end of the file"),
            )),
        }
    };
    let number = |k: usize, s: &str| -> Result<f64> {
        match s.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(bad(path, k + 1, format!("'{s}' is not a finite number"))),
        }
    };
    while k < lines.len() {
        if lines[k].trim().is_empty() {
            k += 1;
            continue;
        }
        let mut frame = Frame::default();
        expect(k, "ITEM: TIMESTEP")?;
        frame.step = lines
            .get(k + 1)
            .and_then(|s| s.trim().parse().ok())
            .ok_or_else(|| bad(path, k + 2, "the timestep must be a non-negative integer"))?;
        expect(k + 2, "ITEM: NUMBER OF ATOMS")?;
        let n: usize = lines
            .get(k + 3)
            .and_then(|s| s.trim().parse().ok())
            .ok_or_else(|| bad(path, k + 4, "the number of atoms must be an integer"))?;
        expect(k + 4, "ITEM: BOX BOUNDS")?;
        let flags: Vec<&str> = lines[k + 4]["ITEM: BOX BOUNDS".len()..]
            .split_whitespace()
            .collect();
        for a in 0..3 {
            frame.periodic[a] = flags.get(a).is_some_and(|f| f.starts_with('p'));
            let l = lines
                .get(k + 5 + a)
                .ok_or_else(|| bad(path, k + 6 + a, "missing box bound line"))?;
            let v: Vec<&str> = l.split_whitespace().collect();
            if v.len() < 2 {
                return Err(bad(path, k + 6 + a, "a box bound line holds lo and hi"));
            }
            frame.bounds[a] = [number(k + 5 + a, v[0])?, number(k + 5 + a, v[1])?];
        }
        expect(k + 8, "ITEM: ATOMS")?;
        let columns: Vec<&str> = lines[k + 8]["ITEM: ATOMS".len()..]
            .split_whitespace()
            .collect();
        let col = |name: &str| columns.iter().position(|c| *c == name);
        let need = |name: &str| {
            col(name).ok_or_else(|| {
                bad(
                    path,
                    k + 9,
                    format!("the ATOMS columns must include '{name}'"),
                )
            })
        };
        let (ci, cx, cy, cz) = (need("id")?, need("x")?, need("y")?, need("z")?);
        let (radius_col, scale) = match (col("radius"), col("diameter")) {
            (Some(c), _) => (c, 1.0),
            (None, Some(c)) => (c, 0.5),
            _ => {
                return Err(bad(
                    path,
                    k + 9,
                    "the ATOMS columns must include 'radius' or 'diameter'",
                ));
            }
        };
        let ct = col("type");
        let vel = [col("vx"), col("vy"), col("vz")];
        let omg = [col("omegax"), col("omegay"), col("omegaz")];
        let frc = [col("fx"), col("fy"), col("fz")];
        frame.has_force = frc.iter().all(Option::is_some);
        let cm = col("mass");
        let mut rows: Vec<Atom> = Vec::with_capacity(n.min(lines.len()));
        for r in 0..n {
            let at = k + 9 + r;
            let line = lines
                .get(at)
                .ok_or_else(|| bad(path, at + 1, format!("expected {n} atom lines")))?;
            let v: Vec<&str> = line.split_whitespace().collect();
            if v.len() < columns.len() {
                return Err(bad(
                    path,
                    at + 1,
                    format!("expected {} values, found {}", columns.len(), v.len()),
                ));
            }
            let f = |c: usize| number(at, v[c]);
            let opt3 = |cs: [Option<usize>; 3]| -> Result<Vec3> {
                let mut out = Vec3::zeros();
                for (a, c) in cs.iter().enumerate() {
                    if let Some(c) = c {
                        out[a] = f(*c)?;
                    }
                }
                Ok(out)
            };
            let id = v[ci]
                .parse()
                .map_err(|_| bad(path, at + 1, format!("id '{}' is not an integer", v[ci])))?;
            let atom_type = match ct {
                Some(c) => v[c]
                    .parse()
                    .map_err(|_| bad(path, at + 1, format!("type '{}' is not an integer", v[c])))?,
                None => 1,
            };
            rows.push(Atom {
                id,
                atom_type,
                radius: f(radius_col)? * scale,
                position: Vec3::new(f(cx)?, f(cy)?, f(cz)?),
                velocity: opt3(vel)?,
                omega: opt3(omg)?,
                mass: match cm {
                    Some(c) => f(c)?,
                    None => 0.0,
                },
                force: opt3(frc)?,
            });
        }
        // Ranks write their own atoms one after the other, each in its own order.
        rows.sort_by_key(|a| a.id);
        if let Some(w) = rows.windows(2).find(|w| w[0].id == w[1].id) {
            return Err(bad(
                path,
                k + 9,
                format!("atom id {} appears twice in this frame", w[0].id),
            ));
        }
        for a in rows {
            frame.id.push(a.id);
            frame.atom_type.push(a.atom_type);
            frame.radius.push(a.radius);
            frame.position.push(a.position);
            frame.velocity.push(a.velocity);
            frame.omega.push(a.omega);
            frame.mass.push(a.mass);
            frame.force.push(a.force);
        }
        frames.push(frame);
        k += 9 + n;
    }
    if frames.is_empty() {
        return Err(bad(path, 1, "no frames: expected 'ITEM: TIMESTEP'"));
    }
    Ok(frames)
}

#[cfg(test)]
mod tests {
    use super::*;

    const TWO_FRAMES: &str = "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp fm\n0 1\n0 2\n-1 1\nITEM: ATOMS id type radius mass x y z vx vy vz\n2 1 0.1 1 0.5 0.5 0.5 1 0 0\n1 2 0.2 1 0.1 0.1 0.1 0 0 -1\nITEM: TIMESTEP\n10\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS pp pp fm\n0 1\n0 2\n-1 1\nITEM: ATOMS id type diameter x y z\n7 1 0.4 0 0 0\n";

    #[test]
    fn reads_frames_sorted_by_id_with_periodic_axes() {
        let frames = parse(TWO_FRAMES, Path::new("t")).unwrap();
        assert_eq!(frames.len(), 2);
        let f = &frames[0];
        assert_eq!(f.id, vec![1, 2]);
        assert_eq!(f.atom_type, vec![2, 1]);
        assert_eq!(f.radius, vec![0.2, 0.1]);
        assert_eq!(f.velocity[0], Vec3::new(0.0, 0.0, -1.0));
        assert_eq!(f.mass, vec![1.0, 1.0]);
        assert_eq!(frames[1].force, vec![Vec3::zeros()]);
        assert_eq!(f.periodic, [true, true, false]);
        assert_eq!(f.space().periodic[1], Some((0.0, 2.0)));
        assert_eq!(frames[1].step, 10);
        assert_eq!(frames[1].radius, vec![0.2]);
    }

    /// Written by LAMMPS 22 Jul 2025 on 2 MPI ranks (`mpiexec -n 2`, `dump custom`
    /// without `sort id`): rank 0 (x < 2) writes ids 2 and 4, then rank 1 ids 1 and 3.
    const TWO_RANKS: &str = "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n4\nITEM: BOX BOUNDS pp pp ff\n0.0000000000000000e+00 4.0000000000000000e+00\n0.0000000000000000e+00 1.0000000000000000e+00\n0.0000000000000000e+00 1.0000000000000000e+00\nITEM: ATOMS id type radius mass x y z vx vy vz\n2 1 0.25 65.4498 0.5 0.5 0.5 0.1 0 0\n4 1 0.25 65.4498 1.5 0.75 0.25 0.1 0 0\n1 1 0.25 65.4498 3.5 0.5 0.5 0.1 0 0\n3 1 0.25 65.4498 2.5 0.25 0.75 0.1 0 0\n";

    #[test]
    fn a_dump_written_by_two_mpi_ranks_is_read_in_id_order() {
        let f = &parse(TWO_RANKS, Path::new("t")).unwrap()[0];
        assert_eq!(f.id, vec![1, 2, 3, 4]);
        let x: Vec<[f64; 3]> = f.position.iter().map(|p| [p.x, p.y, p.z]).collect();
        assert_eq!(
            x,
            [
                [3.5, 0.5, 0.5],
                [0.5, 0.5, 0.5],
                [2.5, 0.25, 0.75],
                [1.5, 0.75, 0.25]
            ]
        );
        assert_eq!(f.periodic, [true, true, false]);
    }

    #[test]
    fn an_atom_twice_in_a_frame_is_refused() {
        let text = TWO_RANKS.replace("\n3 1 0.25", "\n2 1 0.25");
        let err = parse(&text, Path::new("d")).unwrap_err();
        assert!(err.to_string().contains("atom id 2 appears twice"), "{err}");
        assert_eq!(err.exit_code(), 2);
    }

    #[test]
    fn names_the_line_of_a_bad_value() {
        let text = TWO_FRAMES.replace("0.5 0.5 0.5", "0.5 oops 0.5");
        let err = parse(&text, Path::new("d")).unwrap_err().to_string();
        assert!(err.contains("d:10") && err.contains("'oops'"), "{err}");
        assert_eq!(parse(&text, Path::new("d")).unwrap_err().exit_code(), 2);
    }
}
