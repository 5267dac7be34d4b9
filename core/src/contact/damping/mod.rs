//! Viscous normal damping: F_n^d = c_n · dδ/dt (Rojek 2016 eq 6, Zhong 2009 eq 6),
//! positive (repulsive) while the overlap grows. Without a force limit the damped
//! force turns attractive near the end of a contact, as in the closed forms of
//! Zhong eqs 7–9 and LIGGGHTS's default `limitForce off`.
//!
//! Two types of c_n:
//! - `CriticalFraction`: c_n = ξ · 2√(m* k_n) (Rojek eqs 7–8), with k_n the
//!   tangent stiffness of the normal law at the current overlap (eq 9, eq 10);
//! - `Viscous` (viscous.rs): c_n that does not follow k_n, in one of three forms
//!   chosen at run time: `constant` γ_n (Zhong eq 6), and LAMMPS's `mass_velocity`
//!   η_n0·m* and `viscoelastic` η_n0·m*·√(δR*).
//!
//! The scene kinds `liggghts_restitution` and `tsuji` are not further forms:
//! `liggghts.rs` turns LIGGGHTS's restitution coefficient, `tsuji.rs` LAMMPS's
//! `damping tsuji` coefficient, into the `CriticalFraction` ξ that gives the peer's
//! γ_n for the scene's normal law, once, when the scene is built.
//!
//! Each kind names its LAMMPS `damping` model (`lammps`, for `tamp export-lammps`).

pub mod liggghts;
pub mod tsuji;
pub mod viscous;

use crate::contact::lammps::{LammpsDamping, LammpsNormal, NoLammpsModel};
pub use crate::contact::model::DampingModel;
use crate::contact::model::Roles;
use crate::contact::normal::NormalLaw;
use crate::error::Errors;
pub use liggghts::LiggghtsRestitution;
pub use tsuji::Tsuji;
pub use viscous::{Constant, MassVelocity, Viscoelastic, Viscous};

/// c_n = ξ · 2√(m* k_n), Rojek eqs 6–10.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct CriticalFraction {
    /// Damping ratio ξ ≥ 0: the fraction of the critical damping 2√(m* k_n); 1 is critical.
    pub xi: f64,
}

impl DampingModel for CriticalFraction {
    fn name(&self) -> &'static str {
        "critical_fraction"
    }
    fn check(&self, path: &str, _: Roles, e: &mut Errors) {
        e.non_negative(format!("{path}.xi"), self.xi);
    }
    #[inline(always)]
    fn coefficient(&self, effective_mass: f64, stiffness: f64, _: impl FnOnce() -> f64) -> f64 {
        self.xi * critical_damping(effective_mass, stiffness)
    }
    fn ratio(&self, _: f64, _: f64, _: f64) -> f64 {
        self.xi
    }
}

impl CriticalFraction {
    /// LAMMPS's `coeff_restitution` damping, η = d √(m* F/δ), is c_n = ξ · 2√(m* k_n)
    /// with ξ = d √(F/(δ k_n))/2 (contact/lammps.rs), d = −2√(5/6)√(3/2) β for
    /// `hertz/material` and −2β for `hooke`, β = ln e/√(ln²e + π²)
    /// (`GranSubModDampingCoeffRestitution::init`): so ξ = −√(5/6) β or −β, LIGGGHTS's
    /// relation (liggghts.rs), and the e written is the one whose β gives this ξ.
    pub fn lammps(&self, normal: LammpsNormal) -> Result<LammpsDamping, NoLammpsModel> {
        let beta = match normal {
            LammpsNormal::HertzMaterial => -self.xi / liggghts::SQRT_FIVE_SIXTHS,
            LammpsNormal::Hooke { .. } => -self.xi,
            LammpsNormal::Mdr(_) => {
                return Err(NoLammpsModel(
                    "mdr takes only its own dashpot (damping mdr 1|2), the law's 'damping' field"
                        .into(),
                ));
            }
        };
        if beta <= -1.0 {
            return Err(NoLammpsModel(format!(
                "xi = {} is more than coeff_restitution can express beside {} (e -> 0)",
                self.xi,
                normal.keyword()
            )));
        }
        Ok(LammpsDamping {
            keyword: "coeff_restitution",
            coefficient: liggghts::restitution_from_beta(beta),
        })
    }
}

/// The scene's damping role, read as `{"kind": "<name>", <its parameters>}`.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Damping {
    /// c_n = ξ · 2√(m* k_n) (Rojek eqs 6–10).
    CriticalFraction(CriticalFraction),
    /// c_n = γ_n, a fixed coefficient (viscous.rs).
    Constant(Constant),
    /// LAMMPS's `damping mass_velocity` (viscous.rs).
    MassVelocity(MassVelocity),
    /// LAMMPS's `damping viscoelastic` (viscous.rs).
    Viscoelastic(Viscoelastic),
    /// LIGGGHTS 3.8's damping from a restitution coefficient: run as the
    /// `CriticalFraction` whose ξ the normal law gives (liggghts.rs).
    LiggghtsRestitution(LiggghtsRestitution),
    /// LAMMPS 22 Jul 2025's `damping tsuji`: run as the `CriticalFraction` whose ξ the
    /// normal law gives (tsuji.rs).
    Tsuji(Tsuji),
}

