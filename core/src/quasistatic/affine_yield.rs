//! Upper-bound yield surfaces of a 2D aggregate of equal, rigid-perfectly plastic,
//! frictionless cylinders under affine motion (Redanz & Fleck 2001, Appendix A; the
//! 3D originals are Fleck, Kuhn & McMeeking 1992 and Fleck 1995).
//!
//! Affine motion makes the approach of two cylinders of radius R whose line of
//! centres makes angle φ with the 1-axis (eq A1, eq 16):
//!
//!   u_N = −2R e(φ),   e(φ) = E₁₁ cos²φ + E₂₂ sin²φ + 2E₁₂ sin φ cos φ,
//!
//! so the contact width (eq 2 with R* = R/2) is A_c = 2R √(−2e(φ)) and the normal force
//! 3σ_y A_c. Contacts are spread uniformly over φ with Z₀ per cylinder and D/(πR²)
//! cylinders per unit area. Only contacts that are approaching (ė(φ) < 0) dissipate;
//! the others unload elastically. The dissipation per unit area (eq A4) is then
//!
//!   W̄ = −(6 σ_y D Z₀/π²) ∫₀^π √(−2e(φ)) ė(φ) H(−ė(φ)) dφ,
//!
//! and the stress on the yield surface is Σ_αβ = ∂W̄/∂Ė_αβ (eq A5, Gurson):
//!
//!   Σ_αβ = −(6 σ_y D Z₀/π²) ∫₀^π √(−2e(φ)) n_α n_β H(−ė(φ)) dφ.
//!
//! `yield_stress` evaluates this integral by quadrature for any prestrain E and any
//! probing direction Ė. The closed forms below are its values in the two cases the
//! paper works out; the unit tests check quadrature against them.
//!
//! Closed die prestrain (E₂₂ < 0, others 0), √(−2e) = √(−2E₂₂) |sin φ|, with
//! s = D Z₀ σ_y √(−2E₂₂) and, for mixed-sign probing, the angle where ė changes sign
//! θ_c = atan √(−Ė₁₁/Ė₂₂):
//!
//! * Ė₁₁, Ė₂₂ ≤ 0 (eqs A7–A8):  Σ₁₁ = −(4/π²) s,  Σ₂₂ = −(8/π²) s.
//! * Ė₁₁ > 0 > Ė₂₂ (eqs A9–A10): Σ₁₁ = −(4/π²) s cos³θ_c,
//!   Σ₂₂ = −(12/π²) s (cos θ_c − cos³θ_c/3).
//! * Ė₁₁ < 0 < Ė₂₂ (eqs A11–A12): Σ₁₁ = −(4/π²) s (1 − cos³θ_c),
//!   Σ₂₂ = −(12/π²) s (2/3 − cos θ_c + cos³θ_c/3).
//!
//! The paper prints θ_c = atan √(Ė₁₁Ė₂₂), which is not dimensionless; the integration
//! limits that reproduce eqs A9–A12 are tan²θ_c = −Ė₁₁/Ė₂₂
//! (docs/paper-discrepancies.md §23).
//!
//! Hydrostatic prestrain (E₁₁ = E₂₂ = E < 0, E₁₂ = 0), √(−2e) = √(−2E) for every φ,
//! h = D Z₀ σ_y √(−2E), with ψ the angle where ė changes sign, tan²ψ = −Ė₁₁/Ė₂₂:
//!
//! * Ė₁₁, Ė₂₂ ≤ 0: Σ₁₁ = Σ₂₂ = −(3/π) h (the vertex at the loading point).
//! * Ė₁₁ > 0 > Ė₂₂: Σ₁₁ = −(12/π²) h (π/2 − ψ − sin 2ψ/2)/2,
//!   Σ₂₂ = −(12/π²) h (π/2 − ψ + sin 2ψ/2)/2.
//! * Ė₁₁ < 0 < Ė₂₂: the same with 1 ↔ 2 (and ψ measured from the 2-axis).
//!
//! This is the 2D form of the isotropic surface of Storåkers, Fleck & McMeeking (1999)
//! the paper plots in Fig 9(a) from Sridhar, Fleck & Akisanya (2001).

use std::f64::consts::PI;

/// A symmetric 2D strain or stress (11, 22, 12).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sym2 {
    /// Component 11.
    pub xx: f64,
    /// Component 22.
    pub yy: f64,
    /// Component 12 (the tensor's, not the engineering shear strain).
    pub xy: f64,
}

