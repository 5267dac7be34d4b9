//! `tamp compare A B [--tolerances FILE]`: two runs, quantity by quantity and
//! trajectory by trajectory, B being the reference. The run layout any code can
//! emit is documented in docs/compare.md:
//!
//! - `quantities.csv`: header `quantity,value`, one scalar per row;
//! - `trajectory.csv`: header `step,id,radius,x,y,z,vx,vy,vz,omegax,omegay,omegaz`
//!   (velocities and spins may be left out), one row per particle per step;
//! - or a LIGGGHTS/LAMMPS `dump custom` file, read as a trajectory.
//!
//! A run is a directory holding either or both files (`tamp run` writes them; a
//! directory of an exported deck, with only `dump.liggghts` or `final.liggghts`
//! (LIGGGHTS) or `dump.lammps` or `final.lammps` (LAMMPS), is read as a trajectory),
//! or one file of any of the three kinds.
//!
//! Deviations, each against its tolerance:
//! - a quantity: |a − b|/|b| (relative, the default) or |a − b| (absolute);
//! - `position`: max over steps and particles of |x_a − x_b| / R, R the particle
//!   radius: the displacement measured in the particle's own size, so particles near
//!   the origin are judged like all others;
//! - `velocity`, `omega`: max of |v_a − v_b| / V, V the largest |v_b| of that
//!   particle over the compared steps (the speed it actually reached).
//!
//! Steps and ids present in only one run are reported; they fail the comparison
//! only when nothing is left to compare.

use crate::error::{Result, TampError};
use crate::particles::Vec3;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

/// Default tolerances: quantities must agree to 1e-9 relative, trajectories to 1e-6.
pub const DEFAULT_QUANTITY_TOLERANCE: f64 = 1e-9;
pub const DEFAULT_TRAJECTORY_TOLERANCE: f64 = 1e-6;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct State {
    pub radius: f64,
    pub position: Vec3,
    pub velocity: Option<Vec3>,
    pub omega: Option<Vec3>,
    /// The particle's total force (`fx fy fz`), when the file has it; not compared.
    pub force: Option<Vec3>,
}

/// What a run provides.
#[derive(Clone, Debug, Default)]
pub struct Run {
    pub quantities: BTreeMap<String, f64>,
    /// (step, id) → state.
    pub trajectory: BTreeMap<(u64, u64), State>,
}

