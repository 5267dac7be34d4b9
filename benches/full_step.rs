//! Cost of one full time step (`Simulation::step`) per particle on a dense settled bed,
//! against the number of spheres N = 1e3, 4e3, 1.6e4, 6.4e4, 1e5, to show that the cost
//! per step grows linearly in N.
//!
//! The physics is that of a realistic frictional bed: glass spheres (R = 0.5 mm,
//! E = 1e8 Pa), Hertz with damping ξ = 0.3, Mindlin–Deresiewicz friction μ = 0.5,
//! rotation, gravity and a floor plane, periodic in x and y.
//!
//! How the beds are made. Settling 1e5 spheres by simulation would take half an
//! hour for every run of the bench, so one small bed is settled and then tiled:
//! 1. 1000 spheres are deposited ballistically on a 10 mm × 10 mm floor periodic
//!    in x and y, and settled under gravity for 20 000 steps (0.08 s, ~10 s here).
//! 2. For k = 1, 2, 4, 8, 10 that bed is copied k × k times side by side, in a box
//!    periodic over k × 10 mm. A contact across a periodic face of the small bed
//!    is a contact between neighbouring copies in the tiled one, so every copy has
//!    exactly the small bed's contacts: the same contact structure at N = 1000 k².
//! 3. The tiled bed is built from the scene (explicit particles with their
//!    velocities and spins; overlaps allowed up to 0.1 R) and stepped 200 steps so
//!    the tangential springs, which a scene cannot carry, build up again.
//!
//! Particle order. tamp keeps particles in creation order, and a poured or
//! deposited bed is created in no spatial order, so the `shuffled` variant
//! permutes the particles at random before building: a particle's neighbours are
//! then anywhere in memory, as in a real large bed. The `sorted` variant is the same
//! shuffled scene with `broad_phase.sort`, which renumbers the particles at build by
//! the cell (edge 2R + skin; z, then y, then x) they lie in, as codes that renumber
//! particles for locality do (LAMMPS `atom_modify sort`); the difference between the
//! two is the cost of cache misses alone, with the same arithmetic.
//!
//! Before timing, each bed is reported: contacts per sphere (pairs and floor),
//! the largest and the mean speed, and the neighbour-list rebuilds over 100 trial
//! steps (a settled bed rebuilds almost never, so the broad phase is not in these
//! times; `benches/broad_phase.rs` times it against N).
//!
//! Every sample clones the prepared bed (outside the timing) and times that many
//! consecutive steps of the clone, so each sample starts from the same state.
//! Times are the CPU time of the bench thread (`common/cpu_time.rs`); samples span
//! ≥ 0.4 s. Criterion's throughput (elements/s) is particle-steps per second.
//!
//! Run with `cargo bench --bench full_step` (≈ 4 min); docs/performance.md has the
//! table.

#[path = "common/cpu_time.rs"]
mod cpu_time;

use cpu_time::ThreadCpuTime;
use criterion::measurement::Measurement;
use criterion::{
    BenchmarkId, Criterion, SamplingMode, Throughput, criterion_group, criterion_main,
};
use rand::SeedableRng;
use rand::seq::SliceRandom;
use rand_chacha::ChaCha8Rng;
use serde_json::{Value, json};
use std::time::{Duration, Instant};
use tamp::particles::Vec3;
use tamp::scene;
use tamp::simulation::Simulation;

const R: f64 = 5e-4;
/// Side of the small bed's periodic square, m.
const SIDE: f64 = 0.01;
/// Spheres in the small bed.
const BASE: usize = 1000;
const SETTLE_STEPS: u64 = 20_000;
const RESETTLE_STEPS: u64 = 200;
/// Copies per side: N = 1000, 4000, 16 000, 64 000, 100 000.
const TILES: [usize; 5] = [1, 2, 4, 8, 10];

/// The scene around the particles: periodic square of k small beds.
fn scene(k: usize, particles: Value) -> Value {
    let period = SIDE * k as f64;
    let mut v = json!({
        "seed": 8,
        "materials": [{"name": "glass", "density": 2500, "youngs_modulus": 1e8, "poisson_ratio": 0.25}],
        "contact": {
            "normal": {"law": "hertz"},
            "damping": {"kind": "critical_fraction", "xi": 0.3},
            "tangential": {"law": "mindlin_deresiewicz", "friction": 0.5}
        },
        "walls": [{"name": "floor", "material": "glass",
            "shape": {"kind": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}}],
        "periodic": {"x": [0, period], "y": [0, period]},
        "gravity": [0, 0, -9.81],
        "rotation": {},
        "time_step": {"alpha": 0.2, "characteristic_velocity": 0.5},
        // A settled bed overlaps by ~1e-3 R; the default (1e-6) is meant for
        // hand-placed particles.
        "stability": {"initial_overlap_tolerance": 0.1},
        "run": {"steps": 1}
    });
    if particles.is_null() {
        v["deposit"] = json!([{"count": BASE, "radius": R, "material": "glass",
            "footprint": [[0, 0], [SIDE, SIDE]], "floor": 0}]);
    } else {
        v["particles"] = particles;
    }
    v
}

