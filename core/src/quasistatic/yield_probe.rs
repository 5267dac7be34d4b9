//! Probing the yield surface of a compacted network (Redanz & Fleck 2001 §3.4).
//!
//! After compaction to D = 0.85 the network is unloaded elastically (each contact
//! unloads along its stiff branch, `unloading_factor` = 10³ times the loading
//! stiffness) and reloaded from that one state along strain directions
//! d = (Ė₁₁, Ė₂₂)/|Ė| covering the plane. Reloading is first elastic, then the stress
//! saturates: the network yields.
//!
//! **Yield point.** The paper takes the point of maximum curvature of each reloading
//! stress–density curve and says it lies at about 0.1 % offset strain. tamp uses the
//! offset definition directly, on the stress that does work along the probe,
//!
//!   s(ε) = Σ : d,   ε the reloading strain along d,
//!
//! (the dissipation rate per unit |Ė| at yield, eq A5's Σ : Ė), because the density
//! hardly changes along the near-isochoric probes, so a stress–density curve has no
//! knee there, and curvature of a discrete curve depends on the step. Yield is where
//! s(ε) meets the elastic line shifted by the offset,
//!
//!   s(ε) = s₀ + k₀ (ε − ε_offset),
//!
//! with k₀ the steepest secant stiffness of the reloading increments so far, the line
//! drawn through the start of that increment (the offset method's compensation of a
//! soft start: a compacted network's first, small reloading increment can be ten times
//! softer than the next ones); Σ there (linearly interpolated between increments) is
//! the yield point. The elastic strain is about 10⁻⁴ at D = 0.85 (F_N/k_unload over
//! 2R), an order below the offset, so the point moves little with k₀.
//!
//! **Unloading** follows the loading direction backwards until s along it is at most
//! `unload_to` of its loaded value. Not to zero: a network with no force left has no
//! stiffness to tell FIRE where the cylinders belong, and the paper's surfaces near
//! Σ = 0 are hand-sketched anyway.
//!
//! **Equilibrium.** Every increment is relaxed to static equilibrium by the network's
//! FIRE corrector. A network whose settings allow `carry_over` may commit one out of
//! balance; `Unloading::unconverged` and `YieldPoint::unconverged` count those, so a
//! caller can refuse a surface read off such states.

use super::affine_yield::Sym2;
use super::network::Network;
use crate::error::{Result, TampError};

/// How a yield point is probed: the offset strain, the reloading increment, how far to
/// unload first, and when to give up.
#[derive(Clone, Copy, Debug)]
pub struct ProbeSettings {
    /// ε_offset.
    pub offset: f64,
    /// Reloading strain per increment along d.
    pub step: f64,
    /// Unload until s along the loading direction is this fraction of its value.
    pub unload_to: f64,
    /// Give up when no yield is found within this reloading strain.
    pub max_strain: f64,
}

impl ProbeSettings {
    /// The paper's 0.1 % offset, reloaded in ten increments to the offset.
    pub fn redanz_fleck() -> Self {
        ProbeSettings {
            offset: 1e-3,
            step: 1e-4,
            unload_to: 0.05,
            max_strain: 5e-3,
        }
    }
}

/// s = Σ : d.
pub fn work_conjugate(stress: Sym2, direction: Sym2) -> f64 {
    stress.xx * direction.xx + stress.yy * direction.yy + 2.0 * stress.xy * direction.xy
}

fn scaled(d: Sym2, by: f64) -> Sym2 {
    Sym2::new(d.xx * by, d.yy * by, d.xy * by)
}

/// The unloaded state's record.
#[derive(Clone, Copy, Debug)]
pub struct Unloading {
    /// The strain it took: the elastic range that sizes `probe`'s first increment.
    pub strain: f64,
    /// Unloading increments committed out of balance (`NetworkSettings::carry_over`).
    pub unconverged: usize,
}

