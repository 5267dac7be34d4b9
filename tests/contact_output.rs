//! `output.forces` and `output.contacts_every` read back: at every recorded step, the
//! contact forces of contacts/contacts_NNNNNN.csv, plus the weight, add up to each
//! particle's force column in trajectory.csv, and their moments (lever R − δ/2) to its
//! torque column, to round-off; the VTK files parse and carry the same numbers.

mod common;

use serde_json::{Value, json};
use std::collections::BTreeMap;
use std::path::Path;
use vtkio::model::{Attribute, DataSet, Piece};

type V = [f64; 3];

fn cross(a: V, b: V) -> V {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn csv(path: &Path) -> Vec<BTreeMap<String, String>> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    lines
        .map(|l| {
            header
                .iter()
                .zip(l.split(','))
                .map(|(h, v)| (h.to_string(), v.to_string()))
                .collect()
        })
        .collect()
}

fn num(row: &BTreeMap<String, String>, k: &str) -> f64 {
    row[k]
        .parse()
        .unwrap_or_else(|_| panic!("{k} = {:?}", row[k]))
}

fn vec3(row: &BTreeMap<String, String>, k: [&str; 3]) -> V {
    [num(row, k[0]), num(row, k[1]), num(row, k[2])]
}

/// The point or cell data array `name` of the first piece of a legacy VTK file.
fn vtk_array(path: &Path, name: &str, cell: bool) -> Vec<f64> {
    let vtk = vtkio::Vtk::import(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let DataSet::PolyData { pieces, .. } = vtk.data else {
        panic!("not polydata")
    };
    let Piece::Inline(piece) = &pieces[0] else {
        panic!("not inline")
    };
    let list = if cell {
        &piece.data.cell
    } else {
        &piece.data.point
    };
    for a in list {
        if let Attribute::DataArray(d) = a
            && d.name == name
        {
            return d.data.clone().cast_into::<f64>().unwrap();
        }
    }
    panic!("{}: no array {name}", path.display())
}

/// Run `s` with forces, trajectory, contacts and VTK frames every `every` steps, check
/// every recorded step, and return (pair contacts, wall contacts, largest |F_t|) seen.
fn check(mut s: Value, every: u64) -> (usize, usize, f64) {
    s["output"] = json!({"forces": true, "trajectory_every": every, "contacts_every": every,
        "vtk_every": every});
    let ids: Vec<u64> = (1..=s["particles"].as_array().unwrap().len() as u64).collect();
    let (_dir, scene, out) = common::scene_in_tempdir(&s);
    let o = common::run(&scene, &out, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));

    let density = 2500.0;
    let g = [0.0, 0.0, -9.81];
    let trajectory = csv(&out.join("trajectory.csv"));
    let row = |step: u64, id: u64| {
        trajectory
            .iter()
            .find(|r| num(r, "step") == step as f64 && num(r, "id") == id as f64)
            .unwrap_or_else(|| panic!("no trajectory row for step {step}, id {id}"))
    };
    let (mut pairs, mut walls, mut files, mut largest_t) = (0, 0, 0, 0.0f64);
    let mut paths: Vec<_> = std::fs::read_dir(out.join("contacts"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "csv"))
        .collect();
    paths.sort();
    for path in paths {
        files += 1;
        let contacts = csv(&path);
        let step = match contacts.first() {
            Some(c) => num(c, "step") as u64,
            None => continue,
        };
        // Sum each particle's contact forces and moments, as seen from the records.
        let mut force: BTreeMap<u64, V> = BTreeMap::new();
        let mut torque: BTreeMap<u64, V> = BTreeMap::new();
        let mut scale = 0.0f64;
        for c in &contacts {
            let n = vec3(c, ["nx", "ny", "nz"]);
            let t = vec3(c, ["tx", "ty", "tz"]);
            let f_n = num(c, "normal_force");
            let total: V = std::array::from_fn(|k| n[k] * f_n + t[k]);
            let moment = cross(n, t).map(|x| -x);
            let delta = num(c, "overlap");
            let i = num(c, "i") as u64;
            let mut add = |id: u64, sign: f64| {
                let r = num(row(step, id), "radius");
                let lever = r - 0.5 * delta;
                let f = force.entry(id).or_default();
                let m = torque.entry(id).or_default();
                for k in 0..3 {
                    f[k] += sign * total[k];
                    m[k] += moment[k] * lever;
                }
            };
            add(i, 1.0);
            if c["j"].is_empty() {
                walls += 1;
                assert!(!c["wall"].is_empty());
            } else {
                pairs += 1;
                add(c["j"].parse().unwrap(), -1.0);
            }
            scale = scale.max(f_n.abs());
            largest_t = largest_t.max((t[0] * t[0] + t[1] * t[1] + t[2] * t[2]).sqrt());
        }
        for &id in &ids {
            let r = row(step, id);
            let radius = num(r, "radius");
            let weight = g.map(|x| x * density * 4.0 / 3.0 * std::f64::consts::PI * radius.powi(3));
            let sum = force.get(&id).copied().unwrap_or_default();
            let column = vec3(r, ["fx", "fy", "fz"]);
            for k in 0..3 {
                let expected = sum[k] + weight[k];
                assert!(
                    (column[k] - expected).abs() <= 1e-12 * scale.max(weight[2].abs()),
                    "step {step}, particle {id}, axis {k}: force column {} vs contacts + weight {expected}",
                    column[k]
                );
            }
            let moments = torque.get(&id).copied().unwrap_or_default();
            let column = vec3(r, ["tx", "ty", "tz"]);
            for k in 0..3 {
                assert!(
                    (column[k] - moments[k]).abs() <= 1e-12 * scale * radius,
                    "step {step}, particle {id}, axis {k}: torque column {} vs contact moments {}",
                    column[k],
                    moments[k]
                );
            }
        }
        // The VTK lines carry the same contacts and forces.
        let vtk = path.with_extension("vtk");
        let normal = vtk_array(&vtk, "normal_force", true);
        assert_eq!(normal.len(), contacts.len());
        for (v, c) in normal.iter().zip(&contacts) {
            let f_n = num(c, "normal_force");
            assert!((v - f_n).abs() <= 1e-15 * f_n.abs(), "{v} vs {f_n}");
        }
    }
    assert!(files >= 2, "{files} contact files");

    // The particle frames carry the force column as point data.
    let frame = out.join("vtk").join("frame_000001.vtk");
    let f = vtk_array(&frame, "force", false);
    for &id in &ids {
        let column = vec3(row(every, id), ["fx", "fy", "fz"]);
        let k = 3 * (id as usize - 1);
        for a in 0..3 {
            assert!(
                (f[k + a] - column[a]).abs() <= 1e-15 * column[a].abs(),
                "{f:?} vs {column:?}"
            );
        }
    }
    assert_eq!(vtk_array(&frame, "torque", false).len(), 3 * ids.len());
    (pairs, walls, largest_t)
}

