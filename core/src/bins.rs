//! Items binned by an integer key into compressed lists: the items of bin b are
//! `order[start[b]..start[b + 1]]`, in their original order. Contact detection bins
//! particles into grid cells (detect/grid.rs) and size classes (detect/multigrid.rs);
//! a mesh bins its triangles into the cells their bounding boxes overlap
//! (boundary/shape/mesh.rs). All of them are built once and then only read, which is
//! what a counting sort into flat arrays serves.
//!
//! The generators' grid (generate/grid.rs) is the one cell grid that does not use it:
//! deposition inserts one sphere at a time between queries, on a floor without bounds,
//! so it keeps a hash map of growing cells instead of flat arrays rebuilt per insert.

/// Stable counting sort of the items `0..keys.len()` by their key (< `buckets`):
/// returns `(start, order)`, where `order[start[b]..start[b + 1]]` are the items
/// with key `b` in increasing order.
pub fn counting_sort(keys: &[usize], buckets: usize) -> (Vec<usize>, Vec<u32>) {
    let mut start = vec![0usize; buckets + 1];
    for &b in keys {
        start[b + 1] += 1;
    }
    for b in 0..buckets {
        start[b + 1] += start[b];
    }
    let mut fill = start.clone();
    let mut order = vec![0u32; keys.len()];
    for (item, &b) in keys.iter().enumerate() {
        order[fill[b]] = item as u32;
        fill[b] += 1;
    }
    (start, order)
}
