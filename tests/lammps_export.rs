//! `export-lammps` of whole scenes: the deck text of walls, their motion and friction
//! pairs, and refusals that need the scene built (a particle against a wall at the
//! start, a box narrower than a particle). Integration tests, so that the library's
//! unit-test build does not compile the force loop for every law (docs/performance.md).

use tamp::lammps::export::{export, refusals};
use tamp::scene::materials::MaterialSpec;
use tamp::scene::{self, Scene};
fn two_spheres(contact: &str, extra: &str) -> Scene {
    scene::parse(&format!(
        r#"{{"name": "t", "materials": [{{"name": "steel", "density": 7800, "youngs_modulus": 2e11, "poisson_ratio": 0.3}}],
          "contact": {contact},
          "particles": [{{"position": [-0.001001, 0, 0], "radius": 0.001, "material": "steel", "velocity": [0.5, 0, 0]}},
                        {{"position": [0.001001, 0, 0], "radius": 0.001, "material": "steel", "velocity": [-0.5, 0, 0]}}],
          "time_step": {{"fixed": 1e-9}}, "run": {{"duration": 1e-6}}{extra}}}"#
    ))
    .expect("a valid scene")
}

#[test]
fn refusals_name_every_field_and_nothing_is_written() {
    let s = two_spheres(
        r#"{"normal": {"law": "hertz"}, "tangential": {"law": "cundall_strack", "stiffness": 1e3, "friction": 0.3}}"#,
        r#", "rotation": {}, "walls": [{"name": "floor", "material": "steel", "shape": {"kind": "plane", "point": [0, 0, -0.01], "normal": [0, 1, 1]},
             "motion": {"kind": "servo", "direction": [0, -1, -1], "force": 1, "gain": 1e-3, "max_speed": 0.1}}]"#,
    );
    let paths: Vec<String> = refusals(&s).into_iter().map(|(p, _)| p).collect();
    assert_eq!(
        paths,
        [
            "contact.tangential.law",
            "walls[0].motion",
            "contact.lever_arm"
        ]
    );
    let dir = std::env::temp_dir().join(format!("tamp-lammps-refused-{}", std::process::id()));
    let err = export(&s, "sha", &dir, None).unwrap_err().to_string();
    assert!(
        err.contains("contact.tangential.law: cannot export to LAMMPS: "),
        "{err}"
    );
    assert!(!dir.exists());
}

/// One steel sphere well clear of the scene's walls (`walls`, a JSON list body).
fn sphere_with_walls(walls: &str) -> Scene {
    two_spheres(
        r#"{"normal": {"law": "hertz"}}"#,
        &format!(r#", "walls": [{walls}]"#),
    )
}

/// The deck `export` writes for `s`, or its refusal as text.
fn deck_of(s: &Scene, tag: &str) -> std::result::Result<String, String> {
    let dir = std::env::temp_dir().join(format!("tamp-lammps-{tag}-{}", std::process::id()));
    let out = export(s, "sha", &dir, None)
        .map(|_| std::fs::read_to_string(dir.join("in.tamp")).unwrap())
        .map_err(|e| e.to_string());
    let _ = std::fs::remove_dir_all(&dir);
    out
}

#[test]
fn friction_pairs_are_pair_coeff_lines_and_wall_fixes_per_particle_type() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/scenes/lammps_export_friction_pairs.json"
    );
    let s = scene::parse(&std::fs::read_to_string(path).unwrap()).unwrap();
    let deck = deck_of(&s, "friction-pairs").unwrap();
    let coeffs: Vec<&str> = deck
        .lines()
        .filter(|l| l.starts_with("pair_coeff"))
        .collect();
    let model =
        "hertz/material 1e7 7e-1 2.5e-1 damping coeff_restitution tangential mindlin -1 0e0";
    assert_eq!(
        coeffs,
        [
            format!("pair_coeff   1 1 {model} 2e-1"),
            format!("pair_coeff   2 2 {model} 4e-1"),
            format!("pair_coeff   3 3 {model} 4e-1"),
            format!("pair_coeff   1 2 {model} 6e-1"),
        ],
        "{deck}"
    );
    assert!(deck.contains("group        type1 type 1\ngroup        type2 type 2\n"));
    assert!(
        deck.contains(&format!(
            "fix          wall0x_type1 type1 wall/gran granular {model} 1e-1 xplane"
        )),
        "{deck}"
    );
    assert!(
        deck.contains(&format!(
            "fix          wall0z_type2 type2 wall/gran granular {model} 5e-1 zplane"
        )),
        "{deck}"
    );

    let mut other = s.clone();
    other.materials[1].poisson_ratio = Some(0.3);
    other.materials[2].poisson_ratio = Some(0.3);
    let refused: Vec<(String, String)> = refusals(&other)
        .into_iter()
        .filter(|(p, _)| p.starts_with("contact"))
        .collect();
    assert_eq!(refused.len(), 1, "{refused:?}");
    assert_eq!(refused[0].0, "contact.tangential.friction_pairs");
    assert!(refused[0].1.contains("'a' and 'b'"), "{}", refused[0].1);
}

