//! Binary packing of spheres with size ratio 10, Zhong 2009 §6.1 (Table 1, Fig 4):
//! N_b large (R_b = 5 cm) and N_s small (R_s = 5 mm) frictionless spheres of one
//! steel (ρ = 7800 kg/m³; linear hysteretic law k_n = 1e7 N/m, γ_n = 0.7), placed
//! at random in a container of twice their volume with periodic side faces and a
//! floor, grown without gravity for 0.2 s, then settled under gravity. The packing
//! fraction of the settled bed is measured for N_s/N_b = 0, 10, 50, 100, 200, 300,
//! 500. Zhong (N_b = 2000, Δt = 10 µs, 3 s) states two points of the
//! curve: 0.636 at N_s = 0 and the peak, 0.824, at N_s/N_b = 300.
//!
//! Scaled down. N_b = 2000 means 10⁶ small spheres at N_s/N_b = 500; tamp affords
//! the N_b of the case's scene (the r = 300 point, runnable on its own with
//! `tamp run`). The container keeps Zhong's volume (twice the particles') and his
//! 1:1:2 shape, except that its side never falls below 2.5 large diameters: the
//! periodic faces need more than two (a large sphere must not meet two images of
//! another), and the monodisperse point of a small N_b would otherwise be narrower.
//!
//! Measured from the last recorded frame of each point's run (centres and radii) and
//! the scene's periodic faces: the interior fraction of the settled bed, the slab from one large
//! diameter above the floor to one below the bed's Gibbs surface (`measure::bed`),
//! as the Scott case measures away from the floor and the loose top. The bulk
//! fraction of the whole bed below its surface is written beside it; it includes the
//! floor's loose layer and the top diameter. At the peak the two agree to 0.004, and
//! the interior one varies less from seed to seed (docs/paper-discrepancies.md §20).
//! The peak ratio is the vertex of the parabola in ln(N_s/N_b) through the highest
//! point and its two neighbours.
//!
//! Independent reference for the shape: Furnas' limit of an infinite size ratio.
//! Small spheres filling the voids of a large-sphere packing of fraction φ₀ give
//! φ = φ₀ (1 + v) (v = V_s/V_b = (N_s/N_b)/1000 here); large spheres dispersed in a
//! small-sphere packing give φ = (1 + v)/(1 + v/φ₀). The branches meet at
//! v* = 1 − φ₀ (N_s/N_b = 363 for φ₀ = 0.637) with φ* = φ₀(2 − φ₀) = 0.868, an upper
//! bound that a finite ratio of 10 stays below. Zhong's 0.824 = 0.637 × 1.29 lies
//! on the filling branch, just short of v*.

use crate::error::{Result, TampError};
use crate::measure::bed::bulk_packing_fraction;
use crate::measure::region::ball_volume;
use crate::particles::Vec3;
use crate::plot::{Panel, Series, write_svg};
use crate::scene::Scene;
use crate::scene::physics::space;
use crate::scene::schema::{BoxRegion, PeriodicSpec, RadiusSpec};
use crate::verify::{CaseContext, Measured};
use std::fmt::Write as _;
use std::time::Instant;

/// N_s/N_b of the sweep (Zhong's Fig 4 spans 10 to 500).
const RATIOS: [usize; 7] = [0, 10, 50, 100, 200, 300, 500];
/// Smallest side of the container, in large diameters (see the module comment).
const MIN_SIDE_DIAMETERS: f64 = 2.5;
/// Random close packing of equal spheres (Scott & Kilgour 1969), φ₀ of the bound.
const RANDOM_CLOSE: f64 = 0.637;

/// Zhong 2009 §6.1, the two stated points of Fig 4: (N_s/N_b, φ).
const ZHONG: [(f64, f64); 2] = [(0.0, 0.636), (300.0, 0.824)];

fn fixed_radius(spec: &RadiusSpec, which: &str) -> Result<f64> {
    match spec {
        RadiusSpec::Fixed(r) => Ok(*r),
        _ => Err(TampError::Other(format!(
            "binary packing scene: the {which} spheres must have one fixed radius"
        ))),
    }
}

struct Point {
    ratio: usize,
    n_big: usize,
    n_small: usize,
    side: f64,
    container_height: f64,
    bed_height: f64,
    surface_fraction: f64,
    bulk_fraction: f64,
    interior_fraction: f64,
    cpu_s: f64,
}

