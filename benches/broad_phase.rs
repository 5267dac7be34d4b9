//! Cost of ONE broad-phase call (`Detector::candidate_pairs`, i.e. one Verlet-list
//! rebuild) for the linked-cell and the multigrid (He, Dong & Zhou 2007) detectors,
//! on dense bidisperse packings of N ≈ 20 000 spheres at size ratios 1, 3, 10, 30.
//!
//! The packings: small spheres of radius 1 and big ones of radius `ratio`, with equal
//! total volume of the two kinds (N_big = N / (1 + ratio³), at least one), placed by
//! random sequential insertion — big ones first, then small ones, each at a uniform
//! random spot inside a cube, retried until it overlaps nothing — to packing
//! fraction 0.35, below the insertion limit (≈ 0.38) so the set-up stays cheap. The
//! margin is 0.2 × the small radius, the default Verlet skin (`skin_fraction`).
//! At ratio 30 equal volume means a single big sphere (N / 27 001 < 1): that case is
//! one big sphere in a bath of 19 999 small ones.
//!
//! With the overall packing fraction fixed, the small spheres of a bidisperse
//! packing fill only the space the big ones leave, at a local packing fraction of
//! about 0.2 instead of 0.35; cheaper to search, and fewer neighbours. A fifth
//! case, monodisperse at 0.2, is that density with no size ratio, the fair
//! reference for the bidisperse ones. Benchmark ids read `detector/ratio@fraction`.
//!
//! The pair count and the small spheres' local packing fraction of each
//! configuration are printed once before it is timed, and the two detectors are
//! checked to agree. Run with
//! `cargo bench --bench broad_phase`.
//!
//! Times are the CPU time of the benchmark thread, not wall time: the machine is
//! shared (two cores, other jobs running), and wall time then mostly measures how
//! long the thread waited for a core. The kernel's per-thread count
//! (`/proc/thread-self/schedstat`, Linux only) advances in scheduler ticks (4 ms
//! here), so each sample runs for ~300 ms to keep that below ~2 %.

use criterion::measurement::{Measurement, ValueFormatter, WallTime};
use criterion::{BenchmarkId, Criterion, SamplingMode, criterion_group, criterion_main};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::hint::black_box;
use std::time::Duration;
use tamp::detect::Detector;
use tamp::particles::Vec3;
use tamp::space::Space;

const N: usize = 20_000;
/// (size ratio, packing fraction).
const CASES: [(f64, f64); 5] = [
    (1.0, 0.35),
    (3.0, 0.35),
    (10.0, 0.35),
    (30.0, 0.35),
    (1.0, 0.2),
];
/// The Verlet margin, as a fraction of the small radius.
const MARGIN: f64 = 0.2;

/// CPU time consumed by the calling thread.
struct ThreadCpuTime;

fn thread_cpu_nanos() -> u64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse().ok())
        .expect("/proc/thread-self/schedstat (Linux) gives the thread's CPU time")
}

impl Measurement for ThreadCpuTime {
    type Intermediate = u64;
    type Value = Duration;

    fn start(&self) -> u64 {
        thread_cpu_nanos()
    }
    fn end(&self, start: u64) -> Duration {
        Duration::from_nanos(thread_cpu_nanos() - start)
    }
    fn add(&self, a: &Duration, b: &Duration) -> Duration {
        *a + *b
    }
    fn zero(&self) -> Duration {
        Duration::ZERO
    }
    fn to_f64(&self, value: &Duration) -> f64 {
        value.as_nanos() as f64
    }
    fn formatter(&self) -> &dyn ValueFormatter {
        // Same unit (a duration) as wall time, so reuse its formatting.
        WallTime.formatter()
    }
}

/// Placed spheres of one radius binned into cubic cells of edge 2r, so an insertion
/// test looks at a few cells instead of every sphere.
struct Bins {
    radius: f64,
    cell: f64,
    dims: usize,
    bins: Vec<Vec<Vec3>>,
}

impl Bins {
    fn new(radius: f64, side: f64) -> Bins {
        let cell = 2.0 * radius;
        let dims = ((side / cell).ceil() as usize).max(1);
        Bins {
            radius,
            cell,
            dims,
            bins: vec![Vec::new(); dims * dims * dims],
        }
    }

    fn coordinate(&self, x: f64) -> i64 {
        ((x / self.cell).floor() as i64).clamp(0, self.dims as i64 - 1)
    }

    fn insert(&mut self, x: Vec3) {
        let c = [0, 1, 2].map(|k| self.coordinate(x[k]) as usize);
        self.bins[c[0] + self.dims * (c[1] + self.dims * c[2])].push(x);
    }

