//! The head-on impact of a Hertz spring beside a dashpot, K = 4/3 E* √R*:
//!
//!   m* δ'' = −K δ^{3/2} − η(δ) δ',   δ(0) = 0, δ'(0) = v,
//!
//! with the dashpots of tamp's laws:
//! - ξ · 2√(m* k_n), k_n the Hertz tangent stiffness 2E*√(R*δ) (Tsuji et al. 1992's form;
//!   tamp's `critical_fraction`, and `liggghts_restitution` and `tsuji`, which run as one):
//!   η = 2ξ √(m* (3/2) K) δ^{1/4};
//! - Kuwabara & Kono 1987 (`kuwabara_kono`): η = (3/2) K A δ^{1/2}, and the total force
//!   is clamped at zero, so the bodies stop pushing when it vanishes and coast apart
//!   through the rest of the overlap;
//! - a constant γ_n (`constant`, Zhong 2009 eq 6; `mass_velocity`, γ_n = η_n0 m*): η = γ_n,
//!   no clamp (the force turns attractive before the overlap closes, as tamp's dashpot
//!   does);
//! - LAMMPS's `viscoelastic` (viscous.rs): η = η_n0 m* √(R* δ), Kuwabara–Kono's form
//!   without the clamp.
//!
//! Any of them with the total force clamped at zero (`contact.damping.limit`, LAMMPS's
//! `limit_damping`, LIGGGHTS's `limitForce on`) is `unit_impact_no_pull`.
//!
//! With δ = δ_s x, t = (δ_s/v) τ and δ_s = (m* v²/K)^{2/5} it becomes
//!
//!   x'' = −x^{3/2} − c x^q x',   x(0) = 0, x'(0) = 1,
//!
//! q = 1/4, 1/2, 0, 1/2 and c = 2√(3/2) ξ, (3/2) A v/δ_s, γ_n δ_s/(m* v),
//! η_n0 √(R* δ_s) δ_s/v: one equation per c
//! for every mass, radius, modulus and speed. For the first, c depends on ξ alone (Tsuji
//! 1992: the restitution depends on ξ alone), and the restitution is LIGGGHTS's relation
//! ξ = −√(5/6) ln e/√(ln²e + π²) (liggghts.rs; RK4 of this equation at step 5e-5 meets it
//! within 2e-7 at e = 0.9, 0.7, 0.5, 0.1, the gap halving with the step); for the other
//! two, c and so e depend on the speed (Kuwabara–Kono: 1 − e = C₁ c − …, Schwager &
//! Pöschel 2008's series). None of the three has a closed form of the overlap, force and
//! duration, and LAMMPS `tsuji` (Marshall's fit, tsuji.rs) rebounds at 0.616 when asked
//! for 0.5. So the reference of the accuracy setting is this one-parameter equation
//! solved by classical Runge–Kutta, not by tamp's force loop: a different integrator on
//! the equation as the sources write it, converged far below what the setting is asked
//! for (unit tests: halving its step moves nothing above 1e-6, c = 0 gives Johnson's
//! Hertz closed forms, and Kuwabara–Kono's restitution meets the series' first term).

/// RK4 steps per unit of τ (an undamped contact lasts τ = 3.2): halving the step moves
/// the quantities by less than 1e-6 (the test `converged`; the measured largest is in
/// docs/accuracy-cost.md; the x^q at touch and release keeps RK4 from its fourth order
/// there), far below the 1e-4 the setting is checked at.
const STEPS_PER_UNIT: f64 = 20_000.0;

/// The dimensionless impact: largest x, largest |x^{3/2} + c x^q x'| (the force over
/// K δ_s^{3/2}), duration in τ (while x > 0), and rebound speed −x' at separation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Unit {
    /// Largest overlap over δ_s.
    pub max_overlap: f64,
    /// Largest contact force over K δ_s^{3/2}.
    pub max_force: f64,
    /// Contact duration in units of τ, from touch to separation (x > 0).
    pub duration: f64,
    /// Rebound speed over approach speed, −x' at separation.
    pub restitution: f64,
}

/// Which dashpot sits beside the Hertz spring: its power q of the overlap, and whether
/// the total force is clamped at zero.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dashpot {
    /// ξ · 2√(m* k_n): q = 1/4, c = 2√(3/2) ξ.
    CriticalFraction,
    /// Kuwabara–Kono: q = 1/2, c = (3/2) A v/δ_s, force ≥ 0.
    KuwabaraKono,
    /// A constant γ_n: q = 0, c = γ_n δ_s/(m* v).
    Constant,
    /// LAMMPS's `viscoelastic`, η_n0 m* √(R* δ): q = 1/2, c = η_n0 √(R* δ_s) δ_s/v, no
    /// clamp (Kuwabara–Kono's form, pulling at the end as every unclamped dashpot).
    Viscoelastic,
}

impl Dashpot {
    /// x^q, written with square roots where q allows (the same bits as before the
    /// other dashpots joined, and faster than powf).
    fn power(self, x: f64) -> f64 {
        match self {
            Dashpot::CriticalFraction => x.sqrt().sqrt(),
            Dashpot::KuwabaraKono | Dashpot::Viscoelastic => x.sqrt(),
            Dashpot::Constant => 1.0,
        }
    }
}

