//! The `walls` of a scene: each boundary is a shape, a material and a motion.
//!
//! ```json
//! {"name": "lid", "material": "steel",
//!  "shape": {"kind": "plane", "point": [0, 0, 0.1], "normal": [0, 0, -1]},
//!  "motion": {"kind": "servo", "direction": [0, 0, -1], "force": 10, "gain": 1e-3, "max_speed": 0.1}}
//! ```
//! Shapes: plane, box (inside of), cylinder, cone, funnel (surfaces of revolution),
//! height_field (z = f(x, y) as an expression or a grid), mesh (STL file or convex
//! polygons). Motions: fixed, velocity, displacement (expressions of t), servo, pressure
//! (a punch of given mass under a ramped pressure).

use super::build::v3;
use super::validate::Errors;
use crate::boundary::shape::Shape;
use crate::boundary::{Boundary, BoundaryMotion, PressureLoad, Servo, WallCurvature};
use crate::error::{Result, TampError};
use crate::expression::Expression;
use crate::particles::Vec3;
use serde::{Deserialize, Serialize};
use std::collections::HashSet;
use std::path::Path;

/// One entry of the scene's `walls`: a rigid boundary that particles touch through a
/// contact law, made of a shape, the material its contacts use, and a prescribed motion.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct WallSpec {
    /// Used in series columns, the summary and messages; `wall<k>` by default.
    #[serde(default)]
    pub name: Option<String>,
    /// Name of an entry of the scene's `materials`: the wall's side of every particle-wall
    /// contact (its E, ν and friction enter E* and the law's coefficients).
    pub material: String,
    /// The surface, in the wall's rest position.
    pub shape: ShapeSpec,
    /// How the surface moves during the run; `fixed` when absent.
    #[serde(default)]
    pub motion: MotionSpec,
}

impl WallSpec {
    /// The wall's name: the given one, or `wall<k>` for the k-th wall of the scene.
    pub fn name(&self, k: usize) -> String {
        self.name.clone().unwrap_or_else(|| format!("wall{k}"))
    }
}

/// The surface of a wall as written in the scene file (`kind` selects the variant);
/// coordinates and lengths in m. [`build`] turns it into a [`Shape`].
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum ShapeSpec {
    /// Infinite one-sided plane; `normal` points to the particles.
    Plane {
        /// A point of the plane, m.
        point: [f64; 3],
        /// Direction towards the particles' side (normalised when built).
        normal: [f64; 3],
    },
    /// The inside of an axis-aligned box; `open` lists missing faces ("+z" for no lid).
    Box {
        /// Corner with the smallest coordinates, m.
        lower: [f64; 3],
        /// Corner with the largest coordinates, m; larger than `lower` on every axis.
        upper: [f64; 3],
        /// Faces left out, among "-x", "+x", "-y", "+y", "-z", "+z".
        #[serde(default)]
        open: Vec<String>,
    },
    /// Lateral surface of a cylinder, between heights `bottom` and `top` along `axis`
    /// measured from `origin`. `curvature`: how the wall's curvature enters the
    /// contact's effective radius, `flat` (the default) or `mean` (`Curvature`).
    Cylinder {
        /// A point on the axis, m; heights are measured along `axis` from it.
        origin: [f64; 3],
        /// Direction of the axis (any non-zero length; normalised when built).
        axis: [f64; 3],
        /// Radius of the cylinder, m.
        radius: f64,
        /// Height of the lower rim along the axis, m.
        bottom: f64,
        /// Height of the upper rim along the axis, m; above `bottom`.
        top: f64,
        /// Flat (the default) or mean-curvature effective radius for its contacts.
        #[serde(default)]
        curvature: Curvature,
    },
    /// Lateral surface of a cone frustum.
    Cone {
        /// A point on the axis, m; heights are measured along `axis` from it.
        origin: [f64; 3],
        /// Direction of the axis (any non-zero length; normalised when built).
        axis: [f64; 3],
        /// Height of the lower rim along the axis, m.
        bottom: f64,
        /// Radius at `bottom`, m; zero puts the apex there.
        bottom_radius: f64,
        /// Height of the upper rim along the axis, m; above `bottom`.
        top: f64,
        /// Radius at `top`, m; zero puts the apex there.
        top_radius: f64,
    },
    /// An outlet tube (from `outlet_bottom` to `outlet_top`) continued by a cone that
    /// widens to `top_radius` at height `top`.
    Funnel {
        /// A point on the axis, m; heights are measured along `axis` from it.
        origin: [f64; 3],
        /// Direction of the axis (any non-zero length; normalised when built).
        axis: [f64; 3],
        /// Radius of the outlet tube, m.
        outlet_radius: f64,
        /// Height of the outlet's lower end along the axis, m.
        outlet_bottom: f64,
        /// Height where the tube meets the cone, m.
        outlet_top: f64,
        /// Radius of the cone at `top`, m; larger than `outlet_radius`.
        top_radius: f64,
        /// Height of the cone's upper rim along the axis, m; above `outlet_top`.
        top: f64,
    },
    /// z = f(x, y) over a rectangle, as an `expression` of x and y sampled on `cells`,
    /// or as a `grid` of heights. Give exactly one of the two.
    HeightField {
        /// Extent [low, high] of the surface along x, m.
        x_range: [f64; 2],
        /// Extent [low, high] of the surface along y, m.
        y_range: [f64; 2],
        /// Height z (m) as an expression of x and y (m); needs `cells`.
        #[serde(default)]
        expression: Option<String>,
        /// Cells along x and y used to sample the expression.
        #[serde(default)]
        cells: Option<[usize; 2]>,
        /// Heights at (nx+1)×(ny+1) nodes, row by row: `grid[j][i]` is at x_i, y_j.
        #[serde(default)]
        grid: Option<Vec<Vec<f64>>>,
    },
    /// Triangles from an STL file (path relative to the scene file) or convex polygons.
    Mesh {
        /// Path of an STL file, relative to the scene file's directory.
        #[serde(default)]
        stl: Option<String>,
        /// Convex polygons, each a list of at least three vertices (m).
        #[serde(default)]
        polygons: Option<Vec<Vec<[f64; 3]>>>,
    },
}

