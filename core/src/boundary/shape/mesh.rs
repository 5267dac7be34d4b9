//! A two-sided triangle mesh: convex polygon sets, STL files and height fields
//! z = f(x, y) all become triangles (Zhong 2009 §3).
//!
//! Distance: for each triangle near the sphere, the closest point q and its feature
//! (face, edge or vertex; `super::triangle`); d = |x − q|, δ = r − d, normal
//! (x − q)/d, facet = the triangle's index. The mesh is a thin two-sided sheet, so
//! a centre exactly on a triangle (d = 0) takes the triangle's normal (b − a) × (c − a).
//!
//! One contact per touching point (`super::push_distinct`): candidates are taken
//! face features first, then edges, then vertices (each group by distance, then
//! index), and a candidate is dropped when its closest point lies, to 1e-9 of that
//! triangle's longest edge, on a triangle already accepted for this sphere. Hence
//! - coplanar neighbours sharing an edge or a vertex: one contact (the first
//!   triangle's point lies on the others);
//! - a convex ridge or corner: one (the others offer points on the first);
//! - a concave valley or inside corner: one per face, each foot being interior to
//!   its own face and off the others.
//!   The rule fails only at the measure-zero position where the centre lies exactly
//!   on a concave edge (d = 0 to two faces), where one of the two is kept.
//!
//! Acceleration: a uniform grid of cubic cells over the mesh's bounding box; each
//! triangle is listed in every cell its bounding box overlaps. A query visits the
//! cells overlapped by the box of side 2(r + reach) around the centre and tests a
//! triangle only in the first cell (lowest index on each axis) common to both
//! boxes, so each candidate is tested once without a visited set. Any triangle
//! within r + reach has a point in both boxes, so the candidates, and after the
//! total ordering the contacts, are exactly those of testing every triangle.
//!
//! A height field is the piecewise-linear interpolant of its samples: its distance
//! is exact for a plane z = a x + b y + c and second order in the grid spacing
//! otherwise.

use std::path::Path;

use super::triangle::Triangle;
use super::{Candidate, ShapeContact, push_distinct, within_reach};
use crate::bins::counting_sort;
use crate::error::{Result, TampError};
use crate::particles::Vec3;

/// A two-sided triangle mesh with a uniform cell grid for finding the triangles near
/// a sphere.
#[derive(Clone, Debug)]
pub struct Mesh {
    triangles: Vec<Triangle>,
    lower: Vec3,
    upper: Vec3,
    grid: Grid,
    skipped: usize,
}

/// Triangle indices per cell, compressed: the triangles of cell c are
/// `items[start[c]..start[c + 1]]`.
#[derive(Clone, Debug)]
struct Grid {
    origin: Vec3,
    cell: f64,
    dims: [usize; 3],
    start: Vec<usize>,
    items: Vec<u32>,
    /// Per triangle, the lowest cell index on each axis of its bounding box.
    first_cell: Vec<[usize; 3]>,
}

impl Grid {
    /// Cell size about the mean triangle extent, so a triangle spans a few cells,
    /// enlarged until the grid holds at most 8 cells per triangle (a few huge
    /// triangles among many small ones must not make the grid enormous).
    fn build(triangles: &[Triangle], lower: Vec3, upper: Vec3) -> Grid {
        let extent = upper - lower;
        let n = triangles.len();
        let mean = triangles
            .iter()
            .map(|t| {
                let (lo, hi) = t.bounds();
                (hi - lo).max()
            })
            .sum::<f64>()
            / n as f64;
        let mut cell = mean.max(1e-12 * extent.max());
        let max_cells = (8 * n).max(64) as f64;
        let dims_for = |cell: f64| -> [usize; 3] {
            std::array::from_fn(|a| ((extent[a] / cell).ceil() as usize).max(1))
        };
        let mut dims = dims_for(cell);
        while (dims[0] as f64) * (dims[1] as f64) * (dims[2] as f64) > max_cells {
            cell *= 1.5;
            dims = dims_for(cell);
        }
        let mut grid = Grid {
            origin: lower,
            cell,
            dims,
            start: Vec::new(),
            items: Vec::new(),
            first_cell: Vec::with_capacity(n),
        };
        let ranges: Vec<([usize; 3], [usize; 3])> = triangles
            .iter()
            .map(|t| {
                let (lo, hi) = t.bounds();
                (grid.cell_of(&lo), grid.cell_of(&hi))
            })
            .collect();
        // One (cell, triangle) entry per cell a triangle's box overlaps, in triangle
        // order, so each cell lists its triangles in increasing index.
        let (mut cell_of_entry, mut triangle_of_entry) = (Vec::new(), Vec::new());
        for (t, (lo, hi)) in ranges.iter().enumerate() {
            grid.for_each_cell(lo, hi, |c| {
                cell_of_entry.push(c);
                triangle_of_entry.push(t as u32);
            });
        }
        let (start, order) = counting_sort(&cell_of_entry, dims[0] * dims[1] * dims[2]);
        grid.start = start;
        grid.items = order
            .iter()
            .map(|&e| triangle_of_entry[e as usize])
            .collect();
        grid.first_cell = ranges.iter().map(|r| r.0).collect();
        grid
    }

