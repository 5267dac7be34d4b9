//! `tamp export-lammps SCENE --out DIR`: the same scene as a LAMMPS deck for
//! `pair_style granular` (LAMMPS 22 Jul 2025, `.ci/install-lammps`), or a refusal
//! listing every field LAMMPS cannot express with the same physics (exit 2, one
//! `path: cannot export to LAMMPS: why` per field, nothing written).
//!
//! What the deck holds, and why it is written this way:
//! - The particles as tamp placed them at t = 0 (`particles.data`, `read_data`, atom
//!   style sphere: id type diameter density x y z; velocities and spins), so both codes
//!   start from the same state.
//! - One atom type per tamp material (type k + 1 = `materials[k]`), each with its own
//!   `pair_coeff k k`; LAMMPS mixes the other pairs itself, E* exactly as tamp does
//!   (`mix_stiffnessE`: 1/E* = (1 − ν_i²)/E_i + (1 − ν_j²)/E_j).
//! - Each role's law says what it is in LAMMPS (contact/lammps.rs, `lammps()` on the
//!   normal, damping and tangential laws); this file only asks, and refuses the field
//!   of a law that has no LAMMPS model (of the tangential laws `lammps_mindlin`,
//!   `lammps_linear_history` and `lammps_linear_nohistory` have one); a scene without
//!   friction writes `tangential linear_nohistory 0 0`, a force of exactly zero. With
//!   spins and friction the scene must take LAMMPS's lever arms (`contact.lever_arm` =
//!   `lammps`).
//! - A scene whose tangential law keeps `pair_style gran/hooke/history`'s history
//!   (`"history": "gran_hooke_history"`, which no `pair granular` model has) is written
//!   as that pair style with `pair_coeff * *` instead (`gran_hooke_history`): the
//!   `linear` law, `mass_velocity` damping or none, one μ between particles, that
//!   style's full-radius lever arms, and no walls.
//! - `limit_damping` is written after the pair and wall models exactly when the scene
//!   sets `contact.damping.limit` (the total normal force clamped at zero); otherwise
//!   the force may pull at the end of a contact in both codes.
//! - Fixed planes normal to an axis are `fix wall/gran granular` with the pair model and
//!   the wall material's E and ν (`xplane lo NULL` or `NULL hi`), a fixed closed box one
//!   such fix per axis (`xplane lo hi`, `wall_fixes`); LAMMPS gives the wall and the
//!   sphere that one material, so particles of another one are refused. A fixed
//!   cylinder along x, y or z with `"curvature": "mean"` and both ends closed is a
//!   `region cylinder` with `fix wall/gran/region` (`cylinder_region`,
//!   `cylinder_refusals` say why and when). A tilted or moving plane is a `region
//!   plane` with `fix wall/gran/region` (`plane_region`); a plane or cylinder moving
//!   at constant velocity or by displacement expressions moves its region (`move` on
//!   equal-style variables of `time`, `region_move`). Servo and pressed walls, moving
//!   boxes and other walls (open boxes included, `wall_fixes` says why), cohesion,
//!   growth and scheduled insertion are refused.
//! - MDR (`LammpsNormal::Mdr`) is `mdr E ν Y γ ψ_b η damping mdr 1|2` with the law's
//!   own E and ν (for walls too), under `atom_style sphere 1` (its radii change), and
//!   every wall a region with `fix wall/gran/region`, as LAMMPS's `fix granular/mdr`
//!   requires: planes and cylinders, no boxes.
//! - MDR scenes also dump each particle's free-surface fraction ψ (`d_psi`, from
//!   `fix granular/mdr`) to `mdr.lammps` at the frames of `dump.lammps`.
//! - Dumps at `%.17g`, sorted by id: every `dump_every` steps to `dump.lammps`, the
//!   final state to `final.lammps`; `tamp compare` and `import-liggghts-dump` read them.

use crate::contact::lammps::LammpsNormal;
use crate::contact::lever_arm::LeverArm;
use crate::contact::mdr::damping::MdrDampingForm;
use crate::contact::tangential::TangentialLaw;
use crate::contact::tangential::lammps_linear_history::LammpsHistory;
use crate::error::{Result, TampError};
use crate::particles::Vec3;
use crate::peer_deck::{
    Exported, LAMMPS, box_axes, build_unless_refused, frame_every, head, integrate_and_run,
    neighbor_skin, scene_refusals, timestep_and_gravity,
};
use crate::scene::Scene;
use crate::scene::physics::InertiaRadius;
use crate::scene::walls::{Curvature, MotionSpec, ShapeSpec, WallSpec};
use std::fmt::Write as _;
use std::path::Path;

const AXES: [&str; 3] = ["x", "y", "z"];

use crate::decimal::g;

/// `model` with MDR's `{gamma}` set to the surface energy of a pair of particles, or of
/// a particle and a wall.
pub(super) fn surface_energy(model: &str, scene: &Scene, wall: bool) -> String {
    let gamma = scene.contact.normal.mdr().map_or(0.0, |law| match wall {
        true => law.at_wall().surface_energy,
        false => law.surface_energy,
    });
    model.replace("{gamma}", &g(gamma))
}

/// The contact model of every `pair_coeff` line, with the material's E and ν left as
/// `{E}` and `{nu}`, and MDR's surface energy as `{gamma}` (`surface_energy`).
pub(super) fn pair_model(scene: &Scene) -> std::result::Result<String, Vec<(String, String)>> {
    let mut refused = Vec::new();
    let normal = scene
        .contact
        .normal
        .lammps()
        .map_err(|why| refused.push(("contact.normal.law".to_string(), why.0)))
        .ok();
    let damping = match (&scene.contact.dashpot(), normal) {
        // MDR's dashpot is the law's own, `damping mdr 1|2` after its η.
        (_, Some(LammpsNormal::Mdr(law))) => Some(("mdr", law.damping.coefficient)),
        // LAMMPS 22 Jul 2025 refuses `damping none` ("Must specify damping granular
        // model"); `velocity` with η = 0 adds a force of exactly zero.
        (None, _) => Some(("velocity", 0.0)),
        (Some(d), Some(n)) => d
            .lammps(n)
            .map(|d| (d.keyword, d.coefficient))
            .map_err(|why| refused.push(("contact.damping.kind".to_string(), why.0)))
            .ok(),
        (Some(_), None) => None,
    };
    let tangential = match &scene.contact.tangential {
        None => Some("linear_nohistory 0 0".to_string()),
        Some(t) => t
            .law
            .lammps()
            .map_err(|why| refused.push(("contact.tangential.law".to_string(), why.0)))
            .ok(),
    };
    // `rolling sds k γ μ` joins the tangential words, as in LAMMPS's examples.
    let tangential = tangential.map(|t| match &scene.contact.rolling {
        Some(r) => format!("{t} {}", r.lammps()),
        None => t,
    });
    match (normal, damping, tangential) {
        (Some(n), Some((kw, coefficient)), Some(t)) if refused.is_empty() => {
            let normal = match n {
                LammpsNormal::HertzMaterial => {
                    format!("hertz/material {{E}} {} {{nu}}", g(coefficient))
                }
                LammpsNormal::Hooke { stiffness } => {
                    format!("hooke {} {}", g(stiffness), g(coefficient))
                }
                LammpsNormal::Mdr(law) => {
                    let form = match law.damping.form {
                        MdrDampingForm::Stiffness => 1,
                        MdrDampingForm::Velocity => 2,
                    };
                    let kw = format!("mdr {form}");
                    // γ is left as `{gamma}`: a wall's may differ from the particles'
                    // (`surface_energy`).
                    return Ok(format!(
                        "mdr {} {} {} {{gamma}} {} {} damping {kw} tangential {t}",
                        g(law.youngs_modulus),
                        g(law.poisson_ratio),
                        g(law.yield_stress),
                        g(law.bulk_trigger),
                        g(coefficient)
                    ));
                }
            };
            let limit = match scene.contact.damping.is_some_and(|d| d.limit) {
                true => " limit_damping",
                false => "",
            };
            Ok(format!("{normal} damping {kw} tangential {t}{limit}"))
        }
        _ => Err(refused),
    }
}

