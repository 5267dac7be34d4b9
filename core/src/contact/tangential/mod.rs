//! Tangential contact laws, one file and one type (implementing `TangentialModel`)
//! per law. An absent law (friction off) is `None` in `ContactLaw` and `NoFriction`
//! in the force loop: no tangential velocity is computed and nothing is stored. The
//! force loop runs a law as its family's type, by the state it keeps (`families.rs`).
//! The shared pieces are `incremental.rs` (Rojek eq 11 with the Coulomb cap) and `scalar_axis.rs` (how the 1D history laws act in 3D).

pub mod coulomb;
pub mod cundall_strack;
pub mod families;
pub mod haff_werner;
pub mod incremental;
pub mod lammps_linear_history;
pub mod lammps_linear_nohistory;
pub mod lammps_mindlin;
pub mod liggghts_history;
pub mod mindlin_deresiewicz;
pub mod mindlin_no_slip;
pub mod scalar_axis;
pub mod storakers;
pub mod walton_braun;

pub use crate::contact::model::TangentialModel;
use crate::contact::model::{Needs, Roles};
use crate::error::Errors;
use crate::particles::Vec3;
pub use coulomb::Coulomb;
pub use cundall_strack::CundallStrack;
pub use haff_werner::HaffWerner;
pub use liggghts_history::LiggghtsHistory;
pub use mindlin_deresiewicz::MindlinDeresiewicz;
pub use mindlin_no_slip::MindlinNoSlip;

/// The scene's tangential law, read as `{"law": "<name>", <its parameters>}` (beside
/// the friction coefficients, `scene::schema::FrictionSpec`). Each variant is the law's
/// own type; this enum, `each_tangential!` and `TangentialLaw::examples` list them.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(tag = "law", rename_all = "snake_case")]
pub enum TangentialLaw {
    /// Zhong model VI.
    MindlinDeresiewicz(MindlinDeresiewicz),
    /// Zhong model VII.
    Coulomb(Coulomb),
    /// Zhong model VIII.
    HaffWerner(HaffWerner),
    /// Zhong model IX.
    CundallStrack(CundallStrack),
    /// Zhong model X.
    WaltonBraun(walton_braun::WaltonBraun),
    /// Rojek eqs 11–14 (H-MDNs).
    MindlinNoSlip(MindlinNoSlip),
    /// Rojek eq 21: k_t = β k_n.
    Storakers(storakers::Storakers),
    /// LIGGGHTS 3.8 `tangential history`, built from the scene's normal law and damping.
    LiggghtsHistory(LiggghtsHistory),
    /// LAMMPS 22 Jul 2025 `tangential mindlin`, `mindlin/force`, `mindlin_rescale`,
    /// `mindlin_rescale/force`.
    LammpsMindlin(lammps_mindlin::LammpsMindlin),
    /// LAMMPS 22 Jul 2025 `tangential linear_history`.
    LammpsLinearHistory(lammps_linear_history::LammpsLinearHistory),
    /// LAMMPS 22 Jul 2025 `tangential linear_nohistory`.
    LammpsLinearNohistory(lammps_linear_nohistory::LammpsLinearNohistory),
}

/// `each_tangential!(law, t => expr)`: `expr` with `t` bound to the law's own type,
/// for every variant (an exhaustive match).
#[macro_export]
macro_rules! each_tangential {
    ($law:expr, $t:ident => $body:expr) => {
        match $law {
            $crate::contact::tangential::TangentialLaw::MindlinDeresiewicz($t) => $body,
            $crate::contact::tangential::TangentialLaw::Coulomb($t) => $body,
            $crate::contact::tangential::TangentialLaw::HaffWerner($t) => $body,
            $crate::contact::tangential::TangentialLaw::CundallStrack($t) => $body,
            $crate::contact::tangential::TangentialLaw::WaltonBraun($t) => $body,
            $crate::contact::tangential::TangentialLaw::MindlinNoSlip($t) => $body,
            $crate::contact::tangential::TangentialLaw::Storakers($t) => $body,
            $crate::contact::tangential::TangentialLaw::LiggghtsHistory($t) => $body,
            $crate::contact::tangential::TangentialLaw::LammpsMindlin($t) => $body,
            $crate::contact::tangential::TangentialLaw::LammpsLinearHistory($t) => $body,
            $crate::contact::tangential::TangentialLaw::LammpsLinearNohistory($t) => $body,
        }
    };
}

/// What a tangential law reads from the contact besides its state.
#[derive(Clone, Copy, Debug)]
pub struct TangentialInput {
    /// Unit normal n from the partner to particle i.
    pub normal: Vec3,
    /// Tangential relative velocity v_t of i's contact point, m/s.
    pub tangential_velocity: Vec3,
    /// Time step Δt, s.
    pub dt: f64,
    /// Coulomb friction coefficient μ of the pair.
    pub friction: f64,
    /// Total normal force (elastic + damping), N.
    pub normal_force: f64,
    /// Tangent stiffness of the normal law, N/m.
    pub normal_stiffness: f64,
    /// Overlap δ, m.
    pub overlap: f64,
    /// Effective radius R*, m.
    pub effective_radius: f64,
    /// Effective shear modulus G*, Pa (0 when the materials have no elastic constants).
    pub effective_shear_modulus: f64,
    /// m*, kg (the tangential damping of `liggghts_history`).
    pub effective_mass: f64,
    /// The normal damping's coefficient c_n of this step (F_n,damp = c_n dδ/dt),
    /// N·s/m, 0 without damping: LAMMPS's `damp_prefactor` η_n, which its
    /// `linear_history` and `linear_nohistory` scale into their tangential dashpot.
    pub normal_damping: f64,
}

impl TangentialLaw {
    /// See `TangentialModel::lammps`.
    pub fn lammps(&self) -> Result<String, crate::contact::lammps::NoLammpsModel> {
        each_tangential!(self, t => t.lammps())
    }

    /// See `TangentialModel::name`.
    pub fn name(&self) -> &'static str {
        each_tangential!(self, t => t.name())
    }

    /// See `TangentialModel::needs`.
    pub fn needs(&self) -> Needs {
        each_tangential!(self, t => t.needs())
    }

    /// See `TangentialModel::check`.
    pub fn check(&self, path: &str, roles: Roles, errors: &mut Errors) {
        each_tangential!(self, t => t.check(path, roles, errors))
    }

    /// See `TangentialModel::bind`.
    pub fn bind(&mut self, roles: Roles) {
        each_tangential!(self, t => t.bind(roles))
    }
}