impl Sym2 {
    /// The tensor with components 11, 22 and 12.
    pub const fn new(xx: f64, yy: f64, xy: f64) -> Self {
        Sym2 { xx, yy, xy }
    }

    /// n·T·n for the unit vector at angle φ from the 1-axis.
    pub fn normal_component(&self, phi: f64) -> f64 {
        let (s, c) = phi.sin_cos();
        self.xx * c * c + self.yy * s * s + 2.0 * self.xy * s * c
    }
}

/// The affine yield stress for prestrain `strain` (every contact compressed:
/// e(φ) ≤ 0) probed along `rate`, by composite Gauss–Legendre quadrature over φ with
/// the panels split where ė(φ) changes sign, so the integrand is smooth on each.
pub fn yield_stress(
    strain: Sym2,
    rate: Sym2,
    density: f64,
    coordination: f64,
    sigma_y: f64,
) -> Sym2 {
    let prefactor = -6.0 * sigma_y * density * coordination / (PI * PI);
    // Roots of ė(φ) = a + b cos 2φ + c sin 2φ in [0, π): split points.
    let a = 0.5 * (rate.xx + rate.yy);
    let b = 0.5 * (rate.xx - rate.yy);
    let c = rate.xy;
    let amp = b.hypot(c);
    let mut cuts = vec![0.0, PI];
    if amp > 0.0 && (a / amp).abs() < 1.0 {
        let base = c.atan2(b); // b cos2φ + c sin2φ = amp cos(2φ − base)
        let delta = (-a / amp).acos();
        for t in [base + delta, base - delta] {
            cuts.push((0.5 * t).rem_euclid(PI));
        }
    }
    // √(−2e) has a kink where e = 0 (closed die: φ = 0); split there too.
    let (ea, eb, ec) = (
        0.5 * (strain.xx + strain.yy),
        0.5 * (strain.xx - strain.yy),
        strain.xy,
    );
    let eamp = eb.hypot(ec);
    if eamp > 0.0 && (ea / eamp).abs() <= 1.0 {
        let base = ec.atan2(eb);
        let delta = (-ea / eamp).acos();
        for t in [base + delta, base - delta] {
            cuts.push((0.5 * t).rem_euclid(PI));
        }
    }
    cuts.sort_by(f64::total_cmp);
    cuts.dedup_by(|x, y| (*x - *y).abs() < 1e-15);

    let rule = crate::quadrature::legendre_rule(16);
    let mut out = Sym2::new(0.0, 0.0, 0.0);
    for w in cuts.windows(2) {
        let (lo, hi) = (w[0], w[1]);
        let mid = 0.5 * (lo + hi);
        // The loading indicator is constant on a panel: evaluate it at the centre.
        if rate.normal_component(mid) >= 0.0 {
            continue;
        }
        // 8 sub-panels keep the quadrature exact to ~1e-14 for the kinked √.
        let sub = 8;
        for k in 0..sub {
            let a0 = lo + (hi - lo) * k as f64 / sub as f64;
            let width = (hi - lo) / sub as f64;
            for &(x, wt) in &rule {
                let phi = a0 + width * x;
                let size = (-2.0 * strain.normal_component(phi)).max(0.0).sqrt();
                let (s, cs) = phi.sin_cos();
                let f = wt * width * size;
                out.xx += f * cs * cs;
                out.yy += f * s * s;
                out.xy += f * s * cs;
            }
        }
    }
    Sym2::new(prefactor * out.xx, prefactor * out.yy, prefactor * out.xy)
}

/// Closed die prestrain E₂₂ < 0 probed along (Ė₁₁, Ė₂₂): eqs A7–A12.
pub fn closed_die_yield(
    e22: f64,
    rate11: f64,
    rate22: f64,
    density: f64,
    coordination: f64,
    sigma_y: f64,
) -> (f64, f64) {
    let s = density * coordination * sigma_y * (-2.0 * e22).sqrt();
    let k = s / (PI * PI);
    // cos θc with tan² θc = −Ė₁₁/Ė₂₂ (only where the rates have opposite signs).
    let c = || (-rate11 / rate22).sqrt().atan().cos();
    if rate11 <= 0.0 && rate22 <= 0.0 {
        (-4.0 * k, -8.0 * k)
    } else if rate11 > 0.0 && rate22 < 0.0 {
        let c = c();
        (-4.0 * k * c.powi(3), -12.0 * k * (c - c.powi(3) / 3.0))
    } else if rate11 < 0.0 && rate22 > 0.0 {
        let c = c();
        (
            -4.0 * k * (1.0 - c.powi(3)),
            -12.0 * k * (2.0 / 3.0 - c + c.powi(3) / 3.0),
        )
    } else {
        (0.0, 0.0)
    }
}