impl Run {
    /// Add the simulation's present state to the trajectory (ids = index + 1).
    pub fn record(&mut self, sim: &crate::simulation::Simulation) {
        let p = &sim.state().particles;
        for i in 0..p.len() {
            self.trajectory.insert(
                (sim.state().step, i as u64 + 1),
                State {
                    radius: p.radius[i],
                    position: p.position[i],
                    velocity: Some(p.velocity[i]),
                    omega: Some(p.omega[i]),
                    force: Some(p.force[i]),
                },
            );
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Relative,
    Absolute,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Tolerance {
    pub value: f64,
    pub kind: Kind,
}

/// One compared item.
#[derive(Clone, Debug)]
pub struct Deviation {
    pub name: String,
    pub a: f64,
    pub b: f64,
    pub deviation: f64,
    pub tolerance: Tolerance,
    /// Where the largest deviation of a trajectory item was found.
    pub at: String,
}

impl Deviation {
    pub fn passes(&self) -> bool {
        self.deviation <= self.tolerance.value
    }
}

#[derive(Debug, Default)]
pub struct Comparison {
    pub deviations: Vec<Deviation>,
    pub notes: Vec<String>,
}

impl Comparison {
    pub fn passes(&self) -> bool {
        !self.deviations.is_empty() && self.deviations.iter().all(Deviation::passes)
    }

    /// The report: every item, the worst (by deviation/tolerance) first.
    pub fn report(&self) -> String {
        let mut rows: Vec<&Deviation> = self.deviations.iter().collect();
        rows.sort_by(|x, y| {
            (y.deviation / y.tolerance.value).total_cmp(&(x.deviation / x.tolerance.value))
        });
        let mut s = String::from("item | A | B | deviation | tolerance | status | where\n");
        for d in rows {
            let _ = writeln!(
                s,
                "{} | {:.10e} | {:.10e} | {:.3e} | {:e} {} | {} | {}",
                d.name,
                d.a,
                d.b,
                d.deviation,
                d.tolerance.value,
                match d.tolerance.kind {
                    Kind::Relative => "rel",
                    Kind::Absolute => "abs",
                },
                if d.passes() { "pass" } else { "FAIL" },
                d.at
            );
        }
        for n in &self.notes {
            let _ = writeln!(s, "note: {n}");
        }
        s
    }
}

fn input_err(path: &Path, rule: impl Into<String>) -> TampError {
    TampError::input(path.display().to_string(), rule)
}

fn csv_reader(path: &Path) -> Result<csv::Reader<std::fs::File>> {
    csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .from_path(path)
        .map_err(|e| input_err(path, e.to_string()))
}

fn read_quantities(path: &Path) -> Result<BTreeMap<String, f64>> {
    let mut reader = csv_reader(path)?;
    let headers = reader
        .headers()
        .map_err(|e| input_err(path, e.to_string()))?
        .clone();
    let (Some(q), Some(v)) = (
        headers.iter().position(|h| h == "quantity"),
        headers.iter().position(|h| h == "value"),
    ) else {
        return Err(input_err(
            path,
            "a quantities file needs the columns 'quantity' and 'value'",
        ));
    };
    let mut out = BTreeMap::new();
    for (k, rec) in reader.records().enumerate() {
        let row = k + 2;
        let rec = rec.map_err(|e| input_err(path, format!("row {row}: {e}")))?;
        let (Some(name), Some(text)) = (rec.get(q), rec.get(v)) else {
            return Err(input_err(
                path,
                format!("row {row}: fewer values than columns"),
            ));
        };
        let value = match text.parse::<f64>() {
            Ok(x) if x.is_finite() => x,
            _ => {
                return Err(input_err(
                    path,
                    format!("row {row}, column 'value': '{text}' is not a number (a finite one)"),
                ));
            }
        };
        if out.insert(name.to_string(), value).is_some() {
            return Err(input_err(
                path,
                format!("row {row}: the quantity '{name}' was given before"),
            ));
        }
    }
    Ok(out)
}

/// The rows of a trajectory.csv, keyed by (step, id). Written by any program, so
/// read as untrusted: a missing required column, a value that is not a finite number
/// and a (step, id) given twice are each refused naming the row and the column.
pub fn read_trajectory(path: &Path) -> Result<BTreeMap<(u64, u64), State>> {
    let mut table = Table::open(path, "a trajectory file")?;
    let (cs, ci, cr) = (
        table.need("step")?,
        table.need("id")?,
        table.need("radius")?,
    );
    let cx = [table.need("x")?, table.need("y")?, table.need("z")?];
    let [cv, cw, cf] = [
        ["vx", "vy", "vz"],
        ["omegax", "omegay", "omegaz"],
        ["fx", "fy", "fz"],
    ]
    .map(|names| names.map(|n| table.col(n)));
    let mut out = BTreeMap::new();
    table.rows(|row| {
        let key = (row.int(cs)?, row.int(ci)?);
        let state = State {
            radius: row.num(cr)?,
            position: row.vec(cx)?,
            velocity: row.optional_vec(cv)?,
            omega: row.optional_vec(cw)?,
            force: row.optional_vec(cf)?,
        };
        match out.insert(key, state) {
            None => Ok(()),
            Some(_) => Err(row.error(format!(
                "step {} and id {} were given before (one row per particle and step)",
                key.0, key.1
            ))),
        }
    })?;
    Ok(out)
}

/// One wall at one step of walls.csv: its displacement from where the scene puts it
/// and the force the particles exert on it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WallRow {
    pub displacement: Vec3,
    pub force: Vec3,
}

/// The rows of a walls.csv (`step,wall,dx,dy,dz,fx,fy,fz`), keyed by (step, wall), read
/// as untrusted like a trajectory.
pub fn read_walls(path: &Path) -> Result<BTreeMap<(u64, u64), WallRow>> {
    let mut table = Table::open(path, "a walls file")?;
    let (cs, cw) = (table.need("step")?, table.need("wall")?);
    let cd = [table.need("dx")?, table.need("dy")?, table.need("dz")?];
    let cf = [table.need("fx")?, table.need("fy")?, table.need("fz")?];
    let mut out = BTreeMap::new();
    table.rows(|row| {
        let key = (row.int(cs)?, row.int(cw)?);
        let wall = WallRow {
            displacement: row.vec(cd)?,
            force: row.vec(cf)?,
        };
        match out.insert(key, wall) {
            None => Ok(()),
            Some(_) => Err(row.error(format!(
                "step {} and wall {} were given before (one row per wall and step)",
                key.0, key.1
            ))),
        }
    })?;
    Ok(out)
}

/// A CSV file read by column name, every cell checked: a missing column, a value that
/// is not a finite number or not a non-negative integer is refused naming the row and
/// the column.
struct Table<'p> {
    path: &'p Path,
    what: &'static str,
    reader: csv::Reader<std::fs::File>,
    headers: csv::StringRecord,
}

/// One row of a `Table`: its line number and its cells.
struct TableRow<'t> {
    path: &'t Path,
    headers: &'t csv::StringRecord,
    row: usize,
    record: csv::StringRecord,
}