    /// Cell holding a point, clamped into the grid. Monotone in each coordinate,
    /// which is what makes a point in two boxes land in a cell of both ranges.
    #[inline]
    fn cell_of(&self, p: &Vec3) -> [usize; 3] {
        std::array::from_fn(|a| {
            let f = ((p[a] - self.origin[a]) / self.cell).floor();
            // `as` saturates, and sends NaN to 0.
            (f.max(0.0) as usize).min(self.dims[a] - 1)
        })
    }

    #[inline]
    fn for_each_cell(&self, lo: &[usize; 3], hi: &[usize; 3], mut f: impl FnMut(usize)) {
        for k in lo[2]..=hi[2] {
            for j in lo[1]..=hi[1] {
                for i in lo[0]..=hi[0] {
                    f(i + self.dims[0] * (j + self.dims[1] * k));
                }
            }
        }
    }
}

fn triangle_error(k: usize, rule: &str) -> TampError {
    TampError::input(format!("triangles[{k}]"), format!("triangle {k} {rule}"))
}

impl Mesh {
    /// A mesh of the given triangles, in order (facet k is triangle k). Errors name
    /// the first triangle that is degenerate or not finite.
    pub fn from_triangles(triangles: Vec<[Vec3; 3]>) -> Result<Mesh> {
        let mut out = Vec::with_capacity(triangles.len());
        for (k, v) in triangles.into_iter().enumerate() {
            if !v.iter().all(|p| p.iter().all(|c| c.is_finite())) {
                return Err(triangle_error(k, "has a coordinate that is not finite"));
            }
            out.push(
                Triangle::new(v).ok_or_else(|| {
                    triangle_error(k, "is degenerate (its vertices are collinear)")
                })?,
            );
        }
        Self::build(out, 0)
    }

    fn build(triangles: Vec<Triangle>, skipped: usize) -> Result<Mesh> {
        if triangles.is_empty() {
            return Err(TampError::input(
                "triangles",
                "a mesh needs at least one triangle",
            ));
        }
        if triangles.len() > u32::MAX as usize {
            return Err(TampError::input("triangles", "too many triangles"));
        }
        let (mut lower, mut upper) = triangles[0].bounds();
        for t in &triangles[1..] {
            let (lo, hi) = t.bounds();
            lower = lower.inf(&lo);
            upper = upper.sup(&hi);
        }
        let grid = Grid::build(&triangles, lower, upper);
        Ok(Mesh {
            triangles,
            lower,
            upper,
            grid,
            skipped,
        })
    }

    /// Convex planar polygons, each split into a fan of triangles from its first
    /// vertex (facets are numbered polygon by polygon, fan order). Errors name the
    /// polygon that is too small, not planar or not convex. Collinear consecutive
    /// vertices are allowed; the empty fan triangles they make are left out.
    pub fn from_polygons(polygons: &[Vec<Vec3>]) -> Result<Mesh> {
        if polygons.is_empty() {
            return Err(TampError::input(
                "polygons",
                "at least one polygon is needed",
            ));
        }
        let mut triangles = Vec::new();
        for (i, poly) in polygons.iter().enumerate() {
            check_convex_polygon(i, poly)?;
            for k in 1..poly.len() - 1 {
                if let Some(t) = Triangle::new([poly[0], poly[k], poly[k + 1]]) {
                    triangles.push(t);
                }
            }
        }
        Self::build(triangles, 0)
    }

