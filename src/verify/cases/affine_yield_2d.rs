//! Affine compaction of a deposited cylinder packing against the analytic affine yield
//! surfaces of Redanz & Fleck 2001 Appendix A (`quasistatic::affine_yield`).
//!
//! Scene: the seed-1 polydispersed deposit of `ballistic_deposition_2d` (r uniform in
//! [0.9R, 1.1R], W = 80R, σ_y = 1), frictionless, every cylinder moved by eqs 14–15
//! (affine), compacted along the closed-die (Ė₂₂ < 0) or hydrostatic path to D = 0.85
//! in increments of 1e-3 of the box area. The network (`quasistatic::network`) finds
//! the contacts, their plastic history and the stress by eq 13 from the nodal forces.
//!
//! The appendix assumes equal radii, contact normals spread uniformly, and a fixed set
//! of Z₀ contacts per cylinder present from the start. A deposit has none of these
//! exactly: its radii spread ±10 %, deposition favours near-vertical contacts, and gaps
//! close during compaction. So the case separates two questions:
//!
//! * Does the network compute affine compaction right? Its stress is compared with an
//!   independent evaluation: every pair of the *initial* packing is moved by the total
//!   affine map x → (I + E)x in one step, its overlap gives eq 2, and the stress is the
//!   contact sum −(1/V) Σ F n ⊗ l — no increments, no contact detection, no eq 13.
//!   Under monotonic affine loading every contact only loads, so the two agree to
//!   round-off.
//! * How far is the deposit from the appendix? `sigma22_normalised_error` (closed die)
//!   and its hydrostatic twin give (Σ₂₂ − Σ₂₂^A)/Σ₂₂^A with Σ^A from eqs A8 / A4–A5 at
//!   the packing's own D and Z₀ (initial disc–disc coordination); the reference is the
//!   same error predicted by the pairwise evaluation, and `paper_value` is what the
//!   appendix assumes (0, and the loading-point ratios 2 and 1).
//!
//! The report gets `affine_closed_die_yield.svg` / `affine_hydrostatic_yield.svg`: the
//! analytic yield surface through the loading point and the deposit's affine yield
//! points, Σ(Ė) = −(1/V) Σ_{c: n·Ė·n < 0} F_c n ⊗ l_c over the directions Ė (the
//! contacts that load carry their current force, the others unload rigidly), which is
//! the appendix's construction applied to the deposit's real contacts.

use super::ballistic_deposition_2d::fill;
use crate::error::Result;
use crate::generate::distribution::SizeDistribution;
use crate::plot::{Panel, Series, write_svg};
use crate::quasistatic::affine_yield::{Sym2, closed_die_yield, hydrostatic_yield};
use crate::quasistatic::compaction::{StrainPath, compact};
use crate::quasistatic::network::{Constraint, Friction, Network, NetworkSettings};
use crate::quasistatic::{CylinderPacking, Vec2};
use crate::verify::{CaseContext, Measured};
use std::f64::consts::PI;

const TARGET_DENSITY: f64 = 0.85;
const AREA_STEP: f64 = 1e-3;
const SIGMA_Y: f64 = 1.0;

pub fn closed_die(ctx: &CaseContext) -> Result<Vec<Measured>> {
    run(ctx, StrainPath::ClosedDie)
}

pub fn hydrostatic(ctx: &CaseContext) -> Result<Vec<Measured>> {
    run(ctx, StrainPath::Hydrostatic)
}

fn run(ctx: &CaseContext, path: StrainPath) -> Result<Vec<Measured>> {
    let packing = fill(&SizeDistribution::Uniform { min: 0.9, max: 1.1 }, 1)?;
    let z0 = packing.coordination(1e-9);
    let settings = NetworkSettings::redanz_fleck(
        SIGMA_Y,
        1.0,
        Friction::Frictionless,
        false,
        Constraint::Affine,
    );
    let mut net = Network::new(&packing, settings);
    compact(&mut net, path, AREA_STEP, TARGET_DENSITY)?;
    let dem = net.stress();
    let d = net.density();
    // The total affine map, as the product of the increments' stretches.
    let stretch = (net.width / packing.width, net.height / packing.height);
    let pairwise = pairwise_stress(&packing, stretch, net.area());
    let (e11, e22) = (stretch.0 - 1.0, stretch.1 - 1.0);

    let loading = match path {
        StrainPath::ClosedDie => (0.0, -1.0),
        StrainPath::Hydrostatic => (-1.0, -1.0),
    };
    let (_, a22) = analytic(path, (e11, e22), loading, d, z0);
    let err = |s22: f64| (s22 - a22) / a22;
    let out = match path {
        StrainPath::ClosedDie => vec![
            Measured::new(
                "sigma22_over_sigma11_affine",
                dem.yy / dem.xx,
                pairwise.yy / pairwise.xx,
            ),
            Measured::new("sigma22_normalised_error", err(dem.yy), err(pairwise.yy)),
        ],
        StrainPath::Hydrostatic => vec![
            Measured::new(
                "sigma11_over_sigma22_affine",
                dem.xx / dem.yy,
                pairwise.xx / pairwise.yy,
            ),
            Measured::new("sigma22_normalised_error", err(dem.yy), err(pairwise.yy)),
        ],
    };
    write_surface(ctx, path, &net, (e11, e22), d, z0)?;
    Ok(out)
}