impl<'p> Table<'p> {
    fn open(path: &'p Path, what: &'static str) -> Result<Self> {
        let mut reader = csv_reader(path)?;
        let headers = reader
            .headers()
            .map_err(|e| input_err(path, e.to_string()))?
            .clone();
        Ok(Table {
            path,
            what,
            reader,
            headers,
        })
    }

    fn col(&self, name: &str) -> Option<usize> {
        self.headers.iter().position(|h| h == name)
    }

    fn need(&self, name: &str) -> Result<usize> {
        self.col(name).ok_or_else(|| {
            input_err(
                self.path,
                format!("{} needs the column '{name}'", self.what),
            )
        })
    }

    /// Call `each` on every row, stopping at the first error.
    fn rows(&mut self, mut each: impl FnMut(&TableRow) -> Result<()>) -> Result<()> {
        for (k, record) in self.reader.records().enumerate() {
            let row = k + 2;
            let record = record.map_err(|e| input_err(self.path, format!("row {row}: {e}")))?;
            each(&TableRow {
                path: self.path,
                headers: &self.headers,
                row,
                record,
            })?;
        }
        Ok(())
    }
}

impl TableRow<'_> {
    fn error(&self, rule: String) -> TampError {
        input_err(self.path, format!("row {}: {rule}", self.row))
    }

    fn cell(&self, c: usize) -> Result<&str> {
        self.record
            .get(c)
            .ok_or_else(|| self.error(format!("no value in column '{}'", &self.headers[c])))
    }

    fn num(&self, c: usize) -> Result<f64> {
        let text = self.cell(c)?;
        match text.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(input_err(
                self.path,
                format!(
                    "row {}, column '{}': '{text}' is not a finite number",
                    self.row, &self.headers[c]
                ),
            )),
        }
    }

    fn int(&self, c: usize) -> Result<u64> {
        let text = self.cell(c)?;
        text.parse().map_err(|_| {
            input_err(
                self.path,
                format!(
                    "row {}, column '{}': '{text}' is not a non-negative integer",
                    self.row, &self.headers[c]
                ),
            )
        })
    }

    fn vec(&self, c: [usize; 3]) -> Result<Vec3> {
        Ok(Vec3::new(self.num(c[0])?, self.num(c[1])?, self.num(c[2])?))
    }

    /// A vector whose three columns are all present, else none.
    fn optional_vec(&self, c: [Option<usize>; 3]) -> Result<Option<Vec3>> {
        match c {
            [Some(a), Some(b), Some(c)] => self.vec([a, b, c]).map(Some),
            _ => Ok(None),
        }
    }
}

/// The frames of a LIGGGHTS or LAMMPS dump, keyed by (step, id).
pub fn dump_trajectory(path: &Path) -> Result<BTreeMap<(u64, u64), State>> {
    let mut out = BTreeMap::new();
    for f in crate::liggghts::dump::read(path)? {
        for k in 0..f.id.len() {
            out.insert(
                (f.step, f.id[k]),
                State {
                    radius: f.radius[k],
                    position: f.position[k],
                    velocity: Some(f.velocity[k]),
                    omega: Some(f.omega[k]),
                    force: f.has_force.then(|| f.force[k]),
                },
            );
        }
    }
    Ok(out)
}

