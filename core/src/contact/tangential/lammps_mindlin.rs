//! LAMMPS's `pair granular` Mindlin tangential models (scene law `lammps_mindlin`),
//! reproduced operation for operation from LAMMPS 22 Jul 2025 (update 4),
//! src/GRANULAR/gran_sub_mod_tangential.cpp `GranSubModTangentialMindlin::calculate_forces`,
//! with the stiffness `k = -1` (8G* from the materials: `mix_stiffnessG`,
//! `mix_stiffnessG_wall`), the tangential dashpot x_γ,t times the normal damping's
//! prefactor (`damp = xt * damping_model->get_damp_prefactor()`, as in
//! `lammps_linear_history`) and F_s from granular_model.cpp. tamp's notation: `normal` n
//! from the partner to particle i, v_t the tangential velocity of i's contact point
//! relative to the partner's (spins included), F_n the total normal force, elastic plus
//! damping, η_n the normal damping's coefficient this step (F_n,damp = η_n dδ/dt; 0
//! without damping). Per step:
//!
//! ```text
//!   a = √(R* δ),  k_a = 8 G* a,  F_s = μ |F_n|            (Fncrit = |F_n,total|)
//!   γ_t = x_γ,t η_n,  F_damp = −γ_t v_t
//!   rescale variants, if a < a_prev:  h ← h · a / a_prev   (unloading)
//!   if |h·n| (·k_a for the displacement variants) > 1e-10 F_s:
//!       h ← (h − (h·n) n) · |h| / |h − (h·n) n|            (projected, length kept)
//!   displacement variants (`mindlin`, `mindlin_rescale`):  h ← h + v_t Δt,  F_t = −k_a h + F_damp
//!   force variants (`mindlin/force`, `mindlin_rescale/force`): h ← h − k_a v_t Δt,  F_t = h + F_damp
//!   rescale variants: a_prev ← a
//!   if |F_t| > F_s and |h| ≠ 0:  F_t ← F_t F_s/|F_t|,
//!                                h ← F_t − F_damp (force) or −(F_t − F_damp)/k_a
//!   if |F_t| > F_s and |h| = 0:  F_t ← 0
//! ```
//!
//! So `mindlin` is a linear spring of stiffness 8G*a on the accumulated displacement
//! (a total-spring law: the force follows a when the overlap changes), `mindlin/force`
//! the incremental no-slip law of Mindlin (tamp's `mindlin_no_slip` structure, but with
//! Coulomb's limit on |F_n| where that law takes max(F_n, 0), and the history turned
//! only above the 1e-10 threshold). `*_rescale` shrink the history with the contact
//! radius on unloading (Walton 1993's device against a spring outliving its contact).
//! The dashpot follows the normal damping through the contact; it counts in the Coulomb
//! test, and on the cone the history keeps only the elastic part F_t − F_damp (so a
//! sliding contact's spring is the cone's force less the dashpot's). x_γ,t = 0 (the
//! default) leaves the dashpot out. The history starts at zero when a contact forms and
//! is dropped when it ends, as in tamp. No micro-slip: not Mindlin–Deresiewicz's full
//! law (`mindlin_deresiewicz`). The lever arms are the scene's (`contact.lever_arm`;
//! `lammps` for LAMMPS's). docs/lammps.md has the measured agreement.

use super::cundall_strack::rotate_into_plane;
use super::{TangentialInput, TangentialLaw, TangentialModel};
use crate::contact::lammps::NoLammpsModel;
use crate::contact::model::{ContactState, Needs, Roles};
use crate::contact::registry::{self, TangentialExample};
use crate::error::Errors;
use crate::particles::Vec3;

/// gran_sub_mod_tangential.cpp's EPSILON: the history is turned into the contact
/// plane only when its normal component exceeds this fraction of F_s.
const TURN_THRESHOLD: f64 = 1e-10;

/// LAMMPS's frame update (`rotate_rescale_vec`, shared by its history models): the
/// history h is turned into the contact plane, its length kept, only when its normal
/// component times `scale` (the stiffness for a displacement history, 1 for a force
/// history) exceeds 1e-10 F_s.
#[inline(always)]
pub(crate) fn turn_above_threshold(h: &mut Vec3, normal: &Vec3, scale: f64, limit: f64) {
    if h.dot(normal).abs() * scale > TURN_THRESHOLD * limit {
        *h = rotate_into_plane(*h, normal);
    }
}

