//! Effects on demand: the cost of one time step with the scene's effects switched on
//! one at a time. A scene pays only for what it enables.
//!
//! Two groups, because a bed needs gravity and a floor to stay a bed:
//! - `bed_2000`: 2000 spheres (R = 0.5 mm) deposited ballistically on a 15 mm × 15 mm
//!   laterally periodic floor and settled under gravity for 1000 steps in the setup
//!   (Hertz with damping); variants add friction (Mindlin–Deresiewicz, or the
//!   Cundall–Strack spring), rotation, both, or cohesion, or replace the normal law by
//!   MDR, which keeps a state per particle.
//! - `gas_2000`: the same spheres inserted at random in a 15 mm × 15 mm × 150 mm
//!   periodic column, flying at 0.1 m/s with hardly any contacts; variants add
//!   gravity or a floor (a wall every sphere is tested against each step).
//!
//! Every iteration times one step from the same state (a fresh clone of the prepared
//! simulation, cloned outside the timing), so a variant cannot drift into another
//! regime while criterion samples it (a gas falling under gravity would otherwise
//! rebuild its neighbour list ever more often).
//!
//! Run with `cargo bench --bench effects`; docs/performance.md has the table.

use criterion::{BatchSize, Criterion, criterion_group, criterion_main};
use serde_json::{Value, json};
use tamp::scene;
use tamp::simulation::Simulation;

const R: f64 = 5e-4;
const SIDE: f64 = 0.015;

fn material() -> Value {
    json!([{"name": "glass", "density": 2500, "youngs_modulus": 1e8, "poisson_ratio": 0.25}])
}

fn floor() -> Value {
    json!([{"name": "floor", "material": "glass",
        "shape": {"kind": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}}])
}

fn bed(variant: &str) -> Value {
    let mut v = json!({
        "seed": 3,
        "materials": material(),
        "contact": {"normal": {"law": "hertz"}, "damping": {"kind": "critical_fraction", "xi": 0.3}},
        "deposit": [{"count": 2000, "radius": R, "material": "glass", "footprint": [[0, 0], [SIDE, SIDE]], "floor": 0}],
        "walls": floor(),
        "periodic": {"x": [0, SIDE], "y": [0, SIDE]},
        "gravity": [0, 0, -9.81],
        "time_step": {"alpha": 0.2, "characteristic_velocity": 0.5},
        "run": {"steps": 1}
    });
    let friction = json!({"law": "mindlin_deresiewicz", "friction": 0.5});
    match variant {
        "base" => {}
        "+friction" => v["contact"]["tangential"] = friction,
        "+rotation" => v["rotation"] = json!({}),
        "+friction+rotation" => {
            v["contact"]["tangential"] = friction;
            v["rotation"] = json!({});
        }
        "+friction(cundall_strack)" => {
            v["contact"]["tangential"] =
                json!({"law": "cundall_strack", "friction": 0.5, "stiffness": 1e3})
        }
        "+friction(cundall_strack)+rotation" => {
            v["contact"]["tangential"] =
                json!({"law": "cundall_strack", "friction": 0.5, "stiffness": 1e3});
            v["rotation"] = json!({});
        }
        // LAMMPS's rolling sds joined to the spring (k_r = 2.25 μ_r² E R, its tableting
        // example's choice).
        "+friction(cundall_strack)+rotation+rolling" => {
            v["contact"]["tangential"] =
                json!({"law": "cundall_strack", "friction": 0.5, "stiffness": 1e3});
            v["contact"]["rolling"] =
                json!({"law": "sds", "stiffness": 4.05e4, "damping": 0.0, "friction": 0.6});
            v["rotation"] = json!({});
        }
        "+no_pull" => v["contact"]["damping"]["limit"] = json!(true),
        "+cohesion" => {
            v["contact"]["cohesion"] = json!({"law": "van_der_waals", "hamaker": 6.5e-20,
                "min_separation": 4e-10, "cutoff": 1e-7})
        }
        // Not an effect added but the normal law replaced: MDR (its own dashpot in place
        // of the damping role), with its pass before the forces and two sides a contact.
        "mdr" => {
            v["contact"] = json!({"normal": {"law": "mdr", "youngs_modulus": 1e8,
                "poisson_ratio": 0.25, "yield_stress": 1e6, "surface_energy": 0.0,
                "bulk_trigger": 0.5, "damping": {"coefficient": 0.5, "form": "stiffness"}}})
        }
        other => panic!("unknown bed variant {other}"),
    }
    v
}

fn gas(variant: &str) -> Value {
    let mut v = json!({
        "seed": 3,
        "materials": material(),
        "contact": {"normal": {"law": "hertz"}, "damping": {"kind": "critical_fraction", "xi": 0.3}},
        "insert": [{"count": 2000, "radius": R, "material": "glass", "speed": 0.1,
            "region": {"lower": [0, 0, 0.001], "upper": [SIDE, SIDE, 0.15]}}],
        "periodic": {"x": [0, SIDE], "y": [0, SIDE]},
        "time_step": {"alpha": 0.2, "characteristic_velocity": 0.5},
        "run": {"steps": 1}
    });
    match variant {
        "base" => {}
        "+gravity" => v["gravity"] = json!([0, 0, -9.81]),
        "+walls" => v["walls"] = floor(),
        other => panic!("unknown gas variant {other}"),
    }
    v
}

fn simulation(v: &Value, settle: u64) -> Simulation {
    let s = scene::parse(&v.to_string()).expect("valid scene");
    let mut sim = scene::build(&s).expect("builds").sim;
    sim.run_with(settle, |_| {}).expect("stable");
    sim
}

fn one_step(b: &mut criterion::Bencher, sim: &Simulation) {
    b.iter_batched_ref(
        || sim.clone(),
        |s| s.step().expect("stable"),
        BatchSize::LargeInput,
    )
}

fn effects(c: &mut Criterion) {
    let mut group = c.benchmark_group("bed_2000");
    for name in [
        "base",
        "+friction",
        "+friction(cundall_strack)",
        "+rotation",
        "+friction+rotation",
        "+friction(cundall_strack)+rotation",
        "+friction(cundall_strack)+rotation+rolling",
        "+no_pull",
        "+cohesion",
        "mdr",
    ] {
        let sim = simulation(&bed(name), 1000);
        group.bench_function(name, |b| one_step(b, &sim));
    }
    group.finish();
    let mut group = c.benchmark_group("gas_2000");
    for name in ["base", "+gravity", "+walls"] {
        let sim = simulation(&gas(name), 0);
        group.bench_function(name, |b| one_step(b, &sim));
    }
    group.finish();
}

criterion_group!(benches, effects);
criterion_main!(benches);
