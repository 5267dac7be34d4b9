//! MDR's adhesion (γ > 0): tensile springs at the edge of the contact on unloading,
//! Part I's adhesive extension (a JKR-like construction in the reduced 1D problem).
//!
//! With the indenter of height A, width B at depth δ_e and the adhesive contact
//! radius a (kept per side, at most 0.99 a_max):
//!   - case 1, loading (δ = δ_max) or the indenter's own radius a_na ≥ a: no
//!     springs, the non-adhesive force; a := 0.99 a_na;
//!   - otherwise the springs have the critical length l_max = √(2π a γ/E*) and the
//!     indenter's depth at radius a is g(a) = A/2 − (A/B) √(B²/4 − a²):
//!     - case 2, δ_e + l_max − g(a) ≥ 0: F = F_na(g(a)) + 2E*(δ_e − g(a)) a;
//!     - case 3, the springs would stretch past l_max: a shrinks to the root of
//!       δ_e − g(a) + √(2π a γ/E*) = 0 (Newton–Raphson from the stored a, at most 100
//!       iterations, stopping at |f| < 1e-10 or a change of f below 1e-16), and the
//!       contact lets go (a := 0, F = 0) once a falls below the closed-form a_crit
//!       where the root disappears.
//!
//! Constants and the order of operations are LAMMPS's (`MDR_MAX_IT`, `MDR_EPSILON*`).

use super::side::{SideHistory, indenter_force};
use std::f64::consts::{PI, TAU};

// LAMMPS's literals, so that both codes round the same way.
const PI_SQ: f64 = 9.869_604_401_089_358;
const PI_TO_5_3: f64 = 6.738_808_595_698_141;
const CBRT_2: f64 = 1.259_921_049_894_873_2;
const CBRT_HALF_PI: f64 = 1.162_447_351_509_626_5;
const SQRT_HALF_PI: f64 = 1.253_314_137_315_500_1;

/// Newton–Raphson iterations at most.
const MAX_ITERATIONS: usize = 100;
/// Stop when |f(a)| is below this, m.
const RESIDUAL: f64 = 1e-10;
/// Stop when an iteration changes f(a) by less than this, m.
const STEP: f64 = 1e-16;
/// Depths in (−this, 0) are round-off of zero, m.
const ROUND_OFF: f64 = 1e-20;
/// The adhesive radius is kept below this fraction of the largest contact radius.
const RADIUS_FRACTION: f64 = 0.99;

/// The indenter of one side at this step.
#[derive(Clone, Copy, Debug)]
pub struct Indenter {
    /// Height A, m.
    pub a: f64,
    /// 1/A, 1/m.
    pub a_inv: f64,
    /// Width B, m.
    pub b: f64,
    /// Depth δ_e, m.
    pub depth: f64,
    /// Largest contact radius a_max, m.
    pub a_max: f64,
    /// Contact radius of the indenter without adhesion, m.
    pub non_adhesive_radius: f64,
    /// Whether the side is at its largest MDR overlap (loading).
    pub at_max: bool,
}

fn zero_round_off(value: f64) -> f64 {
    if value < 0.0 && value > -ROUND_OFF {
        0.0
    } else {
        value
    }
}

/// The adhesive force of one side and the contact radius its damping uses; advances
/// the side's adhesive radius when `update`.
pub fn force(
    ind: &Indenter,
    gamma: f64,
    e_star: f64,
    h: &mut SideHistory,
    update: bool,
) -> (f64, f64) {
    let Indenter {
        a,
        a_inv,
        b,
        depth,
        a_max,
        non_adhesive_radius: a_na,
        at_max,
    } = *ind;
    let e_inv = 1.0 / e_star;
    let mut a_adh = h.adhesive_radius;
    if a_adh > RADIUS_FRACTION * a_max {
        a_adh = RADIUS_FRACTION * a_max;
    }
    let non_adhesive = |d: f64| {
        if d <= 0.0 {
            0.0
        } else {
            indenter_force(d, a_inv, e_star, a, b)
        }
    };
    if at_max || a_na >= a_adh {
        // Case 1: compression only.
        let f = non_adhesive(depth);
        if update {
            h.adhesive_radius = RADIUS_FRACTION * a_na;
        }
        return (f, a_adh);
    }

    let a_inv_sq = a_inv * a_inv;
    let a_sq = a * a;
    let a4 = a_sq * a_sq;
    let b_inv = 1.0 / b;
    let b_sq = b * b;
    let b4 = b_sq * b_sq;
    let g2 = gamma * gamma;
    let (g3, g4) = (g2 * gamma, g2 * g2);
    let e_sq = e_star * e_star;
    let e_sq_inv = e_inv * e_inv;

    let l_max = (TAU * a_adh * gamma * e_inv).sqrt();
    let depth_at = |r: f64| zero_round_off(a * 0.5 - a * b_inv * (b_sq * 0.25 - r * r).sqrt());
    let g_a = depth_at(a_adh);

    // The radius below which case 3 has no root (LAMMPS's closed form).
    let mut t = 27.0 * a4 * b4 * gamma * e_inv;
    t -= 2.0 * (b4 * b_sq) * g3 * PI_SQ * (e_inv * e_inv * e_inv);
    t += 27f64.sqrt()
        * a_sq
        * b4
        * (27.0 * a4 * e_sq * g2 - 4.0 * b_sq * g4 * PI_SQ).sqrt()
        * e_sq_inv;
    let t = t.cbrt();
    let mut a_crit = -b_sq * gamma * PI * a_inv_sq * e_inv;
    a_crit += CBRT_2 * b4 * g2 * PI_TO_5_3 / (a_sq * e_sq * t);
    a_crit += CBRT_HALF_PI * t * a_inv_sq;
    a_crit /= 6.0;

    if depth + l_max - g_a >= 0.0 {
        // Case 2: the springs hold; the stored radius stays.
        let f = indenter_force(g_a, a_inv, e_star, a, b) + 2.0 * e_star * (depth - g_a) * a_adh;
        return (f, a_adh);
    }
    // Case 3: the springs at their critical length.
    let f = if a_adh < a_crit {
        a_adh = 0.0;
        0.0
    } else {
        let mut r = a_adh;
        for k in 0..MAX_ITERATIONS {
            let f_part = depth - a * 0.5 + a * (b_sq * 0.25 - r * r).sqrt() * b_inv;
            let fa = f_part + (TAU * r * gamma * e_inv).sqrt();
            if fa.abs() < RESIDUAL {
                break;
            }
            let mut dfda = -r * a / (b * (-(r * r) + b_sq * 0.25).sqrt());
            dfda += gamma * SQRT_HALF_PI / (r * gamma * e_star).sqrt();
            r -= fa / dfda;
            let fa2 = f_part + (TAU * r * gamma * e_inv).sqrt();
            if (fa - fa2).abs() < STEP {
                break;
            }
            if k == MAX_ITERATIONS - 1 {
                r = 0.0;
            }
        }
        a_adh = r;
        if a_adh < a_crit {
            a_adh = 0.0;
            0.0
        } else {
            let g = depth_at(a_adh);
            indenter_force(g, a_inv, e_star, a, b) + 2.0 * e_star * (depth - g) * a_adh
        }
    };
    if update {
        h.adhesive_radius = a_adh;
    }
    (f, a_adh)
}
