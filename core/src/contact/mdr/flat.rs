//! Where the rigid flat of a pair contact lies: the split of the pair overlap δ into
//! the two sides' overlaps.
//!
//! At the largest pair overlap δ_max the flat is the plane of the two spheres'
//! intersection circle, so side i (radius R_i, partner R_j) has the cap height
//!   δ_geo,i = δ_max (2R_j − δ_max) / (2(R_i + R_j − δ_max)),
//! capped at a fraction of R_i (the remainder goes to the partner). Below δ_max each
//! side's overlap falls linearly from δ_geo,i at δ_max to its plastic set δ_p,i at the
//! pair overlap δ_p,0 + δ_p,1, where both sides' forces vanish:
//!   δ_i = δ_geo,i + (δ_p,i − δ_geo,i)(δ − δ_max)/(δ_p,0 + δ_p,1 − δ_max).
//!
//! LAMMPS writes this twice, in two arithmetics: the force caps a side at 0.75 R_i
//! (`MDR_OVERLAP_LIMIT`); the mean surface displacement of `fix GRANULAR/MDR` at
//! 0.95 R_i, computing the cap heights with a division where the force multiplies by
//! a reciprocal. tamp keeps both, as LAMMPS evaluates them (docs/models/mdr.md).

/// A side's overlap is capped at this fraction of its radius in the force.
pub const FORCE_LIMIT: f64 = 0.75;
/// The same cap in the mean surface displacement.
pub const DISPLACEMENT_LIMIT: f64 = 0.95;

/// The two sides' plastic sets and the pair's largest overlap, m.
#[derive(Clone, Copy, Debug)]
pub struct Flat {
    /// Largest pair overlap δ_max, m.
    pub max_overlap: f64,
    /// Plastic set of each side δ_p (zero while a side is elastic), m.
    pub plastic: [f64; 2],
}

impl Flat {
    /// Overlap of the side of radius `r_i` (partner `r_j`, plastic set `plastic_i`) at
    /// pair overlap `delta`, as the force evaluates it.
    pub fn force_side(&self, delta: f64, r_i: f64, r_j: f64, plastic_i: f64) -> f64 {
        let dmax = self.max_overlap;
        let denom = 1.0 / (2.0 * (dmax - r_i - r_j));
        let opt1 = dmax * (dmax - 2.0 * r_j) * denom;
        let opt2 = dmax * (dmax - 2.0 * r_i) * denom;
        let (mut geo, alt) = if r_i < r_j {
            (opt1.max(opt2), opt1.min(opt2))
        } else {
            (opt1.min(opt2), opt1.max(opt2))
        };
        if geo / r_i > FORCE_LIMIT {
            geo = r_i * FORCE_LIMIT;
        } else if alt / r_j > FORCE_LIMIT {
            geo = dmax - r_j * FORCE_LIMIT;
        }
        let plastic = self.plastic[0] + self.plastic[1];
        geo + (plastic_i - geo) * (delta - dmax) / (plastic - dmax)
    }

    /// Both sides' overlaps (side 0 of radius `r0`, side 1 of `r1`) at pair overlap
    /// `delta`, as the mean surface displacement evaluates them.
    pub fn displacement_sides(&self, delta: f64, r0: f64, r1: f64) -> [f64; 2] {
        let dmax = self.max_overlap;
        let opt1 = dmax * (dmax - 2.0 * r1) / (2.0 * (dmax - r0 - r1));
        let opt2 = dmax * (dmax - 2.0 * r0) / (2.0 * (dmax - r0 - r1));
        let (mut geo0, mut geo1) = if r0 < r1 {
            (opt1.max(opt2), opt1.min(opt2))
        } else {
            (opt1.min(opt2), opt1.max(opt2))
        };
        if geo0 / r0 > DISPLACEMENT_LIMIT {
            geo0 = r0 * DISPLACEMENT_LIMIT;
            geo1 = dmax - geo0;
        } else if geo1 / r1 > DISPLACEMENT_LIMIT {
            geo1 = r1 * DISPLACEMENT_LIMIT;
            geo0 = dmax - geo1;
        }
        let plastic = self.plastic[0] + self.plastic[1];
        [
            geo0 + (self.plastic[0] - geo0) / (plastic - dmax) * (delta - dmax),
            geo1 + (self.plastic[1] - geo1) / (plastic - dmax) * (delta - dmax),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Equal spheres split a loading overlap in halves; unequal ones by the
    /// intersection circle's cap heights, which add up to δ.
    #[test]
    fn loading_splits_by_the_intersection_plane() {
        let flat = Flat {
            max_overlap: 0.1,
            plastic: [0.0; 2],
        };
        assert!((flat.force_side(0.1, 1.0, 1.0, 0.0) - 0.05).abs() < 1e-16);
        let (ri, rj) = (1.0, 2.0);
        let hi = flat.force_side(0.1, ri, rj, 0.0);
        let hj = flat.force_side(0.1, rj, ri, 0.0);
        assert!((hi + hj - 0.1).abs() < 1e-15);
        // The intersection circle: R_i² − (R_i − h_i)² = R_j² − (R_j − h_j)².
        let (ci, cj) = (ri * ri - (ri - hi).powi(2), rj * rj - (rj - hj).powi(2));
        assert!((ci - cj).abs() < 1e-14, "{ci} {cj}");
        let [d0, d1] = flat.displacement_sides(0.1, ri, rj);
        assert!((d0 - hi).abs() < 1e-15 && (d1 - hj).abs() < 1e-15);
    }
}