/// The arguments of `pair_style gran/hooke/history`, `k_n k_t γ_n γ_t {mu} dampflag
/// [limit_damping]`, for a scene whose tangential law
/// keeps that style's history (`"history": "gran_hooke_history"`: the classic rule with
/// the spring k_t, which no `pair granular` model has), or the fields the style cannot
/// say; `None` for every other scene. The style's normal force is k_n δ − m* γ_n v_n
/// (tamp's `linear` law with `mass_velocity` damping), its tangential dashpot m* γ_t
/// with γ_t = x_γ,t γ_n (none with dampflag 0), one μ for every pair of particles
/// (`pair_coeff * *`).
fn gran_hooke_history(scene: &Scene) -> Option<std::result::Result<String, Vec<(String, String)>>> {
    let friction = scene.contact.tangential.as_ref()?;
    let TangentialLaw::LammpsLinearHistory(law) = friction.law else {
        return None;
    };
    if law.history != LammpsHistory::GranHookeHistory {
        return None;
    }
    let mut refused = Vec::new();
    let stiffness = match scene.contact.normal.lammps() {
        Ok(LammpsNormal::Hooke { stiffness }) => Some(stiffness),
        _ => {
            refused.push((
                "contact.normal.law".to_string(),
                "gran/hooke/history's normal force is hooke's k_n δ: tamp's 'linear' law"
                    .to_string(),
            ));
            None
        }
    };
    let gamma_n = match (scene.contact.dashpot(), stiffness) {
        (None, _) => Some(0.0),
        (Some(d), Some(k)) => match d.lammps(LammpsNormal::Hooke { stiffness: k }) {
            Ok(l) if l.keyword == "mass_velocity" => Some(l.coefficient),
            _ => {
                refused.push((
                    "contact.damping.kind".to_string(),
                    "gran/hooke/history damps with m* γ_n: tamp's 'mass_velocity'".to_string(),
                ));
                None
            }
        },
        (Some(_), None) => None,
    };
    if !scene.walls.is_empty() {
        refused.push((
            "walls".to_string(),
            "LAMMPS 22 Jul 2025's fix wall/gran hooke/history is pair granular's hooke with linear_history_classic (the spring k_t times the contact radius; the same dump byte for byte, docs/lammps.md), not pair_style gran/hooke/history's history: no LAMMPS wall keeps this history".to_string(),
        ));
    }
    if let Some(k) = friction
        .friction_pairs
        .iter()
        .position(|p| p.materials.iter().all(|m| made_of(scene, m)))
    {
        refused.push((
            format!("contact.tangential.friction_pairs[{k}]"),
            "pair_style gran/hooke/history gives every pair of particles one μ (pair_coeff * *)"
                .to_string(),
        ));
    }
    let (Some(k_n), Some(gamma_n), true) = (stiffness, gamma_n, refused.is_empty()) else {
        return Some(Err(refused));
    };
    let gamma_t = law.x_gamma_t * gamma_n;
    let limit = match scene.contact.damping.is_some_and(|d| d.limit) {
        true => " limit_damping",
        false => "",
    };
    Some(Ok(format!(
        "{} {} {} {} {{mu}} {}{limit}",
        g(k_n),
        g(law.stiffness),
        g(gamma_n),
        g(gamma_t),
        u8::from(gamma_t > 0.0)
    )))
}

/// The pair style of the scene and the model of every `pair_coeff` and wall fix:
/// `gran/hooke/history` where the scene keeps that style's history, else `granular`
/// (`pair_model`), with E, ν and μ left as `{E}`, `{nu}` and `{mu}`.
fn pair_style(scene: &Scene) -> std::result::Result<PairStyle, Vec<(String, String)>> {
    match gran_hooke_history(scene) {
        Some(args) => args.map(PairStyle::GranHookeHistory),
        None => pair_model(scene).map(PairStyle::Granular),
    }
}

/// `pair_style granular` with its model, or `pair_style gran/hooke/history` with its
/// arguments.
enum PairStyle {
    Granular(String),
    GranHookeHistory(String),
}

impl PairStyle {
    /// The model or arguments, as `pair_coeff` (granular) or `pair_style` (gran) write
    /// them.
    fn model(&self) -> &str {
        match self {
            PairStyle::Granular(model) | PairStyle::GranHookeHistory(model) => model,
        }
    }
}

