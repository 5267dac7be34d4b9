//! Cost of ONE contact evaluation (`Composed::evaluate`) for every law in the
//! library, each role measured on top of the simplest base it needs:
//!
//! - `normal/*`: each normal law alone (no damping, no tangential, no cohesion);
//! - `damping/*`: Hertz + each damping model;
//! - `tangential/*`: Hertz + each tangential law (no damping);
//! - `cohesion/*`: Hertz + van der Waals, in contact and across a gap.
//!
//! The laws and their parameters are the registry's (`tamp::contact::registry`), so a
//! registered law is timed without being named here. Benchmark names are the
//! scene-file law names. One contact geometry is used
//! throughout (R* = 0.5 mm, δ = 1 µm, a relative velocity with both normal and
//! tangential parts) so the numbers compare the laws, not the inputs. The law is
//! turned into its composed type once (`ContactLaw::visit`: the normal law and the
//! tangential family as types), as the simulation does per run; its parameters, the geometry and the pair properties go through
//! `black_box`, so nothing is constant-folded. The contact state is the law's own
//! type, as in the simulation.
//!
//! Run with `cargo bench --bench contact_laws`.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use tamp::contact::damping::{Constant, CriticalFraction, MassVelocity, Viscoelastic};
use tamp::contact::model::{Composed, LawVisitor, NormalModel, StateOf, TangentialModel};
use tamp::contact::normal::Hertz;
use tamp::contact::normal::storakers::storakers_pair_constant;
use tamp::contact::registry;
use tamp::contact::van_der_waals::{Cohesion, VanDerWaals};
use tamp::contact::{
    ContactGeometry, ContactLaw, damping::Damping, normal::NormalLaw, tangential::TangentialLaw,
};
use tamp::material::{Hollomon, PairProperties};
use tamp::particles::Vec3;

/// Time step, s (only the history laws read it).
const DT: f64 = 1e-7;

/// A 1 µm overlap between spheres of effective radius 0.5 mm, approaching at
/// 8 mm/s (δ̇ > 0: the loading branch of the rate-dependent laws) and sliding at
/// about 2 cm/s. Hertz then gives F_n ≈ 0.03 N and k_n ≈ 4.5e4 N/m.
fn contact_geometry() -> ContactGeometry {
    ContactGeometry {
        normal: Vec3::new(0.0, 0.6, 0.8),
        overlap: 1e-6,
        effective_radius: 5e-4,
        effective_mass: 1e-4,
        relative_velocity: Vec3::new(0.01, -0.02, 0.005),
    }
}

fn pair_properties() -> PairProperties {
    let hollomon = Hollomon {
        strength: 1e9,
        exponent: 0.1,
    };
    PairProperties {
        effective_modulus: Some(1e9),
        effective_shear_modulus: Some(4e8),
        hollomon: Some(hollomon),
        law_constant: Some(storakers_pair_constant(hollomon)),
        friction: 0.5,
    }
}

/// Hamaker constant of a typical silicate in air, the 0.4 nm interatomic cut and a
/// 100 nm range.
const VDW: VanDerWaals = VanDerWaals {
    hamaker: 1e-19,
    min_separation: 4e-10,
    cutoff: 1e-7,
};

fn law(
    normal: NormalLaw,
    damping: Option<Damping>,
    tangential: Option<TangentialLaw>,
    cohesion: Option<Cohesion>,
) -> ContactLaw {
    ContactLaw {
        normal,
        damping,
        tangential,
        cohesion,
        rolling: None,
        lever_arm: Default::default(),
        no_pull: false,
    }
}

/// Benchmark each `(name, law, geometry)` in the criterion group `group` (so ids read
/// `group/name`).
///
/// For laws with a state the same state is evaluated over and over. The normal
/// laws with memory then sit on their loading branch (δ = δ_max every call), and
/// the tangential springs saturate at the Coulomb limit within the first few
/// hundred calls of warm-up, so what is timed is a steadily sliding contact: the
/// rotate–increment–cap path that every sliding contact takes each step. That is
/// acceptable and representative of sliding contacts in sheared packings; a
/// sticking contact runs the same arithmetic except the final rescale onto the
/// friction cone. Because each call reads the state the previous call wrote, the
/// history laws are timed latency-bound; in the simulation consecutive contacts
/// have independent records and can overlap, so for them these figures are an
/// upper bound.
fn bench_group<S: AsRef<str>>(
    c: &mut Criterion,
    group: &str,
    cases: Vec<(S, ContactLaw, ContactGeometry)>,
) {
    let pair = pair_properties();
    let mut group = c.benchmark_group(group);
    for (name, law, g) in cases {
        group.bench_function(name.as_ref(), |b| {
            law.visit(Timed {
                bencher: b,
                g: &g,
                pair: &pair,
            })
        });
    }
    group.finish();
}

