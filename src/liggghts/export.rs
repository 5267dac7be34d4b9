//! `tamp export-liggghts SCENE --out DIR`: the same scene as a LIGGGHTS-PUBLIC 3.8
//! deck, or a refusal listing every field LIGGGHTS cannot express (exit 2).
//!
//! What the deck holds, and why it is written this way:
//! - The particles as tamp placed them at t = 0 (`particles.data`, read with
//!   `read_data`): tamp's seeded insertion and deposition run first, so both codes
//!   start from the same state. LIGGGHTS's own insertion would draw other positions.
//! - One atom type per tamp material (type k + 1 = `materials[k]`); a wall's type is
//!   its material's, so LIGGGHTS mixes E*, G* and μ for walls as tamp does.
//! - The normal law writes its own `model` and properties
//!   (`NormalModel::liggghts_deck`, in the law's file); this file asks it, and
//!   refuses the law when it has none. Today:
//!   `model hertz` for `hertz`; `model hooke` for `linear` with a restitution-based
//!   damping, `characteristicVelocity` chosen so that LIGGGHTS's k_n equals tamp's k
//!   (refused when the k_n LIGGGHTS derives per contact kind differs: it depends on
//!   m*, R*); `model hooke/stiffness absolute_damping on` for `linear` with a
//!   constant γ_n. The damping is LIGGGHTS's `coefficientRestitution` e, obtained
//!   from tamp's ξ by inverting the mapping of contact/damping/liggghts.rs.
//! - `tangential history` for tamp's `liggghts_history`; no friction is
//!   `coefficientFriction 0`, which makes the history force exactly zero.
//! - Axis-aligned planes, box faces and axis-aligned cylinders as LIGGGHTS primitive
//!   walls (two-sided and infinite in LIGGGHTS: the same as tamp's one-sided, finite
//!   ones as long as the particles stay inside); every other boundary, and every
//!   moving one, as an ASCII STL mesh (`meshes/`), moved by `fix move/mesh`.
//! - `hard_particles yes` when some E > 1e9 Pa and `soft_particles yes` when some
//!   E < 5e6 Pa: LIGGGHTS 3.8 refuses such moduli in SI units otherwise.
//! - Dumps at `%.17g` so that trajectories compare to the last bit: every
//!   `dump_every` steps to `dump.liggghts`, and the final state to `final.liggghts`.

use crate::boundary::shape::{Revolved, Shape, Triangle};
use crate::contact::damping::liggghts::LiggghtsModel;
use crate::contact::damping::liggghts::{SQRT_FIVE_SIXTHS, restitution_from_beta};
use crate::contact::damping::{CriticalFraction, Damping, LiggghtsRestitution};
use crate::contact::lever_arm::LeverArm;
use crate::contact::model::{LiggghtsContact, LiggghtsScene, LiggghtsValues};
use crate::contact::tangential::TangentialLaw;
use crate::error::{Result, TampError};
use crate::material::{effective_mass, effective_modulus, effective_radius};
use crate::particles::Vec3;
use crate::peer_deck::{
    Exported, LIGGGHTS, box_axes, build_unless_refused, frame_every, head, integrate_and_run,
    neighbor_skin, scene_refusals, timestep_and_gravity,
};
use crate::scene::Scene;
use crate::scene::walls::{Curvature, MotionSpec, ShapeSpec};
use std::fmt::Write as _;
use std::path::Path;

/// Facets around a revolved boundary written as STL (cone, funnel, tilted cylinder).
const REVOLVED_SEGMENTS: usize = 96;

/// The contact model line and its material properties.
pub(super) struct ContactModel {
    pub(super) pair_style: String,
    pub(super) properties: Vec<String>,
}

