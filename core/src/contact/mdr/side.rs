//! One side of an MDR contact: a sphere of apparent radius R (initial radius R₀)
//! pressed by a rigid flat to the overlap δ, with the history that side keeps.
//! The equations are in `mod.rs`; this file evaluates them in LAMMPS's order of
//! operations (`GranSubModNormalMDR::calculate_forces`, one pass of its side loop),
//! so that the two codes agree to the last bit where their inputs do.

use super::adhesion;
use super::parameters::{Mdr, Moduli};
use super::particle::MdrParticles;
use crate::particles::Vec3;
use std::f64::consts::{FRAC_1_PI, FRAC_PI_2, PI, TAU};

/// What one side of a contact remembers between steps (LAMMPS's history entries of
/// the same names, one per side).
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SideHistory {
    /// Overlap of this side at the last step δ, m.
    pub overlap: f64,
    /// δ − (R − R₀): the overlap measured from the initial surface, m.
    pub displacement: f64,
    /// The MDR part of the overlap, m.
    pub mdr_overlap: f64,
    /// The bulk part of the overlap, m.
    pub bulk_overlap: f64,
    /// Largest MDR part so far, m.
    pub max_mdr_overlap: f64,
    /// Whether the side has yielded.
    pub yielded: bool,
    /// MDR overlap at first yield δ_Y, m.
    pub yield_overlap: f64,
    /// Contact-area intercept c_A = π(δ_Y² − δ_Y R), m².
    pub area_intercept: f64,
    /// Adhesive contact radius, m.
    pub adhesive_radius: f64,
    /// Contact area times the contact's weight, m² (the mean surface displacement
    /// weighs this side's overlap increment by it).
    pub area: f64,
    /// This side's share of the particle's mean strain, last step.
    pub strain: f64,
    /// Overlap at which the side's force vanishes on unloading (the flat's plastic
    /// set), m; zero until the side yields.
    pub plastic_overlap: f64,
}

/// The outcome of one side: its force and what the pair's damping needs.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SideForce {
    /// MDR plus bulk force of the side, before the contact's weight, N.
    pub force: f64,
    /// The contact radius the damping uses (the adhesive radius with γ > 0), m.
    pub damping_radius: f64,
}

/// The force of the 1D indenter of height A (1/A = `a_inv`) and width B at depth
/// `depth` ∈ (0, A/2]: E* A B/4 [acos(1 − 2d/A) − (2 − 4d/A) √(d/A − (d/A)²)].
#[inline]
pub fn indenter_force(depth: f64, a_inv: f64, e_star: f64, a: f64, b: f64) -> f64 {
    let x = depth * a_inv;
    let mut f = (1.0 - 2.0 * depth * a_inv).acos();
    f -= (2.0 - 4.0 * depth * a_inv) * (x - x * x).sqrt();
    f * (0.25 * e_star * a * b)
}

/// Mean pressure on the yield surface p_Y = Y (1.75 e^{−4.4 δ_max/R} + 1), Pa.
#[inline]
pub fn yield_pressure(yield_stress: f64, max_mdr_overlap: f64, radius: f64) -> f64 {
    yield_stress * (1.75 * (-4.4 * max_mdr_overlap / radius).exp() + 1.0)
}

/// Hertz's mean contact pressure of a sphere on a flat, 4E* √δ/(3π √R), Pa.
#[inline]
pub fn hertz_mean_pressure(e_star: f64, overlap: f64, radius: f64) -> f64 {
    4.0 * e_star * overlap.sqrt() / (3.0 * PI * radius.sqrt())
}

/// How the side's overlap increment `ddelta` to `delta` divides between the MDR and the
/// bulk responses: all to MDR while particle `i`'s free-surface fraction is at least
/// ψ_b, else the particle's mean surface displacement to the bulk and the rest to MDR.
fn split(
    law: &Mdr,
    h: &SideHistory,
    delta: f64,
    ddelta: f64,
    i: usize,
    particles: &MdrParticles,
) -> (f64, f64) {
    if particles.free_surface[i] < law.bulk_trigger {
        let bar = particles.mean_displacement_increment[i];
        ((ddelta - bar).min(delta - h.mdr_overlap), bar)
    } else {
        (ddelta, 0.0)
    }
}