#[test]
fn a_tilted_plane_is_a_region_plane_and_an_axis_aligned_one_stays_fix_wall_gran() {
    let s = sphere_with_walls(
        r#"{"material": "steel", "shape": {"kind": "plane", "point": [0, 0, -0.01], "normal": [0, -0.5, 2]}},
           {"material": "steel", "shape": {"kind": "plane", "point": [0, 0, -0.02], "normal": [0, 0, 1]}}"#,
    );
    assert!(refusals(&s).is_empty(), "{:?}", refusals(&s));
    let deck = deck_of(&s, "tilted").unwrap();
    assert!(
        deck.contains("region       wall0 plane 0e0 0e0 -1e-2 0e0 -5e-1 2e0 side in units box\nfix          wall0 all wall/gran/region granular hertz/material 2e11 0e0 3e-1 damping velocity tangential linear_nohistory 0 0 region wall0\n"),
        "{deck}"
    );
    assert!(
        deck.contains("fix          wall1 all wall/gran granular hertz/material 2e11 0e0 3e-1 damping velocity tangential linear_nohistory 0 0 zplane -2e-2 NULL\n"),
        "{deck}"
    );
}

#[test]
fn a_velocity_wall_moves_its_region_by_velocity_times_time() {
    let s = sphere_with_walls(
        r#"{"material": "steel", "shape": {"kind": "plane", "point": [0, 0, -0.01], "normal": [0, 0, 1]},
            "motion": {"kind": "velocity", "velocity": [0.5, 0, -0.25]}}"#,
    );
    assert!(refusals(&s).is_empty(), "{:?}", refusals(&s));
    let deck = deck_of(&s, "velocity").unwrap();
    assert!(
        deck.contains("variable     wall0_dx equal 5e-1*time\nvariable     wall0_dz equal -2.5e-1*time\nregion       wall0 plane 0e0 0e0 -1e-2 0e0 0e0 1e0 side in units box move v_wall0_dx NULL v_wall0_dz\n"),
        "{deck}"
    );
}