/// Every field of `scene` LAMMPS cannot express, as (path, reason).
pub fn refusals(scene: &Scene) -> Vec<(String, String)> {
    let mut out = pair_style(scene).err().unwrap_or_default();
    let mut refuse = |path: String, why: &str| out.push((path, why.to_string()));
    if scene.output.trajectory_every_step_from.is_some() {
        refuse(
            "output.trajectory_every_step_from".into(),
            "the exported deck dumps at one interval",
        );
    }
    if scene.contact.cohesion.is_some() {
        refuse(
            "contact.cohesion".into(),
            "pair granular has no van der Waals (Hamaker) cohesion model",
        );
    }
    match &scene.rotation {
        None if scene.contact.tangential.is_some() => refuse(
            "rotation".into(),
            "LAMMPS's fix nve/sphere always integrates rotation: a scene with friction must enable rotation",
        ),
        Some(r) if r.inertia_scale != 1.0 => refuse(
            "rotation.inertia_scale".into(),
            "LAMMPS's fix nve/sphere uses the moment of inertia of a solid sphere (scale 1)",
        ),
        Some(r)
            if scene.contact.normal.mdr().is_some()
                && r.inertia_radius != InertiaRadius::Current =>
        {
            refuse(
                "rotation.inertia_radius".into(),
                "LAMMPS's fix nve/sphere takes the moment of inertia of the radius of the step, which MDR grows; set \"inertia_radius\": \"current\" for the same physics",
            )
        }
        _ => {}
    }
    for (path, why) in scene_refusals(scene, LAMMPS) {
        refuse(path, &why);
    }
    let hertz = scene.contact.normal.lammps() == Ok(LammpsNormal::HertzMaterial);
    let mdr = scene.contact.normal.mdr().is_some();
    if mdr
        && scene
            .materials
            .iter()
            .filter(|m| made_of(scene, &m.name))
            .count()
            > 1
    {
        refuse(
            "materials".into(),
            "LAMMPS's fix granular/mdr takes one mdr model for every atom type (\"Cannot currently define multiple MDR normal models\"): give every particle one material",
        );
    }
    for (k, m) in scene.materials.iter().enumerate() {
        if m.rigid {
            // A wall material only; walls are refused below, and a stand-in
            // stiffness would be a different scene.
            refuse(
                format!("materials[{k}].rigid"),
                "LAMMPS has no rigid material for pair granular; give the wall material elastic constants",
            );
            continue;
        }
        if hertz && (m.youngs_modulus.is_none() || m.poisson_ratio.is_none()) {
            refuse(
                format!("materials[{k}]"),
                "hertz/material needs the Young's modulus and Poisson ratio of every atom type",
            );
        }
    }
    let periodic = scene
        .periodic
        .clone()
        .unwrap_or_default()
        .axes()
        .map(|a| a.is_some());
    for (k, w) in scene.walls.iter().enumerate() {
        let fixed = matches!(w.motion, MotionSpec::Fixed);
        match &w.shape {
            ShapeSpec::Cylinder { .. } => {
                for (field, why) in cylinder_refusals(w, &scene.walls, periodic, 0.0) {
                    refuse(format!("walls[{k}].{field}"), &why);
                }
            }
            ShapeSpec::Plane { normal, .. } => {
                if (0..3).any(|a| periodic[a] && normal[a] != 0.0) {
                    refuse(
                        format!("walls[{k}].shape.normal"),
                        "a plane across a periodic axis: LAMMPS's fix wall/gran cannot stand on a periodic axis (\"Cannot use wall in periodic dimension\") and its region walls have no periodic images",
                    );
                }
            }
            _ if mdr => refuse(
                format!("walls[{k}].shape"),
                "LAMMPS's mdr takes only region walls (fix wall/gran/region): give the box as plane walls",
            ),
            _ => {
                if let Err(why) = wall_fixes(w, periodic) {
                    refuse(format!("walls[{k}]"), why);
                } else if !fixed {
                    refuse(
                        format!("walls[{k}].motion"),
                        "only plane and cylinder walls move in the LAMMPS export (a region's move); a closed box is three fix wall/gran planes, which cannot: use plane walls",
                    );
                }
            }
        }
        if matches!(
            w.shape,
            ShapeSpec::Plane { .. } | ShapeSpec::Cylinder { .. }
        ) && let Err(list) = region_move(k, w)
        {
            for (field, why) in list {
                refuse(format!("walls[{k}].{field}"), &why);
            }
        }
        // fix wall/gran has one material, used for the wall and the sphere alike
        // (E* = E/(2(1 − ν²)), mix_stiffnessE_wall): the same as tamp only where every
        // particle's material is the wall's.
        let wall = scene.materials.iter().find(|m| m.name == w.material);
        let same = |m: &&crate::scene::schema::MaterialSpec| {
            wall.is_some_and(|wm| {
                m.youngs_modulus == wm.youngs_modulus && m.poisson_ratio == wm.poisson_ratio
            })
        };
        // MDR states E and ν in the law, for walls and particles alike.
        if !mdr
            && !scene
                .materials
                .iter()
                .filter(|m| made_of(scene, &m.name))
                .all(|m| same(&m))
        {
            refuse(
                format!("walls[{k}].material"),
                "LAMMPS's fix wall/gran takes one E and ν for the wall and the sphere; export scenes whose particles are of the wall's elastic material",
            );
        }
    }
    // With friction pairs every pair of particle materials gets its own `pair_coeff i j`
    // (LAMMPS would mix μ_ii and μ_jj), and an explicit line takes one E and ν: its
    // E* is then mix_stiffnessE(E, E, ν, ν), tamp's only if both materials share them.
    if let Some(t) = &scene.contact.tangential
        && !t.friction_pairs.is_empty()
    {
        let used: Vec<_> = scene
            .materials
            .iter()
            .filter(|m| made_of(scene, &m.name))
            .collect();
        if let Some((a, b)) = used.iter().enumerate().find_map(|(k, a)| {
            used[k + 1..]
                .iter()
                .find(|b| {
                    (a.youngs_modulus, a.poisson_ratio) != (b.youngs_modulus, b.poisson_ratio)
                })
                .map(|b| (a, b))
        }) {
            refuse(
                "contact.tangential.friction_pairs".into(),
                &format!(
                    "with friction pairs each pair of particle materials is its own pair_coeff line, which takes one E and ν; materials '{}' and '{}' differ in E or ν",
                    a.name, b.name
                ),
            );
        }
    }
    // The lever arms matter only when spins and a tangential force act.
    let spins_and_friction = scene.rotation.is_some() && scene.contact.tangential.is_some();
    let gran = gran_hooke_history(scene).is_some();
    if spins_and_friction && !gran && scene.contact.lever_arm != LeverArm::Lammps {
        refuse(
            "contact.lever_arm".into(),
            "LAMMPS's pair granular and fix wall/gran take the full radii for the contact-point velocity (and for a wall's torque); set \"lever_arm\": \"lammps\" for the same physics",
        );
    }
    if spins_and_friction && gran && scene.contact.lever_arm != LeverArm::FullRadius {
        refuse(
            "contact.lever_arm".into(),
            "pair_style gran/hooke/history takes the full radii for the contact-point velocity and the torques; set \"lever_arm\": \"full_radius\" for the same physics",
        );
    }
    out
}

/// Whether any particle of the scene is of material `name`: placed, inserted or
/// deposited (the deck's data file holds them all).
fn made_of(scene: &Scene, name: &str) -> bool {
    scene.particles.iter().any(|p| p.material == name)
        || scene.insert.iter().any(|i| i.material == name)
        || scene.deposit.iter().any(|d| d.material == name)
}

/// The `fix wall/gran` geometries of a fixed wall, one fix each, as (fix-id suffix,
/// geometry):
/// - an axis-aligned plane is `<axis>plane lo NULL` (normal +axis: the particles above
///   `lo`) or `<axis>plane NULL hi` (normal −axis);
/// - a closed box is one `<axis>plane lo hi` per axis. LAMMPS gives a particle the one
///   contact with the nearer of lo and hi, tamp one per face it touches: the same while
///   no particle spans the box (checked in `export`, which knows the radii); inside the
///   box every face acts as its infinite plane in both codes.
///
/// Refused: an open box (tamp ends its side faces at a rounded rim, LAMMPS's planes are
/// infinite); a wall on a periodic axis (LAMMPS: "Cannot use wall in periodic
/// dimension"); every other shape. Cylinders are `cylinder_region`'s.
fn wall_fixes(
    w: &WallSpec,
    periodic: [bool; 3],
) -> std::result::Result<Vec<(String, String)>, &'static str> {
    let on_periodic = "LAMMPS's fix wall/gran cannot stand on a periodic axis (\"Cannot use wall in periodic dimension\")";
    match &w.shape {
        ShapeSpec::Plane { point, normal } => {
            let Some(a) = along_an_axis(normal) else {
                return Err("fix wall/gran planes are normal to x, y or z");
            };
            if periodic[a] {
                return Err(on_periodic);
            }
            let geometry = if normal[a] > 0.0 {
                format!("{}plane {} NULL", AXES[a], g(point[a]))
            } else {
                format!("{}plane NULL {}", AXES[a], g(point[a]))
            };
            Ok(vec![(String::new(), geometry)])
        }
        ShapeSpec::Box { lower, upper, open } => {
            if !open.is_empty() {
                return Err(
                    "an open box is not exported to LAMMPS: tamp ends its side faces at a rounded rim, fix wall/gran's planes are infinite; use plane walls",
                );
            }
            if periodic.iter().any(|&p| p) {
                return Err(on_periodic);
            }
            Ok((0..3)
                .map(|a| {
                    let geometry = format!("{}plane {} {}", AXES[a], g(lower[a]), g(upper[a]));
                    (AXES[a].to_string(), geometry)
                })
                .collect())
        }
        _ => Err(
            "only plane walls, closed boxes and cylinders are exported to LAMMPS (fix wall/gran xplane/yplane/zplane, fix wall/gran/region on a region cylinder)",
        ),
    }
}

/// The axis (0, 1, 2 for x, y, z) a unit-free direction lies along, if it does.
fn along_an_axis(v: &[f64; 3]) -> Option<usize> {
    let n = Vec3::from(*v);
    (0..3).find(|&a| n[a].abs() == n.norm() && n.norm() > 0.0)
}