impl Damping {
    /// The `kind` of the scene file.
    pub fn name(&self) -> &'static str {
        match self {
            Damping::CriticalFraction(d) => d.name(),
            Damping::LiggghtsRestitution(_) => LiggghtsRestitution::NAME,
            Damping::Tsuji(_) => Tsuji::NAME,
            Damping::Constant(_) | Damping::MassVelocity(_) | Damping::Viscoelastic(_) => {
                self.viscous().expect("a viscous kind").name()
            }
        }
    }

    /// The kinds whose coefficient does not follow the normal stiffness, as the one
    /// type they run as (viscous.rs).
    pub fn viscous(&self) -> Option<Viscous> {
        match *self {
            Damping::Constant(d) => Some(Viscous::Constant(d)),
            Damping::MassVelocity(d) => Some(Viscous::MassVelocity(d)),
            Damping::Viscoelastic(d) => Some(Viscous::Viscoelastic(d)),
            Damping::CriticalFraction(_) | Damping::LiggghtsRestitution(_) | Damping::Tsuji(_) => {
                None
            }
        }
    }

    /// The rules of its parameters and of the normal law it damps.
    pub fn check(&self, path: &str, roles: Roles, errors: &mut Errors) {
        match self {
            Damping::CriticalFraction(d) => d.check(path, roles, errors),
            Damping::LiggghtsRestitution(d) => d.check(path, roles, errors),
            Damping::Tsuji(d) => d.check(path, roles, errors),
            Damping::Constant(_) | Damping::MassVelocity(_) | Damping::Viscoelastic(_) => self
                .viscous()
                .expect("a viscous kind")
                .check(path, roles, errors),
        }
    }

    /// Its `damping` model in LAMMPS's `pair granular` beside `normal`, or why none.
    pub fn lammps(&self, normal: LammpsNormal) -> Result<LammpsDamping, NoLammpsModel> {
        match self {
            Damping::CriticalFraction(d) => d.lammps(normal),
            Damping::LiggghtsRestitution(d) => d.lammps(normal),
            Damping::Tsuji(d) => d.lammps(normal),
            Damping::Constant(_) | Damping::MassVelocity(_) | Damping::Viscoelastic(_) => {
                self.viscous().expect("a viscous kind").lammps(normal)
            }
        }
    }
}

/// The dashpot the force loop runs: the scene's kind resolved against its normal law
/// (`Damping::dashpot`). Which of the two runs is a branch fixed for the run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Dashpot {
    /// c_n = ξ · 2√(m* k_n), also for `liggghts_restitution` and `tsuji`.
    CriticalFraction(CriticalFraction),
    /// A coefficient that does not follow k_n (viscous.rs).
    Viscous(Viscous),
}

impl Dashpot {
    /// See `DampingModel::coefficient`.
    #[inline(always)]
    pub fn coefficient(
        &self,
        effective_mass: f64,
        stiffness: f64,
        contact_radius: impl FnOnce() -> f64,
    ) -> f64 {
        match self {
            Dashpot::CriticalFraction(d) => {
                d.coefficient(effective_mass, stiffness, contact_radius)
            }
            Dashpot::Viscous(d) => d.coefficient(effective_mass, stiffness, contact_radius),
        }
    }

    /// See `DampingModel::ratio`.
    pub fn ratio(&self, effective_mass: f64, stiffness: f64, contact_radius: f64) -> f64 {
        match self {
            Dashpot::CriticalFraction(d) => d.ratio(effective_mass, stiffness, contact_radius),
            Dashpot::Viscous(d) => d.ratio(effective_mass, stiffness, contact_radius),
        }
    }
}

impl Damping {
    /// The dashpot this kind runs as beside `normal`; `None` beside a law that
    /// dissipates by itself, which validation refuses a damping role.
    pub fn dashpot(&self, normal: &NormalLaw) -> Option<Dashpot> {
        if normal.has_own_dissipation() {
            return None;
        }
        Some(match *self {
            Damping::CriticalFraction(d) => Dashpot::CriticalFraction(d),
            Damping::Constant(_) | Damping::MassVelocity(_) | Damping::Viscoelastic(_) => {
                Dashpot::Viscous(self.viscous().expect("a viscous kind"))
            }
            Damping::LiggghtsRestitution(d) => Dashpot::CriticalFraction(
                d.with(normal)
                    .expect("validation refuses liggghts_restitution beside this normal law"),
            ),
            Damping::Tsuji(d) => Dashpot::CriticalFraction(
                d.with(normal)
                    .expect("validation refuses tsuji beside this normal law"),
            ),
        })
    }
}

/// Rojek eq 8: C_cr = 2 √(m_i m_j k_n / (m_i + m_j)) = 2 √(m* k_n).
pub fn critical_damping(effective_mass: f64, stiffness: f64) -> f64 {
    2.0 * (effective_mass * stiffness).sqrt()
}