/// How a cylinder wall's curvature enters the contact law's effective radius R*.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Curvature {
    /// R* = R, as against a plane: a die's radius is many particle radii.
    #[default]
    Flat,
    /// The wall as the sphere of its mean curvature, radius 2R_c (concave inside):
    /// R* = 2R R_c/(2R_c − R) inside. LAMMPS's rule for `fix wall/gran zcylinder` and
    /// `region cylinder` walls; `Boundary::effective_radius` has the formula and source.
    Mean,
}

/// How a wall moves, as written in the scene file (`kind` selects the variant).
#[derive(Clone, Debug, Default, Deserialize, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum MotionSpec {
    /// The wall stays at its rest position.
    #[default]
    Fixed,
    /// Constant velocity, m/s.
    Velocity {
        /// Velocity of the wall, m/s.
        velocity: [f64; 3],
    },
    /// Displacement from the rest position, per axis, as expressions of t (s → m).
    Displacement {
        /// Displacement along x (m) as an expression of t (s).
        x: String,
        /// Displacement along y (m) as an expression of t (s).
        y: String,
        /// Displacement along z (m) as an expression of t (s).
        z: String,
    },
    /// Hold `force` (N), or `pressure` (Pa) × `area` (m²), along `direction`.
    Servo {
        /// Direction in which the wall presses on the particles (normalised when built).
        direction: [f64; 3],
        /// Target reaction of the particles on the wall, N; instead of `pressure` and `area`.
        #[serde(default)]
        force: Option<f64>,
        /// Target pressure, Pa; the target force is `pressure` × `area`.
        #[serde(default)]
        pressure: Option<f64>,
        /// Area the target pressure acts on, m².
        #[serde(default)]
        area: Option<f64>,
        /// Speed per newton of force error, m/(s·N).
        gain: f64,
        /// Largest speed the servo commands, m/s.
        max_speed: f64,
    },
    /// A punch of `mass` (kg) pushed along `direction` by a pressure on `area` (m²)
    /// rising linearly from 0 to `pressure` (Pa) over `ramp_time` (s), then held; it
    /// moves by Newton's law under the load and the particles' reaction.
    Pressure {
        /// Direction in which the punch presses on the particles (normalised when built).
        direction: [f64; 3],
        /// Final pressure, Pa.
        pressure: f64,
        /// Loaded area, m².
        area: f64,
        /// Time over which the pressure rises linearly from zero, s (0: applied at once).
        ramp_time: f64,
        /// Mass of the punch, kg.
        mass: f64,
    },
}

const FACES: [&str; 6] = ["-x", "+x", "-y", "+y", "-z", "+z"];

fn unit(e: &mut Errors, path: String, v: &[f64; 3]) {
    let len = v.iter().map(|c| c * c).sum::<f64>().sqrt();
    if !(len > 0.0 && len.is_finite()) {
        e.push(path, format!("must have non-zero finite length, got {v:?}"));
    }
}

