//! MDR as a scene's normal law (`"law": "mdr"`): Zunker & Kamrin's mechanically
//! derived response, whose equations and sources open `contact/mdr/mod.rs`.
//!
//! Unlike the pairwise laws, MDR keeps state per particle (`MdrParticles`: apparent
//! radius, free surface, volumes) and evaluates a pair as two rigid-flat sides, each
//! with its own particle. The force loop runs it with its particles (`force_loop.rs`);
//! what this file answers without them (`response`, the virgin-contact API of tests
//! and studies) is the pair of two equal spheres of radius 2R* that carry no other
//! contact and whose radius is not updated.
//!
//! Parameters are LAMMPS's `mdr E ν Y γ ψ_b η` with `damping mdr 1|2`: the law states
//! its own E and ν (one material, as in LAMMPS); the materials give density and
//! friction. The dashpot is the law's own (`OWN_DISSIPATION`).
//!
//! Time-step stiffness: one side's indenter has dF/dδ_e = 2E*a at contact radius a, so a
//! side is bounded by 2E*a and a pair of equal sides (in series) by E*a; tamp takes
//! 2E* times the larger side's radius. Before contact, the Hertz impact stiffness of
//! the pair (E*/2, R*), MDR's small-overlap limit. Stored energy: the particles' state
//! is needed, so `energy` here is 0 and the energy book adds each contact's
//! (`MdrContact::pair_energy`, `wall_energy`).

use super::NormalLaw;
use super::hertz::{hertz_max_overlap, hertz_stiffness};
use super::{NormalModel, NormalResponse};
use crate::contact::lammps::{LammpsNormal, NoLammpsModel};
use crate::contact::mdr::{Mdr, MdrContact, MdrParticles, PairSides};
use crate::contact::registry::{self, NormalExample};
use crate::error::Errors;
use crate::material::PairProperties;
use crate::particles::Vec3;

impl NormalModel for Mdr {
    type State = MdrContact;
    const OWN_DISSIPATION: bool = true;

    fn name(&self) -> &'static str {
        "mdr"
    }

    fn check(&self, path: &str, errors: &mut Errors) {
        Mdr::check(self, path, errors)
    }

    /// `pair granular mdr E ν Y γ ψ_b η damping mdr 1|2`, with `newton off`, an
    /// `atom_style sphere 1` whose radii change, and every wall a region
    /// (`fix wall/gran/region`): what LAMMPS's `fix granular/mdr` requires.
    fn lammps(&self) -> Result<LammpsNormal, NoLammpsModel> {
        Ok(LammpsNormal::Mdr(*self))
    }

    /// A fresh pair of equal spheres of radius R = 2R* evaluated once past yield: each
    /// side yields at its overlap δ = δ_pair/2 itself (c_A = π(δ² − δR)), so its contact
    /// area π(2δR − δ²) + c_A is πδR and the indenter, submerged to A/2, carries the
    /// yield pressure over it: F = Y (1.75 e^{−4.4δ/R} + 1) πδR.
    fn examples() -> Vec<NormalExample> {
        let law = reference();
        let r = 2.0 * registry::EFFECTIVE_RADIUS;
        registry::loading_examples(NormalLaw::Mdr(law), |d| {
            let delta = 0.5 * d;
            law.yield_stress
                * (1.75 * (-4.4 * delta / r).exp() + 1.0)
                * std::f64::consts::PI
                * delta
                * r
        })
    }

    fn response(
        &self,
        overlap: f64,
        rate: f64,
        r: f64,
        _: &PairProperties,
        state: &mut MdrContact,
    ) -> NormalResponse {
        let mut particles = MdrParticles::new(&[2.0 * r, 2.0 * r]);
        let moduli = self.moduli();
        let out = state.pair(
            self,
            &moduli,
            overlap,
            PairSides([1, 0]),
            &mut particles,
            Vec3::z(),
            0.0,
            true,
        );
        NormalResponse {
            force: out.force + out.damping * rate,
            stiffness: self.side_stiffness(state),
        }
    }

    fn stiffness(&self, _: f64, _: f64, _: &PairProperties, state: &MdrContact) -> f64 {
        self.side_stiffness(state)
    }

    fn energy(&self, _: f64, _: f64, _: &PairProperties, _: &MdrContact) -> f64 {
        0.0
    }

    fn impact_stiffness(&self, mass: f64, speed: f64, r: f64, _: &PairProperties) -> f64 {
        let e = 0.5 * self.plane_strain_modulus();
        hertz_stiffness(hertz_max_overlap(mass, speed, r, e), r, e)
    }

    fn stiffness_depends_on_speed(&self) -> bool {
        true
    }

    fn mdr(&self) -> Option<&Mdr> {
        Some(self)
    }

    fn mdr_contact(state: &mut MdrContact) -> Option<&mut MdrContact> {
        Some(state)
    }
}

impl Mdr {
    /// 2E* times the larger side's contact radius, N/m.
    fn side_stiffness(&self, state: &MdrContact) -> f64 {
        let a = state.sides[0]
            .adhesive_radius
            .max(state.sides[1].adhesive_radius);
        2.0 * self.plane_strain_modulus() * a
    }
}

/// The law of the registry's examples: steel-like spheres with a yield stress low
/// enough (50 MPa) that each example's overlap is past yield.
fn reference() -> Mdr {
    use crate::contact::mdr::damping::{MdrDamping, MdrDampingForm};
    Mdr {
        youngs_modulus: 2e11,
        poisson_ratio: 0.3,
        yield_stress: 5e7,
        surface_energy: 0.0,
        wall_surface_energy: None,
        bulk_trigger: 0.5,
        damping: MdrDamping {
            coefficient: 0.0,
            form: MdrDampingForm::Stiffness,
        },
    }
}
