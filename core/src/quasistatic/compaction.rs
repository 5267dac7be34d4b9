//! Driving a network along a macroscopic strain path (Redanz & Fleck 2001 §2.4, §3):
//! hydrostatic (Ė₁₁ = Ė₂₂, Ė₁₂ = 0) or closed die (Ė₂₂ < 0, Ė₁₁ = Ė₁₂ = 0), in
//! equal strain increments, recording the stress–density and coordination curves
//! (Figs 4–6).

use super::affine_yield::Sym2;
use super::network::{AffineDeviation, IncrementReport, Network};
use crate::error::Result;
use serde::Serialize;

/// The macroscopic strain path along which a network is compacted (§2.4).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum StrainPath {
    /// Ė₁₁ = Ė₂₂, Ė₁₂ = 0: equal shrinking along both axes.
    Hydrostatic,
    /// Ė₂₂ < 0, Ė₁₁ = Ė₁₂ = 0: the box closes along x₂ only.
    ClosedDie,
}

impl StrainPath {
    /// The strain increment that changes the box area by the fraction `step`.
    pub fn increment(self, step: f64) -> Sym2 {
        match self {
            StrainPath::Hydrostatic => {
                let e = (1.0 - step).sqrt() - 1.0;
                Sym2::new(e, e, 0.0)
            }
            StrainPath::ClosedDie => Sym2::new(0.0, -step, 0.0),
        }
    }
}

/// The network's state after one compaction increment: a point of the paper's
/// stress–density and coordination curves (Figs 4–6).
#[derive(Clone, Copy, Debug, Serialize)]
pub struct CompactionRecord {
    /// Relative density D.
    pub density: f64,
    /// Σ/σ_y (eq 13).
    pub stress_xx: f64,
    /// Σ₂₂/σ_y (eq 13).
    pub stress_yy: f64,
    /// Σ₁₂/σ_y (eq 13).
    pub stress_xy: f64,
    /// Coordination number Z: twice the force-carrying contacts over the cylinders.
    pub coordination: f64,
    /// Fraction of force-carrying contacts that slide.
    pub sliding_fraction: f64,
    /// FIRE iterations the increment took.
    pub iterations: usize,
    /// Mean unbalanced force on the free cylinders over the mean contact force at the end
    /// of the increment.
    pub residual: f64,
    /// False where FIRE ran out of iterations and the increment was carried over
    /// (`NetworkSettings::carry_over`).
    pub converged: bool,
    /// §3.3's measures of the increment that led here (Figs 7–8).
    pub deviation: AffineDeviation,
}

impl CompactionRecord {
    fn of(net: &Network, report: IncrementReport) -> Self {
        let s = net.stress();
        let sy = net.settings.yield_stress;
        CompactionRecord {
            density: net.density(),
            stress_xx: s.xx / sy,
            stress_yy: s.yy / sy,
            stress_xy: s.xy / sy,
            coordination: net.coordination(),
            sliding_fraction: net.sliding_fraction(),
            iterations: report.iterations,
            residual: report.residual,
            converged: report.converged,
            deviation: report.deviation,
        }
    }
}

/// Compact until the density reaches `target`, each increment reducing the box area
/// by the fraction `step` (the last one is shortened to land on `target`).
pub fn compact(
    net: &mut Network,
    path: StrainPath,
    step: f64,
    target: f64,
) -> Result<Vec<CompactionRecord>> {
    let start = IncrementReport {
        iterations: 0,
        residual: 0.0,
        converged: true,
        deviation: AffineDeviation::default(),
    };
    let mut records = vec![CompactionRecord::of(net, start)];
    while net.density() < target * (1.0 - 1e-12) {
        // Area ratio needed to reach the target exactly.
        let needed = 1.0 - net.density() / target;
        let report = net.increment(path.increment(step.min(needed)))?;
        records.push(CompactionRecord::of(net, report));
    }
    Ok(records)
}
