//! The rigid-perfectly plastic contact of two parallel cylinders of unit depth
//! (Redanz & Fleck 2001 §2.1.1), used by the 2D quasi-static network (`quasistatic`).
//!
//! Two cylinders of radii R₁, R₂ whose centres have approached by the overlap u_N
//! flatten over a chord of width (eq 2)
//!
//!   A_c = √(8 u_N R*),   R* = R₁R₂/(R₁ + R₂)  (the `effective_radius`),
//!
//! on which the pressure is the plane-strain Prandtl value 3σ_y, so
//!
//!   F_N = 3σ_y A_c = 3σ_y √(8 u_N R*).
//!
//! The tangent stiffness is the derivative of eq 2:
//!
//!   dF_N/du_N = 3σ_y √(2R*/u_N) = 12 σ_y R*/A_c.
//!
//! The paper's incremental form (eq 3) writes 3σ_y √((R₁+R₂)/(2u_N)), which equals
//! this only for R₁ = R₂ (it has the arithmetic mean (R₁+R₂)/2 where the derivative of
//! eq 2 has 2R*, the harmonic mean); tamp implements the derivative of eq 2 so the
//! incremental and total forms agree (docs/paper-discrepancies.md §23).
//!
//! Unloading (§3.4): below the largest overlap reached, u_max, the contact unloads
//! elastically along a line whose slope is `unloading_factor` (10³ in the paper) times
//! the loading stiffness at u_max; the force never becomes tensile (no cohesion).

/// Plane-strain contact width of two overlapping cylinders, eq 2.
pub fn contact_width(overlap: f64, effective_radius: f64) -> f64 {
    (8.0 * overlap.max(0.0) * effective_radius).sqrt()
}

/// F_N on the loading branch, eq 2 (per unit depth).
pub fn loading_force(overlap: f64, effective_radius: f64, yield_stress: f64) -> f64 {
    3.0 * yield_stress * contact_width(overlap, effective_radius)
}

/// dF_N/du_N on the loading branch (the derivative of eq 2).
pub fn loading_stiffness(overlap: f64, effective_radius: f64, yield_stress: f64) -> f64 {
    3.0 * yield_stress * (2.0 * effective_radius / overlap).sqrt()
}

/// The normal response of a contact that has been loaded to `max_overlap`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlasticCylinderResponse {
    /// Normal force per unit depth F_N, N/m.
    pub force: f64,
    /// Tangent stiffness per unit depth dF_N/du_N, N/m².
    pub stiffness: f64,
    /// The largest overlap after this state (u_max, or u_N when loading further).
    pub max_overlap: f64,
}

/// Force and tangent stiffness at overlap `overlap` given the largest overlap reached
/// so far. `stiffness_floor_overlap` caps the loading stiffness, which is infinite at
/// first touch: the tangent is evaluated at no less than that overlap (the force is
/// always the exact eq 2).
pub fn response(
    overlap: f64,
    max_overlap: f64,
    effective_radius: f64,
    yield_stress: f64,
    unloading_factor: f64,
    stiffness_floor_overlap: f64,
) -> PlasticCylinderResponse {
    let unloading_stiffness = |u_max: f64| {
        unloading_factor
            * loading_stiffness(
                u_max.max(stiffness_floor_overlap),
                effective_radius,
                yield_stress,
            )
    };
    let peak = loading_force(max_overlap, effective_radius, yield_stress);
    if overlap >= max_overlap {
        let force = loading_force(overlap, effective_radius, yield_stress);
        return PlasticCylinderResponse {
            force,
            stiffness: loading_stiffness(
                overlap.max(stiffness_floor_overlap),
                effective_radius,
                yield_stress,
            ),
            max_overlap: overlap,
        };
    }
    let k_unload = unloading_stiffness(max_overlap);
    let force = peak - k_unload * (max_overlap - overlap);
    if force > 0.0 {
        PlasticCylinderResponse {
            force,
            stiffness: k_unload,
            max_overlap,
        }
    } else {
        PlasticCylinderResponse {
            force: 0.0,
            stiffness: 0.0,
            max_overlap,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn stiffness_is_the_derivative_of_the_force() {
        let (r_star, sy) = (0.4, 2.0);
        for u in [1e-6, 1e-4, 1e-2] {
            let h = u * 1e-6;
            let fd =
                (loading_force(u + h, r_star, sy) - loading_force(u - h, r_star, sy)) / (2.0 * h);
            assert_relative_eq!(loading_stiffness(u, r_star, sy), fd, max_relative = 1e-7);
        }
    }

    #[test]
    fn equal_radii_agree_with_the_papers_eq_3() {
        let (r, sy, u) = (1.0_f64, 1.0_f64, 1e-3_f64);
        let paper = 3.0 * sy * ((r + r) / (2.0 * u)).sqrt();
        assert_relative_eq!(
            loading_stiffness(u, 0.5 * r, sy),
            paper,
            max_relative = 1e-15
        );
    }

    #[test]
    fn unloading_is_stiff_linear_and_never_tensile() {
        let (r_star, sy, u_max) = (0.5, 1.0, 1e-2);
        let up = response(u_max, 0.0, r_star, sy, 1e3, 0.0);
        let back = response(u_max - 1e-6, u_max, r_star, sy, 1e3, 0.0);
        assert_relative_eq!(back.stiffness, 1e3 * up.stiffness, max_relative = 1e-15);
        assert_relative_eq!(
            back.force,
            up.force - 1e3 * up.stiffness * 1e-6,
            max_relative = 1e-12
        );
        let gone = response(0.5 * u_max, u_max, r_star, sy, 1e3, 0.0);
        assert_eq!(gone.force, 0.0);
        // Reloading past u_max follows eq 2 again.
        let again = response(2.0 * u_max, u_max, r_star, sy, 1e3, 0.0);
        assert_relative_eq!(again.force, loading_force(2.0 * u_max, r_star, sy));
    }
}