    /// An STL file, ASCII or binary. Triangles with no area are left out and
    /// counted (`skipped_degenerate`); a file with nothing else is an error.
    pub fn from_stl(path: impl AsRef<Path>) -> Result<Mesh> {
        let path = path.as_ref();
        let field = path.display().to_string();
        let mut bytes = std::fs::read(path)
            .map_err(|e| TampError::input(&field, format!("cannot read the STL file: {e}")))?;
        // stl_io takes any file starting with "solid " for ASCII, but some
        // exporters write that word into a binary header too. A binary file is
        // recognised by its size, 84 + 50 × (triangle count at byte 80), and its
        // header (which carries no data) is blanked so the reader takes it as binary.
        if bytes.len() >= 84 {
            let count = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as u64;
            if bytes.len() as u64 == 84 + 50 * count && bytes.starts_with(b"solid") {
                bytes[..5].copy_from_slice(b"     ");
            }
        }
        let mut cursor = std::io::Cursor::new(bytes);
        let reader = stl_io::create_stl_reader(&mut cursor)
            .map_err(|e| TampError::input(&field, format!("not an STL file: {e}")))?;
        let mut triangles = Vec::new();
        let mut skipped = 0;
        for (k, t) in reader.enumerate() {
            let t = t.map_err(|e| {
                TampError::input(&field, format!("STL triangle {k} cannot be read: {e}"))
            })?;
            let v = t
                .vertices
                .map(|p| Vec3::new(p[0] as f64, p[1] as f64, p[2] as f64));
            if !v.iter().all(|p| p.iter().all(|c| c.is_finite())) {
                return Err(TampError::input(
                    &field,
                    format!("STL triangle {k} has a coordinate that is not finite"),
                ));
            }
            match Triangle::new(v) {
                Some(t) => triangles.push(t),
                None => skipped += 1,
            }
        }
        if triangles.is_empty() {
            return Err(TampError::input(
                &field,
                format!("the STL file holds no triangle with an area ({skipped} degenerate)"),
            ));
        }
        Self::build(triangles, skipped)
    }

    /// The surface z = f(x, y) sampled on a grid: z[i + nx·j] is the height at
    /// (x0 + i·dx, y0 + j·dy), for nx, ny ≥ 2 nodes. Each cell becomes two
    /// triangles split along its (i, j)–(i+1, j+1) diagonal; facets 2c and 2c + 1
    /// belong to cell c = i + (nx − 1)·j.
    pub fn from_height_grid(
        x0: f64,
        y0: f64,
        dx: f64,
        dy: f64,
        nx: usize,
        ny: usize,
        z: &[f64],
    ) -> Result<Mesh> {
        if nx < 2 || ny < 2 {
            return Err(TampError::input(
                "nx",
                format!("a height grid needs at least 2 × 2 nodes (got {nx} × {ny})"),
            ));
        }
        if !(dx > 0.0 && dy > 0.0 && dx.is_finite() && dy.is_finite()) {
            return Err(TampError::input(
                "dx",
                format!("grid spacings must be positive (got dx = {dx}, dy = {dy})"),
            ));
        }
        if !(x0.is_finite() && y0.is_finite()) {
            return Err(TampError::input("x0", "the grid origin must be finite"));
        }
        if z.len() != nx * ny {
            return Err(TampError::input(
                "z",
                format!("{} heights given for {nx} × {ny} nodes", z.len()),
            ));
        }
        if let Some(k) = z.iter().position(|v| !v.is_finite()) {
            return Err(TampError::input(
                format!("z[{k}]"),
                format!("height {k} is not finite"),
            ));
        }
        let node =
            |i: usize, j: usize| Vec3::new(x0 + i as f64 * dx, y0 + j as f64 * dy, z[i + nx * j]);
        let mut triangles = Vec::with_capacity(2 * (nx - 1) * (ny - 1));
        for j in 0..ny - 1 {
            for i in 0..nx - 1 {
                let (a, b, c, d) = (
                    node(i, j),
                    node(i + 1, j),
                    node(i + 1, j + 1),
                    node(i, j + 1),
                );
                for v in [[a, b, c], [a, c, d]] {
                    // The xy footprint has area dx dy / 2, so no height can
                    // flatten it; only spacing below rounding could.
                    triangles.push(Triangle::new(v).ok_or_else(|| {
                        TampError::input("dx", "grid spacing too small for its coordinates")
                    })?);
                }
            }
        }
        Self::build(triangles, 0)
    }