fn range(e: &mut Errors, path: String, r: &[f64; 2]) {
    if !(r[0].is_finite() && r[1].is_finite() && r[1] > r[0]) {
        e.push(
            path,
            format!("must be [low, high] with high > low, finite, got {r:?}"),
        );
    }
}

pub(super) fn validate(walls: &[WallSpec], known: &dyn Fn(&str) -> bool, e: &mut Errors) {
    let mut names = HashSet::new();
    for (k, w) in walls.iter().enumerate() {
        let at = |field: &str| format!("walls[{k}].{field}");
        let name = w.name(k);
        if !names.insert(name.clone()) {
            e.push(at("name"), format!("must be unique, '{name}' is repeated"));
        }
        if !known(&w.material) {
            e.push(at("material"), format!("unknown material '{}'", w.material));
        }
        validate_shape(&w.shape, &at, e);
        validate_motion(&w.motion, &at, e);
    }
}

/// `at(field)` is the JSON path of a field of this wall.
fn validate_shape(shape: &ShapeSpec, at: &dyn Fn(&str) -> String, e: &mut Errors) {
    match shape {
        ShapeSpec::Plane { point, normal } => {
            e.finite3(at("shape.point"), point);
            unit(e, at("shape.normal"), normal);
        }
        ShapeSpec::Box { lower, upper, open } => {
            e.finite3(at("shape.lower"), lower);
            e.finite3(at("shape.upper"), upper);
            if (0..3).any(|a| upper[a] <= lower[a]) {
                e.push(
                    at("shape.upper"),
                    format!("must exceed shape.lower on every axis, got {upper:?} vs {lower:?}"),
                );
            }
            for (j, f) in open.iter().enumerate() {
                if !FACES.contains(&f.as_str()) {
                    e.push(
                        at(&format!("shape.open[{j}]")),
                        format!("unknown face '{f}', expected one of {FACES:?}"),
                    );
                }
            }
        }
        ShapeSpec::Cylinder {
            origin,
            axis,
            radius,
            bottom,
            top,
            curvature: _,
        } => {
            e.finite3(at("shape.origin"), origin);
            unit(e, at("shape.axis"), axis);
            e.positive(at("shape.radius"), *radius);
            range(e, at("shape.top"), &[*bottom, *top]);
        }
        ShapeSpec::Cone {
            origin,
            axis,
            bottom,
            bottom_radius,
            top,
            top_radius,
        } => {
            e.finite3(at("shape.origin"), origin);
            unit(e, at("shape.axis"), axis);
            e.non_negative(at("shape.bottom_radius"), *bottom_radius);
            e.non_negative(at("shape.top_radius"), *top_radius);
            if *bottom_radius == 0.0 && *top_radius == 0.0 {
                e.push(
                    at("shape.top_radius"),
                    "a cone needs a non-zero radius at one end at least",
                );
            }
            range(e, at("shape.top"), &[*bottom, *top]);
        }
        ShapeSpec::Funnel {
            origin,
            axis,
            outlet_radius,
            outlet_bottom,
            outlet_top,
            top_radius,
            top,
        } => {
            e.finite3(at("shape.origin"), origin);
            unit(e, at("shape.axis"), axis);
            e.positive(at("shape.outlet_radius"), *outlet_radius);
            range(e, at("shape.outlet_top"), &[*outlet_bottom, *outlet_top]);
            range(e, at("shape.top"), &[*outlet_top, *top]);
            if !(top_radius > outlet_radius && top_radius.is_finite()) {
                e.push(
                    at("shape.top_radius"),
                    format!("must exceed outlet_radius ({outlet_radius:e}), got {top_radius:e}"),
                );
            }
        }
        ShapeSpec::HeightField {
            x_range,
            y_range,
            expression,
            cells,
            grid,
        } => {
            range(e, at("shape.x_range"), x_range);
            range(e, at("shape.y_range"), y_range);
            match (expression, grid) {
                (Some(expr), None) => {
                    if let Err(msg) = Expression::parse(expr, &["x", "y"]) {
                        e.push(at("shape.expression"), msg);
                    }
                    match cells {
                        Some([nx, ny]) if *nx >= 1 && *ny >= 1 => {}
                        _ => e.push(
                            at("shape.cells"),
                            "is required with an expression: [nx, ny], each >= 1",
                        ),
                    }
                }
                (None, Some(g)) => {
                    if cells.is_some() {
                        e.push(
                            at("shape.cells"),
                            "must be absent with a grid (the grid's shape gives the cells)",
                        );
                    }
                    let rows = g.len();
                    let cols = g.first().map_or(0, Vec::len);
                    if rows < 2 || cols < 2 || g.iter().any(|r| r.len() != cols) {
                        e.push(at("shape.grid"), format!("must be a rectangular array of at least 2 x 2 heights, got {rows} rows"));
                    } else if g.iter().flatten().any(|z| !z.is_finite()) {
                        e.push(at("shape.grid"), "heights must be finite");
                    }
                }
                _ => e.push(
                    at("shape"),
                    "give exactly one of 'expression' (with 'cells') or 'grid'",
                ),
            }
        }
        ShapeSpec::Mesh { stl, polygons } => match (stl, polygons) {
            (Some(_), None) => {}
            (None, Some(p)) => {
                for (j, poly) in p.iter().enumerate() {
                    if poly.len() < 3 {
                        e.push(
                            at(&format!("shape.polygons[{j}]")),
                            format!("needs at least 3 vertices, got {}", poly.len()),
                        );
                    }
                    for (v, x) in poly.iter().enumerate() {
                        e.finite3(at(&format!("shape.polygons[{j}][{v}]")), x);
                    }
                }
            }
            _ => e.push(
                at("shape"),
                "give exactly one of 'stl' (a file path) or 'polygons'",
            ),
        },
    }
}

