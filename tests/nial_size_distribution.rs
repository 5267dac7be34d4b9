//! The NiAl size distribution derived in reference_data/nial/README.md from the facts
//! Rojek et al. (2016) §5 states: 1751 particles of diameters 1.5–18.5 µm fill the
//! flattened specimen (diameter 58 µm, height 95 µm) at relative density 0.62, and the
//! largest diameter is the expected largest of 1751 draws.

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use tamp::generate::distribution::SizeDistribution;

const MEDIAN: f64 = 1.990e-6;
const SIGMA: f64 = 0.4723;

fn nial() -> SizeDistribution {
    SizeDistribution::LogNormal {
        median: MEDIAN,
        sigma: SIGMA,
        min: Some(0.75e-6),
        max: Some(9.25e-6),
    }
}

/// Condition 1: 1751 particles fill π·29²·95 µm³ at 0.62. The parameters are given to
/// four digits, which moves the fraction by under 1e-3.
#[test]
fn nial_size_distribution_fills_the_flattened_specimen_at_0_62() {
    let specimen = std::f64::consts::PI * 29e-6f64.powi(2) * 95e-6;
    let fraction = 1751.0 * nial().mean_volume() / specimen;
    assert!((fraction - 0.62).abs() < 1e-3, "fraction {fraction}");
    // The same by sampling (independent of the closed-form moment): 2e5 draws give the
    // mean volume to about 0.5 % (the volume's coefficient of variation is ~2).
    let mut rng = ChaCha8Rng::seed_from_u64(1751);
    let n = 200_000;
    let mean: f64 = (0..n)
        .map(|_| 4.0 / 3.0 * std::f64::consts::PI * nial().sample(&mut rng).powi(3))
        .sum::<f64>()
        / n as f64;
    assert!(
        (1751.0 * mean / specimen - 0.62).abs() < 0.62 * 0.015,
        "sampled fraction {}",
        1751.0 * mean / specimen
    );
}

/// Condition 3: the upper bound 9.25 µm is the untruncated quantile 1 − 1/1752,
/// z = 3.2531 standard deviations of ln r above the median.
#[test]
fn nial_largest_particle_is_the_expected_largest_of_1751() {
    let z = (9.25e-6f64 / MEDIAN).ln() / SIGMA;
    assert!((z - 3.2531).abs() < 2e-3, "z {z}");
}
