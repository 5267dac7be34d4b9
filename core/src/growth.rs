//! The growth stage of Zhong 2009 §6.1: particles are placed at random in the
//! container with small radii, then every radius grows linearly to its target
//! while gravity is off; contacts that form push the particles apart, so the bed
//! starts dense and free of the large initial overlaps random placement would
//! give. Gravity is switched on when the growth ends.
//!
//!   R_i(t) = R_i · (f₀ + (1 − f₀) · min(t / T, 1))
//!
//! Zhong starts from f₀ = 0. Masses and moments of inertia keep their final
//! values throughout (only the contact radius grows), so the time step estimated
//! from the final particles stays valid during growth; this is the usual choice in
//! DEM growth algorithms and what Zhong's fixed time step implies.
//!
//! Growing radii create overlap energy out of nothing, so the energy book is
//! restarted when the growth ends and the energy check is off during it.

/// The growth stage: radii rising linearly from f₀ R_i to R_i over a duration T, with
/// gravity off.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Growth {
    /// T, s.
    pub duration: f64,
    /// f₀ in [0, 1).
    pub initial_fraction: f64,
}

impl Growth {
    /// Fraction of its target radius each particle has at time t.
    pub fn fraction(&self, t: f64) -> f64 {
        let s = (t / self.duration).clamp(0.0, 1.0);
        self.initial_fraction + (1.0 - self.initial_fraction) * s
    }

    /// Whether radii are still growing at time t, s.
    pub fn is_growing(&self, t: f64) -> bool {
        t < self.duration
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grows_linearly_to_the_target() {
        let g = Growth {
            duration: 2.0,
            initial_fraction: 0.2,
        };
        assert_eq!(g.fraction(0.0), 0.2);
        assert!((g.fraction(1.0) - 0.6).abs() < 1e-15);
        assert_eq!(g.fraction(5.0), 1.0);
        assert!(g.is_growing(1.999) && !g.is_growing(2.0));
    }
}