fn validate_motion(motion: &MotionSpec, at: &dyn Fn(&str) -> String, e: &mut Errors) {
    match motion {
        MotionSpec::Fixed => {}
        MotionSpec::Velocity { velocity } => e.finite3(at("motion.velocity"), velocity),
        MotionSpec::Displacement { x, y, z } => {
            for (axis, src) in [("x", x), ("y", y), ("z", z)] {
                if let Err(msg) = Expression::parse(src, &["t"]) {
                    e.push(at(&format!("motion.{axis}")), msg);
                }
            }
        }
        MotionSpec::Servo {
            direction,
            force,
            pressure,
            area,
            gain,
            max_speed,
        } => {
            unit(e, at("motion.direction"), direction);
            match (force, pressure, area) {
                (Some(f), None, None) => e.non_negative(at("motion.force"), *f),
                (None, Some(p), Some(a)) => {
                    e.non_negative(at("motion.pressure"), *p);
                    e.positive(at("motion.area"), *a);
                }
                _ => e.push(
                    at("motion"),
                    "give either 'force' (N) or both 'pressure' (Pa) and 'area' (m²)",
                ),
            }
            e.positive(at("motion.gain"), *gain);
            e.positive(at("motion.max_speed"), *max_speed);
        }
        MotionSpec::Pressure {
            direction,
            pressure,
            area,
            ramp_time,
            mass,
        } => {
            unit(e, at("motion.direction"), direction);
            e.non_negative(at("motion.pressure"), *pressure);
            e.positive(at("motion.area"), *area);
            e.non_negative(at("motion.ramp_time"), *ramp_time);
            e.positive(at("motion.mass"), *mass);
        }
    }
}

fn build_motion(m: &MotionSpec) -> BoundaryMotion {
    match m {
        MotionSpec::Fixed => BoundaryMotion::Fixed,
        MotionSpec::Velocity { velocity } => BoundaryMotion::Velocity(v3(velocity)),
        MotionSpec::Displacement { x, y, z } => {
            let parse = |s: &str| Expression::parse(s, &["t"]).expect("validated expression");
            BoundaryMotion::Displacement(Box::new([parse(x), parse(y), parse(z)]))
        }
        MotionSpec::Servo {
            direction,
            force,
            pressure,
            area,
            gain,
            max_speed,
        } => BoundaryMotion::Servo(Servo {
            direction: v3(direction).normalize(),
            target_force: force.unwrap_or_else(|| pressure.unwrap_or(0.0) * area.unwrap_or(0.0)),
            gain: *gain,
            max_speed: *max_speed,
        }),
        MotionSpec::Pressure {
            direction,
            pressure,
            area,
            ramp_time,
            mass,
        } => BoundaryMotion::Pressed(PressureLoad {
            direction: v3(direction).normalize(),
            pressure: *pressure,
            area: *area,
            ramp_time: *ramp_time,
            mass: *mass,
        }),
    }
}

