//! Cold uniaxial die compaction as in Rojek et al. 2016 §5: fill a cylindrical die,
//! flatten the top, then press with a punch under a linearly rising pressure.
//!
//! Each stage is an ordinary scene built from the die-compaction scene and the
//! particles' state at the end of the previous stage (positions, radii, velocities,
//! spins), so a stage can be written out and rerun, or exported, on its own:
//!
//! 1. **Fill** (`fill`): the particles' radii are drawn from the size distribution
//!    and placed, largest first, by random sequential insertion in a loose cloud at
//!    `fill.loose_fraction`; they then settle under gravity times `fill.gravity_scale`
//!    with the fill contact law until the kinetic energy is below `rest_fraction` ·
//!    M g′ ⟨d⟩. With `fill.method: "settled_column"` (the default) the cloud is a
//!    column over the die floor, as LIGGGHTS users fill a die (`insert/pack` in the
//!    die, then run). With `"funnel"` it stands on the rim of a funnel resting in the
//!    die's mouth and pours through it, as Rojek pours (Fig 13a; the funnel's
//!    dimensions, which the paper does not give, are `scene::funnel`); the fill then
//!    fails, naming the funnel field, if any particle is left above the outlet.
//! 2. **Flatten** (`flatten`): a flat punch is put at the top of the highest
//!    particle (first contact), moved down `depth` over `duration`, back up over the
//!    same time, and the bed relaxes for a third `duration`. H₀ is then the top of
//!    the highest particle; the specimen density is the exact solid fraction of the
//!    cylinder of the die's radius and height H₀, and the RVE density that of the
//!    sphere of `rve_diameter` centred on the axis at H₀/2 (Rojek §5, Fig 15).
//! 3. **Press** (`press`): the punch, of mass `punch_mass`, is loaded by the
//!    pressure p(t) = p_max t / t_ramp (`BoundaryMotion::Pressed`) under the scene's
//!    own contact law, damping, rotation and (unscaled) gravity, the die's contacts
//!    with `die_curvature` (flat by default, as in the fill and flatten; `mean` for
//!    LAMMPS's cylinder wall, `boundary::Boundary::effective_radius`). The time step is
//!    re-estimated every `dt_every` steps from the contacts as they stiffen (Rojek
//!    §3.4: α times the critical step), or fixed by `time_step` (every record on a
//!    step), as a run an engine records needs. At `records` equal pressure increments the
//!    height H (the punch face), ΔH/H₀, both densities (the RVE centred at H/2) and
//!    the forces on punch, floor and die wall are recorded.

use super::die_compaction_file::{DieCompactionFile, DieCompactionSpec, FillMethod};
use super::funnel::Funnel;
use super::press_cycle::DieWall;
use crate::error::{Result, TampError};
use crate::generate::rsi::{InsertionBox, Placed};
use crate::measure::{Region, packing::packing_fraction};
use crate::particles::Vec3;
use crate::progress::Progress;
use crate::scene::schema::{ContactSpec, ParticleSpec, RunSpec, Scene};
use crate::scene::walls::{MotionSpec, ShapeSpec, WallSpec};
use crate::scene::{self, validate};
use crate::simulation::{Simulation, State};
use crate::space::Space;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Attempts per particle in the loose cloud before insertion gives up.
const INSERTION_ATTEMPTS: usize = 100_000;
/// Steps between checks of whether the settling bed is at rest.
const REST_CHECK_EVERY: u64 = 1000;

/// The flattened specimen: what the press stage starts from.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Specimen {
    /// Height after flattening and unloading (top of the highest particle), m.
    pub h0: f64,
    /// Solid fraction of the cylinder of the die's radius and height H₀.
    pub density_specimen: f64,
    /// Solid fraction of the RVE sphere (`rve_diameter`) centred on the axis at H₀/2.
    pub density_rve: f64,
    /// The particles as the press stage's explicit particles (position, radius, velocity,
    /// spin, material).
    pub particles: Vec<ParticleSpec>,
    /// Simulated settling time of the fill, s.
    pub fill_time: f64,
    /// Whether the bed came to rest before `fill.max_duration`.
    pub fill_at_rest: bool,
    /// The steps each stage took (fill, flatten).
    pub steps: [u64; 2],
    /// Time steps of the fill and flatten stages, s.
    pub dt: [f64; 2],
}