fn build(v: &Value) -> Simulation {
    let s = scene::parse(&v.to_string()).expect("valid scene");
    scene::build(&s).expect("builds").sim
}

fn small_bed() -> Simulation {
    let mut sim = build(&scene(1, Value::Null));
    sim.run_with(SETTLE_STEPS, |_| {}).expect("stable");
    sim
}

/// The small bed copied k × k times, numbered at random, and renumbered by cell at
/// build (`broad_phase.sort`) when `sorted`.
fn tiled_bed(small: &Simulation, k: usize, sorted: bool) -> Simulation {
    let p = &small.state().particles;
    let n = p.len();
    let position = |c: usize| {
        let (copy, i) = (c / n, c % n);
        p.position[i] + Vec3::new((copy % k) as f64 * SIDE, (copy / k) as f64 * SIDE, 0.0)
    };
    let mut order: Vec<usize> = (0..k * k * n).collect();
    order.shuffle(&mut ChaCha8Rng::seed_from_u64(k as u64));
    let particles = order
        .into_iter()
        .map(|c| {
            let (x, i) = (position(c), c % n);
            let (v, w) = (p.velocity[i], p.omega[i]);
            json!({
                "position": [x[0], x[1], x[2]],
                "velocity": [v[0], v[1], v[2]],
                "omega": [w[0], w[1], w[2]],
                "radius": p.radius[i],
                "material": "glass"
            })
        })
        .collect();
    let mut v = scene(k, Value::Array(particles));
    // The small bed's step, not a new estimate: every N runs the same dt.
    v["time_step"] = json!({"fixed": small.dt()});
    // Sorted: the scene asks tamp to renumber the shuffled particles by cell.
    v["broad_phase"]["sort"] = json!(sorted);
    let mut sim = build(&v);
    sim.run_with(RESETTLE_STEPS, |_| {}).expect("stable");
    sim
}

/// Contacts per sphere, counting a pair contact for both spheres and a floor
/// contact for one.
fn coordination(sim: &Simulation) -> (f64, f64) {
    let pairs = sim
        .state()
        .neighbors
        .pairs
        .iter()
        .filter(|&&(i, j)| sim.overlap(i as usize, j as usize) > 0.0)
        .count();
    let walls = sim.contact_count() - pairs;
    let n = sim.state().particles.len() as f64;
    (2.0 * pairs as f64 / n, walls as f64 / n)
}

/// Prints the checks of the module doc; panics if 100 trial steps fail.
fn report(name: &str, sim: &Simulation, prepared_in: Duration) {
    let n = sim.state().particles.len();
    let (pair_z, wall_z) = coordination(sim);
    let speed: Vec<f64> = sim
        .state()
        .particles
        .velocity
        .iter()
        .map(|v| v.norm())
        .collect();
    let max_speed = speed.iter().cloned().fold(0.0, f64::max);
    let mean_speed = speed.iter().sum::<f64>() / n as f64;
    let mut trial = sim.clone();
    let builds = trial.state().neighbors.builds;
    trial
        .run_with(100, |_| {})
        .expect("100 trial steps are stable");
    let (after_z, _) = coordination(&trial);
    println!(
        "{name}/{n}: prepared in {prepared_in:.1?}; {} pairs in the list, contacts per sphere {pair_z:.3} \
         between spheres + {wall_z:.3} with the floor; speed max {:.2} mm/s, mean {:.3} mm/s \
         (√(g·2R) = 99 mm/s); over 100 trial steps: {} list rebuilds, contacts per sphere {after_z:.3}",
        sim.state().neighbors.pairs.len(),
        1e3 * max_speed,
        1e3 * mean_speed,
        trial.state().neighbors.builds - builds,
    );
}

fn full_step(c: &mut Criterion<ThreadCpuTime>) {
    let start = Instant::now();
    let small = small_bed();
    println!(
        "small bed: {BASE} spheres settled for {SETTLE_STEPS} steps of {:.3e} s in {:.1?}",
        small.dt(),
        start.elapsed()
    );
    let mut group = c.benchmark_group("full_step");
    // A step takes from ~0.3 ms (N = 1e3) to ~50 ms (N = 1e5); flat sampling, and
    // 0.4 s per sample keeps the tick granularity of the CPU clock below 2 %.
    group
        .sample_size(10)
        .sampling_mode(SamplingMode::Flat)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(4));
    for k in TILES {
        for (name, sorted) in [("shuffled", false), ("sorted", true)] {
            let start = Instant::now();
            let sim = tiled_bed(&small, k, sorted);
            report(name, &sim, start.elapsed());
            let n = sim.state().particles.len();
            group.throughput(Throughput::Elements(n as u64));
            group.bench_function(BenchmarkId::new(name, n), |b| {
                b.iter_custom(|steps| {
                    let mut s = sim.clone();
                    let clock = ThreadCpuTime;
                    let start = clock.start();
                    for _ in 0..steps {
                        s.step().expect("stable");
                    }
                    clock.end(start)
                })
            });
        }
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().with_measurement(ThreadCpuTime);
    targets = full_step
}
criterion_main!(benches);
