//! Line plots as SVG (plotters), for curves people compare with the papers'
//! figures. Rendered to a string and written atomically like every output.

use crate::error::{Result, TampError};
use plotters::prelude::*;
use std::path::Path;

pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
    /// Markers at the points: for sparse data such as a paper's stated values.
    pub markers: bool,
    /// A line through the points: for curves.
    pub line: bool,
}

impl Series {
    pub fn line(name: &str, points: Vec<(f64, f64)>) -> Self {
        Series {
            name: name.to_string(),
            points,
            markers: false,
            line: true,
        }
    }

    pub fn points(name: &str, points: Vec<(f64, f64)>) -> Self {
        Series {
            name: name.to_string(),
            points,
            markers: true,
            line: false,
        }
    }
}

pub struct Panel<'a> {
    pub title: &'a str,
    pub x_label: &'a str,
    pub y_label: &'a str,
    pub log_y: bool,
    pub log_x: bool,
    pub series: &'a [Series],
}

fn bounds(series: &[Series], log_x: bool, log_y: bool) -> (f64, f64, f64, f64) {
    let pts = series.iter().flat_map(|s| s.points.iter());
    let pts: Vec<&(f64, f64)> = pts.filter(|p| shown(p, log_x, log_y)).collect();
    let fold = |f: fn(&(f64, f64)) -> f64| {
        pts.iter()
            .map(|p| f(p))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            })
    };
    let (x0, x1) = fold(|p| p.0);
    let (y0, y1) = fold(|p| p.1);
    (x0, x1, y0, y1)
}

/// A point a panel can draw: finite, and positive on a logarithmic axis.
fn shown(p: &(f64, f64), log_x: bool, log_y: bool) -> bool {
    p.0.is_finite() && p.1.is_finite() && (!log_x || p.0 > 0.0) && (!log_y || p.1 > 0.0)
}

fn draw_err<E: std::fmt::Debug>(e: E) -> TampError {
    TampError::Other(format!("plotting failed: {e:?}"))
}

/// Panels side by side in one SVG file.
pub fn write_svg(path: &Path, panels: &[Panel]) -> Result<()> {
    let mut svg = String::new();
    {
        let width = 640 * panels.len() as u32;
        let root = SVGBackend::with_string(&mut svg, (width, 480)).into_drawing_area();
        root.fill(&WHITE).map_err(draw_err)?;
        let areas = root.split_evenly((1, panels.len()));
        for (area, panel) in areas.iter().zip(panels) {
            let (x0, x1, y0, y1) = bounds(panel.series, panel.log_x, panel.log_y);
            // A log axis over one value would be empty: widen it by a factor 2.
            let (x0, x1) = if panel.log_x && x0 == x1 {
                (x0 / 2.0, x1 * 2.0)
            } else {
                (x0, x1)
            };
            let (y0, y1) = if panel.log_y && y0 == y1 {
                (y0 / 2.0, y1 * 2.0)
            } else {
                (y0, y1)
            };
            let mut builder = ChartBuilder::on(area);
            builder
                .caption(panel.title, ("sans-serif", 18))
                .margin(12)
                .x_label_area_size(40)
                .y_label_area_size(70);
            // Ten distinct colours: the NiAl density plot has nine series, and a
            // repeated colour made two of its curves indistinguishable.
            let colors = [
                &BLUE,
                &RED,
                &GREEN,
                &MAGENTA,
                &BLACK,
                &CYAN,
                &RGBColor(230, 140, 0),
                &RGBColor(120, 60, 160),
                &RGBColor(140, 90, 40),
                &RGBColor(128, 128, 128),
            ];
            macro_rules! draw {
                ($chart:expr) => {{
                    let mut chart = $chart;
                    chart
                        .configure_mesh()
                        .x_desc(panel.x_label)
                        .y_desc(panel.y_label)
                        .draw()
                        .map_err(draw_err)?;
                    for (k, s) in panel.series.iter().enumerate() {
                        let color = colors[k % colors.len()];
                        let shown = || {
                            s.points
                                .iter()
                                .cloned()
                                .filter(|p| shown(p, panel.log_x, panel.log_y))
                        };
                        if s.line {
                            chart
                                .draw_series(LineSeries::new(shown(), color))
                                .map_err(draw_err)?;
                        }
                        if s.markers {
                            chart
                                .draw_series(shown().map(|p| Circle::new(p, 4, color.filled())))
                                .map_err(draw_err)?;
                        }
                        // An empty series only to carry the legend entry.
                        chart
                            .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())
                            .map_err(draw_err)?
                            .label(s.name.as_str())
                            .legend(move |(x, y)| {
                                PathElement::new(vec![(x, y), (x + 20, y)], color)
                            });
                    }
                    chart
                        .configure_series_labels()
                        .background_style(WHITE.mix(0.8))
                        .border_style(BLACK)
                        .draw()
                        .map_err(draw_err)?;
                }};
            }
            if panel.log_x && panel.log_y {
                draw!(
                    builder
                        .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())
                        .map_err(draw_err)?
                );
            } else if panel.log_x {
                draw!(
                    builder
                        .build_cartesian_2d((x0..x1).log_scale(), y0..y1)
                        .map_err(draw_err)?
                );
            } else if panel.log_y {
                draw!(
                    builder
                        .build_cartesian_2d(x0..x1, (y0..y1).log_scale())
                        .map_err(draw_err)?
                );
            } else {
                draw!(
                    builder
                        .build_cartesian_2d(x0..x1, y0..y1)
                        .map_err(draw_err)?
                );
            }
        }
        root.present().map_err(draw_err)?;
    }
    crate::output::write_atomic(path, svg.as_bytes())
}

/// Line segments drawn to scale (equal units on both axes) over the box
/// [x0, x1] × [y0, y1], with the box outlined: a contact network, one segment per
/// contact between the centres it joins (Redanz & Fleck 2001 Fig 3), each with its
/// line width in pixels (a force chain: width by force).
pub fn write_segments_svg(
    path: &Path,
    title: &str,
    (x0, x1, y0, y1): (f64, f64, f64, f64),
    segments: &[([(f64, f64); 2], u32)],
) -> Result<()> {
    let mut svg = String::new();
    {
        // Equal units on both axes: the plot area is `side` pixels wide and
        // side × aspect high, plus 50 px of y labels and margins of 10 px, and
        // about 75 px of caption and x labels.
        let side = 700u32;
        let aspect = ((y1 - y0) / (x1 - x0)).clamp(0.1, 10.0);
        let height = (side as f64 * aspect) as u32 + 75;
        let root = SVGBackend::with_string(&mut svg, (side + 70, height)).into_drawing_area();
        root.fill(&WHITE).map_err(draw_err)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 18))
            .margin(10)
            .x_label_area_size(30)
            .y_label_area_size(50)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(draw_err)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .draw()
            .map_err(draw_err)?;
        chart
            .draw_series(std::iter::once(PathElement::new(
                vec![(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)],
                BLACK,
            )))
            .map_err(draw_err)?;
        chart
            .draw_series(
                segments
                    .iter()
                    .map(|(s, w)| PathElement::new(vec![s[0], s[1]], BLUE.stroke_width(*w))),
            )
            .map_err(draw_err)?;
        root.present().map_err(draw_err)?;
    }
    crate::output::write_atomic(path, svg.as_bytes())
}
