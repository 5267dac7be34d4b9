//! The registry of laws: each law's closed-form examples, evaluated at one reference
//! contact. Every harness takes its laws from here (tests/contact_laws.rs,
//! tests/properties.rs, `benches/contact_laws.rs`, `tamp study stable-alpha`), so a
//! law enrols in all of them by registering its examples; a role enum's variant with
//! no example fails `every_law_has_a_closed_form_example` (tests/contact_laws.rs).
//!
//! An example is data: a law with parameters, the state it is evaluated at, and the
//! value the law's source gives there, written from the source's formula in the
//! law's file (not by calling the law's own code).

use super::model::TangentialInput;
use super::normal::NormalLaw;
use super::tangential::TangentialLaw;
use crate::material::{Hollomon, PairProperties};
use crate::particles::Vec3;

/// The reference contact of every example: two steel-like spheres of R = 1 mm
/// (R* = 0.5 mm), E* = 110 GPa, G* = 21 GPa, Hollomon σ0 = 1 GPa, m = 0.15, μ = 0.4.
pub const EFFECTIVE_RADIUS: f64 = 5e-4;
/// Effective mass m* of the reference contact, kg.
pub const EFFECTIVE_MASS: f64 = 1e-4;
/// Effective modulus E* of the reference contact, Pa.
pub const EFFECTIVE_MODULUS: f64 = 1.1e11;
/// Effective shear modulus G* of the reference contact, Pa.
pub const EFFECTIVE_SHEAR_MODULUS: f64 = 2.1e10;
/// Friction coefficient μ of the reference contact.
pub const FRICTION: f64 = 0.4;
/// Effective Hollomon constants σ0* (Pa) and m of the reference contact.
pub const HOLLOMON: Hollomon = Hollomon {
    strength: 1e9,
    exponent: 0.15,
};

/// The material pair of the reference contact.
pub fn pair() -> PairProperties {
    PairProperties {
        effective_modulus: Some(EFFECTIVE_MODULUS),
        effective_shear_modulus: Some(EFFECTIVE_SHEAR_MODULUS),
        hollomon: Some(HOLLOMON),
        law_constant: Some(crate::contact::normal::storakers::storakers_pair_constant(
            HOLLOMON,
        )),
        friction: FRICTION,
    }
}

/// A normal law's closed form: the force of a fresh contact at the reference pair,
/// loaded to `overlap` at the rate `rate` (> 0: approaching).
#[derive(Clone, Copy, Debug)]
pub struct NormalExample {
    /// The law, with its parameters.
    pub law: NormalLaw,
    /// Overlap δ reached, m.
    pub overlap: f64,
    /// Overlap rate dδ/dt, m/s (> 0: approaching).
    pub rate: f64,
    /// What the law's source gives, N.
    pub force: f64,
}

/// A tangential law's closed form: the force after one step from a fresh state.
#[derive(Clone, Copy, Debug)]
pub struct TangentialExample {
    /// The law, with its parameters.
    pub law: TangentialLaw,
    /// The contact and the step the law is evaluated at.
    pub input: TangentialInput,
    /// What the law's source gives, N.
    pub force: Vec3,
}

/// The reference contact at overlap 1 µm, carrying a normal force of 3 N (the Hertz
/// force there is 3.3 N) with tangent stiffness 2 MN/m, sliding at `velocity` over
/// one step `dt`.
pub fn tangential_input(velocity: Vec3, dt: f64) -> TangentialInput {
    TangentialInput {
        normal: Vec3::z(),
        tangential_velocity: velocity,
        dt,
        friction: FRICTION,
        normal_force: 3.0,
        normal_stiffness: 2e6,
        overlap: 1e-6,
        effective_radius: EFFECTIVE_RADIUS,
        effective_shear_modulus: EFFECTIVE_SHEAR_MODULUS,
        effective_mass: EFFECTIVE_MASS,
        normal_damping: 0.0,
    }
}

/// A step that sticks for every spring law (k Δs ≪ μF_n): 10 mm/s over 1 µs.
pub fn sticking_input() -> TangentialInput {
    tangential_input(Vec3::new(6e-3, -8e-3, 0.0), 1e-6)
}

