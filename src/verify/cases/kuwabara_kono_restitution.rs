//! Viscoelastic (Kuwabara–Kono / Brilliantov, Zhong 2009 eq 15) head-on collisions
//! of two equal steel spheres at impact speeds from 1 mm/s to 0.1 m/s. Theory
//! (Brilliantov et al. 1996; Schwager & Pöschel 2008, PRE 78 051304):
//!   1 − e = C₁ (3/2) A α^{2/5} v^{1/5} + O(v^{2/5}),  α = k̃/m*,  C₁ = 1.15344
//! Quantities: the exponent of a least-squares fit of ln(1 − e) against ln v (1/5),
//! C₁ from the slowest impact, and the count of speed steps at which e fails to
//! fall (0). Each impact is measured from its recorded trajectory.

use super::two_body::{Pair, with_steps};
use crate::contact::normal::{KuwabaraKono, NormalLaw};
use crate::error::{Result, TampError};
use crate::verify::recording::RecordSpec;
use crate::verify::{CaseContext, Measured, measure};

/// A viscoelastic contact lasts about as long as Hertz's; four durations leave room.
const CONTACTS: f64 = 4.0;

const SPEEDS: [f64; 5] = [1e-3, 3e-3, 1e-2, 3e-2, 1e-1];

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    let NormalLaw::KuwabaraKono(KuwabaraKono { dissipation_time }) = base.contact.normal else {
        return Err(TampError::Other("the scene must use kuwabara_kono".into()));
    };
    let mut points = Vec::new();
    let mut c1 = f64::NAN;
    for (k, &v) in SPEEDS.iter().enumerate() {
        let mut s = base.clone();
        s.particles[0].velocity = Some([0.5 * v, 0.0, 0.0]);
        s.particles[1].velocity = Some([-0.5 * v, 0.0, 0.0]);
        let pair = Pair::of(&s)?;
        let k_tilde = 4.0 / 3.0 * pair.effective_modulus()? * pair.r_eff.sqrt();
        let s = with_steps(&s, pair.steps_through_collision(CONTACTS)?);
        let rec = ctx.record(&format!("v{v:e}"), &s, RecordSpec::EVERY_STEP)?;
        let c = measure::two_body(&rec, 0, 1)?;
        if k == 0 {
            c1 = (1.0 - c.restitution)
                / (1.5 * dissipation_time * (k_tilde / pair.m_eff).powf(0.4) * v.powf(0.2));
        }
        points.push((v.ln(), (1.0 - c.restitution).ln(), c.restitution));
    }
    let n = points.len() as f64;
    let (sx, sy) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), p| (a + p.0, b + p.1));
    let (mx, my) = (sx / n, sy / n);
    let slope = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum::<f64>()
        / points.iter().map(|p| (p.0 - mx).powi(2)).sum::<f64>();
    let not_falling = points.windows(2).filter(|w| w[1].2 >= w[0].2).count();
    Ok(vec![
        Measured::new("restitution_exponent", slope, 0.2),
        Measured::new("restitution_c1", c1, 1.15344),
        Measured::new(
            "restitution_rises_with_speed_count",
            not_falling as f64,
            0.0,
        ),
    ])
}
