//! Segregation of two species (A and not-A) along the vertical.
//!
//! **Bed extent.** Along the vertical axis k the bed spans [bottom, top], given or by
//! default the particles' own extent: bottom = min(x_k − r), top = max(x_k + r).
//! A particle belongs to whatever its centre lies in; centres outside [bottom, top]
//! (possible with a given extent) are ignored.
//!
//! **Weights.** Each particle weighs w_i = 1 (composition by number) or w_i = r_i³
//! (by volume, i.e. by mass for equal solid densities).
//!
//! **Surface layers.** The top layer holds the centres with x_k ≥ top − t, the bottom
//! layer those with x_k ≤ bottom + t; each reports the weighted fraction of A.
//!
//! **Segregation index.** The bed is cut into n horizontal layers of equal thickness.
//! With c_j the weighted fraction of A in layer j, W_j its weight and p the fraction
//! of A in the whole bed,
//!
//!   σ² = Σ_j W_j (c_j − p)² / Σ_j W_j,   σ₀² = p (1 − p),   S = σ / σ₀.
//!
//! σ₀² is the variance when every sample holds one species only (Lacey 1954), so
//! S = 1 for a bed segregated along layer boundaries, and S = 0 when every layer has
//! the bed's composition. S² is Danckwerts' (1952) intensity of segregation. Weighting
//! by W_j makes the mean of c_j exactly p, so the bound S ≤ 1 holds for layers of
//! any size. A random mixture does not give S = 0 but S ≈ 1/√n̄ (n̄ particles per
//! layer), the sampling noise; Lacey's mixing index corrects for it,
//!
//!   M = (σ₀² − σ²) / (σ₀² − σ_R²),   σ_R² = p (1 − p) / n̄,
//!
//! M = 0 fully segregated, ≈ 1 randomly mixed, > 1 more even than random (an ordered
//! bed). Both are discussed in Rhodes, Introduction to Particle Technology (2nd ed.
//! 2008), in the chapter on mixing and segregation. With volume weights and unequal
//! sizes σ_R² is only approximate (it counts particles, not volumes).

use crate::error::{Result, TampError};
use crate::particles::Vec3;

/// What a composition counts: particles, or solid volume.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Basis {
    /// w_i = 1: fractions by number.
    Number,
    /// w_i = r_i³: fractions by volume (by mass for equal solid densities).
    Volume,
}

/// The bed's vertical extent; `None` takes it from the particles.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BedExtent {
    /// Lowest point of the bed along the vertical, m.
    pub bottom: Option<f64>,
    /// Highest point of the bed along the vertical, m.
    pub top: Option<f64>,
}

/// What one horizontal layer of the bed holds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LayerComposition {
    /// Number of particles whose centre lies in the layer.
    pub particles: usize,
    /// Weighted fraction of species A; `None` for an empty layer.
    pub fraction_a: Option<f64>,
}

/// Composition of the bed's top and bottom layers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceLayers {
    /// Centres within the layer thickness below the top.
    pub top: LayerComposition,
    /// Centres within the layer thickness above the bottom.
    pub bottom: LayerComposition,
}

/// How to measure the segregation index: the vertical axis, the number n of layers,
/// the bed extent and the weighting.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SegregationSpec {
    /// Vertical axis (0, 1 or 2).
    pub axis: usize,
    /// Number n of horizontal layers of equal thickness.
    pub layers: usize,
    /// The bed's vertical extent [bottom, top].
    pub extent: BedExtent,
    /// Weighting of the particles.
    pub basis: Basis,
}

