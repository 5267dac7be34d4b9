//! Which radius MDR's spins take their moment of inertia from
//! (`rotation.inertia_radius`): the initial one unless the scene asks for the radius of
//! the step, LAMMPS's `fix nve/sphere` (the `lammps_mdr_triaxial` case compares the two
//! codes).

use tamp::scene::{self, physics::InertiaRadius};

/// The moments of inertia and the 2/5 m R² of the radii now, after 20 000 steps of the
/// triaxial compaction, whose particles have yielded by then.
fn after_yield(inertia_radius: InertiaRadius) -> Vec<(f64, f64, f64)> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("verification/lammps_mdr_triaxial.scene.json");
    let mut s = scene::load(&path).expect("the case's scene").0;
    s.rotation.as_mut().expect("it spins").inertia_radius = inertia_radius;
    let mut sim = scene::build(&s).expect("it builds").sim;
    let initial = sim.state().particles.inertia.clone();
    for _ in 0..20_000 {
        sim.step().expect("a stable step");
    }
    let p = &sim.state().particles;
    (0..p.len())
        .map(|i| {
            (
                p.inertia[i],
                0.4 * p.mass[i] * p.radius[i] * p.radius[i],
                initial[i],
            )
        })
        .collect()
}

#[test]
fn spins_keep_the_initial_moment_of_inertia_unless_the_scene_asks_for_the_current_radius() {
    let initial = after_yield(InertiaRadius::Initial);
    assert!(
        initial
            .iter()
            .any(|(_, now, start)| now > &(start * (1.0 + 1e-6))),
        "some radius has grown by the 20 000th step"
    );
    assert!(initial.iter().all(|(i, _, start)| i == start));
    let current = after_yield(InertiaRadius::Current);
    assert!(current.iter().all(|(i, now, _)| i == now));
}
