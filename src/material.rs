//! Materials and their pair (effective) properties, mixed once into a table.
//!
//! Effective modulus (Rojek 2016 eq 3, Zhong 2009 eq 12):
//!   1/E* = (1 − ν_i²)/E_i + (1 − ν_j²)/E_j
//! Effective shear modulus (Rojek 2016 eq 13, with G = E / (2(1 + ν))):
//!   1/G* = (2 − ν_i)/G_i + (2 − ν_j)/G_j
//! Effective radius (Rojek eq 4): 1/R* = 1/R_i + 1/R_j; a plane wall has R = ∞.
//! Effective mass: m* = m_i m_j / (m_i + m_j); a wall or an immovable body has m = ∞.

#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub name: String,
    pub density: f64,
    pub youngs_modulus: Option<f64>,
    pub poisson_ratio: Option<f64>,
}

impl Material {
    pub fn shear_modulus(&self) -> Option<f64> {
        Some(self.youngs_modulus? / (2.0 * (1.0 + self.poisson_ratio?)))
    }
}

/// Properties of one material pair, computed once when the simulation is built.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PairProperties {
    /// E* (Pa); `None` when either material has no elastic constants (linear laws need none).
    pub effective_modulus: Option<f64>,
    pub effective_shear_modulus: Option<f64>,
    /// Coulomb friction coefficient μ of this pair.
    pub friction: f64,
}

pub fn effective_modulus(a: &Material, b: &Material) -> Option<f64> {
    let term = |m: &Material| Some((1.0 - m.poisson_ratio?.powi(2)) / m.youngs_modulus?);
    Some(1.0 / (term(a)? + term(b)?))
}

pub fn effective_shear_modulus(a: &Material, b: &Material) -> Option<f64> {
    let term = |m: &Material| Some((2.0 - m.poisson_ratio?) / m.shear_modulus()?);
    Some(1.0 / (term(a)? + term(b)?))
}

pub fn effective_radius(r_i: f64, r_j: f64) -> f64 {
    r_i * r_j / (r_i + r_j)
}

pub fn effective_mass(m_i: f64, m_j: f64) -> f64 {
    m_i * m_j / (m_i + m_j)
}

/// Symmetric table of pair properties indexed by material ids.
#[derive(Clone, Debug)]
pub struct PairTable {
    n: usize,
    entries: Vec<PairProperties>,
}

impl PairTable {
    pub fn new(materials: &[Material], friction: impl Fn(usize, usize) -> f64) -> Self {
        let n = materials.len();
        let mut entries = Vec::with_capacity(n * n);
        for a in 0..n {
            for b in 0..n {
                entries.push(PairProperties {
                    effective_modulus: effective_modulus(&materials[a], &materials[b]),
                    effective_shear_modulus: effective_shear_modulus(&materials[a], &materials[b]),
                    friction: friction(a, b),
                });
            }
        }
        PairTable { n, entries }
    }

    #[inline]
    pub fn get(&self, a: usize, b: usize) -> &PairProperties {
        &self.entries[a * self.n + b]
    }
}

/// Hertz force at the onset of yield for two equal spheres of radius `radius`
/// (Rojek 2016 eq 30, von Mises criterion):
///   F_Y = 1.61³ π³ R² (1 − ν²)² σ_Y³ / (6 E²)
pub fn hertz_yield_onset_force(
    radius: f64,
    youngs_modulus: f64,
    poisson_ratio: f64,
    yield_stress: f64,
) -> f64 {
    let pi = std::f64::consts::PI;
    1.61f64.powi(3)
        * pi.powi(3)
        * radius.powi(2)
        * (1.0 - poisson_ratio.powi(2)).powi(2)
        * yield_stress.powi(3)
        / (6.0 * youngs_modulus.powi(2))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn steel() -> Material {
        Material {
            name: "s".into(),
            density: 7800.0,
            youngs_modulus: Some(2e11),
            poisson_ratio: Some(0.3),
        }
    }

    #[test]
    fn equal_materials_mix_to_half_plane_strain_modulus() {
        let e = effective_modulus(&steel(), &steel()).unwrap();
        approx::assert_relative_eq!(e, 2e11 / (2.0 * (1.0 - 0.09)), max_relative = 1e-14);
    }

    #[test]
    fn shear_mixing_matches_rojek_eq13() {
        let g = 2e11 / 2.6;
        let gs = effective_shear_modulus(&steel(), &steel()).unwrap();
        approx::assert_relative_eq!(gs, g / (2.0 * 1.7), max_relative = 1e-14);
    }

    #[test]
    fn missing_elastic_constants_give_none() {
        let mut m = steel();
        m.youngs_modulus = None;
        assert!(effective_modulus(&m, &steel()).is_none());
    }
}
