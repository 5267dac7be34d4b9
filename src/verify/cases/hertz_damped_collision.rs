//! Two steel spheres meet head-on under Hertz with the dashpot ξ · 2√(m* k_n) (Tsuji et
//! al. 1992's form), ξ set from a restitution e by LIGGGHTS's relation
//! ξ = −√(5/6) ln e/√(ln²e + π²) (`liggghts_restitution`; LIGGGHTS `model hertz`,
//! LAMMPS `damping coeff_restitution`). The damped Hertz impact has no closed form, so
//! the reference is its equation of motion m* δ'' = −K δ^{3/2} − η(δ) δ', made
//! dimensionless with δ_s = (m* v²/K)^{2/5} and solved by classical Runge–Kutta
//! (`accuracy::damped_hertz`, converged far below these tolerances): restitution,
//! contact duration and largest overlap, for each e of the case file's parameters.
//! Measured from the recorded trajectory, so every engine with this dashpot is held
//! to the same equation.

use super::two_body::{collision_quantities, each_hertz_impact};
use crate::accuracy::damped_hertz::unit_impact;
use crate::error::Result;
use crate::verify::{CaseContext, Measured};

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    Ok(each_hertz_impact(ctx, &base, unit_impact)?
        .iter()
        .flat_map(|i| {
            collision_quantities(
                &format!("_e{}", i.e),
                &i.measured,
                i.restitution,
                i.duration,
                i.max_overlap,
            )
        })
        .collect())
}
