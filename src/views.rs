//! Pictures of a particle bed that people look at: the bed seen from the top and from
//! the bottom, and vertical slices through it (the analogue of Zhong et al. 2009,
//! Figs 5–6). Everything here is a pure function of positions, radii and a colour key;
//! `render` writes the picture as PNG (shaded spheres, no text, so no system fonts are
//! needed) or SVG (flat discs with a legend). The same inputs give the same bytes.
//! See docs/views.md for the projections and the colour maps.

use crate::error::{Result, TampError};
use crate::particles::Vec3;
use plotters::prelude::{BitMapBackend, DrawingBackend};
use std::fmt::Write as _;
use std::path::Path;

/// What decides a particle's colour.
#[derive(Clone, Debug, PartialEq)]
pub enum ColourBy {
    /// Categorical, one index per particle (e.g. light = 0, heavy = 1); colours from
    /// [`species_colour`].
    Species(Vec<usize>),
    /// Continuous, one value per particle (size, speed, …), mapped through [`viridis`]
    /// from the smallest to the largest finite value; non-finite values are grey.
    Value { values: Vec<f64>, label: String },
}

/// Which picture of the bed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum View {
    /// Looking down along −z: x to the right, y up the page.
    Top,
    /// Looking up along +z: x to the left (mirrored, as seen from below), y up the page.
    Bottom,
    /// The vertical plane `axis = at` (axis 0 = x, 1 = y): the other horizontal axis to
    /// the right, z up. `thickness` widens the plane into a slab; each sphere reaching
    /// into the slab shows its largest cross-section inside it, so thickness 0 gives the
    /// plain plane section, of radius √(r² − d²) at distance d from the centre.
    Slice {
        axis: usize,
        at: f64,
        thickness: f64,
    },
}

/// The colour of empty space in every view.
pub const BACKGROUND: [u8; 3] = [255, 255, 255];

/// For non-finite values under [`ColourBy::Value`].
const NON_FINITE: [u8; 3] = [150, 150, 150];

/// Okabe–Ito, reordered so that the first two (the usual light/heavy pair) contrast most;
/// chosen because it stays distinguishable under the common colour-vision deficiencies,
/// and no entry is a multiple of another, so a depth-darkened disc keeps its hue.
const PALETTE: [[u8; 3]; 8] = [
    [0, 114, 178],
    [230, 159, 0],
    [0, 158, 115],
    [213, 94, 0],
    [204, 121, 167],
    [86, 180, 233],
    [240, 228, 66],
    [60, 60, 60],
];

/// Anchors of matplotlib's viridis (the same eight plotters uses behind its
/// `colormaps` feature, which is not enabled here).
const VIRIDIS: [[u8; 3]; 8] = [
    [68, 1, 84],
    [70, 50, 127],
    [54, 92, 141],
    [39, 127, 143],
    [31, 162, 136],
    [74, 194, 110],
    [160, 219, 57],
    [254, 232, 37],
];

/// Brightness of a sphere's rim relative to its centre (headlight Lambert shading):
/// enough ambient light that rims stay coloured rather than black.
const AMBIENT: f64 = 0.35;
/// Fraction of brightness lost at the full depth-cue distance.
const DEPTH_CUE: f64 = 0.5;
/// Depth-cue distance, in mean radii below the highest visible point. A fixed multiple of
/// the particle size (not the bed height or the domain) so the top layers of a deep bed
/// still show their relief, and PNG and SVG darken alike.
const DEPTH_RADII: f64 = 4.0;
/// Samples per pixel along each axis: anti-aliased rims without a rasteriser whose
/// edge rules we would have to trust.
const SUPERSAMPLE: usize = 3;
/// Width of the SVG strip that holds the legend.
const LEGEND_WIDTH: f64 = 190.0;

/// Colour of species `k`; the palette repeats after eight species.
pub fn species_colour(k: usize) -> [u8; 3] {
    PALETTE[k % PALETTE.len()]
}

/// Viridis at `t` ∈ [0, 1] (clamped), linear between the anchors.
pub fn viridis(t: f64) -> [u8; 3] {
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.5
    };
    let x = t * (VIRIDIS.len() - 1) as f64;
    let k = (x.floor() as usize).min(VIRIDIS.len() - 2);
    let f = x - k as f64;
    let (a, b) = (VIRIDIS[k], VIRIDIS[k + 1]);
    std::array::from_fn(|c| (a[c] as f64 + f * (b[c] as f64 - a[c] as f64)).round() as u8)
}

/// An RGB image, row-major from the top-left corner, three bytes per pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct Raster {
    pub width: u32,
    pub height: u32,
    pub rgb: Vec<u8>,
}

impl Raster {
    pub fn pixel(&self, col: u32, row: u32) -> [u8; 3] {
        let k = 3 * (row as usize * self.width as usize + col as usize);
        [self.rgb[k], self.rgb[k + 1], self.rgb[k + 2]]
    }
}

/// One disc in the picture plane. `w` is the height of its centre towards the viewer;
/// `sphere` discs bulge towards the viewer by √(r² − ρ²), the cut faces of a slice do not.
struct Disc {
    u: f64,
    v: f64,
    r: f64,
    w: f64,
    sphere: bool,
    rgb: [u8; 3],
    /// The particle it shows.
    index: usize,
}

