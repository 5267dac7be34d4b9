//! One uniform grid level and the pair search over a stack of levels, shared by the
//! linked-cell detector (one level) and the multigrid detector of He, Dong & Zhou
//! 2007 (one level per size class).
//!
//! A level bins its particles into cells by a counting sort into flat arrays
//! (`start[c]..start[c + 1]` indexes the level's slots), and keeps a copy of each
//! particle's centre and radius in slot order so the search streams contiguous
//! memory instead of jumping through the particle arrays.
//!
//! Search. A particle `i` of level `a` looks for partners in level `a` itself and in
//! every coarser level `b > a`, in the cells that overlap the cube of half-width
//! `r_i + R_b + margin` around its centre (`R_b` the largest radius in `b`). That
//! holds every partner whatever the cell edge; the edge only sets the cost. With an
//! edge of at least `2 R_b + margin` and `r_i ≤ R_b` the cube spans at most three
//! cells per axis, and about `1 + 2 (r_i + R_b + margin) / edge` on average — so a
//! small particle looking into a much coarser level visits about 8 cells, not 27. A
//! cross-level pair is met once, from its finer member; a same-level pair twice,
//! and kept from the member with the lower slot.
//!
//! Along an open axis the grid covers the bounding box of the level's members; a
//! query from a finer level may fall outside it, and its range is clipped. Along a
//! periodic axis `(lo, L)` the grid covers exactly `[lo, lo + L)` with
//! `max(1, ⌊L / cell⌋)` cells of edge `L / dims ≥ cell`, and the range wraps round;
//! when it would cover the whole axis (few cells) each cell is listed once.
//! Distances are the minimum image (`Space::displacement`), unique because the scene
//! keeps every reach below L/2.

pub(crate) use crate::bins::counting_sort;
use crate::particles::Vec3;
use crate::space::Space;

/// Cap on the number of cells of one search, so a sparse cloud in a large box
/// cannot exhaust memory (levels coarsen instead; see [`Level::build`]).
pub(crate) const MAX_CELLS: usize = 1 << 22;

/// Relative widening of the search reach, so that rounding in `(x - lo) / edge`
/// cannot leave out the cell of a partner at a distance a few ulp below the reach
/// (the rounding is a few ulp of the coordinate; 1e-8 covers coordinates up to
/// ~1e7 reaches from `lo`).
const REACH_SAFETY: f64 = 1.0 + 1e-8;

/// `⌊v⌋` as an integer (saturating, NaN → 0). `f64::floor` is a library call on
/// the baseline x86-64 target, and this sits in the innermost per-query code.
#[inline]
fn floor(v: f64) -> i64 {
    let t = v as i64;
    if (t as f64) > v { t - 1 } else { t }
}

#[derive(Clone, Copy, Debug)]
struct Axis {
    lo: f64,
    /// 1 / cell edge: cell coordinates are computed by multiplying, which is
    /// several times cheaper than dividing and runs six times per query.
    per_edge: f64,
    dims: usize,
    /// `Some(L)` along a periodic axis.
    period: Option<f64>,
}

/// Up to two runs of consecutive cells, as inclusive `(first, last)`; a periodic
/// range that wraps round is two runs.
type Runs = ([(usize, usize); 2], usize);

impl Axis {
    fn new(cell: f64, periodic: Option<(f64, f64)>, lo: f64, hi: f64) -> Axis {
        match periodic {
            Some((lo, length)) => {
                let dims = ((length / cell).floor() as usize).max(1);
                Axis {
                    lo,
                    per_edge: dims as f64 / length,
                    dims,
                    period: Some(length),
                }
            }
            None => Axis {
                lo,
                per_edge: 1.0 / cell,
                dims: (((hi - lo) / cell).floor() as usize).saturating_add(1),
                period: None,
            },
        }
    }

    /// Distance of `x` from `lo`, taken modulo `L` along a periodic axis.
    #[inline]
    fn offset(&self, x: f64) -> f64 {
        match self.period {
            None => x - self.lo,
            Some(length) => {
                let u = x - self.lo;
                // Positions arrive wrapped; the library fmod is only paid otherwise.
                if (0.0..length).contains(&u) {
                    u
                } else {
                    u.rem_euclid(length)
                }
            }
        }
    }

    /// The cell a member at `x` is stored in. The clamp catches a periodic offset
    /// that rounds to exactly `L` (that cell's range still reaches round to cell 0).
    #[inline]
    fn home(&self, x: f64) -> usize {
        floor(self.offset(x) * self.per_edge).clamp(0, self.dims as i64 - 1) as usize
    }

