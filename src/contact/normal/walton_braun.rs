//! Walton–Braun normal law: linear loading, stiffer linear unloading with a
//! permanent set (Zhong 2009 model IV, eq 16; Walton & Braun 1986, J. Rheol. 30, 949).
//!
//!   loading (δ = δ_max, the virgin branch):  F = k₁ δ
//!   unloading and reloading (δ < δ_max):     F = max(0, k₂ (δ − δ₀)),  δ₀ = δ_max (1 − k₁/k₂)
//!
//! Zhong writes the branch choice with the sign of dδ/dt; we choose it by the memory
//! δ_max instead, which is Walton & Braun's original rule: reloading after a partial
//! unloading climbs the k₂ line until it meets the k₁ line at δ_max, so the law is
//! path-independent between turning points and never creates energy. A head-on
//! collision has e = √(k₁/k₂) exactly, whatever the speed. Requires k₂ ≥ k₁.
//! History: δ_max (m). Stiffness for the time step: k₁ loading, k₂ otherwise.
//! Recoverable (stored) energy: ½ k₂ (δ − δ₀)² while δ > δ₀.

/// Force and tangent stiffness at `overlap` given the largest overlap so far.
pub fn walton_braun_response(
    overlap: f64,
    max_overlap: f64,
    loading_stiffness: f64,
    unloading_stiffness: f64,
) -> (f64, f64) {
    if overlap >= max_overlap {
        (loading_stiffness * overlap, loading_stiffness)
    } else {
        let set = max_overlap * (1.0 - loading_stiffness / unloading_stiffness);
        if overlap > set {
            (unloading_stiffness * (overlap - set), unloading_stiffness)
        } else {
            (0.0, unloading_stiffness)
        }
    }
}

pub fn walton_braun_energy(
    overlap: f64,
    max_overlap: f64,
    loading_stiffness: f64,
    unloading_stiffness: f64,
) -> f64 {
    let set = max_overlap.max(overlap) * (1.0 - loading_stiffness / unloading_stiffness);
    0.5 * unloading_stiffness * (overlap - set).max(0.0).powi(2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn unloading_line_meets_loading_line_at_the_turning_point() {
        let (k1, k2, dm) = (1e5, 4e5, 1e-4);
        let (f_load, _) = walton_braun_response(dm, dm, k1, k2);
        let (f_unload, _) = walton_braun_response(dm * (1.0 - 1e-12), dm, k1, k2);
        assert_relative_eq!(f_load, f_unload, max_relative = 1e-9);
        // permanent set: zero force at δ₀ = δ_max (1 − k1/k2)
        assert_eq!(walton_braun_response(0.75 * dm, dm, k1, k2).0, 0.0);
    }
}