#[test]
fn a_displacement_wall_moves_by_its_expressions_as_lammps_formulas_or_is_refused() {
    let s = sphere_with_walls(
        r#"{"material": "steel", "shape": {"kind": "plane", "point": [0, 0, -0.01], "normal": [0, 0, 1]},
            "motion": {"kind": "displacement", "x": "0.001 * math::sin(100.0 * t)", "y": "0.0", "z": "-0.5 * t"}}"#,
    );
    assert!(refusals(&s).is_empty(), "{:?}", refusals(&s));
    let deck = deck_of(&s, "displacement").unwrap();
    assert!(
        deck.contains("variable     wall0_dx equal (1e-3)*(sin((1e2)*(time)))\nvariable     wall0_dy equal 0e0\n"),
        "{deck}"
    );
    assert!(
        deck.contains("move v_wall0_dx v_wall0_dy v_wall0_dz\n"),
        "{deck}"
    );
    let s = sphere_with_walls(
        r#"{"material": "steel", "shape": {"kind": "plane", "point": [0, 0, -0.01], "normal": [0, 0, 1]},
            "motion": {"kind": "displacement", "x": "0.0", "y": "math::cbrt(t)", "z": "t * (1/2)"}}"#,
    );
    let paths: Vec<String> = refusals(&s).into_iter().map(|(p, _)| p).collect();
    assert_eq!(paths, ["walls[0].motion.y", "walls[0].motion.z"]);
}

/// LAMMPS's setup force sees a moving region at rest.
#[test]
fn a_particle_touching_a_velocity_wall_at_the_start_is_refused() {
    let s = sphere_with_walls(
        // Touching by 1e-10 m, within the initial-overlap tolerance (1e-6 R).
        r#"{"material": "steel", "shape": {"kind": "plane", "point": [-0.0020009999, 0, 0], "normal": [1, 0, 0]},
            "motion": {"kind": "velocity", "velocity": [0.1, 0, 0]}}"#,
    );
    assert!(refusals(&s).is_empty(), "{:?}", refusals(&s));
    let err = deck_of(&s, "touching").unwrap_err();
    assert!(
        err.contains("walls[0].motion: cannot export to LAMMPS: particle ")
            && err.contains(" touches the moving wall at t = 0"),
        "{err}"
    );
}

/// A cylinder's ends stay closed only while its axial travel keeps the fixed faces
/// between them.
#[test]
fn a_cylinder_moves_across_its_axis_and_along_it_only_as_far_as_its_closed_ends_allow() {
    let tube = |motion: &str| {
        sphere_with_walls(&format!(
            r#"{{"material": "steel", "shape": {{"kind": "cylinder", "origin": [0, 0, 0], "axis": [1, 0, 0], "radius": 0.005,
                 "bottom": -0.004, "top": 0.004, "curvature": "mean"}}, "motion": {motion}}},
               {{"material": "steel", "shape": {{"kind": "plane", "point": [-0.003, 0, 0], "normal": [1, 0, 0]}}}},
               {{"material": "steel", "shape": {{"kind": "plane", "point": [0.003, 0, 0], "normal": [-1, 0, 0]}}}}"#
        ))
    };
    // 1 µs of run: 1500 m/s along the axis travels 1.5 mm, past the 1 mm margin
    // between the faces and the ends; 0.5 m/s travels 0.5 µm.
    let far = tube(r#"{"kind": "velocity", "velocity": [1500, 0.1, 0]}"#);
    assert!(refusals(&far).is_empty(), "{:?}", refusals(&far));
    let err = deck_of(&far, "cylinder-far").unwrap_err();
    assert!(
        err.contains("walls[0].motion.velocity: cannot export to LAMMPS: particles could reach the cylinder's end"),
        "{err}"
    );
    let ok = tube(r#"{"kind": "velocity", "velocity": [0.5, 0.1, 0]}"#);
    let deck = deck_of(&ok, "cylinder").unwrap();
    assert!(
        deck.contains("region       wall0 cylinder x 0e0 0e0 5e-3 -4e-3 4e-3 side in open 1 open 2 units box move v_wall0_dx v_wall0_dy NULL\n"),
        "{deck}"
    );
    let axial = tube(r#"{"kind": "displacement", "x": "0.001 * t", "y": "0.0", "z": "0.0"}"#);
    let paths: Vec<String> = refusals(&axial).into_iter().map(|(p, _)| p).collect();
    assert_eq!(paths, ["walls[0].motion.x"]);
}

#[test]
fn a_box_no_wider_than_a_particle_is_refused_and_nothing_is_written() {
    let narrow = two_spheres(
        r#"{"normal": {"law": "hertz"}}"#,
        r#", "walls": [{"material": "steel", "shape": {"kind": "box", "lower": [-0.01, -0.001, -0.01], "upper": [0.01, 0.001, 0.02]}}]"#,
    );
    let dir = std::env::temp_dir().join(format!("tamp-lammps-narrow-{}", std::process::id()));
    let err = export(&narrow, "sha", &dir, None).unwrap_err().to_string();
    assert!(
        err.contains("walls[0].shape: cannot export to LAMMPS"),
        "{err}"
    );
    assert!(!dir.exists());
}

#[test]
fn servo_pressed_and_moving_box_walls_are_refused_at_their_motion() {
    for wall in [
        r#"{"material": "steel", "shape": {"kind": "plane", "point": [0, 0, -0.01], "normal": [0, 0, 1]},
            "motion": {"kind": "pressure", "direction": [0, 0, 1], "pressure": 1e3, "area": 1e-4, "ramp_time": 1e-6, "mass": 1.0}}"#,
        r#"{"material": "steel", "shape": {"kind": "box", "lower": [-0.01, -0.01, -0.01], "upper": [0.01, 0.01, 0.01]},
            "motion": {"kind": "velocity", "velocity": [0, 0, 0.1]}}"#,
    ] {
        let paths: Vec<String> = refusals(&sphere_with_walls(wall))
            .into_iter()
            .map(|(p, _)| p)
            .collect();
        assert_eq!(paths, ["walls[0].motion"], "{wall}");
    }
}

