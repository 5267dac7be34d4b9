//! A cylinder wall's `"curvature": "mean"` (R* = R r_w/(R + r_w), r_w = ∓2R_c,
//! LAMMPS's fix_wall_gran.cpp / region_cylinder.cpp rule) and `export-lammps` of
//! cylinders: the deck text and every refusal, by field.

use tamp::lammps::export::{export, refusals};
use tamp::particles::Vec3;
use tamp::scene::{self, Scene};

/// A steel sphere (R = 1 mm) at `centre` inside the cylinder `cylinder` (a JSON shape),
/// with `extra_walls` after it.
fn scene_with(cylinder: &str, extra_walls: &str, centre: [f64; 3]) -> Scene {
    scene::parse(&format!(
        r#"{{"name": "t", "materials": [{{"name": "steel", "density": 7800, "youngs_modulus": 2e11, "poisson_ratio": 0.3}}],
          "contact": {{"normal": {{"law": "hertz"}}}},
          "particles": [{{"position": {centre:?}, "radius": 0.001, "material": "steel"}}],
          "walls": [{{"material": "steel", "shape": {cylinder}}}{extra_walls}],
          "time_step": {{"fixed": 1e-8}}, "run": {{"steps": 10}}}}"#
    ))
    .expect("a valid scene")
}

const CAPS: &str = r#", {"material": "steel", "shape": {"kind": "plane", "point": [0, -0.005, 0], "normal": [0, 1, 0]}},
                        {"material": "steel", "shape": {"kind": "plane", "point": [0, 0.005, 0], "normal": [0, -1, 0]}}"#;

fn cylinder(axis: [f64; 3], curvature: &str) -> String {
    format!(
        r#"{{"kind": "cylinder", "origin": [0, 0, 0.0025], "axis": {axis:?}, "radius": 0.0025, "bottom": -0.005, "top": 0.005{curvature}}}"#
    )
}

fn paths(s: &Scene) -> Vec<String> {
    refusals(s).into_iter().map(|(p, _)| p).collect()
}