/// One record along the pressure ramp.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct PressRecord {
    /// Simulated time since the pressing began, s.
    pub time: f64,
    /// Pressure applied to the punch, Pa.
    pub pressure: f64,
    /// The particles' push on the punch over the die's cross-section, Pa.
    pub punch_reaction: f64,
    /// The particles' push on the floor over the die's cross-section, Pa.
    pub floor_reaction: f64,
    /// The particles' axial friction on the die wall over the die's cross-section, Pa.
    pub die_friction: f64,
    /// Punch face height H, m.
    pub height: f64,
    /// Height reduction ΔH/H₀ = (H₀ − H)/H₀.
    pub height_reduction: f64,
    /// Solid fraction of the cylinder of the die's radius and height H.
    pub density_specimen: f64,
    /// Solid fraction of the RVE sphere centred on the axis at H/2.
    pub density_rve: f64,
    /// Volume of the caps of particles pressed through the floor, punch face and die
    /// wall, m³ (planar caps, of the material's spheres as the densities): what the
    /// specimen's exact solid volume leaves out of the particles' volume.
    pub wall_lens_volume: f64,
    /// Number of particle–particle and particle–wall contacts.
    pub contact_count: usize,
    /// Time step in force at the record, s (re-estimated every `press.dt_every` steps).
    pub dt: f64,
    /// Steps since the pressing began.
    pub step: u64,
}

/// The press stage of one contact law.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Pressing {
    /// The records at equal pressure increments, from p = 0 to the final pressure.
    pub records: Vec<PressRecord>,
    /// Steps the pressing took.
    pub steps: u64,
    /// Particles whose centre left the die (radially, below the floor or above the
    /// punch face) at some step of the pressing.
    pub escaped: Vec<usize>,
    /// With a press cycle (`die_compaction.unload`): the die wall's radial force at
    /// each record, in the records' order.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub die_wall: Vec<DieWall>,
}

/// Where a pressing is, for a restart checkpoint: the records so far and the
/// simulation's state.
#[derive(Serialize, Deserialize)]
pub struct PressState {
    /// The pressing so far.
    pub pressing: Pressing,
    /// The simulation's state at the checkpoint's step.
    pub sim: State,
}

impl Pressing {
    /// Value of `column` at the applied pressure p, linearly interpolated between
    /// the records around it.
    pub fn at_pressure(&self, p: f64, column: impl Fn(&PressRecord) -> f64) -> Option<f64> {
        self.records.windows(2).find_map(|w| {
            let (a, b) = (&w[0], &w[1]);
            (a.pressure <= p && p <= b.pressure && b.pressure > a.pressure).then(|| {
                let s = (p - a.pressure) / (b.pressure - a.pressure);
                column(a) + s * (column(b) - column(a))
            })
        })
    }
}

fn gravity(scene: &Scene) -> Result<Vec3> {
    scene
        .gravity
        .map(|g| Vec3::new(g[0], g[1], g[2]))
        .ok_or_else(|| TampError::input("gravity", "is required by die_compaction"))
}

/// A stage scene: the die-compaction scene's materials, rotation, time step, broad
/// phase and stability settings with the stage's particles, walls, law and gravity.
fn stage_scene(
    base: &Scene,
    stage: &str,
    contact: &ContactSpec,
    particles: Vec<ParticleSpec>,
    walls: Vec<WallSpec>,
    gravity: Vec3,
    duration: f64,
) -> Result<Scene> {
    let mut s = base.clone();
    s.name = format!("{} — {stage} stage", base.name);
    // The stages step by α (the press re-estimates it from the contacts), never by
    // the accuracy default of a scene that states no step.
    s.time_step.alpha = Some(base.time_step.alpha());
    s.contact = contact.clone();
    s.particles = particles;
    s.walls = walls;
    s.gravity = Some([gravity.x, gravity.y, gravity.z]);
    s.run = RunSpec {
        duration: Some(duration),
        steps: None,
        until: None,
        max_wall_time: base.run.max_wall_time,
    };
    // A carried bed is in contact: its overlaps are state, not input mistakes.
    s.stability.initial_overlap_tolerance = s.stability.max_overlap_fraction;
    validate::validate(&s)?;
    Ok(s)
}

fn die_wall(dc: &DieCompactionSpec, top: f64) -> WallSpec {
    WallSpec {
        name: Some("die".into()),
        material: dc.wall_material.clone(),
        shape: ShapeSpec::Cylinder {
            origin: [0.0; 3],
            axis: [0.0, 0.0, 1.0],
            radius: 0.5 * dc.die_diameter,
            bottom: 0.0,
            top,
            curvature: Default::default(),
        },
        motion: MotionSpec::Fixed,
    }
}

