//! Boundary shapes through their public interface: STL files on disk, and
//! cross-checks of one shape kind against another or against brute force.

use std::io::Write;

use proptest::prelude::*;
use tamp::boundary::shape::{BoxShape, Mesh, Shape, ShapeContact};
use tamp::particles::Vec3;

fn contacts(s: &Shape, x: Vec3, r: f64, reach: f64) -> Vec<ShapeContact> {
    let mut out = Vec::new();
    s.contacts(&x, r, reach, &mut out);
    out
}

const SQUARE_ASCII: &str = "solid square
facet normal 0 0 1
  outer loop
    vertex 0 0 0
    vertex 1 0 0
    vertex 1 1 0
  endloop
endfacet
facet normal 0 0 1
  outer loop
    vertex 0 0 0
    vertex 1 1 0
    vertex 0 1 0
  endloop
endfacet
facet normal 0 0 0
  outer loop
    vertex 0 0 0
    vertex 0.5 0.5 0
    vertex 1 1 0
  endloop
endfacet
endsolid square
";

/// An ASCII STL square (two triangles and a zero-area sliver) reads back as two
/// triangles, and a sphere over its diagonal touches it once.
#[test]
fn ascii_stl_round_trip() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("square.stl");
    std::fs::write(&path, SQUARE_ASCII).unwrap();
    let m = Mesh::from_stl(&path).unwrap();
    assert_eq!(m.len(), 2);
    assert_eq!(m.skipped_degenerate(), 1);
    assert_eq!(m.bounding_box(), (Vec3::zeros(), Vec3::new(1.0, 1.0, 0.0)));
    let s = Shape::Mesh(m);
    let out = contacts(&s, Vec3::new(0.5, 0.5, 0.25), 0.3, 0.0);
    assert_eq!(out.len(), 1);
    assert!((out[0].overlap - 0.05).abs() < 1e-15);
    assert!((out[0].normal - Vec3::z()).norm() < 1e-14);
}

/// A binary STL whose 80-byte header begins with "solid" (as some exporters
/// write) is still read as binary.
#[test]
fn binary_stl_with_a_solid_header() {
    let tris: [[[f32; 3]; 3]; 2] = [
        [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [2.0, 2.0, 0.0]],
        [[0.0, 0.0, 0.0], [2.0, 2.0, 0.0], [0.0, 2.0, 0.0]],
    ];
    let mut bytes = Vec::new();
    let mut header = [b' '; 80];
    // With a line break in the header, stl_io's probe sees a clean first line
    // "solid from a CAD" and would parse the rest as ASCII.
    header[..17].copy_from_slice(b"solid from a CAD\n");
    bytes.extend_from_slice(&header);
    bytes.extend_from_slice(&(tris.len() as u32).to_le_bytes());
    for t in &tris {
        for f in [0.0f32, 0.0, 1.0] {
            bytes.extend_from_slice(&f.to_le_bytes());
        }
        for p in t {
            for c in p {
                bytes.extend_from_slice(&c.to_le_bytes());
            }
        }
        bytes.extend_from_slice(&0u16.to_le_bytes());
    }
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("square_bin.stl");
    std::fs::File::create(&path)
        .unwrap()
        .write_all(&bytes)
        .unwrap();
    let m = Mesh::from_stl(&path).unwrap();
    assert_eq!(m.len(), 2);
    assert_eq!(m.skipped_degenerate(), 0);
    let out = contacts(&Shape::Mesh(m), Vec3::new(1.0, 1.0, -0.1), 0.3, 0.0);
    assert_eq!(out.len(), 1);
    assert!((out[0].overlap - 0.2).abs() < 1e-15);
    assert!((out[0].normal + Vec3::z()).norm() < 1e-14);
}

#[test]
fn unreadable_stl_is_an_input_error_naming_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("nothing.stl");
    let e = Mesh::from_stl(&missing).unwrap_err();
    assert_eq!(e.exit_code(), 2);
    assert!(e.to_string().contains("nothing.stl"), "{e}");
    let garbage = dir.path().join("garbage.stl");
    std::fs::write(
        &garbage,
        "solid x\nfacet normal 0 0 1\n outer loop\n vertex 1 2\n",
    )
    .unwrap();
    assert!(Mesh::from_stl(&garbage).is_err());
}

/// The closed box [0, 1]³ as six squares (two triangles each).
fn cube_polygons(open_top: bool) -> Vec<Vec<Vec3>> {
    let c = |i: usize| Vec3::new((i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64);
    let faces = [
        [0, 2, 6, 4],
        [1, 3, 7, 5],
        [0, 1, 5, 4],
        [2, 3, 7, 6],
        [0, 1, 3, 2],
        [4, 5, 7, 6],
    ];
    let n = if open_top { 5 } else { 6 };
    faces[..n]
        .iter()
        .map(|f| f.iter().map(|&i| c(i)).collect())
        .collect()
}

/// Overlaps and normals in a canonical order (facet numbering differs by kind).
fn canonical(mut v: Vec<ShapeContact>) -> Vec<(f64, Vec3)> {
    v.sort_by(|a, b| {
        a.overlap
            .total_cmp(&b.overlap)
            .then(a.normal.x.total_cmp(&b.normal.x))
            .then(a.normal.y.total_cmp(&b.normal.y))
    });
    v.into_iter().map(|c| (c.overlap, c.normal)).collect()
}

fn same(a: &[(f64, Vec3)], b: &[(f64, Vec3)]) -> bool {
    a.len() == b.len()
        && a.iter()
            .zip(b)
            .all(|(x, y)| (x.0 - y.0).abs() < 1e-12 && (x.1 - y.1).norm() < 1e-9)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Inside the box, and above an open top, the box and a mesh of the same
    /// squares agree on every contact (they differ only behind a face, where the
    /// box is one-sided).
    #[test]
    fn box_agrees_with_its_mesh(
        u in 0.0..1.0f64, v in 0.0..1.0f64, w in 0.0..1.0f64,
        r in 0.02..0.3f64, open in any::<bool>(), above in any::<bool>(),
    ) {
        // Above the open top the centre may also be beyond the walls.
        let (open, centre) = if above {
            (true, Vec3::new(-0.2 + 1.4 * u, -0.2 + 1.4 * v, 1.0 + 1e-9 + 0.3 * w))
        } else {
            (open, Vec3::new(u, v, w))
        };
        let b = if open {
            BoxShape::open_top(Vec3::zeros(), Vec3::repeat(1.0)).unwrap()
        } else {
            BoxShape::new(Vec3::zeros(), Vec3::repeat(1.0)).unwrap()
        };
        let m = Mesh::from_polygons(&cube_polygons(open)).unwrap();
        let a = canonical(contacts(&Shape::Box(b), centre, r, 0.0));
        let c = canonical(contacts(&Shape::Mesh(m), centre, r, 0.0));
        prop_assert!(same(&a, &c), "box {:?}\nmesh {:?}", a, c);
    }
}
