//! The contact records of an MDR run are the forces its steps apply: they are
//! evaluated on a copy of the run that has made MDR's pass before the forces
//! (`simulation/records.rs`), so a pressing's force chains and die-wall forces read
//! the law as the run evolves it.

use tamp::contact::record::Partner;
use tamp::particles::Vec3;
use tamp::scene;

#[test]
fn each_particles_recorded_contact_forces_add_up_to_the_force_its_step_applied() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("verification/lammps_mdr_triaxial.scene.json");
    let s = scene::load(&path).expect("the case's scene").0;
    let mut sim = scene::build(&s).expect("it builds").sim;
    let (mut checked, mut yielded) = (0, false);
    for step in 1..=30_000u64 {
        if step % 2_500 != 0 {
            sim.step().expect("a stable step");
            continue;
        }
        let records = sim.step_recording_contacts().expect("a stable step");
        let p = &sim.state().particles;
        let mut sum = vec![Vec3::zeros(); p.len()];
        for r in &records {
            let f = r.normal * r.normal_force + r.tangential_force;
            sum[r.i] += f;
            if let Partner::Particle(j) = r.partner {
                sum[j] -= f;
            }
        }
        let largest = p.force.iter().map(|f| f.norm()).fold(0.0, f64::max);
        for (i, total) in sum.iter().enumerate() {
            let gap = (total - p.force[i]).norm();
            assert!(
                gap <= 1e-12 * largest,
                "step {step}, particle {}: records sum to {total:?}, the step applied {:?}",
                p.id[i],
                p.force[i]
            );
        }
        yielded |= p
            .radius
            .iter()
            .zip(&s.particles)
            .any(|(r, q)| *r > q.radius);
        checked += 1;
    }
    assert_eq!(checked, 12);
    assert!(yielded, "the radii grow within the steps checked");
}