fn floor_wall(dc: &DieCompactionSpec) -> WallSpec {
    WallSpec {
        name: Some("floor".into()),
        material: dc.wall_material.clone(),
        shape: ShapeSpec::Plane {
            point: [0.0; 3],
            normal: [0.0, 0.0, 1.0],
        },
        motion: MotionSpec::Fixed,
    }
}

fn punch_wall(dc: &DieCompactionSpec, height: f64, motion: MotionSpec) -> WallSpec {
    WallSpec {
        name: Some("punch".into()),
        material: dc.wall_material.clone(),
        shape: ShapeSpec::Plane {
            point: [0.0, 0.0, height],
            normal: [0.0, 0.0, -1.0],
        },
        motion,
    }
}

/// The particles of a simulation as explicit particles of the next stage.
fn carried(sim: &Simulation, material: &str) -> Vec<ParticleSpec> {
    let p = &sim.state.particles;
    (0..p.len())
        .map(|i| ParticleSpec {
            position: p.position[i].into(),
            radius: p.radius[i],
            material: material.to_string(),
            velocity: Some(p.velocity[i].into()),
            // A scene without rotation carries no spins, which it would refuse.
            omega: sim.model.rotation.then(|| p.omega[i].into()),
            prescribed_velocity: None,
            prescribed_velocity_changes: Vec::new(),
        })
        .collect()
}

/// The top of the highest particle, m.
pub(super) fn top_of_bed(sim: &Simulation) -> f64 {
    let p = &sim.state.particles;
    (0..p.len())
        .map(|i| p.position[i].z + p.radius[i])
        .fold(f64::NEG_INFINITY, f64::max)
}

/// Solid fraction of the die cylinder up to `height` and of the RVE centred at
/// half that height (Rojek §5, Fig 15), of the particles' material
/// (`State::material_radius`).
pub fn densities(state: &State, dc: &DieCompactionSpec, height: f64) -> Result<(f64, f64)> {
    let positions = &state.particles.position;
    densities_in(
        positions,
        state.material_radius(),
        dc.die_diameter,
        dc.rve_diameter,
        height,
    )
}

/// `densities` for a die and RVE given by their diameters.
pub fn densities_in(
    positions: &[Vec3],
    radii: &[f64],
    die_diameter: f64,
    rve_diameter: f64,
    height: f64,
) -> Result<(f64, f64)> {
    let space = Space::open();
    let specimen = Region::Cylinder {
        base: Vec3::zeros(),
        axis: Vec3::z(),
        radius: 0.5 * die_diameter,
        height,
    };
    let rve = Region::Sphere {
        centre: Vec3::new(0.0, 0.0, 0.5 * height),
        radius: 0.5 * rve_diameter,
    };
    Ok((
        packing_fraction(positions, radii, &specimen, &space)?,
        packing_fraction(positions, radii, &rve, &space)?,
    ))
}

/// Σ of the caps π δ² (3r − δ)/3 that particles push through the floor (z = 0), the
/// punch face (z = height) and the die wall (radius R), each cap taken as cut by a
/// plane: the die wall curves towards the axis, so a die cap is larger by up to a
/// fraction r/(2R) of itself, which the full case's tolerance allows for.
pub fn wall_lens_volume(positions: &[Vec3], radii: &[f64], die_radius: f64, height: f64) -> f64 {
    let cap = |r: f64, depth: f64| {
        let d = depth.clamp(0.0, 2.0 * r);
        PI * d * d * (3.0 * r - d) / 3.0
    };
    positions
        .iter()
        .zip(radii)
        .map(|(x, &r)| {
            cap(r, r - x.z) + cap(r, x.z + r - height) + cap(r, x.x.hypot(x.y) + r - die_radius)
        })
        .sum()
}

