//! A uniform cell grid over sphere centres for the generators, keyed by integer
//! cell coordinates so it needs no bounds along open axes (a heap on an open floor
//! may spread without limit). Along a periodic axis the period is split into
//! `n = max(1, ⌊L / h⌋)` cells of width L/n ≥ h, and indices wrap.
//!
//! The hash map is only looked up, never iterated, so results do not depend on its
//! iteration order; within a cell, indices keep insertion order.

use crate::particles::Vec3;
use crate::space::Space;
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// Multiplicative hash of the three cell indices. SipHash's protection against
/// adversarial keys buys nothing here and cost a tenth of the deposition time.
#[derive(Default)]
pub(crate) struct CellHasher(u64);

impl Hasher for CellHasher {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        // Integer slices (the [i64; 3] key) arrive here as raw bytes in one call.
        for chunk in bytes.chunks(8) {
            let mut word = [0u8; 8];
            word[..chunk.len()].copy_from_slice(chunk);
            self.write_u64(u64::from_le_bytes(word));
        }
    }
    fn write_usize(&mut self, i: usize) {
        self.write_u64(i as u64);
    }
    fn write_i64(&mut self, i: i64) {
        self.write_u64(i as u64);
    }
    fn write_u64(&mut self, i: u64) {
        self.0 = (self.0.rotate_left(5) ^ i).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }
}

/// Particles hashed into cubic cells (periodic axes wrap), for the generators' and the
/// studies' neighbour queries.
pub struct CellGrid {
    /// Per axis: cell width and, along periodic axes, (lo, number of cells).
    width: [f64; 3],
    periodic: [Option<(f64, i64)>; 3],
    origin: [f64; 3],
    cells: HashMap<[i64; 3], Vec<usize>, BuildHasherDefault<CellHasher>>,
}

impl CellGrid {
    /// `min_width` must be at least the largest distance a query has to resolve
    /// per cell step (here: the largest contact distance).
    pub fn new(space: &Space, min_width: f64, origin_z: f64) -> Self {
        let mut width = [min_width; 3];
        let mut periodic = [None; 3];
        let mut origin = [0.0, 0.0, origin_z];
        for k in 0..3 {
            if let Some((lo, length)) = space.periodic[k] {
                let n = ((length / min_width).floor() as i64).max(1);
                width[k] = length / n as f64;
                periodic[k] = Some((lo, n));
                origin[k] = lo;
            }
        }
        CellGrid {
            width,
            periodic,
            origin,
            cells: HashMap::default(),
        }
    }

    fn index(&self, k: usize, x: f64) -> i64 {
        let i = ((x - self.origin[k]) / self.width[k]).floor() as i64;
        match self.periodic[k] {
            Some((_, n)) => i.rem_euclid(n),
            None => i,
        }
    }

    fn cell_of(&self, x: &Vec3) -> [i64; 3] {
        [
            self.index(0, x[0]),
            self.index(1, x[1]),
            self.index(2, x[2]),
        ]
    }

    /// The z layer holding height z.
    pub(crate) fn layer_of(&self, z: f64) -> i64 {
        self.index(2, z)
    }

    /// Lower edge of the z layer `layer`.
    pub(crate) fn layer_bottom(&self, layer: i64) -> f64 {
        self.origin[2] + layer as f64 * self.width[2]
    }

    /// Files the particle `id` at `x` in its cell.
    pub fn insert(&mut self, x: &Vec3, id: usize) {
        let key = self.cell_of(x);
        self.cells.entry(key).or_default().push(id);
    }

    /// Cell indices along axis k covering [x − reach, x + reach], each once.
    fn span(&self, k: usize, x: f64, reach: f64) -> Vec<i64> {
        let raw = |y: f64| ((y - self.origin[k]) / self.width[k]).floor() as i64;
        let (a, b) = (raw(x - reach), raw(x + reach));
        match self.periodic[k] {
            Some((_, n)) if b - a + 1 >= n => (0..n).collect(),
            Some((_, n)) => (a..=b).map(|i| i.rem_euclid(n)).collect(),
            None => (a..=b).collect(),
        }
    }

    /// Ids in the cells covering the axis-aligned box x ± reach (a superset of the
    /// ids within distance `reach`), in a fixed order.
    pub fn near(&self, x: &Vec3, reach: f64, out: &mut Vec<usize>) {
        out.clear();
        let (sx, sy, sz) = (
            self.span(0, x[0], reach),
            self.span(1, x[1], reach),
            self.span(2, x[2], reach),
        );
        for i in &sx {
            for j in &sy {
                for k in &sz {
                    if let Some(ids) = self.cells.get(&[*i, *j, *k]) {
                        out.extend_from_slice(ids);
                    }
                }
            }
        }
    }

    /// Ids in one z layer of the cells whose columns cover (x, y) ± reach.
    pub(crate) fn column_layer(&self, x: &Vec3, reach: f64, layer: i64, out: &mut Vec<usize>) {
        out.clear();
        let (sx, sy) = (self.span(0, x[0], reach), self.span(1, x[1], reach));
        for i in &sx {
            for j in &sy {
                if let Some(ids) = self.cells.get(&[*i, *j, layer]) {
                    out.extend_from_slice(ids);
                }
            }
        }
    }
}
