//! Properties every contact law must have, checked over the whole library: force
//! against its closed form at several overlaps, continuity at first touch, symmetry
//! under swapping the bodies, Newton's third law in a running simulation, non-positive
//! work of the contact over closed cycles for the dissipative laws, and the friction
//! cone. The laws and their closed forms come from the registry
//! (`tamp::contact::registry`): a registered law is checked here without being named.

use tamp::contact::normal::{NormalLaw, WaltonBraun};
use tamp::contact::registry::{self, EFFECTIVE_RADIUS as R_EFF, FRICTION as MU, pair};
use tamp::contact::tangential::{MindlinDeresiewicz, TangentialLaw, TangentialModel, walton_braun};
use tamp::contact::{ContactForce, ContactGeometry, ContactLaw};
use tamp::material::PairProperties;
use tamp::particles::Vec3;

/// Every registered normal law with every registered tangential law (and none).
fn every_law() -> Vec<ContactLaw> {
    let mut out = Vec::new();
    for n in registry::normal_laws() {
        let frictionless = std::iter::once(None);
        for t in frictionless.chain(registry::tangential_laws().into_iter().map(Some)) {
            out.push(ContactLaw {
                normal: n,
                damping: None,
                tangential: t,
                cohesion: None,
                rolling: None,
                lever_arm: Default::default(),
                no_pull: false,
            });
        }
    }
    out
}

/// The forces of a fresh contact driven along `path` at the step `dt`.
fn forces(
    law: &ContactLaw,
    pair: &PairProperties,
    path: &[ContactGeometry],
    dt: f64,
) -> Vec<ContactForce> {
    let path: Vec<(ContactGeometry, f64)> = path.iter().map(|g| (*g, dt)).collect();
    law.forces_along(pair, &path)
}

fn geometry(normal: Vec3, overlap: f64, relative_velocity: Vec3) -> ContactGeometry {
    ContactGeometry {
        normal,
        overlap,
        effective_radius: R_EFF,
        effective_mass: 1e-4,
        relative_velocity,
    }
}

