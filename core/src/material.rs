//! Materials and their pair (effective) properties, mixed once into a table.
//!
//! Effective modulus (Rojek 2016 eq 3, Zhong 2009 eq 12):
//!   1/E* = (1 − ν_i²)/E_i + (1 − ν_j²)/E_j
//! Effective shear modulus (Rojek 2016 eq 13, with G = E / (2(1 + ν))):
//!   1/G* = (2 − ν_i)/G_i + (2 − ν_j)/G_j
//! A rigid material (a wall's only) has zero compliance: its term in both sums is 0, so
//! against a rigid wall E* = E_i/(1 − ν_i²) and G* = G_i/(2 − ν_i). Two rigid bodies
//! never touch (walls meet particles only), so their pair has no modulus.
//! Effective radius (Rojek eq 4): 1/R* = 1/R_i + 1/R_j; a plane wall has R = ∞.
//! Effective mass: m* = m_i m_j / (m_i + m_j); a wall or an immovable body has m = ∞.
//! Effective Hollomon constant (Rojek eq 18): (σ0*)^{−1/m} = (σ0_i)^{−1/m} + (σ0_j)^{−1/m};
//! a partner without Hollomon constants (a rigid wall) does not yield, so σ0* = σ0_i.

/// One material of the scene, referred to by index from particles and walls: its
/// density, elastic constants and, for the plastic laws, its hardening curve.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// The material's name in the scene file.
    pub name: String,
    /// kg/m³; `None` for a rigid material, which no particle may use.
    pub density: Option<f64>,
    /// Infinitely stiff (zero compliance); validation gives it no elastic constants.
    pub rigid: bool,
    /// Young's modulus E, Pa; `None` for a rigid material, or when no law needs it.
    pub youngs_modulus: Option<f64>,
    /// Poisson's ratio ν, dimensionless, in (−1, 0.5); `None` like `youngs_modulus`.
    pub poisson_ratio: Option<f64>,
    /// Rigid-plastic hardening curve σ = σ0 ε^m (Rojek eq 15); needed by Storåkers.
    pub hollomon: Option<Hollomon>,
}

/// Hollomon stress–strain curve σ = σ0 ε^m (Rojek 2016 eq 15).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hollomon {
    /// σ0, Pa.
    pub strength: f64,
    /// m, the hardening exponent (0 = perfectly plastic).
    pub exponent: f64,
}

impl Hollomon {
    /// The curve through the elastic yield point (σ_Y/E, σ_Y), as Rojek §4 chooses
    /// its constants: σ0 = σ_Y (σ_Y/E)^{−m} = σ_Y^{1−m} E^m.
    pub fn through_yield_point(yield_stress: f64, youngs_modulus: f64, exponent: f64) -> Self {
        Hollomon {
            strength: yield_stress * (youngs_modulus / yield_stress).powf(exponent),
            exponent,
        }
    }
}

/// Rojek eq 18 for two materials with the same exponent m, evaluated in logarithms so
/// that small m does not overflow: ln σ0* = min ln σ0 − m ln(1 + e^{−|Δ ln σ0|/m}).
/// At m = 0 this is the limit, the smaller σ0.
pub fn effective_hollomon(a: Option<Hollomon>, b: Option<Hollomon>) -> Option<Hollomon> {
    match (a, b) {
        (Some(a), Some(b)) => {
            let m = a.exponent;
            let (la, lb) = (a.strength.ln(), b.strength.ln());
            let tail = if m > 0.0 {
                m * (-(la - lb).abs() / m).exp().ln_1p()
            } else {
                0.0
            };
            Some(Hollomon {
                strength: (la.min(lb) - tail).exp(),
                exponent: m,
            })
        }
        (Some(h), None) | (None, Some(h)) => Some(h),
        (None, None) => None,
    }
}

impl Material {
    /// The density of a particle's material; validation refuses a rigid material (the
    /// only one without a density) for particles.
    pub fn particle_density(&self) -> f64 {
        self.density
            .expect("validated: particle materials are not rigid and have a density")
    }

    /// Shear modulus G = E / (2(1 + ν)), Pa; `None` without both elastic constants.
    pub fn shear_modulus(&self) -> Option<f64> {
        Some(self.youngs_modulus? / (2.0 * (1.0 + self.poisson_ratio?)))
    }
}

/// Properties of one material pair, computed once when the simulation is built.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PairProperties {
    /// E* (Pa); `None` when either material has no elastic constants (linear laws need none).
    pub effective_modulus: Option<f64>,
    /// G* (Pa) of the pair, read by the Mindlin-type tangential laws; `None` like
    /// `effective_modulus`.
    pub effective_shear_modulus: Option<f64>,
    /// σ0* and m (Rojek eq 18); `None` unless a material of the pair has Hollomon constants.
    pub hollomon: Option<Hollomon>,
    /// What the scene's normal law derives from this pair once, when the scene is
    /// built, rather than at every contact (`NormalModel::pair_constant`: Storåkers'
    /// plastic factor); `None` for a law that derives nothing, or before the build.
    pub law_constant: Option<f64>,
    /// Coulomb friction coefficient μ of this pair.
    pub friction: f64,
}