/// The scene of one point of the sweep: the base scene's two species, N_s = ratio N_b,
/// in a container of twice their volume.
fn point_scene(base: &Scene, ratio: usize) -> Result<(Scene, f64, f64)> {
    if base.insert.len() != 2 {
        return Err(TampError::Other(
            "binary packing scene: expected two insert entries, large then small".into(),
        ));
    }
    let r_big = fixed_radius(&base.insert[0].radius, "large")?;
    let r_small = fixed_radius(&base.insert[1].radius, "small")?;
    let n_big = base.insert[0].count;
    let n_small = ratio * n_big;
    let solid = n_big as f64 * ball_volume(r_big) + n_small as f64 * ball_volume(r_small);
    // Zhong: volume 2 × solid, sides 1:1:2, so side³ = solid.
    let side = solid.cbrt().max(MIN_SIDE_DIAMETERS * 2.0 * r_big);
    let height = 2.0 * solid / (side * side);
    let mut scene = base.clone();
    let region = BoxRegion {
        lower: [0.0; 3],
        upper: [side, side, height],
    };
    scene.insert[0].region = region.clone();
    scene.insert[1].region = region;
    scene.insert[1].count = n_small;
    if n_small == 0 {
        scene.insert.truncate(1);
    }
    scene.periodic = Some(PeriodicSpec {
        x: Some([0.0, side]),
        y: Some([0.0, side]),
        z: None,
    });
    Ok((scene, side, height))
}

fn run_point(ctx: &CaseContext, base: &Scene, ratio: usize) -> Result<Point> {
    let (scene, side, container_height) = point_scene(base, ratio)?;
    let clock = Instant::now();
    let label = format!("ns_over_nb_{ratio}");
    let (_, last) = ctx.first_and_last(&label, &scene)?;
    let position: Vec<Vec3> = last.bodies.iter().map(|b| b.position).collect();
    let radius: Vec<f64> = last.bodies.iter().map(|b| b.radius).collect();
    let bed = bulk_packing_fraction(&position, &radius, &space(scene.periodic.as_ref()), 2, 0.0)?;
    write_state(ctx, ratio, &position, &radius)?;
    Ok(Point {
        ratio,
        n_big: scene.insert[0].count,
        n_small: scene.insert.get(1).map_or(0, |s| s.count),
        side,
        container_height,
        bed_height: bed.height,
        surface_fraction: bed.surface_fraction,
        bulk_fraction: bed.bulk_fraction,
        interior_fraction: bed.interior_fraction,
        cpu_s: clock.elapsed().as_secs_f64(),
    })
}

/// The settled bed of one point (centres and radii), for measures of one's own.
fn write_state(ctx: &CaseContext, ratio: usize, positions: &[Vec3], radii: &[f64]) -> Result<()> {
    let mut csv = String::from("x_m,y_m,z_m,radius_m\n");
    for (c, r) in positions.iter().zip(radii) {
        let _ = writeln!(csv, "{:e},{:e},{:e},{:e}", c.x, c.y, c.z, r);
    }
    crate::output::create_dir(&ctx.report_dir)?;
    let file = format!("{}_state_{ratio}.csv", ctx.spec.name);
    crate::output::write_atomic(&ctx.report_dir.join(file), csv.as_bytes())
}

/// Furnas' infinite-ratio bound at v = V_s/V_b (see the module comment).
fn furnas_bound(v: f64) -> f64 {
    let filling = RANDOM_CLOSE * (1.0 + v);
    let floating = (1.0 + v) / (1.0 + v / RANDOM_CLOSE);
    filling.min(floating)
}

/// Vertex of the parabola through three points.
fn parabola_vertex((x0, y0): (f64, f64), (x1, y1): (f64, f64), (x2, y2): (f64, f64)) -> f64 {
    let num = (x1 - x0).powi(2) * (y1 - y2) - (x1 - x2).powi(2) * (y1 - y0);
    let den = (x1 - x0) * (y1 - y2) - (x1 - x2) * (y1 - y0);
    x1 - 0.5 * num / den
}