fn first_line(path: &Path) -> Result<String> {
    use std::io::BufRead;
    let file = std::fs::File::open(path)
        .map_err(|e| TampError::io(format!("opening {}", path.display()), e))?;
    let mut line = String::new();
    std::io::BufReader::new(file)
        .read_line(&mut line)
        .map_err(|e| TampError::io(format!("reading {}", path.display()), e))?;
    Ok(line.trim().to_string())
}

/// The dumps a deck of `tamp export-liggghts` or `export-lammps` writes, the
/// trajectory first.
const DECK_DUMPS: [&str; 4] = [
    "dump.liggghts",
    "final.liggghts",
    "dump.lammps",
    "final.lammps",
];

/// Load a run from a directory or a file (see the module comment).
pub fn load(path: &Path) -> Result<Run> {
    let mut run = Run::default();
    if path.is_dir() {
        let q = path.join("quantities.csv");
        let t = path.join("trajectory.csv");
        if q.exists() {
            run.quantities = read_quantities(&q)?;
        }
        if t.exists() {
            run.trajectory = read_trajectory(&t)?;
        } else {
            // The dump an exported deck writes every few steps, else its final state.
            for dump in DECK_DUMPS {
                if path.join(dump).exists() {
                    run.trajectory = dump_trajectory(&path.join(dump))?;
                    break;
                }
            }
        }
        if run.quantities.is_empty() && run.trajectory.is_empty() {
            return Err(input_err(
                path,
                "holds none of quantities.csv, trajectory.csv, dump.liggghts, final.liggghts, dump.lammps, final.lammps (docs/compare.md)",
            ));
        }
        return Ok(run);
    }
    let head = first_line(path)?;
    if head.starts_with("ITEM: TIMESTEP") {
        run.trajectory = dump_trajectory(path)?;
    } else if head.starts_with("quantity") {
        run.quantities = read_quantities(path)?;
    } else if head.starts_with("step") {
        run.trajectory = read_trajectory(path)?;
    } else {
        return Err(input_err(
            path,
            "is neither a LIGGGHTS dump, a quantities.csv nor a trajectory.csv (docs/compare.md)",
        ));
    }
    Ok(run)
}

/// Tolerances CSV: `item,tolerance,kind` with kind `relative` or `absolute`; items
/// are quantity names or `position`, `velocity`, `omega`.
pub fn read_tolerances(path: &Path) -> Result<BTreeMap<String, Tolerance>> {
    let mut reader = csv_reader(path)?;
    let mut out = BTreeMap::new();
    for (k, rec) in reader.records().enumerate() {
        let rec = rec.map_err(|e| input_err(path, e.to_string()))?;
        let row = k + 2;
        if rec.len() < 3 {
            return Err(input_err(
                path,
                format!("row {row}: expected item,tolerance,kind"),
            ));
        }
        let value: f64 = rec[1]
            .parse()
            .ok()
            .filter(|v: &f64| *v >= 0.0 && v.is_finite())
            .ok_or_else(|| {
                input_err(
                    path,
                    format!(
                        "row {row}: tolerance '{}' must be a finite number >= 0",
                        &rec[1]
                    ),
                )
            })?;
        let kind = match &rec[2] {
            "relative" => Kind::Relative,
            "absolute" => Kind::Absolute,
            other => {
                return Err(input_err(
                    path,
                    format!("row {row}: kind '{other}' must be 'relative' or 'absolute'"),
                ));
            }
        };
        out.insert(rec[0].to_string(), Tolerance { value, kind });
    }
    Ok(out)
}