/// Deposited particles are in the deck's data file like placed ones, so their material
/// counts in the rules that compare particle materials (the wall's one E and ν, and the
/// explicit pair_coeff lines of friction pairs).
#[test]
fn deposited_materials_count_in_the_material_rules() {
    let s = scene::parse(
        r#"{"name": "t", "seed": 1,
          "materials": [{"name": "glass", "density": 2500, "youngs_modulus": 1e7, "poisson_ratio": 0.25},
                        {"name": "soft", "density": 2500, "youngs_modulus": 1e6, "poisson_ratio": 0.25}],
          "contact": {"normal": {"law": "hertz"},
                      "tangential": {"law": "lammps_mindlin", "variant": "mindlin", "friction": 0.5,
                                     "friction_pairs": [{"materials": ["glass", "soft"], "friction": 0.2}]},
                      "lever_arm": "lammps"},
          "particles": [{"position": [0.005, 0.005, 0.01], "radius": 0.0005, "material": "glass"}],
          "deposit": [{"count": 20, "material": "soft", "radius": 0.0005,
                       "footprint": [[0, 0], [0.01, 0.01]], "floor": 0.0}],
          "walls": [{"name": "floor", "material": "glass",
                     "shape": {"kind": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}}],
          "periodic": {"x": [0, 0.01], "y": [0, 0.01]},
          "rotation": {}, "gravity": [0, 0, -9.81],
          "time_step": {"fixed": 1e-6}, "run": {"steps": 10}}"#,
    )
    .expect("a valid scene");
    let paths: Vec<String> = refusals(&s).into_iter().map(|(p, _)| p).collect();
    assert!(
        paths.contains(&"walls[0].material".to_string()),
        "{paths:?}"
    );
    assert!(
        paths.contains(&"contact.tangential.friction_pairs".to_string()),
        "{paths:?}"
    );
}

/// One MDR sphere (the law's own E and ν, the material's density) with `walls`.
fn mdr_sphere_with_walls(walls: &str, output: &str) -> Scene {
    two_spheres(
        r#"{"normal": {"law": "mdr", "youngs_modulus": 1.83e11, "poisson_ratio": 0.318, "yield_stress": 8e8,
            "bulk_trigger": 0.5, "damping": {"coefficient": 1.8, "form": "stiffness"}}}"#,
        &format!(r#", "walls": [{walls}]{output}"#),
    )
}

