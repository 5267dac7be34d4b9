//! The four contact models of Rojek 2016 §4 applied to one scene: Hertz, and
//! Storåkers with the Hollomon exponents m = 0, 0.1, 0.2, each curve through the
//! yield point (σ_Y/E, σ_Y) of the scene's material (Table 2: σ_Y = 800 MPa), and
//! the closed forms the compression cases compare against, written out from the
//! papers' equations independently of `crate::contact`.

use crate::contact::normal::{NormalLaw, Storakers};
use crate::error::{Result, TampError};
use crate::scene::schema::{HollomonSpec, Scene};

/// (quantity suffix, Hollomon exponent; `None` = Hertz).
pub const MODELS: [(&str, Option<f64>); 4] = [
    ("hertz", None),
    ("storakers_m0", Some(0.0)),
    ("storakers_m0.1", Some(0.1)),
    ("storakers_m0.2", Some(0.2)),
];

/// The scene with its normal law replaced by the model; every material keeps its
/// yield stress and takes the exponent.
pub fn with_model(base: &Scene, exponent: Option<f64>) -> Scene {
    let mut s = base.clone();
    if let Some(m) = exponent {
        s.contact.normal = NormalLaw::Storakers(Storakers {
            min_with_hertz: false,
        });
        for mat in &mut s.materials {
            if let Some(h) = &mat.hollomon {
                mat.hollomon = Some(HollomonSpec {
                    exponent: m,
                    ..h.clone()
                });
            }
        }
    }
    s
}

/// (E, ν, σ_Y) of the scene's first material, which must give `hollomon.yield_stress`.
pub fn material_constants(scene: &Scene) -> Result<(f64, f64, f64)> {
    let mat = &scene.materials[0];
    let yield_stress = mat
        .hollomon
        .as_ref()
        .and_then(|h| h.yield_stress)
        .ok_or_else(|| TampError::Other("the material needs hollomon.yield_stress".into()))?;
    Ok((
        mat.youngs_modulus.unwrap_or(0.0),
        mat.poisson_ratio.unwrap_or(0.0),
        yield_stress,
    ))
}

/// E* of two spheres of one material (Rojek eq 3).
pub fn equal_effective_modulus(e: f64, nu: f64) -> f64 {
    e / (2.0 * (1.0 - nu * nu))
}

/// Hollomon σ0 through (σ_Y/E, σ_Y): σ0 = σ_Y^{1−m} E^m.
pub fn sigma0(yield_stress: f64, e: f64, m: f64) -> f64 {
    yield_stress.powf(1.0 - m) * e.powf(m)
}

/// Overlap at contact force `force` between two spheres of one material with
/// effective radius `r_eff`: Hertz (Rojek eq 2) or Storåkers (eqs 16–18 with
/// σ0* = 2^{−m} σ0 for equal materials).
pub fn overlap_at_force(
    force: f64,
    r_eff: f64,
    e: f64,
    nu: f64,
    yield_stress: f64,
    exponent: Option<f64>,
) -> f64 {
    match exponent {
        None => {
            let k = 4.0 / 3.0 * equal_effective_modulus(e, nu) * r_eff.sqrt();
            (force / k).powf(2.0 / 3.0)
        }
        Some(m) => {
            let c = 2f64.powf(1.0 - m / 2.0)
                * 3f64.powf(1.0 - m)
                * std::f64::consts::PI
                * 1.43
                * (-0.97 * m).exp()
                * 2f64.powf(-m)
                * sigma0(yield_stress, e, m)
                * r_eff.powf(1.0 - m / 2.0);
            (force / c).powf(1.0 / (1.0 + m / 2.0))
        }
    }
}
