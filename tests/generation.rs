//! Ballistic deposition against the literature: bulk solid fraction and mean
//! coordination of monodisperse steepest-descent packings.

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use tamp::generate::distribution::SizeDistribution;
use tamp::generate::{ballistic, measure};
use tamp::measure::{Region, packing::packing_fraction};
use tamp::particles::Vec3;
use tamp::space::Space;

fn pile(n: usize, width: f64, seed: u64) -> (Vec<Vec3>, Vec<f64>, Space) {
    let space = Space {
        periodic: [Some((0.0, width)), Some((0.0, width)), None],
    };
    let radii = vec![0.5; n];
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let p =
        ballistic::deposit(&radii, ([0.0, 0.0], [width, width]), 0.0, &space, &mut rng).unwrap();
    (p, radii, space)
}

/// Mean and sample standard deviation.
fn stats(v: &[f64]) -> (f64, f64) {
    let m = v.iter().sum::<f64>() / v.len() as f64;
    let s = (v.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (v.len() - 1) as f64).sqrt();
    (m, s)
}

struct Bulk {
    solid_fraction: f64,
    coordination: f64,
    /// Spheres off the floor whose number of contacts with earlier spheres is not 3.
    not_three_supports: usize,
}

/// Bulk of a monodisperse (d = 1) deposit: the slab from 5 diameters above the
/// floor (below, the floor orders the packing: φ ≈ 0.54 in the first two diameters)
/// to 10 diameters below the highest centre (the rough surface). Moving either
/// face 5 diameters further in changes φ by less than the seed-to-seed spread.
fn bulk(p: &[Vec3], radii: &[f64], space: &Space) -> Bulk {
    let top = p.iter().map(|x| x[2]).fold(0.0, f64::max);
    let (lo, hi) = (5.0, top - 10.0);
    let pairs = measure::contact_pairs(p, radii, space, 1e-9);
    let mut contacts = vec![0usize; p.len()];
    let mut earlier = vec![0usize; p.len()];
    for &(i, j, _) in &pairs {
        contacts[i] += 1;
        contacts[j] += 1;
        earlier[j] += 1;
    }
    let inside: Vec<usize> = (0..p.len())
        .filter(|&i| p[i][2] > lo && p[i][2] < hi)
        .collect();
    Bulk {
        solid_fraction: packing_fraction(p, radii, &Region::Slab { axis: 2, lo, hi }, space)
            .unwrap(),
        coordination: inside.iter().map(|&i| contacts[i] as f64).sum::<f64>() / inside.len() as f64,
        not_three_supports: (0..p.len())
            .filter(|&i| (p[i][2] - radii[i]).abs() > 1e-12 && earlier[i] != 3)
            .count(),
    }
}

/// Visscher & Bolsterli (1972) report φ ≈ 0.582 for 3D steepest-descent deposition
/// of equal spheres. Survey (`generate_survey` below): N = 10⁴ in a 12 d × 12 d
/// periodic footprint gives φ = 0.5812 with seed-to-seed σ = 0.0008 (16 seeds);
/// the mean of 4 seeds then has σ/2 = 0.0004. Tolerance 0.003 = 4 × 0.0004 for our
/// sampling + 0.0013 for the literature value, quoted to three digits from much
/// smaller packings. Mean coordination: every sphere rests on exactly 3 earlier
/// ones, so each contributes 3 contacts below and, on average, 3 above: Z → 6
/// (σ = 0.0009 per seed); checked to 4 σ/√4 ≈ 0.002, rounded up to 0.003.
#[test]
fn generate_monodisperse_bulk_matches_visscher_bolsterli() {
    let width = 12.0;
    let mut phi = Vec::new();
    let mut z = Vec::new();
    for seed in 1..=4 {
        let (p, radii, space) = pile(10_000, width, seed);
        let b = bulk(&p, &radii, &space);
        assert_eq!(b.not_three_supports, 0, "seed {seed}");
        phi.push(b.solid_fraction);
        z.push(b.coordination);
    }
    let ((phi_mean, _), (z_mean, _)) = (stats(&phi), stats(&z));
    assert!(
        (phi_mean - 0.582).abs() < 0.003,
        "bulk φ {phi_mean} ({phi:?})"
    );
    assert!((z_mean - 6.0).abs() < 0.003, "bulk Z {z_mean} ({z:?})");
}