/// Time one law as its own type, with a state of its own type.
struct Timed<'a, 'b> {
    bencher: &'a mut criterion::Bencher<'b>,
    g: &'a ContactGeometry,
    pair: &'a PairProperties,
}

impl LawVisitor for Timed<'_, '_> {
    type Output = ();
    fn visit<N: NormalModel, T: TangentialModel>(self, law: Composed<N, T>) {
        let mut state = StateOf::<N, T>::default();
        self.bencher.iter(|| {
            black_box(black_box(&law).evaluate(
                black_box(self.g),
                black_box(self.pair),
                &mut state,
                black_box(DT),
            ))
        })
    }
}

/// Each law with its benchmark name: the scene's law name, numbered from the second
/// registered instance of a name on (`liggghts_history_2` is its `model hooke`).
fn labelled<L>(laws: Vec<L>, name: impl Fn(&L) -> &'static str) -> Vec<(String, L)> {
    let mut seen: Vec<&str> = Vec::new();
    laws.into_iter()
        .map(|law| {
            let base = name(&law);
            seen.push(base);
            let count = seen.iter().filter(|&&n| n == base).count();
            let label = if count == 1 {
                base.to_string()
            } else {
                format!("{base}_{count}")
            };
            (label, law)
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let g = contact_geometry();

    bench_group(
        c,
        "normal",
        labelled(registry::normal_laws(), |n| n.name())
            .into_iter()
            .map(|(name, n)| (name, law(n, None, None, None), g))
            .collect(),
    );

    // Critical damping here is 2√(m* k_n) ≈ 4.2 N·s/m.
    bench_group(
        c,
        "damping",
        vec![
            (
                "critical_fraction",
                law(
                    NormalLaw::Hertz(Hertz {}),
                    Some(Damping::CriticalFraction(CriticalFraction { xi: 0.3 })),
                    None,
                    None,
                ),
                g,
            ),
            (
                "constant",
                law(
                    NormalLaw::Hertz(Hertz {}),
                    Some(Damping::Constant(Constant { gamma_n: 1.0 })),
                    None,
                    None,
                ),
                g,
            ),
            (
                "mass_velocity",
                law(
                    NormalLaw::Hertz(Hertz {}),
                    Some(Damping::MassVelocity(MassVelocity { eta_n0: 1.0e4 })),
                    None,
                    None,
                ),
                g,
            ),
            (
                "viscoelastic",
                law(
                    NormalLaw::Hertz(Hertz {}),
                    Some(Damping::Viscoelastic(Viscoelastic { eta_n0: 1.0e9 })),
                    None,
                    None,
                ),
                g,
            ),
        ],
    );

    bench_group(
        c,
        "tangential",
        labelled(registry::tangential_laws(), |t| t.name())
            .into_iter()
            .map(|(name, t)| {
                (
                    name,
                    law(NormalLaw::Hertz(Hertz {}), None, Some(t), None),
                    g,
                )
            })
            .collect(),
    );

    let cohesive = law(
        NormalLaw::Hertz(Hertz {}),
        None,
        None,
        Some(Cohesion::VanDerWaals(VDW)),
    );
    bench_group(
        c,
        "cohesion",
        vec![
            // In contact the attraction is saturated at h_min.
            ("van_der_waals_contact", cohesive, g),
            // A 10 nm gap, inside the 100 nm cut-off: no normal law, only A R*/(6h²).
            (
                "van_der_waals_gap",
                cohesive,
                ContactGeometry {
                    overlap: -1e-8,
                    ..g
                },
            ),
        ],
    );
}

criterion_group!(benches, bench);
criterion_main!(benches);