    /// The cells overlapping `[x - reach, x + reach]`, each once.
    #[inline]
    fn runs(&self, x: f64, reach: f64) -> Runs {
        let u = self.offset(x);
        let first = floor((u - reach) * self.per_edge);
        let last = floor((u + reach) * self.per_edge);
        let d = self.dims as i64;
        let mut runs = [(0, 0); 2];
        let count = match self.period {
            None => {
                let (a, b) = (first.max(0), last.min(d - 1));
                runs[0] = (a as usize, b as usize);
                usize::from(a <= b)
            }
            Some(_) if last.saturating_sub(first) >= d - 1 => {
                runs[0] = (0, self.dims - 1);
                1
            }
            Some(_) => {
                let (a, b) = (first.rem_euclid(d) as usize, last.rem_euclid(d) as usize);
                if a <= b {
                    runs[0] = (a, b);
                    1
                } else {
                    runs = [(0, b), (a, self.dims - 1)];
                    2
                }
            }
        };
        (runs, count)
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
    /// Largest radius in the level: sets how far a query must look into it.
    r_max: f64,
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
        let mut r_max = 0.0f64;
        for &i in members {
            lo = lo.inf(&position[i as usize]);
            hi = hi.sup(&position[i as usize]);
            r_max = r_max.max(radius[i as usize]);
        }
        let mut cell = cell.max(f64::MIN_POSITIVE);
        let axes = loop {
            let axes = [0, 1, 2].map(|k| Axis::new(cell, space.periodic[k], lo[k], hi[k]));
            let total = axes.iter().fold(1usize, |n, a| n.saturating_mul(a.dims));
            if total <= max_cells.max(1) {
                break axes;
            }
            cell *= 2.0;
        };
        let flat = |c: [usize; 3]| c[0] + axes[0].dims * (c[1] + axes[1].dims * c[2]);
        let home: Vec<usize> = members
            .iter()
            .map(|&i| flat([0, 1, 2].map(|k| axes[k].home(position[i as usize][k]))))
            .collect();
        let ncell = axes[0].dims * axes[1].dims * axes[2].dims;
        let (start, order) = counting_sort(&home, ncell);
        let id: Vec<u32> = order.iter().map(|&m| members[m as usize]).collect();
        Level {
            axes,
            start,
            centre: id.iter().map(|&i| position[i as usize]).collect(),
            radius: id.iter().map(|&i| radius[i as usize]).collect(),
            id,
            r_max,
        }
    }

    /// Call `visit` with the slot range of every cell overlapping the cube of
    /// half-width `reach` around `x`, each cell once. Cells adjacent along x are
    /// adjacent in memory, so a run along x is one range.
    #[inline]
    fn for_each_near(&self, x: &Vec3, reach: f64, mut visit: impl FnMut(std::ops::Range<usize>)) {
        let [rx, ry, rz] = [0, 1, 2].map(|k| self.axes[k].runs(x[k], reach));
        let [dx, dy] = [self.axes[0].dims, self.axes[1].dims];
        for &(z0, z1) in &rz.0[..rz.1] {
            for cz in z0..=z1 {
                for &(y0, y1) in &ry.0[..ry.1] {
                    for cy in y0..=y1 {
                        let row = dx * (cy + dy * cz);
                        for &(x0, x1) in &rx.0[..rx.1] {
                            let range = self.start[row + x0]..self.start[row + x1 + 1];
                            if !range.is_empty() {
                                visit(range);
                            }
                        }
                    }
                }
            }
        }
    }
}

/// All pairs closer than `margin` between surfaces, from levels ordered fine to
/// coarse (see the module doc); sorted, no duplicates.
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
                let look = (r + other.r_max + margin) * REACH_SAFETY;
                other.for_each_near(&x, look, |range| {
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
    sort_pairs(pairs)
}

/// The pairs (i < j, no duplicates) in lexicographic order: a counting sort by i,
/// then each i's few partners sorted by j. The same list `sort_unstable` makes
/// (a sorted list of distinct pairs is unique), in time linear in the pairs
/// instead of a comparison sort of the whole list.
fn sort_pairs(pairs: Vec<(u32, u32)>) -> Vec<(u32, u32)> {
    let Some(n) = pairs.iter().map(|&(i, _)| i as usize + 1).max() else {
        return pairs;
    };
    let mut start = vec![0usize; n + 1];
    for &(i, _) in &pairs {
        start[i as usize + 1] += 1;
    }
    for b in 0..n {
        start[b + 1] += start[b];
    }
    let mut fill = start.clone();
    let mut sorted = vec![(0u32, 0u32); pairs.len()];
    for &(i, j) in &pairs {
        let slot = &mut fill[i as usize];
        sorted[*slot] = (i, j);
        *slot += 1;
    }
    for b in 0..n {
        let run = &mut sorted[start[b]..start[b + 1]];
        if run.len() > 1 {
            run.sort_unstable_by_key(|&(_, j)| j);
        }
    }
    sorted
}

#[cfg(test)]
mod sort_tests {
    use super::*;

    #[test]
    fn pairs_come_out_as_sort_unstable_leaves_them() {
        let mut state = 12345u64;
        let mut next = |m: u32| {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 33) % m as u64) as u32
        };
        let mut pairs = Vec::new();
        for _ in 0..5000 {
            let (a, b) = (next(300), next(300));
            if a != b && !pairs.contains(&(a.min(b), a.max(b))) {
                pairs.push((a.min(b), a.max(b)));
            }
        }
        let mut expected = pairs.clone();
        expected.sort_unstable();
        assert_eq!(sort_pairs(pairs), expected);
        assert!(sort_pairs(Vec::new()).is_empty());
    }
}