/// The variant names serde knows for a role enum (from its unknown-variant message):
/// the compiler's list of the laws, independent of the registry.
fn variants<T: serde::de::DeserializeOwned + std::fmt::Debug>() -> Vec<String> {
    let err = serde_json::from_str::<T>(r#"{"law": "?"}"#)
        .unwrap_err()
        .to_string();
    let expected = &err[err.find("expected").expect("an unknown-variant message")..];
    expected
        .split('`')
        .skip(1)
        .step_by(2)
        .map(str::to_string)
        .collect()
}

#[test]
fn every_law_has_a_closed_form_example() {
    let normal: Vec<&str> = registry::normal_examples()
        .iter()
        .map(|e| e.law.name())
        .collect();
    for law in variants::<NormalLaw>() {
        assert!(
            normal.iter().any(|n| n.starts_with(law.as_str())),
            "normal law '{law}' registers no closed-form example (contact/registry.rs)"
        );
    }
    let tangential: Vec<&str> = registry::tangential_examples()
        .iter()
        .map(|e| e.law.name())
        .collect();
    let names = variants::<TangentialLaw>();
    assert!(names.len() >= 8, "{names:?}");
    for law in names {
        assert!(
            tangential.contains(&law.as_str()),
            "tangential law '{law}' registers no closed-form example (contact/registry.rs)"
        );
    }
}

/// Rounding only: the closed forms are evaluated with other operations in another
/// order than the laws, a few ulps apart.
const CLOSED_FORM_TOLERANCE: f64 = 1e-12;

#[test]
fn normal_force_matches_the_closed_forms() {
    for e in registry::normal_examples() {
        let got = e.law.response(e.overlap, e.rate, R_EFF, &pair()).force;
        assert!(
            (got - e.force).abs() <= CLOSED_FORM_TOLERANCE * e.force.abs(),
            "{} at {:e}: {got:e} vs {:e}",
            e.law.name(),
            e.overlap,
            e.force
        );
    }
}

#[test]
fn tangential_force_matches_the_closed_forms() {
    for e in registry::tangential_examples() {
        let got = tamp::each_tangential!(e.law, t => t.force(&e.input, &mut Default::default()));
        assert!(
            (got - e.force).norm() <= CLOSED_FORM_TOLERANCE * e.force.norm(),
            "{} at v_t {:?}: {got:?} vs {:?}",
            e.law.name(),
            e.input.tangential_velocity,
            e.force
        );
    }
}

#[test]
fn force_is_continuous_at_first_touch() {
    for law in every_law() {
        let g = geometry(Vec3::z(), 1e-300, Vec3::new(0.0, 0.0, -1e-3));
        let f = forces(&law, &pair(), &[g], 1e-7)[0];
        assert!(
            f.normal.abs() < 1e-100 && f.tangential.norm() < 1e-100,
            "{} + {:?}",
            law.normal.name(),
            law.tangential.map(|t| t.name())
        );
    }
}

#[test]
fn swapping_the_bodies_reverses_the_force() {
    let n = Vec3::new(0.0, 0.6, 0.8);
    let v = Vec3::new(0.02, -0.01, -0.015);
    for law in every_law() {
        // A few steps so that history laws leave their first branch.
        let overlaps: Vec<f64> = (0..5).map(|k| 1e-6 * (1.0 + k as f64)).collect();
        let path: Vec<_> = overlaps.iter().map(|&d| geometry(n, d, v)).collect();
        let swapped: Vec<_> = overlaps.iter().map(|&d| geometry(-n, d, -v)).collect();
        let f1 = *forces(&law, &pair(), &path, 1e-5).last().unwrap();
        let f2 = *forces(&law, &pair(), &swapped, 1e-5).last().unwrap();
        let (a, b) = (
            n * f1.normal + f1.tangential,
            -n * f2.normal + f2.tangential,
        );
        assert!(
            (a + b).norm() <= 1e-12 * a.norm(),
            "{} + {:?}",
            law.normal.name(),
            law.tangential.map(|t| t.name())
        );
    }
}

#[test]
fn friction_never_leaves_the_cone() {
    let n = Vec3::z();
    for law in every_law().into_iter().filter(|l| l.tangential.is_some()) {
        let path: Vec<_> = (0..400)
            .map(|k| {
                let t = k as f64 * 0.05;
                let overlap = 1e-6 * (1.5 + t.sin());
                let v = Vec3::new((3.0 * t).cos(), (1.7 * t).sin(), 0.0) * 0.05;
                geometry(n, overlap, v + n * (-1e-3 * t.cos()))
            })
            .collect();
        for (k, f) in forces(&law, &pair(), &path, 1e-5).into_iter().enumerate() {
            assert!(
                f.tangential.norm() <= MU * f.normal.max(0.0) * (1.0 + 1e-12) + 1e-300,
                "{} + {:?} at step {k}",
                law.normal.name(),
                law.tangential.map(|t| t.name())
            );
            assert!(f.tangential.dot(&n).abs() <= 1e-12 * f.tangential.norm() + 1e-300);
        }
    }
}

/// Work done on the contact (by the bodies) over a closed cycle: overlap 0 → δ_m → 0
/// and a tangential excursion out and back, integrated with the midpoint rule.
fn work_absorbed(law: &ContactLaw, max_overlap: f64) -> f64 {
    let n = Vec3::z();
    let steps = 20_000;
    let period = 1e-3;
    let dt = period / steps as f64;
    let position = |t: f64| {
        let phase = std::f64::consts::PI * t / period;
        (
            max_overlap * phase.sin(),
            0.3 * max_overlap * (2.0 * phase).sin(),
        )
    };
    let path: Vec<_> = (0..steps)
        .map(|k| {
            let t = (k as f64 + 0.5) * dt;
            let (d0, s0) = position(t - 0.5 * dt);
            let (d1, s1) = position(t + 0.5 * dt);
            let overlap = 0.5 * (d0 + d1);
            // Relative velocity of i: approach means −n; the tangential slip along x.
            let v = Vec3::new((s1 - s0) / dt, 0.0, -(d1 - d0) / dt);
            geometry(n, overlap, v)
        })
        .collect();
    let mut work = 0.0;
    for (g, f) in path.iter().zip(forces(law, &pair(), &path, dt)) {
        let force = n * f.normal + f.tangential;
        // The contact force on i does work force·v dt on i; the contact absorbs minus that.
        work -= force.dot(&g.relative_velocity) * dt;
    }
    work
}

#[test]
fn dissipative_laws_absorb_work_over_closed_cycles() {
    for law in every_law() {
        // Pure Storåkers is not passive below its threshold (see its unit tests);
        // cycle it beyond, at 1e-5 m for this pair.
        let max_overlap = 1e-5;
        let absorbed = work_absorbed(&law, max_overlap);
        let scale = law.normal.response(max_overlap, 0.0, R_EFF, &pair()).force * max_overlap;
        let name = format!(
            "{} + {:?}",
            law.normal.name(),
            law.tangential.map(|t| t.name())
        );
        assert!(
            absorbed >= -1e-6 * scale,
            "{name}: absorbed {absorbed:e} J of scale {scale:e} J"
        );
        // `lammps_linear_nohistory` is only a dashpot scaled from the normal damping,
        // which these laws leave out: it exerts no force here, so it is elastic.
        let frictional = law
            .tangential
            .is_some_and(|t| t.name() != "lammps_linear_nohistory");
        let dissipative = law.normal.has_memory() || law.normal.has_own_dissipation() || frictional;
        if dissipative {
            assert!(
                absorbed > 1e-6 * scale,
                "{name}: a dissipative law absorbed {absorbed:e} J"
            );
        } else {
            assert!(
                absorbed.abs() <= 1e-6 * scale,
                "{name}: an elastic law absorbed {absorbed:e} J"
            );
        }
    }
}

#[test]
fn newtons_third_law_holds_in_a_simulation() {
    use tamp::scene::{self, schema::Scene};
    let text = r#"{
      "materials": [{"name": "s", "density": 7800, "youngs_modulus": 2e11, "poisson_ratio": 0.3,
                     "hollomon": {"exponent": 0.1, "strength": 1e9}}],
      "contact": {"normal": {"law": "hertz"}},
      "particles": [
        {"position": [-0.001, 0, 0], "radius": 0.001, "material": "s", "velocity": [0.1, 0.05, 0]},
        {"position": [0.001, 0, 0], "radius": 0.001, "material": "s", "velocity": [-0.1, 0, 0.02]}
      ],
      "rotation": {},
      "time_step": {"fixed": 1e-8},
      "run": {"steps": 10}
    }"#;
    let base: Scene = serde_json::from_str(text).unwrap();
    // liggghts_history exists only with LIGGGHTS's normal models (scenes refuse the rest).
    let buildable = |law: &ContactLaw| {
        !matches!(law.tangential, Some(TangentialLaw::LiggghtsHistory(_)))
            || law.normal.liggghts().is_some()
    };
    for law in every_law().into_iter().filter(buildable) {
        let mut s = base.clone();
        s.contact = tamp::scene::schema::ContactSpec {
            normal: law.normal,
            damping: None,
            tangential: law.tangential.map(|law| tamp::scene::schema::FrictionSpec {
                law,
                friction: MU,
                friction_pairs: Vec::new(),
            }),
            cohesion: None,
            rolling: None,
            lever_arm: Default::default(),
        };
        let mut sim = scene::build(&s).unwrap().sim;
        for _ in 0..50 {
            sim.step().unwrap();
            let p = &sim.state().particles;
            assert!(p.force[0].norm() > 0.0, "{}: no contact", law.normal.name());
            assert!((p.force[0] + p.force[1]).norm() <= 1e-12 * p.force[0].norm());
        }
    }
}

