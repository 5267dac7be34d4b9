//! LIGGGHTS 3.8's `tangential history` (scene law `liggghts_history`), reproduced
//! operation for operation from LIGGGHTS-PUBLIC 3.8.0 (release commit 84ba3d7,
//! src/tangential_model_history.h l. 147–227; the surface, normal and damping values it
//! reads come from surface_model_default.h l. 151–203 and normal_model_hertz.h /
//! normal_model_hooke.h). tamp's notation: `normal` n points from the partner to
//! particle i, v_t is the tangential velocity of i's contact point relative to the
//! partner's (spins included, at the half step v(n+½) like every contact velocity),
//! F_n the total normal force (elastic + damping, not clipped: `limitForce off`).
//!
//!   s ← s + v_t Δt;  s ← s − (s·n) n        (l. 147–159: projected onto the tangent
//!                                            plane, its length NOT restored)
//!   F_t = −k_t s                             (l. 166–171, with the CURRENT k_t)
//!   if k_t|s| > μ|F_n|  (slip, l. 174–210):  F_t ← F_t · μ|F_n| / (k_t|s|),
//!                                            s ← −F_t / k_t,  no damping this step
//!   else                (stick, l. 212–226): F_t ← F_t − γ_t v_t
//!                                            (not re-checked against the cone)
//!
//! with, per contact and per step (`tangential_damping on`, the LIGGGHTS default):
//!   `model hertz` (normal_model_hertz.h l. 231–237): k_t = S_t = 8G*√(R*δ),
//!       γ_t = −2√(5/6) β √(S_t m*)
//!   `model hooke` (normal_model_hooke.h l. 269–275): k_t = k_n,  γ_t = γ_n
//! β = ln e/√(ln²e + π²) ≤ 0 (global_properties.cpp l. 539). In tamp's terms
//! γ_t = ξ · 2√(m* k_t) with the ξ that `liggghts_restitution` gives the normal damping
//! (damping/liggghts.rs), for both models; ξ = 0 (e = 1) without damping.
//! 1/G* = 2(2 − ν_i)(1 + ν_i)/E_i + 2(2 − ν_j)(1 + ν_j)/E_j (global_properties.cpp l. 463).
//! The Coulomb test takes |F_n|, so a contact pulled together by the damping near its
//! end (F_n < 0) still carries friction μ|F_n|.
//!
//! The torque −lever·(n × F_t) with lever R − δ/2 (l. 229–263) is tamp's, applied by
//! the simulation for every law. History: the shear displacement s (m), reset to zero
//! when the bodies separate (pairs: `surfacesClose`; primitive walls:
//! fix_wall_gran.cpp l. 1145–1150), as tamp resets every contact history.
//! Parameters: μ from the material pair; the model and ξ come from the scene's normal
//! law and damping when the law is built. See docs/liggghts.md.

use super::mindlin_no_slip::mindlin_no_slip_stiffness;
use super::{TangentialInput, TangentialLaw, TangentialModel};
use crate::contact::damping::liggghts::LiggghtsModel;
use crate::contact::damping::{Damping, critical_damping};
use crate::contact::model::{Needs, Roles};
use crate::contact::registry::{self, TangentialExample};
use crate::error::Errors;

use crate::particles::Vec3;

/// Why `liggghts_history` is refused with the normal law `law` (path
/// `contact.tangential.law`).
pub fn unsupported_normal_law(law: &str) -> String {
    format!(
        "'liggghts_history' needs contact.normal.law 'hertz' (model hertz) or 'linear' (model hooke), the laws whose LIGGGHTS k_t and γ_t it reproduces; got '{law}'"
    )
}

/// Why `liggghts_history` is refused with the damping kind `kind` (path `contact.damping`).
pub fn unsupported_damping(kind: &str) -> String {
    format!(
        "must be absent or of kind 'liggghts_restitution' with contact.tangential.law 'liggghts_history', whose tangential damping LIGGGHTS derives from the restitution coefficient; got kind '{kind}'"
    )
}