/// c of the critical-fraction dashpot ξ · 2√(m* k_n).
pub fn critical_fraction_c(xi: f64) -> f64 {
    2.0 * 1.5f64.sqrt() * xi
}

/// The impact of x'' = −x^{3/2} − c x^q x' from x = 0, x' = 1. `None` when the bodies
/// do not separate within τ = 100 (overdamped).
pub fn unit_impact(dashpot: Dashpot, c: f64) -> Option<Unit> {
    unit_impact_with(
        dashpot,
        c,
        dashpot == Dashpot::KuwabaraKono,
        1.0 / STEPS_PER_UNIT,
    )
}

/// The same impact with the total force clamped at zero: once it vanishes the bodies
/// coast apart through the rest of the overlap.
pub fn unit_impact_no_pull(dashpot: Dashpot, c: f64) -> Option<Unit> {
    unit_impact_with(dashpot, c, true, 1.0 / STEPS_PER_UNIT)
}

/// The c at which the unit impact rebounds at `restitution` (e falls as c grows), by
/// bisection between 0 and `c_max`.
pub fn c_for_restitution(dashpot: Dashpot, restitution: f64, c_max: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, c_max);
    for _ in 0..50 {
        let mid = 0.5 * (lo + hi);
        match unit_impact(dashpot, mid) {
            Some(u) if u.restitution > restitution => lo = mid,
            _ => hi = mid,
        }
    }
    0.5 * (lo + hi)
}

fn unit_impact_with(dashpot: Dashpot, c: f64, no_pull: bool, h: f64) -> Option<Unit> {
    // The force vanishes outside contact (x < 0): the equation is only integrated to
    // the crossing, but an RK4 stage may look just beyond it.
    let force = |x: f64, v: f64| {
        let x = x.max(0.0);
        let f = x * x.sqrt() + c * dashpot.power(x) * v;
        if no_pull { f.max(0.0) } else { f }
    };
    let accel = |x: f64, v: f64| -force(x, v);
    let (mut x, mut v, mut t) = (0.0f64, 1.0f64, 0.0f64);
    // A constant dashpot pushes with c at first touch.
    let (mut max_overlap, mut max_force) = (0.0f64, force(0.0, 1.0).abs());
    while t < 100.0 {
        let (k1x, k1v) = (v, accel(x, v));
        let (k2x, k2v) = (
            v + 0.5 * h * k1v,
            accel(x + 0.5 * h * k1x, v + 0.5 * h * k1v),
        );
        let (k3x, k3v) = (
            v + 0.5 * h * k2v,
            accel(x + 0.5 * h * k2x, v + 0.5 * h * k2v),
        );
        let (k4x, k4v) = (v + h * k3v, accel(x + h * k3x, v + h * k3v));
        let xn = x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
        let vn = v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        if xn <= 0.0 && t > 0.0 {
            // The crossing within the step, on the cubic Hermite interpolant of x.
            let p = |s: f64| {
                let (s2, s3) = (s * s, s * s * s);
                (2.0 * s3 - 3.0 * s2 + 1.0) * x
                    + (s3 - 2.0 * s2 + s) * h * v
                    + (-2.0 * s3 + 3.0 * s2) * xn
                    + (s3 - s2) * h * vn
            };
            let (mut lo, mut hi) = (0.0, 1.0);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if p(mid) > 0.0 { lo = mid } else { hi = mid }
            }
            let s = 0.5 * (lo + hi);
            // x' at the crossing from the same interpolant.
            let dp = ((6.0 * s * s - 6.0 * s) * x
                + (3.0 * s * s - 4.0 * s + 1.0) * h * v
                + (-6.0 * s * s + 6.0 * s) * xn
                + (3.0 * s * s - 2.0 * s) * h * vn)
                / h;
            return Some(Unit {
                max_overlap,
                max_force,
                duration: t + s * h,
                restitution: -dp,
            });
        }
        if v > 0.0 && vn <= 0.0 {
            // The turning point: x' = 0 on the Hermite interpolant (a quadratic in s).
            max_overlap = max_overlap.max(hermite_max(x, v, xn, vn, h));
        }
        (x, v, t) = (xn, vn, t + h);
        max_overlap = max_overlap.max(x);
        max_force = max_force.max(force(x, v).abs());
    }
    None
}