/// LAMMPS's Coulomb step (shared by its history models): a force F beyond F_s is
/// scaled onto the cone and the history set to the elastic part F − F_damp, times
/// `to_history` (−1/k for a displacement history, 1 for a force history); with an
/// empty history (|h| now, or `magnitude` where the model measured it before) the force
/// is dropped instead.
#[inline(always)]
pub(super) fn onto_the_cone(
    f: &mut Vec3,
    h: &mut Vec3,
    damping: Vec3,
    limit: f64,
    to_history: f64,
    magnitude: Option<f64>,
) {
    let force = f.norm();
    if force > limit {
        if magnitude.unwrap_or_else(|| h.norm()) != 0.0 {
            *f *= limit / force;
            *h = (*f - damping) * to_history;
        } else {
            *f = Vec3::zeros();
        }
    }
}

/// Which of LAMMPS's four Mindlin models.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Variant {
    /// `mindlin`: history is the tangential displacement, F_t = −8G*a h.
    Mindlin,
    /// `mindlin/force`: history is the force, ΔF_t = −8G*a v_t Δt.
    MindlinForce,
    /// `mindlin_rescale`: `mindlin`, history scaled by a/a_prev on unloading.
    MindlinRescale,
    /// `mindlin_rescale/force`: `mindlin/force`, history scaled by a/a_prev on unloading.
    MindlinRescaleForce,
}

impl Variant {
    /// The LAMMPS keyword after `tangential`.
    pub fn keyword(self) -> &'static str {
        match self {
            Variant::Mindlin => "mindlin",
            Variant::MindlinForce => "mindlin/force",
            Variant::MindlinRescale => "mindlin_rescale",
            Variant::MindlinRescaleForce => "mindlin_rescale/force",
        }
    }

    /// The scene's name of the variant.
    pub fn name(self) -> &'static str {
        match self {
            Variant::Mindlin => "mindlin",
            Variant::MindlinForce => "mindlin_force",
            Variant::MindlinRescale => "mindlin_rescale",
            Variant::MindlinRescaleForce => "mindlin_rescale_force",
        }
    }

    /// Every variant, in LAMMPS's order.
    pub const ALL: [Variant; 4] = [
        Variant::Mindlin,
        Variant::MindlinForce,
        Variant::MindlinRescale,
        Variant::MindlinRescaleForce,
    ];

    fn force(self) -> bool {
        matches!(self, Variant::MindlinForce | Variant::MindlinRescaleForce)
    }

    fn rescale(self) -> bool {
        matches!(self, Variant::MindlinRescale | Variant::MindlinRescaleForce)
    }
}

/// `{"law": "lammps_mindlin", "variant": ..., "x_gamma_t": x, "friction": μ}`.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct LammpsMindlin {
    /// Which of LAMMPS's four Mindlin models.
    pub variant: Variant,
    /// x_γ,t: the tangential dashpot over the normal one, γ_t = x_γ,t η_n; 0 (no
    /// dashpot) when absent.
    #[serde(default)]
    pub x_gamma_t: f64,
}

/// The history h (a displacement in m, or a force in N for the force variants) and,
/// for the rescale variants, the contact radius a of the last update (LAMMPS's
/// `history[3]`), m.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Deserialize, serde::Serialize)]
pub struct MindlinHistory {
    /// The history h: a displacement (m), or a force (N) for the force variants.
    pub history: Vec3,
    /// Contact radius a = √(R*δ) at the last update, m (rescale variants only).
    pub contact_radius: f64,
}

impl ContactState for MindlinHistory {
    fn tangential(&self) -> Vec3 {
        self.history
    }
}

impl LammpsMindlin {
    /// 8G*√(R*δ), LAMMPS's k_scaled = k · contact_radius.
    fn scaled_stiffness(input: &TangentialInput) -> f64 {
        8.0 * input.effective_shear_modulus * (input.overlap * input.effective_radius).sqrt()
    }
}

impl TangentialModel for LammpsMindlin {
    type State = MindlinHistory;