/// A cylinder wall as a LAMMPS region: `cylinder <axis> c1 c2 R_c lo hi side in open 1
/// open 2 units box`, the lateral face of tamp's cylinder between its ends (faces 1 and
/// 2, the end caps, open), for `fix wall/gran/region`. Why the region and not
/// `fix wall/gran ... zcylinder R_c`: zcylinder's axis is the z axis through x = y = 0
/// and has no ends, the region takes any centre, an x, y or z axis and tamp's ends; both
/// give the curved face the contact radius −2R_c from inside (region_cylinder.cpp
/// `surface_interior`, fix_wall_gran.cpp), which is tamp's `"curvature": "mean"`.
fn cylinder_region(w: &WallSpec) -> Option<String> {
    let ShapeSpec::Cylinder {
        origin,
        axis,
        radius,
        bottom,
        top,
        ..
    } = &w.shape
    else {
        return None;
    };
    let a = along_an_axis(axis)?;
    let s = axis[a].signum();
    let (e0, e1) = (origin[a] + s * bottom, origin[a] + s * top);
    let (lo, hi) = (e0.min(e1), e0.max(e1));
    let [c1, c2] = match a {
        0 => [origin[1], origin[2]],
        1 => [origin[0], origin[2]],
        _ => [origin[0], origin[1]],
    };
    Some(format!(
        "cylinder {} {} {} {} {} {} side in open 1 open 2 units box",
        AXES[a],
        g(c1),
        g(c2),
        g(*radius),
        g(lo),
        g(hi)
    ))
}

/// A plane wall that `fix wall/gran` cannot write (tilted, or moving) as a LAMMPS
/// region: `plane px py pz nx ny nz side in units box`, the particles on the normal's
/// side, for `fix wall/gran/region`. Exact: region_plane.cpp normalises the normal as
/// tamp does (each component over the square root of their sum of squares), finds
/// the contact at the distance d = (x − p)·n̂ when 0 ≤ d < R, and gives it the contact
/// radius 0, the flat wall R* = R of tamp's plane. Behind the plane (d < 0) LAMMPS has
/// no contact where tamp reports a deep overlap; a run that gets there has already
/// failed tamp's stability limits. Every plane of an MDR scene is a region (`mdr`:
/// LAMMPS's mdr takes no other wall). Other axis-aligned fixed planes stay `fix wall/gran`
/// planes (`wall_fixes`): the same contact to the bit, for a normal along an axis the
/// region's d has the other components' products exactly zero, and the recorded cases
/// use that form.
fn plane_region(w: &WallSpec, mdr: bool) -> Option<String> {
    let ShapeSpec::Plane { point, normal } = &w.shape else {
        return None;
    };
    if !mdr && matches!(w.motion, MotionSpec::Fixed) && along_an_axis(normal).is_some() {
        return None;
    }
    let [px, py, pz] = point.map(g);
    let [nx, ny, nz] = normal.map(g);
    Some(format!(
        "plane {px} {py} {pz} {nx} {ny} {nz} side in units box"
    ))
}

/// A region's motion in the deck: its `variable` lines and its `move …` keyword.
type RegionMove = (String, String);

/// Refused fields, as (path, reason).
type Refused = Vec<(String, String)>;

/// A moving wall's region motion: the deck's `variable` lines and the region's
/// `move v_x v_y v_z` keyword (`NULL` for an axis it does not move along), `None` for a
/// fixed wall; or, as (field under `walls[k]`, reason), why it has none.
///
/// LAMMPS moves a region by displacement variables evaluated once per step, at the
/// step's `time` = step·Δt, before the wall forces (region.cpp `prematch`,
/// `pretransform`), and gives the wall the velocity (d(t) − d(t − Δt))/Δt
/// (`set_velocity`), in the normal and tangential relative velocity alike
/// (granular_model.cpp takes vᵢ − v_wall), as tamp's wall motion does:
/// - `Velocity` v: d(t) = v·time. tamp adds v Δt per step and takes v itself, LAMMPS's
///   chord is v to round-off. In the setup force of step 0 LAMMPS's velocity is 0,
///   tamp's v: `export` refuses a particle that touches such a wall at t = 0.
/// - `Displacement` u(t): the expressions as LAMMPS formulas (`formula`), refused
///   where there is none; the chord over the step and the velocity 0 at step 0 are
///   tamp's own (`Boundary::advance`).
/// - `Servo`, `Pressure`: refused, the displacement follows the particles' force.
///
/// A cylinder's ends must stay closed by fixed faces (`cylinder_refusals`): its
/// displacement along the axis must be zero, or a constant velocity, whose travel
/// `export` checks against the faces.
fn region_move(k: usize, w: &WallSpec) -> std::result::Result<Option<RegionMove>, Refused> {
    let axis = match &w.shape {
        ShapeSpec::Cylinder { axis, .. } => along_an_axis(axis),
        _ => None,
    };
    let formulas: [Option<String>; 3] = match &w.motion {
        MotionSpec::Fixed => return Ok(None),
        MotionSpec::Velocity { velocity } => {
            velocity.map(|v| (v != 0.0).then(|| format!("{}*time", g(v))))
        }
        MotionSpec::Displacement { x, y, z } => {
            let mut refused = Vec::new();
            let mut out = [None, None, None];
            for (a, src) in [x, y, z].into_iter().enumerate() {
                let field = format!("motion.{}", AXES[a]);
                let translated = crate::expression::Expression::parse(src, &["t"])
                    .and_then(|e| super::formula::lammps_formula(e.tree()));
                match translated {
                    Err(why) => refused.push((
                        field,
                        format!("no LAMMPS equal-style formula with the same value: {why}"),
                    )),
                    Ok(f) if Some(a) == axis && f != "0" && f != g(0.0) => refused.push((
                        field,
                        "a cylinder displaced along its axis by an expression: its ends would move against the fixed faces that close them (a constant velocity along the axis is checked over the run)".to_string(),
                    )),
                    Ok(f) => out[a] = Some(f),
                }
            }
            if !refused.is_empty() {
                return Err(refused);
            }
            out
        }
        MotionSpec::Servo { .. } | MotionSpec::Pressure { .. } => {
            return Err(vec![(
                "motion".to_string(),
                "a servo or pressed wall moves by the particles' force on it, step by step; a LAMMPS region moves only by displacement variables given in advance, so no deck runs the same controller".to_string(),
            )]);
        }
    };
    let mut variables = String::new();
    let names: Vec<String> = (0..3)
        .map(|a| match &formulas[a] {
            Some(f) => {
                let name = format!("wall{k}_d{}", AXES[a]);
                let _ = writeln!(variables, "variable     {name} equal {f}");
                format!("v_{name}")
            }
            None => "NULL".to_string(),
        })
        .collect();
    Ok(Some((variables, format!("move {}", names.join(" ")))))
}