/// Unload `net` elastically against the unit loading direction `loading`.
pub fn unload(net: &mut Network, loading: Sym2, settings: &ProbeSettings) -> Result<Unloading> {
    let s_loaded = work_conjugate(net.stress(), loading);
    if s_loaded <= 0.0 {
        return Err(TampError::Other(format!(
            "yield probe: the network carries no stress along the loading direction \
             (Σ : d = {s_loaded:.3e}); compact it first"
        )));
    }
    let target = settings.unload_to * s_loaded;
    // A first step far inside the elastic range measures the unloading stiffness.
    let first = 1e-2 * settings.offset;
    let mut unconverged = usize::from(!net.increment(scaled(loading, -first))?.converged);
    let mut strain = first;
    let mut s = work_conjugate(net.stress(), loading);
    let stiffness = (s_loaded - s) / first;
    if stiffness <= 0.0 {
        return Err(TampError::Other(format!(
            "yield probe: the stress did not fall when unloading ({s_loaded:.3e} → {s:.3e})"
        )));
    }
    let mut increments = 1;
    // Contacts that open make unloading softer than its start, so each linear
    // estimate falls short; the next one uses the secant stiffness of the last, and
    // ten increments per estimate keep each one small for FIRE's predictor.
    let mut secant = stiffness;
    while s > target {
        if increments > 400 {
            return Err(TampError::Other(format!(
                "yield probe: unloading did not bring Σ : d below {target:.3e} in 400 \
                 increments (now {s:.3e})"
            )));
        }
        // Aimed below the target so round-off cannot leave it just above.
        let remaining = (s - 0.5 * target) / secant;
        for _ in 0..10 {
            let report = net.increment(scaled(loading, -remaining / 10.0))?;
            unconverged += usize::from(!report.converged);
            increments += 1;
        }
        strain += remaining;
        let before = s;
        s = work_conjugate(net.stress(), loading);
        if before - s > 0.0 {
            secant = (before - s) / remaining;
        }
    }
    Ok(Unloading {
        strain,
        unconverged,
    })
}

/// One reloading curve and the yield point on it.
#[derive(Clone, Debug)]
pub struct YieldPoint {
    /// The unit probing direction d.
    pub direction: Sym2,
    /// Σ at yield.
    pub stress: Sym2,
    /// k₀, the slope of the elastic line (`yield_in_last_increment`).
    pub elastic_stiffness: f64,
    /// (ε, Σ) after each reloading increment, starting at the unloaded state.
    pub curve: Vec<(f64, Sym2)>,
    /// Reloading increments committed out of balance (`NetworkSettings::carry_over`).
    pub unconverged: usize,
}

/// Reload a copy of the unloaded network along the unit direction `direction` until
/// it yields. `elastic_strain` sizes the first increment (the unloading strain is a
/// good measure): it stays within the elastic range, so the elastic line
/// (`yield_in_last_increment`) is drawn from the start of the curve.
pub fn probe(
    unloaded: &Network,
    direction: Sym2,
    elastic_strain: f64,
    settings: &ProbeSettings,
) -> Result<YieldPoint> {
    let mut net = unloaded.clone();
    let start = net.stress();
    let s0 = work_conjugate(start, direction);
    let mut curve = vec![(0.0, start)];
    let first = 0.25 * elastic_strain.min(settings.step);
    let mut unconverged = usize::from(!net.increment(scaled(direction, first))?.converged);
    curve.push((first, net.stress()));
    let k_first = (work_conjugate(net.stress(), direction) - s0) / first;
    if k_first <= 0.0 {
        return Err(TampError::Other(format!(
            "yield probe: no elastic stiffness along ({:.3}, {:.3}, {:.3}) (k₀ = {k_first:.3e})",
            direction.xx, direction.yy, direction.xy
        )));
    }
    let mut strain = first;
    while strain < settings.max_strain {
        strain += settings.step;
        unconverged += usize::from(!net.increment(scaled(direction, settings.step))?.converged);
        curve.push((strain, net.stress()));
        let s_curve: Vec<(f64, f64)> = curve
            .iter()
            .map(|&(e, stress)| (e, work_conjugate(stress, direction)))
            .collect();
        if let Some((t, k0)) = yield_in_last_increment(&s_curve, settings.offset) {
            let (a, b) = (curve[curve.len() - 2], curve[curve.len() - 1]);
            let lerp = |x: f64, y: f64| x + t * (y - x);
            return Ok(YieldPoint {
                direction,
                stress: Sym2::new(
                    lerp(a.1.xx, b.1.xx),
                    lerp(a.1.yy, b.1.yy),
                    lerp(a.1.xy, b.1.xy),
                ),
                elastic_stiffness: k0,
                curve,
                unconverged,
            });
        }
    }
    Err(TampError::Other(format!(
        "yield probe: no yield along ({:.3}, {:.3}, {:.3}) within a reloading strain of {:.1e}",
        direction.xx, direction.yy, direction.xy, settings.max_strain
    )))
}