/// R* from the closed form: inside 2R R_c/(2R_c − R), outside 2R R_c/(2R_c + R); flat R.
#[test]
fn mean_curvature_gives_the_effective_radius_of_the_signed_mean_curvature_sphere() {
    let (r, r_c) = (0.001, 0.0025);
    let mean = scene_with(
        &cylinder([0.0, 1.0, 0.0], r#", "curvature": "mean""#),
        "",
        [0.0, 0.0, 0.001001],
    );
    let sim = scene::build(&mean).unwrap().sim;
    let (wall, pose) = (&sim.model().walls[0], &sim.state().walls[0]);
    let inside = wall.effective_radius(pose, &Vec3::new(0.0, 0.3, 0.0011), r);
    let outside = wall.effective_radius(pose, &Vec3::new(0.0, 0.0, -0.0009), r);
    assert!(
        (inside - 2.0 * r * r_c / (2.0 * r_c - r)).abs() < 1e-18,
        "{inside}"
    );
    assert!(
        (outside - 2.0 * r * r_c / (2.0 * r_c + r)).abs() < 1e-18,
        "{outside}"
    );
    let flat = scene_with(&cylinder([0.0, 1.0, 0.0], ""), "", [0.0, 0.0, 0.001001]);
    let sim = scene::build(&flat).unwrap().sim;
    let at = Vec3::new(0.0, 0.0, 0.0011);
    let pose = &sim.state().walls[0];
    assert_eq!(sim.model().walls[0].effective_radius(pose, &at, r), r);
}

#[test]
fn a_closed_mean_cylinder_is_a_region_cylinder_with_fix_wall_gran_region() {
    let s = scene_with(
        &cylinder([0.0, 1.0, 0.0], r#", "curvature": "mean""#),
        CAPS,
        [0.0, 0.0, 0.001001],
    );
    assert!(refusals(&s).is_empty(), "{:?}", refusals(&s));
    let dir = std::env::temp_dir().join(format!("tamp-lammps-cyl-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    export(&s, "sha", &dir, None).unwrap();
    let deck = std::fs::read_to_string(dir.join("in.tamp")).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    assert!(
        deck.contains(
            "region       wall0 cylinder y 0e0 2.5e-3 2.5e-3 -5e-3 5e-3 side in open 1 open 2 units box\n\
             fix          wall0 all wall/gran/region granular hertz/material 2e11 0e0 3e-1 damping velocity tangential linear_nohistory 0 0 region wall0\n"
        ),
        "{deck}"
    );
    assert!(deck.contains("fix          wall1 all wall/gran granular hertz/material 2e11 0e0 3e-1 damping velocity tangential linear_nohistory 0 0 yplane -5e-3 NULL\n"), "{deck}");
    // A negative axis turns the ends: heights -5e-3..5e-3 along -y are the same span.
    let s = scene_with(
        &cylinder([0.0, -2.0, 0.0], r#", "curvature": "mean""#),
        CAPS,
        [0.0, 0.0, 0.001001],
    );
    assert!(refusals(&s).is_empty(), "{:?}", refusals(&s));
}

#[test]
fn a_flat_cylinder_is_refused_at_its_curvature() {
    let s = scene_with(&cylinder([0.0, 1.0, 0.0], ""), CAPS, [0.0, 0.0, 0.001001]);
    assert_eq!(paths(&s), ["walls[0].shape.curvature"]);
    let why = &refusals(&s)[0].1;
    assert!(
        why.contains("r_w = -2 R_c") && why.contains("\"mean\""),
        "{why}"
    );
}

#[test]
fn a_tilted_cylinder_is_refused_at_its_axis() {
    let s = scene_with(
        &cylinder([0.0, 1.0, 1.0], r#", "curvature": "mean""#),
        CAPS,
        [0.0, 0.0, 0.001001],
    );
    assert_eq!(paths(&s), ["walls[0].shape.axis"]);
}

#[test]
fn a_cylinder_with_open_ends_is_refused_once_per_end() {
    let s = scene_with(
        &cylinder([0.0, 1.0, 0.0], r#", "curvature": "mean""#),
        "",
        [0.0, 0.0, 0.001001],
    );
    assert_eq!(paths(&s), ["walls[0].shape", "walls[0].shape"]);
    let why: Vec<String> = refusals(&s).into_iter().map(|(_, w)| w).collect();
    assert!(why[0].contains("end at y = -5e-3"), "{why:?}");
    assert!(why[1].contains("end at y = 5e-3"), "{why:?}");
    // A cap outside the ends does not close them.
    let far = r#", {"material": "steel", "shape": {"kind": "plane", "point": [0, -0.006, 0], "normal": [0, 1, 0]}},
                   {"material": "steel", "shape": {"kind": "plane", "point": [0, 0.005, 0], "normal": [0, -1, 0]}}"#;
    let s = scene_with(
        &cylinder([0.0, 1.0, 0.0], r#", "curvature": "mean""#),
        far,
        [0.0, 0.0, 0.001001],
    );
    assert_eq!(paths(&s), ["walls[0].shape"]);
}

#[test]
fn a_particle_starting_outside_the_cylinder_is_refused_and_nothing_is_written() {
    let s = scene_with(
        &cylinder([0.0, 1.0, 0.0], r#", "curvature": "mean""#),
        CAPS,
        [0.0, 0.0, -0.0011],
    );
    assert!(refusals(&s).is_empty());
    let dir = std::env::temp_dir().join(format!("tamp-lammps-out-{}", std::process::id()));
    let err = export(&s, "sha", &dir, None).unwrap_err().to_string();
    assert!(
        err.contains("walls[0].shape: cannot export to LAMMPS: particle 1 does not start inside"),
        "{err}"
    );
    assert!(!dir.exists());
}