/// LIGGGHTS's restitution for the scene's damping, or why there is none.
fn restitution(scene: &Scene) -> std::result::Result<f64, (String, String)> {
    let hertz = scene.contact.normal.liggghts() == Some(LiggghtsModel::Hertz);
    let e = match &scene.contact.dashpot() {
        None => 1.0,
        Some(Damping::LiggghtsRestitution(LiggghtsRestitution { restitution })) => *restitution,
        Some(Damping::CriticalFraction(CriticalFraction { xi })) => {
            // ξ = −√(5/6) β for hertz, −β for linear (contact/damping/liggghts.rs).
            let beta = if hertz { -xi / SQRT_FIVE_SIXTHS } else { -xi };
            if beta <= -1.0 {
                return Err((
                    "contact.damping.xi".into(),
                    format!(
                        "{xi} is beyond what a LIGGGHTS restitution coefficient can express (ξ < {} for this law)",
                        if hertz { SQRT_FIVE_SIXTHS } else { 1.0 }
                    ),
                ));
            }
            restitution_from_beta(beta)
        }
        Some(Damping::Constant(_)) => unreachable!("handled by the caller"),
        Some(d @ (Damping::MassVelocity(_) | Damping::Viscoelastic(_))) => {
            return Err((
                "contact.damping.kind".into(),
                format!(
                    "LAMMPS's {} has no LIGGGHTS 3.8 model (its dashpot is not a fraction of critical)",
                    d.name()
                ),
            ));
        }
        Some(Damping::Tsuji(t)) => {
            let xi = t.with(&scene.contact.normal).map(|d| d.xi);
            return Err((
                "contact.damping.kind".into(),
                format!(
                    "LAMMPS's tsuji has no LIGGGHTS 3.8 model (the same dashpot is critical_fraction with xi = {})",
                    xi.map_or_else(|e| e, |x| format!("{x:e}"))
                ),
            ));
        }
    };
    if !(e > 0.05 && e <= 1.0) {
        return Err((
            "contact.damping".into(),
            format!("gives restitution {e}, outside LIGGGHTS's 0.05 < e <= 1"),
        ));
    }
    Ok(e)
}

