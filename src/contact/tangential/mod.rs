//! Tangential contact laws. An absent law (friction off) is `None` in
//! `ContactLaw`: no tangential velocity is computed and no history is stored.
//! One file per law; the shared pieces are `incremental.rs` (Rojek eq 11 with the
//! Coulomb cap) and `scalar_axis.rs` (how the 1D history laws act in 3D).

pub mod coulomb;
pub mod cundall_strack;
pub mod haff_werner;
pub mod incremental;
pub mod liggghts_history;
pub mod mindlin_deresiewicz;
pub mod mindlin_no_slip;
pub mod scalar_axis;
pub mod storakers;
pub mod walton_braun;

use crate::contact::damping::critical_damping;
use crate::contact::damping::liggghts::LiggghtsModel;
use crate::contact::history::ContactHistory;
use crate::particles::Vec3;

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TangentialLaw {
    /// Zhong model VI.
    MindlinDeresiewicz,
    /// Zhong model VII.
    Coulomb,
    /// Zhong model VIII; γ_s in N·s/m.
    HaffWerner { damping: f64 },
    /// Zhong model IX; k_s in N/m.
    CundallStrack { stiffness: f64 },
    /// Zhong model X; k₀ in N/m.
    WaltonBraun { stiffness: f64 },
    /// Rojek eqs 11–14 (H-MDNs).
    MindlinNoSlip,
    /// Rojek eq 21: k_t = β k_n.
    Storakers { beta: f64 },
    /// LIGGGHTS 3.8 `tangential history`: k_t of the LIGGGHTS `model` (8G*√(R*δ) for
    /// hertz, k_n for hooke) and γ_t = ξ·2√(m* k_t) with ξ the normal damping's
    /// (`liggghts_restitution`, 0 without damping). Built from the scene's normal law
    /// and damping.
    LiggghtsHistory { model: LiggghtsModel, xi: f64 },
}

/// What a tangential law reads from the contact besides its history.
#[derive(Clone, Copy, Debug)]
pub struct TangentialInput {
    pub normal: Vec3,
    pub tangential_velocity: Vec3,
    pub dt: f64,
    pub friction: f64,
    /// Total normal force (elastic + damping), N.
    pub normal_force: f64,
    /// Tangent stiffness of the normal law, N/m.
    pub normal_stiffness: f64,
    pub overlap: f64,
    pub effective_radius: f64,
    pub effective_shear_modulus: f64,
    /// m*, kg (the tangential damping of `liggghts_history`).
    pub effective_mass: f64,
}