/// A step that slides for every law (k Δs ≫ μF_n): 1 m/s over 10 µs.
pub fn sliding_input() -> TangentialInput {
    tangential_input(Vec3::new(0.6, 0.8, 0.0), 1e-5)
}

/// `sticking_input` and `sliding_input` with the normal dashpot's coefficient η_n,
/// N·s/m, for the laws whose tangential dashpot scales with it (LAMMPS's).
pub fn damped_inputs(eta: f64) -> (TangentialInput, TangentialInput) {
    (
        TangentialInput {
            normal_damping: eta,
            ..sticking_input()
        },
        TangentialInput {
            normal_damping: eta,
            ..sliding_input()
        },
    )
}

/// Coulomb's limit at the reference contact, opposing the slip: −μF_n v̂_t.
pub fn sliding_force(input: &TangentialInput) -> Vec3 {
    -input.tangential_velocity.normalize() * (input.friction * input.normal_force)
}

/// The overlaps every normal law is checked at, m, and the loading rate, m/s.
pub const OVERLAPS: [f64; 4] = [1e-8, 1e-7, 1e-6, 5e-6];
/// Overlap rate dδ/dt of the normal examples, m/s.
pub const LOADING_RATE: f64 = 0.01;

/// A normal law's examples: a fresh contact loaded to each of `OVERLAPS` at
/// `LOADING_RATE`, where its source gives `force(δ)`.
pub fn loading_examples(law: NormalLaw, force: impl Fn(f64) -> f64) -> Vec<NormalExample> {
    OVERLAPS
        .map(|overlap| NormalExample {
            law,
            overlap,
            rate: LOADING_RATE,
            force: force(overlap),
        })
        .to_vec()
}

/// The two examples of a spring law of stiffness `k` from rest: sticking, F = −k v_t Δt;
/// sliding, Coulomb's limit −μF_n v̂_t.
pub fn spring_examples(law: TangentialLaw, k: f64) -> Vec<TangentialExample> {
    let (stick, slide) = (sticking_input(), sliding_input());
    vec![
        TangentialExample {
            law,
            input: stick,
            force: -stick.tangential_velocity * (k * stick.dt),
        },
        TangentialExample {
            law,
            input: slide,
            force: sliding_force(&slide),
        },
    ]
}

/// Mindlin's no-slip stiffness 8G*√(R*δ) at the reference contact (Rojek eq 12).
pub fn mindlin_stiffness() -> f64 {
    let s = sticking_input();
    8.0 * s.effective_shear_modulus * (s.effective_radius * s.overlap).sqrt()
}

/// Every normal law's examples, in the order of `NormalLaw`.
pub fn normal_examples() -> Vec<NormalExample> {
    use super::normal::*;
    [
        Linear::examples(),
        Hertz::examples(),
        KuwabaraKono::examples(),
        WaltonBraun::examples(),
        Hysteretic::examples(),
        Storakers::examples(),
        Thornton::examples(),
        crate::contact::mdr::Mdr::examples(),
    ]
    .concat()
}

/// Every tangential law's examples, in the order of `TangentialLaw`.
pub fn tangential_examples() -> Vec<TangentialExample> {
    use super::tangential::*;
    [
        MindlinDeresiewicz::examples(),
        Coulomb::examples(),
        HaffWerner::examples(),
        CundallStrack::examples(),
        walton_braun::WaltonBraun::examples(),
        MindlinNoSlip::examples(),
        storakers::Storakers::examples(),
        LiggghtsHistory::examples(),
        lammps_mindlin::LammpsMindlin::examples(),
        lammps_linear_history::LammpsLinearHistory::examples(),
        lammps_linear_nohistory::LammpsLinearNohistory::examples(),
    ]
    .concat()
}

/// The registered normal laws, each once (the parameters of its first example).
pub fn normal_laws() -> Vec<NormalLaw> {
    distinct(normal_examples().into_iter().map(|e| e.law))
}

/// The registered tangential laws, each once (the parameters of its first example).
pub fn tangential_laws() -> Vec<TangentialLaw> {
    distinct(tangential_examples().into_iter().map(|e| e.law))
}

fn distinct<L: PartialEq>(laws: impl Iterator<Item = L>) -> Vec<L> {
    let mut out: Vec<L> = Vec::new();
    for law in laws {
        if !out.contains(&law) {
            out.push(law);
        }
    }
    out
}
