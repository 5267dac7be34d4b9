//! `broad_phase.sort`: particles renumbered by cell for memory locality keep their ids.
//! The sorted run is the same motion as the unsorted one, particle by particle (by id),
//! up to the round-off of summing each particle's contact forces in another order;
//! every output names particles by id.

mod common;

use serde_json::{Value, json};
use std::collections::BTreeMap;
use tamp::simulation::Simulation;

/// 400 spheres deposited ballistically (created in the order they were dropped, not
/// by place) on a floor, with friction and rotation: every sphere in contact from
/// the start. Only 40 steps, because a packing is chaotic: two runs that differ at
/// round-off part exponentially (after 0.04 s of a pour, by tens of radii).
fn bed(sort: bool) -> Value {
    json!({
        "seed": 3,
        "materials": [{"name": "glass", "density": 2500, "youngs_modulus": 1e7, "poisson_ratio": 0.25}],
        "contact": {
            "normal": {"law": "hertz"},
            "damping": {"kind": "critical_fraction", "xi": 0.3},
            "tangential": {"law": "mindlin_deresiewicz", "friction": 0.5}
        },
        "deposit": [{"count": 400, "material": "glass", "radius": {"min": 4e-4, "max": 5e-4},
                     "footprint": [[0, 0], [0.01, 0.01]], "floor": 0.0}],
        "walls": [{"name": "floor", "material": "glass",
                   "shape": {"kind": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}}],
        "periodic": {"x": [0, 0.01], "y": [0, 0.01]},
        "gravity": [0, 0, -9.81],
        "rotation": {},
        "broad_phase": {"sort": sort},
        "time_step": {"alpha": 0.2, "characteristic_velocity": 0.5},
        "run": {"steps": 40}
    })
}

fn built(sort: bool) -> (Simulation, u64) {
    let b = common::built(&bed(sort));
    (b.sim, b.steps)
}

#[test]
fn sorting_renumbers_the_storage_but_not_the_ids_or_the_motion() {
    let (mut plain, steps) = built(false);
    let (mut sorted, _) = built(true);
    let n = plain.state().particles.len();
    assert_eq!(
        plain.state().particles.id,
        (1..=n as u64).collect::<Vec<_>>()
    );
    // Sorted: a permutation of the same ids, no longer in id order, and stored by
    // z-layer (the slowest key of the cell order).
    let mut ids = sorted.state().particles.id.clone();
    assert_ne!(
        ids,
        plain.state().particles.id,
        "the sort must reorder a deposited bed"
    );
    ids.sort_unstable();
    assert_eq!(ids, plain.state().particles.id);
    let z: Vec<f64> = sorted
        .state()
        .particles
        .position
        .iter()
        .map(|x| x.z)
        .collect();
    let r = &sorted.state().particles.radius;
    let (r_min, r_max) = r
        .iter()
        .fold((1.0f64, 0.0f64), |(a, b), &x| (a.min(x), b.max(x)));
    let (edge, lowest) = (
        2.0 * r_max + 0.2 * r_min,
        z.iter().cloned().fold(1.0, f64::min),
    );
    let layer = |z: f64| ((z - lowest) / edge).floor();
    assert!(z.windows(2).all(|w| layer(w[0]) <= layer(w[1])));
    // The same bed, particle for particle.
    let by_id = |s: &Simulation| -> BTreeMap<u64, usize> {
        s.state()
            .particles
            .id
            .iter()
            .enumerate()
            .map(|(k, &id)| (id, k))
            .collect()
    };
    let at = by_id(&sorted);
    for i in 0..n {
        let k = at[&plain.state().particles.id[i]];
        assert_eq!(
            plain.state().particles.position[i],
            sorted.state().particles.position[k]
        );
        assert_eq!(
            plain.state().particles.radius[i],
            sorted.state().particles.radius[k]
        );
    }
    plain.run_with(steps, |_| {}).expect("stable");
    sorted.run_with(steps, |_| {}).expect("stable");
    let contacts = plain.state().neighbors.pairs.len();
    assert!(
        contacts > n,
        "the bed must be in contact to test anything ({contacts} pairs)"
    );
    // The two runs sum forces in another order, so they part at round-off, and the
    // gap grows by a factor e every 3–4 steps in this bed (measured: 0 after 10 steps,
    // 4e-15 R after 20, 1.5e-11 R after 50). After 40 steps 1e-9 R bounds that growth
    // and is far below what a mistake in the renumbering makes (a radius or more).
    let at = by_id(&sorted);
    let mut worst = 0.0f64;
    for i in 0..n {
        let k = at[&plain.state().particles.id[i]];
        let dx =
            (plain.state().particles.position[i] - sorted.state().particles.position[k]).norm();
        worst = worst.max(dx / plain.state().particles.radius[i]);
    }
    assert!(worst <= 1e-9, "positions differ by up to {worst:e} R");
}

/// `tamp run` of the bed, sorted or not: its trajectory.csv rows at step 0.
fn first_rows(sort: bool) -> Vec<String> {
    let mut s = bed(sort);
    s["run"] = json!({"steps": 1});
    s["output"] = json!({"trajectory_every": 1});
    let (_dir, scene, out) = common::scene_in_tempdir(&s);
    let o = common::run(&scene, &out, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
    text.lines()
        .filter(|l| l.starts_with("0,"))
        .map(String::from)
        .collect()
}

#[test]
fn trajectory_rows_carry_the_scene_ids_in_a_sorted_run() {
    let (plain, mut sorted) = (first_rows(false), first_rows(true));
    assert_eq!(plain.len(), 400);
    assert_ne!(
        plain, sorted,
        "the sorted run lists particles in storage order"
    );
    // Step 0 is before any force: the same row for every id, bit for bit.
    sorted.sort_by_key(|row| row.split(',').nth(1).unwrap().parse::<u64>().unwrap());
    assert_eq!(plain, sorted);
}