/// Whether the reloading curve s(ε) so far yields in its last increment: the
/// fraction along it where s falls below the elastic line shifted by `offset`, and
/// that line's slope k₀. The elastic line runs through the start of the steepest
/// increment so far with its slope, as the offset method compensates a soft start
/// (a "toe"): a compacted network's first reloading increment can be much softer
/// than the next ones (docs/verification-notes.md), and a line with its slope would put yield far up the
/// hardening branch, or beyond `max_strain`.
fn yield_in_last_increment(curve: &[(f64, f64)], offset: f64) -> Option<(f64, f64)> {
    let n = curve.len();
    if n < 2 {
        return None;
    }
    let (anchor, k0) = curve
        .windows(2)
        .map(|w| (w[0], (w[1].1 - w[0].1) / (w[1].0 - w[0].0)))
        .fold(None, |best: Option<((f64, f64), f64)>, (a, k)| match best {
            Some((_, kb)) if kb >= k => best,
            _ => Some((a, k)),
        })?;
    if k0 <= 0.0 {
        return None;
    }
    // Above the shifted elastic line: not yet yielded.
    let gap = |(e, s): (f64, f64)| s - anchor.1 - k0 * (e - anchor.0 - offset);
    let (ga, gb) = (gap(curve[n - 2]), gap(curve[n - 1]));
    (ga > 0.0 && gb <= 0.0).then(|| (ga / (ga - gb), k0))
}