/// The picture plane: `u` to the right over [u0, u1], `v` up over [v0, v1].
struct Scene {
    u0: f64,
    u1: f64,
    v0: f64,
    v1: f64,
    width: u32,
    height: u32,
    discs: Vec<Disc>,
    /// Highest point of any sphere and the depth-cue distance (see DEPTH_RADII).
    top: f64,
    depth_scale: f64,
}

impl Scene {
    fn depth_factor(&self, h: f64) -> f64 {
        if self.depth_scale > 0.0 {
            1.0 - DEPTH_CUE * ((self.top - h) / self.depth_scale).clamp(0.0, 1.0)
        } else {
            1.0
        }
    }

    /// Pixel coordinates (column, row, both continuous) of a picture-plane point.
    fn to_pixel(&self, u: f64, v: f64) -> (f64, f64) {
        (
            (u - self.u0) / (self.u1 - self.u0) * self.width as f64,
            (self.v1 - v) / (self.v1 - self.v0) * self.height as f64,
        )
    }
}

fn bad(rule: impl Into<String>) -> TampError {
    TampError::Other(format!("view: {}", rule.into()))
}

fn base_colours(colour: &ColourBy) -> Vec<[u8; 3]> {
    match colour {
        ColourBy::Species(s) => s.iter().map(|&k| species_colour(k)).collect(),
        ColourBy::Value { values, .. } => {
            let (lo, hi) = finite_range(values);
            values
                .iter()
                .map(|&x| {
                    if !x.is_finite() {
                        NON_FINITE
                    } else if hi > lo {
                        viridis((x - lo) / (hi - lo))
                    } else {
                        viridis(0.5)
                    }
                })
                .collect()
        }
    }
}

fn finite_range(values: &[f64]) -> (f64, f64) {
    values
        .iter()
        .filter(|x| x.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
            (lo.min(x), hi.max(x))
        })
}

fn scene(
    view: &View,
    positions: &[Vec3],
    radii: &[f64],
    colour: &ColourBy,
    bounds: [Vec3; 2],
    pixels: u32,
) -> Result<Scene> {
    let n = positions.len();
    let keys = match colour {
        ColourBy::Species(s) => s.len(),
        ColourBy::Value { values, .. } => values.len(),
    };
    if radii.len() != n || keys != n {
        return Err(bad(format!(
            "{n} positions, {} radii and {keys} colour keys; they must match",
            radii.len()
        )));
    }
    if pixels == 0 {
        return Err(bad("pixels must be > 0"));
    }
    let [lo, hi] = bounds;
    for a in 0..3 {
        if !(lo[a].is_finite() && hi[a].is_finite() && hi[a] > lo[a]) {
            return Err(bad(format!(
                "bounds on axis {a} must be finite with hi > lo, got [{}, {}]",
                lo[a], hi[a]
            )));
        }
    }
    for i in 0..n {
        if !(positions[i].iter().all(|x| x.is_finite()) && radii[i].is_finite() && radii[i] > 0.0) {
            return Err(bad(format!(
                "particle {i}: position and radius must be finite and the radius > 0"
            )));
        }
    }
    let (u0, u1, v0, v1) = match *view {
        View::Top => (lo.x, hi.x, lo.y, hi.y),
        View::Bottom => (-hi.x, -lo.x, lo.y, hi.y),
        View::Slice {
            axis,
            at,
            thickness,
        } => {
            if axis > 1 {
                return Err(bad(format!(
                    "slice axis must be 0 (x) or 1 (y), got {axis}"
                )));
            }
            if !(at.is_finite() && thickness.is_finite() && thickness >= 0.0) {
                return Err(bad(format!(
                    "slice needs a finite position and a finite thickness >= 0, got at = {at}, thickness = {thickness}"
                )));
            }
            let b = 1 - axis;
            (lo[b], hi[b], lo.z, hi.z)
        }
    };
    let (du, dv) = (u1 - u0, v1 - v0);
    let (width, height) = if du >= dv {
        (pixels, ((pixels as f64 * dv / du).round() as u32).max(1))
    } else {
        (((pixels as f64 * du / dv).round() as u32).max(1), pixels)
    };

    let rgb = base_colours(colour);
    let mut discs = Vec::with_capacity(n);
    for i in 0..n {
        let (p, r) = (positions[i], radii[i]);
        let disc = match *view {
            // Seen from below, x and the height towards the viewer both flip.
            View::Top | View::Bottom => {
                let s = if *view == View::Top { 1.0 } else { -1.0 };
                Disc {
                    u: s * p.x,
                    v: p.y,
                    r,
                    w: s * p.z,
                    sphere: true,
                    rgb: rgb[i],
                    index: i,
                }
            }
            View::Slice {
                axis,
                at,
                thickness,
            } => {
                let d = ((p[axis] - at).abs() - 0.5 * thickness).max(0.0);
                if d >= r {
                    continue;
                }
                Disc {
                    u: p[1 - axis],
                    v: p.z,
                    r: (r * r - d * d).sqrt(),
                    // Among overlapping cut faces of a slab, the one cut nearest its centre
                    // is the most representative of the slab, so it goes on top.
                    w: -d,
                    sphere: false,
                    rgb: rgb[i],
                    index: i,
                }
            }
        };
        let outside = disc.u + disc.r < u0
            || disc.u - disc.r > u1
            || disc.v + disc.r < v0
            || disc.v - disc.r > v1;
        if !outside {
            discs.push(disc);
        }
    }

    let spheres = discs.iter().filter(|d| d.sphere);
    let top = spheres
        .clone()
        .map(|d| d.w + d.r)
        .fold(f64::NEG_INFINITY, f64::max);
    let count = spheres.clone().count();
    let depth_scale = if count > 0 {
        DEPTH_RADII * spheres.map(|d| d.r).sum::<f64>() / count as f64
    } else {
        0.0
    };
    Ok(Scene {
        u0,
        u1,
        v0,
        v1,
        width,
        height,
        discs,
        top,
        depth_scale,
    })
}