/// Radii drawn from the distribution, placed largest first in a loose cylindrical
/// cloud of `radius` standing on the height `bottom` (the die floor for the settled
/// column, the funnel's rim for the pour); returned sorted by height so neighbours in
/// space are near in memory, with the cloud's height.
fn loose_cloud(
    scene: &Scene,
    dc: &DieCompactionSpec,
    radius: f64,
    bottom: f64,
) -> Result<(Vec<ParticleSpec>, f64)> {
    let mut rng = ChaCha8Rng::seed_from_u64(scene.seed);
    let law = dc.particles.radius.distribution();
    let mut radii: Vec<f64> = (0..dc.particles.count)
        .map(|_| law.sample(&mut rng))
        .collect();
    radii.sort_by(|a, b| b.total_cmp(a));
    let solid: f64 = radii.iter().map(|r| 4.0 / 3.0 * PI * r.powi(3)).sum();
    let height = solid / (dc.fill.loose_fraction * PI * radius * radius);
    let region = InsertionBox {
        lower: Vec3::new(-radius, -radius, bottom),
        upper: Vec3::new(radius, radius, bottom + height),
    };
    let inside = |x: &Vec3, r: f64| x.x.hypot(x.y) + r <= radius;
    let mut placed = Placed::new(&Space::open(), 2.0 * radii.first().copied().unwrap_or(0.0));
    let mut progress = Progress::new("place", radii.len() as u64, false);
    for (k, &r) in radii.iter().enumerate() {
        if placed
            .place(r, &region, &inside, 1.0, &mut rng, INSERTION_ATTEMPTS)
            .is_none()
        {
            return Err(TampError::input(
                "die_compaction.fill.loose_fraction",
                format!(
                    "particle {k} (radius {r:e} m) found no room in the loose cloud after {INSERTION_ATTEMPTS} attempts; lower the loose fraction (got {})",
                    dc.fill.loose_fraction
                ),
            ));
        }
        if k % 1024 == 0 {
            progress.set(k as u64);
        }
    }
    progress.finish();
    let Placed {
        position, radius, ..
    } = placed;
    let mut order: Vec<usize> = (0..position.len()).collect();
    order.sort_by(|&a, &b| position[a].z.total_cmp(&position[b].z));
    let particles = order
        .into_iter()
        .map(|i| ParticleSpec {
            position: position[i].into(),
            radius: radius[i],
            material: dc.particles.material.clone(),
            velocity: None,
            omega: None,
            prescribed_velocity: None,
            prescribed_velocity_changes: Vec::new(),
        })
        .collect();
    Ok((particles, height))
}

/// How the fill stage starts: the particles, the walls, the highest point a particle
/// falls from, and the top of the die wall (kept for the flatten stage).
struct FillStart {
    particles: Vec<ParticleSpec>,
    walls: Vec<WallSpec>,
    fall_height: f64,
    die_top: f64,
}

fn fill_start(scene: &Scene, dc: &DieCompactionSpec) -> Result<FillStart> {
    let die_radius = 0.5 * dc.die_diameter;
    match dc.fill.method {
        FillMethod::SettledColumn => {
            let (particles, height) = loose_cloud(scene, dc, die_radius, 0.0)?;
            let die_top = 1.5 * height;
            Ok(FillStart {
                particles,
                walls: vec![die_wall(dc, die_top), floor_wall(dc)],
                fall_height: height,
                die_top,
            })
        }
        FillMethod::Funnel => {
            let f = Funnel::of(dc);
            let (particles, height) = loose_cloud(scene, dc, 0.5 * f.top_diameter, f.top())?;
            let die_top = f.die_top(dc.die_diameter);
            Ok(FillStart {
                particles,
                walls: vec![die_wall(dc, die_top), floor_wall(dc), funnel_wall(dc, &f)],
                fall_height: f.top() + height,
                die_top,
            })
        }
    }
}

fn funnel_wall(dc: &DieCompactionSpec, f: &Funnel) -> WallSpec {
    WallSpec {
        name: Some("funnel".into()),
        material: dc.wall_material.clone(),
        shape: ShapeSpec::Funnel {
            origin: [0.0; 3],
            axis: [0.0, 0.0, 1.0],
            outlet_radius: 0.5 * f.outlet_diameter,
            outlet_bottom: f.outlet_height,
            outlet_top: f.knee(),
            top_radius: 0.5 * f.top_diameter,
            top: f.top(),
        },
        motion: MotionSpec::Fixed,
    }
}

/// The kinetic energy the rest test of the fill reads. The column counts spin too.
/// The pour does not: every particle slides down the cone, whose friction (0.02)
/// spins it up, and between frictionless particles nothing spins it down again, so
/// the spin outlives the settling; it does not move the packing, which only the
/// die wall's 0.02 couples it to.
fn moving_energy(sim: &Simulation, method: FillMethod) -> f64 {
    match method {
        FillMethod::SettledColumn => sim.kinetic_energy(),
        FillMethod::Funnel => sim.state.particles.translational_kinetic_energy(),
    }
}

