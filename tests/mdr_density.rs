//! Under MDR a relative density counts each particle's material, not its apparent
//! ball (`State::material_radius`): the apparent radius grows as plastic flow moves
//! material out of the contact flats, while the mass stays.

use std::f64::consts::PI;
use tamp::scene;

/// The triaxial compaction after 20 000 steps, when some radii have grown: the
/// material radius is the initial one, and the solid it gives is the mass over the
/// density, to round-off.
#[test]
fn the_material_radius_is_the_initial_one_and_weighs_the_mass() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("verification/lammps_mdr_triaxial.scene.json");
    let s = scene::load(&path).expect("the case's scene").0;
    let density = s.materials[0]
        .density
        .expect("the particles have a density");
    let mut sim = scene::build(&s).expect("it builds").sim;
    let initial = sim.state().particles.radius.clone();
    for _ in 0..20_000 {
        sim.step().expect("a stable step");
    }
    let state = sim.state();
    let p = &state.particles;
    assert!(
        (0..p.len()).any(|i| p.radius[i] > initial[i] * (1.0 + 1e-6)),
        "some radius has grown by the 20 000th step"
    );
    assert_eq!(state.material_radius(), &initial[..]);
    for (r, m) in state.material_radius().iter().zip(&p.mass) {
        let solid = 4.0 / 3.0 * PI * r.powi(3);
        assert!((solid * density - m).abs() <= 1e-12 * m);
    }
}