    /// Whether a sphere of radius `r` at `x` overlaps any sphere in the bins.
    fn overlaps(&self, x: &Vec3, r: f64) -> bool {
        let reach = r + self.radius;
        let span = (reach / self.cell).ceil() as i64;
        let c = [0, 1, 2].map(|k| self.coordinate(x[k]));
        let d = self.dims as i64;
        for cz in (c[2] - span).max(0)..=(c[2] + span).min(d - 1) {
            for cy in (c[1] - span).max(0)..=(c[1] + span).min(d - 1) {
                for cx in (c[0] - span).max(0)..=(c[0] + span).min(d - 1) {
                    let bin = &self.bins[(cx + d * (cy + d * cz)) as usize];
                    if bin.iter().any(|y| (x - y).norm_squared() < reach * reach) {
                        return true;
                    }
                }
            }
        }
        false
    }
}

/// The bidisperse packing described in the module doc.
struct Packing {
    position: Vec<Vec3>,
    radius: Vec<f64>,
    n_big: usize,
    /// Volume of the small spheres over the volume the big ones leave free.
    small_fraction: f64,
}

fn packing(ratio: f64, fraction: f64) -> Packing {
    let n_big = if ratio == 1.0 {
        N / 2
    } else {
        ((N as f64 / (1.0 + ratio.powi(3))).round() as usize).max(1)
    };
    let solid =
        4.0 / 3.0 * std::f64::consts::PI * (n_big as f64 * ratio.powi(3) + (N - n_big) as f64);
    let side = (solid / fraction).cbrt();
    let mut rng = ChaCha8Rng::seed_from_u64(2007);
    let mut big = Bins::new(ratio, side);
    let mut small = Bins::new(1.0, side);
    let mut position = Vec::with_capacity(N);
    let mut radius = Vec::with_capacity(N);
    for k in 0..N {
        let r = if k < n_big { ratio } else { 1.0 };
        let x = loop {
            let x = Vec3::from_fn(|_, _| rng.random_range(r..side - r));
            if !big.overlaps(&x, r) && !small.overlaps(&x, r) {
                break x;
            }
        };
        if k < n_big {
            big.insert(x);
        } else {
            small.insert(x);
        }
        position.push(x);
        radius.push(r);
    }
    let (n_small, n_big_f) = ((N - n_big) as f64, n_big as f64);
    let sphere = 4.0 / 3.0 * std::f64::consts::PI;
    let small_fraction = if ratio == 1.0 {
        fraction
    } else {
        sphere * n_small / (side.powi(3) - sphere * n_big_f * ratio.powi(3))
    };
    Packing {
        position,
        radius,
        n_big,
        small_fraction,
    }
}

fn bench(c: &mut Criterion<ThreadCpuTime>) {
    let mut group = c.benchmark_group("broad_phase");
    // One call takes from a few milliseconds to ~0.1 s (cells at ratio 30); flat
    // sampling with 10 samples keeps the whole run to a few minutes.
    group
        .sample_size(10)
        .sampling_mode(SamplingMode::Flat)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    let space = Space::open();
    for (ratio, fraction) in CASES {
        let Packing {
            position,
            radius,
            n_big,
            small_fraction,
        } = packing(ratio, fraction);
        let cells = Detector::Cells.candidate_pairs(&position, &radius, MARGIN, &space);
        let multigrid = Detector::Multigrid.candidate_pairs(&position, &radius, MARGIN, &space);
        assert_eq!(
            cells, multigrid,
            "the detectors disagree at {ratio}@{fraction}"
        );
        let big_pairs = cells
            .iter()
            .filter(|&&(i, j)| (i as usize) < n_big || (j as usize) < n_big)
            .count();
        let kinds = if ratio == 1.0 {
            "monodisperse".to_string()
        } else {
            format!("{n_big} big, {big_pairs} pairs with a big sphere")
        };
        println!(
            "{ratio}@{fraction}: N = {N} ({kinds}), pairs = {}, small spheres' local packing fraction {small_fraction:.3}",
            cells.len()
        );
        for (name, detector) in [
            ("cells", Detector::Cells),
            ("multigrid", Detector::Multigrid),
        ] {
            let id = BenchmarkId::new(name, format!("{ratio}@{fraction}"));
            group.bench_function(id, |b| {
                b.iter(|| {
                    black_box(detector.candidate_pairs(
                        black_box(&position),
                        black_box(&radius),
                        MARGIN,
                        &space,
                    ))
                })
            });
        }
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().with_measurement(ThreadCpuTime);
    targets = bench
}
criterion_main!(benches);
