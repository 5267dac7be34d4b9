//! Cost of one contact evaluation for each composition of roles the scene can
//! enable (normal law, + damping, + tangential spring). Run with
//! `cargo bench --bench contact_laws`.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use tamp::contact::history::ContactHistory;
use tamp::contact::{
    ContactGeometry, ContactLaw, damping::Damping, normal::NormalLaw, tangential::TangentialLaw,
};
use tamp::material::PairProperties;
use tamp::particles::Vec3;

fn bench(c: &mut Criterion) {
    let g = ContactGeometry {
        normal: Vec3::new(0.0, 0.6, 0.8),
        overlap: 1e-6,
        effective_radius: 5e-4,
        effective_mass: 1e-4,
        relative_velocity: Vec3::new(0.01, -0.02, 0.005),
    };
    let pair = PairProperties {
        effective_modulus: Some(1e9),
        effective_shear_modulus: Some(4e8),
        hollomon: None,
        friction: 0.5,
    };
    let laws = [
        ("linear", NormalLaw::Linear { stiffness: 1e5 }, None, None),
        ("hertz", NormalLaw::Hertz, None, None),
        (
            "hertz+critical_fraction",
            NormalLaw::Hertz,
            Some(Damping::CriticalFraction { xi: 0.3 }),
            None,
        ),
        (
            "hertz+critical_fraction+cundall_strack",
            NormalLaw::Hertz,
            Some(Damping::CriticalFraction { xi: 0.3 }),
            Some(TangentialLaw::CundallStrack { stiffness: 1e4 }),
        ),
    ];
    let mut group = c.benchmark_group("contact_evaluation");
    for (name, normal, damping, tangential) in laws {
        let law = ContactLaw {
            normal,
            damping,
            tangential,
            cohesion: None,
        };
        let mut spring = ContactHistory::default();
        group.bench_function(name, |b| {
            b.iter(|| {
                let s = law.has_history().then_some(&mut spring);
                black_box(law.evaluate(black_box(&g), &pair, s, 1e-7))
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
