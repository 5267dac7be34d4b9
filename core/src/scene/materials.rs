//! The `materials` of a scene: each is a name, a density and the elastic and
//! hardening constants the contact laws ask for, or `rigid` for a wall that does not
//! deform.
//!
//! ```json
//! {"name": "nial", "density": 5910, "youngs_modulus": 183e9, "poisson_ratio": 0.318,
//!  "hollomon": {"exponent": 0.2, "yield_stress": 800e6}}
//! ```

use crate::error::Errors;
use crate::material::{Hollomon, Material};
use serde::{Deserialize, Serialize};
use std::collections::HashSet;

/// One material of the scene file; particles and walls name it.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSpec {
    /// The name particles and walls refer to it by; unique in the scene.
    pub name: String,
    /// kg/m³; required unless `rigid`.
    #[serde(default)]
    pub density: Option<f64>,
    /// A wall material that does not deform: no density or elastic constants, and a
    /// zero compliance term in E* and G* (docs/scene-format.md). Walls only.
    #[serde(default)]
    pub rigid: bool,
    /// Pa; required by elastic laws (hertz) unless `rigid`.
    #[serde(default)]
    pub youngs_modulus: Option<f64>,
    /// Poisson's ratio ν, in (−1, 0.5); required by elastic laws unless `rigid`.
    #[serde(default)]
    pub poisson_ratio: Option<f64>,
    /// Hollomon hardening σ = σ0 ε^m (Rojek eq 15); required by the Storåkers law.
    #[serde(default)]
    pub hollomon: Option<HollomonSpec>,
}

/// Give `exponent` and exactly one of `strength` (σ0, Pa) or `yield_stress` (σ_Y,
/// Pa: the curve then passes through (σ_Y/E, σ_Y), as in Rojek §4).
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct HollomonSpec {
    /// The hardening exponent m, in [0, 1).
    pub exponent: f64,
    /// σ0, Pa.
    #[serde(default)]
    pub strength: Option<f64>,
    /// σ_Y, Pa.
    #[serde(default)]
    pub yield_stress: Option<f64>,
}

/// The names the rest of the scene may refer to, and which of them are rigid.
pub struct MaterialNames<'a> {
    names: HashSet<&'a str>,
    rigid: HashSet<&'a str>,
}

impl MaterialNames<'_> {
    /// Whether a material of this name exists.
    pub fn known(&self, name: &str) -> bool {
        self.names.contains(name)
    }

    /// What a particle's material must be: known, and not rigid (a rigid body has no
    /// mass to integrate).
    pub fn check_particle_material(&self, e: &mut Errors, path: String, name: &str) {
        if !self.known(name) {
            e.push(path, format!("unknown material '{name}'"));
        } else if self.rigid.contains(name) {
            e.push(
                path,
                format!("'{name}' is rigid: only walls may be made of a rigid material"),
            );
        }
    }
}

/// Names unique, a density unless rigid, nothing a rigid material would ignore, and
/// the elastic constants in range where given.
pub fn validate<'a>(materials: &'a [MaterialSpec], e: &mut Errors) -> MaterialNames<'a> {
    if materials.is_empty() {
        e.push("materials", "must list at least one material");
    }
    let mut names = HashSet::new();
    for (k, m) in materials.iter().enumerate() {
        if !names.insert(m.name.as_str()) {
            e.push(
                format!("materials[{k}].name"),
                format!("must be unique, '{}' is repeated", m.name),
            );
        }
        if m.rigid {
            // Refused rather than ignored: a value given but never used would mislead.
            for (field, given) in [
                ("density", m.density.is_some()),
                ("youngs_modulus", m.youngs_modulus.is_some()),
                ("poisson_ratio", m.poisson_ratio.is_some()),
                ("hollomon", m.hollomon.is_some()),
            ] {
                if given {
                    e.push(
                        format!("materials[{k}].{field}"),
                        "must be absent for a rigid material: it does not deform or move, so the value would never be used",
                    );
                }
            }
        } else {
            match m.density {
                Some(d) => e.positive(format!("materials[{k}].density"), d),
                None => e.push(
                    format!("materials[{k}].density"),
                    "is required (kg/m³) unless the material is \"rigid\": true",
                ),
            }
        }
        if let Some(y) = m.youngs_modulus {
            e.positive(format!("materials[{k}].youngs_modulus"), y);
        }
        if let Some(nu) = m.poisson_ratio
            && !(nu > -1.0 && nu < 0.5)
        {
            e.push(
                format!("materials[{k}].poisson_ratio"),
                format!("must be > -1 and < 0.5, got {nu}"),
            );
        }
    }
    let rigid = materials
        .iter()
        .filter(|m| m.rigid)
        .map(|m| m.name.as_str())
        .collect();
    MaterialNames { names, rigid }
}

/// The Hollomon blocks: m in [0, 1) and exactly one of σ0 or σ_Y (with E for σ_Y).
/// Listed after the contact law's rules, as they always were.
pub fn validate_hardening(materials: &[MaterialSpec], e: &mut Errors) {
    for (k, m) in materials.iter().enumerate() {
        let Some(h) = &m.hollomon else { continue };
        let path = format!("materials[{k}].hollomon");
        if !(h.exponent >= 0.0 && h.exponent < 1.0) {
            e.push(
                format!("{path}.exponent"),
                format!("must be in [0, 1), got {}", h.exponent),
            );
        }
        match (h.strength, h.yield_stress) {
            (Some(s), None) => e.positive(format!("{path}.strength"), s),
            (None, Some(y)) => {
                e.positive(format!("{path}.yield_stress"), y);
                if m.youngs_modulus.is_none() {
                    e.push(
                        format!("materials[{k}].youngs_modulus"),
                        "is required by hollomon.yield_stress (the curve passes through (σ_Y/E, σ_Y))",
                    );
                }
            }
            _ => e.push(
                path,
                "give exactly one of 'strength' (σ0, Pa) or 'yield_stress' (σ_Y, Pa)",
            ),
        }
    }
}

/// The material table of the simulation, in the scene's order (a material's index is
/// its place in the file).
pub fn build(materials: &[MaterialSpec]) -> Vec<Material> {
    materials
        .iter()
        .map(|m| Material {
            name: m.name.clone(),
            density: m.density,
            rigid: m.rigid,
            youngs_modulus: m.youngs_modulus,
            poisson_ratio: m.poisson_ratio,
            hollomon: m.hollomon.as_ref().map(|h| match h.strength {
                Some(strength) => Hollomon {
                    strength,
                    exponent: h.exponent,
                },
                None => Hollomon::through_yield_point(
                    h.yield_stress.unwrap_or(0.0),
                    m.youngs_modulus.unwrap_or(0.0),
                    h.exponent,
                ),
            }),
        })
        .collect()
}
