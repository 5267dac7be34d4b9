//! Linear spring normal law (Zhong 2009 model I, eq 5).
//!
//!   F_n^e = k_n δ            (δ = R_i + R_j − |x_i − x_j| > 0, repulsive positive)
//!   stiffness dF/dδ = k_n,   stored energy U = ½ k_n δ²
//!
//! With a constant dashpot γ_n (eq 6) the collision has the closed forms of
//! Zhong eqs 7–9, implemented below for the verification cases.
//!
//! With the total force k_n δ + γ_n dδ/dt clamped at zero (`contact.damping.limit`)
//! the contact force ends where ω₀² δ + 2β dδ/dt = 0 (β = γ_n/2m*, ω₀² = k_n/m*), at
//! ω t_f = π − atan2(2βω, ω² − β²), before the overlap returns to zero; from then on
//! the spheres part at constant speed, so e = exp(−β t_f) and the overlap closes at
//! t_f + δ(t_f)/(e v). Schwager & Pöschel (Granular Matter 9 (2007) 465) give the
//! same restitution, derived here from the oscillator's δ(t).
//! Parameters: k_n in N/m. No history. LIGGGHTS keyword: `model hooke/stiffness`.

use super::NormalLaw;
use super::{NormalModel, NormalResponse};
use crate::contact::damping::liggghts::{LiggghtsModel, hooke_stiffness};
use crate::contact::damping::{Constant, Damping};
use crate::contact::lammps::{LammpsNormal, NoLammpsModel};
use crate::contact::model::{
    LiggghtsContact, LiggghtsDeck, LiggghtsProperty, LiggghtsRefusal, LiggghtsScene, LiggghtsValues,
};
use crate::contact::registry::{self, NormalExample};
use crate::error::Errors;
use crate::material::PairProperties;

/// Linear spring force F_n = k_n δ, N.
pub fn linear_force(stiffness: f64, overlap: f64) -> f64 {
    stiffness * overlap
}

/// Elastic energy U = ½ k_n δ², J.
pub fn linear_energy(stiffness: f64, overlap: f64) -> f64 {
    0.5 * stiffness * overlap * overlap
}

/// Damped linear oscillator of one collision: natural frequency ω₀ = √(k/m*),
/// decay rate β = γ_n / (2 m*), damped frequency ω = √(ω₀² − β²).
#[derive(Clone, Copy, Debug)]
pub struct LinearCollision {
    /// Undamped natural frequency ω₀ = √(k_n/m*), rad/s.
    pub omega0: f64,
    /// Decay rate β = γ_n/(2m*), 1/s.
    pub beta: f64,
}

impl LinearCollision {
    /// The oscillator of a contact with stiffness k_n (N/m), effective mass m* (kg) and
    /// dashpot γ_n (N·s/m).
    pub fn new(stiffness: f64, effective_mass: f64, gamma_n: f64) -> Self {
        LinearCollision {
            omega0: (stiffness / effective_mass).sqrt(),
            beta: gamma_n / (2.0 * effective_mass),
        }
    }

    /// Damped frequency ω = √(ω₀² − β²), rad/s (NaN when overdamped, β > ω₀).
    pub fn damped_frequency(&self) -> f64 {
        (self.omega0.powi(2) - self.beta.powi(2)).sqrt()
    }

    /// Zhong eq 8: t_n = π / ω (until the overlap returns to zero).
    pub fn contact_duration(&self) -> f64 {
        std::f64::consts::PI / self.damped_frequency()
    }

    /// Zhong eq 7: ε_n = exp(−β t_n).
    pub fn restitution(&self) -> f64 {
        (-self.beta * self.contact_duration()).exp()
    }

    /// Exact maximum overlap of δ(t) = (v/ω) e^{−βt} sin ωt, reached at
    /// t* = atan(ω/β)/ω. Zhong eq 9 gives only the bound v t_n / π = v/ω, which is
    /// reached when β = 0.
    pub fn max_overlap(&self, approach_speed: f64) -> f64 {
        let w = self.damped_frequency();
        if self.beta == 0.0 {
            return approach_speed / w;
        }
        let t_star = (w / self.beta).atan() / w;
        approach_speed / w * (-self.beta * t_star).exp() * (w * t_star).sin()
    }

    /// With the force clamped at zero: the time t_f at which k_n δ + γ_n dδ/dt falls
    /// to zero, s (underdamped contacts, β < ω₀).
    pub fn no_pull_force_duration(&self) -> f64 {
        let w = self.damped_frequency();
        (std::f64::consts::PI - (2.0 * self.beta * w).atan2(w * w - self.beta * self.beta)) / w
    }