/// Segregation of species A along the vertical: the fraction p of A, the index
/// S = σ/σ₀, Lacey's mixing index M and each layer's composition.
#[derive(Clone, Debug, PartialEq)]
pub struct Segregation {
    /// Fraction of species A in the bed, p.
    pub fraction_a: f64,
    /// S = σ/σ₀: 0 evenly mixed, 1 fully segregated.
    pub index: f64,
    /// Lacey's M: 0 fully segregated, ≈ 1 randomly mixed. `None` when the occupied
    /// layers hold one particle each on average or fewer (n̄ ≤ 1): a random mixture of
    /// one-particle samples is then as uneven as a sorted bed (σ_R² = σ₀²), and M is 0/0.
    pub lacey: Option<f64>,
    /// Layers from bottom to top.
    pub layers: Vec<LayerComposition>,
    /// (bottom, top) used.
    pub extent: (f64, f64),
}

/// Composition of the layers of thickness `thickness` at the top and the bottom.
pub fn surface_layers(
    positions: &[Vec3],
    radii: &[f64],
    is_a: &[bool],
    axis: usize,
    thickness: f64,
    extent: BedExtent,
    basis: Basis,
) -> Result<SurfaceLayers> {
    let (bottom, top) = bed_extent(positions, radii, is_a, axis, extent)?;
    if !(thickness.is_finite() && thickness > 0.0) {
        return Err(TampError::input(
            "thickness",
            format!("must be positive, got {thickness}"),
        ));
    }
    let mut acc = [Acc::default(); 2];
    for i in 0..positions.len() {
        let z = positions[i][axis];
        if z < bottom || z > top {
            continue;
        }
        let w = weight(radii[i], basis);
        if z >= top - thickness {
            acc[0].add(w, is_a[i]);
        }
        if z <= bottom + thickness {
            acc[1].add(w, is_a[i]);
        }
    }
    Ok(SurfaceLayers {
        top: acc[0].composition(),
        bottom: acc[1].composition(),
    })
}

/// Segregation index S and Lacey's index M of species A (`is_a`) over the n layers of
/// `spec`. Errors (naming the field) on mismatched lengths, a bad axis, an empty or
/// inverted extent, zero layers, or a bed lacking one of the two species.
pub fn segregation(
    positions: &[Vec3],
    radii: &[f64],
    is_a: &[bool],
    spec: &SegregationSpec,
) -> Result<Segregation> {
    let (bottom, top) = bed_extent(positions, radii, is_a, spec.axis, spec.extent)?;
    if spec.layers == 0 {
        return Err(TampError::input("layers", "at least one layer is needed"));
    }
    let n = spec.layers;
    let thickness = (top - bottom) / n as f64;
    let mut acc = vec![Acc::default(); n];
    let mut bed = Acc::default();
    for i in 0..positions.len() {
        let z = positions[i][spec.axis];
        if z < bottom || z > top {
            continue;
        }
        // A centre exactly at the top belongs to the top layer.
        let j = (((z - bottom) / thickness) as usize).min(n - 1);
        let w = weight(radii[i], spec.basis);
        acc[j].add(w, is_a[i]);
        bed.add(w, is_a[i]);
    }
    if bed.particles == 0 {
        return Err(TampError::input(
            "extent",
            "no particle centre lies in the bed",
        ));
    }
    let p = bed.weight_a / bed.weight;
    let sigma0_sq = p * (1.0 - p);
    if sigma0_sq <= 0.0 {
        return Err(TampError::input(
            "is_a",
            "both species must be present for a segregation index",
        ));
    }
    let sigma_sq = acc
        .iter()
        .filter(|a| a.particles > 0)
        .map(|a| a.weight * (a.weight_a / a.weight - p).powi(2))
        .sum::<f64>()
        / bed.weight;
    let occupied = acc.iter().filter(|a| a.particles > 0).count();
    let mean_particles = bed.particles as f64 / occupied as f64;
    let sigma_r_sq = sigma0_sq / mean_particles;
    Ok(Segregation {
        fraction_a: p,
        index: (sigma_sq / sigma0_sq).sqrt(),
        lacey: (mean_particles > 1.0).then(|| (sigma0_sq - sigma_sq) / (sigma0_sq - sigma_r_sq)),
        layers: acc.iter().map(Acc::composition).collect(),
        extent: (bottom, top),
    })
}