impl TangentialLaw {
    pub fn name(&self) -> &'static str {
        match self {
            TangentialLaw::MindlinDeresiewicz => "mindlin_deresiewicz",
            TangentialLaw::Coulomb => "coulomb",
            TangentialLaw::HaffWerner { .. } => "haff_werner",
            TangentialLaw::CundallStrack { .. } => "cundall_strack",
            TangentialLaw::WaltonBraun { .. } => "walton_braun",
            TangentialLaw::MindlinNoSlip => "mindlin_no_slip",
            TangentialLaw::Storakers { .. } => "storakers",
            TangentialLaw::LiggghtsHistory { .. } => "liggghts_history",
        }
    }

    /// Whether the law keeps a tangential state between steps.
    pub fn has_history(&self) -> bool {
        !matches!(
            self,
            TangentialLaw::Coulomb | TangentialLaw::HaffWerner { .. }
        )
    }

    /// Whether the law needs G* (elastic constants on every material).
    pub fn needs_elastic_constants(&self) -> bool {
        matches!(
            self,
            TangentialLaw::MindlinDeresiewicz
                | TangentialLaw::MindlinNoSlip
                | TangentialLaw::LiggghtsHistory {
                    model: LiggghtsModel::Hertz,
                    ..
                }
        )
    }

    /// Tangential force on particle i; advances the history.
    #[inline]
    pub fn force(&self, input: &TangentialInput, history: &mut ContactHistory) -> Vec3 {
        let v_t = &input.tangential_velocity;
        let mu = input.friction;
        let n = input.normal_force;
        match *self {
            TangentialLaw::Coulomb => coulomb::coulomb_force(v_t, mu, n),
            TangentialLaw::HaffWerner { damping } => {
                haff_werner::haff_werner_force(v_t, damping, mu, n)
            }
            TangentialLaw::CundallStrack { stiffness } => cundall_strack::cundall_strack_force(
                &mut history.tangential,
                &input.normal,
                v_t,
                input.dt,
                stiffness,
                mu,
                n,
            ),
            TangentialLaw::MindlinNoSlip | TangentialLaw::Storakers { .. } => {
                incremental::incremental_force(
                    &mut history.tangential,
                    &input.normal,
                    v_t,
                    input.dt,
                    self.stiffness(input),
                    mu,
                    n,
                )
            }
            TangentialLaw::MindlinDeresiewicz => mindlin_deresiewicz::mindlin_deresiewicz_force(
                history,
                &input.normal,
                v_t,
                input.dt,
                self.stiffness(input),
                mu,
                n,
            ),
            TangentialLaw::LiggghtsHistory { xi, .. } => {
                let k_t = self.stiffness(input);
                liggghts_history::liggghts_history_force(
                    &mut history.tangential,
                    &input.normal,
                    v_t,
                    input.dt,
                    k_t,
                    xi * critical_damping(input.effective_mass, k_t),
                    mu,
                    n,
                )
            }
            TangentialLaw::WaltonBraun { stiffness } => {
                walton_braun::walton_braun_tangential_force(
                    history,
                    &input.normal,
                    v_t,
                    input.dt,
                    stiffness,
                    mu,
                    n,
                )
            }
        }
    }

    /// Largest tangent stiffness at this contact state (θ = 1), N/m; zero for the
    /// spring-less laws. Used by the critical time step and the stored energy.
    pub fn stiffness(&self, input: &TangentialInput) -> f64 {
        match *self {
            TangentialLaw::Coulomb | TangentialLaw::HaffWerner { .. } => 0.0,
            TangentialLaw::CundallStrack { stiffness }
            | TangentialLaw::WaltonBraun { stiffness } => stiffness,
            TangentialLaw::MindlinNoSlip
            | TangentialLaw::MindlinDeresiewicz
            | TangentialLaw::LiggghtsHistory {
                model: LiggghtsModel::Hertz,
                ..
            } => mindlin_no_slip::mindlin_no_slip_stiffness(
                input.overlap,
                input.effective_radius,
                input.effective_shear_modulus,
            ),
            TangentialLaw::LiggghtsHistory {
                model: LiggghtsModel::Hooke,
                ..
            } => input.normal_stiffness,
            TangentialLaw::Storakers { beta } => {
                storakers::storakers_tangential_stiffness(beta, input.normal_stiffness)
            }
        }
    }

    /// Energy held in the tangential state, J: ½k|ξ|² for the laws that store a spring
    /// displacement (Cundall–Strack, LIGGGHTS's shear), ½|F_t|²/k_t for the laws that
    /// store the force.
    pub fn energy(&self, input: &TangentialInput, history: &ContactHistory) -> f64 {
        match *self {
            TangentialLaw::Coulomb | TangentialLaw::HaffWerner { .. } => 0.0,
            TangentialLaw::CundallStrack { stiffness } => {
                0.5 * stiffness * history.tangential.norm_squared()
            }
            TangentialLaw::LiggghtsHistory { .. } => {
                0.5 * self.stiffness(input) * history.tangential.norm_squared()
            }
            _ => {
                let k = self.stiffness(input);
                if k > 0.0 {
                    0.5 * history.tangential.norm_squared() / k
                } else {
                    0.0
                }
            }
        }
    }
}
