//! Quadrature rules: composite Simpson's rule, for the closed forms that have no
//! elementary integral (Thornton's loading time, the Hertz duration constant's test),
//! and Gauss–Legendre, for the exact ball ∩ region volumes (`measure::region`) and the
//! affine yield surfaces (`quasistatic::affine_yield`).

use std::f64::consts::PI;

/// ∫ₐᵇ f by composite Simpson's rule on `intervals` (even) equal intervals.
pub fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, intervals: usize) -> f64 {
    let h = (b - a) / intervals as f64;
    (0..=intervals)
        .map(|i| {
            let weight = if i == 0 || i == intervals {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            weight * f(a + i as f64 * h)
        })
        .sum::<f64>()
        * h
        / 3.0
}

/// Gauss–Legendre nodes and weights on [0, 1], by Newton iteration on P_n.
pub fn legendre_rule(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut x = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    let kf = k as f64;
                    let p2 = ((2.0 * kf - 1.0) * x * p1 - (kf - 1.0) * p0) / kf;
                    p0 = p1;
                    p1 = p2;
                }
                dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                let dx = p1 / dp;
                x -= dx;
                if dx.abs() < 1e-16 {
                    break;
                }
            }
            (0.5 * (1.0 - x), 1.0 / ((1.0 - x * x) * dp * dp))
        })
        .collect()
}