/// Hydrostatic prestrain E₁₁ = E₂₂ = e < 0 probed along (Ė₁₁, Ė₂₂).
pub fn hydrostatic_yield(
    e: f64,
    rate11: f64,
    rate22: f64,
    density: f64,
    coordination: f64,
    sigma_y: f64,
) -> (f64, f64) {
    let h = density * coordination * sigma_y * (-2.0 * e).sqrt();
    let k = 12.0 * h / (PI * PI);
    if rate11 <= 0.0 && rate22 <= 0.0 {
        (-3.0 / PI * h, -3.0 / PI * h)
    } else if rate11 > 0.0 && rate22 < 0.0 {
        let psi = (-rate11 / rate22).sqrt().atan();
        let arc = 0.5 * PI - psi;
        let chord = 0.5 * (2.0 * psi).sin();
        (-k * 0.5 * (arc - chord), -k * 0.5 * (arc + chord))
    } else if rate11 < 0.0 && rate22 > 0.0 {
        let (s22, s11) = hydrostatic_yield(e, rate22, rate11, density, coordination, sigma_y);
        (s11, s22)
    } else {
        (0.0, 0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    const D: f64 = 0.85;
    const Z: f64 = 4.1;
    const SY: f64 = 1.0;

    /// Probing directions every 5°, except pure dilatation (which unloads every
    /// contact), with exact zeros on the axes: sin π = 1.2e-16 would be a (legitimate
    /// but ill-conditioned) mixed-sign direction.
    fn directions() -> impl Iterator<Item = (f64, f64)> {
        let clean = |v: f64| if v.abs() < 1e-12 { 0.0 } else { v };
        (0..360).step_by(5).filter_map(move |deg| {
            let t = (deg as f64).to_radians();
            let (r11, r22) = (clean(t.cos()), clean(t.sin()));
            (r11 <= 0.0 || r22 <= 0.0).then_some((r11, r22))
        })
    }

    #[test]
    fn quadrature_reproduces_the_closed_forms() {
        let e = -0.02;
        for (r11, r22) in directions() {
            let rate = Sym2::new(r11, r22, 0.0);
            let cases = [
                (
                    Sym2::new(0.0, e, 0.0),
                    closed_die_yield(e, r11, r22, D, Z, SY),
                ),
                (
                    Sym2::new(e, e, 0.0),
                    hydrostatic_yield(e, r11, r22, D, Z, SY),
                ),
            ];
            for (strain, (s11, s22)) in cases {
                let q = yield_stress(strain, rate, D, Z, SY);
                assert_relative_eq!(q.xx, s11, epsilon = 1e-12, max_relative = 1e-10);
                assert_relative_eq!(q.yy, s22, epsilon = 1e-12, max_relative = 1e-10);
            }
        }
    }

    #[test]
    fn loading_point_ratios() {
        let (s11, s22) = closed_die_yield(-0.01, 0.0, -1.0, D, Z, SY);
        assert_relative_eq!(s22 / s11, 2.0, max_relative = 1e-15);
        let (h11, h22) = hydrostatic_yield(-0.01, -1.0, -1.0, D, Z, SY);
        assert_relative_eq!(h11 / h22, 1.0, max_relative = 1e-15);
    }

    #[test]
    fn the_surface_is_continuous_where_the_probing_rate_changes_sign() {
        // Ė₁₁ → 0⁺ with Ė₂₂ < 0 must meet the all-loading branch (θ_c → 0).
        let (a11, a22) = closed_die_yield(-0.01, 1e-30, -1.0, D, Z, SY);
        let (b11, b22) = closed_die_yield(-0.01, 0.0, -1.0, D, Z, SY);
        assert_relative_eq!(a11, b11, max_relative = 1e-9);
        assert_relative_eq!(a22, b22, max_relative = 1e-9);
        // Ė₂₂ → 0⁻ with Ė₁₁ < 0 (θ_c → π/2 from the A11–A12 side).
        let (c11, c22) = closed_die_yield(-0.01, -1.0, 1e-30, D, Z, SY);
        assert_relative_eq!(c11, b11, max_relative = 1e-9);
        assert_relative_eq!(c22, b22, max_relative = 1e-9);
    }
}