/// The view as an RGB image whose longer side is `pixels`, the other side following the
/// aspect ratio of `bounds` (the domain `[lo, hi]`), which fills the image exactly.
/// Visibility is exact per sample (a height buffer over the sphere surfaces, so
/// interpenetrating spheres cut each other correctly); spheres are shaded by a
/// headlight and darkened with depth, cut faces of a slice are flat.
pub fn raster(
    view: &View,
    positions: &[Vec3],
    radii: &[f64],
    colour: &ColourBy,
    bounds: [Vec3; 2],
    pixels: u32,
) -> Result<Raster> {
    let sc = scene(view, positions, radii, colour, bounds, pixels)?;
    Ok(rasterise(&sc))
}

fn rasterise(sc: &Scene) -> Raster {
    let s = SUPERSAMPLE;
    let (nu, nv) = (sc.width as usize * s, sc.height as usize * s);
    let du = (sc.u1 - sc.u0) / nu as f64;
    let dv = (sc.v1 - sc.v0) / nv as f64;
    let mut nearest = vec![f64::NEG_INFINITY; nu * nv];
    let mut shade = vec![0.0f64; nu * nv];
    let mut owner = vec![usize::MAX; nu * nv];
    // Sample (c, m) sits at u = u0 + (c + ½)·du, v = v1 − (m + ½)·dv.
    let span = |a: f64, b: f64, n: usize| -> Option<(usize, usize)> {
        let lo = (a - 0.5).floor().max(0.0);
        let hi = (b - 0.5).ceil().min(n as f64 - 1.0);
        (lo <= hi).then_some((lo as usize, hi as usize))
    };
    for (k, d) in sc.discs.iter().enumerate() {
        let Some((c0, c1)) = span((d.u - d.r - sc.u0) / du, (d.u + d.r - sc.u0) / du, nu) else {
            continue;
        };
        let Some((m0, m1)) = span((sc.v1 - d.v - d.r) / dv, (sc.v1 - d.v + d.r) / dv, nv) else {
            continue;
        };
        for m in m0..=m1 {
            let y = sc.v1 - (m as f64 + 0.5) * dv - d.v;
            for c in c0..=c1 {
                let x = sc.u0 + (c as f64 + 0.5) * du - d.u;
                let q = d.r * d.r - x * x - y * y;
                if q <= 0.0 {
                    continue;
                }
                let (h, cosine) = if d.sphere {
                    let bulge = q.sqrt();
                    (d.w + bulge, bulge / d.r)
                } else {
                    (d.w, 1.0)
                };
                let idx = m * nu + c;
                if h > nearest[idx] {
                    nearest[idx] = h;
                    owner[idx] = k;
                    shade[idx] = if d.sphere {
                        (AMBIENT + (1.0 - AMBIENT) * cosine) * sc.depth_factor(h)
                    } else {
                        1.0
                    };
                }
            }
        }
    }
    let (w, h) = (sc.width as usize, sc.height as usize);
    let mut rgb = vec![0u8; 3 * w * h];
    for row in 0..h {
        for col in 0..w {
            let mut sum = [0.0f64; 3];
            for m in row * s..(row + 1) * s {
                for c in col * s..(col + 1) * s {
                    let idx = m * nu + c;
                    let (base, f) = match owner[idx] {
                        usize::MAX => (BACKGROUND, 1.0),
                        k => (sc.discs[k].rgb, shade[idx]),
                    };
                    for ch in 0..3 {
                        sum[ch] += base[ch] as f64 * f;
                    }
                }
            }
            let out = 3 * (row * w + col);
            for ch in 0..3 {
                rgb[out + ch] = (sum[ch] / (s * s) as f64).round().clamp(0.0, 255.0) as u8;
            }
        }
    }
    Raster {
        width: sc.width,
        height: sc.height,
        rgb,
    }
}

fn hex(c: [u8; 3]) -> String {
    format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2])
}

fn scaled(c: [u8; 3], f: f64) -> [u8; 3] {
    c.map(|x| (x as f64 * f).round().clamp(0.0, 255.0) as u8)
}

