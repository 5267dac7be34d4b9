//! Random sequential insertion (RSI): a sphere's centre is drawn uniformly in an
//! axis-aligned box shrunk by its radius, so the whole sphere lies inside, and the
//! draw is kept only if the sphere is clear of every sphere already present and of
//! the boundaries; otherwise it is drawn again. RSI jams near φ ≈ 0.38 for equal
//! spheres (Widom 1966; Torquato, Uche & Stillinger 2006 give 0.3841), so dense beds
//! are made by inserting small (a growth stage) or by pouring and settling.
//!
//! `scale` multiplies the radii in the clearance test: 1 for spheres placed at full
//! size, the initial fraction f₀ for a growth stage (0: any position is accepted, as
//! in Zhong 2009 §6.1 where particles start from zero radius).

use super::grid::CellGrid;
use crate::particles::Vec3;
use crate::space::Space;
use rand::RngExt;
use rand_chacha::ChaCha8Rng;

/// An insertion region: the box [lower, upper] that must contain whole spheres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InsertionBox {
    /// Lower corner, m.
    pub lower: Vec3,
    /// Upper corner, m.
    pub upper: Vec3,
}

impl InsertionBox {
    /// A centre drawn uniformly where a sphere of radius r fits; on an axis narrower
    /// than the sphere the centre sits midway.
    pub fn draw(&self, r: f64, rng: &mut ChaCha8Rng) -> Vec3 {
        Vec3::from_fn(|a, _| {
            let (from, to) = (self.lower[a] + r, self.upper[a] - r);
            if from < to {
                rng.random_range(from..=to)
            } else {
                0.5 * (self.lower[a] + self.upper[a])
            }
        })
    }
}

/// The spheres already placed, held in a cell grid so that a candidate is tested
/// against the spheres near it only: a draw costs O(1) instead of O(N), and a bed
/// of N spheres O(N) instead of O(N²). The grid returns a superset of the spheres
/// within reach and the test is the same inequality, so the accepted positions are
/// those of the all-pairs test, bit for bit.
pub struct Placed {
    /// Sphere centres, m.
    pub position: Vec<Vec3>,
    /// Sphere radii, m.
    pub radius: Vec<f64>,
    grid: CellGrid,
    space: Space,
    largest: f64,
    near: Vec<usize>,
    pair_tests: u64,
}

impl Placed {
    /// An empty set in `space`; `cell` is the grid's cell width, best about the
    /// largest diameter the set will hold (any positive width gives the same result).
    pub fn new(space: &Space, cell: f64) -> Self {
        Placed {
            position: Vec::new(),
            radius: Vec::new(),
            grid: CellGrid::new(space, cell, 0.0),
            space: *space,
            largest: 0.0,
            near: Vec::new(),
            pair_tests: 0,
        }
    }

    /// The spheres (x, r) already present, with a cell sized for them and for
    /// spheres up to `largest_to_come`.
    pub fn with(space: &Space, position: &[Vec3], radius: &[f64], largest_to_come: f64) -> Self {
        let largest = radius.iter().copied().fold(largest_to_come, f64::max);
        let mut placed = Placed::new(space, 2.0 * largest);
        for (x, &r) in position.iter().zip(radius) {
            placed.add(*x, r);
        }
        placed
    }

    /// Add a sphere of centre x and radius r without a clearance test.
    pub fn add(&mut self, x: Vec3, r: f64) {
        self.grid.insert(&x, self.position.len());
        self.position.push(x);
        self.radius.push(r);
        self.largest = self.largest.max(r);
    }

    /// Whether a sphere of radius r at x keeps `scale` (r + r_q) from every sphere q.
    fn is_clear(&mut self, x: &Vec3, r: f64, scale: f64) -> bool {
        self.grid
            .near(x, scale * (r + self.largest), &mut self.near);
        self.pair_tests += self.near.len() as u64;
        self.near.iter().all(|&q| {
            self.space.displacement(x, &self.position[q]).norm() >= scale * (r + self.radius[q])
        })
    }

    /// Sphere pairs tested for clearance so far: the work of generation, which a
    /// test can hold to O(1) per draw without timing anything.
    pub fn pair_tests(&self) -> u64 {
        self.pair_tests
    }

    /// Try up to `attempts` positions for a sphere of radius r and add the first
    /// clear one; `None` when none is clear.
    pub fn place(
        &mut self,
        r: f64,
        region: &InsertionBox,
        clear_of_boundaries: &dyn Fn(&Vec3, f64) -> bool,
        scale: f64,
        rng: &mut ChaCha8Rng,
        attempts: usize,
    ) -> Option<Vec3> {
        let x = (0..attempts).find_map(|_| {
            let x = region.draw(r, rng);
            let clear =
                scale == 0.0 || (self.is_clear(&x, r, scale) && clear_of_boundaries(&x, scale * r));
            clear.then_some(x)
        })?;
        self.add(x, r);
        Some(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    /// The grid must accept exactly the positions the all-pairs test accepts, also
    /// across periodic boundaries and for a wide size ratio.
    #[test]
    fn grid_accepts_what_the_all_pairs_test_accepts() {
        let space = Space {
            periodic: [Some((0.0, 1.0)), None, Some((-0.5, 0.7))],
        };
        let region = InsertionBox {
            lower: Vec3::new(0.0, 0.0, -0.5),
            upper: Vec3::new(1.0, 1.0, 0.2),
        };
        let mut rng = ChaCha8Rng::seed_from_u64(11);
        let mut placed = Placed::new(&space, 0.02);
        for k in 0..3000 {
            let r = if k % 10 == 0 { 0.08 } else { 0.008 };
            let mut probe = rng.clone();
            let x = region.draw(r, &mut probe);
            let all_pairs = placed
                .position
                .iter()
                .zip(&placed.radius)
                .all(|(q, rq)| space.displacement(&x, q).norm() >= 0.9 * (r + rq));
            let grid = placed.place(r, &region, &|_, _| true, 0.9, &mut rng, 1);
            assert_eq!(grid.is_some(), all_pairs, "draw {k}");
        }
        assert!(
            placed.position.len() > 500,
            "the test must exercise a full region"
        );
    }

    #[test]
    fn placed_spheres_are_inside_and_apart() {
        let region = InsertionBox {
            lower: Vec3::zeros(),
            upper: Vec3::new(1.0, 1.0, 1.0),
        };
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let mut placed = Placed::new(&Space::open(), 0.1);
        for _ in 0..200 {
            placed
                .place(0.05, &region, &|_, _| true, 1.0, &mut rng, 10_000)
                .expect("φ ≈ 0.1 is far from jamming");
        }
        let pos = placed.position;
        for (i, a) in pos.iter().enumerate() {
            assert!(a.iter().all(|c| (0.05..=0.95).contains(c)));
            for b in &pos[..i] {
                assert!((a - b).norm() >= 0.1);
            }
        }
    }
}
