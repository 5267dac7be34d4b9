//! One uniform grid level and the pair search over a stack of levels, shared by the
//! linked-cell detector (one level) and the multigrid detector of He, Dong & Zhou
//! 2007 (one level per size class).
//!
//! A level bins its particles into cells by a counting sort into flat arrays
//! (`start[c]..start[c + 1]` indexes the level's slots), and keeps a copy of each
//! particle's centre and radius in slot order so the search streams contiguous
//! memory instead of jumping through the particle arrays.
//!
//! The search rule, which every caller must respect when it chooses cell edges:
//! a particle of level `a` looks for partners in level `a` itself and in every
//! coarser level `b > a`, in the 3×3×3 block of cells around its own position in
//! level `b`. That block holds every partner in `b` provided level `b`'s cell edge is
//! at least `r_i + r_j + margin` for every particle `i` of a level `≤ b` and `j` of
//! `b`. A cross-level pair is then met once, from its finer member; a same-level pair
//! twice, and kept from the member with the lower slot.
//!
//! Along an open axis the grid covers the bounding box of the level's members; a
//! query from a finer level may fall outside it, and the 3-cell block is clipped.
//! Along a periodic axis `(lo, L)` the grid covers exactly `[lo, lo + L)` with
//! `max(1, ⌊L / cell⌋)` cells of edge `L / dims ≥ cell`, and the block wraps round;
//! with fewer than three cells the wrapped block would name a cell twice, so its
//! distinct cells are listed instead. Distances are the minimum image
//! (`Space::displacement`), unique because the scene keeps every reach below L/2.

use crate::particles::Vec3;
use crate::space::Space;

/// Relative widening of every cell edge, so that rounding in `(x - lo) / edge` can
/// never put two centres closer than the reach into cells two apart (the rounding
/// error is a few ulp of the cell coordinate, far below 1e-8 while coordinates stay
/// below ~1e7 cells from `lo`).
const EDGE_SAFETY: f64 = 1.0 + 1e-8;

#[derive(Clone, Copy, Debug)]
struct Axis {
    lo: f64,
    edge: f64,
    dims: usize,
    /// `Some(L)` along a periodic axis.
    period: Option<f64>,
}

impl Axis {
    fn new(cell: f64, periodic: Option<(f64, f64)>, lo: f64, hi: f64) -> Axis {
        match periodic {
            Some((lo, length)) => {
                let dims = ((length / cell).floor() as usize).max(1);
                Axis {
                    lo,
                    edge: length / dims as f64,
                    dims,
                    period: Some(length),
                }
            }
            None => Axis {
                lo,
                edge: cell,
                dims: (((hi - lo) / cell).floor() as usize).saturating_add(1),
                period: None,
            },
        }
    }

    /// The cell coordinate of `x`: along an open axis not clamped (a query from
    /// another level may lie outside the box), along a periodic axis wrapped into
    /// `[0, dims)`; the clamp catches `x - lo` rounding to exactly `L`.
    #[inline]
    fn coordinate(&self, x: f64) -> i64 {
        match self.period {
            None => ((x - self.lo) / self.edge).floor() as i64,
            Some(length) => {
                let c = ((x - self.lo).rem_euclid(length) / self.edge) as i64;
                c.clamp(0, self.dims as i64 - 1)
            }
        }
    }

    /// The distinct cells within one of coordinate `c`, ascending except across a
    /// periodic wrap.
    #[inline]
    fn block(&self, c: i64) -> ([usize; 3], usize) {
        let d = self.dims as i64;
        let mut cells = [0usize; 3];
        let mut count = 0;
        match self.period {
            None => {
                for k in c.saturating_sub(1).max(0)..=c.saturating_add(1).min(d - 1) {
                    cells[count] = k as usize;
                    count += 1;
                }
            }
            Some(_) if d < 3 => {
                for k in 0..d {
                    cells[count] = k as usize;
                    count += 1;
                }
            }
            Some(_) => {
                cells = [
                    ((c - 1).rem_euclid(d)) as usize,
                    c as usize,
                    ((c + 1) % d) as usize,
                ];
                count = 3;
            }
        }
        (cells, count)
    }
}

/// One grid level: its particles binned into cells of one edge.
#[derive(Clone, Debug)]
pub(crate) struct Level {
    axes: [Axis; 3],
    /// `start[c]..start[c + 1]`: the slots of cell `c`.
    start: Vec<usize>,
    /// Particle id of each slot.
    id: Vec<u32>,
    centre: Vec<Vec3>,
    radius: Vec<f64>,
}

