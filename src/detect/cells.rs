//! Linked-cell broad phase: particles are binned into cubic cells of edge
//! ≥ 2 R_max + margin, so each particle's partners lie in its own or the 26
//! neighbouring cells. O(N) for narrow size distributions; for wide ones the cell
//! size is set by the largest particle and the cost grows with the size ratio
//! (the multigrid detector of He, Dong & Zhou 2007 removes that dependence).

use crate::particles::Vec3;

/// Cap on the number of cells so a sparse cloud in a large box cannot exhaust memory.
const MAX_CELLS: usize = 1 << 22;

pub fn candidate_pairs(position: &[Vec3], radius: &[f64], margin: f64) -> Vec<(u32, u32)> {
    let n = position.len();
    if n < 2 {
        return Vec::new();
    }
    let r_max = radius.iter().cloned().fold(0.0, f64::max);
    let mut lo = position[0];
    let mut hi = position[0];
    for p in position {
        lo = lo.inf(p);
        hi = hi.sup(p);
    }
    let extent = hi - lo;
    let mut cell = (2.0 * r_max + margin).max(f64::MIN_POSITIVE);
    let dims = |cell: f64| -> [usize; 3] {
        [0, 1, 2].map(|k| ((extent[k] / cell).floor() as usize).saturating_add(1))
    };
    let mut d = dims(cell);
    while d[0].saturating_mul(d[1]).saturating_mul(d[2]) > MAX_CELLS {
        cell *= 2.0;
        d = dims(cell);
    }
    let index = |p: &Vec3| -> [usize; 3] {
        [0, 1, 2].map(|k| (((p[k] - lo[k]) / cell) as usize).min(d[k] - 1))
    };
    let flat = |c: [usize; 3]| c[0] + d[0] * (c[1] + d[1] * c[2]);

    // Counting sort of particle ids by cell: `start[c]..start[c+1]` indexes `sorted`.
    let ncell = d[0] * d[1] * d[2];
    let cell_of: Vec<usize> = position.iter().map(|p| flat(index(p))).collect();
    let mut start = vec![0usize; ncell + 1];
    for &c in &cell_of {
        start[c + 1] += 1;
    }
    for c in 0..ncell {
        start[c + 1] += start[c];
    }
    let mut fill = start.clone();
    let mut sorted = vec![0u32; n];
    for (i, &c) in cell_of.iter().enumerate() {
        sorted[fill[c]] = i as u32;
        fill[c] += 1;
    }

    let mut pairs = Vec::new();
    for i in 0..n {
        let c = index(&position[i]);
        for dz in -1i64..=1 {
            for dy in -1i64..=1 {
                for dx in -1i64..=1 {
                    let nb = [c[0] as i64 + dx, c[1] as i64 + dy, c[2] as i64 + dz];
                    if (0..3).any(|k| nb[k] < 0 || nb[k] >= d[k] as i64) {
                        continue;
                    }
                    let f = flat([nb[0] as usize, nb[1] as usize, nb[2] as usize]);
                    for &j in &sorted[start[f]..start[f + 1]] {
                        let j = j as usize;
                        if j <= i {
                            continue;
                        }
                        let reach = radius[i] + radius[j] + margin;
                        if (position[i] - position[j]).norm_squared() < reach * reach {
                            pairs.push((i as u32, j as u32));
                        }
                    }
                }
            }
        }
    }
    pairs.sort_unstable();
    pairs
}