/// After a funnel pour every particle must lie whole in the die below the outlet: a
/// particle left in the funnel (a clogged outlet) or a bed reaching the tube would
/// make a specimen the flatten stage cannot mean.
fn check_poured(sim: &Simulation, dc: &DieCompactionSpec) -> Result<()> {
    let f = Funnel::of(dc);
    let p = &sim.state.particles;
    let above = (0..p.len())
        .filter(|&i| p.position[i].z + p.radius[i] > f.outlet_height)
        .count();
    if above == 0 {
        return Ok(());
    }
    let in_funnel = (0..p.len())
        .filter(|&i| p.position[i].z > f.outlet_height)
        .count();
    Err(if in_funnel > 0 {
        TampError::input(
            "die_compaction.fill.funnel.outlet_diameter",
            format!(
                "{in_funnel} of {} particles did not leave the funnel by the end of the fill (the outlet clogged, or fill.max_duration is too short); widen the outlet",
                p.len()
            ),
        )
    } else {
        TampError::input(
            "die_compaction.fill.funnel.outlet_height",
            format!(
                "the settled bed reaches the outlet ({above} particles above its lower end at {:e} m); raise the outlet",
                f.outlet_height
            ),
        )
    })
}

/// Fill and flatten: the specimen the press stage starts from.
pub fn prepare(file: &DieCompactionFile, quiet: bool) -> Result<Specimen> {
    let (scene, dc) = (&file.shared_scene(), &file.die_compaction);
    crate::scene::memory::check_with(
        scene,
        None,
        Some(("die_compaction.particles.count", dc.particles.count)),
    )?;
    let g = gravity(scene)? * dc.fill.gravity_scale;
    let start = fill_start(scene, dc)?;
    let die_top = start.die_top;

    // Fill: settle under scaled gravity. The fastest impact is a free fall from the
    // top of the loose cloud, which sets the step of the (overlap-dependent) law.
    let mut fill = stage_scene(
        scene,
        "fill",
        &dc.fill.contact,
        start.particles,
        start.walls,
        g,
        dc.fill.max_duration,
    )?;
    fill.time_step.characteristic_velocity = Some((2.0 * g.norm() * start.fall_height).sqrt());
    fill.time_step.alpha = Some(dc.fill.alpha.unwrap_or(scene.time_step.alpha()));
    let built = scene::build(&fill)?;
    let mut sim = built.sim;
    let p = &sim.state.particles;
    let total_mass: f64 = p.mass.iter().sum();
    let mean_diameter = 2.0 * p.radius.iter().sum::<f64>() / p.len() as f64;
    let at_rest = dc.fill.rest_fraction * total_mass * g.norm() * mean_diameter;
    let mut progress = Progress::new("fill", built.steps, quiet);
    let mut fill_at_rest = false;
    while sim.state.step < built.steps {
        sim.step()?;
        stop_if_signalled(&sim, "filling")?;
        if sim.state.step % REST_CHECK_EVERY == 0 {
            progress.set(sim.state.step);
            if moving_energy(&sim, dc.fill.method) < at_rest {
                fill_at_rest = true;
                break;
            }
        }
    }
    progress.finish();
    if dc.fill.method == FillMethod::Funnel {
        check_poured(&sim, dc)?;
        // The spin the cone gave (see `moving_energy`) is not carried on: the flatten
        // punch's friction would turn it back into speed (tens of m/s under g′, where
        // the bed's own settling speeds are mm/s) and throw the top layer about.
        sim.state.particles.omega.fill(Vec3::zeros());
    }
    let (fill_time, fill_steps, fill_dt) = (sim.state.time, sim.state.step, sim.state.dt);
    if !quiet {
        eprintln!(
            "fill: {} after {fill_time:e} s ({fill_steps} steps of {fill_dt:e} s)",
            if fill_at_rest {
                "at rest"
            } else {
                "NOT at rest (max_duration reached)"
            }
        );
    }

    // Flatten: down `depth` from first contact, back up, relax.
    let (depth, t) = (dc.flatten.depth, dc.flatten.duration);
    let first_contact = top_of_bed(&sim);
    let stroke = format!(
        "-{depth:e} * min(t / {t:e}, 1.0) + {depth:e} * min(max((t - {t:e}) / {t:e}, 0.0), 1.0)"
    );
    let flatten_motion = MotionSpec::Displacement {
        x: "0.0".into(),
        y: "0.0".into(),
        z: stroke,
    };
    let mut flatten = stage_scene(
        scene,
        "flatten",
        &dc.fill.contact,
        carried(&sim, &dc.particles.material),
        vec![
            die_wall(dc, die_top),
            floor_wall(dc),
            punch_wall(dc, first_contact, flatten_motion),
        ],
        g,
        3.0 * t,
    )?;
    flatten.time_step = fill.time_step.clone();
    let built = scene::build(&flatten)?;
    let mut sim = built.sim;
    let mut progress = Progress::new("flatten", built.steps, quiet);
    while sim.state.step < built.steps {
        sim.step()?;
        stop_if_signalled(&sim, "flattening")?;
        if sim.state.step % REST_CHECK_EVERY == 0 {
            progress.set(sim.state.step);
        }
    }
    progress.finish();
    let h0 = top_of_bed(&sim);
    let (density_specimen, density_rve) = densities(&sim.state, dc, h0)?;
    Ok(Specimen {
        h0,
        density_specimen,
        density_rve,
        particles: carried(&sim, &dc.particles.material),
        fill_time,
        fill_at_rest,
        steps: [fill_steps, sim.state.step],
        dt: [fill_dt, sim.state.dt],
    })
}