#[derive(Clone, Copy, Debug, Default)]
struct Acc {
    particles: usize,
    weight: f64,
    weight_a: f64,
}

impl Acc {
    fn add(&mut self, w: f64, a: bool) {
        self.particles += 1;
        self.weight += w;
        if a {
            self.weight_a += w;
        }
    }

    fn composition(&self) -> LayerComposition {
        LayerComposition {
            particles: self.particles,
            fraction_a: (self.particles > 0).then(|| self.weight_a / self.weight),
        }
    }
}

fn weight(r: f64, basis: Basis) -> f64 {
    match basis {
        Basis::Number => 1.0,
        Basis::Volume => r * r * r,
    }
}

fn bed_extent(
    positions: &[Vec3],
    radii: &[f64],
    is_a: &[bool],
    axis: usize,
    extent: BedExtent,
) -> Result<(f64, f64)> {
    let n = positions.len();
    if radii.len() != n || is_a.len() != n {
        return Err(TampError::input(
            "radii",
            format!(
                "one radius and one species flag per position expected, got {} and {} for {n}",
                radii.len(),
                is_a.len()
            ),
        ));
    }
    if axis > 2 {
        return Err(TampError::input(
            "axis",
            format!("must be 0, 1 or 2, got {axis}"),
        ));
    }
    let bottom = extent.bottom.unwrap_or_else(|| {
        positions
            .iter()
            .zip(radii)
            .map(|(x, r)| x[axis] - r)
            .fold(f64::INFINITY, f64::min)
    });
    let top = extent.top.unwrap_or_else(|| {
        positions
            .iter()
            .zip(radii)
            .map(|(x, r)| x[axis] + r)
            .fold(f64::NEG_INFINITY, f64::max)
    });
    if !(bottom.is_finite() && top.is_finite() && top > bottom) {
        return Err(TampError::input(
            "extent",
            format!("the bed needs a finite bottom < top, got [{bottom}, {top}]"),
        ));
    }
    Ok((bottom, top))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// A cubic stack of 10 × 10 sites in each of 8 layers of spacing 1; `species`
    /// decides A per site (i, j, layer).
    fn stack(species: impl Fn(usize, usize, usize) -> bool) -> (Vec<Vec3>, Vec<f64>, Vec<bool>) {
        let mut x = Vec::new();
        let mut a = Vec::new();
        for k in 0..8 {
            for i in 0..10 {
                for j in 0..10 {
                    x.push(Vec3::new(i as f64, j as f64, k as f64 + 0.5));
                    a.push(species(i, j, k));
                }
            }
        }
        let r = vec![0.5; x.len()];
        (x, r, a)
    }

    fn spec(layers: usize, basis: Basis) -> SegregationSpec {
        SegregationSpec {
            axis: 2,
            layers,
            extent: BedExtent::default(),
            basis,
        }
    }

    #[test]
    fn fully_segregated_bed_scores_one() {
        // A below, B above, three quarters A: the interface falls on a layer
        // boundary for 4 and 8 layers.
        let (x, r, a) = stack(|_, _, k| k < 6);
        for layers in [4, 8] {
            let s = segregation(&x, &r, &a, &spec(layers, Basis::Number)).unwrap();
            assert!((s.fraction_a - 0.75).abs() < 1e-15);
            assert!((s.index - 1.0).abs() < 1e-15, "{layers}: {}", s.index);
            assert!(s.lacey.unwrap().abs() < 1e-15);
        }
        // Three layers straddle the interface: less than full segregation is seen.
        let coarse = segregation(&x, &r, &a, &spec(3, Basis::Number)).unwrap();
        assert!(coarse.index < 1.0 && coarse.index > 0.5);
        let surface = surface_layers(&x, &r, &a, 2, 1.0, BedExtent::default(), Basis::Number);
        let surface = surface.unwrap();
        assert_eq!(surface.top.fraction_a, Some(0.0));
        assert_eq!(surface.bottom.fraction_a, Some(1.0));
        assert_eq!(surface.top.particles, 100);
    }

    /// One particle per layer: S is defined (every layer is pure, S = 1), Lacey's M is
    /// not (σ_R² = σ₀²), and it is reported as absent rather than as 0/0.
    #[test]
    fn one_particle_per_layer_has_no_lacey_index() {
        let x: Vec<Vec3> = (0..4)
            .map(|k| Vec3::new(0.0, 0.0, k as f64 + 0.5))
            .collect();
        let r = vec![0.5; 4];
        let a = vec![true, false, true, false];
        let s = segregation(&x, &r, &a, &spec(4, Basis::Number)).unwrap();
        assert!((s.index - 1.0).abs() < 1e-15, "{}", s.index);
        assert_eq!(s.lacey, None);
    }

    #[test]
    fn evenly_mixed_bed_scores_zero() {
        let (x, r, a) = stack(|i, j, _| (i + j) % 2 == 0);
        let s = segregation(&x, &r, &a, &spec(8, Basis::Number)).unwrap();
        assert_eq!(s.index, 0.0);
        // More even than a random mixture.
        assert!(s.lacey.unwrap() > 1.0);
        let surface =
            surface_layers(&x, &r, &a, 2, 1.0, BedExtent::default(), Basis::Number).unwrap();
        assert_eq!(surface.top.fraction_a, Some(0.5));
    }

    /// A random mixture: S is the sampling noise 1/√n̄ (here n̄ = 2500, so ≈ 0.02)
    /// and Lacey's M ≈ 1.
    #[test]
    fn random_mixture_scores_noise_only() {
        let mut rng = ChaCha8Rng::seed_from_u64(11);
        let n = 20_000;
        let x: Vec<Vec3> = (0..n)
            .map(|_| Vec3::new(0.0, 0.0, rng.random_range(0.0..1.0)))
            .collect();
        let a: Vec<bool> = (0..n).map(|_| rng.random_range(0.0..1.0) < 0.3).collect();
        let r = vec![1e-3; n];
        let s = segregation(&x, &r, &a, &spec(8, Basis::Number)).unwrap();
        assert!(s.index < 3.0 / 2500f64.sqrt(), "{}", s.index);
        let lacey = s.lacey.unwrap();
        assert!((lacey - 1.0).abs() < 0.01, "{lacey}");
    }

    /// By volume: big A particles on top of many small B particles. By number the
    /// bed is mostly B; by volume the two halves weigh the same.
    #[test]
    fn volume_basis_weighs_by_size() {
        let mut x = Vec::new();
        let mut r = Vec::new();
        let mut a = Vec::new();
        for i in 0..8 {
            for j in 0..8 {
                for k in 0..4 {
                    x.push(Vec3::new(
                        i as f64 * 0.5,
                        j as f64 * 0.5,
                        0.25 + k as f64 * 0.5,
                    ));
                    r.push(0.25);
                    a.push(false);
                }
            }
        }
        for i in 0..4 {
            for j in 0..4 {
                for k in 0..2 {
                    x.push(Vec3::new(i as f64, j as f64, 2.5 + k as f64));
                    r.push(0.5);
                    a.push(true);
                }
            }
        }
        let s = segregation(&x, &r, &a, &spec(4, Basis::Volume)).unwrap();
        assert!((s.fraction_a - 0.5).abs() < 1e-15);
        assert!((s.index - 1.0).abs() < 1e-15);
        let by_number = segregation(&x, &r, &a, &spec(4, Basis::Number)).unwrap();
        assert!((by_number.fraction_a - 32.0 / 288.0).abs() < 1e-15);
        assert!((by_number.index - 1.0).abs() < 1e-15);
    }

    #[test]
    fn one_species_has_no_index() {
        let (x, r, _) = stack(|_, _, _| true);
        let a = vec![true; x.len()];
        assert!(segregation(&x, &r, &a, &spec(4, Basis::Number)).is_err());
    }
}