/// Why `liggghts_history` needs rotation (path `rotation`).
pub const NEEDS_ROTATION: &str = "is required by contact.tangential.law 'liggghts_history': LIGGGHTS always integrates the spins (fix nve/sphere), so the law is only LIGGGHTS's with them; add \"rotation\": {}";

/// One step of LIGGGHTS's `tangential history`: advances the shear displacement
/// `shear` and returns the tangential force on particle i.
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn liggghts_history_force(
    shear: &mut Vec3,
    normal: &Vec3,
    tangential_velocity: &Vec3,
    dt: f64,
    stiffness: f64,
    damping: f64,
    friction: f64,
    normal_force: f64,
) -> Vec3 {
    *shear += tangential_velocity * dt;
    let along_normal = shear.dot(normal);
    *shear -= normal * along_normal;
    let length = shear.norm();
    let mut force = -(*shear * stiffness);
    let spring = stiffness * length;
    let limit = friction * normal_force.abs();
    if spring > limit {
        if length != 0.0 {
            force *= limit / spring;
            *shear = -force / stiffness;
        } else {
            force = Vec3::zeros();
        }
    } else {
        force -= tangential_velocity * damping;
    }
    force
}

/// LIGGGHTS 3.8 `tangential history`: k_t of the LIGGGHTS `model` (8G*√(R*δ) for
/// hertz, k_n for hooke) and γ_t = ξ·2√(m* k_t) with ξ the normal damping's
/// (`liggghts_restitution`, 0 without damping). State: the shear displacement, m.
///
/// The scene gives no parameters (`{"law": "liggghts_history", "friction": μ}`): the
/// model and ξ are bound from the other roles by `ContactLaw::new` (`bound`); until
/// then ξ is NaN, so an unbound law cannot run unnoticed.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct LiggghtsHistory {
    /// The LIGGGHTS normal model whose k_t is used, bound from the normal law.
    #[serde(skip)]
    pub model: LiggghtsModel,
    /// Damping ratio ξ of the tangential dashpot, bound from the damping role (NaN until
    /// bound).
    #[serde(skip, default = "unbound")]
    pub xi: f64,
}

fn unbound() -> f64 {
    f64::NAN
}

impl LiggghtsHistory {
    /// The law beside the scene's normal law and damping: the LIGGGHTS model of the
    /// normal law gives k_t, the ξ of `liggghts_restitution` (0 without damping) γ_t.
    pub fn bound(&self, roles: Roles) -> Result<Self, Refused> {
        let model = roles
            .normal
            .liggghts()
            .ok_or_else(|| Refused::NormalLaw(unsupported_normal_law(roles.normal.name())))?;
        let xi = match roles.damping {
            None => 0.0,
            Some(Damping::LiggghtsRestitution(d)) => {
                d.with(roles.normal).map_err(Refused::NormalLaw)?.xi
            }
            Some(other) => return Err(Refused::Damping(unsupported_damping(other.name()))),
        };
        Ok(LiggghtsHistory { model, xi })
    }
}

/// A combination of roles LIGGGHTS's `tangential history` is not defined with, and why.
#[derive(Clone, Debug, PartialEq)]
pub enum Refused {
    /// The normal law has no LIGGGHTS `model` with this tangential history.
    NormalLaw(String),
    /// The damping kind is not LIGGGHTS's restitution damping.
    Damping(String),
}

impl TangentialModel for LiggghtsHistory {
    type State = Vec3;