/// Numbers for people: four significant digits, exponent only when far from 1.
fn fmt_num(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let mag = x.abs().log10().floor();
    if (-3.0..5.0).contains(&mag) {
        let fixed = format!("{:.*}", (3.0 - mag).max(0.0) as usize, x);
        if fixed.contains('.') {
            fixed
                .trim_end_matches('0')
                .trim_end_matches('.')
                .to_string()
        } else {
            fixed
        }
    } else {
        format!("{x:.3e}")
    }
}

fn xml_escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The view as SVG: the picture (same size and framing as [`raster`]) and a legend strip
/// to its right. Every sphere in the frame (Top, Bottom) or reaching into the slice
/// becomes exactly one `<circle>`, hidden ones included, painted from the far side to
/// the viewer by centre height. Spheres are flat discs darkened by the same depth cue as
/// the PNG; the legend uses `<rect>` and `<text>` only, so circles count spheres.
pub fn svg(
    view: &View,
    positions: &[Vec3],
    radii: &[f64],
    colour: &ColourBy,
    bounds: [Vec3; 2],
    pixels: u32,
) -> Result<String> {
    let sc = scene(view, positions, radii, colour, bounds, pixels)?;
    let (w, h) = (sc.width as f64, sc.height as f64);
    let legend = legend_lines(view, colour, bounds);
    // Every species of the bed is listed, so colours read the same in every slice.
    let kinds: Vec<usize> = match colour {
        ColourBy::Species(species) => {
            let mut kinds = species.clone();
            kinds.sort_unstable();
            kinds.dedup();
            kinds
        }
        ColourBy::Value { .. } => Vec::new(),
    };
    let key_height = match colour {
        ColourBy::Species(_) => 18.0 * kinds.len() as f64,
        ColourBy::Value { .. } => 150.0,
    };
    let total_h = h.max(24.0 + 18.0 * legend.len() as f64 + key_height);
    let total_w = w + LEGEND_WIDTH;
    let mut out = String::new();
    let o = &mut out;
    // Writing to a String cannot fail; the results are dropped on purpose.
    let _ = writeln!(
        o,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{total_w}" height="{total_h}" viewBox="0 0 {total_w} {total_h}">"#
    );
    let _ = writeln!(
        o,
        r#"<rect x="0" y="0" width="{total_w}" height="{total_h}" fill="{}"/>"#,
        hex(BACKGROUND)
    );
    let _ = writeln!(
        o,
        r#"<defs><clipPath id="frame"><rect x="0" y="0" width="{w}" height="{h}"/></clipPath>"#
    );
    if matches!(colour, ColourBy::Value { .. }) {
        let _ = writeln!(
            o,
            r#"<linearGradient id="viridis" x1="0" y1="1" x2="0" y2="0">"#
        );
        for (k, c) in VIRIDIS.iter().enumerate() {
            let _ = writeln!(
                o,
                r#"<stop offset="{}" stop-color="{}"/>"#,
                fmt_num(k as f64 / (VIRIDIS.len() - 1) as f64),
                hex(*c)
            );
        }
        let _ = writeln!(o, "</linearGradient>");
    }
    let _ = writeln!(o, "</defs>");

    let mut order: Vec<usize> = (0..sc.discs.len()).collect();
    order.sort_by(|&a, &b| sc.discs[a].w.total_cmp(&sc.discs[b].w));
    let _ = writeln!(o, r#"<g clip-path="url(#frame)" stroke-width="0.6">"#);
    let px_per_unit = w / (sc.u1 - sc.u0);
    for k in order {
        let d = &sc.discs[k];
        let f = if d.sphere {
            sc.depth_factor(d.w + d.r)
        } else {
            1.0
        };
        let (cx, cy) = sc.to_pixel(d.u, d.v);
        let _ = writeln!(
            o,
            r#"<circle cx="{cx:.2}" cy="{cy:.2}" r="{:.2}" fill="{}" stroke="{}"/>"#,
            d.r * px_per_unit,
            hex(scaled(d.rgb, f)),
            hex(scaled(d.rgb, 0.6 * f))
        );
    }
    let _ = writeln!(o, "</g>");
    let _ = writeln!(
        o,
        r##"<rect x="0" y="0" width="{w}" height="{h}" fill="none" stroke="#888888"/>"##
    );

    let x0 = w + 12.0;
    let text = |o: &mut String, x: f64, y: f64, s: &str| {
        let _ = writeln!(
            o,
            r#"<text x="{x}" y="{y}" font-family="sans-serif" font-size="12">{}</text>"#,
            xml_escape(s)
        );
    };
    let mut y = 18.0;
    for line in &legend {
        text(o, x0, y, line);
        y += 18.0;
    }
    y += 6.0;
    match colour {
        ColourBy::Species(species) => {
            // The count is of what this picture draws.
            for &k in &kinds {
                let count = sc.discs.iter().filter(|d| species[d.index] == k).count();
                let _ = writeln!(
                    o,
                    r#"<rect x="{x0}" y="{}" width="12" height="12" fill="{}"/>"#,
                    y - 10.0,
                    hex(species_colour(k))
                );
                text(o, x0 + 18.0, y, &format!("species {k} ({count} drawn)"));
                y += 18.0;
            }
        }
        ColourBy::Value { values, label } => {
            text(o, x0, y, label);
            y += 10.0;
            let (lo, hi) = finite_range(values);
            let bar = 120.0;
            let _ = writeln!(
                o,
                r#"<rect x="{x0}" y="{y}" width="16" height="{bar}" fill="url(#viridis)"/>"#
            );
            let (top, bottom) = if hi >= lo {
                (fmt_num(hi), fmt_num(lo))
            } else {
                ("–".to_string(), "–".to_string())
            };
            text(o, x0 + 22.0, y + 10.0, &top);
            text(o, x0 + 22.0, y + bar, &bottom);
        }
    }
    let _ = writeln!(o, "</svg>");
    Ok(out)
}

fn legend_lines(view: &View, colour: &ColourBy, bounds: [Vec3; 2]) -> Vec<String> {
    let [lo, hi] = bounds;
    let range = |a: usize| format!("[{}, {}]", fmt_num(lo[a]), fmt_num(hi[a]));
    let axis = ["x", "y", "z"];
    let mut lines = match *view {
        View::Top => vec![
            "top view (looking down −z)".to_string(),
            format!("x → {}", range(0)),
            format!("y ↑ {}", range(1)),
        ],
        View::Bottom => vec![
            "bottom view (looking up +z)".to_string(),
            format!("x ← {}", range(0)),
            format!("y ↑ {}", range(1)),
        ],
        View::Slice {
            axis: a,
            at,
            thickness,
        } => {
            let b = 1 - a.min(1);
            let mut head = format!("slice {} = {}", axis[a.min(1)], fmt_num(at));
            if thickness > 0.0 {
                head += &format!(" ± {}", fmt_num(0.5 * thickness));
            }
            vec![
                head,
                format!("{} → {}", axis[b], range(b)),
                format!("z ↑ {}", range(2)),
            ]
        }
    };
    if let ColourBy::Value { values, .. } = colour
        && values.iter().any(|x| !x.is_finite())
    {
        lines.push("grey: non-finite value".to_string());
    }
    lines
}

/// Writes the view to `path`: PNG if it ends in `.png`, SVG if `.svg` (see [`raster`] and
/// [`svg`]). Like every output, it is written under a temporary name next to the target
/// and renamed, so a reader never sees half a picture.
pub fn render(
    view: &View,
    positions: &[Vec3],
    radii: &[f64],
    colour: &ColourBy,
    bounds: [Vec3; 2],
    path: &Path,
    pixels: u32,
) -> Result<()> {
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    match ext.as_deref() {
        Some("svg") => {
            let text = svg(view, positions, radii, colour, bounds, pixels)?;
            crate::output::write_atomic(path, text.as_bytes())
        }
        Some("png") => {
            let image = raster(view, positions, radii, colour, bounds, pixels)?;
            write_png(path, &image)
        }
        _ => Err(bad(format!(
            "{}: the picture format comes from the extension, which must be .png or .svg",
            path.display()
        ))),
    }
}

fn write_png(path: &Path, image: &Raster) -> Result<()> {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().to_string())
        .unwrap_or_default();
    // The encoder picks the format from the extension, so the temporary name keeps .png.
    let tmp = path.with_file_name(format!(".{name}.tmp.png"));
    let size = (image.width, image.height);
    let encoded = {
        let mut backend = BitMapBackend::new(&tmp, size);
        backend
            .blit_bitmap((0, 0), size, &image.rgb)
            .and_then(|_| backend.present())
            .map_err(|e| TampError::Other(format!("writing {}: {e:?}", tmp.display())))
    };
    if let Err(e) = encoded {
        let _ = std::fs::remove_file(&tmp);
        return Err(e);
    }
    std::fs::rename(&tmp, path).map_err(|e| {
        TampError::io(
            format!("renaming {} to {}", tmp.display(), path.display()),
            e,
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 10 × 10 × 10 box at 100 pixels: 10 pixels per unit, so a point at u = a.b5
    /// lands in the middle of a pixel.
    fn cube() -> [Vec3; 2] {
        [Vec3::zeros(), Vec3::new(10.0, 10.0, 10.0)]
    }

    /// Renders through the file path a user takes and decodes the PNG back.
    fn png_round_trip(
        view: &View,
        positions: &[Vec3],
        radii: &[f64],
        colour: &ColourBy,
        bounds: [Vec3; 2],
        pixels: u32,
    ) -> Raster {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("view.png");
        render(view, positions, radii, colour, bounds, &path, pixels).unwrap();
        let leftovers: Vec<_> = std::fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(leftovers, vec![std::ffi::OsString::from("view.png")]);
        let decoder = png::Decoder::new(std::fs::File::open(&path).unwrap());
        let mut reader = decoder.read_info().unwrap();
        let mut buf = vec![0; reader.output_buffer_size()];
        let info = reader.next_frame(&mut buf).unwrap();
        assert_eq!(info.color_type, png::ColorType::Rgb);
        assert_eq!(info.bit_depth, png::BitDepth::Eight);
        buf.truncate(info.buffer_size());
        Raster {
            width: info.width,
            height: info.height,
            rgb: buf,
        }
    }

    /// The pixel under picture-plane point (u, v).
    fn at(img: &Raster, sc: &Scene, u: f64, v: f64) -> [u8; 3] {
        let (c, r) = sc.to_pixel(u, v);
        img.pixel(c.floor() as u32, r.floor() as u32)
    }

    fn frame(view: &View, bounds: [Vec3; 2], pixels: u32) -> Scene {
        scene(view, &[], &[], &ColourBy::Species(vec![]), bounds, pixels).unwrap()
    }

    /// Darkening only scales a colour, so a shaded pixel is `t · base` up to rounding;
    /// returns t when it is, None when the pixel has another hue.
    fn shade_of(p: [u8; 3], base: [u8; 3]) -> Option<f64> {
        let (p, b) = (p.map(f64::from), base.map(f64::from));
        let t = (0..3).map(|c| p[c] * b[c]).sum::<f64>() / (0..3).map(|c| b[c] * b[c]).sum::<f64>();
        (0..3).all(|c| (p[c] - t * b[c]).abs() <= 2.0).then_some(t)
    }

    fn close(p: [u8; 3], q: [u8; 3]) -> bool {
        (0..3).all(|c| (p[c] as i32 - q[c] as i32).abs() <= 2)
    }

    #[test]
    fn top_view_centres_have_their_species_colour_and_background_is_background() {
        let pos = [Vec3::new(3.05, 5.05, 2.0), Vec3::new(7.05, 5.05, 4.0)];
        let radii = [1.5, 1.5];
        let colour = ColourBy::Species(vec![0, 1]);
        let img = png_round_trip(&View::Top, &pos, &radii, &colour, cube(), 100);
        assert_eq!((img.width, img.height), (100, 100));
        let sc = frame(&View::Top, cube(), 100);
        // The highest point of the bed is seen head-on at full brightness.
        let upper = at(&img, &sc, 7.05, 5.05);
        assert!(close(upper, species_colour(1)), "{upper:?}");
        // The lower sphere keeps its hue, darkened by depth: its top is 2 below the
        // highest point, a third of the depth-cue distance (4 radii).
        let lower = at(&img, &sc, 3.05, 5.05);
        let t = shade_of(lower, species_colour(0)).unwrap();
        assert!(
            (t - (1.0 - DEPTH_CUE / 3.0)).abs() < 0.02,
            "{lower:?}, t = {t}"
        );
        assert_eq!(at(&img, &sc, 5.05, 9.05), BACKGROUND);
        assert_eq!(at(&img, &sc, 0.05, 0.05), BACKGROUND);
    }

    #[test]
    fn the_upper_sphere_wins_where_discs_overlap_whatever_the_order() {
        let low = Vec3::new(4.05, 5.05, 2.0);
        let high = Vec3::new(5.05, 5.05, 6.0);
        let radii = [1.5, 1.5];
        for (pos, species) in [([low, high], vec![0, 1]), ([high, low], vec![1, 0])] {
            let colour = ColourBy::Species(species);
            let top = png_round_trip(&View::Top, &pos, &radii, &colour, cube(), 100);
            let sc = frame(&View::Top, cube(), 100);
            // u = 4.55 lies inside both discs.
            let p = at(&top, &sc, 4.55, 5.05);
            assert!(shade_of(p, species_colour(1)).is_some(), "top: {p:?}");
            // Left of the overlap only the low sphere is there.
            let p = at(&top, &sc, 3.05, 5.05);
            assert!(shade_of(p, species_colour(0)).is_some(), "top: {p:?}");

            // From below the low sphere is the near one, and x runs the other way.
            let bottom = png_round_trip(&View::Bottom, &pos, &radii, &colour, cube(), 100);
            let sb = frame(&View::Bottom, cube(), 100);
            let p = at(&bottom, &sb, -4.55, 5.05);
            assert!(shade_of(p, species_colour(0)).is_some(), "bottom: {p:?}");
            let p = at(&bottom, &sb, -6.05, 5.05);
            assert!(shade_of(p, species_colour(1)).is_some(), "bottom: {p:?}");
            // Mirrored: the low sphere (x = 4.05) is right of the high one (x = 5.05).
            let (c_low, _) = sb.to_pixel(-4.05, 5.05);
            let (c_high, _) = sb.to_pixel(-5.05, 5.05);
            assert!(c_low > c_high);
        }
    }

    #[test]
    fn a_slice_shows_the_circle_of_intersection() {
        let r: f64 = 2.0;
        let d = 1.2;
        let rc = (r * r - d * d).sqrt(); // 1.6
        let pos = [
            Vec3::new(5.0 + d, 3.05, 5.05),
            Vec3::new(5.0 + r + 0.1, 8.05, 5.05),
        ];
        let radii = [r, r];
        let colour = ColourBy::Species(vec![1, 0]);
        let view = View::Slice {
            axis: 0,
            at: 5.0,
            thickness: 0.0,
        };
        let img = png_round_trip(&view, &pos, &radii, &colour, cube(), 100);
        let sc = frame(&view, cube(), 100);
        // Slice pictures are flat: the cut face has exactly its species colour.
        assert_eq!(at(&img, &sc, 3.05, 5.05), species_colour(1));
        for (du, dv) in [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)] {
            let inside = at(&img, &sc, 3.05 + du * (rc - 0.2), 5.05 + dv * (rc - 0.2));
            let outside = at(&img, &sc, 3.05 + du * (rc + 0.2), 5.05 + dv * (rc + 0.2));
            assert_eq!(inside, species_colour(1));
            // rc + 0.2 < r: the full sphere would still cover this pixel.
            assert_eq!(outside, BACKGROUND);
        }
        // The second sphere does not reach the plane.
        assert_eq!(at(&img, &sc, 8.05, 5.05), BACKGROUND);

        // A slab as thick as 2d contains the first centre: its full radius shows.
        let slab = View::Slice {
            axis: 0,
            at: 5.0,
            thickness: 2.0 * d,
        };
        let img = png_round_trip(&slab, &pos, &radii, &colour, cube(), 100);
        assert_eq!(at(&img, &sc, 3.05 + r - 0.2, 5.05), species_colour(1));
        // and the second sphere, 0.9 from the slab, its cut there.
        assert_eq!(at(&img, &sc, 8.05, 5.05), species_colour(0));
        assert_eq!(at(&img, &sc, 3.05 + r + 0.2, 5.05), BACKGROUND);
    }

    #[test]
    fn a_y_slice_draws_x_to_the_right() {
        let pos = [Vec3::new(2.05, 5.5, 8.05)];
        let view = View::Slice {
            axis: 1,
            at: 5.0,
            thickness: 0.0,
        };
        let colour = ColourBy::Species(vec![2]);
        let img = png_round_trip(&view, &pos, &[1.0], &colour, cube(), 100);
        let sc = frame(&view, cube(), 100);
        assert_eq!(at(&img, &sc, 2.05, 8.05), species_colour(2));
        assert_eq!(at(&img, &sc, 8.05, 2.05), BACKGROUND);
    }

    #[test]
    fn value_colouring_uses_viridis_over_the_finite_range() {
        let pos = [
            Vec3::new(2.05, 2.05, 5.0),
            Vec3::new(5.05, 5.05, 5.0),
            Vec3::new(8.05, 8.05, 5.0),
        ];
        let colour = ColourBy::Value {
            values: vec![1.0, 3.0, 2.0],
            label: "speed / m s⁻¹".into(),
        };
        let img = png_round_trip(&View::Top, &pos, &[1.0; 3], &colour, cube(), 100);
        let sc = frame(&View::Top, cube(), 100);
        // Equal heights: every centre is at full brightness.
        assert!(close(at(&img, &sc, 2.05, 2.05), viridis(0.0)));
        assert!(close(at(&img, &sc, 5.05, 5.05), viridis(1.0)));
        assert!(close(at(&img, &sc, 8.05, 8.05), viridis(0.5)));
        assert_eq!(viridis(0.0), VIRIDIS[0]);
        assert_eq!(viridis(1.0), VIRIDIS[7]);
    }

    #[test]
    fn the_picture_keeps_the_aspect_ratio_of_the_domain() {
        let wide = [Vec3::zeros(), Vec3::new(20.0, 10.0, 5.0)];
        let img = raster(&View::Top, &[], &[], &ColourBy::Species(vec![]), wide, 200).unwrap();
        assert_eq!((img.width, img.height), (200, 100));
        let slice = View::Slice {
            axis: 1,
            at: 5.0,
            thickness: 0.0,
        };
        let img = raster(&slice, &[], &[], &ColourBy::Species(vec![]), wide, 200).unwrap();
        assert_eq!((img.width, img.height), (200, 50));
        let tall = View::Slice {
            axis: 0,
            at: 5.0,
            thickness: 0.0,
        };
        let deep = [Vec3::zeros(), Vec3::new(1.0, 10.0, 40.0)];
        let img = raster(&tall, &[], &[], &ColourBy::Species(vec![]), deep, 200).unwrap();
        assert_eq!((img.width, img.height), (50, 200));
    }

    #[test]
    fn png_and_svg_are_deterministic() {
        let pos = [Vec3::new(3.0, 4.0, 2.0), Vec3::new(4.0, 4.5, 2.5)];
        let colour = ColourBy::Species(vec![0, 1]);
        let dir = tempfile::tempdir().unwrap();
        for name in ["a.png", "b.png", "a.svg", "b.svg"] {
            render(
                &View::Top,
                &pos,
                &[1.0, 1.2],
                &colour,
                cube(),
                &dir.path().join(name),
                64,
            )
            .unwrap();
        }
        let read = |n: &str| std::fs::read(dir.path().join(n)).unwrap();
        assert_eq!(read("a.png"), read("b.png"));
        assert_eq!(read("a.svg"), read("b.svg"));
    }

    #[test]
    fn svg_has_one_circle_per_drawn_sphere() {
        // The third sphere is hidden under the second from above; it is still drawn.
        let pos = [
            Vec3::new(2.0, 2.0, 1.0),
            Vec3::new(6.0, 6.0, 5.0),
            Vec3::new(6.0, 6.0, 2.0),
        ];
        let radii = [1.0, 1.5, 1.0];
        let colour = ColourBy::Species(vec![0, 1, 0]);
        let text = svg(&View::Top, &pos, &radii, &colour, cube(), 100).unwrap();
        assert!(text.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""));
        assert!(text.trim_end().ends_with("</svg>"));
        assert_eq!(text.matches("<circle").count(), 3);
        assert!(text.contains("species 0 (2 drawn)") && text.contains("species 1 (1 drawn)"));
        // Painted far to near: the hidden sphere comes before the one covering it.
        let circles: Vec<&str> = text.lines().filter(|l| l.starts_with("<circle")).collect();
        assert!(circles[2].contains(r#"r="15.00""#));

        // Only the spheres the plane cuts appear in a slice.
        let slice = View::Slice {
            axis: 0,
            at: 2.5,
            thickness: 0.0,
        };
        let text = svg(&slice, &pos, &radii, &colour, cube(), 100).unwrap();
        assert_eq!(text.matches("<circle").count(), 1);
        assert!(text.contains("species 0 (1 drawn)") && text.contains("species 1 (0 drawn)"));
        assert!(text.contains("slice x = 2.5<"));

        let colour = ColourBy::Value {
            values: vec![0.5, f64::NAN, 2.0],
            label: "radius <m>".into(),
        };
        let text = svg(&View::Bottom, &pos, &radii, &colour, cube(), 100).unwrap();
        assert_eq!(text.matches("<circle").count(), 3);
        assert!(text.contains("radius &lt;m&gt;") && text.contains("non-finite"));
    }

    #[test]
    fn bad_requests_are_errors() {
        let pos = [Vec3::new(1.0, 1.0, 1.0)];
        let dir = tempfile::tempdir().unwrap();
        let colour = ColourBy::Species(vec![0]);
        let path = dir.path().join("view.jpg");
        assert!(render(&View::Top, &pos, &[1.0], &colour, cube(), &path, 10).is_err());
        let png = dir.path().join("view.png");
        let two = ColourBy::Species(vec![0, 1]);
        assert!(render(&View::Top, &pos, &[1.0], &two, cube(), &png, 10).is_err());
        let flat = [Vec3::zeros(), Vec3::new(1.0, 1.0, 0.0)];
        assert!(render(&View::Top, &pos, &[1.0], &colour, flat, &png, 10).is_err());
        let sideways = View::Slice {
            axis: 2,
            at: 0.5,
            thickness: 0.0,
        };
        assert!(render(&sideways, &pos, &[1.0], &colour, cube(), &png, 10).is_err());
        let missing = dir.path().join("no/such/dir/view.png");
        assert!(render(&View::Top, &pos, &[1.0], &colour, cube(), &missing, 10).is_err());
        assert!(!png.exists());
    }

    /// A binary bed by random deposition: each sphere tries a few spots and settles,
    /// without rolling, at the lowest, which is enough to look like a loose packing.
    fn deposited_bed(n: usize, seed: u64) -> (Vec<Vec3>, Vec<f64>, Vec<usize>, [Vec3; 2]) {
        use rand::{RngExt, SeedableRng};
        let side = 1.0;
        let bounds = [Vec3::zeros(), Vec3::new(side, side, 0.8 * side)];
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        let (mut pos, mut radii, mut species) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..n {
            let s = usize::from(rng.random_range(0.0..1.0) < 0.5);
            let r = if s == 0 { 0.045 } else { 0.033 };
            let mut best = Vec3::new(0.0, 0.0, f64::INFINITY);
            for _ in 0..24 {
                let x = rng.random_range(r..side - r);
                let y = rng.random_range(r..side - r);
                let mut z: f64 = r;
                for (p, &rj) in pos.iter().zip(&radii) {
                    let p: &Vec3 = p;
                    let h2 = (p.x - x).powi(2) + (p.y - y).powi(2);
                    let reach = (r + rj) * (r + rj);
                    if h2 < reach {
                        z = z.max(p.z + (reach - h2).sqrt());
                    }
                }
                if z < best.z {
                    best = Vec3::new(x, y, z);
                }
            }
            pos.push(best);
            radii.push(r);
            species.push(s);
        }
        (pos, radii, species, bounds)
    }

    /// Regenerates the pictures in docs/img: `cargo test --release views -- --ignored`.
    #[test]
    #[ignore]
    fn docs_example_images() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/img");
        crate::output::create_dir(&dir).unwrap();
        let (pos, radii, species, bounds) = deposited_bed(1000, 2009);
        let colour = ColourBy::Species(species);
        let slice = View::Slice {
            axis: 0,
            at: 0.5,
            thickness: 0.0,
        };
        for (view, name) in [
            (View::Top, "views-top.png"),
            (View::Bottom, "views-bottom.png"),
            (slice, "views-slice-x.png"),
            (slice, "views-slice-x.svg"),
        ] {
            render(&view, &pos, &radii, &colour, bounds, &dir.join(name), 200).unwrap();
        }
        let heights = ColourBy::Value {
            values: pos.iter().map(|p| p.z).collect(),
            label: "height z / m".into(),
        };
        let path = dir.join("views-top-height.png");
        render(&View::Top, &pos, &radii, &heights, bounds, &path, 200).unwrap();
    }
}