/// The peak's N_s/N_b: the parabola in ln(N_s/N_b) through the best point and its
/// neighbours, or the best point itself at an end of the sweep.
fn peak_ratio(points: &[Point], best: usize) -> f64 {
    if best == 0 || best + 1 == points.len() || points[best - 1].ratio == 0 {
        return points[best].ratio as f64;
    }
    let at = |k: usize| ((points[k].ratio as f64).ln(), points[k].interior_fraction);
    parabola_vertex(at(best - 1), at(best), at(best + 1)).exp()
}

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    let mut points = Vec::new();
    for ratio in RATIOS {
        points.push(run_point(ctx, &base, ratio)?);
    }
    let best = (0..points.len())
        .max_by(|&a, &b| {
            points[a]
                .interior_fraction
                .total_cmp(&points[b].interior_fraction)
        })
        .expect("the sweep is not empty");
    let peak_fraction = points[best].interior_fraction;
    let peak_at = peak_ratio(&points, best);

    let name = &ctx.spec.name;
    let mut csv = String::from(
        "ns_over_nb,n_big,n_small,side_m,container_height_m,bed_height_m,surface_layer_fraction,bulk_packing_fraction,interior_packing_fraction,furnas_bound,cpu_s\n",
    );
    for p in &points {
        let _ = writeln!(
            csv,
            "{},{},{},{:e},{:e},{:e},{:.6},{:.6},{:.6},{:.6},{:.1}",
            p.ratio,
            p.n_big,
            p.n_small,
            p.side,
            p.container_height,
            p.bed_height,
            p.surface_fraction,
            p.bulk_fraction,
            p.interior_fraction,
            furnas_bound(p.ratio as f64 / 1000.0),
            p.cpu_s
        );
    }
    crate::output::create_dir(&ctx.report_dir)?;
    crate::output::write_atomic(&ctx.report_dir.join(format!("{name}.csv")), csv.as_bytes())?;
    let n_big = points[0].n_big;
    let mut measured = Series::line(
        &format!("tamp, N_b = {n_big}, interior"),
        points
            .iter()
            .map(|p| (p.ratio as f64, p.interior_fraction))
            .collect(),
    );
    measured.markers = true;
    let mut bulk = Series::line(
        &format!("tamp, N_b = {n_big}, whole bed (bulk)"),
        points
            .iter()
            .map(|p| (p.ratio as f64, p.bulk_fraction))
            .collect(),
    );
    bulk.markers = true;
    let bound: Vec<(f64, f64)> = (0..=100)
        .map(|k| {
            let r = 5.0 * k as f64;
            (r, furnas_bound(r / 1000.0))
        })
        .collect();
    write_svg(
        &ctx.report_dir.join(format!("{name}.svg")),
        &[Panel {
            title: "Binary packing, R_b/R_s = 10 (Zhong 2009 Fig 4)",
            x_label: "N_s / N_b",
            y_label: "packing fraction",
            log_y: false,
            log_x: false,
            series: &[
                measured,
                bulk,
                Series::points("Zhong 2009, stated points (N_b = 2000)", ZHONG.to_vec()),
                Series::line("Furnas bound, infinite size ratio", bound),
            ],
        }],
    )?;
    Ok(vec![
        Measured::new("peak_packing_fraction", peak_fraction, ZHONG[1].1),
        Measured::new("peak_number_ratio", peak_at, ZHONG[1].0),
    ])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn furnas_branches_meet_at_the_stated_peak() {
        let v_star = 1.0 - RANDOM_CLOSE;
        let filling = RANDOM_CLOSE * (1.0 + v_star);
        let floating = (1.0 + v_star) / (1.0 + v_star / RANDOM_CLOSE);
        assert!((filling - floating).abs() < 1e-12);
        assert!((furnas_bound(v_star) - RANDOM_CLOSE * (2.0 - RANDOM_CLOSE)).abs() < 1e-12);
        assert!(
            furnas_bound(0.2) < furnas_bound(v_star) && furnas_bound(0.6) < furnas_bound(v_star)
        );
    }

    #[test]
    fn parabola_vertex_of_a_known_parabola() {
        let f = |x: f64| 2.0 - 3.0 * (x - 1.7).powi(2);
        let v = parabola_vertex((1.0, f(1.0)), (1.5, f(1.5)), (2.5, f(2.5)));
        assert!((v - 1.7).abs() < 1e-12);
    }
}