/// Every field of `scene` LIGGGHTS 3.8 cannot express, as (path, reason).
pub fn refusals(scene: &Scene) -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = Vec::new();
    let mut refuse = |path: &str, why: &str| out.push((path.to_string(), why.to_string()));
    if scene.output.trajectory_every_step_from.is_some() {
        refuse(
            "output.trajectory_every_step_from",
            "the exported deck dumps at one interval",
        );
    }
    if scene.contact.rolling.is_some() {
        refuse(
            "contact.rolling",
            "LIGGGHTS 3.8's rolling_friction models (cdt, epsd, epsd2, epsd3) are not LAMMPS's sds rolling resistance, the only one tamp has",
        );
    }
    // The law's own rules; the contact kinds are checked after the scene is built.
    match scene.contact.normal.liggghts_deck(&deck_scene(scene, None)) {
        None => refuse(
            "contact.normal.law",
            &format!(
                "LIGGGHTS 3.8 has no counterpart of '{}' (exportable: {})",
                scene.contact.normal.name(),
                exportable_laws()
            ),
        ),
        Some(Err(list)) => {
            for (path, why) in list {
                refuse(&path, &why);
            }
        }
        Some(Ok(_)) => {}
    }
    match &scene.contact.dashpot() {
        Some(Damping::Constant(_)) | None => {}
        _ => {
            if let Err((path, why)) = restitution(scene) {
                refuse(&path, &why);
            }
        }
    }
    if let Some(t) = &scene.contact.tangential {
        if scene.contact.lever_arm != LeverArm::MidOverlap {
            refuse(
                "contact.lever_arm",
                &format!(
                    "LIGGGHTS 3.8 takes R − δ/2 for the contact-point velocity and the torque, pairs and walls ('mid_overlap'); got '{}'",
                    scene.contact.lever_arm.name()
                ),
            );
        }
        if !matches!(t.law, TangentialLaw::LiggghtsHistory(_)) {
            refuse(
                "contact.tangential.law",
                &format!(
                    "'{}' is not LIGGGHTS's tangential model; 'liggghts_history' is (tangential history)",
                    t.law.name()
                ),
            );
        }
        match &scene.rotation {
            None => refuse(
                "rotation",
                "LIGGGHTS's fix nve/sphere always integrates rotation: a scene with friction must enable rotation",
            ),
            Some(r) if r.inertia_scale != 1.0 => refuse(
                "rotation.inertia_scale",
                "LIGGGHTS uses the moment of inertia of a solid sphere (scale 1)",
            ),
            _ => {}
        }
    }
    if scene.contact.cohesion.is_some() {
        refuse(
            "contact.cohesion",
            "LIGGGHTS 3.8 has no van der Waals (Hamaker) cohesion model",
        );
    }
    for (path, why) in scene_refusals(scene, LIGGGHTS) {
        refuse(&path, &why);
    }
    for (k, m) in scene.materials.iter().enumerate() {
        if m.rigid {
            // An atom type's youngsModulus must be finite: a stand-in stiffness would
            // be a different scene, so the user chooses it.
            refuse(
                &format!("materials[{k}].rigid"),
                "LIGGGHTS has no rigid material (every atom type needs a finite youngsModulus and poissonsRatio); give the wall material elastic constants",
            );
            continue;
        }
        if m.youngs_modulus.is_none() {
            refuse(
                &format!("materials[{k}].youngs_modulus"),
                "LIGGGHTS needs youngsModulus for every atom type",
            );
        }
        match m.poisson_ratio {
            None => refuse(
                &format!("materials[{k}].poisson_ratio"),
                "LIGGGHTS needs poissonsRatio for every atom type",
            ),
            Some(nu) if !(0.0..=0.5).contains(&nu) => refuse(
                &format!("materials[{k}].poisson_ratio"),
                "LIGGGHTS requires 0 <= poissonsRatio <= 0.5",
            ),
            _ => {}
        }
    }
    for (k, w) in scene.walls.iter().enumerate() {
        if let ShapeSpec::Cylinder {
            curvature: Curvature::Mean,
            ..
        } = w.shape
        {
            refuse(
                &format!("walls[{k}].shape.curvature"),
                "LIGGGHTS's cylinder walls (primitive or mesh) give a sphere the effective radius R, as against a plane: tamp's \"flat\" cylinder, not \"mean\"",
            );
        }
        match &w.motion {
            MotionSpec::Fixed | MotionSpec::Velocity { .. } => {}
            MotionSpec::Displacement { .. } => refuse(
                &format!("walls[{k}].motion"),
                "displacement expressions are not exported (only fixed and constant-velocity walls)",
            ),
            MotionSpec::Servo { .. } => refuse(
                &format!("walls[{k}].motion"),
                "servo walls are not exported (LIGGGHTS's mesh/surface/stress/servo has another control law)",
            ),
            MotionSpec::Pressure { .. } => refuse(
                &format!("walls[{k}].motion"),
                "pressure-loaded punches are not exported (LIGGGHTS 3.8 moves meshes only kinematically or by its servo)",
            ),
        }
    }
    out
}

pub(super) fn refuse_all(list: Vec<(String, String)>) -> TampError {
    crate::error::cannot_export("LIGGGHTS 3.8", list)
}

/// Axis index of a unit vector along ±x, ±y or ±z.
fn axis_of(v: &Vec3) -> Option<usize> {
    (0..3).find(|&a| v[a].abs() == v.norm() && v.norm() > 0.0)
}

const AXES: [&str; 3] = ["x", "y", "z"];

pub(super) use crate::decimal::g;

/// The normal laws LIGGGHTS 3.8 has, as "law → model" (from the registry).
fn exportable_laws() -> String {
    let scene = LiggghtsScene {
        damping: None,
        tangential: false,
        types: 1,
        friction: vec![0.0],
        restitution: Some(1.0),
        contacts: Vec::new(),
    };
    let mut laws: Vec<String> = crate::contact::registry::normal_laws()
        .iter()
        .filter_map(|law| {
            let deck = law.liggghts_deck(&scene)?.ok()?;
            Some(format!("{} → model {}", law.name(), deck.model))
        })
        .collect();
    laws.sort();
    laws.join(", ")
}