/// The press-stage scene for a specimen, under the scene's own contact law.
pub fn press_scene(file: &DieCompactionFile, specimen: &Specimen) -> Result<Scene> {
    let (scene, dc) = (&file.shared_scene(), &file.die_compaction);
    let area = PI * (0.5 * dc.die_diameter).powi(2);
    let motion = MotionSpec::Pressure {
        direction: [0.0, 0.0, -1.0],
        pressure: dc.press.pressure,
        area,
        ramp_time: dc.press.ramp_time,
        mass: dc.press.punch_mass,
    };
    // The pressing's die takes `die_curvature`; the fill's and flatten's stay flat, so
    // scenes that differ only in it (and the press law) share one specimen
    // (verify/cases/die_specimen.rs) and the peer replays, which start from tamp's
    // flattened specimen, compare the pressing alone.
    // A die pressed through a cycle is filled to its brim: its mouth at H₀ is where the
    // ejected compact leaves it. The pressing alone keeps the die twice as tall, which
    // no particle below the punch reaches either.
    let mouth = if dc.unload.is_some() { 1.0 } else { 2.0 };
    let mut die = die_wall(dc, mouth * specimen.h0);
    if let ShapeSpec::Cylinder { curvature, .. } = &mut die.shape {
        *curvature = dc.die_curvature;
    }
    let mut stage = stage_scene(
        scene,
        "press",
        &scene.contact,
        specimen.particles.clone(),
        vec![die, floor_wall(dc), punch_wall(dc, specimen.h0, motion)],
        gravity(scene)?,
        dc.press.ramp_time,
    )?;
    if let Some((dt, per_record)) = dc.press.fixed_step() {
        stage.time_step.fixed = Some(dt);
        stage.run.duration = None;
        stage.run.steps = Some(per_record * dc.press.records as u64);
    }
    Ok(stage)
}

/// Stop after a whole step of a stage that is not checkpointed when a signal came.
fn stop_if_signalled(sim: &Simulation, stage: &str) -> Result<()> {
    match crate::interrupt::received() {
        None => Ok(()),
        Some(signal) => Err(TampError::Interrupted {
            signal,
            step: sim.state.step,
            time: sim.state.time,
            next: format!("the {stage} is not checkpointed; a new run starts from the filling"),
        }),
    }
}

