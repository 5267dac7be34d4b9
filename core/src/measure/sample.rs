//! Statistics of a measure over independent samples (seeds, specimens): the mean and the
//! sample standard deviation s = √(Σ(x − x̄)²/(n − 1)), with which cases and studies state
//! the spread that sets a tolerance.

/// Mean and sample standard deviation (n − 1 in the denominator; 0 for one value).
pub fn mean_sd(x: &[f64]) -> (f64, f64) {
    let n = x.len() as f64;
    let mean = x.iter().sum::<f64>() / n;
    let var = x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0);
    (mean, var.sqrt())
}