/// The area enclosed by Σ = 0 and the yield points in the (Σ₁₁, Σ₂₂) plane, taken in
/// the order given (shoelace formula); its square root measures a surface's size.
pub fn enclosed_area(points: &[(f64, f64)]) -> f64 {
    let mut ring = vec![(0.0, 0.0)];
    ring.extend_from_slice(points);
    let n = ring.len();
    0.5 * (0..n)
        .map(|k| {
            let (a, b) = (ring[k], ring[(k + 1) % n]);
            a.0 * b.1 - b.0 * a.1
        })
        .sum::<f64>()
        .abs()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::normal::plastic_cylinder::loading_force;
    use crate::quasistatic::network::Friction;
    use crate::quasistatic::network::tests::chain;
    use approx::assert_relative_eq;

    /// Five unit cylinders in a row, the two ends prescribed, compressed along x by
    /// ten increments of 10⁻³: each of the four contacts at the same overlap.
    fn compressed_chain() -> Network {
        let mut net = chain(Friction::Frictionless);
        // Unloading is 10³ times stiffer than loading: 1e-8 is near its round-off.
        net.settings.tolerance = 1e-8;
        for _ in 0..10 {
            net.increment(Sym2::new(-1e-3, 0.0, 0.0)).unwrap();
        }
        net
    }

    #[test]
    fn a_chain_yields_at_its_loaded_force_hardened_by_the_offset_strain() {
        let mut net = compressed_chain();
        let loaded = net.stress().xx;
        let overlap = (8.0 - (net.centres[4].x - net.centres[0].x)) / 4.0;
        let settings = ProbeSettings::redanz_fleck();
        let d = Sym2::new(-1.0, 0.0, 0.0);
        let unloaded = unload(&mut net, d, &settings).unwrap();
        assert!(work_conjugate(net.stress(), d) <= settings.unload_to * (-loaded));
        assert_eq!(unloaded.unconverged, 0);
        let point = probe(&net, d, unloaded.strain, &settings).unwrap();
        assert_eq!(point.unconverged, 0);
        // By the offset rule the plastic shortening at yield is ε_offset of the
        // end-to-end distance 8, a quarter of it per contact, on eq 2: the yield force
        // is the loaded one hardened to u + 2ε_offset. The 10⁻³ covers the secant k₀
        // and the interpolation between increments.
        let hardened = |strain: f64| loading_force(overlap + 2.0 * strain, 0.5, 1.0);
        let expected = hardened(settings.offset) / hardened(0.0);
        assert_relative_eq!(point.stress.xx / loaded, expected, max_relative = 1e-3);
    }

    /// Reloading increments of a curve that is soft for its first 2.5e-5 (slope 60)
    /// when `toe`, then elastic (slope 800) until s = 0.24, where it yields and hardens
    /// slowly (slope 10): the shape of a compacted network's reloading whose first
    /// increment is soft (seed 8's closed die sticking network, W = 20R, probed at
    /// ψ = 157.5°, has slopes 59, 679, 823, 697, then under 200).
    fn toe_curve(toe: bool) -> Vec<(f64, f64)> {
        let elastic_from = if toe { 2.5e-5 } else { 0.0 };
        let s_toe = 60.0 * elastic_from;
        let knee = elastic_from + (0.24 - s_toe) / 800.0;
        let s_at = |e: f64| {
            if e <= elastic_from {
                60.0 * e
            } else if e <= knee {
                s_toe + 800.0 * (e - elastic_from)
            } else {
                0.24 + 10.0 * (e - knee)
            }
        };
        let mut strains = vec![0.0, 2.5e-5];
        while strains.last().unwrap() < &5e-3 {
            strains.push(strains.last().unwrap() + 1e-4);
        }
        strains.into_iter().map(|e| (e, s_at(e))).collect()
    }

    fn first_yield(curve: &[(f64, f64)], offset: f64) -> Option<f64> {
        (2..=curve.len()).find_map(|n| {
            yield_in_last_increment(&curve[..n], offset).map(|(t, _)| {
                let (a, b) = (curve[n - 2], curve[n - 1]);
                a.1 + t * (b.1 - a.1)
            })
        })
    }

    #[test]
    fn a_soft_first_increment_does_not_move_the_yield_point() {
        let offset = ProbeSettings::redanz_fleck().offset;
        let without = first_yield(&toe_curve(false), offset).expect("yields");
        let with = first_yield(&toe_curve(true), offset).expect("yields");
        // Past the knee at s = 0.24 the curve gains about 10 × the offset strain.
        assert!((without - 0.2501).abs() < 1e-4, "{without}");
        // Only the start of the elastic part moves, so the point does not; the
        // first increment's secant (slope 60) would not find yield by ε = 5e-3.
        assert!((with - without).abs() < 1e-9, "{with} against {without}");
    }

    #[test]
    fn a_cohesionless_chain_stretched_yields_at_zero_stress() {
        let mut net = compressed_chain();
        let loaded = net.stress().xx;
        let settings = ProbeSettings::redanz_fleck();
        let unloaded = unload(&mut net, Sym2::new(-1.0, 0.0, 0.0), &settings).unwrap();
        let point = probe(&net, Sym2::new(1.0, 0.0, 0.0), unloaded.strain, &settings).unwrap();
        assert!(
            point.stress.xx.abs() < 1e-6 * loaded.abs(),
            "{:?}",
            point.stress
        );
    }

    #[test]
    fn increments_committed_out_of_balance_are_counted() {
        let mut net = compressed_chain();
        let settings = ProbeSettings::redanz_fleck();
        let d = Sym2::new(-1.0, 0.0, 0.0);
        // One FIRE iteration cannot bring the chain to 1e-8 after the predictor.
        net.settings.max_iterations = 1;
        net.settings.carry_over = true;
        let unloaded = unload(&mut net, d, &settings).unwrap();
        assert!(unloaded.unconverged > 0, "{unloaded:?}");
        let point = probe(&net, d, unloaded.strain, &settings).unwrap();
        assert!(point.unconverged > 0);
    }

    #[test]
    fn the_enclosed_area_of_a_quarter_square_is_its_area() {
        let square = [(-1.0, 0.0), (-1.0, -1.0), (0.0, -1.0)];
        assert!((enclosed_area(&square) - 1.0).abs() < 1e-15);
    }

    #[test]
    fn work_conjugate_counts_the_shear_twice() {
        let s = Sym2::new(1.0, 2.0, 3.0);
        let d = Sym2::new(0.5, 0.25, 0.125);
        assert_eq!(work_conjugate(s, d), 0.5 + 0.5 + 0.75);
    }
}