/// Why a cylinder wall cannot be written as `cylinder_region` with the same physics, as
/// (field under `walls[k]`, reason); `walls` are the scene's, whose planes and closed
/// boxes may close the cylinder's ends.
///
/// Exact only where the contacts are the lateral face's from inside: there tamp's
/// `"curvature": "mean"` wall is LAMMPS's region cylinder to round-off. Beyond an end
/// LAMMPS's open region gives a rim contact with the contact radius 0 (flat;
/// region_cylinder.cpp `surface_exterior`, `crad` set only without open faces) and
/// starts a new tangential history (the rim is face 0, the curved face 2), where tamp's
/// wall keeps −2R_c and one history; from outside LAMMPS gives the lateral face radius 0
/// too. So each end must be closed by a plane wall or a closed box's face normal to the
/// axis between the ends (particles inside stay inside; `export` checks they start
/// there), the axis must lie along x, y or z, and no axis across it may be periodic.
fn cylinder_refusals(
    w: &WallSpec,
    walls: &[WallSpec],
    periodic: [bool; 3],
    travel: f64,
) -> Vec<(&'static str, String)> {
    let mut out = Vec::new();
    let ShapeSpec::Cylinder {
        origin,
        axis,
        bottom,
        top,
        curvature,
        ..
    } = &w.shape
    else {
        return out;
    };
    if *curvature != Curvature::Mean {
        out.push((
            "shape.curvature",
            "LAMMPS's cylinder walls give the contact the effective radius R r_w/(R + r_w) with r_w = -2 R_c (fix_wall_gran.cpp zcylinder, region_cylinder.cpp); tamp's default \"flat\" cylinder takes R, a different Hertz stiffness; set \"curvature\": \"mean\" for LAMMPS's contact".to_string(),
        ));
    }
    let Some(a) = along_an_axis(axis) else {
        out.push((
            "shape.axis",
            "LAMMPS's region cylinder has its axis along x, y or z".to_string(),
        ));
        return out;
    };
    if (0..3).any(|b| b != a && periodic[b]) {
        out.push((
            "shape",
            "a cylinder across a periodic axis: LAMMPS's region wall has no periodic images"
                .to_string(),
        ));
    }
    let s = axis[a].signum();
    let (e0, e1) = (origin[a] + s * bottom, origin[a] + s * top);
    let (lo, hi) = (e0.min(e1), e0.max(e1));
    // Between the ends at the start and, moved by `travel` along the axis, at the end.
    let inside = |h: f64| (lo..=hi).contains(&h) && (lo + travel..=hi + travel).contains(&h);
    // A face normal to the axis at axial coordinate h, facing +axis (closes lo) or −axis.
    // Only fixed faces: a moving one could leave the ends open later in the run.
    let fixed = walls
        .iter()
        .filter(|other| matches!(other.motion, MotionSpec::Fixed));
    let faces = fixed.flat_map(|other| match &other.shape {
        ShapeSpec::Plane { point, normal } => along_an_axis(normal)
            .filter(|&b| b == a)
            .map(|_| vec![(point[a], normal[a] > 0.0)])
            .unwrap_or_default(),
        ShapeSpec::Box { lower, upper, open } if open.is_empty() => {
            vec![(lower[a], true), (upper[a], false)]
        }
        _ => Vec::new(),
    });
    let (mut closed_lo, mut closed_hi) = (false, false);
    for (h, up) in faces {
        closed_lo |= up && inside(h);
        closed_hi |= !up && inside(h);
    }
    for (closed, end) in [(closed_lo, lo), (closed_hi, hi)] {
        if !closed {
            out.push((
                "shape",
                format!(
                    "particles could reach the cylinder's end at {}{}: beyond it LAMMPS's open region cylinder gives a flat rim contact with a new tangential history (region_cylinder.cpp surface_exterior), tamp's \"mean\" wall the wall's curvature and one history; close the end with a fixed plane wall or a fixed closed box normal to the axis between the ends (over the whole run, if the cylinder moves along its axis)",
                    AXES[a],
                    format_args!(" = {}", g(end))
                ),
            ));
        }
    }
    out
}

/// The first particle (its id) not inside a cylinder wall: centre off the axis by
/// R_c or more, or beyond an end. LAMMPS's region (side in) has no contact from outside.
/// `shift` is the wall's displacement at t = 0.
fn starts_outside(w: &WallSpec, sim: &crate::simulation::Simulation, shift: Vec3) -> Option<u64> {
    let ShapeSpec::Cylinder {
        origin,
        axis,
        radius,
        bottom,
        top,
        ..
    } = &w.shape
    else {
        return None;
    };
    let (o, a) = (Vec3::from(*origin), Vec3::from(*axis).normalize());
    let p = &sim.state().particles;
    (0..p.len())
        .find(|&i| {
            let x = p.position[i] - shift - o;
            let h = x.dot(&a);
            (x - a * h).norm() >= *radius || h < *bottom || h > *top
        })
        .map(|i| p.id[i])
}

/// The fixes of one wall and the axes its region moves along, for `walls_record`.
struct WallRecord {
    fixes: Vec<String>,
    moves: [bool; 3],
}

/// `walls.csv` as `tamp run` writes it for `output.walls` (docs/engines.md): every
/// `every` steps and each wall, its displacement (the region's move variables, 0 for
/// a fixed wall) and the force the particles exert on it, minus the sum of the wall's
/// force on each particle (columns 2–4 of its fixes' `contacts` arrays) over its fixes.
/// Every number goes through a `format` variable at `%.17g`: a plain substitution
/// would give 15 digits.
fn walls_record(deck: &mut String, walls: &[WallRecord], every: u64) {
    deck.push_str(
        "variable     rec_step equal step
",
    );
    let mut rows = Vec::new();
    for (k, w) in walls.iter().enumerate() {
        for fix in &w.fixes {
            let _ = writeln!(
                deck,
                "compute      {fix}_f all reduce sum f_{fix}[2] f_{fix}[3] f_{fix}[4]"
            );
        }
        for (a, (axis, moves)) in AXES.iter().zip(w.moves).enumerate() {
            let d = match moves {
                true => format!("v_wall{k}_d{axis}"),
                false => "0".to_string(),
            };
            let _ = writeln!(deck, "variable     rec{k}_d{axis} equal {d}");
            let sum: Vec<String> = w
                .fixes
                .iter()
                .map(|fix| format!("c_{fix}_f[{}]", a + 1))
                .collect();
            let _ = writeln!(
                deck,
                "variable     rec{k}_f{axis} equal -({})",
                sum.join("+")
            );
        }
        let cells: Vec<String> = ["d", "f"]
            .iter()
            .flat_map(|q| AXES.iter().map(move |axis| format!("rec{k}_{q}{axis}")))
            .collect();
        for c in &cells {
            let _ = writeln!(deck, "variable     {c}_g format {c} %.17g");
        }
        let values: Vec<String> = cells.iter().map(|c| format!("${{{c}_g}}")).collect();
        rows.push(format!("${{rec_step}},{},{}", k + 1, values.join(",")));
    }
    let _ = writeln!(
        deck,
        "fix          rec_walls all print {every} \"\"\"{}\"\"\" file walls.csv screen no title \"{}\"",
        rows.join("\n"),
        crate::output::run_files::WALLS_HEADER
    );
}

fn refuse_all(list: Vec<(String, String)>) -> TampError {
    crate::error::cannot_export("LAMMPS", list)
}