#[test]
fn mdr_is_pair_granular_mdr_with_its_dashpot_radii_that_change_and_only_region_walls() {
    let s = mdr_sphere_with_walls(
        r#"{"material": "steel", "shape": {"kind": "plane", "point": [0, 0, -0.02], "normal": [0, 0, 1]}}"#,
        "",
    );
    assert!(refusals(&s).is_empty(), "{:?}", refusals(&s));
    let deck = deck_of(&s, "mdr").unwrap();
    let model =
        "mdr 1.83e11 3.18e-1 8e8 0e0 5e-1 1.8e0 damping mdr 1 tangential linear_nohistory 0 0";
    for line in [
        "atom_style   sphere 1\n".to_string(),
        "newton       off\n".to_string(),
        format!("pair_coeff   * * {model}\n"),
        "dump         mdr all custom 10 mdr.lammps id d_psi\n".to_string(),
        // Even an axis-aligned fixed plane: LAMMPS's mdr takes region walls only.
        format!(
            "region       wall0 plane 0e0 0e0 -2e-2 0e0 0e0 1e0 side in units box\nfix          wall0 all wall/gran/region granular {model} region wall0\n"
        ),
    ] {
        assert!(deck.contains(&line), "{line}\n{deck}");
    }
    let boxed = mdr_sphere_with_walls(
        r#"{"material": "steel", "shape": {"kind": "box", "lower": [-0.01, -0.01, -0.01], "upper": [0.01, 0.01, 0.01]}}"#,
        "",
    );
    let refused = refusals(&boxed);
    assert_eq!(refused.len(), 1, "{refused:?}");
    assert_eq!(refused[0].0, "walls[0].shape");
    assert!(refused[0].1.contains("region walls"), "{}", refused[0].1);
    // Spins take the moment of inertia of the growing radius in LAMMPS.
    let plane = r#"{"material": "steel", "shape": {"kind": "plane", "point": [0, 0, -0.02], "normal": [0, 0, 1]}}"#;
    let spinning = mdr_sphere_with_walls(plane, r#", "rotation": {}"#);
    let refused: Vec<String> = refusals(&spinning).into_iter().map(|(p, _)| p).collect();
    assert_eq!(refused, ["rotation.inertia_radius"]);
    let current = mdr_sphere_with_walls(plane, r#", "rotation": {"inertia_radius": "current"}"#);
    assert!(refusals(&current).is_empty(), "{:?}", refusals(&current));
}

/// A wall's own surface energy goes into its fix, the particles' into `pair_coeff`
/// (LAMMPS's tableting example: adhesive particles, non-adhesive walls).
#[test]
fn mdr_walls_take_their_own_surface_energy() {
    let s = two_spheres(
        r#"{"normal": {"law": "mdr", "youngs_modulus": 1.83e11, "poisson_ratio": 0.318, "yield_stress": 8e8,
            "surface_energy": 2.0, "wall_surface_energy": 0.0,
            "bulk_trigger": 0.5, "damping": {"coefficient": 1.8, "form": "stiffness"}}}"#,
        r#", "walls": [{"material": "steel", "shape": {"kind": "plane", "point": [0, 0, -0.02], "normal": [0, 0, 1]}}]"#,
    );
    assert!(refusals(&s).is_empty(), "{:?}", refusals(&s));
    let deck = deck_of(&s, "mdr-gamma").unwrap();
    let model = |gamma: &str| {
        format!(
            "mdr 1.83e11 3.18e-1 8e8 {gamma} 5e-1 1.8e0 damping mdr 1 tangential linear_nohistory 0 0"
        )
    };
    assert!(
        deck.contains(&format!("pair_coeff   * * {}\n", model("2e0"))),
        "{deck}"
    );
    assert!(
        deck.contains(&format!(
            "wall/gran/region granular {} region wall0",
            model("0e0")
        )),
        "{deck}"
    );
}

