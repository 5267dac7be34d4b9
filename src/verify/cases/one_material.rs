//! The one material of a scene whose spheres and walls are all made of it, as the
//! references of several cases take it from the scene's inputs: its density and the
//! effective modulus of a contact between two bodies of it,
//! 1/E* = (1 − ν²)/E + (1 − ν²)/E (Rojek 2016 eq 3).

use crate::error::{Result, TampError};
use crate::scene::Scene;

pub(super) struct OneMaterial {
    /// ρ, kg/m³.
    pub density: f64,
    /// E*, Pa.
    pub effective_modulus: f64,
}

pub(super) fn of(scene: &Scene) -> Result<OneMaterial> {
    let [material] = scene.materials.as_slice() else {
        return Err(TampError::Other(
            "the scene must have one material, the spheres' and the walls'".into(),
        ));
    };
    let (Some(density), Some(e), Some(nu)) = (
        material.density,
        material.youngs_modulus,
        material.poisson_ratio,
    ) else {
        return Err(TampError::Other(
            "the material must give a density, E and nu".into(),
        ));
    };
    let compliance = (1.0 - nu * nu) / e;
    Ok(OneMaterial {
        density,
        effective_modulus: 1.0 / (compliance + compliance),
    })
}