/// What the normal law's deck entry reads from the scene; before the scene is built
/// (`sim` None) it has no contact kinds and zero friction.
fn deck_scene<'a>(
    scene: &'a Scene,
    sim: Option<&crate::simulation::Simulation>,
) -> LiggghtsScene<'a> {
    let types = scene.materials.len();
    let friction = match sim {
        Some(sim) if scene.contact.tangential.is_some() => (0..types * types)
            .map(|k| sim.model().pair_table.get(k / types, k % types).friction)
            .collect(),
        _ => vec![0.0; types * types],
    };
    LiggghtsScene {
        damping: scene.contact.damping.as_ref().map(|d| &d.kind),
        tangential: scene.contact.tangential.is_some(),
        types,
        friction,
        restitution: match &scene.contact.dashpot() {
            Some(Damping::Constant(_)) => None,
            _ => restitution(scene).ok(),
        },
        contacts: sim.map(contact_kinds).unwrap_or_default(),
    }
}

/// The contact model of the deck (after `refusals` came back empty).
pub(super) fn contact_model(
    scene: &Scene,
    sim: &crate::simulation::Simulation,
) -> Result<ContactModel> {
    let mut properties = Vec::new();
    let per_type = |f: &dyn Fn(&crate::material::Material) -> f64| -> String {
        sim.model()
            .materials
            .iter()
            .map(|m| g(f(m)))
            .collect::<Vec<_>>()
            .join(" ")
    };
    properties.push(format!(
        "fix m1 all property/global youngsModulus peratomtype {}",
        per_type(&|m| m.youngs_modulus.expect("checked"))
    ));
    properties.push(format!(
        "fix m2 all property/global poissonsRatio peratomtype {}",
        per_type(&|m| m.poisson_ratio.expect("checked"))
    ));
    let n = sim.model().materials.len();
    let deck = match scene
        .contact
        .normal
        .liggghts_deck(&deck_scene(scene, Some(sim)))
    {
        Some(Ok(deck)) => deck,
        Some(Err(list)) => return Err(refuse_all(list)),
        None => unreachable!("refused by `refusals`"),
    };
    for (k, p) in deck.properties.iter().enumerate() {
        let values = match &p.values {
            LiggghtsValues::Scalar(v) => format!("scalar {}", g(*v)),
            LiggghtsValues::PerType(v) => format!("peratomtype {}", join(v)),
            LiggghtsValues::PerTypePair(v) => format!("peratomtypepair {n} {}", join(v)),
        };
        properties.push(format!(
            "fix m{} all property/global {} {values}",
            k + 3,
            p.name
        ));
    }
    let tangential = "tangential history";
    let mut pair_style = if deck.options.is_empty() {
        format!("model {} {tangential}", deck.model)
    } else {
        format!("model {} {tangential} {}", deck.model, deck.options)
    };
    // The no-pull clamp, after the models as every model keyword (walls take this
    // line too).
    if scene.contact.damping.is_some_and(|d| d.limit) {
        pair_style.push_str(" limitForce on");
    }
    Ok(ContactModel {
        pair_style,
        properties,
    })
}

/// Values separated by spaces, each as `g` writes it.
fn join(values: &[f64]) -> String {
    values.iter().map(|v| g(*v)).collect::<Vec<_>>().join(" ")
}

