//! Normal contact laws: the elastic, viscoelastic or plastic part of the normal force.
//! One file per law, each a type implementing `NormalModel`. Laws with memory
//! (Walton–Braun, Storåkers) keep the largest overlap δ_max (`PeakOverlap`,
//! `storakers::StorakersHistory`).

pub mod hertz;
pub mod hysteretic;
pub mod kuwabara_kono;
pub mod linear;
pub mod mdr;
pub mod plastic_cylinder;
pub mod storakers;
pub mod thornton;
pub mod walton_braun;

use crate::contact::damping::Damping;
use crate::contact::damping::liggghts::LiggghtsModel;
use crate::contact::lammps::{LammpsNormal, NoLammpsModel};
pub use crate::contact::model::{
    LiggghtsDeck, LiggghtsRefusal, LiggghtsScene, Needs, NormalModel, NormalResponse,
};
use crate::error::Errors;
use crate::material::PairProperties;
pub use hertz::Hertz;
pub use hysteretic::Hysteretic;
pub use kuwabara_kono::KuwabaraKono;
pub use linear::Linear;
pub use storakers::Storakers;
pub use thornton::Thornton;
pub use walton_braun::WaltonBraun;

/// The state of a law with memory: the largest overlap reached on the loading
/// branch, m (Walton–Braun).
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PeakOverlap {
    /// Largest overlap δ_max reached so far, m.
    pub max_overlap: f64,
}

impl crate::contact::model::ContactState for PeakOverlap {}

/// The scene's normal law, read from the scene as `{"law": "<name>", <its parameters>}`.
/// Each variant is the law's own type (its file holds its equations, source, rules and
/// examples); this enum, `each_normal!` and `NormalLaw::examples` list them.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(tag = "law", rename_all = "snake_case")]
pub enum NormalLaw {
    /// Zhong model I.
    Linear(Linear),
    /// Zhong model II, Rojek eq 2.
    Hertz(Hertz),
    /// Zhong model III.
    KuwabaraKono(KuwabaraKono),
    /// Zhong model IV.
    WaltonBraun(WaltonBraun),
    /// Zhong model V.
    Hysteretic(Hysteretic),
    /// Rojek eqs 15–22, optionally capped by Hertz (Martin et al. 2003).
    Storakers(Storakers),
    /// Thornton 1997 elastic–perfectly-plastic (or LIGGGHTS's `thornton_ning` unloading).
    Thornton(Thornton),
    /// Zunker & Kamrin 2024's mechanically derived response (LAMMPS's `mdr`).
    Mdr(crate::contact::mdr::Mdr),
}

/// `each_normal!(law, n => expr)`: `expr` with `n` bound to the law's own type, for
/// every variant (an exhaustive match: a new law that is not listed does not compile).
#[macro_export]
macro_rules! each_normal {
    ($law:expr, $n:ident => $body:expr) => {
        match $law {
            $crate::contact::normal::NormalLaw::Linear($n) => $body,
            $crate::contact::normal::NormalLaw::Hertz($n) => $body,
            $crate::contact::normal::NormalLaw::KuwabaraKono($n) => $body,
            $crate::contact::normal::NormalLaw::WaltonBraun($n) => $body,
            $crate::contact::normal::NormalLaw::Hysteretic($n) => $body,
            $crate::contact::normal::NormalLaw::Storakers($n) => $body,
            $crate::contact::normal::NormalLaw::Thornton($n) => $body,
            $crate::contact::normal::NormalLaw::Mdr($n) => $body,
        }
    };
}

impl NormalLaw {
    /// See `NormalModel::name`.
    pub fn name(&self) -> &'static str {
        each_normal!(self, n => n.name())
    }

    /// See `NormalModel::needs`.
    pub fn needs(&self) -> Needs {
        each_normal!(self, n => n.needs())
    }

    /// See `NormalModel::check`.
    pub fn check(&self, path: &str, errors: &mut Errors) {
        each_normal!(self, n => n.check(path, errors))
    }

    /// See `NormalModel::liggghts`.
    pub fn liggghts(&self) -> Option<LiggghtsModel> {
        each_normal!(self, n => n.liggghts())
    }

    /// See `NormalModel::lammps`.
    pub fn lammps(&self) -> Result<LammpsNormal, NoLammpsModel> {
        each_normal!(self, n => n.lammps())
    }

    /// See `NormalModel::liggghts_deck`.
    pub fn liggghts_deck(
        &self,
        scene: &LiggghtsScene,
    ) -> Option<Result<LiggghtsDeck, Vec<LiggghtsRefusal>>> {
        each_normal!(self, n => n.liggghts_deck(scene))
    }

    /// Whether the law keeps δ_max in the contact state.
    pub fn has_memory(&self) -> bool {
        each_normal!(self, n => std::mem::size_of_val(&state_of(n)) > 0)
    }

    /// Whether the law dissipates by itself (a separate damping role is then refused).
    pub fn has_own_dissipation(&self) -> bool {
        each_normal!(self, n => own_dissipation(n))
    }

    /// Force and stiffness of a virgin contact at `overlap` approached at `rate`.
    pub fn response(
        &self,
        overlap: f64,
        rate: f64,
        effective_radius: f64,
        pair: &PairProperties,
    ) -> NormalResponse {
        each_normal!(self, n => n.response(overlap, rate, effective_radius, pair, &mut state_of(n)))
    }

    /// See `NormalModel::impact_stiffness`.
    pub fn impact_stiffness(
        &self,
        effective_mass: f64,
        speed: f64,
        effective_radius: f64,
        pair: &PairProperties,
    ) -> f64 {
        each_normal!(self, n => n.impact_stiffness(effective_mass, speed, effective_radius, pair))
    }

    /// See `NormalModel::stiffness_depends_on_speed`.
    pub fn stiffness_depends_on_speed(&self) -> bool {
        each_normal!(self, n => n.stiffness_depends_on_speed())
    }

    /// See `NormalModel::pair_constant`.
    pub fn pair_constant(&self, pair: &PairProperties) -> Option<f64> {
        each_normal!(self, n => n.pair_constant(pair))
    }

    /// The MDR law, if this is it (`NormalModel::mdr`).
    pub fn mdr(&self) -> Option<&crate::contact::mdr::Mdr> {
        each_normal!(self, n => n.mdr())
    }

    /// See `NormalModel::error_model`.
    pub fn error_model(&self, damping: Option<&Damping>) -> Option<&'static str> {
        each_normal!(self, n => n.error_model(damping))
    }
}

fn own_dissipation<N: NormalModel>(_: &N) -> bool {
    N::OWN_DISSIPATION
}

/// A fresh state of the law `n` (its type, for code generic over the laws).
fn state_of<N: NormalModel>(_: &N) -> N::State {
    N::State::default()
}
