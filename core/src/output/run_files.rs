//! The two text files every run writes and `tamp compare` reads back, so that tamp's runs
//! and the peers' imported dumps are compared in one layout (docs/compare.md):
//! `quantities.csv` (`quantity,value` rows) and `trajectory.csv` (one row per particle and
//! recorded step, full precision).

use super::Sci;
use crate::particles::Vec3;
use std::fmt::Write as _;

/// `quantities.csv` text: a header and one `quantity,value` row each.
pub fn quantities_csv(quantities: &[(String, f64)]) -> String {
    let mut s = String::from("quantity,value\n");
    for (q, v) in quantities {
        let _ = writeln!(s, "{q},{}", Sci(*v));
    }
    s
}

/// Header of `trajectory.csv`.
pub const TRAJECTORY_HEADER: &str = "step,id,radius,x,y,z,vx,vy,vz,omegax,omegay,omegaz";
/// The columns `output.forces` appends: the particle's total force (contacts, walls and
/// gravity) and torque at that step. `tamp compare` reads columns by name and ignores them.
pub const TRAJECTORY_FORCE_COLUMNS: &str = ",fx,fy,fz,tx,ty,tz";

/// Header of `walls.csv`: per recorded step and wall (`wall` = k + 1 for the scene's
/// `walls[k]`), its displacement from where the scene puts it and the force the
/// particles exert on it.
pub const WALLS_HEADER: &str = "step,wall,dx,dy,dz,fx,fy,fz";

/// One `walls.csv` row; full precision.
pub fn walls_row(out: &mut String, step: u64, wall: usize, displacement: &Vec3, force: &Vec3) {
    let (d, f) = (displacement, force);
    let _ = writeln!(
        out,
        "{step},{wall},{},{},{},{},{},{}",
        Sci(d.x),
        Sci(d.y),
        Sci(d.z),
        Sci(f.x),
        Sci(f.y),
        Sci(f.z)
    );
}

/// One `trajectory.csv` row; full precision (Rust's shortest round-trip form).
pub fn trajectory_row(out: &mut String, step: u64, id: u64, r: f64, x: &Vec3, v: &Vec3, w: &Vec3) {
    let _ = writeln!(
        out,
        "{step},{id},{},{},{},{},{},{},{},{},{},{}",
        Sci(r),
        Sci(x.x),
        Sci(x.y),
        Sci(x.z),
        Sci(v.x),
        Sci(v.y),
        Sci(v.z),
        Sci(w.x),
        Sci(w.y),
        Sci(w.z)
    );
}