    /// The surface z = f(x, y) sampled at nx × ny nodes spanning x.0..=x.1 and
    /// y.0..=y.1 (see `from_height_grid` for the triangles).
    pub fn from_height_fn(
        x: (f64, f64),
        y: (f64, f64),
        nx: usize,
        ny: usize,
        f: impl Fn(f64, f64) -> f64,
    ) -> Result<Mesh> {
        if nx < 2 || ny < 2 {
            return Err(TampError::input(
                "nx",
                format!("a height grid needs at least 2 × 2 nodes (got {nx} × {ny})"),
            ));
        }
        let dx = (x.1 - x.0) / (nx - 1) as f64;
        let dy = (y.1 - y.0) / (ny - 1) as f64;
        let mut z = Vec::with_capacity(nx * ny);
        for j in 0..ny {
            for i in 0..nx {
                z.push(f(x.0 + i as f64 * dx, y.0 + j as f64 * dy));
            }
        }
        Self::from_height_grid(x.0, y.0, dx, dy, nx, ny, &z)
    }

    /// The non-degenerate triangles, in facet order.
    pub fn triangles(&self) -> &[Triangle] {
        &self.triangles
    }

    /// Number of triangles.
    pub fn len(&self) -> usize {
        self.triangles.len()
    }

    /// Always false: a mesh is never built empty.
    pub fn is_empty(&self) -> bool {
        self.triangles.is_empty()
    }

    /// Componentwise (lower, upper) corners of all the vertices.
    pub fn bounding_box(&self) -> (Vec3, Vec3) {
        (self.lower, self.upper)
    }

    /// Zero-area triangles left out when reading an STL file.
    pub fn skipped_degenerate(&self) -> usize {
        self.skipped
    }

    /// The candidate of triangle t, if within r + reach.
    #[inline]
    fn candidate(&self, t: usize, centre: &Vec3, radius: f64, reach: f64) -> Option<Candidate> {
        let tri = &self.triangles[t];
        let (q, feature) = tri.closest_point(centre);
        let v = centre - q;
        let distance = v.norm();
        if !within_reach(radius - distance, reach) {
            return None;
        }
        Some(Candidate {
            rank: feature.rank(),
            distance,
            facet: t as u32,
            point: q,
            normal: if distance > 0.0 {
                v / distance
            } else {
                tri.normal
            },
        })
    }

    fn finish(&self, candidates: &mut [Candidate], radius: f64, out: &mut Vec<ShapeContact>) {
        push_distinct(
            candidates,
            radius,
            |t, p| self.triangles[t as usize].contains(p),
            out,
        );
    }

    /// Call `f` once for every triangle listed in a cell that the box of
    /// half-side `range` around `centre` overlaps.
    #[inline]
    fn for_each_near(&self, centre: &Vec3, range: f64, mut f: impl FnMut(usize)) {
        let lo = centre.add_scalar(-range);
        let hi = centre.add_scalar(range);
        if (0..3).any(|a| hi[a] < self.lower[a] || lo[a] > self.upper[a]) {
            return;
        }
        let g = &self.grid;
        let (clo, chi) = (g.cell_of(&lo), g.cell_of(&hi));
        g.for_each_cell(&clo, &chi, |c| {
            let here = [
                c % g.dims[0],
                (c / g.dims[0]) % g.dims[1],
                c / (g.dims[0] * g.dims[1]),
            ];
            for &t in &g.items[g.start[c]..g.start[c + 1]] {
                let first = g.first_cell[t as usize];
                if (0..3).all(|a| here[a] == first[a].max(clo[a])) {
                    f(t as usize);
                }
            }
        });
    }

    /// Append the contacts of a sphere with the mesh, one per distinct touching point
    /// (facet = triangle index).
    pub fn contacts(&self, centre: &Vec3, radius: f64, reach: f64, out: &mut Vec<ShapeContact>) {
        let mut candidates: Vec<Candidate> = Vec::new();
        self.for_each_near(centre, radius + reach, |t| {
            if let Some(c) = self.candidate(t, centre, radius, reach) {
                candidates.push(c);
            }
        });
        self.finish(&mut candidates, radius, out);
    }

    /// `contacts` by testing every triangle: the reference the grid must match.
    #[cfg(test)]
    fn contacts_all(&self, centre: &Vec3, radius: f64, reach: f64, out: &mut Vec<ShapeContact>) {
        let mut candidates: Vec<Candidate> = (0..self.triangles.len())
            .filter_map(|t| self.candidate(t, centre, radius, reach))
            .collect();
        self.finish(&mut candidates, radius, out);
    }
}

