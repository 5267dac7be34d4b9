//! Van der Waals attraction between spheres (Zhong 2009 eq 28; Hamaker 1937 in the
//! near-contact limit h ≪ R):
//!
//!   F_v = A R* / (6 h²),   h = |x_i − x_j| − R_i − R_j  (the surface gap)
//!
//! attracting the two bodies (Zhong prints +n̂_ij, which points from j to i, i.e.
//! repulsion in his own convention; the Hamaker force attracts —
//! docs/paper-discrepancies.md). The 1/h² singularity is cut at a minimum
//! separation h_min (typically 0.4 nm, the interatomic distance): for h < h_min,
//! including overlap, the force is A R*/(6 h_min²). Beyond the cut-off h_c it is
//! zero, and the broad phase widens its reach by h_c so that pairs across a gap are
//! found. A plane wall is the R_j → ∞ limit, R* = R_i.
//! Potential (for the energy book), continuous at h_min and zero at h_c:
//!   U(h) = −(A R*/6)(1/h − 1/h_c)                  for h_min ≤ h ≤ h_c
//!   U(h) = U(h_min) − A R*/(6 h_min²) (h_min − h)  for h < h_min
//! No history. A (J), h_min and h_c (m) are scene parameters.

use crate::contact::model::CohesionModel;
use crate::error::Errors;

/// Van der Waals (Hamaker) attraction between the surfaces of two bodies: held at
/// its value at h_min for smaller gaps (and overlaps), zero beyond h_c.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct VanDerWaals {
    /// Hamaker constant A, J.
    pub hamaker: f64,
    /// h_min, m.
    pub min_separation: f64,
    /// h_c, m.
    pub cutoff: f64,
}

/// The scene's cohesion role, read as `{"law": "van_der_waals", ...}`.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(tag = "law", rename_all = "snake_case")]
pub enum Cohesion {
    /// Hamaker's van der Waals attraction.
    VanDerWaals(VanDerWaals),
}

impl Cohesion {
    /// How far beyond touching it acts, m.
    pub fn reach(&self) -> f64 {
        match self {
            Cohesion::VanDerWaals(c) => c.reach(),
        }
    }

    /// The rules of the law's parameters; `path` is where the scene holds the role.
    pub fn check(&self, path: &str, errors: &mut Errors) {
        match self {
            Cohesion::VanDerWaals(c) => c.check(path, errors),
        }
    }

    /// See `CohesionModel::force`.
    #[inline(always)]
    pub fn force(&self, gap: f64, effective_radius: f64) -> f64 {
        match self {
            Cohesion::VanDerWaals(c) => CohesionModel::force(c, gap, effective_radius),
        }
    }

    /// See `CohesionModel::energy`.
    pub fn energy(&self, gap: f64, effective_radius: f64) -> f64 {
        match self {
            Cohesion::VanDerWaals(c) => CohesionModel::energy(c, gap, effective_radius),
        }
    }
}

impl VanDerWaals {
    /// Attractive force magnitude at surface gap `gap` (negative gap = overlap), N.
    #[inline]
    pub fn force(&self, gap: f64, effective_radius: f64) -> f64 {
        if gap > self.cutoff {
            return 0.0;
        }
        let h = gap.max(self.min_separation);
        self.hamaker * effective_radius / (6.0 * h * h)
    }

    /// Potential energy of the attraction, J (≤ 0).
    pub fn energy(&self, gap: f64, effective_radius: f64) -> f64 {
        if gap > self.cutoff {
            return 0.0;
        }
        let scale = self.hamaker * effective_radius / 6.0;
        let h = gap.max(self.min_separation);
        let far = -scale * (1.0 / h - 1.0 / self.cutoff);
        far - self.force(gap, effective_radius) * (self.min_separation - gap).max(0.0)
    }
}

impl CohesionModel for VanDerWaals {
    fn check(&self, path: &str, e: &mut Errors) {
        let (min, cutoff) = (self.min_separation, self.cutoff);
        e.positive(format!("{path}.hamaker"), self.hamaker);
        e.positive(format!("{path}.min_separation"), min);
        if !(cutoff > min && cutoff.is_finite()) {
            e.push(
                format!("{path}.cutoff"),
                format!("must be > min_separation ({min:e}) and finite, got {cutoff:e}"),
            );
        }
    }
    fn reach(&self) -> f64 {
        self.cutoff
    }
    #[inline(always)]
    fn force(&self, gap: f64, effective_radius: f64) -> f64 {
        VanDerWaals::force(self, gap, effective_radius)
    }
    fn energy(&self, gap: f64, effective_radius: f64) -> f64 {
        VanDerWaals::energy(self, gap, effective_radius)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    const VDW: VanDerWaals = VanDerWaals {
        hamaker: 1e-19,
        min_separation: 4e-10,
        cutoff: 1e-7,
    };

    #[test]
    fn force_is_minus_the_derivative_of_the_energy() {
        let r = 1e-5;
        for gap in [-1e-9f64, 1e-10, 1e-9, 5e-9, 5e-8] {
            let h = 1e-6 * gap.abs();
            let de = (VDW.energy(gap + h, r) - VDW.energy(gap - h, r)) / (2.0 * h);
            assert_relative_eq!(de, VDW.force(gap, r), max_relative = 1e-6);
        }
    }

    #[test]
    fn saturates_below_min_separation_and_vanishes_beyond_cutoff() {
        let r = 1e-5;
        assert_eq!(VDW.force(-1e-8, r), VDW.force(4e-10, r));
        assert_eq!(VDW.force(1.01e-7, r), 0.0);
        assert_relative_eq!(
            VDW.force(1e-9, r),
            1e-19 * 1e-5 / 6e-18,
            max_relative = 1e-14
        );
    }
}