/// Build the boundaries; `base_dir` resolves relative STL paths.
pub fn build(
    walls: &[WallSpec],
    material_id: &dyn Fn(&str) -> usize,
    base_dir: &Path,
) -> Result<Vec<Boundary>> {
    walls
        .iter()
        .enumerate()
        .map(|(k, w)| {
            let shape = build_shape(&w.shape, base_dir)
                .map_err(|rule| TampError::input(format!("walls[{k}].shape"), rule))?;
            let mut wall = Boundary::new(
                w.name(k),
                shape,
                material_id(&w.material),
                build_motion(&w.motion),
            );
            if let ShapeSpec::Cylinder {
                origin,
                axis,
                radius,
                curvature: Curvature::Mean,
                ..
            } = &w.shape
            {
                wall.curvature = WallCurvature::Mean {
                    origin: v3(origin),
                    axis: v3(axis).normalize(),
                    radius: *radius,
                };
            }
            Ok(wall)
        })
        .collect()
}

fn build_shape(s: &ShapeSpec, base_dir: &Path) -> std::result::Result<Shape, String> {
    use crate::boundary::shape::{BoxShape, Mesh, Plane, Revolved};
    let rule = |e: TampError| match e {
        TampError::Input { path, rule } => format!("{path}: {rule}"),
        other => other.to_string(),
    };
    Ok(match s {
        ShapeSpec::Plane { point, normal } => Shape::Plane(Plane {
            point: v3(point),
            normal: v3(normal).normalize(),
        }),
        ShapeSpec::Box { lower, upper, open } => {
            let faces: [bool; 6] = std::array::from_fn(|k| !open.iter().any(|f| f == FACES[k]));
            Shape::Box(BoxShape::with_faces(v3(lower), v3(upper), faces).map_err(rule)?)
        }
        ShapeSpec::Cylinder {
            origin,
            axis,
            radius,
            bottom,
            top,
            curvature: _,
        } => Shape::Revolved(
            Revolved::cylinder(v3(origin), v3(axis), *radius, *bottom, *top).map_err(rule)?,
        ),
        ShapeSpec::Cone {
            origin,
            axis,
            bottom,
            bottom_radius,
            top,
            top_radius,
        } => Shape::Revolved(
            Revolved::cone(
                v3(origin),
                v3(axis),
                (*bottom_radius, *bottom),
                (*top_radius, *top),
            )
            .map_err(rule)?,
        ),
        ShapeSpec::Funnel {
            origin,
            axis,
            outlet_radius,
            outlet_bottom,
            outlet_top,
            top_radius,
            top,
        } => Shape::Revolved(
            Revolved::funnel(
                v3(origin),
                v3(axis),
                *outlet_radius,
                *outlet_bottom,
                *outlet_top,
                *top_radius,
                *top,
            )
            .map_err(rule)?,
        ),
        ShapeSpec::HeightField {
            x_range,
            y_range,
            expression,
            cells,
            grid,
        } => {
            let mesh = match (expression, grid) {
                (Some(src), _) => {
                    let f = Expression::parse(src, &["x", "y"])?;
                    let [nx, ny] = cells.unwrap_or([1, 1]);
                    let failure = std::cell::RefCell::new(None);
                    let mesh = Mesh::from_height_fn(
                        (x_range[0], x_range[1]),
                        (y_range[0], y_range[1]),
                        nx + 1,
                        ny + 1,
                        |x, y| match f.eval(&[x, y]) {
                            Ok(z) if z.is_finite() => z,
                            Ok(z) => {
                                failure.borrow_mut().get_or_insert(format!(
                                    "expression is {z} at x = {x:e}, y = {y:e}"
                                ));
                                0.0
                            }
                            Err(e) => {
                                failure.borrow_mut().get_or_insert(e);
                                0.0
                            }
                        },
                    )
                    .map_err(rule)?;
                    if let Some(f) = failure.into_inner() {
                        return Err(f);
                    }
                    mesh
                }
                (None, Some(g)) => {
                    let (ny, nx) = (g.len(), g[0].len());
                    let z: Vec<f64> = g.iter().flatten().copied().collect();
                    let dx = (x_range[1] - x_range[0]) / (nx - 1) as f64;
                    let dy = (y_range[1] - y_range[0]) / (ny - 1) as f64;
                    Mesh::from_height_grid(x_range[0], y_range[0], dx, dy, nx, ny, &z)
                        .map_err(rule)?
                }
                (None, None) => unreachable!("validated"),
            };
            Shape::Mesh(mesh)
        }
        ShapeSpec::Mesh { stl, polygons } => Shape::Mesh(match (stl, polygons) {
            (Some(path), _) => Mesh::from_stl(base_dir.join(path)).map_err(rule)?,
            (None, Some(p)) => {
                let polys: Vec<Vec<Vec3>> =
                    p.iter().map(|poly| poly.iter().map(v3).collect()).collect();
                Mesh::from_polygons(&polys).map_err(rule)?
            }
            (None, None) => unreachable!("validated"),
        }),
    })
}
