//! Cost of ONE broad-phase call (`Detector::candidate_pairs`, i.e. one Verlet-list
//! rebuild) for the linked-cell and the multigrid (He, Dong & Zhou 2007) detectors,
//! in two groups:
//! - `broad_phase`: bidisperse packings of N ≈ 20 000 spheres in an open cube at
//!   size ratios 1, 3, 10, 30 (ids `detector/ratio@fraction`);
//! - `broad_phase_vs_n`: N = 1000 m³ for m = 1…5 (1000 to 125 000) at size ratios
//!   1 and 10 in a periodic cube, to show the cost is linear in N, with the
//!   particle ids in random or in spatial order (ids `detector ratio R order/N`).
//!   Criterion's throughput (elements/s) is particles per second.
//!
//! The packings: small spheres of radius 1 and big ones of radius `ratio`, with equal
//! total volume of the two kinds (N_big = N / (1 + ratio³), at least one), placed by
//! random sequential insertion — big ones first, then small ones, each at a uniform
//! random spot inside a cube, retried until it overlaps nothing — to packing
//! fraction 0.35, below the insertion limit (≈ 0.38). The overlap test looks only
//! at the spheres binned in nearby cells, but near 0.35 a sphere takes hundreds of
//! tries (~650 on average in a periodic cube), and in a small open cube far more:
//! the layer along the faces packs worse, so 0.35 is close to jamming there (N =
//! 1000 took 13 minutes; the N = 20 000 ratio-1 case of `broad_phase` takes
//! 15–30 s). The margin is 0.2 × the small radius, the default Verlet
//! skin (`skin_fraction`). At ratio 30 equal volume means a single big sphere
//! (N / 27 001 < 1): that case is one big sphere in a bath of 19 999 small ones.
//!
//! `broad_phase_vs_n` therefore places one block of 1000 spheres in a periodic
//! cube (0.2 s) and copies it m × m × m times into a periodic cube m times wider,
//! with the particle ids shuffled (insertion order has no spatial order either)
//! or, at ratio 1, sorted by cell (a code that renumbers particles for locality).
//! Every N then has the same pairs per particle, and being periodic no particle
//! sits at a face where the search is clipped, so the cost per particle can only
//! change with N itself: the sort of the pair list (N log N) and memory. The
//! sorted order shows how much of the latter is cache misses. At ratio 10 the
//! block holds one big sphere, so the big spheres form a cubic lattice; the small
//! ones see them as in a random packing.
//!
//! With the overall packing fraction fixed, the small spheres of a bidisperse
//! packing fill only the space the big ones leave, at a local packing fraction of
//! about 0.2 instead of 0.35; cheaper to search, and fewer neighbours. A fifth
//! case of `broad_phase`, monodisperse at 0.2, is that density with no size ratio,
//! the fair reference for the bidisperse ones.
//!
//! The pair count and the small spheres' local packing fraction of each
//! configuration are printed once before it is timed, and the two detectors are
//! checked to agree. Run with
//! `cargo bench --bench broad_phase` (≈ 7 min; one group: `-- broad_phase_vs_n`,
//! though every packing is still made).
//!
//! Times are the CPU time of the benchmark thread, not wall time
//! (`common/cpu_time.rs`), so each sample runs for ~300 ms.

#[path = "common/cpu_time.rs"]
mod cpu_time;

use cpu_time::ThreadCpuTime;
use criterion::{
    BenchmarkGroup, BenchmarkId, Criterion, SamplingMode, Throughput, criterion_group,
    criterion_main,
};
use rand::seq::SliceRandom;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::hint::black_box;
use std::time::{Duration, Instant};
use tamp::detect::Detector;
use tamp::particles::Vec3;
use tamp::space::Space;

const N: usize = 20_000;
/// The `broad_phase_vs_n` group tiles one periodic packing of `BLOCK` spheres
/// m × m × m times for each m in `COPIES`: N = 1000, 8000, 27 000, 64 000, 125 000.
const BLOCK: usize = 1000;
const COPIES: [usize; 5] = [1, 2, 3, 4, 5];
/// Particle orders of the `broad_phase_vs_n` group, (name, sorted by cell);
/// `sorted` at ratio 1 only.
const ORDERS: [(&str, bool); 2] = [("shuffled", false), ("sorted", true)];
/// Size ratios of the `broad_phase_vs_n` group (at packing fraction 0.35).
const RATIOS_VS_N: [f64; 2] = [1.0, 10.0];
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

