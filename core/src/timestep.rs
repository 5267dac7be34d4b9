//! Critical time step of the explicit central-difference scheme (Rojek 2016 §3.4).
//!
//!   Δt_cr = (2/ω)(√(1 + ξ²) − ξ)       (eqs 24–25, 28)
//!   ω_i   = √(k_i / m_i)                (eq 29)
//!   Δt    = α · min_i Δt_cr,i            (eqs 26–27; Rojek calls α "β" in the text)
//!
//! k_i is the stiffness particle i meets: for a law with constant stiffness the law's
//! k_n; for Hertz the stiffness at the maximum overlap of a head-on impact at the
//! scene's characteristic velocity against an identical particle or any wall (eq 9
//! at δ_max), or, if larger, the sum of its current contact stiffnesses.

/// α of Rojek eq 26 when the scene gives none.
pub const DEFAULT_ALPHA: f64 = 0.2;

/// Rojek eq 28 for one mass–spring–dashpot system.
pub fn critical_time_step(stiffness: f64, mass: f64, damping_ratio: f64) -> f64 {
    let omega = (stiffness / mass).sqrt();
    2.0 / omega * ((1.0 + damping_ratio * damping_ratio).sqrt() - damping_ratio)
}

/// Rojek eq 28 for a mode of stiffness k and dashpot c (N·s/m) on the mass m, written
/// as 2/(√(ω² + β²) + β), β = c/(2m) = ξω: the same number as `critical_time_step`
/// with ξ = c/(2√(km)), and also defined without a spring (k = 0: the explicit limit
/// of a pure dashpot, 2m/c).
pub fn critical_time_step_with_dashpot(stiffness: f64, mass: f64, dashpot: f64) -> f64 {
    let beta = dashpot / (2.0 * mass);
    2.0 / ((stiffness / mass + beta * beta).sqrt() + beta)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn undamped_limit_is_two_over_omega() {
        assert_relative_eq!(critical_time_step(4.0, 1.0, 0.0), 1.0);
    }

    #[test]
    fn the_dashpot_form_is_eq_28_and_a_pure_dashpot_gives_two_m_over_c() {
        let (k, m, c): (f64, f64, f64) = (4.0, 1.0, 1.5);
        let xi = c / (2.0 * (k * m).sqrt());
        assert_relative_eq!(
            critical_time_step_with_dashpot(k, m, c),
            critical_time_step(k, m, xi),
            max_relative = 1e-14
        );
        assert_relative_eq!(critical_time_step_with_dashpot(0.0, 2.0, 0.5), 8.0);
    }

    #[test]
    fn damping_shortens_the_step() {
        assert!(critical_time_step(4.0, 1.0, 0.9) < critical_time_step(4.0, 1.0, 0.0));
        assert_relative_eq!(
            critical_time_step(4.0, 1.0, 1.0),
            2f64.sqrt() - 1.0,
            max_relative = 1e-14
        );
    }
}