/// 1/E* as the sum of the two compliance terms; `None` when a term is missing or both
/// bodies are rigid (they never touch).
fn mix(a: Option<f64>, b: Option<f64>) -> Option<f64> {
    let sum = a? + b?;
    (sum > 0.0).then(|| 1.0 / sum)
}

/// Effective modulus E* of a material pair, Pa (the 1/E* sum of the module header);
/// `None` when a non-rigid material lacks E or ν, or when both are rigid.
pub fn effective_modulus(a: &Material, b: &Material) -> Option<f64> {
    let term = |m: &Material| match m.rigid {
        true => Some(0.0),
        false => Some((1.0 - m.poisson_ratio?.powi(2)) / m.youngs_modulus?),
    };
    mix(term(a), term(b))
}

/// Effective shear modulus G* of a material pair, Pa (the 1/G* sum of the module
/// header); `None` in the same cases as [`effective_modulus`].
pub fn effective_shear_modulus(a: &Material, b: &Material) -> Option<f64> {
    let term = |m: &Material| match m.rigid {
        true => Some(0.0),
        false => Some((2.0 - m.poisson_ratio?) / m.shear_modulus()?),
    };
    mix(term(a), term(b))
}

/// Effective radius R* = R_i R_j / (R_i + R_j) of two spheres, m. Both radii must be
/// finite: against a plane wall (R = ∞) the limit is the particle's own radius, which
/// callers take directly.
pub fn effective_radius(r_i: f64, r_j: f64) -> f64 {
    r_i * r_j / (r_i + r_j)
}

/// Effective mass m* = m_i m_j / (m_i + m_j) of two bodies, kg. Both masses must be
/// finite: against a wall or a prescribed particle (m = ∞) the limit is the other
/// body's mass, which callers take directly.
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
    /// Mix every ordered pair of `materials` once; `friction(a, b)` gives the pair's μ.
    pub fn new(materials: &[Material], friction: impl Fn(usize, usize) -> f64) -> Self {
        let n = materials.len();
        let mut entries = Vec::with_capacity(n * n);
        for a in 0..n {
            for b in 0..n {
                let hollomon = effective_hollomon(materials[a].hollomon, materials[b].hollomon);
                entries.push(PairProperties {
                    effective_modulus: effective_modulus(&materials[a], &materials[b]),
                    effective_shear_modulus: effective_shear_modulus(&materials[a], &materials[b]),
                    hollomon,
                    law_constant: None,
                    friction: friction(a, b),
                });
            }
        }
        PairTable { n, entries }
    }

    /// Every pair's properties, to be completed by what a law derives from them.
    pub fn pairs_mut(&mut self) -> impl Iterator<Item = &mut PairProperties> {
        self.entries.iter_mut()
    }

    /// Properties of the pair of materials with indices `a` and `b`.
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
            density: Some(7800.0),
            rigid: false,
            youngs_modulus: Some(2e11),
            poisson_ratio: Some(0.3),
            hollomon: None,
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
    fn equal_hollomon_materials_mix_to_two_to_minus_m() {
        for m in [0.0, 0.05, 0.1, 0.2] {
            let h = Hollomon {
                strength: 1e9,
                exponent: m,
            };
            let mixed = effective_hollomon(Some(h), Some(h)).unwrap();
            approx::assert_relative_eq!(mixed.strength, 1e9 * 2f64.powf(-m), max_relative = 1e-13);
        }
    }

    #[test]
    fn unequal_hollomon_mixing_matches_eq18_directly() {
        let (a, b) = (
            Hollomon {
                strength: 8e8,
                exponent: 0.2,
            },
            Hollomon {
                strength: 2.4e9,
                exponent: 0.2,
            },
        );
        let direct = (8e8f64.powf(-5.0) + 2.4e9f64.powf(-5.0)).powf(-0.2);
        let mixed = effective_hollomon(Some(a), Some(b)).unwrap();
        approx::assert_relative_eq!(mixed.strength, direct, max_relative = 1e-13);
        assert_eq!(effective_hollomon(Some(a), None), Some(a));
    }

    #[test]
    fn hollomon_through_yield_point_recovers_sigma_y_at_yield_strain() {
        let h = Hollomon::through_yield_point(800e6, 183e9, 0.1);
        approx::assert_relative_eq!(
            h.strength * (800e6f64 / 183e9).powf(0.1),
            800e6,
            max_relative = 1e-14
        );
    }

    #[test]
    fn a_rigid_partner_leaves_the_particle_term_alone() {
        let wall = Material {
            name: "w".into(),
            density: None,
            rigid: true,
            youngs_modulus: None,
            poisson_ratio: None,
            hollomon: None,
        };
        let e = effective_modulus(&steel(), &wall).unwrap();
        assert_eq!(e, 1.0 / ((1.0 - 0.09) / 2e11));
        let g = effective_shear_modulus(&wall, &steel()).unwrap();
        assert_eq!(g, 1.0 / ((2.0 - 0.3) / (2e11 / 2.6)));
        assert!(effective_modulus(&wall, &wall).is_none());
    }

    #[test]
    fn missing_elastic_constants_give_none() {
        let mut m = steel();
        m.youngs_modulus = None;
        assert!(effective_modulus(&m, &steel()).is_none());
    }
}