/// LAMMPS's fix granular/mdr takes one mdr model: one `pair_coeff * *`, and a scene whose
/// particles are of two materials is refused.
#[test]
fn mdr_is_one_pair_coeff_for_every_type_and_one_particle_material() {
    let plane = r#"{"material": "steel", "shape": {"kind": "plane", "point": [0, 0, -0.02], "normal": [0, 0, 1]}}"#;
    let mut s = mdr_sphere_with_walls(plane, "");
    let steel = s.materials[0].clone();
    s.materials.push(MaterialSpec {
        name: "brass".into(),
        ..steel
    });
    let deck = deck_of(&s, "mdr-types").unwrap();
    assert_eq!(deck.matches("pair_coeff").count(), 1, "{deck}");
    s.particles[1].material = "brass".into();
    let refused: Vec<String> = refusals(&s).into_iter().map(|(p, _)| p).collect();
    assert_eq!(refused, ["materials"]);
}

/// A rolling law turns LAMMPS's atom sorting off: the sort swaps pairs in the
/// neighbour list, and LAMMPS negates a swapped pair's rolling history.
#[test]
fn rolling_sds_is_written_with_atom_sorting_off() {
    let s = two_spheres(
        r#"{"normal": {"law": "linear", "stiffness": 1e4},
            "tangential": {"law": "lammps_linear_history", "stiffness": 1e4, "x_gamma_t": 0, "friction": 0.5},
            "rolling": {"law": "sds", "stiffness": 1.0, "damping": 0.0, "friction": 0.2}, "lever_arm": "lammps"}"#,
        r#", "rotation": {}"#,
    );
    let deck = deck_of(&s, "rolling").unwrap();
    assert!(
        deck.contains("atom_modify  map array sort 0 0.0\n"),
        "{deck}"
    );
    assert!(
        deck.contains("tangential linear_history 1e4 0e0 5e-1 rolling sds 1e0 0e0 2e-1"),
        "{deck}"
    );
    let plain = two_spheres(r#"{"normal": {"law": "linear", "stiffness": 1e4}}"#, "");
    assert!(
        deck_of(&plain, "no-rolling")
            .unwrap()
            .contains("atom_modify  map array\n")
    );
}

#[test]
fn output_walls_prints_each_walls_displacement_and_force_into_walls_csv() {
    let s = mdr_sphere_with_walls(
        r#"{"material": "steel", "shape": {"kind": "plane", "point": [0, 0, -0.02], "normal": [0, 0, 1]},
            "motion": {"kind": "velocity", "velocity": [0, 0, 0.5]}}"#,
        r#", "output": {"trajectory_every": 10, "walls": true}"#,
    );
    let deck = deck_of(&s, "walls").unwrap();
    for line in [
        " region wall0 contacts\n",
        "compute      wall0_f all reduce sum f_wall0[2] f_wall0[3] f_wall0[4]\n",
        "variable     rec0_dx equal 0\n",
        "variable     rec0_dz equal v_wall0_dz\n",
        "variable     rec0_fz equal -(c_wall0_f[3])\n",
        "variable     rec0_fz_g format rec0_fz %.17g\n",
        "fix          rec_walls all print 10 \"\"\"${rec_step},1,${rec0_dx_g},${rec0_dy_g},${rec0_dz_g},${rec0_fx_g},${rec0_fy_g},${rec0_fz_g}\"\"\" file walls.csv screen no title \"step,wall,dx,dy,dz,fx,fy,fz\"\n",
    ] {
        assert!(deck.contains(line), "{line}\n{deck}");
    }
    // Without output.walls the deck is as before.
    let plain = mdr_sphere_with_walls(
        r#"{"material": "steel", "shape": {"kind": "plane", "point": [0, 0, -0.02], "normal": [0, 0, 1]}}"#,
        "",
    );
    let deck = deck_of(&plain, "no-walls").unwrap();
    assert!(
        !deck.contains("contacts") && !deck.contains("walls.csv"),
        "{deck}"
    );
}