    fn name(&self) -> &'static str {
        "liggghts_history"
    }

    /// From rest, sticking: F = −k_t v_t Δt with k_t = 8G*√(R*δ) (`model hertz`) or k_n
    /// (`model hooke`), no damping (ξ = 0: with it LIGGGHTS's sticking force may leave
    /// the cone, see the tests below); sliding: −μ|F_n| v̂_t.
    fn examples() -> Vec<TangentialExample> {
        let hooke_stiffness = registry::sticking_input().normal_stiffness;
        [
            (LiggghtsModel::Hertz, registry::mindlin_stiffness()),
            (LiggghtsModel::Hooke, hooke_stiffness),
        ]
        .into_iter()
        .flat_map(|(model, k)| {
            let law = TangentialLaw::LiggghtsHistory(LiggghtsHistory { model, xi: 0.0 });
            registry::spring_examples(law, k)
        })
        .collect()
    }

    fn needs(&self) -> Needs {
        Needs {
            rotation: Some(NEEDS_ROTATION),
            ..Needs::default()
        }
    }

    /// Left unbound (ξ NaN) beside roles validation refuses.
    fn bind(&mut self, roles: Roles) {
        if let Ok(bound) = self.bound(roles) {
            *self = bound;
        }
    }

    /// The normal law must be LIGGGHTS's, the damping absent or LIGGGHTS's.
    fn check(&self, path: &str, roles: Roles, e: &mut Errors) {
        match self.bound(roles) {
            Ok(_) => {}
            Err(Refused::NormalLaw(rule)) => e.push(format!("{path}.law"), rule),
            Err(Refused::Damping(rule)) => e.push("contact.damping", rule),
        }
    }

    #[inline(always)]
    fn force(&self, input: &TangentialInput, shear: &mut Vec3) -> Vec3 {
        let k_t = self.stiffness(input);
        liggghts_history_force(
            shear,
            &input.normal,
            &input.tangential_velocity,
            input.dt,
            k_t,
            self.xi * critical_damping(input.effective_mass, k_t),
            input.friction,
            input.normal_force,
        )
    }

    fn stiffness(&self, input: &TangentialInput) -> f64 {
        match self.model {
            LiggghtsModel::Hertz => mindlin_no_slip_stiffness(
                input.overlap,
                input.effective_radius,
                input.effective_shear_modulus,
            ),
            LiggghtsModel::Hooke => input.normal_stiffness,
        }
    }

    /// ½ k_t |s|².
    fn energy(&self, input: &TangentialInput, shear: &Vec3) -> f64 {
        0.5 * self.stiffness(input) * shear.norm_squared()
    }

    /// Hooke's k_t = k_n is known before any contact.
    fn stiffness_before_contact(&self, impact_stiffness: f64) -> f64 {
        match self.model {
            LiggghtsModel::Hooke => impact_stiffness,
            LiggghtsModel::Hertz => 0.0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::damping::liggghts::{LiggghtsModel, beta, hooke_stiffness};
    use approx::assert_relative_eq;

    // Steel spheres of the LIGGGHTS cross-checks: R = 1 mm, E = 2e11 Pa, ν = 0.3.
    const M_EFF: f64 = 1.633_628_179_866_692_5e-5;
    const R_EFF: f64 = 5e-4;
    const E_EFF: f64 = 2e11 / (2.0 * (1.0 - 0.09));
    // 1/G* = 2 · 2(2 − ν)(1 + ν)/E (global_properties.cpp l. 463).
    const G_EFF: f64 = 2e11 / (4.0 * 1.7 * 1.3);

    fn input(overlap: f64, v_t: Vec3, normal_stiffness: f64) -> TangentialInput {
        TangentialInput {
            normal: Vec3::z(),
            tangential_velocity: v_t,
            dt: 1e-9,
            friction: 0.5,
            normal_force: 10.0,
            normal_stiffness,
            overlap,
            effective_radius: R_EFF,
            effective_shear_modulus: G_EFF,
            effective_mass: M_EFF,
            normal_damping: 0.0,
        }
    }

    /// One step from a fresh contact, sticking: F_t = −k_t v_t Δt − γ_t v_t, with k_t
    /// and γ_t written as normal_model_hertz.h / normal_model_hooke.h write them.
    #[test]
    fn stiffness_and_damping_are_liggghts_kt_and_gammat() {
        let v = Vec3::new(0.02, -0.01, 0.0);
        for e in [0.06, 0.5, 0.9, 1.0] {
            let overlap: f64 = 1.6e-6;
            // model hertz
            let sqrtval = (R_EFF * overlap).sqrt();
            let st = 8.0 * G_EFF * sqrtval;
            let gammat = -2.0 * 0.912_870_929_175_276_9 * beta(e) * (st * M_EFF).sqrt();
            let law = LiggghtsHistory {
                model: LiggghtsModel::Hertz,
                xi: LiggghtsModel::Hertz.critical_fraction(e),
            };
            let k_n = 2.0 * E_EFF * sqrtval;
            let f = law.force(&input(overlap, v, k_n), &mut Vec3::zeros());
            let want = -(v * 1e-9 * st) - v * gammat;
            assert!((f - want).norm() <= 1e-14 * want.norm(), "hertz e {e}");
            // model hooke: k_t = k_n, γ_t = γ_n.
            let kn = hooke_stiffness(M_EFF, R_EFF, E_EFF, 1.0);
            let l = e.ln();
            let gamman = (4.0 * M_EFF * kn * l * l / (l * l + std::f64::consts::PI.powi(2))).sqrt();
            let law = LiggghtsHistory {
                model: LiggghtsModel::Hooke,
                xi: LiggghtsModel::Hooke.critical_fraction(e),
            };
            let f = law.force(&input(overlap, v, kn), &mut Vec3::zeros());
            let want = -(v * 1e-9 * kn) - v * gamman;
            assert!((f - want).norm() <= 1e-14 * want.norm(), "hooke e {e}");
        }
    }

    #[test]
    fn sticking_spring_carries_the_current_stiffness_and_the_dashpot() {
        let n = Vec3::z();
        let mut s = Vec3::zeros();
        let v = Vec3::new(1.0, 0.0, 0.0);
        let f = liggghts_history_force(&mut s, &n, &v, 1e-3, 1e4, 2.0, 0.5, 100.0);
        // −k s − γ v = −1e4·1e-3 − 2·1 = −12 N.
        assert_relative_eq!(f.x, -12.0, max_relative = 1e-15);
        // Not incremental: the same shear under twice the stiffness gives twice the spring.
        let f = liggghts_history_force(&mut s, &n, &Vec3::zeros(), 1e-3, 2e4, 2.0, 0.5, 100.0);
        assert_relative_eq!(f.x, -20.0, max_relative = 1e-15);
    }

    #[test]
    fn projection_keeps_only_the_tangential_part_without_rescaling() {
        let mut s = Vec3::new(1e-6, 0.0, 0.0);
        let n = Vec3::new(0.6, 0.0, 0.8);
        liggghts_history_force(&mut s, &n, &Vec3::zeros(), 1e-3, 1.0, 0.0, 1.0, 1.0);
        // s − (s·n) n = (1 − 0.36, 0, −0.48)·1e-6: length 0.8e-6, not the 1e-6 it had.
        assert_relative_eq!(s.x, 0.64e-6, max_relative = 1e-14);
        assert_relative_eq!(s.z, -0.48e-6, max_relative = 1e-14);
        assert_relative_eq!(s.norm(), 0.8e-6, max_relative = 1e-14);
    }

    #[test]
    fn slip_puts_force_and_spring_on_the_cone_without_damping() {
        let n = Vec3::z();
        let mut s = Vec3::zeros();
        let v = Vec3::new(3.0, 4.0, 0.0);
        // k|s| = 1e4·5e-3 = 50 N > μ|F_n| = 0.5·|−20| = 10 N: slip.
        let f = liggghts_history_force(&mut s, &n, &v, 1e-3, 1e4, 7.0, 0.5, -20.0);
        assert_relative_eq!(f.norm(), 10.0, max_relative = 1e-14);
        assert_relative_eq!(f.x, -6.0, max_relative = 1e-14);
        assert_relative_eq!(f.y, -8.0, max_relative = 1e-14);
        assert_relative_eq!(s.norm() * 1e4, 10.0, max_relative = 1e-14);
    }

    #[test]
    fn sticking_force_may_exceed_the_cone_by_its_damping() {
        // LIGGGHTS does not re-check F_t after adding −γ v_t.
        let n = Vec3::z();
        let mut s = Vec3::zeros();
        let v = Vec3::new(1.0, 0.0, 0.0);
        let f = liggghts_history_force(&mut s, &n, &v, 1e-3, 1e4, 5.0, 0.1, 100.0);
        assert_relative_eq!(f.norm(), 15.0, max_relative = 1e-15);
        assert!(f.norm() > 0.1 * 100.0);
    }
}