/// The largest value of the cubic Hermite interpolant through (x0, v0), (x1, v1) over
/// one step h, where v changes sign from + to −.
fn hermite_max(x0: f64, v0: f64, x1: f64, v1: f64, h: f64) -> f64 {
    let p = |s: f64| {
        let (s2, s3) = (s * s, s * s * s);
        (2.0 * s3 - 3.0 * s2 + 1.0) * x0
            + (s3 - 2.0 * s2 + s) * h * v0
            + (-2.0 * s3 + 3.0 * s2) * x1
            + (s3 - s2) * h * v1
    };
    let dp = |s: f64| {
        (6.0 * s * s - 6.0 * s) * x0
            + (3.0 * s * s - 4.0 * s + 1.0) * h * v0
            + (-6.0 * s * s + 6.0 * s) * x1
            + (3.0 * s * s - 2.0 * s) * h * v1
    };
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if dp(mid) > 0.0 { lo = mid } else { hi = mid }
    }
    p(0.5 * (lo + hi))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::normal::hertz::HERTZ_DURATION_CONSTANT;

    const DASHPOTS: [Dashpot; 3] = [
        Dashpot::CriticalFraction,
        Dashpot::KuwabaraKono,
        Dashpot::Constant,
    ];

    /// Undamped, the unit impact is Johnson's: x_max = (5/4)^{2/5} (the energy
    /// 2/5 x^{5/2} = 1/2 in units where m* = K = v = 1), force x_max^{3/2}, e = 1, and
    /// τ_c = 3.2180655, the constant of hertz.rs; whichever dashpot is switched off.
    #[test]
    fn undamped_is_johnsons_hertz_impact() {
        for dashpot in DASHPOTS {
            let u = unit_impact(dashpot, 0.0).unwrap();
            let x_max = 1.25f64.powf(0.4);
            assert!((u.max_overlap / x_max - 1.0).abs() < 1e-12, "{u:?}");
            // The force's peak is sampled at the steps (an O(h²) = 2.5e-9 miss).
            assert!((u.max_force / x_max.powf(1.5) - 1.0).abs() < 1e-8, "{u:?}");
            assert!((u.restitution - 1.0).abs() < 1e-10, "{u:?}");
            // The crossing is found on a cubic interpolant of RK4's steps.
            assert!(
                (u.duration / HERTZ_DURATION_CONSTANT - 1.0).abs() < 1e-9,
                "{u:?}"
            );
        }
    }

    /// Halving the RK4 step moves no quantity by more than 1e-6 (relative), from weak to
    /// strong damping of each dashpot (its c for e ≈ 0.9 to below 0.1): the reference
    /// must sit 100 times below the finest accuracy `accuracy_on_demand` checks (1e-4).
    /// The dashpots' x^q is not smooth at first touch, nor Kuwabara–Kono's clamp where
    /// the force vanishes, so RK4 does not reach its fourth order there (measured
    /// moves: docs/accuracy-cost.md).
    #[test]
    fn converged() {
        for (dashpot, cs) in [
            (
                Dashpot::CriticalFraction,
                [0.05, 0.3, 0.6].map(critical_fraction_c),
            ),
            (Dashpot::KuwabaraKono, [0.1, 1.0, 4.5]),
            (Dashpot::Constant, [0.1, 0.5, 0.9]),
        ] {
            // Each dashpot as its law has it, and clamped at zero (`no_pull`).
            for (c, clamp) in cs
                .into_iter()
                .flat_map(|c| [(c, dashpot == Dashpot::KuwabaraKono), (c, true)])
            {
                let a = unit_impact_with(dashpot, c, clamp, 1.0 / STEPS_PER_UNIT).unwrap();
                let b = unit_impact_with(dashpot, c, clamp, 0.5 / STEPS_PER_UNIT).unwrap();
                let moves = [
                    (a.max_overlap, b.max_overlap),
                    (a.max_force, b.max_force),
                    (a.duration, b.duration),
                    (a.restitution, b.restitution),
                ]
                .map(|(p, q)| (p / q - 1.0).abs());
                eprintln!(
                    "{dashpot:?} c = {c}, clamped {clamp}: moves {:?}",
                    moves.map(|m| format!("{m:.1e}"))
                );
                assert!(
                    moves.iter().all(|m| *m < 1e-6),
                    "{dashpot:?} c = {c}: {a:?} {b:?}"
                );
            }
        }
    }

    /// Kuwabara–Kono's restitution against the first term of its series in
    /// c = (3/2) A (K/m*)^{2/5} v^{1/5}, 1 − e = C₁ c − C₂ c² + …, C₁ = 1.15344
    /// (Ramírez et al. 1999; Schwager & Pöschel 2008 find the same C₁ with the force
    /// clamped): Richardson's 2g(c) − g(2c) of g = (1 − e)/c removes the c² term and
    /// leaves O(c²) = 1e-6 at c = 1e-3.
    #[test]
    fn kuwabara_kono_restitution_meets_the_series() {
        let g = |c: f64| (1.0 - unit_impact(Dashpot::KuwabaraKono, c).unwrap().restitution) / c;
        let c1 = 2.0 * g(1e-3) - g(2e-3);
        assert!((c1 / 1.15344 - 1.0).abs() < 2e-5, "C1 = {c1}");
    }

    /// The bisection returns the c whose impact rebounds at the asked restitution.
    #[test]
    fn c_for_restitution_inverts() {
        for (dashpot, c_max) in [(Dashpot::KuwabaraKono, 20.0), (Dashpot::Constant, 1.2)] {
            for e in [0.9, 0.5, 0.1] {
                let c = c_for_restitution(dashpot, e, c_max);
                let u = unit_impact(dashpot, c).unwrap();
                assert!((u.restitution - e).abs() < 1e-9, "{dashpot:?}: {u:?}");
            }
        }
    }
}
