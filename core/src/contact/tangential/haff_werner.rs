//! Haff–Werner viscous friction capped by Coulomb (Zhong 2009 model VIII, eq 23;
//! Haff & Werner 1986, Powder Technol. 48, 239).
//!
//!   F_t = −min(γ_s |v_t|, μ max(F_n, 0)) v_t/|v_t|
//!
//! γ_s (N·s/m) is the tangential damping coefficient. Viscous below the Coulomb
//! limit, so slow slip is resisted in proportion to its speed and a contact cannot
//! stick. No history. Explicit stability of the viscous part needs Δt < 2 m/(n_c γ_s L)
//! per particle: its n_c contacts' dashpots act on it together, and L is the
//! rotational lever factor when spin is on (simulation/critical_step.rs).

use super::{TangentialInput, TangentialLaw, TangentialModel};
use crate::contact::model::Roles;
use crate::contact::registry::{self, TangentialExample};
use crate::error::Errors;

use crate::particles::Vec3;

/// Viscous friction −min(γ_s |v_t|, μ max(F_n, 0)) v_t/|v_t| on particle i, N; zero
/// when v_t = 0.
#[inline]
pub fn haff_werner_force(
    tangential_velocity: &Vec3,
    damping: f64,
    friction: f64,
    normal_force: f64,
) -> Vec3 {
    let speed = tangential_velocity.norm();
    if speed == 0.0 {
        return Vec3::zeros();
    }
    let magnitude = (damping * speed).min(friction * normal_force.max(0.0));
    -tangential_velocity * (magnitude / speed)
}

/// Zhong model VIII; γ_s in N·s/m.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct HaffWerner {
    /// Tangential damping coefficient γ_s, N·s/m.
    pub damping: f64,
}

impl TangentialModel for HaffWerner {
    type State = ();

    fn name(&self) -> &'static str {
        "haff_werner"
    }

    /// F = −min(γ_s |v_t|, μF_n) v̂_t (Zhong eq 23), γ_s = 50 N·s/m: viscous at 10 mm/s
    /// (0.5 N < 1.2 N), Coulomb at 1 m/s.
    fn examples() -> Vec<TangentialExample> {
        let law = TangentialLaw::HaffWerner(HaffWerner { damping: 50.0 });
        let (stick, slide) = (registry::sticking_input(), registry::sliding_input());
        vec![
            TangentialExample {
                law,
                input: stick,
                force: -stick.tangential_velocity * 50.0,
            },
            TangentialExample {
                law,
                input: slide,
                force: registry::sliding_force(&slide),
            },
        ]
    }

    fn check(&self, path: &str, _: Roles, e: &mut Errors) {
        e.positive(format!("{path}.damping"), self.damping);
    }

    #[inline(always)]
    fn force(&self, input: &TangentialInput, _: &mut ()) -> Vec3 {
        haff_werner_force(
            &input.tangential_velocity,
            self.damping,
            input.friction,
            input.normal_force,
        )
    }

    fn stiffness(&self, _: &TangentialInput) -> f64 {
        0.0
    }

    fn energy(&self, _: &TangentialInput, _: &()) -> f64 {
        0.0
    }

    /// The dashpots of all a particle's contacts act on it together: Δt < 2m/(n_c γ_s (1 + m R²/I)).
    fn viscous_coefficient(&self) -> Option<f64> {
        (self.damping > 0.0).then_some(self.damping)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn viscous_below_the_cone_coulomb_above() {
        let slow = haff_werner_force(&Vec3::new(1e-3, 0.0, 0.0), 100.0, 0.5, 10.0);
        assert!((slow.x + 0.1).abs() < 1e-14);
        let fast = haff_werner_force(&Vec3::new(1.0, 0.0, 0.0), 100.0, 0.5, 10.0);
        assert!((fast.x + 5.0).abs() < 1e-14);
    }
}
