//! The measures end to end through the public API, on a random packing in a
//! periodic box where an independent answer exists: for non-overlapping balls the
//! packing fraction of a region is the probability that a uniform random point of the
//! region lies in some ball (by minimum image), which Monte Carlo estimates without
//! any of the intersection formulas or the image bookkeeping.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use tamp::detect::brute::candidate_pairs;
use tamp::measure::{
    CoordinationOptions, PlaneProfile, Region, coordination, packing_fraction, plane_wall_profile,
    rve_packing_fraction,
};
use tamp::particles::Vec3;
use tamp::space::Space;

const L: f64 = 1.0;

/// Random sequential addition of non-overlapping balls (radii 0.04–0.08) in a
/// periodic unit cube until `n` are placed.
fn rsa_packing(n: usize, seed: u64) -> (Vec<Vec3>, Vec<f64>, Space) {
    let space = Space {
        periodic: [Some((0.0, L)); 3],
    };
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut x: Vec<Vec3> = Vec::new();
    let mut r: Vec<f64> = Vec::new();
    while x.len() < n {
        let c = Vec3::new(
            rng.random_range(0.0..L),
            rng.random_range(0.0..L),
            rng.random_range(0.0..L),
        );
        let rc = rng.random_range(0.04..0.08);
        if x.iter()
            .zip(&r)
            .all(|(p, rp)| space.displacement(&c, p).norm() >= rc + rp)
        {
            x.push(c);
            r.push(rc);
        }
    }
    (x, r, space)
}

/// Point-in-union queries on a periodic grid of cells no smaller than the largest
/// radius, so a point needs only the 27 cells around its own.
struct Grid {
    cells: usize,
    members: Vec<Vec<usize>>,
}

impl Grid {
    fn new(x: &[Vec3], r_max: f64) -> Grid {
        let cells = (L / r_max).floor() as usize;
        let mut members = vec![Vec::new(); cells * cells * cells];
        for (i, c) in x.iter().enumerate() {
            members[Grid::index(cells, c)].push(i);
        }
        Grid { cells, members }
    }

    fn coords(cells: usize, p: &Vec3) -> [usize; 3] {
        let n = cells as f64;
        [0, 1, 2].map(|k| ((p[k].rem_euclid(L) / L * n) as usize).min(cells - 1))
    }

    fn index(cells: usize, p: &Vec3) -> usize {
        let [i, j, k] = Grid::coords(cells, p);
        (i * cells + j) * cells + k
    }

    fn in_some_ball(&self, p: &Vec3, x: &[Vec3], r: &[f64], space: &Space) -> bool {
        let n = self.cells;
        let [i, j, k] = Grid::coords(n, p);
        for di in [n - 1, 0, 1] {
            for dj in [n - 1, 0, 1] {
                for dk in [n - 1, 0, 1] {
                    let cell = (((i + di) % n) * n + (j + dj) % n) * n + (k + dk) % n;
                    for &b in &self.members[cell] {
                        if space.displacement(p, &x[b]).norm_squared() <= r[b] * r[b] {
                            return true;
                        }
                    }
                }
            }
        }
        false
    }
}

/// Regions straddling the periodic faces and longer than the cell: the exact
/// packing fraction against the Monte Carlo one, within 5 standard errors.
#[test]
fn measure_packing_fraction_matches_monte_carlo_point_sampling() {
    let (x, r, space) = rsa_packing(400, 5);
    let total: f64 = r
        .iter()
        .map(|r| 4.0 / 3.0 * std::f64::consts::PI * r.powi(3))
        .sum();
    let cell = Region::Box {
        lower: Vec3::repeat(0.0),
        upper: Vec3::repeat(L),
    };
    let phi_cell = packing_fraction(&x, &r, &cell, &space).unwrap();
    assert!((phi_cell - total).abs() < 1e-14, "{phi_cell} {total}");

    let regions = [
        Region::Box {
            lower: Vec3::new(-0.3, 0.6, 0.2),
            upper: Vec3::new(0.45, 1.3, 1.5),
        },
        Region::Cylinder {
            base: Vec3::new(0.9, 0.1, -0.2),
            axis: Vec3::new(0.3, 1.0, 0.6),
            radius: 0.35,
            height: 1.1,
        },
        Region::Sphere {
            centre: Vec3::new(0.05, 0.95, 0.5),
            radius: 0.42,
        },
    ];
    let grid = Grid::new(&x, 0.08);
    let mut rng = ChaCha8Rng::seed_from_u64(6);
    let points = 160_000;
    for region in regions {
        let exact = packing_fraction(&x, &r, &region, &space).unwrap();
        let (lo, hi) = region.bounding_box();
        let mut inside_region = 0usize;
        let mut solid = 0usize;
        while inside_region < points {
            let p = Vec3::new(
                rng.random_range(lo[0]..hi[0]),
                rng.random_range(lo[1]..hi[1]),
                rng.random_range(lo[2]..hi[2]),
            );
            if !region.contains_point(&p) {
                continue;
            }
            inside_region += 1;
            solid += grid.in_some_ball(&p, &x, &r, &space) as usize;
        }
        let estimate = solid as f64 / points as f64;
        let se = (exact * (1.0 - exact) / points as f64).sqrt();
        let z = (estimate - exact) / se;
        println!("{region:?}: exact {exact:.6}, MC {estimate:.6}, z {z:+.2}");
        assert!(
            z.abs() < 5.0,
            "{region:?}: exact {exact}, MC {estimate}, z {z}"
        );
        if let Region::Sphere { centre, radius } = region {
            let rve = rve_packing_fraction(&x, &r, &space, centre, radius).unwrap();
            assert_eq!(rve, exact);
        }
    }
}

/// The layer profile from a "wall" at z = 0.3 through the periodic bed, with slabs,
/// averages to the cell's packing fraction when the layers span one period.
#[test]
fn measure_slab_profile_spans_the_period() {
    let (x, r, space) = rsa_packing(300, 9);
    let cell = Region::Box {
        lower: Vec3::repeat(0.0),
        upper: Vec3::repeat(L),
    };
    let phi = packing_fraction(&x, &r, &cell, &space).unwrap();
    let spec = PlaneProfile {
        domain: Region::Slab {
            axis: 2,
            lo: 0.3,
            hi: 1.3,
        },
        axis: 2,
        wall: 0.3,
        positive_side: true,
        thickness: 0.1,
        layers: 10,
    };
    let layers = plane_wall_profile(&x, &r, &space, &spec).unwrap();
    let mean = layers.iter().map(|l| l.solid_fraction).sum::<f64>() / 10.0;
    assert!((mean - phi).abs() < 1e-14, "{mean} {phi}");
}

/// RSA packings have no touching pairs; with a tolerance wider than the closest gap
/// every near pair counts, and the count agrees with a direct O(N²) count.
#[test]
fn measure_coordination_matches_direct_count() {
    let (x, r, space) = rsa_packing(300, 12);
    let tol = 0.01;
    let pairs = candidate_pairs(&x, &r, 2.0 * tol, &space);
    let c = coordination(
        &x,
        &r,
        &space,
        &pairs,
        &CoordinationOptions {
            tolerance: tol,
            ..Default::default()
        },
    )
    .unwrap();
    let mut direct = 0usize;
    for i in 0..x.len() {
        for j in i + 1..x.len() {
            if space.displacement(&x[i], &x[j]).norm() - r[i] - r[j] < tol {
                direct += 2;
            }
        }
    }
    assert!(direct > 0);
    assert!((c.mean - direct as f64 / x.len() as f64).abs() < 1e-15);
    assert_eq!(c.histogram.iter().sum::<usize>(), x.len());
}
