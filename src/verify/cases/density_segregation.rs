//! Density segregation of equal spheres, Zhong 2009 §6.2 (Table 2, Figs 5–6):
//! 3000 light (ρ = 1200 kg/m³) and 3000 heavy (ρ = 7800 kg/m³) frictionless spheres
//! of radius 2 cm with the linear hysteretic law (k_n = 1e7 N/m, γ_n = 0.7), mixed
//! at random, grown for 0.2 s without gravity, then settled until t = 3 s. Zhong's
//! container is not stated for this study; we take the one of §6.1 (1:1:2, twice
//! the particles' volume, periodic sides, floor).
//!
//! Zhong reports it qualitatively: light spheres dominate the top surface, heavy
//! ones the bottom, with visible clustering. Measured here: the light fraction of
//! the top layer and the heavy fraction of the bottom layer (centres within one
//! diameter of the bed's top or bottom), and the segregation index S = σ/σ₀ over
//! ten horizontal layers (`measure::segregation`). The top and bottom views
//! (the analogue of Zhong Fig 6) are written to the report.
//!
//! Time step: Zhong used 50 µs. For a light sphere (m = 0.040 kg) with the
//! loading stiffness k(1 + γ) = 1.7e7 N/m the single-contact critical step is
//! 2√(m/k) = 97 µs, and the sum of six contact stiffnesses lowers it to 40 µs, below
//! Zhong's step. A run at 50 µs nevertheless reached t = 3 s without tripping any
//! stability check, so the sum-of-stiffnesses bound is conservative for this bed;
//! the case uses the estimate with α = 0.2 (docs/paper-discrepancies.md §19).

use crate::error::Result;
use crate::measure::segregation::{Basis, BedExtent, SegregationSpec, segregation, surface_layers};
use crate::scene;
use crate::verify::{CaseContext, Measured};
use crate::views::{self, ColourBy, View};

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let scene = ctx.scene()?;
    let built = scene::build(&scene)?;
    let mut sim = built.sim;
    sim.run_with(built.steps, |_| {})?;
    let p = &sim.state().particles;
    let light = 0; // material index of "light" in the scene
    let is_light: Vec<bool> = p.material.iter().map(|&m| m == light).collect();
    let d = 2.0 * p.radius[0];
    let layers = surface_layers(
        &p.position,
        &p.radius,
        &is_light,
        2,
        d,
        BedExtent::default(),
        Basis::Number,
    )?;
    let light_top = layers.top.fraction_a.unwrap_or(f64::NAN);
    let heavy_bottom = 1.0 - layers.bottom.fraction_a.unwrap_or(f64::NAN);
    let s = segregation(
        &p.position,
        &p.radius,
        &is_light,
        &SegregationSpec {
            axis: 2,
            layers: 10,
            extent: BedExtent::default(),
            basis: Basis::Number,
        },
    )?;

    let top = (0..p.len())
        .map(|i| p.position[i].z + p.radius[i])
        .fold(0.0, f64::max);
    let (lo, len) = sim.model().detection.space.periodic[0].expect("periodic x");
    let bounds = [
        crate::particles::Vec3::new(lo, lo, 0.0),
        crate::particles::Vec3::new(lo + len, lo + len, top),
    ];
    let species = ColourBy::Species(p.material.clone());
    for (view, file) in [(View::Top, "top.png"), (View::Bottom, "bottom.png")] {
        let path = ctx.report_dir.join(format!("{}_{file}", ctx.spec.name));
        views::render(&view, &p.position, &p.radius, &species, bounds, &path, 600)?;
    }
    Ok(vec![
        Measured::new("light_fraction_top_layer", light_top, 0.75),
        Measured::new("heavy_fraction_bottom_layer", heavy_bottom, 0.75),
        Measured::new("segregation_index", s.index, 0.5),
    ])
}
