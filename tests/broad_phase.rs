//! The fast detectors (linked cells, multigrid) find exactly the pairs brute force
//! finds, on random polydisperse clouds — size ratios 1 to 50, log-uniform or
//! bidisperse radii, dense and sparse, any margin — in open space and with any
//! subset of the axes periodic; plus deterministic edge cases.

use proptest::prelude::*;
use tamp::detect::{Detector, brute};
use tamp::particles::Vec3;
use tamp::space::Space;

const R_MIN: f64 = 0.05;

#[derive(Debug, Clone)]
struct Cloud {
    position: Vec<Vec3>,
    radius: Vec<f64>,
    margin: f64,
    space: Space,
}

/// A periodic length must exceed 2·(2 R_max + margin) for the minimum image to be
/// the only image in reach. It is taken from the largest radius the cloud may have;
/// when the drawn box is smaller the period sits just above that bound, which gives
/// grids of two or three cells along the axis (the deduplication case).
fn cloud() -> impl Strategy<Value = Cloud> {
    (
        2usize..300,
        1.0f64..50.0,
        0.5f64..30.0,
        0.0f64..0.5,
        0u8..8,
        any::<bool>(),
        -5.0f64..5.0,
    )
        .prop_flat_map(
            |(n, ratio, box_size, margin, periodic_axes, bidisperse, lo)| {
                let r_max = R_MIN * ratio;
                let min_period = 2.0 * (2.0 * r_max + margin) * 1.0001;
                let space = Space {
                    periodic: [0, 1, 2].map(|k| {
                        (periodic_axes >> k & 1 == 1).then_some((lo, box_size.max(min_period)))
                    }),
                };
                let radius = prop::collection::vec(0.0f64..1.0, n).prop_map(move |u| {
                    u.into_iter()
                        .map(|u| {
                            if bidisperse {
                                if u < 0.5 { R_MIN } else { r_max }
                            } else {
                                R_MIN * ratio.powf(u)
                            }
                        })
                        .collect::<Vec<f64>>()
                });
                let position = prop::collection::vec((0.0f64..1.0, 0.0f64..1.0, 0.0f64..1.0), n)
                    .prop_map(move |f| {
                        f.into_iter()
                            .map(|(a, b, c)| {
                                let f = [a, b, c];
                                Vec3::from_fn(|k, _| match space.periodic[k] {
                                    Some((lo, length)) => lo + f[k] * length,
                                    None => f[k] * box_size,
                                })
                            })
                            .collect::<Vec<Vec3>>()
                    });
                (position, radius).prop_map(move |(position, radius)| Cloud {
                    position,
                    radius,
                    margin,
                    space,
                })
            },
        )
}

/// Every fast detector against brute force.
fn assert_all_match(position: &[Vec3], radius: &[f64], margin: f64, space: &Space) {
    let reference = brute::candidate_pairs(position, radius, margin, space);
    for detector in [Detector::Cells, Detector::Multigrid] {
        let found = detector.candidate_pairs(position, radius, margin, space);
        assert_eq!(found, reference, "{detector:?} differs from brute force");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]
    #[test]
    fn fast_detectors_match_brute_force(c in cloud()) {
        // proptest catches the assertion's panic and shrinks the cloud as usual.
        assert_all_match(&c.position, &c.radius, c.margin, &c.space);
    }
}

#[test]
fn coincident_centres_are_found() {
    let p = vec![Vec3::zeros(), Vec3::zeros(), Vec3::new(10.0, 0.0, 0.0)];
    let r = vec![1.0, 1.0, 1.0];
    for space in [
        Space::open(),
        Space {
            periodic: [Some((-6.0, 12.5)), None, Some((-6.0, 12.5))],
        },
    ] {
        assert_eq!(brute::candidate_pairs(&p, &r, 0.0, &space), vec![(0, 1)]);
        assert_all_match(&p, &r, 0.0, &space);
    }
}

/// Centres on the periodic face itself, including one at lo + L (which the
/// simulation's wrap never produces, but rounding could) — it is the same point as lo.
#[test]
fn particles_on_the_periodic_face() {
    let space = Space {
        periodic: [Some((0.0, 10.0)), Some((-1.0, 10.0)), None],
    };
    let p = vec![
        Vec3::new(10.0, 9.0, 0.0),  // x at lo + L, y at lo + L
        Vec3::new(0.1, -1.0, 0.0),  // x near lo, y at lo
        Vec3::new(9.95, 8.95, 0.0), // just inside the upper faces
        Vec3::new(0.0, 4.0, 0.0),   // x at lo, far in y
        Vec3::new(5.0, 4.0, 0.0),
    ];
    let r = vec![0.1; p.len()];
    let expected = vec![(0, 1), (0, 2), (1, 2)];
    assert_eq!(brute::candidate_pairs(&p, &r, 0.0, &space), expected);
    assert_all_match(&p, &r, 0.0, &space);
}

/// One sphere 500 times larger than a cloud of tiny ones: the huge one touches many,
/// and in periodic space it reaches round the faces.
#[test]
fn huge_particle_among_tiny_ones() {
    let mut p = vec![Vec3::new(3.0, 15.0, 15.0)];
    let mut r = vec![5.0];
    // Deterministic scatters (golden-ratio sequences) so the test needs no RNG: half
    // through the box, half in a thin shell on the big sphere's surface.
    let phi = [
        0.618_033_988_749_895,
        0.754_877_666_246_693,
        0.569_840_290_998_053,
    ];
    for k in 1..=1500 {
        p.push(Vec3::from_fn(|a, _| (k as f64 * phi[a]).fract() * 30.0));
        r.push(0.01);
    }
    for k in 0..1500 {
        let z = 1.0 - 2.0 * (k as f64 + 0.5) / 1500.0;
        let angle = k as f64 * std::f64::consts::TAU * phi[0];
        let along = Vec3::new(
            (1.0 - z * z).sqrt() * angle.cos(),
            (1.0 - z * z).sqrt() * angle.sin(),
            z,
        );
        let distance = 5.0 + 0.05 * (k as f64 * phi[1]).fract();
        let mut x = p[0] + distance * along;
        x[0] = x[0].rem_euclid(30.0);
        p.push(x);
        r.push(0.01);
    }
    for space in [
        Space::open(),
        Space {
            periodic: [Some((0.0, 30.0)), Some((0.0, 30.0)), Some((0.0, 30.0))],
        },
    ] {
        let reference = brute::candidate_pairs(&p, &r, 0.02, &space);
        assert!(reference.iter().filter(|&&(i, _)| i == 0).count() > 100);
        assert_all_match(&p, &r, 0.02, &space);
    }
}

/// Two tight groups a billion radii apart: the grids must coarsen instead of
/// allocating a cell per radius across the gap.
#[test]
fn sparse_cloud_stays_within_the_cell_cap() {
    let p = vec![
        Vec3::new(0.0, 0.0, 0.0),
        Vec3::new(1.0, 0.0, 0.0),
        Vec3::new(1e9, 1e9, 1e9),
        Vec3::new(1e9, 1e9 + 1.0, 1e9),
    ];
    let r = vec![1.0, 0.1, 1.0, 0.001];
    assert_all_match(&p, &r, 0.0, &Space::open());
    assert_eq!(
        Detector::Multigrid.candidate_pairs(&p, &r, 0.0, &Space::open()),
        vec![(0, 1), (2, 3)]
    );
}