/// The contact kinds of a scene: every pair of particle classes (mass, radius,
/// material) and every class against every wall.
fn contact_kinds(sim: &crate::simulation::Simulation) -> Vec<LiggghtsContact> {
    let p = &sim.state().particles;
    let mut classes: Vec<(f64, f64, usize)> = Vec::new();
    for i in 0..p.len() {
        let c = (p.mass[i], p.radius[i], p.material[i]);
        if !classes.contains(&c) {
            classes.push(c);
            if classes.len() > 64 {
                break;
            }
        }
    }
    let e_star = |a: usize, b: usize| {
        effective_modulus(&sim.model().materials[a], &sim.model().materials[b]).expect("checked")
    };
    let mut kinds = Vec::new();
    for (k, a) in classes.iter().enumerate() {
        for b in &classes[k..] {
            kinds.push(LiggghtsContact {
                effective_mass: effective_mass(a.0, b.0),
                effective_radius: effective_radius(a.1, b.1),
                effective_modulus: e_star(a.2, b.2),
                first: (a.2, a.1),
                second: Some((b.2, b.1)),
            });
        }
        for w in &sim.model().walls {
            kinds.push(LiggghtsContact {
                effective_mass: a.0,
                effective_radius: a.1,
                effective_modulus: e_star(a.2, w.material),
                first: (a.2, a.1),
                second: None,
            });
        }
    }
    kinds
}

pub(super) fn stl(name: &str, triangles: &[[Vec3; 3]]) -> String {
    let mut s = format!("solid {name}\n");
    for t in triangles {
        let n = (t[1] - t[0]).cross(&(t[2] - t[0])).normalize();
        let _ = writeln!(s, "  facet normal {} {} {}", g(n.x), g(n.y), g(n.z));
        s.push_str("    outer loop\n");
        for v in t {
            let _ = writeln!(s, "      vertex {} {} {}", g(v.x), g(v.y), g(v.z));
        }
        s.push_str("    endloop\n  endfacet\n");
    }
    let _ = writeln!(s, "endsolid {name}");
    s
}

/// Two unit vectors completing `axis` to a right-handed basis.
fn perpendicular_basis(axis: &Vec3) -> (Vec3, Vec3) {
    let trial = if axis.x.abs() < 0.9 {
        Vec3::x()
    } else {
        Vec3::y()
    };
    let u = axis.cross(&trial).normalize();
    (u, axis.cross(&u))
}

/// Facets of a surface of revolution, REVOLVED_SEGMENTS around.
fn revolved_triangles(shape: &Revolved) -> Vec<[Vec3; 3]> {
    let axis = shape.axis();
    let (u, w) = perpendicular_basis(&axis);
    let point = |h: f64, r: f64, k: usize| {
        let phi = std::f64::consts::TAU * k as f64 / REVOLVED_SEGMENTS as f64;
        shape.origin() + axis * h + (u * phi.cos() + w * phi.sin()) * r
    };
    let mut out = Vec::new();
    for pair in shape.profile().windows(2) {
        let ((r0, h0), (r1, h1)) = (pair[0], pair[1]);
        for k in 0..REVOLVED_SEGMENTS {
            let (a, b) = (point(h0, r0, k), point(h0, r0, k + 1));
            let (c, d) = (point(h1, r1, k), point(h1, r1, k + 1));
            out.push([a, b, d]);
            out.push([a, d, c]);
        }
    }
    out
}

/// A square of half-width `half` in the plane through `point` with normal `normal`.
pub(super) fn plane_triangles(point: &Vec3, normal: &Vec3, half: f64) -> Vec<[Vec3; 3]> {
    let (u, w) = perpendicular_basis(normal);
    let c = |a: f64, b: f64| point + u * (a * half) + w * (b * half);
    vec![
        [c(-1.0, -1.0), c(1.0, -1.0), c(1.0, 1.0)],
        [c(-1.0, -1.0), c(1.0, 1.0), c(-1.0, 1.0)],
    ]
}