    /// With the force clamped at zero: e = exp(−β t_f), the speed the spheres part
    /// with once the force has ended.
    pub fn no_pull_restitution(&self) -> f64 {
        (-self.beta * self.no_pull_force_duration()).exp()
    }

    /// With the force clamped at zero: the time until the overlap returns to zero, s,
    /// t_f plus δ(t_f) crossed at the parting speed e v (independent of v).
    pub fn no_pull_contact_duration(&self) -> f64 {
        let (w, t_f) = (self.damped_frequency(), self.no_pull_force_duration());
        // δ(t)/v = e^{−βt} sin(ωt)/ω.
        let overlap_per_speed = (-self.beta * t_f).exp() * (w * t_f).sin() / w;
        t_f + overlap_per_speed / self.no_pull_restitution()
    }

    /// The damping coefficient γ_n that gives restitution `e` (inverse of eqs 7–8).
    pub fn gamma_for_restitution(stiffness: f64, effective_mass: f64, e: f64) -> f64 {
        let ln_e = e.ln();
        let omega0 = (stiffness / effective_mass).sqrt();
        let beta = -ln_e * omega0 / (std::f64::consts::PI.powi(2) + ln_e * ln_e).sqrt();
        2.0 * effective_mass * beta
    }
}

/// The `characteristicVelocity` V for which LIGGGHTS's `model hooke` gives k_n =
/// `stiffness` (normal_model_hooke.h l. 269–275 solved for V), refused unless that
/// holds for every contact kind of the scene.
fn characteristic_velocity(
    contacts: &[LiggghtsContact],
    stiffness: f64,
) -> Result<f64, LiggghtsRefusal> {
    let Some(first) = contacts.first() else {
        return Ok(1.0);
    };
    let (m, r, e) = (
        first.effective_mass,
        first.effective_radius,
        first.effective_modulus,
    );
    let a = 16.0 * r.sqrt() * e;
    let v = (a / (15.0 * m) * (15.0 * stiffness / a).powi(5)).sqrt();
    for c in contacts {
        let (m, r) = (c.effective_mass, c.effective_radius);
        let k = hooke_stiffness(m, r, c.effective_modulus, v);
        if ((k - stiffness) / stiffness).abs() > 1e-9 {
            return Err((
                "contact.normal.stiffness".into(),
                format!(
                    "model hooke derives k_n from m*, R*, E* and one characteristicVelocity; with V = {v:e} m/s it gives {k:e} N/m for a contact with m* = {m:e} kg, R* = {r:e} m (a wall contact, or another size or material), not {stiffness:e} N/m"
                ),
            ));
        }
    }
    Ok(v)
}

/// Zhong model I: F = k_n δ, k_n in N/m.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Linear {
    /// Normal spring stiffness k_n, N/m.
    pub stiffness: f64,
}

impl NormalModel for Linear {
    type State = ();