/// Compare run `a` against the reference `b`.
pub fn compare(a: &Run, b: &Run, tolerances: &BTreeMap<String, Tolerance>) -> Comparison {
    let mut out = Comparison::default();
    let tol = |name: &str, default: f64| {
        tolerances.get(name).cloned().unwrap_or(Tolerance {
            value: default,
            kind: Kind::Relative,
        })
    };
    let only = |x: &Run, y: &Run| -> Vec<String> {
        x.quantities
            .keys()
            .filter(|n| !y.quantities.contains_key(*n))
            .cloned()
            .collect()
    };
    for (side, names) in [("A", only(a, b)), ("B", only(b, a))] {
        if !names.is_empty() {
            out.notes.push(format!(
                "quantities only in {side} (not compared): {}",
                names.join(", ")
            ));
        }
    }
    for (name, &vb) in &b.quantities {
        let Some(&va) = a.quantities.get(name) else {
            continue;
        };
        let t = tol(name, DEFAULT_QUANTITY_TOLERANCE);
        let deviation = match t.kind {
            Kind::Absolute => (va - vb).abs(),
            // A zero reference admits only an exact zero.
            Kind::Relative if vb == 0.0 => f64::INFINITY,
            Kind::Relative => ((va - vb) / vb).abs(),
        };
        out.deviations.push(Deviation {
            name: name.clone(),
            a: va,
            b: vb,
            deviation: if va == vb { 0.0 } else { deviation },
            tolerance: t,
            at: String::new(),
        });
    }
    if !a.trajectory.is_empty() || !b.trajectory.is_empty() {
        compare_trajectories(a, b, &tol, &mut out);
    }
    out
}

fn compare_trajectories(
    a: &Run,
    b: &Run,
    tol: &dyn Fn(&str, f64) -> Tolerance,
    out: &mut Comparison,
) {
    // Per-particle speed scales of the reference.
    let mut v_scale: BTreeMap<u64, f64> = BTreeMap::new();
    let mut w_scale: BTreeMap<u64, f64> = BTreeMap::new();
    for ((_, id), s) in &b.trajectory {
        if let Some(v) = s.velocity {
            let e = v_scale.entry(*id).or_default();
            *e = e.max(v.norm());
        }
        if let Some(w) = s.omega {
            let e = w_scale.entry(*id).or_default();
            *e = e.max(w.norm());
        }
    }
    // (deviation, a, b, where) per item.
    let mut worst: BTreeMap<&str, (f64, f64, f64, String)> = BTreeMap::new();
    let mut record = |item: &'static str, dev: f64, va: f64, vb: f64, at: &dyn Fn() -> String| {
        let e = worst.entry(item).or_insert((-1.0, 0.0, 0.0, String::new()));
        if dev > e.0 || dev.is_nan() {
            *e = (dev, va, vb, at());
        }
    };
    let mut matched = 0usize;
    for (&(step, id), sb) in &b.trajectory {
        let Some(sa) = a.trajectory.get(&(step, id)) else {
            continue;
        };
        matched += 1;
        let at = || format!("step {step}, id {id}");
        let dx = (sa.position - sb.position).norm();
        record(
            "position",
            dx / sb.radius,
            sa.position.norm(),
            sb.position.norm(),
            &at,
        );
        if let (Some(va), Some(vb)) = (sa.velocity, sb.velocity) {
            let scale = v_scale[&id];
            let d = (va - vb).norm();
            record(
                "velocity",
                if d == 0.0 { 0.0 } else { d / scale },
                va.norm(),
                vb.norm(),
                &at,
            );
        }
        if let (Some(wa), Some(wb)) = (sa.omega, sb.omega) {
            let scale = w_scale[&id];
            let d = (wa - wb).norm();
            record(
                "omega",
                if d == 0.0 { 0.0 } else { d / scale },
                wa.norm(),
                wb.norm(),
                &at,
            );
        }
    }
    let only = |x: &Run, y: &Run| {
        x.trajectory
            .keys()
            .filter(|k| !y.trajectory.contains_key(k))
            .count()
    };
    let (only_a, only_b) = (only(a, b), only(b, a));
    if only_a + only_b > 0 {
        out.notes.push(format!(
            "trajectory rows (step, id) only in A: {only_a}, only in B: {only_b}; {matched} compared"
        ));
    }
    if matched == 0 {
        out.notes
            .push("no (step, id) in common: the trajectories were not compared".into());
        out.deviations.push(Deviation {
            name: "trajectory rows in common".into(),
            a: a.trajectory.len() as f64,
            b: b.trajectory.len() as f64,
            deviation: f64::INFINITY,
            tolerance: Tolerance {
                value: 0.0,
                kind: Kind::Absolute,
            },
            at: String::new(),
        });
        return;
    }
    for (item, (dev, va, vb, at)) in worst {
        out.deviations.push(Deviation {
            name: item.to_string(),
            a: va,
            b: vb,
            deviation: dev,
            tolerance: tol(item, DEFAULT_TRAJECTORY_TOLERANCE),
            at,
        });
    }
}