/// Write the deck and the data file for `scene` into `out_dir`.
pub fn export(
    scene: &Scene,
    sha: &str,
    out_dir: &Path,
    dump_every: Option<u64>,
) -> Result<Exported> {
    let built = build_unless_refused(scene, refusals(scene), "LAMMPS")?;
    let style = pair_style(scene).map_err(refuse_all)?;
    let model = style.model();
    let sim = built.sim;
    let p = &sim.state().particles;
    // A particle spanning a box touches both faces of an axis in tamp, only the nearer
    // in LAMMPS (wall_fixes).
    let diameter = 2.0 * p.largest_radius();
    let narrow: Vec<(String, String)> = scene
        .walls
        .iter()
        .enumerate()
        .filter_map(|(k, w)| match &w.shape {
            ShapeSpec::Box { lower, upper, .. }
                if (0..3).any(|a| upper[a] - lower[a] <= diameter) =>
            {
                Some((
                    format!("walls[{k}].shape"),
                    "a box no wider than a particle: LAMMPS's fix wall/gran gives a particle only the nearer of two opposite faces".to_string(),
                ))
            }
            _ => None,
        })
        .collect();
    let outside: Vec<(String, String)> = scene
        .walls
        .iter()
        .enumerate()
        .filter_map(|(k, w)| {
            starts_outside(w, &sim, sim.state().walls[k].displacement).map(|id| {
                (
                    format!("walls[{k}].shape"),
                    format!("particle {id} does not start inside the cylinder: LAMMPS's region cylinder (side in) has no contact from outside or beyond its ends, tamp's wall is a two-sided shell with rims"),
                )
            })
        })
        .collect();
    // LAMMPS's region velocity is 0 in the setup force (region.cpp set_velocity at
    // step 0), tamp's velocity wall has its v from the start (`region_move`).
    let touching = scene.walls.iter().enumerate().filter_map(|(k, w)| {
        let MotionSpec::Velocity { .. } = w.motion else {
            return None;
        };
        (0..p.len())
            .find(|&i| {
                sim.model().walls[k].deepest_overlap(&sim.state().walls[k], &p.position[i], p.radius[i]) > 0.0
            })
            .map(|i| {
                (
                    format!("walls[{k}].motion"),
                    format!("particle {} touches the moving wall at t = 0: LAMMPS gives a moving region the velocity 0 in the first (setup) force, tamp the wall's velocity; start the particles clear of it", p.id[i]),
                )
            })
    });
    // A cylinder moving along its axis at constant velocity keeps its ends closed
    // only if the closing faces stay between them over the run.
    let duration = built.steps as f64 * sim.dt();
    let periodic = scene.periodic.clone().unwrap_or_default().axes();
    let periodic_axes = periodic.map(|a| a.is_some());
    let travelling = scene.walls.iter().enumerate().flat_map(|(k, w)| {
        let travel = match (&w.shape, &w.motion) {
            (ShapeSpec::Cylinder { axis, .. }, MotionSpec::Velocity { velocity }) => {
                along_an_axis(axis).map_or(0.0, |a| velocity[a] * duration)
            }
            _ => 0.0,
        };
        let open = if travel != 0.0 {
            cylinder_refusals(w, &scene.walls, periodic_axes, travel)
        } else {
            Vec::new()
        };
        open.into_iter()
            .filter(|(field, _)| *field == "shape")
            .map(move |(_, why)| (format!("walls[{k}].motion.velocity"), why))
    });
    let narrow: Vec<(String, String)> = narrow
        .into_iter()
        .chain(outside)
        .chain(touching)
        .chain(travelling)
        .collect();
    if !narrow.is_empty() {
        return Err(refuse_all(narrow));
    }
    crate::output::create_dir(out_dir)?;

    // Box: periodic axes exactly; the others shrink-wrap with a minimum (`m`) around
    // the particles' bounding box and a margin.
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for (x, r) in p.position.iter().zip(&p.radius) {
        for a in 0..3 {
            lo[a] = lo[a].min(x[a] - r);
            hi[a] = hi[a].max(x[a] + r);
        }
    }
    if p.is_empty() {
        (lo, hi) = ([-1.0; 3], [1.0; 3]);
    }
    let span = (0..3).map(|a| hi[a] - lo[a]).fold(0.0, f64::max);
    let max_r = p.largest_radius();
    let margin = 0.05 * span + 2.0 * max_r;
    let (boundary, bounds) = box_axes(periodic, (lo, hi), margin);
    let data = crate::output::data_file::particles_data(
        &sim,
        "LAMMPS",
        sha,
        "",
        &bounds,
        "Atoms # sphere",
    );
    crate::output::write_atomic(&out_dir.join("particles.data"), data.as_bytes())?;

    let skin = neighbor_skin(scene, &p.radius);
    let every = dump_every.unwrap_or_else(|| frame_every(scene, built.steps));

    let mut deck = String::new();
    head(
        &mut deck,
        "LAMMPS (22 Jul 2025)",
        (scene, sha),
        &format!(", dt {}", g(sim.dt())),
        "lmp -in in.tamp   (or mpiexec -n N lmp -in in.tamp)",
    );
    // MDR's apparent radii change every step: `sphere 1` sends them to the ghosts.
    let mdr = scene.contact.normal.mdr().is_some();
    let atom_style = match mdr {
        true => "sphere 1",
        false => "sphere",
    };
    let _ = writeln!(deck, "units        si\natom_style   {atom_style}");
    // LAMMPS 22 Jul 2025 negates every history value of a pair whose two atoms swap
    // places in the neighbour list, the rolling displacement too, which keeps its sign
    // under the swap; the spatial sort of atoms (every 1000 steps by default) is what
    // swaps them in a serial run (docs/models/rolling_sds.md).
    if scene.contact.rolling.is_some() {
        deck.push_str(
            "# atom sorting off: it would swap pairs in the neighbour list, and LAMMPS negates a swapped pair's rolling history\natom_modify  map array sort 0 0.0\n",
        );
    } else {
        deck.push_str("atom_modify  map array\n");
    }
    let _ = writeln!(deck, "boundary     {}", boundary.join(" "));
    deck.push_str("newton       off\ncomm_modify  vel yes\nread_data    particles.data\n");
    let _ = writeln!(deck, "neighbor     {} bin\nneigh_modify delay 0", g(skin));
    deck.push_str(
        "# limit_damping as contact.damping.limit: the total normal force clamped at zero, or free to pull.\n",
    );
    let has_friction_pairs = scene
        .contact
        .tangential
        .as_ref()
        .is_some_and(|t| !t.friction_pairs.is_empty());
    // The pair model with material `m`'s E and ν and the friction `mu`.
    let line = |m: usize, mu: f64, wall: bool| {
        let m = &sim.model().materials[m];
        surface_energy(model, scene, wall)
            .replace("{E}", &g(m.youngs_modulus.unwrap_or(0.0)))
            .replace("{nu}", &g(m.poisson_ratio.unwrap_or(0.0)))
            .replace("{mu}", &g(mu))
    };
    let mu = |a: usize, b: usize| sim.model().pair_table.get(a, b).friction;
    // Particle types: the materials particles are made of (the data file's types).
    let mut kinds: Vec<usize> = p.material.clone();
    kinds.sort_unstable();
    kinds.dedup();
    match &style {
        PairStyle::Granular(_) => {
            deck.push_str("pair_style   granular\n");
            // One line per material; with friction pairs, one per pair of particle
            // materials too: LAMMPS would mix μ_ii and μ_jj, and tamp's μ_ij is the
            // scene's (refusals checked that the two materials share E and ν, so E* is
            // mixed as tamp mixes it).
            // LAMMPS's fix granular/mdr takes one mdr model ("Cannot currently define
            // multiple MDR normal models"): one line for every type, the particles'.
            if mdr {
                let a = kinds[0];
                let _ = writeln!(deck, "pair_coeff   * * {}", line(a, mu(a, a), false));
            }
            let mut pairs: Vec<(usize, usize)> = if mdr {
                Vec::new()
            } else {
                (0..sim.model().materials.len()).map(|k| (k, k)).collect()
            };
            if has_friction_pairs {
                for (x, &a) in kinds.iter().enumerate() {
                    pairs.extend(kinds[x + 1..].iter().map(|&b| (a, b)));
                }
            }
            for (a, b) in pairs {
                let _ = writeln!(
                    deck,
                    "pair_coeff   {} {} {}",
                    a + 1,
                    b + 1,
                    line(a, mu(a, b), false)
                );
            }
        }
        PairStyle::GranHookeHistory(_) => {
            let first = kinds.first().copied().unwrap_or(0);
            let _ = writeln!(
                deck,
                "pair_style   gran/hooke/history {}\npair_coeff   * *",
                line(first, mu(first, first), false)
            );
        }
    }
    timestep_and_gravity(&mut deck, &sim);
    // Walls take the pair's model with the wall material's E and ν. A fix wall/gran has
    // one μ: where the particle materials meet a wall with different μ (friction
    // pairs), the wall is one fix per particle type, each on the group of that type.
    let mut grouped = Vec::new();
    // With `output.walls` each wall fix keeps its per-particle forces (`contacts`),
    // summed into the wall's force in `walls.csv` (`walls_record`).
    let contacts = match scene.output.walls {
        true => " contacts",
        false => "",
    };
    let mut wall_records: Vec<WallRecord> = Vec::new();
    for (k, w) in scene.walls.iter().enumerate() {
        let mut record = WallRecord {
            fixes: Vec::new(),
            moves: [false; 3],
        };
        let wm = sim.model().walls[k].material;
        let groups: Vec<(String, String, f64)> =
            if kinds.iter().all(|&a| mu(a, wm) == mu(kinds[0], wm)) {
                let mu0 = kinds.first().map_or(mu(wm, wm), |&a| mu(a, wm));
                vec![(String::new(), "all".to_string(), mu0)]
            } else {
                kinds
                    .iter()
                    .map(|&a| {
                        if !grouped.contains(&a) {
                            grouped.push(a);
                            let _ = writeln!(deck, "group        type{0} type {0}", a + 1);
                        }
                        (
                            format!("_type{}", a + 1),
                            format!("type{}", a + 1),
                            mu(a, wm),
                        )
                    })
                    .collect()
            };
        if let Some(region) = cylinder_region(w).or_else(|| plane_region(w, mdr)) {
            let motion = region_move(k, w).expect("refusals checked the motion");
            let moving = match motion {
                Some((variables, keyword)) => {
                    deck.push_str(&variables);
                    for (moves, axis) in record.moves.iter_mut().zip(AXES) {
                        *moves = keyword.contains(&format!("v_wall{k}_d{axis}"));
                    }
                    format!(" {keyword}")
                }
                None => String::new(),
            };
            let _ = writeln!(deck, "region       wall{k} {region}{moving}");
            for (id, group, mu) in &groups {
                let _ = writeln!(
                    deck,
                    "fix          wall{k}{id} {group} wall/gran/region granular {} region wall{k}{contacts}",
                    line(wm, *mu, true)
                );
                record.fixes.push(format!("wall{k}{id}"));
            }
            wall_records.push(record);
            continue;
        }
        for (suffix, geometry) in wall_fixes(w, periodic_axes).expect("refusals checked the wall") {
            for (id, group, mu) in &groups {
                let _ = writeln!(
                    deck,
                    "fix          wall{k}{suffix}{id} {group} wall/gran granular {} {geometry}{contacts}",
                    line(wm, *mu, true)
                );
                record.fixes.push(format!("wall{k}{suffix}{id}"));
            }
        }
        wall_records.push(record);
    }
    if scene.output.walls {
        walls_record(&mut deck, &wall_records, every);
    }
    if mdr {
        // fix granular/mdr's free-surface fraction ψ of every particle, beside the
        // frames of dump.lammps (whose radius column is the apparent radius).
        let _ = writeln!(
            deck,
            "dump         mdr all custom {every} mdr.lammps id d_psi\ndump_modify  mdr format line \"%d %.17g\" sort id"
        );
    }
    integrate_and_run(&mut deck, LAMMPS, every, built.steps);
    crate::output::write_atomic(&out_dir.join("in.tamp"), deck.as_bytes())?;
    Ok(Exported {
        particles: p.len(),
        steps: built.steps,
        dt: sim.dt(),
        files: vec!["in.tamp".into(), "particles.data".into()],
        notes: Vec::new(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn two_spheres(contact: &str, extra: &str) -> Scene {
        crate::scene::parse(&format!(
            r#"{{"name": "t", "materials": [{{"name": "steel", "density": 7800, "youngs_modulus": 2e11, "poisson_ratio": 0.3}}],
              "contact": {contact},
              "particles": [{{"position": [-0.001001, 0, 0], "radius": 0.001, "material": "steel", "velocity": [0.5, 0, 0]}},
                            {{"position": [0.001001, 0, 0], "radius": 0.001, "material": "steel", "velocity": [-0.5, 0, 0]}}],
              "time_step": {{"fixed": 1e-9}}, "run": {{"duration": 1e-6}}{extra}}}"#
        ))
        .expect("a valid scene")
    }

    /// The gran/hooke/history history is written as that pair style, with its
    /// coefficients in its order; what the style cannot say is refused by field.
    #[test]
    fn the_gran_history_is_pair_style_gran_hooke_history() {
        let gran = r#"{"normal": {"law": "linear", "stiffness": 2e6},
            "damping": {"kind": "mass_velocity", "eta_n0": 2e4},
            "tangential": {"law": "lammps_linear_history", "stiffness": 1e6, "x_gamma_t": 0.5,
                           "history": "gran_hooke_history", "friction": 0.3},
            "lever_arm": "full_radius"}"#;
        let s = two_spheres(gran, r#", "rotation": {}"#);
        assert!(refusals(&s).is_empty(), "{:?}", refusals(&s));
        let out = std::env::temp_dir().join(format!("tamp-gran-{}", std::process::id()));
        export(&s, "0", &out, None).unwrap();
        let deck = std::fs::read_to_string(out.join("in.tamp")).unwrap();
        std::fs::remove_dir_all(&out).unwrap();
        assert!(
            deck.contains(
                "pair_style   gran/hooke/history 2e6 1e6 2e4 1e4 3e-1 1\npair_coeff   * *\n"
            ),
            "{deck}"
        );
        let refused = |contact: &str, extra: &str| -> Vec<String> {
            refusals(&two_spheres(contact, extra))
                .into_iter()
                .map(|(f, _)| f)
                .collect()
        };
        let constant = gran.replace(
            r#""kind": "mass_velocity", "eta_n0": 2e4"#,
            r#""kind": "constant", "gamma_n": 0.5"#,
        );
        assert_eq!(
            refused(&constant, r#", "rotation": {}"#),
            ["contact.damping.kind"]
        );
        let arms = gran.replace("full_radius", "lammps");
        assert_eq!(refused(&arms, r#", "rotation": {}"#), ["contact.lever_arm"]);
        let wall = r#", "rotation": {}, "walls": [{"shape": {"kind": "plane", "point": [0, 0, -0.002], "normal": [0, 0, 1]}, "material": "steel"}]"#;
        assert_eq!(refused(gran, wall), ["walls"]);
    }

    #[test]
    fn each_damping_law_names_its_lammps_model() {
        for (damping, line) in [
            (
                r#"{"kind": "liggghts_restitution", "restitution": 0.5}"#,
                "hertz/material {E} 5e-1 {nu} damping coeff_restitution tangential linear_nohistory 0 0",
            ),
            (
                r#"{"kind": "tsuji", "restitution": 0.9}"#,
                "hertz/material {E} 9e-1 {nu} damping tsuji tangential linear_nohistory 0 0",
            ),
            (
                r#"{"kind": "constant", "gamma_n": 2.5}"#,
                "hertz/material {E} 2.5e0 {nu} damping velocity tangential linear_nohistory 0 0",
            ),
            (
                r#"{"kind": "mass_velocity", "eta_n0": 5e4}"#,
                "hertz/material {E} 5e4 {nu} damping mass_velocity tangential linear_nohistory 0 0",
            ),
            (
                r#"{"kind": "viscoelastic", "eta_n0": 1e9}"#,
                "hertz/material {E} 1e9 {nu} damping viscoelastic tangential linear_nohistory 0 0",
            ),
        ] {
            let s = two_spheres(
                &format!(r#"{{"normal": {{"law": "hertz"}}, "damping": {damping}}}"#),
                "",
            );
            assert_eq!(pair_model(&s).unwrap(), line);
        }
        let s = two_spheres(r#"{"normal": {"law": "linear", "stiffness": 1e6}}"#, "");
        assert_eq!(
            pair_model(&s).unwrap(),
            "hooke 1e6 0e0 damping velocity tangential linear_nohistory 0 0"
        );
    }

    #[test]
    fn lammps_linear_laws_are_written_as_linear_history_and_linear_nohistory() {
        for (tangential, words) in [
            (
                r#"{"law": "lammps_linear_history", "stiffness": 2e5, "x_gamma_t": 0.5, "friction": 0.3}"#,
                "linear_history 2e5 5e-1 {mu}",
            ),
            (
                r#"{"law": "lammps_linear_nohistory", "x_gamma_t": 1.0, "friction": 0.3}"#,
                "linear_nohistory 1e0 {mu}",
            ),
        ] {
            let s = two_spheres(
                &format!(
                    r#"{{"normal": {{"law": "linear", "stiffness": 1e6}}, "damping": {{"kind": "constant", "gamma_n": 0.5}}, "tangential": {tangential}, "lever_arm": "lammps"}}"#
                ),
                r#", "rotation": {}"#,
            );
            assert!(refusals(&s).is_empty(), "{:?}", refusals(&s));
            assert_eq!(
                pair_model(&s).unwrap(),
                format!("hooke 1e6 5e-1 damping velocity tangential {words}")
            );
        }
    }

    /// LAMMPS's `fix nve/sphere` always turns the particles, so friction without tamp's
    /// rotation would run different physics in the deck.
    #[test]
    fn friction_without_rotation_is_refused_naming_rotation() {
        let contact = r#"{"normal": {"law": "linear", "stiffness": 1e6}, "tangential": {"law": "lammps_linear_history", "stiffness": 2e5, "x_gamma_t": 0, "friction": 0.3}, "lever_arm": "lammps"}"#;
        let paths: Vec<String> = refusals(&two_spheres(contact, ""))
            .into_iter()
            .map(|(p, _)| p)
            .collect();
        assert_eq!(paths, ["rotation"]);
        assert!(refusals(&two_spheres(contact, r#", "rotation": {}"#)).is_empty());
    }

    #[test]
    fn critical_fraction_is_written_as_the_restitution_that_gives_its_xi() {
        // ξ = −√(5/6) β(e) for hertz/material (CriticalFraction::lammps).
        let xi = -crate::contact::damping::liggghts::SQRT_FIVE_SIXTHS
            * crate::contact::damping::liggghts::beta(0.7);
        let s = two_spheres(
            &format!(
                r#"{{"normal": {{"law": "hertz"}}, "damping": {{"kind": "critical_fraction", "xi": {xi:e}}}}}"#
            ),
            "",
        );
        let line = pair_model(&s).unwrap();
        let e: f64 = line.split(' ').nth(2).unwrap().parse().unwrap();
        assert!((e - 0.7).abs() < 1e-14, "{line}");
    }

    #[test]
    fn axis_aligned_planes_are_fix_wall_gran_planes_with_the_pair_model() {
        let s = two_spheres(
            r#"{"normal": {"law": "hertz"}, "tangential": {"law": "lammps_mindlin", "variant": "mindlin_rescale_force", "friction": 0.3}, "lever_arm": "lammps"}"#,
            r#", "rotation": {}, "walls": [{"material": "steel", "shape": {"kind": "plane", "point": [0, 0, -0.01], "normal": [0, 0, 1]}},
                                           {"material": "steel", "shape": {"kind": "plane", "point": [0.02, 0, 0], "normal": [-1, 0, 0]}}]"#,
        );
        assert!(refusals(&s).is_empty(), "{:?}", refusals(&s));
        let geometry = |k: usize| wall_fixes(&s.walls[k], [false; 3]).unwrap();
        assert_eq!(geometry(0), [(String::new(), "zplane -1e-2 NULL".into())]);
        assert_eq!(geometry(1), [(String::new(), "xplane NULL 2e-2".into())]);
        assert_eq!(
            pair_model(&s).unwrap(),
            "hertz/material {E} 0e0 {nu} damping velocity tangential mindlin_rescale/force -1 0e0 {mu}"
        );
    }

    #[test]
    fn a_closed_box_is_three_planes_and_open_boxes_and_cylinders_are_refused() {
        let with_wall = |shape: &str| {
            two_spheres(
                r#"{"normal": {"law": "hertz"}}"#,
                &format!(r#", "walls": [{{"material": "steel", "shape": {shape}}}]"#),
            )
        };
        let closed = with_wall(
            r#"{"kind": "box", "lower": [-0.01, -0.01, -0.01], "upper": [0.01, 0.01, 0.02]}"#,
        );
        assert!(refusals(&closed).is_empty(), "{:?}", refusals(&closed));
        let fixes = wall_fixes(&closed.walls[0], [false; 3]).unwrap();
        assert_eq!(
            fixes.iter().map(|(_, g)| g.as_str()).collect::<Vec<_>>(),
            [
                "xplane -1e-2 1e-2",
                "yplane -1e-2 1e-2",
                "zplane -1e-2 2e-2"
            ]
        );
        // A flat cylinder is refused for its curvature and, alone, for its two open ends
        // (tests/lammps_export_cylinder.rs has the exported ones).
        for (shape, expected) in [
            (
                r#"{"kind": "box", "lower": [-0.01, -0.01, -0.01], "upper": [0.01, 0.01, 0.02], "open": ["+z"]}"#,
                &["walls[0]"][..],
            ),
            (
                r#"{"kind": "cylinder", "origin": [0, 0, -0.01], "axis": [0, 0, 1], "radius": 0.01, "bottom": 0, "top": 0.03}"#,
                &[
                    "walls[0].shape.curvature",
                    "walls[0].shape",
                    "walls[0].shape",
                ][..],
            ),
        ] {
            let paths: Vec<String> = refusals(&with_wall(shape))
                .into_iter()
                .map(|(p, _)| p)
                .collect();
            assert_eq!(paths, expected, "{shape}");
        }
    }

    #[test]
    fn a_wall_of_another_elastic_material_than_the_particles_is_refused() {
        let s = crate::scene::parse(
            r#"{"name": "t", "materials": [{"name": "steel", "density": 7800, "youngs_modulus": 2e11, "poisson_ratio": 0.3},
                                          {"name": "glass", "density": 2500, "youngs_modulus": 7e10, "poisson_ratio": 0.2}],
              "contact": {"normal": {"law": "hertz"}},
              "particles": [{"position": [0, 0, 0.0011], "radius": 0.001, "material": "steel"}],
              "walls": [{"material": "glass", "shape": {"kind": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}}],
              "time_step": {"fixed": 1e-9}, "run": {"steps": 10}}"#,
        )
        .unwrap();
        let paths: Vec<String> = refusals(&s).into_iter().map(|(p, _)| p).collect();
        assert_eq!(paths, ["walls[0].material"]);
    }
}