    fn name(&self) -> &'static str {
        "linear"
    }

    /// F = k_n δ.
    fn examples() -> Vec<NormalExample> {
        let law = NormalLaw::Linear(Linear { stiffness: 1e7 });
        registry::loading_examples(law, |overlap| 1e7 * overlap)
    }

    fn check(&self, path: &str, e: &mut Errors) {
        e.positive(format!("{path}.stiffness"), self.stiffness);
    }

    /// LIGGGHTS's `model hooke` when k_n is its `hooke_stiffness` (damping/liggghts.rs).
    fn liggghts(&self) -> Option<LiggghtsModel> {
        Some(LiggghtsModel::Hooke)
    }

    /// `hooke k damp`: F = k δ with k this law's stiffness.
    fn lammps(&self) -> Result<LammpsNormal, NoLammpsModel> {
        Ok(LammpsNormal::Hooke {
            stiffness: self.stiffness,
        })
    }

    /// With a constant γ_n: `model hooke/stiffness absolute_damping on` (kn = kt = k,
    /// gamman_abs = γ_n, gammat_abs = 0), exported only without friction. Otherwise
    /// `model hooke`, damped by `coefficientRestitution`, with the
    /// `characteristicVelocity` that makes its k_n equal k (`characteristic_velocity`).
    fn liggghts_deck(
        &self,
        scene: &LiggghtsScene,
    ) -> Option<Result<LiggghtsDeck, Vec<LiggghtsRefusal>>> {
        let k = self.stiffness;
        if let Some(Damping::Constant(Constant { gamma_n })) = scene.damping {
            if scene.tangential {
                return Some(Err(vec![(
                    "contact.tangential".into(),
                    "a constant gamma_n exports as model hooke/stiffness, which tamp exports only without friction".into(),
                )]));
            }
            return Some(Ok(LiggghtsDeck {
                model: "hooke/stiffness",
                options: "absolute_damping on",
                properties: vec![
                    scene.uniform_pair("kn", k),
                    scene.uniform_pair("kt", k),
                    scene.uniform_pair("gamman_abs", *gamma_n),
                    scene.uniform_pair("gammat_abs", 0.0),
                    scene.coefficient_friction(),
                ],
            }));
        }
        Some(
            characteristic_velocity(&scene.contacts, k)
                .map(|v| LiggghtsDeck {
                    model: "hooke",
                    options: "",
                    properties: vec![
                        scene.coefficient_restitution(),
                        scene.coefficient_friction(),
                        LiggghtsProperty {
                            name: "characteristicVelocity",
                            values: LiggghtsValues::Scalar(v),
                        },
                    ],
                })
                .map_err(|refusal| vec![refusal]),
        )
    }

    #[inline(always)]
    fn response(
        &self,
        overlap: f64,
        _: f64,
        _: f64,
        _: &PairProperties,
        _: &mut (),
    ) -> NormalResponse {
        NormalResponse {
            force: linear_force(self.stiffness, overlap),
            stiffness: self.stiffness,
        }
    }

    fn stiffness(&self, _: f64, _: f64, _: &PairProperties, _: &()) -> f64 {
        self.stiffness
    }

    fn energy(&self, overlap: f64, _: f64, _: &PairProperties, _: &()) -> f64 {
        linear_energy(self.stiffness, overlap)
    }

    fn impact_stiffness(&self, _: f64, _: f64, _: f64, _: &PairProperties) -> f64 {
        self.stiffness
    }

    fn stiffness_depends_on_speed(&self) -> bool {
        false
    }

    fn error_model(&self, damping: Option<&Damping>) -> Option<&'static str> {
        match damping {
            None => Some("linear"),
            Some(
                Damping::Constant(_) | Damping::MassVelocity(_) | Damping::CriticalFraction(_),
            ) => Some("linear_damped"),
            Some(_) => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn gamma_for_restitution_inverts_eq7() {
        let g = LinearCollision::gamma_for_restitution(1e7, 2e-3, 0.5);
        assert_relative_eq!(
            LinearCollision::new(1e7, 2e-3, g).restitution(),
            0.5,
            max_relative = 1e-12
        );
    }

    #[test]
    fn the_clamped_force_ends_where_it_crosses_zero_and_not_before() {
        // Integrated with a step of t_n/2e6, the clamped oscillator's parting speed
        // and overlap crossing meet the closed forms.
        for gamma in [1.0, 40.0, 100.0, 180.0, 200.0, 250.0] {
            let (k, m) = (1e7, 2e-3);
            let c = LinearCollision::new(k, m, gamma);
            let dt = c.contact_duration() / 2e6;
            let (mut x, mut v, mut t) = (0.0, 1.0, 0.0);
            let force = |x: f64, v: f64| (k * x + gamma * v).max(0.0);
            let mut a = -force(x, v) / m;
            let mut parted = None;
            loop {
                x += v * dt + 0.5 * a * dt * dt;
                let v_half = v + 0.5 * a * dt;
                a = -force(x, v_half) / m;
                v = v_half + 0.5 * a * dt;
                t += dt;
                if parted.is_none() && a == 0.0 && v < 0.0 {
                    parted = Some(-v);
                }
                if x <= 0.0 {
                    break;
                }
            }
            let e = parted.expect("the force ended");
            assert_relative_eq!(e, c.no_pull_restitution(), max_relative = 1e-5);
            assert_relative_eq!(t, c.no_pull_contact_duration(), max_relative = 1e-5);
            assert!(c.no_pull_restitution() > c.restitution());
        }
        // No damping: the clamp never acts.
        let c = LinearCollision::new(1e7, 2e-3, 0.0);
        assert_relative_eq!(c.no_pull_restitution(), 1.0);
        assert_relative_eq!(c.no_pull_contact_duration(), c.contact_duration());
    }

    #[test]
    fn undamped_max_overlap_equals_zhong_eq9_bound() {
        let c = LinearCollision::new(1e7, 2e-3, 0.0);
        assert_relative_eq!(
            c.max_overlap(1.0),
            1.0 * c.contact_duration() / std::f64::consts::PI
        );
    }

    #[test]
    fn damped_max_overlap_is_below_eq9_bound() {
        let c = LinearCollision::new(1e7, 2e-3, 3.0);
        assert!(c.max_overlap(1.0) < c.contact_duration() / std::f64::consts::PI);
    }

    #[test]
    fn energy_derivative_is_force() {
        let (k, d, h) = (1e7, 1e-4, 1e-9);
        let fd = (linear_energy(k, d + h) - linear_energy(k, d - h)) / (2.0 * h);
        assert_relative_eq!(fd, linear_force(k, d), max_relative = 1e-6);
    }
}