/// Evaluate one side at overlap `delta` for particle `i` of `particles`: the side's
/// force, with its history and (when `update`) the particle's sums advanced.
/// `weight` is the contact's w = max(1 − p, 0); `normal` the contact normal.
#[allow(clippy::too_many_arguments)]
pub fn evaluate(
    law: &Mdr,
    moduli: &Moduli,
    h: &mut SideHistory,
    delta: f64,
    i: usize,
    particles: &mut MdrParticles,
    weight: f64,
    normal: Vec3,
    update: bool,
) -> SideForce {
    let e_star = moduli.plane_strain;
    let e_star_inv = 1.0 / e_star;
    let ro = particles.initial_radius[i];
    let r = particles.radius[i];

    // Kinematics: this step's increments of the overlap and of the displacement
    // from the initial surface.
    let ddelta = delta - h.overlap;
    if update {
        h.overlap = delta;
    }
    let deltao = delta - (r - ro);
    let ddeltao = deltao - h.displacement;
    if update {
        h.displacement = deltao;
    }

    let (ddelta_mdr, ddelta_bulk) = split(law, h, delta, ddelta, i, particles);
    let delta_mdr = h.mdr_overlap + ddelta_mdr;
    if update {
        h.mdr_overlap = delta_mdr;
    }
    let delta_bulk = (h.bulk_overlap + ddelta_bulk).max(0.0);
    if update {
        h.bulk_overlap = delta_bulk;
    }
    // LAMMPS keeps the largest MDR overlap even on a step that does not update.
    if delta_mdr > h.max_mdr_overlap {
        h.max_mdr_overlap = delta_mdr;
    }
    let deltamax_mdr = h.max_mdr_overlap;

    let p_y = yield_pressure(law.yield_stress, deltamax_mdr, r);
    if !h.yielded
        && delta_mdr >= deltamax_mdr
        && update
        && hertz_mean_pressure(e_star, delta_mdr, r) > p_y
    {
        h.yielded = true;
        h.yield_overlap = delta_mdr;
        h.area_intercept = PI * (h.yield_overlap * h.yield_overlap - h.yield_overlap * r);
    }

    // The indenter: the sphere itself while elastic, the ellipse once yielded.
    let c_a = h.area_intercept;
    let (a, a_inv, b, depth, a_max);
    if !h.yielded {
        a = 4.0 * r;
        a_inv = 1.0 / a;
        b = 2.0 * r;
        depth = delta_mdr;
        a_max = (deltamax_mdr * r).sqrt();
    } else {
        a_max = (2.0 * deltamax_mdr * r - deltamax_mdr * deltamax_mdr + c_a * FRAC_1_PI).sqrt();
        let a_max_sq = a_max * a_max;
        a = 4.0 * p_y * e_star_inv * a_max;
        a_inv = 1.0 / a;
        b = 2.0 * a_max;
        let depth_max = a * 0.5;
        // The indenter submerged to A/2 (acos(0) = π/2; the root term vanishes but
        // for round-off, which LAMMPS subtracts without the prefactor: kept as is).
        let x = depth_max * a_inv;
        let mut f_max = e_star * (a * b * 0.25) * (1.0 - 2.0 * depth_max * a_inv).acos();
        f_max -= (2.0 - 4.0 * depth_max * a_inv) * (x - x * x).sqrt();
        // Depth of the particle's centre below the flat's first touch.
        let z_r = r - (deltamax_mdr - depth_max);
        let nu = law.poisson_ratio;
        let root = (a_max_sq + z_r * z_r).sqrt();
        let mut delta_r = 2.0 * a_max_sq * (-1.0 + nu) - (-1.0 + 2.0 * nu) * z_r * (-z_r + root);
        delta_r *= f_max / (TAU * a_max_sq * moduli.shear * root);
        depth = (delta_mdr - deltamax_mdr + depth_max + delta_r) / (1.0 + delta_r / depth_max);
        if update {
            h.plastic_overlap = deltamax_mdr - (depth_max + delta_r);
        }
    }

    let a_na = if depth >= 0.0 {
        b * (a - depth).sqrt() * depth.sqrt() * a_inv
    } else {
        0.0
    };
    let indenter = adhesion::Indenter {
        a,
        a_inv,
        b,
        depth,
        a_max,
        non_adhesive_radius: a_na,
        at_max: delta_mdr == deltamax_mdr,
    };
    let (f_mdr, a_adh) = if law.surface_energy <= 0.0 {
        let f = if depth <= 0.0 {
            0.0
        } else {
            indenter_force(depth, a_inv, e_star, a, b)
        };
        if update {
            h.adhesive_radius = a_na;
        }
        (f, a_na)
    } else {
        adhesion::force(&indenter, law.surface_energy, e_star, h, update)
    };

    // Contact area of the side: πδR while elastic, π(2δR − δ²) + c_A once yielded.
    let mut area = if !h.yielded {
        PI * delta * r
    } else {
        PI * (2.0 * delta * r - delta * delta) + c_a
    };
    if area < 0.0 {
        area = 0.0;
    }
    if update {
        particles.area_change_sum[i] += weight * (area - TAU * r * (deltamax_mdr + delta_bulk));
        particles.contact_area_next[i] += weight * area;
    }

    let f_bulk = if delta_bulk <= 0.0 {
        0.0
    } else {
        (1.0 / particles.geometric_volume[i])
            * particles.contact_area[i]
            * delta_bulk
            * moduli.bulk
            * area
    };

    if update {
        h.area = weight * area;
        particles.cap_volume[i] += PI * (1.0 / 3.0) * (delta * delta) * (3.0 * r - delta);
    }

    // The particle's mean strain from this contact: f·b/(3κ V_elas), with the force
    // f = w F n and the arm b = −(R₀ − δ₀) n from the centre to the contact.
    let fn_total = weight * (f_mdr + f_bulk);
    let f = normal * fn_total;
    let arm = normal * -(ro - deltao);
    let strain = (f.x * arm.x + f.y * arm.y + f.z * arm.z)
        / (3.0 * moduli.bulk * particles.elastic_volume[i]);
    if update {
        particles.mean_strain[i] += strain;
        if delta_mdr == deltamax_mdr && h.yielded && f_mdr > 0.0 {
            let vo = (4.0 / 3.0) * PI * (ro * ro * ro);
            particles.radius_numerator[i] -= vo * (strain - h.strain);
            particles.radius_numerator[i] -=
                weight * PI * ddeltao * (2.0 * deltao * ro - deltao * deltao + r * r - ro * ro);
            particles.radius_denominator[i] += weight * 2.0 * PI * r * (deltao + r - ro);
        }
        h.strain = strain;
        let v = particles.elastic_volume[i];
        particles.stress[i] += Vec3::new(f.x * arm.x / v, f.y * arm.y / v, f.z * arm.z / v);
    }

    SideForce {
        force: f_mdr + f_bulk,
        damping_radius: a_adh,
    }
}