impl Level {
    /// Bin `members` (particle ids) into cells of edge at least `cell`. The edge is
    /// doubled until the level has at most `max_cells` cells, so a sparse cloud in a
    /// large box cannot exhaust memory; coarser cells only cost more candidates.
    pub(crate) fn build(
        members: &[u32],
        position: &[Vec3],
        radius: &[f64],
        cell: f64,
        space: &Space,
        max_cells: usize,
    ) -> Level {
        debug_assert!(!members.is_empty());
        let mut lo = Vec3::repeat(f64::INFINITY);
        let mut hi = Vec3::repeat(f64::NEG_INFINITY);
        for &i in members {
            lo = lo.inf(&position[i as usize]);
            hi = hi.sup(&position[i as usize]);
        }
        let mut cell = (cell * EDGE_SAFETY).max(f64::MIN_POSITIVE);
        let axes = loop {
            let axes = [0, 1, 2].map(|k| Axis::new(cell, space.periodic[k], lo[k], hi[k]));
            let total = axes.iter().fold(1usize, |n, a| n.saturating_mul(a.dims));
            if total <= max_cells.max(1) {
                break axes;
            }
            cell *= 2.0;
        };
        let mut level = Level {
            axes,
            start: Vec::new(),
            id: vec![0; members.len()],
            centre: vec![Vec3::zeros(); members.len()],
            radius: vec![0.0; members.len()],
        };
        let ncell = axes[0].dims * axes[1].dims * axes[2].dims;
        let home: Vec<usize> = members
            .iter()
            .map(|&i| level.home(&position[i as usize]))
            .collect();
        let mut start = vec![0usize; ncell + 1];
        for &c in &home {
            start[c + 1] += 1;
        }
        for c in 0..ncell {
            start[c + 1] += start[c];
        }
        let mut fill = start.clone();
        for (&i, &c) in members.iter().zip(&home) {
            let slot = fill[c];
            fill[c] += 1;
            level.id[slot] = i;
            level.centre[slot] = position[i as usize];
            level.radius[slot] = radius[i as usize];
        }
        level.start = start;
        level
    }

    fn flat(&self, c: [usize; 3]) -> usize {
        c[0] + self.axes[0].dims * (c[1] + self.axes[1].dims * c[2])
    }

    /// The cell a member is stored in (its own coordinate, inside the grid).
    fn home(&self, x: &Vec3) -> usize {
        self.flat([0, 1, 2].map(|k| {
            let a = &self.axes[k];
            a.coordinate(x[k]).clamp(0, a.dims as i64 - 1) as usize
        }))
    }

    /// Call `visit` with the slot range of every cell of the block around `x`.
    /// Cells adjacent along x are adjacent in memory, so an unwrapped run along x is
    /// one range.
    #[inline]
    fn for_each_near(&self, x: &Vec3, mut visit: impl FnMut(std::ops::Range<usize>)) {
        let [bx, by, bz] = [0, 1, 2].map(|k| self.axes[k].block(self.axes[k].coordinate(x[k])));
        for &cz in &bz.0[..bz.1] {
            for &cy in &by.0[..by.1] {
                let row = self.flat([0, cy, cz]);
                let xs = &bx.0[..bx.1];
                let mut k = 0;
                while k < xs.len() {
                    let first = xs[k];
                    let mut last = first;
                    while k + 1 < xs.len() && xs[k + 1] == last + 1 {
                        k += 1;
                        last += 1;
                    }
                    k += 1;
                    let range = self.start[row + first]..self.start[row + last + 1];
                    if !range.is_empty() {
                        visit(range);
                    }
                }
            }
        }
    }
}

/// All pairs closer than `margin` between surfaces, from levels ordered fine to
/// coarse that respect the search rule of the module doc; sorted, no duplicates.
pub(crate) fn pairs(levels: &[Level], margin: f64, space: &Space) -> Vec<(u32, u32)> {
    if space.is_periodic() {
        search::<true>(levels, margin, space)
    } else {
        search::<false>(levels, margin, space)
    }
}

/// `WRAP` lifts the minimum-image branch out of the innermost loop when no axis is
/// periodic; both forms give bit-identical distances to brute force.
fn search<const WRAP: bool>(levels: &[Level], margin: f64, space: &Space) -> Vec<(u32, u32)> {
    let mut pairs = Vec::new();
    for (a, own) in levels.iter().enumerate() {
        for s in 0..own.id.len() {
            let (x, r, i) = (own.centre[s], own.radius[s], own.id[s]);
            for (b, other) in levels.iter().enumerate().skip(a) {
                let same = a == b;
                other.for_each_near(&x, |range| {
                    // Same level: keep a pair from its lower slot only.
                    let from = if same {
                        range.start.max(s + 1)
                    } else {
                        range.start
                    };
                    for t in from..range.end {
                        let d = if WRAP {
                            space.displacement(&x, &other.centre[t])
                        } else {
                            x - other.centre[t]
                        };
                        let reach = r + other.radius[t] + margin;
                        if d.norm_squared() < reach * reach {
                            let j = other.id[t];
                            pairs.push((i.min(j), i.max(j)));
                        }
                    }
                });
            }
        }
    }
    pairs.sort_unstable();
    pairs
}
