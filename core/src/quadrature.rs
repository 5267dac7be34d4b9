//! Composite Simpson's rule, the quadrature of the closed forms that have no
//! elementary integral (Thornton's loading time, the Hertz duration constant's test).

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