/// ∫₀ˣ [acos(1 − 2s) − (2 − 4s)√(s − s²)] ds, the indenter's work per E*AB/4 · A, as
/// θ = acos(1 − 2x): (sin θ − θ cos θ)/2 − sin³θ/6. Its terms cancel to θ⁵/15 at small
/// θ (Hertz's 8/15 E* √R δ^{5/2}), so below θ = 0.2 the series to θ¹³ is taken, whose
/// next term is 1e-12 of the sum there.
fn indenter_work(x: f64) -> f64 {
    let t = 2.0 * x.sqrt().asin();
    if t < 0.2 {
        let t2 = t * t;
        let series = 1.0 / 15.0
            + t2 * (-11.0 / 630.0
                + t2 * (17.0 / 7560.0
                    + t2 * (-461.0 / 2_494_800.0 + t2 * (8303.0 / 778_377_600.0))));
        series * t2 * t2 * t
    } else {
        let s = t.sin();
        0.5 * (s - t * t.cos()) - s * s * s / 6.0
    }
}

/// The elastic energy one side of particle `i` holds at overlap `delta`, its history
/// taken on to `delta` as `evaluate` takes it (so that overlaps the history has not yet
/// seen, such as a specimen's at the start of a run, hold their energy too): the work
/// its force returns as the side unloads to where that force vanishes, with the history
/// held (no yield, no bulk split, no radius change on the way). The indenter's part in
/// closed form: with x = d/A, ∫₀ˣ [acos(1 − 2s) − (2 − 4s)√(s − s²)] ds =
/// √(x − x²) − (1 − 2x) acos(1 − 2x)/2 − (4/3)(x − x²)^{3/2}, times E*AB/4 · A, and
/// after yield times dδ/dd = 1 + Δ_R/d_max, by which the overlap moves per unit of the
/// indenter's depth. The bulk part ½ F_bulk δ_bulk, the force being linear in δ_bulk at
/// the side's area. Adhesion's energy is not counted.
pub fn stored_energy(
    law: &Mdr,
    moduli: &Moduli,
    h: &SideHistory,
    delta: f64,
    i: usize,
    particles: &MdrParticles,
) -> f64 {
    let e_star = moduli.plane_strain;
    let r = particles.radius[i];
    let (ddelta_mdr, ddelta_bulk) = split(law, h, delta, delta - h.overlap, i, particles);
    let delta_mdr = h.mdr_overlap + ddelta_mdr;
    let delta_bulk = (h.bulk_overlap + ddelta_bulk).max(0.0);
    let deltamax_mdr = h.max_mdr_overlap.max(delta_mdr);
    let (a, b, depth, stretch) = if !h.yielded {
        (4.0 * r, 2.0 * r, delta_mdr, 1.0)
    } else {
        let p_y = yield_pressure(law.yield_stress, deltamax_mdr, r);
        let a_max_sq =
            2.0 * deltamax_mdr * r - deltamax_mdr * deltamax_mdr + h.area_intercept * FRAC_1_PI;
        let a_max = a_max_sq.sqrt();
        let a = 4.0 * p_y / e_star * a_max;
        let depth_max = 0.5 * a;
        let f_max = e_star * (a * 2.0 * a_max * 0.25) * FRAC_PI_2;
        let z_r = r - (deltamax_mdr - depth_max);
        let nu = law.poisson_ratio;
        let root = (a_max_sq + z_r * z_r).sqrt();
        let delta_r = (2.0 * a_max_sq * (nu - 1.0) - (2.0 * nu - 1.0) * z_r * (root - z_r)) * f_max
            / (TAU * a_max_sq * moduli.shear * root);
        let depth = (delta_mdr - deltamax_mdr + depth_max + delta_r) / (1.0 + delta_r / depth_max);
        (a, 2.0 * a_max, depth, 1.0 + delta_r / depth_max)
    };
    let indenter = if depth > 0.0 {
        stretch * e_star * a * b * 0.25 * a * indenter_work((depth / a).min(0.5))
    } else {
        0.0
    };
    let bulk = if delta_bulk > 0.0 && particles.geometric_volume[i] > 0.0 {
        let area = if !h.yielded {
            PI * delta * r
        } else {
            PI * (2.0 * delta * r - delta * delta) + h.area_intercept
        }
        .max(0.0);
        let f_bulk = particles.contact_area[i] * delta_bulk * moduli.bulk * area
            / particles.geometric_volume[i];
        0.5 * f_bulk * delta_bulk
    } else {
        0.0
    };
    indenter + bulk
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::mdr::damping::{MdrDamping, MdrDampingForm};

    #[allow(clippy::approx_constant)] // NiAl's ν, not 1/π
    fn nial(surface_energy: f64) -> Mdr {
        Mdr {
            youngs_modulus: 1.83e11,
            poisson_ratio: 0.318,
            yield_stress: 8e8,
            surface_energy,
            wall_surface_energy: None,
            bulk_trigger: 0.5,
            damping: MdrDamping {
                coefficient: 0.0,
                form: MdrDampingForm::Stiffness,
            },
        }
    }

    /// Drive one side of radius 1 µm to `peak` and back to zero overlap in `n` steps
    /// each way; the forces on the way.
    fn cycle(law: &Mdr, peak: f64, n: usize) -> (Vec<f64>, Vec<f64>, SideHistory, f64) {
        let moduli = law.moduli();
        let mut particles = MdrParticles::new(&[1e-6]);
        let mut h = SideHistory::default();
        let go = |d: f64, p: &mut MdrParticles, h: &mut SideHistory| {
            p.begin_step(law.bulk_trigger);
            evaluate(law, &moduli, h, d, 0, p, 1.0, Vec3::x(), true).force
        };
        let load: Vec<f64> = (1..=n)
            .map(|k| go(peak * k as f64 / n as f64, &mut particles, &mut h))
            .collect();
        let radius_at_peak = particles.radius[0];
        let unload = (0..n)
            .rev()
            .map(|k| go(peak * k as f64 / n as f64, &mut particles, &mut h))
            .collect();
        (load, unload, h, radius_at_peak)
    }

    /// Past yield the loading force is the yield pressure over the contact area, and
    /// unloading leaves a plastic set: the force vanishes before the overlap does.
    #[test]
    fn plastic_loading_and_set() {
        let law = nial(0.0);
        let (load, unload, h, r) = cycle(&law, 5e-8, 500);
        assert!(h.yielded && h.yield_overlap > 0.0);
        assert!(r > 1e-6, "the apparent radius did not grow");
        let d = h.max_mdr_overlap;
        let area = PI * (2.0 * d * r - d * d) + h.area_intercept;
        let closed = yield_pressure(law.yield_stress, d, r) * area;
        let last = *load.last().unwrap();
        assert!((last - closed).abs() < 1e-13 * closed, "{last} {closed}");
        assert!(h.plastic_overlap > 0.0 && h.plastic_overlap < d);
        let zero_from = unload.iter().position(|&f| f == 0.0).unwrap();
        assert!(
            zero_from < unload.len() - 1,
            "the force vanished only at δ = 0"
        );
        assert!(unload.iter().all(|&f| f >= 0.0));
    }

    /// The stored energy is the work the side returns on unloading: elastic, where it
    /// is Hertz's 8/15 E* √R δ^{5/2} to first order, and past yield, where the force
    /// vanishes at the plastic set.
    #[test]
    fn stored_energy_is_the_work_returned_on_unloading() {
        let law = nial(0.0);
        let moduli = law.moduli();
        for peak in [2e-10, 5e-8] {
            let mut particles = MdrParticles::new(&[1e-6]);
            let mut h = SideHistory::default();
            let n = 2000;
            for k in 1..=n {
                particles.begin_step(law.bulk_trigger);
                let d = peak * k as f64 / n as f64;
                evaluate(
                    &law,
                    &moduli,
                    &mut h,
                    d,
                    0,
                    &mut particles,
                    1.0,
                    Vec3::x(),
                    true,
                );
            }
            let stored = stored_energy(&law, &moduli, &h, peak, 0, &particles);
            // The history not yet taken to the overlap holds the same energy.
            let fresh = SideHistory {
                max_mdr_overlap: h.max_mdr_overlap,
                ..Default::default()
            };
            if !h.yielded {
                let unseen = stored_energy(&law, &moduli, &fresh, peak, 0, &particles);
                assert!(
                    (unseen - stored).abs() <= 1e-12 * stored,
                    "{unseen:e} {stored:e}"
                );
            }
            // Unload with the history held (no update), trapezoids of F dδ.
            let m = 20_000;
            let (mut work, mut last) = (0.0, None);
            for k in (0..=m).rev() {
                let d = peak * k as f64 / m as f64;
                let mut copy = h;
                let f = evaluate(
                    &law,
                    &moduli,
                    &mut copy,
                    d,
                    0,
                    &mut particles,
                    1.0,
                    Vec3::x(),
                    false,
                )
                .force;
                if let Some((d0, f0)) = last {
                    work += 0.5 * (f + f0) * (d0 - d);
                }
                last = Some((d, f));
            }
            assert!(
                (stored - work).abs() < 1e-6 * work,
                "peak {peak:e}: stored {stored:e}, work returned {work:e}"
            );
            if !h.yielded {
                let hertz = 8.0 / 15.0 * moduli.plane_strain * 1e-6_f64.sqrt() * peak.powf(2.5);
                assert!((stored / hertz - 1.0).abs() < 1e-3, "{stored:e} {hertz:e}");
            }
        }
    }

    /// The indenter's work in closed form and as its series agree where they meet.
    #[test]
    fn indenter_work_is_continuous_at_the_series_switch() {
        let x = (0.1_f64).sin().powi(2); // θ = 0.2
        let t = 0.2_f64;
        let closed = 0.5 * (t.sin() - t * t.cos()) - t.sin().powi(3) / 6.0;
        let below = indenter_work(x * (1.0 - 1e-15));
        assert!(
            (below - closed).abs() < 1e-12 * closed,
            "{below:e} {closed:e}"
        );
    }

    /// With surface energy the unloading side pulls before it lets go, and then
    /// carries no force.
    #[test]
    fn adhesion_pulls_then_lets_go() {
        let (_, unload, h, _) = cycle(&nial(20.0), 5e-8, 2000);
        let pull = unload.iter().cloned().fold(f64::INFINITY, f64::min);
        assert!(pull < 0.0, "no tensile force on unloading: {pull}");
        assert_eq!(*unload.last().unwrap(), 0.0);
        assert_eq!(h.adhesive_radius, 0.0);
    }
}