/// Placed spheres of one radius binned into cubic cells of edge ≥ 2r, so an
/// insertion test looks at a few cells instead of every sphere. In a periodic cube
/// the cells tile the period and the search wraps round it.
struct Bins {
    radius: f64,
    edge: f64,
    dims: usize,
    space: Space,
    bins: Vec<Vec<Vec3>>,
}

impl Bins {
    fn new(radius: f64, side: f64, space: Space) -> Bins {
        let cell = 2.0 * radius;
        let (dims, edge) = if space.is_periodic() {
            let dims = ((side / cell).floor() as usize).max(1);
            (dims, side / dims as f64)
        } else {
            (((side / cell).ceil() as usize).max(1), cell)
        };
        Bins {
            radius,
            edge,
            dims,
            space,
            bins: vec![Vec::new(); dims * dims * dims],
        }
    }

    fn coordinate(&self, x: f64) -> i64 {
        ((x / self.edge).floor() as i64).clamp(0, self.dims as i64 - 1)
    }

    fn insert(&mut self, x: Vec3) {
        let c = [0, 1, 2].map(|k| self.coordinate(x[k]) as usize);
        self.bins[c[0] + self.dims * (c[1] + self.dims * c[2])].push(x);
    }

    /// Whether a sphere of radius `r` at `x` overlaps any sphere in the bins (through
    /// the nearest image in a periodic cube).
    fn overlaps(&self, x: &Vec3, r: f64) -> bool {
        let reach = r + self.radius;
        let d = self.dims as i64;
        // The cells overlapping the cube of half-width `reach` around x, each once.
        let range = |k: usize| {
            let lo = ((x[k] - reach) / self.edge).floor() as i64;
            let hi = ((x[k] + reach) / self.edge).floor() as i64;
            if !self.space.is_periodic() {
                (lo.max(0), hi.min(d - 1))
            } else if hi - lo + 1 >= d {
                (0, d - 1)
            } else {
                (lo, hi)
            }
        };
        let [(x0, x1), (y0, y1), (z0, z1)] = [0, 1, 2].map(range);
        for cz in z0..=z1 {
            for cy in y0..=y1 {
                for cx in x0..=x1 {
                    let [cx, cy, cz] = [cx, cy, cz].map(|c| c.rem_euclid(d));
                    let bin = &self.bins[(cx + d * (cy + d * cz)) as usize];
                    if bin
                        .iter()
                        .any(|y| self.space.displacement(x, y).norm_squared() < reach * reach)
                    {
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
    /// Edge of the cube.
    side: f64,
    /// Open, or periodic over the cube on every axis.
    space: Space,
}

/// Random sequential insertion into a cube: an open one (centres at least r from
/// its faces) or a periodic one.
fn packing(n: usize, ratio: f64, fraction: f64, periodic: bool) -> Packing {
    let n_big = if ratio == 1.0 {
        n / 2
    } else {
        ((n as f64 / (1.0 + ratio.powi(3))).round() as usize).max(1)
    };
    let solid =
        4.0 / 3.0 * std::f64::consts::PI * (n_big as f64 * ratio.powi(3) + (n - n_big) as f64);
    let side = (solid / fraction).cbrt();
    let space = if periodic {
        Space {
            periodic: [Some((0.0, side)); 3],
        }
    } else {
        Space::open()
    };
    let mut rng = ChaCha8Rng::seed_from_u64(2007);
    let mut big = Bins::new(ratio, side, space);
    let mut small = Bins::new(1.0, side, space);
    let mut position = Vec::with_capacity(n);
    let mut radius = Vec::with_capacity(n);
    for k in 0..n {
        let r = if k < n_big { ratio } else { 1.0 };
        let inset = if periodic { 0.0 } else { r };
        let x = loop {
            let x = Vec3::from_fn(|_, _| rng.random_range(inset..side - inset));
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
    let (n_small, n_big_f) = ((n - n_big) as f64, n_big as f64);
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
        side,
        space,
    }
}

/// A periodic packing copied m × m × m times into a periodic cube m times wider.
/// The particle ids are either shuffled — an insertion places spheres in no spatial
/// order, and the copies should not be blocks of neighbours in memory either — or
/// `sorted` by the cell (of the detector's edge, z then y then x) they lie in, as a
/// code that renumbers particles for locality would have them.
fn tiled(block: &Packing, m: usize, sorted: bool) -> Packing {
    let n = block.position.len();
    let copy = |k: usize| {
        let (c, i) = (k / n, k % n);
        let shift = Vec3::new((c % m) as f64, (c / m % m) as f64, (c / (m * m)) as f64);
        (block.position[i] + shift * block.side, block.radius[i])
    };
    let mut order: Vec<usize> = (0..m * m * m * n).collect();
    if sorted {
        let edge = 2.0 * block.radius.iter().cloned().fold(0.0, f64::max) + MARGIN;
        let cell = |k: &usize| {
            let x = copy(*k).0;
            [2, 1, 0].map(|a| (x[a] / edge).floor() as i64)
        };
        order.sort_by_cached_key(cell);
    } else {
        order.shuffle(&mut ChaCha8Rng::seed_from_u64(m as u64));
    }
    let (position, radius) = order.into_iter().map(copy).unzip();
    let side = block.side * m as f64;
    Packing {
        position,
        radius,
        n_big: block.n_big * m * m * m,
        small_fraction: block.small_fraction,
        side,
        space: Space {
            periodic: [Some((0.0, side)); 3],
        },
    }
}

/// Checks the two detectors agree on the packing and prints what it is.
fn describe(packing: &Packing, ratio: f64, label: &str, made_in: Duration) {
    let Packing {
        position,
        radius,
        n_big,
        small_fraction,
        space,
        ..
    } = packing;
    let cells = Detector::Cells.candidate_pairs(position, radius, MARGIN, space);
    let multigrid = Detector::Multigrid.candidate_pairs(position, radius, MARGIN, space);
    assert_eq!(cells, multigrid, "the detectors disagree at {label}");
    let big_pairs = cells
        .iter()
        .filter(|&&(i, j)| radius[i as usize] > 1.0 || radius[j as usize] > 1.0)
        .count();
    let kinds = if ratio == 1.0 {
        "monodisperse".to_string()
    } else {
        format!("{n_big} big, {big_pairs} pairs with a big sphere")
    };
    println!(
        "{label}: N = {} ({kinds}), pairs = {}, small spheres' local packing fraction {small_fraction:.3}, made in {made_in:.2?}",
        position.len(),
        cells.len()
    );
}

fn time_detectors(
    group: &mut BenchmarkGroup<ThreadCpuTime>,
    packing: &Packing,
    id: impl Fn(&str) -> BenchmarkId,
) {
    for (name, detector) in [
        ("cells", Detector::Cells),
        ("multigrid", Detector::Multigrid),
    ] {
        group.bench_function(id(name), |b| {
            b.iter(|| {
                black_box(detector.candidate_pairs(
                    black_box(&packing.position),
                    black_box(&packing.radius),
                    MARGIN,
                    &packing.space,
                ))
            })
        });
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
    for (ratio, fraction) in CASES {
        let start = Instant::now();
        let packing = packing(N, ratio, fraction, false);
        describe(
            &packing,
            ratio,
            &format!("{ratio}@{fraction}"),
            start.elapsed(),
        );
        time_detectors(&mut group, &packing, |name| {
            BenchmarkId::new(name, format!("{ratio}@{fraction}"))
        });
    }
    group.finish();

    // From ~0.1 ms (N = 1e3) to ~0.1 s (cells, ratio 10, N = 1e5) per call: the same
    // flat sampling, so every sample still spans ~300 ms of CPU time.
    let mut group = c.benchmark_group("broad_phase_vs_n");
    group
        .sample_size(10)
        .sampling_mode(SamplingMode::Flat)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    for ratio in RATIOS_VS_N {
        let start = Instant::now();
        let block = packing(BLOCK, ratio, 0.35, true);
        let placed_in = start.elapsed();
        for m in COPIES {
            for (order, sorted) in ORDERS.into_iter().filter(|o| ratio == 1.0 || !o.1) {
                let start = Instant::now();
                let packing = tiled(&block, m, sorted);
                let n = packing.position.len();
                let label = format!("{ratio}@0.35 periodic, {m}³ copies, {order}");
                describe(&packing, ratio, &label, placed_in + start.elapsed());
                group.throughput(Throughput::Elements(n as u64));
                time_detectors(&mut group, &packing, |name| {
                    BenchmarkId::new(format!("{name} ratio {ratio} {order}"), n)
                });
            }
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