/// The measurement behind the tolerances above and docs/generation.md:
/// `cargo test --release --test generation generate_survey -- --ignored --nocapture`
#[test]
#[ignore]
fn generate_survey() {
    for n in [10_000usize, 20_000, 40_000] {
        let t = std::time::Instant::now();
        let _ = pile(n, 12.0, 1);
        println!("deposit N = {n} on 12 d × 12 d: {:?}", t.elapsed());
    }
    for (n, width, seeds) in [(10_000usize, 12.0, 16u64), (20_000, 16.0, 8)] {
        let (mut phi, mut z) = (Vec::new(), Vec::new());
        for seed in 1..=seeds {
            let (p, radii, space) = pile(n, width, seed);
            let b = bulk(&p, &radii, &space);
            println!(
                "N {n} L {width} seed {seed}: phi {:.5} Z {:.4} non-floor spheres without exactly 3 supports {}",
                b.solid_fraction, b.coordination, b.not_three_supports
            );
            phi.push(b.solid_fraction);
            z.push(b.coordination);
        }
        let ((pm, ps), (zm, zs)) = (stats(&phi), stats(&z));
        println!(
            "N {n} L {width} ({seeds} seeds): phi {pm:.4} ± {ps:.4} (sd), Z {zm:.4} ± {zs:.4} (sd)"
        );
    }
}

/// Wide and strongly bimodal size laws, where small spheres fall through the
/// pores of large ones: no failures, overlaps or unsupported spheres.
/// `cargo test --release --test generation generate_stress -- --ignored --nocapture`
#[test]
#[ignore]
fn generate_stress_polydisperse() {
    let laws = [
        SizeDistribution::LogNormal {
            median: 0.3,
            sigma: 0.5,
            min: Some(0.05),
            max: Some(1.0),
        },
        SizeDistribution::Discrete {
            radii: vec![0.1, 0.6],
            number_fractions: vec![0.9, 0.1],
        },
        SizeDistribution::Uniform { min: 0.1, max: 1.0 },
        SizeDistribution::Discrete {
            radii: vec![0.06, 0.6],
            number_fractions: vec![0.95, 0.05],
        },
        SizeDistribution::LogNormal {
            median: 0.2,
            sigma: 0.8,
            min: Some(0.02),
            max: Some(1.0),
        },
    ];
    let width = 12.0;
    let space = Space {
        periodic: [Some((0.0, width)), Some((0.0, width)), None],
    };
    let mut bad = 0;
    for (l, law) in laws.iter().enumerate() {
        for seed in 0..40u64 {
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            let radii: Vec<f64> = (0..5000).map(|_| law.sample(&mut rng)).collect();
            let fp = ([0.0, 0.0], [width, width]);
            match ballistic::deposit(&radii, fp, 0.0, &space, &mut rng) {
                Ok(p) => {
                    let pairs = measure::contact_pairs(&p, &radii, &space, 1e-9);
                    let worst = pairs.iter().map(|c| c.2).fold(0.0, f64::min);
                    let loose = measure::unsupported(&p, &radii, &space, 0.0, 1e-9);
                    if worst < -1e-9 || !loose.is_empty() {
                        bad += 1;
                        println!("law {l} seed {seed}: overlap {worst:e}, unsupported {loose:?}");
                    }
                }
                Err(e) => {
                    bad += 1;
                    println!("law {l} seed {seed}: {e}");
                }
            }
        }
    }
    assert_eq!(bad, 0);
}

/// Issue 27 class 7: random sequential insertion was all-pairs, so a bed of N
/// spheres cost O(N²) clearance tests (100 000 spheres took 32 s to place). With
/// the cell grid, the pairs examined per draw must not grow with N at fixed solid
/// fraction: counted, not timed, so the test holds on any machine.
#[test]
fn random_insertion_examines_a_bounded_number_of_pairs_per_draw() {
    use tamp::generate::rsi::{InsertionBox, Placed};
    let per_draw = |n: usize| {
        // Side for a solid fraction of 0.2 with radius 0.5.
        let side = (n as f64 * 4.0 / 3.0 * std::f64::consts::PI * 0.125 / 0.2).cbrt();
        let region = InsertionBox {
            lower: Vec3::zeros(),
            upper: Vec3::new(side, side, side),
        };
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        let mut placed = Placed::new(&Space::open(), 1.0);
        let mut draws = 0u64;
        while placed.position.len() < n {
            draws += 1;
            placed.place(0.5, &region, &|_, _| true, 1.0, &mut rng, 1);
        }
        placed.pair_tests() as f64 / draws as f64
    };
    let (small, large) = (per_draw(1_000), per_draw(20_000));
    assert!(
        large < 1.5 * small && large < 30.0,
        "pairs examined per draw: {small:.2} at N = 1000, {large:.2} at N = 20000"
    );
}
