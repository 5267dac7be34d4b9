//! Where the rigid flat of a pair contact lies: the split of the pair overlap δ into
//! the two sides' overlaps.
//!
//! At the largest pair overlap δ_max the flat is the plane of the two spheres'
//! intersection circle, so side i (radius R_i, partner R_j) has the cap height
//!   δ_geo,i = δ_max (2R_j − δ_max) / (2(R_i + R_j − δ_max)),
//! capped at 0.95 R_i (the remainder goes to the partner). Below δ_max each
//! side's overlap falls linearly from δ_geo,i at δ_max to its plastic set δ_p,i at the
//! pair overlap δ_p,0 + δ_p,1, where both sides' forces vanish:
//!   δ_i = δ_geo,i + (δ_p,i − δ_geo,i)(δ − δ_max)/(δ_p,0 + δ_p,1 − δ_max).
//!
//! LAMMPS writes the split twice: in the force, and in the mean surface displacement of
//! `fix GRANULAR/MDR`, which computes the cap heights with a division where the force
//! multiplies by a reciprocal. tamp keeps both arithmetics. Both cap at 0.95 R in
//! LAMMPS 22 Jul 2025 as it runs (measured: docs/models/mdr.md, "One overlap cap"); a
//! force cap of 0.75 R, which a version of LAMMPS's source has, would make the two
//! splits disagree past 0.75 R, and that difference would enter the mean surface
//! displacement as an increment at every step, even of a pair that does not move.

/// A side's overlap is capped at this fraction of its radius, in the force and in the
/// mean surface displacement.
pub const OVERLAP_LIMIT: f64 = 0.95;

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
        if geo / r_i > OVERLAP_LIMIT {
            geo = r_i * OVERLAP_LIMIT;
        } else if alt / r_j > OVERLAP_LIMIT {
            geo = dmax - r_j * OVERLAP_LIMIT;
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
        if geo0 / r0 > OVERLAP_LIMIT {
            geo0 = r0 * OVERLAP_LIMIT;
            geo1 = dmax - geo0;
        } else if geo1 / r1 > OVERLAP_LIMIT {
            geo1 = r1 * OVERLAP_LIMIT;
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

    /// Past the cap the force's split and the mean surface displacement's agree to
    /// round-off, so a pair that does not move adds no surface displacement: a small
    /// sphere whose share of the overlap would be 0.83 and 1.13 of its radius.
    #[test]
    fn both_splits_cap_alike() {
        for (dmax, small) in [(1.0e-6, 0.833), (1.3e-6, 1.131)] {
            let flat = Flat {
                max_overlap: dmax,
                plastic: [0.0; 2],
            };
            let (r, big) = (1e-6, 3e-6);
            let uncapped = dmax * (2.0 * big - dmax) / (2.0 * (r + big - dmax));
            assert!((uncapped / r - small).abs() < 1e-3);
            let force = [
                flat.force_side(dmax, big, r, 0.0),
                flat.force_side(dmax, r, big, 0.0),
            ];
            let shown = flat.displacement_sides(dmax, big, r);
            for s in 0..2 {
                assert!(
                    (force[s] - shown[s]).abs() < 1e-15 * dmax,
                    "{force:?} {shown:?}"
                );
            }
            assert!((force[1] - uncapped.min(OVERLAP_LIMIT * r)).abs() < 1e-15 * dmax);
        }
    }
}
