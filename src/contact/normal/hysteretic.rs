//! Hysteretic linear law (Zhong 2009 model V, eqs 17–18).
//!
//!   F_n = k_n δ (1 + γ sgn(dδ/dt)),  0 ≤ γ < 1
//!
//! Zhong writes F_dn = −γ_n sgn(ξ̇) F_cn with ξ̇ the normal relative velocity
//! (negative on approach); in our convention dδ/dt > 0 on approach, hence the plus.
//! The contact is stiffer while loading, k(1 + γ), than while unloading, k(1 − γ),
//! so a head-on collision has e = √((1 − γ)/(1 + γ)) whatever the speed, and with
//! Zhong's γ_n = 0.7 (Tables 1–2) e = 0.420. γ is dimensionless.
//! No history. Stiffness for the time step: k(1 + γ).
//! Recoverable (stored) energy: ½ k (1 − γ) δ², released along the unloading branch.

pub fn hysteretic_force(overlap: f64, overlap_rate: f64, stiffness: f64, hysteresis: f64) -> f64 {
    let factor = if overlap_rate > 0.0 {
        1.0 + hysteresis
    } else if overlap_rate < 0.0 {
        1.0 - hysteresis
    } else {
        1.0
    };
    stiffness * overlap * factor
}

/// Closed-form restitution of a head-on collision.
pub fn hysteretic_restitution(hysteresis: f64) -> f64 {
    ((1.0 - hysteresis) / (1.0 + hysteresis)).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn loading_is_stiffer_than_unloading() {
        assert_eq!(hysteretic_force(1e-3, 1.0, 1e6, 0.7), 1e3 * 1.7);
        assert!((hysteretic_force(1e-3, -1.0, 1e6, 0.7) - 300.0).abs() < 1e-9);
        assert!((hysteretic_restitution(0.7) - 0.420_084).abs() < 1e-6);
    }
}