/// At least three finite vertices, no repeated neighbours, all in one plane, and
/// every turn the same way round with the turns adding up to one revolution (a
/// pentagram turns consistently but twice).
fn check_convex_polygon(i: usize, poly: &[Vec3]) -> Result<()> {
    let err =
        |rule: String| TampError::input(format!("polygons[{i}]"), format!("polygon {i} {rule}"));
    let n = poly.len();
    if n < 3 {
        return Err(err(format!("has {n} vertices; at least 3 are needed")));
    }
    if let Some(k) = poly.iter().position(|p| !p.iter().all(|c| c.is_finite())) {
        return Err(err(format!("vertex {k} is not finite")));
    }
    let size = poly
        .iter()
        .flat_map(|p| poly.iter().map(move |q| (p - q).norm()))
        .fold(0.0, f64::max);
    for k in 0..n {
        if (poly[(k + 1) % n] - poly[k]).norm() <= 1e-12 * size {
            return Err(err(format!("repeats vertex {k} at vertex {}", (k + 1) % n)));
        }
    }
    // Newell's normal: exact for planar polygons, a robust average otherwise.
    let mut normal = Vec3::zeros();
    for k in 0..n {
        normal += poly[k].cross(&poly[(k + 1) % n]);
    }
    let twice_area = normal.norm();
    if twice_area <= 1e-12 * size * size {
        return Err(err("has no area (its vertices are collinear)".into()));
    }
    let normal = normal / twice_area;
    let centroid = poly.iter().sum::<Vec3>() / n as f64;
    if let Some(k) = poly
        .iter()
        .position(|p| (p - centroid).dot(&normal).abs() > 1e-9 * size)
    {
        return Err(err(format!("is not planar (vertex {k} is off its plane)")));
    }
    let mut turning = 0.0;
    for k in 0..n {
        let e0 = poly[(k + 1) % n] - poly[k];
        let e1 = poly[(k + 2) % n] - poly[(k + 1) % n];
        let sin = e0.cross(&e1).dot(&normal);
        let cos = e0.dot(&e1);
        if sin < -1e-9 * e0.norm() * e1.norm() {
            return Err(err(format!(
                "is not convex (it turns the other way at vertex {})",
                (k + 1) % n
            )));
        }
        turning += sin.atan2(cos);
    }
    if (turning - std::f64::consts::TAU).abs() > 1e-6 {
        return Err(err(
            "is not convex (its boundary winds more than once)".into()
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn v(x: f64, y: f64, z: f64) -> Vec3 {
        Vec3::new(x, y, z)
    }

    fn query(m: &Mesh, x: Vec3, r: f64, reach: f64) -> Vec<ShapeContact> {
        let mut out = Vec::new();
        m.contacts(&x, r, reach, &mut out);
        let mut all = Vec::new();
        m.contacts_all(&x, r, reach, &mut all);
        assert_eq!(out, all, "grid and brute force differ at {x:?}");
        for c in &out {
            assert!((c.normal.norm() - 1.0).abs() < 1e-14);
        }
        out
    }

    /// The square [0, 1]² in the plane z = 0, anticlockwise.
    fn unit_square() -> Vec<Vec3> {
        vec![
            v(0.0, 0.0, 0.0),
            v(1.0, 0.0, 0.0),
            v(1.0, 1.0, 0.0),
            v(0.0, 1.0, 0.0),
        ]
    }

    /// The faces of the cube [0, 1]³ as squares (two triangles each).
    fn cube() -> Mesh {
        let c = |i: usize| v((i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64);
        let faces = [
            [0, 2, 6, 4],
            [1, 3, 7, 5],
            [0, 1, 5, 4],
            [2, 3, 7, 6],
            [0, 1, 3, 2],
            [4, 5, 7, 6],
        ];
        let polys: Vec<Vec<Vec3>> = faces
            .iter()
            .map(|f| f.iter().map(|&i| c(i)).collect())
            .collect();
        Mesh::from_polygons(&polys).unwrap()
    }

    #[test]
    fn coplanar_shared_edge_and_shared_vertex_give_one_contact() {
        let square = Mesh::from_polygons(&[unit_square()]).unwrap();
        assert_eq!(square.len(), 2);
        // Exactly over the shared diagonal, and just off it on either side.
        for x in [
            v(0.5, 0.5, 0.07),
            v(0.5 + 1e-13, 0.5, 0.07),
            v(0.3, 0.3 + 1e-9, 0.07),
        ] {
            let out = query(&square, x, 0.1, 0.0);
            assert_eq!(out.len(), 1, "{x:?}");
            assert!((out[0].overlap - 0.03).abs() < 1e-15);
            assert!((out[0].normal - Vec3::z()).norm() < 1e-14);
        }
        // Below: the sheet is two-sided.
        let out = query(&square, v(0.25, 0.6, -0.04), 0.1, 0.0);
        assert_eq!(out.len(), 1);
        assert!((out[0].overlap - 0.06).abs() < 1e-15);
        assert!((out[0].normal + Vec3::z()).norm() < 1e-14);

        // A flat fan of eight triangles around the origin.
        let ring: Vec<Vec3> = (0..8)
            .map(|k| {
                let a = std::f64::consts::TAU * k as f64 / 8.0;
                v(a.cos(), a.sin(), 0.0)
            })
            .collect();
        let fan = Mesh::from_triangles(
            (0..8)
                .map(|k| [Vec3::zeros(), ring[k], ring[(k + 1) % 8]])
                .collect(),
        )
        .unwrap();
        for x in [v(0.0, 0.0, 0.05), v(0.4, 0.0, 0.05), v(-0.2, 0.01, 0.05)] {
            let out = query(&fan, x, 0.1, 0.0);
            assert_eq!(out.len(), 1, "{x:?}");
            assert!((out[0].overlap - 0.05).abs() < 1e-15);
            assert!((out[0].normal - Vec3::z()).norm() < 1e-14);
        }
    }

    #[test]
    fn inside_corner_of_a_mesh_cube_gives_three_contacts() {
        let m = cube();
        assert_eq!(m.len(), 12);
        let out = query(&m, v(0.05, 0.94, 0.97), 0.1, 0.0);
        assert_eq!(out.len(), 3);
        let mut got: Vec<(Vec3, f64)> = out.iter().map(|c| (c.normal, c.overlap)).collect();
        got.sort_by(|a, b| a.1.total_cmp(&b.1));
        let want: [(Vec3, f64); 3] = [
            (v(1.0, 0.0, 0.0), 0.05),
            (v(0.0, -1.0, 0.0), 0.04),
            (v(0.0, 0.0, -1.0), 0.07),
        ];
        let mut want = want.to_vec();
        want.sort_by(|a, b| a.1.total_cmp(&b.1));
        for (g, w) in got.iter().zip(&want) {
            assert!(
                (g.0 - w.0).norm() < 1e-14 && (g.1 - w.1).abs() < 1e-14,
                "{g:?} vs {w:?}"
            );
        }
        // Outside the cube, beyond an edge: the ridge gives one contact.
        let out = query(&m, v(1.03, 0.5, 1.04), 0.1, 0.0);
        assert_eq!(out.len(), 1);
        assert!((out[0].overlap - 0.05).abs() < 1e-14);
        assert!((out[0].normal - v(0.6, 0.0, 0.8)).norm() < 1e-14);
        // Outside beyond a corner: one contact at the vertex.
        let x = v(1.0 + 0.02, 1.0 + 0.03, 1.0 + 0.06);
        let out = query(&m, x, 0.1, 0.0);
        assert_eq!(out.len(), 1);
        assert!((out[0].overlap - 0.03).abs() < 1e-14);
        // Outside over a face near a ridge: the face foot only.
        let out = query(&m, v(0.97, 0.5, 1.05), 0.1, 0.0);
        assert_eq!(out.len(), 1);
        assert!((out[0].overlap - 0.05).abs() < 1e-14);
        assert!((out[0].normal - Vec3::z()).norm() < 1e-14);
    }

    #[test]
    fn valley_two_ridge_one() {
        // Two planes meeting along the y axis at 90°: z = |x| (a valley seen from
        // above, a ridge from below).
        let m = Mesh::from_polygons(&[
            vec![
                v(0.0, -1.0, 0.0),
                v(1.0, -1.0, 1.0),
                v(1.0, 1.0, 1.0),
                v(0.0, 1.0, 0.0),
            ],
            vec![
                v(0.0, -1.0, 0.0),
                v(0.0, 1.0, 0.0),
                v(-1.0, 1.0, 1.0),
                v(-1.0, -1.0, 1.0),
            ],
        ])
        .unwrap();
        // In the valley on its axis, at height 0.1: 0.1/√2 from each face.
        let out = query(&m, v(0.0, 0.2, 0.1), 0.1, 0.0);
        assert_eq!(out.len(), 2);
        for c in &out {
            assert!((c.overlap - (0.1 - 0.1 / 2f64.sqrt())).abs() < 1e-14);
        }
        assert!((out[0].normal.x + out[1].normal.x).abs() < 1e-14);
        // Under the ridge: one contact, along −z.
        let out = query(&m, v(0.0, 0.2, -0.06), 0.1, 0.0);
        assert_eq!(out.len(), 1);
        assert!((out[0].overlap - 0.04).abs() < 1e-14);
        assert!((out[0].normal + Vec3::z()).norm() < 1e-14);
    }

    #[test]
    fn reach_and_appending() {
        let m = cube();
        let mut out = vec![ShapeContact {
            normal: Vec3::x(),
            overlap: 1.0,
            facet: 99,
        }];
        m.contacts(&v(0.5, 0.5, 0.15), 0.1, 0.06, &mut out);
        assert_eq!(out.len(), 2);
        assert_eq!(out[0].facet, 99);
        assert!((out[1].overlap + 0.05).abs() < 1e-14);
        assert!(query(&m, v(0.5, 0.5, 0.17), 0.1, 0.06).is_empty());
        // Far outside the grid.
        assert!(query(&m, v(50.0, -3.0, 7.0), 0.1, 0.0).is_empty());
    }

    #[test]
    fn height_field_of_a_plane_is_the_plane() {
        let (a, b, c) = (0.3, -0.2, 0.5);
        let m =
            Mesh::from_height_fn((-1.0, 2.0), (0.0, 1.5), 7, 5, |x, y| a * x + b * y + c).unwrap();
        assert_eq!(m.len(), 2 * 6 * 4);
        let n = v(-a, -b, 1.0).normalize();
        for (x, y, h) in [
            (0.3, 0.7, 0.04),
            (1.51, 0.2, -0.07),
            (0.5, 1.0, 0.09),
            (0.0, 0.5, 0.02),
        ] {
            let foot = v(x, y, a * x + b * y + c);
            let centre = foot + n * h;
            let out = query(&m, centre, 0.1, 0.0);
            assert_eq!(out.len(), 1, "{centre:?}");
            assert!((out[0].overlap - (0.1 - h.abs())).abs() < 1e-14);
            assert!((out[0].normal - n * h.signum()).norm() < 1e-13);
        }
        let (lo, hi) = m.bounding_box();
        assert!((lo - v(-1.0, 0.0, -a + b * 1.5 + c)).norm() < 1e-15);
        assert!((hi - v(2.0, 1.5, a * 2.0 + c)).norm() < 1e-15);
        // The grid form gives the same triangles.
        let z: Vec<f64> = (0..5)
            .flat_map(|j| (0..7).map(move |i| (i, j)))
            .map(|(i, j)| a * (-1.0 + 0.5 * i as f64) + b * (0.375 * j as f64) + c)
            .collect();
        let g = Mesh::from_height_grid(-1.0, 0.0, 0.5, 0.375, 7, 5, &z).unwrap();
        assert_eq!(g.triangles(), m.triangles());
    }

    #[test]
    fn bad_input_is_named() {
        let msg = |r: Result<Mesh>| r.unwrap_err().to_string();
        let square = unit_square();
        let dart = vec![
            v(0.0, 0.0, 0.0),
            v(2.0, 0.0, 0.0),
            v(0.5, 0.5, 0.0),
            v(0.0, 2.0, 0.0),
        ];
        let e = msg(Mesh::from_polygons(&[
            square.clone(),
            square.clone(),
            square.clone(),
            dart,
        ]));
        assert!(e.contains("polygon 3 is not convex"), "{e}");
        let mut bent = square.clone();
        bent[2].z = 0.1;
        let e = msg(Mesh::from_polygons(&[bent]));
        assert!(e.contains("polygon 0 is not planar"), "{e}");
        let star: Vec<Vec3> = (0..5)
            .map(|k| {
                let a = std::f64::consts::TAU * (2 * k) as f64 / 5.0;
                v(a.cos(), a.sin(), 0.0)
            })
            .collect();
        let e = msg(Mesh::from_polygons(&[star]));
        assert!(e.contains("winds more than once"), "{e}");
        let e = msg(Mesh::from_polygons(&[square[..2].to_vec()]));
        assert!(e.contains("at least 3"), "{e}");
        let z = Vec3::zeros();
        let e = msg(Mesh::from_triangles(vec![
            [z, v(1.0, 0.0, 0.0), v(0.0, 1.0, 0.0)],
            [z, z, v(1.0, 0.0, 0.0)],
        ]));
        assert!(e.contains("triangle 1 is degenerate"), "{e}");
        let e = msg(Mesh::from_height_grid(0.0, 0.0, 1.0, 1.0, 3, 3, &[0.0; 8]));
        assert!(e.contains("8 heights given for 3 × 3 nodes"), "{e}");
        assert!(Mesh::from_triangles(Vec::new()).is_err());
        // Collinear vertices along an edge are fine: the empty fan triangle goes.
        let m = Mesh::from_polygons(&[vec![
            v(0.0, 0.0, 0.0),
            v(1.0, 0.0, 0.0),
            v(2.0, 0.0, 0.0),
            v(2.0, 1.0, 0.0),
            v(0.0, 1.0, 0.0),
        ]])
        .unwrap();
        assert_eq!(m.len(), 2);
    }

    #[test]
    fn queries_on_a_large_mesh_test_few_triangles() {
        let m = Mesh::from_height_fn((0.0, 1.0), (0.0, 1.0), 101, 101, |x, y| {
            0.05 * (6.0 * x).sin() * (5.0 * y).cos()
        })
        .unwrap();
        assert_eq!(m.len(), 20_000);
        let mut most = 0;
        let mut seen = vec![0u32; m.len()];
        for k in 0..500 {
            let (x, y) = ((k % 25) as f64 / 24.0, (k / 25) as f64 / 19.0);
            let centre = v(x, y, 0.05 * (6.0 * x).sin() * (5.0 * y).cos());
            let mut tested = 0;
            m.for_each_near(&centre, 0.006, |t| {
                tested += 1;
                seen[t] += 1;
            });
            most = most.max(tested);
            // Every visit is a distinct triangle.
            assert!(seen.iter().all(|&s| s <= 1));
            seen.iter_mut().for_each(|s| *s = 0);
        }
        // Cells of about one triangle's extent (0.01): a box of side 0.012 meets at
        // most 3 × 3 × (a few) cells, each listing a handful of triangles.
        assert!(most > 0 && most < 64, "{most} triangles tested");
    }

    fn coord() -> impl Strategy<Value = f64> {
        -1.0..1.0f64
    }
    fn point() -> impl Strategy<Value = Vec3> {
        (coord(), coord(), coord()).prop_map(|(x, y, z)| Vec3::new(x, y, z))
    }

    proptest! {
        /// A soup of random triangles: the grid finds exactly the contacts of
        /// testing every triangle.
        #[test]
        fn grid_matches_all_triangles_soup(
            tris in prop::collection::vec((point(), point(), point()), 1..60),
            scale in prop::sample::select(vec![0.05, 0.3, 1.0]),
            centres in prop::collection::vec(point(), 20),
            radius in 0.01..0.6f64,
            reach in prop::sample::select(vec![0.0, 0.05]),
        ) {
            let triangles: Vec<[Vec3; 3]> = tris
                .into_iter()
                .map(|(a, b, c)| [a, a + (b - a) * scale, a + (c - a) * scale])
                .filter(|t| Triangle::new(*t).is_some())
                .collect();
            if triangles.is_empty() {
                return Ok(());
            }
            let m = Mesh::from_triangles(triangles).unwrap();
            for x in centres {
                let (mut a, mut b) = (Vec::new(), Vec::new());
                m.contacts(&(x * 1.3), radius, reach, &mut a);
                m.contacts_all(&(x * 1.3), radius, reach, &mut b);
                prop_assert_eq!(a, b);
            }
        }

        /// A bumpy height field (shared edges and vertices everywhere).
        #[test]
        fn grid_matches_all_triangles_height_field(
            z in prop::collection::vec(-0.3..0.3f64, 64),
            centres in prop::collection::vec(point(), 30),
            radius in 0.01..0.5f64,
        ) {
            let m = Mesh::from_height_grid(-1.0, -1.0, 2.0 / 7.0, 2.0 / 7.0, 8, 8, &z).unwrap();
            for x in centres {
                let (mut a, mut b) = (Vec::new(), Vec::new());
                m.contacts(&x, radius, 0.0, &mut a);
                m.contacts_all(&x, radius, 0.0, &mut b);
                prop_assert_eq!(a, b);
            }
        }
    }
}