/// The CLI: load, compare, print; 0 within tolerance, 1 beyond.
pub fn run_cli(a: &Path, b: &Path, tolerances: Option<&Path>) -> Result<u8> {
    let tolerances = match tolerances {
        Some(p) => read_tolerances(p)?,
        None => BTreeMap::new(),
    };
    let (ra, rb) = (load(a)?, load(b)?);
    let comparison = compare(&ra, &rb, &tolerances);
    println!("A = {}\nB = {} (reference)", a.display(), b.display());
    print!("{}", comparison.report());
    Ok(if comparison.passes() { 0 } else { 1 })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_walls_file_is_read_as_untrusted_input() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("walls.csv");
        let read = |text: &str| {
            std::fs::write(&path, text).unwrap();
            read_walls(&path).map_err(|e| e.to_string())
        };
        let rows = read("step,wall,dx,dy,dz,fx,fy,fz\n0,1,0,0,-1e-6,0,0,2.5\n").unwrap();
        assert_eq!(rows[&(0, 1)].displacement.z, -1e-6);
        assert_eq!(rows[&(0, 1)].force.z, 2.5);
        for (text, expected) in [
            ("step,wall,dx,dy,dz,fx,fy\n", "needs the column 'fz'"),
            (
                "step,wall,dx,dy,dz,fx,fy,fz\n0,1,0,0,0,0,0,inf\n",
                "row 2, column 'fz': 'inf'",
            ),
            (
                "step,wall,dx,dy,dz,fx,fy,fz\n0,-1,0,0,0,0,0,0\n",
                "column 'wall': '-1'",
            ),
            (
                "step,wall,dx,dy,dz,fx,fy,fz\n0,1,0,0,0,0,0,0\n0,1,0,0,0,0,0,0\n",
                "row 3: step 0 and wall 1 were given before",
            ),
        ] {
            let e = read(text).unwrap_err();
            assert!(e.contains(expected), "{text:?}: {e}");
        }
    }

    fn run_with(x: f64) -> Run {
        let mut r = Run::default();
        r.quantities.insert("packing_fraction".into(), 0.6 + x);
        r.trajectory.insert(
            (0, 1),
            State {
                radius: 0.5,
                position: Vec3::new(1.0 + x, 0.0, 0.0),
                velocity: Some(Vec3::new(2.0, 0.0, 0.0)),
                omega: None,
                force: None,
            },
        );
        r
    }

    #[test]
    fn identical_runs_pass_and_deviations_are_measured_in_radii() {
        let c = compare(&run_with(0.0), &run_with(0.0), &BTreeMap::new());
        assert!(c.passes(), "{}", c.report());
        let c = compare(&run_with(1e-3), &run_with(0.0), &BTreeMap::new());
        assert!(!c.passes());
        let pos = c.deviations.iter().find(|d| d.name == "position").unwrap();
        assert!((pos.deviation - 2e-3).abs() < 1e-12, "{}", pos.deviation);
        let q = c
            .deviations
            .iter()
            .find(|d| d.name == "packing_fraction")
            .unwrap();
        assert!((q.deviation - 1e-3 / 0.6).abs() < 1e-12);
    }

    #[test]
    fn a_tolerance_file_loosens_one_item() {
        let mut t = BTreeMap::new();
        t.insert(
            "position".to_string(),
            Tolerance {
                value: 1e-2,
                kind: Kind::Relative,
            },
        );
        t.insert(
            "packing_fraction".to_string(),
            Tolerance {
                value: 2e-3,
                kind: Kind::Absolute,
            },
        );
        let c = compare(&run_with(1e-3), &run_with(0.0), &t);
        assert!(c.passes(), "{}", c.report());
    }

    #[test]
    fn nothing_in_common_fails() {
        let mut b = run_with(0.0);
        b.quantities.clear();
        b.trajectory = BTreeMap::from([((5, 9), b.trajectory[&(0, 1)])]);
        let mut a = run_with(0.0);
        a.quantities.clear();
        assert!(!compare(&a, &b, &BTreeMap::new()).passes());
    }
}