#[test]
fn contact_forces_add_up_to_the_force_and_torque_columns() {
    let base = common::base();
    // Two glass spheres with friction and rotation, one straight above the other,
    // dropped on a floor: they land and rest stacked, so pairs and wall contacts both
    // carry load at the recorded steps.
    let mut stacked = base.clone();
    stacked["particles"][1]["position"] = json!([0.0, 0.0, 0.0045]);
    stacked["run"] = json!({"duration": 0.1});
    let (pairs, walls, _) = check(stacked, 5000);
    assert!(pairs > 0 && walls > 0, "pairs {pairs}, walls {walls}");
    // One sphere launched along the floor slides for about 2v/(7μg) = 3.6 ms: friction
    // then loads the tangential force and the torque columns.
    let mut sliding = base;
    sliding["particles"] = json!([{"position": [0, 0, 0.001], "radius": 0.001,
        "material": "glass", "velocity": [0.05, 0, 0]}]);
    sliding["run"] = json!({"duration": 0.003});
    let (_, walls, largest_t) = check(sliding, 50);
    assert!(
        walls > 0 && largest_t > 1e-6,
        "walls {walls}, |F_t| {largest_t:e}"
    );
}

/// `output.walls`: at every step of trajectory.csv, walls.csv gives each wall's
/// displacement (the lid's, a known function of time) and the force the particles
/// exert on it. Pair forces cancel, so by Newton's third law the walls' forces add up to
/// minus the particles' total force less their weight, to round-off.
#[test]
fn wall_forces_balance_the_particles_forces_at_every_recorded_step() {
    let mut s = common::base();
    s["walls"].as_array_mut().unwrap().push(json!({
        "name": "lid", "material": "glass",
        "shape": {"kind": "plane", "point": [0, 0, 0.0062], "normal": [0, 0, -1]},
        "motion": {"kind": "velocity", "velocity": [0, 0, -0.01]}
    }));
    s["run"] = json!({"duration": 0.05});
    s["output"] = json!({"forces": true, "trajectory_every": 500, "walls": true});
    let (_dir, scene, out) = common::scene_in_tempdir(&s);
    let o = common::run(&scene, &out, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let summary: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let dt = summary["provenance"]["dt"].as_f64().unwrap();
    let trajectory = csv(&out.join("trajectory.csv"));
    let walls = csv(&out.join("walls.csv"));
    let steps: std::collections::BTreeSet<u64> = trajectory
        .iter()
        .map(|r| r["step"].parse().unwrap())
        .collect();
    assert_eq!(
        walls.len(),
        2 * steps.len(),
        "a row per wall and recorded step"
    );
    let glass = 2500.0 * 4.0 / 3.0 * std::f64::consts::PI * 1e-9;
    let mut touched = 0;
    for &step in &steps {
        let at = |rows: &[BTreeMap<String, String>]| -> Vec<BTreeMap<String, String>> {
            rows.iter()
                .filter(|r| r["step"] == step.to_string())
                .cloned()
                .collect()
        };
        let (bodies, walls_now) = (at(&trajectory), at(&walls));
        let mut net = [0.0; 3];
        for b in &bodies {
            let f = vec3(b, ["fx", "fy", "fz"]);
            net = [net[0] + f[0], net[1] + f[1], net[2] + f[2] + 9.81 * glass];
        }
        let mut on_walls = [0.0; 3];
        for (k, w) in walls_now.iter().enumerate() {
            assert_eq!(w["wall"], (k + 1).to_string());
            let f = vec3(w, ["fx", "fy", "fz"]);
            on_walls = [on_walls[0] + f[0], on_walls[1] + f[1], on_walls[2] + f[2]];
        }
        let scale = 9.81 * glass;
        for a in 0..3 {
            assert!(
                (net[a] + on_walls[a]).abs() <= 1e-9 * scale,
                "step {step}, axis {a}: particles {net:?}, walls {on_walls:?}"
            );
        }
        touched += usize::from(on_walls[2].abs() > 0.1 * scale);
        let lid = vec3(&walls_now[1], ["dx", "dy", "dz"]);
        assert_eq!(lid[..2], [0.0, 0.0]);
        let expected = -0.01 * step as f64 * dt;
        assert!(
            (lid[2] - expected).abs() <= 1e-12 * expected.abs().max(1e-12),
            "step {step}: {lid:?}"
        );
    }
    assert!(touched >= 2, "the check needs steps with the floor loaded");
}