/// The scene's extent: the particles' bounding box, widened by the periodic box.
fn extent(sim: &crate::simulation::Simulation, scene: &Scene) -> (Vec3, Vec3) {
    let p = &sim.state().particles;
    let mut lo = Vec3::repeat(f64::INFINITY);
    let mut hi = Vec3::repeat(f64::NEG_INFINITY);
    for (x, r) in p.position.iter().zip(&p.radius) {
        lo = lo.inf(&(x - Vec3::repeat(*r)));
        hi = hi.sup(&(x + Vec3::repeat(*r)));
    }
    if let Some(per) = &scene.periodic {
        for (a, range) in per.axes().iter().enumerate() {
            if let Some([l, h]) = range {
                lo[a] = *l;
                hi[a] = *h;
            }
        }
    }
    if p.is_empty() {
        lo = Vec3::repeat(-1.0);
        hi = Vec3::repeat(1.0);
    }
    (lo, hi)
}

/// The data file of `read_data` (`output::data_file`, titled as LIGGGHTS writes it).
pub(super) fn particles_data(
    sim: &crate::simulation::Simulation,
    sha: &str,
    bounds: &[[f64; 2]; 3],
) -> String {
    crate::output::data_file::particles_data(sim, "LIGGGHTS", sha, "", bounds, "Atoms")
}

/// The deck up to the walls: header, box, particles, contact model, step, gravity.
pub(super) fn deck_head(
    scene: &Scene,
    sha: &str,
    sim: &crate::simulation::Simulation,
    boundary: &[&str],
    model: &ContactModel,
) -> String {
    let moduli: Vec<f64> = sim
        .model()
        .materials
        .iter()
        .filter_map(|m| m.youngs_modulus)
        .collect();
    let skin = neighbor_skin(scene, &sim.state().particles.radius);
    let mut deck = String::new();
    head(
        &mut deck,
        "LIGGGHTS-PUBLIC 3.8",
        (scene, sha),
        "",
        "liggghts -in in.tamp",
    );
    deck.push_str("atom_style   granular\natom_modify  map array\n");
    let _ = writeln!(deck, "boundary     {}", boundary.join(" "));
    deck.push_str("newton       off\ncommunicate  single vel yes\nunits        si\n");
    if moduli.iter().any(|&e| e > 1e9) {
        deck.push_str("# LIGGGHTS 3.8 refuses youngsModulus > 1e9 Pa in SI units without this.\nhard_particles yes\n");
    }
    if moduli.iter().any(|&e| e < 5e6) {
        deck.push_str("# LIGGGHTS 3.8 refuses youngsModulus < 5e6 Pa in SI units without this.\nsoft_particles yes\n");
    }
    deck.push_str("read_data    particles.data\n");
    // contact_distance_factor > 1 makes LIGGGHTS reset the tangential history of a
    // pair that has separated (surfacesClose, pair_gran_base.h l. 414): with the
    // default 1 the stale shear survives while the pair stays neighbours, and a
    // contact that re-forms starts from it (docs/liggghts.md). 1.01 is a band of
    // 0.01 (R_i + R_j) that every separating pair crosses at the speeds of a step.
    let _ = writeln!(
        deck,
        "neighbor     {} bin\nneigh_modify delay 0 contact_distance_factor 1.01",
        g(skin)
    );
    for line in &model.properties {
        let _ = writeln!(deck, "{line}");
    }
    let _ = writeln!(
        deck,
        "# limitForce as contact.damping.limit (off, the 3.8 default: the force may pull); tangential_damping on, the 3.8 default and tamp's behaviour."
    );
    let _ = writeln!(
        deck,
        "pair_style   gran {}\npair_coeff   * *",
        model.pair_style
    );
    timestep_and_gravity(&mut deck, sim);

    deck
}

