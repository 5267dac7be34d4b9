//! The screening of contacts through a third particle (Zunker et al. 2025; LAMMPS's
//! `FixGranularMDR::calculate_contact_penalty`). When particles i, j, k overlap
//! pairwise, the contact across the longest of the three centre distances passes
//! through the third particle, the "central" one; it is given the penalty
//!   p += 1/(1 + e^{−50(α/π − 1/2)}),
//! with α the angle at the central particle between the directions to the other two,
//! and its force is weighed by w = max(1 − p, 0). A contact seen nearly straight
//! through the centre (α → π) loses its force; one at a right angle keeps half.

use std::f64::consts::PI;

/// The penalty one triplet adds to the contact opposite the angle `alpha` (rad).
pub fn screening(alpha: f64) -> f64 {
    1.0 / (1.0 + (-50.0 * (alpha / PI - 0.5)).exp())
}

/// The weight of a contact with penalty `p`.
pub fn weight(p: f64) -> f64 {
    (1.0 - p).max(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn straight_through_loses_the_force() {
        assert!((screening(PI / 2.0) - 0.5).abs() < 1e-15);
        assert!(weight(screening(PI)) < 1e-10);
        assert!(weight(screening(PI / 3.0)) > 0.9997);
    }
}