    fn name(&self) -> &'static str {
        "lammps_mindlin"
    }

    /// From rest, one step: sticking F = −8G*a v_t Δt (both structures give it), less
    /// x_γ,t η_n v_t with the dashpot; sliding: Coulomb's −μ|F_n| v̂_t.
    fn examples() -> Vec<TangentialExample> {
        let mut out: Vec<TangentialExample> = Variant::ALL
            .iter()
            .flat_map(|&variant| {
                let law = TangentialLaw::LammpsMindlin(LammpsMindlin {
                    variant,
                    x_gamma_t: 0.0,
                });
                registry::spring_examples(law, registry::mindlin_stiffness())
            })
            .collect();
        let eta = 2.0;
        let (stick, slide) = registry::damped_inputs(eta);
        let v = stick.tangential_velocity;
        for variant in Variant::ALL {
            let law = TangentialLaw::LammpsMindlin(LammpsMindlin {
                variant,
                x_gamma_t: 0.5,
            });
            out.push(TangentialExample {
                law,
                input: stick,
                force: -v * (registry::mindlin_stiffness() * stick.dt) - v * (0.5 * eta),
            });
            out.push(TangentialExample {
                law,
                input: slide,
                force: registry::sliding_force(&slide),
            });
        }
        out
    }

    /// x_γ,t ≥ 0 and finite (LAMMPS refuses xt < 0: "Illegal Mindlin tangential model").
    fn check(&self, path: &str, _: Roles, e: &mut Errors) {
        e.non_negative(format!("{path}.x_gamma_t"), self.x_gamma_t);
    }

    fn needs(&self) -> Needs {
        Needs {
            elastic: Some(" (G* of LAMMPS's k = 8G*)"),
            ..Needs::default()
        }
    }

    fn lammps(&self) -> Result<String, NoLammpsModel> {
        Ok(format!(
            "{} -1 {} {{mu}}",
            self.variant.keyword(),
            crate::decimal::g(self.x_gamma_t)
        ))
    }

    #[inline(always)]
    fn force(&self, input: &TangentialInput, state: &mut MindlinHistory) -> Vec3 {
        let force_history = self.variant.force();
        let a = (input.overlap * input.effective_radius).sqrt();
        let k_scaled = 8.0 * input.effective_shear_modulus * a;
        let damping = self.x_gamma_t * input.normal_damping;
        let limit = input.normal_force.abs() * input.friction;
        let h = &mut state.history;
        if self.variant.rescale() && a < state.contact_radius {
            *h *= a / state.contact_radius;
        }
        // A force history is compared with F_s as it is, a displacement times k_a.
        let scale = if force_history { 1.0 } else { k_scaled };
        turn_above_threshold(h, &input.normal, scale, limit);
        if force_history {
            *h += input.tangential_velocity * (-k_scaled * input.dt);
        } else {
            *h += input.tangential_velocity * input.dt;
        }
        if self.variant.rescale() {
            state.contact_radius = a;
        }
        let dashpot = input.tangential_velocity * -damping;
        let mut f = if force_history { *h } else { *h * -k_scaled } + dashpot;
        let to_history = if force_history { 1.0 } else { -1.0 / k_scaled };
        onto_the_cone(&mut f, h, dashpot, limit, to_history, None);
        f
    }

    fn stiffness(&self, input: &TangentialInput) -> f64 {
        Self::scaled_stiffness(input)
    }

    fn dashpot_over_normal(&self) -> f64 {
        self.x_gamma_t
    }

    fn energy(&self, input: &TangentialInput, state: &MindlinHistory) -> f64 {
        let k = Self::scaled_stiffness(input);
        if k == 0.0 {
            return 0.0;
        }
        let h = state.history;
        if self.variant.force() {
            0.5 * h.norm_squared() / k
        } else {
            0.5 * k * h.norm_squared()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn input(overlap: f64, v: Vec3, normal_force: f64) -> TangentialInput {
        TangentialInput {
            overlap,
            tangential_velocity: v,
            normal_force,
            ..registry::sticking_input()
        }
    }

    #[test]
    fn the_displacement_spring_follows_the_contact_radius_the_force_one_does_not() {
        // Load one step at δ, then hold still at δ/4 (a halves): `mindlin`'s force
        // halves with a, `mindlin/force` keeps its force.
        let v = Vec3::new(1e-3, 0.0, 0.0);
        for (variant, ratio) in [(Variant::Mindlin, 0.5), (Variant::MindlinForce, 1.0)] {
            let law = LammpsMindlin {
                variant,
                x_gamma_t: 0.0,
            };
            let mut s = MindlinHistory::default();
            let f1 = law.force(&input(4e-6, v, 10.0), &mut s);
            let f2 = law.force(&input(1e-6, Vec3::zeros(), 10.0), &mut s);
            assert!((f2.x / f1.x - ratio).abs() < 1e-14, "{variant:?}");
        }
    }

    #[test]
    fn rescale_shrinks_the_history_with_the_contact_radius_on_unloading() {
        // `mindlin_rescale/force` at δ/4 after δ: the stored force is halved (a/a_prev).
        let law = LammpsMindlin {
            variant: Variant::MindlinRescaleForce,
            x_gamma_t: 0.0,
        };
        let v = Vec3::new(1e-3, 0.0, 0.0);
        let mut s = MindlinHistory::default();
        let f1 = law.force(&input(4e-6, v, 10.0), &mut s);
        let f2 = law.force(&input(1e-6, Vec3::zeros(), 10.0), &mut s);
        assert!((f2.x / f1.x - 0.5).abs() < 1e-14);
    }

    #[test]
    fn coulomb_limit_takes_the_magnitude_of_a_pulling_normal_force() {
        // F_n = −3 N (the damping pulls): LAMMPS still allows μ·3 N.
        let law = LammpsMindlin {
            variant: Variant::MindlinForce,
            x_gamma_t: 0.0,
        };
        let i = TangentialInput {
            normal_force: -3.0,
            ..registry::sliding_input()
        };
        let f = law.force(&i, &mut MindlinHistory::default());
        assert!((f.norm() - i.friction * 3.0).abs() < 1e-12);
    }

    #[test]
    fn each_variant_names_its_lammps_keyword() {
        let words: Vec<String> = Variant::ALL
            .iter()
            .map(|&variant| {
                LammpsMindlin {
                    variant,
                    x_gamma_t: 0.0,
                }
                .lammps()
                .unwrap()
            })
            .collect();
        assert_eq!(
            words,
            [
                "mindlin -1 0e0 {mu}",
                "mindlin/force -1 0e0 {mu}",
                "mindlin_rescale -1 0e0 {mu}",
                "mindlin_rescale/force -1 0e0 {mu}",
            ]
        );
        let damped = LammpsMindlin {
            variant: Variant::Mindlin,
            x_gamma_t: 0.5,
        };
        assert_eq!(damped.lammps().unwrap(), "mindlin -1 5e-1 {mu}");
    }

    #[test]
    fn on_the_cone_the_history_keeps_only_the_elastic_part() {
        // From rest, one step with the dashpot: k_a = 8·2.1e10·√(5e-4·1e-6) N/m, and
        // the displacement variants' spring −k_a v Δt plus the dashpot −γ_t v overshoot
        // F_s = 0.4·|−20| = 8 N; the force is put on the cone, F = −8 v̂, and the history
        // holds F − F_damp: −(F + γ_t v)/k_a for a displacement, F + γ_t v for a force.
        let v = Vec3::new(3.0, 4.0, 0.0);
        let (eta, x) = (2.0, 0.5);
        let i = TangentialInput {
            tangential_velocity: v,
            normal_force: -20.0,
            normal_damping: eta,
            ..registry::sticking_input()
        };
        let k_a = 8.0 * i.effective_shear_modulus * (i.overlap * i.effective_radius).sqrt();
        let cone = v * (-8.0 / 5.0);
        let elastic = cone + v * (x * eta);
        for variant in Variant::ALL {
            let law = LammpsMindlin {
                variant,
                x_gamma_t: x,
            };
            let mut s = MindlinHistory::default();
            let f = law.force(&i, &mut s);
            let expected = if variant.force() {
                elastic
            } else {
                elastic * (-1.0 / k_a)
            };
            for c in 0..2 {
                approx::assert_relative_eq!(f[c], cone[c], max_relative = 1e-14);
                approx::assert_relative_eq!(s.history[c], expected[c], max_relative = 1e-13);
            }
        }
    }
}
