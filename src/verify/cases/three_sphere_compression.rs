//! Three NiAl spheres in a line, R = 10, 2, 10 µm, the outer two driven towards the
//! middle one (Rojek 2016 §4, Fig 8b, Fig 11): the overlap of a small contact when
//! its force reaches 0.02 N, for Hertz and Storåkers m = 0, 0.1, 0.2. The middle
//! sphere is held still: driven symmetrically it would stay put anyway, and holding
//! it lets the step follow the stiff small contact without resolving its
//! oscillation. Reference: eq 2 (Hertz) or eq 16 (Storåkers) with
//! R* = 10·2/12 µm, inverted at 0.02 N. The paper reads 0.4–0.5 µm for Storåkers.
//! The overlap is read from the recorded run, between the consecutive steps where the
//! force on the outer sphere first reaches 0.02 N.

use super::rojek_models::{MODELS, material_constants, overlap_at_force, with_model};
use super::two_body::compression_past;
use crate::error::Result;
use crate::material::effective_radius;
use crate::verify::{CaseContext, Measured, measure};

const FORCE: f64 = 0.02;

/// Steps between recorded frames before the crossing (about a hundred per run).
const EVERY: u64 = 10_000;

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    let (e, nu, yield_stress) = material_constants(&base)?;
    let r_eff = effective_radius(base.particles[0].radius, base.particles[1].radius);
    let mut out = Vec::new();
    for (name, exponent) in MODELS {
        let reference = overlap_at_force(FORCE, r_eff, e, nu, yield_stress, exponent);
        let (scene, spec) = compression_past(&with_model(&base, exponent), reference, EVERY)?;
        let rec = ctx.record(name, &scene, spec)?;
        let h = measure::overlap_where_force_reaches(&rec, 0, 1, FORCE)?;
        out.push(Measured::new(
            &format!("small_contact_overlap_at_0.02N_{name}"),
            h,
            reference,
        ));
    }
    Ok(out)
}