/// Write the deck, the data file and the meshes for `scene` into `out_dir`.
pub fn export(
    scene: &Scene,
    sha: &str,
    out_dir: &Path,
    dump_every: Option<u64>,
) -> Result<Exported> {
    let built = build_unless_refused(scene, refusals(scene), "LIGGGHTS 3.8")?;
    let sim = built.sim;
    let model = contact_model(scene, &sim)?;
    crate::output::create_dir(out_dir)?;
    let mut files = Vec::new();
    let mut notes = Vec::new();
    let p = &sim.state().particles;

    // Box: periodic axes exactly; the others shrink-wrap (`m`) around a start box.
    let (lo, hi) = extent(&sim, scene);
    let max_r = p.largest_radius();
    let margin = (hi - lo).max() * 0.05 + 2.0 * max_r;
    let periodic = scene.periodic.clone().unwrap_or_default().axes();
    let (boundary, bounds) = box_axes(periodic, (lo.into(), hi.into()), margin);
    let data = particles_data(&sim, sha, &bounds);
    crate::output::write_atomic(&out_dir.join("particles.data"), data.as_bytes())?;
    files.push("particles.data".to_string());

    let every = dump_every.unwrap_or_else(|| frame_every(scene, built.steps));
    let mut deck = deck_head(scene, sha, &sim, &boundary, &model);

    // Walls.
    // Walls take the pair's contact model (fix wall/gran accepts the same keywords).
    let half = (hi - lo).norm() * 2.0 + 10.0 * max_r;
    let wall_model = &model.pair_style;
    let mut meshes: Vec<String> = Vec::new();
    for (k, (wall, spec)) in sim.model().walls.iter().zip(&scene.walls).enumerate() {
        let wtype = wall.material + 1;
        let velocity = match &spec.motion {
            MotionSpec::Velocity { velocity } => Some(*velocity),
            _ => None,
        };
        let mut primitives: Vec<String> = Vec::new();
        let mut triangles: Vec<[Vec3; 3]> = Vec::new();
        match &wall.shape {
            Shape::Plane(pl) => match (axis_of(&pl.normal), velocity) {
                (Some(a), None) => primitives.push(format!("{}plane {}", AXES[a], g(pl.point[a]))),
                _ => triangles = plane_triangles(&pl.point, &pl.normal, half),
            },
            Shape::Box(b) => {
                for f in 0..6 {
                    if !b.faces[f] {
                        continue;
                    }
                    let a = f / 2;
                    let c = if f % 2 == 0 { b.lower[a] } else { b.upper[a] };
                    if velocity.is_none() {
                        primitives.push(format!("{}plane {}", AXES[a], g(c)));
                    } else {
                        let mut normal = Vec3::zeros();
                        normal[a] = 1.0;
                        let mut point = (b.lower + b.upper) * 0.5;
                        point[a] = c;
                        let span = (b.upper - b.lower).max() * 0.5;
                        triangles.extend(plane_triangles(&point, &normal, span));
                    }
                }
            }
            Shape::Revolved(r) => {
                let profile = r.profile();
                // Profile points are (radius, height along the axis).
                let cylinder = profile.len() == 2 && profile[0].0 == profile[1].0;
                match (axis_of(&r.axis()), cylinder, velocity) {
                    (Some(a), true, None) => {
                        let o = r.origin();
                        let (b, c) = ((a + 1) % 3, (a + 2) % 3);
                        primitives.push(format!(
                            "{}cylinder {} {} {}",
                            AXES[a],
                            g(profile[0].0),
                            g(o[b]),
                            g(o[c])
                        ));
                        notes.push(format!(
                            "walls[{k}]: a LIGGGHTS primitive cylinder is infinite along its axis; tamp's ends at heights {} and {}",
                            profile[0].1, profile[1].1
                        ));
                    }
                    _ => {
                        triangles = revolved_triangles(r);
                        notes.push(format!(
                            "walls[{k}]: a surface of revolution, written as {} flat facets: LIGGGHTS meets facets, tamp the exact surface",
                            triangles.len()
                        ));
                    }
                }
            }
            Shape::Mesh(m) => {
                triangles = m
                    .triangles()
                    .iter()
                    .map(|t: &Triangle| t.vertices)
                    .collect();
            }
        }
        for (j, prim) in primitives.iter().enumerate() {
            let _ = writeln!(
                deck,
                "fix          w{k}_{j} all wall/gran {wall_model} primitive type {wtype} {prim}"
            );
        }
        if !triangles.is_empty() {
            let name = format!("mesh{k}");
            let file = format!("meshes/{name}.stl");
            crate::output::create_dir(&out_dir.join("meshes"))?;
            crate::output::write_atomic(&out_dir.join(&file), stl(&name, &triangles).as_bytes())?;
            files.push(file.clone());
            let _ = writeln!(
                deck,
                "fix          {name} all mesh/surface file {file} type {wtype}"
            );
            if let Some(v) = velocity {
                let _ = writeln!(
                    deck,
                    "fix          move{k} all move/mesh mesh {name} linear {} {} {}",
                    g(v[0]),
                    g(v[1]),
                    g(v[2])
                );
            }
            meshes.push(name);
        }
    }
    if !meshes.is_empty() {
        let _ = writeln!(
            deck,
            "fix          meshwalls all wall/gran {wall_model} mesh n_meshes {} meshes {}",
            meshes.len(),
            meshes.join(" ")
        );
    }
    integrate_and_run(&mut deck, LIGGGHTS, every, built.steps);
    if !meshes.is_empty() {
        notes.push(
            "run LIGGGHTS with its screen output on (not -screen none): LIGGGHTS 3.8 crashes reading an STL mesh without a screen".into(),
        );
    }
    for note in notes.iter().rev() {
        deck.insert_str(0, &format!("# note: {note}\n"));
    }
    crate::output::write_atomic(&out_dir.join("in.tamp"), deck.as_bytes())?;
    files.insert(0, "in.tamp".to_string());
    Ok(Exported {
        particles: p.len(),
        steps: built.steps,
        dt: sim.dt(),
        files,
        notes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::damping::liggghts::beta;

    #[test]
    fn revolved_facets_lie_on_the_profile() {
        // A cone frustum from radius 12 mm at height 0 to 20 mm at height 10 mm.
        let cone = Revolved::cone(
            Vec3::new(0.0, 0.0, 0.03),
            Vec3::z(),
            (0.012, 0.0),
            (0.020, 0.01),
        )
        .unwrap();
        let facets = revolved_triangles(&cone);
        assert_eq!(facets.len(), 2 * REVOLVED_SEGMENTS);
        for v in facets.iter().flatten() {
            let (r, h) = ((v.x * v.x + v.y * v.y).sqrt(), v.z - 0.03);
            let on_profile = 0.012 + (0.020 - 0.012) * h / 0.01;
            assert!(
                (r - on_profile).abs() < 1e-12,
                "vertex {v:?} is off the cone"
            );
        }
    }

    #[test]
    fn lammps_mass_scaled_dashpots_are_refused() {
        for kind in ["mass_velocity", "viscoelastic"] {
            let scene = crate::scene::parse(&format!(
                r#"{{"name": "t", "materials": [{{"name": "steel", "density": 7800, "youngs_modulus": 2e11, "poisson_ratio": 0.3}}],
                  "contact": {{"normal": {{"law": "hertz"}}, "damping": {{"kind": "{kind}", "eta_n0": 1e4}}}},
                  "particles": [{{"position": [0, 0, 0], "radius": 0.001, "material": "steel"}}],
                  "time_step": {{"fixed": 1e-9}}, "run": {{"duration": 1e-6}}}}"#
            ))
            .expect("a valid scene");
            let list = refusals(&scene);
            assert!(
                list.iter()
                    .any(|(path, why)| path == "contact.damping.kind" && why.contains(kind)),
                "{list:?}"
            );
        }
    }

    #[test]
    fn restitution_inverts_beta() {
        for e in [0.06, 0.3, 0.5, 0.9, 0.99, 1.0] {
            let back = restitution_from_beta(beta(e));
            assert!((back - e).abs() < 1e-14 * e.max(1e-300), "{e} -> {back}");
        }
    }
}