/// Press a specimen under the scene's contact law and record the ramp; the run at the
/// peak is returned too, for a press cycle to go on from (`press_cycle::run`).
/// `resume` continues a pressing from its checkpoint; `checkpoint` is called with the
/// state every `every` steps (0: never). With a cycle, every record also measures the
/// die wall's radial force, and a checkpoint is written at the peak, so that an
/// interrupted cycle starts again from there.
pub fn press(
    file: &DieCompactionFile,
    specimen: &Specimen,
    quiet: bool,
    resume: Option<PressState>,
    every: u64,
    checkpoint: &mut dyn FnMut(&PressState) -> Result<()>,
) -> Result<(Pressing, Simulation)> {
    let (scene, dc) = (&file.shared_scene(), &file.die_compaction);
    let stage = press_scene(file, specimen)?;
    let built = scene::build(&stage)?;
    let mut sim = built.sim;
    let (die, floor, punch) = (0, 1, 2);
    let area = PI * (0.5 * dc.die_diameter).powi(2);
    let die_radius = 0.5 * dc.die_diameter;
    let alpha = scene.time_step.alpha();
    let fixed = stage.time_step.fixed;
    let ramp = dc.press.ramp_time;
    let records = dc.press.records;
    let record = |sim: &Simulation, out: &mut Pressing| -> Result<()> {
        let height = specimen.h0 + sim.state.walls[punch].displacement.z;
        let (density_specimen, density_rve) = densities(&sim.state, dc, height)?;
        let crate::boundary::BoundaryMotion::Pressed(load) = &sim.model.walls[punch].motion else {
            unreachable!("the punch is pressure-loaded")
        };
        out.records.push(PressRecord {
            time: sim.state.time,
            pressure: load.pressure_at(sim.state.time),
            punch_reaction: sim.state.wall_force[punch].z / area,
            floor_reaction: -sim.state.wall_force[floor].z / area,
            die_friction: -sim.state.wall_force[die].z / area,
            height,
            height_reduction: (specimen.h0 - height) / specimen.h0,
            density_specimen,
            density_rve,
            wall_lens_volume: wall_lens_volume(
                &sim.state.particles.position,
                sim.state.material_radius(),
                die_radius,
                height,
            ),
            contact_count: sim.contact_count(),
            dt: sim.state.dt,
            step: sim.state.step,
        });
        if let Some(bands) = dc.die_bands() {
            let floor_level = sim.state.walls[floor].displacement.z;
            out.die_wall.push(DieWall::of(
                sim,
                die,
                die_radius,
                floor_level,
                height,
                bands,
            ));
        }
        Ok(())
    };
    let mut out = match resume {
        Some(state) => {
            sim.resume(state.sim)?;
            state.pressing
        }
        None => {
            let mut out = Pressing {
                records: Vec::with_capacity(records + 1),
                steps: 0,
                escaped: Vec::new(),
                die_wall: Vec::new(),
            };
            record(&sim, &mut out)?;
            out
        }
    };
    let mut progress = Progress::new("press", records as u64, quiet);
    loop {
        let next = out.records.len();
        if next > records {
            break;
        }
        // Land exactly on the record times so every run samples the same pressures.
        let due = ramp * next as f64 / records as f64;
        if sim.state.time >= due * (1.0 - 1e-12) {
            record(&sim, &mut out)?;
            progress.set(next as u64);
            continue;
        }
        if let Some(signal) = crate::interrupt::received() {
            progress.finish();
            if every > 0 {
                out.steps = sim.state.step;
                checkpoint(&PressState {
                    pressing: out.clone(),
                    sim: sim.state.clone(),
                })?;
            }
            return Err(TampError::Interrupted {
                signal,
                step: sim.state.step,
                time: sim.state.time,
                next: if every > 0 {
                    "the pressing was checkpointed".into()
                } else {
                    "nothing was saved (output.checkpoint_every is 0)".into()
                },
            });
        }
        if every > 0 && sim.state.step > 0 && sim.state.step % every == 0 {
            out.steps = sim.state.step;
            checkpoint(&PressState {
                pressing: out.clone(),
                sim: sim.state.clone(),
            })?;
        }
        if fixed.is_none()
            && sim.state.step % dc.press.dt_every == 0
            && let Some(dt_cr) = sim.critical_time_step(None)
        {
            sim.set_time_step(alpha * dt_cr)?;
        }
        let dt = sim.state.dt;
        sim.set_time_step(dt.min(due - sim.state.time))?;
        sim.step()?;
        sim.set_time_step(dt)?;
        let height = specimen.h0 + sim.state.walls[punch].displacement.z;
        let p = &sim.state.particles;
        for (i, x) in p.position.iter().enumerate() {
            if (x.x.hypot(x.y) > die_radius || x.z < 0.0 || x.z > height)
                && !out.escaped.contains(&i)
            {
                out.escaped.push(i);
            }
        }
    }
    progress.finish();
    out.steps = sim.state.step;
    if every > 0 && dc.unload.is_some() {
        checkpoint(&PressState {
            pressing: out.clone(),
            sim: sim.state.clone(),
        })?;
    }
    Ok((out, sim))
}