/// The appendix's yield stress (Σ₁₁, Σ₂₂) after prestrain (E₁₁, E₂₂) along `path`,
/// probed along `rate`: eqs A7–A12 for closed die, eqs A4–A5 with E₁₁ = E₂₂ for
/// hydrostatic.
fn analytic(
    path: StrainPath,
    (e11, e22): (f64, f64),
    rate: (f64, f64),
    d: f64,
    z0: f64,
) -> (f64, f64) {
    match path {
        StrainPath::ClosedDie => closed_die_yield(e22, rate.0, rate.1, d, z0, SIGMA_Y),
        StrainPath::Hydrostatic => {
            hydrostatic_yield(0.5 * (e11 + e22), rate.0, rate.1, d, z0, SIGMA_Y)
        }
    }
}

/// −(1/V) Σ F n ⊗ l over every pair of the initial packing after the affine stretch
/// (x, y) → (s₁x, s₂y), each pair loaded once to its final overlap by eq 2.
fn pairwise_stress(packing: &CylinderPacking, stretch: (f64, f64), area: f64) -> Sym2 {
    let map = |c: Vec2| Vec2::new(stretch.0 * c.x, stretch.1 * c.y);
    let mut s = Sym2::new(0.0, 0.0, 0.0);
    // Pairs that can touch after a stretch of at most 10 %.
    let reach = 0.1 * 2.2;
    for (i, j) in packing.touching_pairs(reach) {
        let (ri, rj) = (packing.radii[i], packing.radii[j]);
        let l = map(packing.centres[j]) - map(packing.centres[i]);
        let overlap = ri + rj - l.norm();
        if overlap <= 0.0 {
            continue;
        }
        let f = crate::contact::normal::plastic_cylinder::loading_force(
            overlap,
            ri * rj / (ri + rj),
            SIGMA_Y,
        );
        let n = l / l.norm();
        s.xx -= f * n.x * l.x;
        s.yy -= f * n.y * l.y;
        s.xy -= f * n.x * l.y;
    }
    Sym2::new(s.xx / area, s.yy / area, s.xy / area)
}

/// The deposit's affine yield points and the analytic surface, both through the
/// loading point, over the directions of (Ė₁₁, Ė₂₂).
fn write_surface(
    ctx: &CaseContext,
    path: StrainPath,
    net: &Network,
    (e11, e22): (f64, f64),
    d: f64,
    z0: f64,
) -> Result<()> {
    let contacts = net.contact_forces();
    let area = net.area();
    let (mut surface, mut discrete) = (Vec::new(), Vec::new());
    for k in 0..=144 {
        let t = 2.0 * PI * k as f64 / 144.0;
        let (r11, r22) = (t.cos(), t.sin());
        if r11 > 1e-12 && r22 > 1e-12 {
            continue; // pure dilatation unloads every contact
        }
        surface.push(analytic(path, (e11, e22), (r11, r22), d, z0));
        let mut s = (0.0, 0.0);
        for c in &contacts {
            let (n, l, f) = (c.normal, c.branch, c.normal_force);
            if r11 * n.x * n.x + r22 * n.y * n.y < 0.0 {
                s.0 -= f * n.x * l.x / area;
                s.1 -= f * n.y * l.y / area;
            }
        }
        discrete.push(s);
    }
    crate::output::create_dir(&ctx.report_dir)?;
    write_svg(
        &ctx.report_dir.join(format!("{}.svg", ctx.spec.name)),
        &[Panel {
            title: match path {
                StrainPath::ClosedDie => {
                    "Affine yield surface after closed die compaction to D = 0.85 (R&F App. A)"
                }
                StrainPath::Hydrostatic => {
                    "Affine yield surface after hydrostatic compaction to D = 0.85 (R&F App. A)"
                }
            },
            x_label: "Sigma11 / sigma_y",
            y_label: "Sigma22 / sigma_y",
            log_y: false,
            log_x: false,
            series: &[
                Series::line("eqs A7-A12 / A4-A5 (D, Z0 of the deposit)", surface),
                Series::points("deposit, affine (contacts that load)", discrete),
            ],
        }],
    )
}