#[test]
fn frictionless_tangential_laws_keep_the_normal_memory() {
    // With μ = 0 the tangential laws reset their own state every step; the normal
    // law's δ_max must survive, or Walton–Braun would never unload elastically.
    let frictionless = PairProperties {
        friction: 0.0,
        ..pair()
    };
    for t in [
        TangentialLaw::MindlinDeresiewicz(MindlinDeresiewicz {}),
        TangentialLaw::WaltonBraun(walton_braun::WaltonBraun { stiffness: 1e6 }),
    ] {
        let law = ContactLaw {
            normal: NormalLaw::WaltonBraun(WaltonBraun {
                loading_stiffness: 1e7,
                unloading_stiffness: 2e7,
            }),
            damping: None,
            tangential: Some(t),
            cohesion: None,
            rolling: None,
            lever_arm: Default::default(),
            no_pull: false,
        };
        let v = Vec3::new(1e-3, 0.0, 0.0);
        let path: Vec<_> = [1e-6, 2e-6, 1.5e-6]
            .iter()
            .map(|&d| geometry(Vec3::z(), d, v))
            .collect();
        let f = *forces(&law, &frictionless, &path, 1e-6).last().unwrap();
        // Unloading line: k2 (δ − δ_max (1 − k1/k2)) = 2e7 (1.5e-6 − 1e-6) = 10 N.
        assert!((f.normal - 10.0).abs() < 1e-9, "{}: {}", t.name(), f.normal);
    }
}
