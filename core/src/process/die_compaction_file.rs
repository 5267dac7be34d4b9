//! A die-compaction file: the cold uniaxial die compaction of Rojek et al. 2016 §5 as
//! one JSON object, a process document that `process::die_compaction` runs as a short
//! sequence of stage scenes sharing the particles' state. Its `die_compaction` block
//! describes the process; its other blocks are those the stage scenes share, written
//! as in a scene file (docs/scene-format.md):
//!
//! ```json
//! "die_compaction": {
//!   "die_diameter": 58e-6, "wall_material": "die",
//!   "particles": {"count": 1751, "material": "NiAl", "radius": {"law": "log_normal", ...}},
//!   "fill": {"contact": {...}, "gravity_scale": 1e4, "loose_fraction": 0.25,
//!            "max_duration": 1e-3, "method": "settled_column"},
//!   "flatten": {"depth": 3e-6, "duration": 1e-5},
//!   "press": {"pressure": 50e6, "ramp_time": 1e-4, "punch_mass": 1e-9,
//!             "records": 200, "dt_every": 100},
//!   "rve_diameter": 54e-6, "die_curvature": "flat"
//! }
//! ```
//! The file's own `contact`, `rotation`, `time_step` and `gravity` are those of the
//! pressing stage; `fill.contact` is the law used while the die is filled and the
//! top flattened (frictionless Hertz in the paper). The die, its floor and the punch
//! are made of `wall_material`, so particle–wall friction is set through
//! `friction_pairs` of each contact block. `die_curvature` is how the die's curvature
//! enters the pressing's wall contacts (`scene::walls::Curvature`); the fill and
//! flatten keep a flat die (`process::die_compaction::press_scene` says why). The
//! particles, walls, periodic axes, growth and run length are the stages' own, so a
//! file that gives them is refused, naming each.
//!
//! `fill.method` is how the particles reach the die: `settled_column` (the default)
//! places them in a loose column inside the die; `funnel` places them in a loose cloud
//! above a funnel that rests in the die's mouth, as Rojek's Fig 13a pours them
//! (`fill.funnel`, every dimension optional, `process::funnel`; the pour in
//! `process::die_compaction`).

pub use super::funnel::{FillMethod, FunnelSpec};
pub use super::press_cycle::{EjectSpec, RelaxSpec, UnloadSpec};
use crate::error::{Errors, Result};
use crate::scene::contact::{self, LawContext};
use crate::scene::schema::{ContactSpec, RadiusSpec, Scene};
use crate::scene::walls::Curvature;
use crate::scene::{materials, physics, run};
use serde::{Deserialize, Serialize};
use std::collections::HashSet;
use std::path::Path;

/// A die-compaction file: the scene its stages share, and the process. In the file
/// the scene's blocks and `die_compaction` are members of one object; the blocks the
/// stages set (particles, walls, periodic axes, growth, the run's length) are refused
/// when given.
#[derive(Clone, Debug)]
pub struct DieCompactionFile {
    /// The blocks the stage scenes share, read by the scene's own reader and rules:
    /// the pressing stage's contact law, the materials, gravity (required), rotation,
    /// the time step, detection, stability and output.
    pub scene: Scene,
    /// The process: die, particles, fill, flatten, press and RVE.
    pub die_compaction: DieCompactionSpec,
}

/// The `die_compaction` member, the file's other members passed over.
#[derive(Deserialize)]
struct Process {
    die_compaction: DieCompactionSpec,
}

/// The text with the `die_compaction` member (key, value and one separating comma)
/// replaced by spaces, line breaks kept, so that every other member keeps its line
/// and column.
fn without_process(text: &str) -> Result<String> {
    #[derive(Deserialize)]
    struct Raw<'a> {
        #[serde(borrow)]
        die_compaction: &'a serde_json::value::RawValue,
    }
    // The process member was read from this text already, so it is well formed.
    let raw: Raw = serde_json::from_str(text).map_err(|e| {
        crate::error::TampError::input("die_compaction", format!("could not be placed: {e}"))
    })?;
    let value = raw.die_compaction.get();
    // The value borrows from `text`, so its place there is the pointers' difference.
    let start = value.as_ptr() as usize - text.as_ptr() as usize;
    let end = start + value.len();
    let key = "\"die_compaction\"";
    let before = text[..start]
        .trim_end()
        .strip_suffix(':')
        .map(str::trim_end);
    let Some(key_start) = before.and_then(|b| b.strip_suffix(key)).map(|b| b.len()) else {
        return Err(crate::error::TampError::input(
            "die_compaction",
            "must be written as the plain key \"die_compaction\" (no escapes in its name)",
        ));
    };
    let mut blank = vec![(key_start, end)];
    let after = end + (text.len() - end - text[end..].trim_start().len());
    if text[after..].starts_with(',') {
        blank.push((after, after + 1));
    } else if let Some(comma) = text[..key_start].trim_end().strip_suffix(',') {
        blank.push((comma.len(), comma.len() + 1));
    }
    let mut out = text.as_bytes().to_vec();
    for (a, b) in blank {
        for byte in &mut out[a..b] {
            if *byte != b'\n' && *byte != b'\r' {
                *byte = b' ';
            }
        }
    }
    Ok(String::from_utf8(out).expect("multi-byte characters are blanked whole"))
}

/// The file as written: the scene's members, then `die_compaction`.
#[derive(Serialize)]
struct Written<'a> {
    #[serde(flatten)]
    scene: &'a Scene,
    die_compaction: &'a DieCompactionSpec,
}

impl Serialize for DieCompactionFile {
    fn serialize<S: serde::Serializer>(
        &self,
        serializer: S,
    ) -> std::result::Result<S::Ok, S::Error> {
        Written {
            scene: &self.scene,
            die_compaction: &self.die_compaction,
        }
        .serialize(serializer)
    }
}

impl DieCompactionFile {
    /// Parse a die-compaction file's JSON text and check every rule. Errors name the
    /// JSON path and the rule, as a scene's do; a scene file is refused naming
    /// `die_compaction`.
    pub fn parse(text: &str) -> Result<Self> {
        if crate::scene::is_process(text) == Some(false) {
            return Err(crate::error::TampError::input(
                "die_compaction",
                "is required: this file is a scene, not a die-compaction process",
            ));
        }
        Self::parse_known(text)
    }

    /// `parse` of a text already known to be a die-compaction file (`document::parse`
    /// has looked). Each part is read by its own reader from the text as written, so
    /// errors give the file's own lines and columns: `die_compaction` by a reader of
    /// that member alone, the scene's members by the scene's reader from the text with
    /// `die_compaction` blanked out, so they meet every rule of a scene (an unknown
    /// member is refused by name, which one reader of both could not do: serde's
    /// `flatten` lets unknown members through).
    pub(crate) fn parse_known(text: &str) -> Result<Self> {
        // Malformed JSON first, named at its path as in a scene (the process reader
        // passes over the other members without following their paths).
        let _: serde_json::Value = crate::scene::parse_json(text)?;
        let scene: Scene = crate::scene::parse_json(&without_process(text)?)?;
        let process: Process = crate::scene::parse_json(text)?;
        let file = DieCompactionFile {
            scene,
            die_compaction: process.die_compaction,
        };
        file.validate()?;
        Ok(file)
    }

    /// Read, parse and validate a die-compaction file; also returns the SHA-256 of its
    /// bytes. `-` (or `/dev/stdin`) reads standard input, as `scene::load` does.
    pub fn load(path: &Path) -> Result<(Self, String)> {
        let input = crate::scene::read_input(path)?;
        let mut file = Self::parse(&input.text)?;
        file.scene.base_dir = input.base_dir;
        Ok((file, input.sha256))
    }

    /// The scene every stage starts from: the file's shared blocks, with no particles,
    /// walls or run length (each stage sets its own).
    pub fn shared_scene(&self) -> Scene {
        self.scene.clone()
    }

    /// Every rule of the file; all violations are listed together (exit 2). The
    /// shared blocks are checked by the scene topics' own rules, the fill stage's
    /// contact block at its path.
    pub fn validate(&self) -> Result<()> {
        let (scene, dc) = (&self.scene, &self.die_compaction);
        let mut e = Errors(Vec::new());
        let owned = [
            ("particles", !scene.particles.is_empty()),
            ("insert", !scene.insert.is_empty()),
            ("deposit", !scene.deposit.is_empty()),
            ("walls", !scene.walls.is_empty()),
            ("periodic", scene.periodic.is_some()),
            ("growth", scene.growth.is_some()),
            (
                "run",
                scene.run.duration.is_some()
                    || scene.run.steps.is_some()
                    || scene.run.until.is_some(),
            ),
        ];
        for (field, given) in owned {
            if given {
                e.push(
                    field,
                    "must be left out of a die_compaction scene: its stages set it",
                );
            }
        }
        if scene.gravity.is_none() {
            e.push(
                "gravity",
                "is required by die_compaction: the die is filled by settling under it",
            );
        }
        if scene.time_step.accuracy.is_some() {
            e.push(
                "time_step.accuracy",
                "is not available in a die_compaction scene (its press stage re-estimates the step from the contacts with time_step.alpha); give time_step.alpha",
            );
        }
        let names: HashSet<&str> = scene.materials.iter().map(|m| m.name.as_str()).collect();
        dc.validate(&|name| names.contains(name), &mut e);
        if let Some(m) = scene
            .materials
            .iter()
            .find(|m| m.rigid && m.name == dc.particles.material)
        {
            e.push(
                "die_compaction.particles.material",
                format!(
                    "'{}' is rigid: only walls may be made of a rigid material",
                    m.name
                ),
            );
        }
        if e.0.is_empty() {
            // The topics the stages share with an ordinary scene, the particles being
            // the specimen's and the run's length the stages'.
            let names = materials::validate(&scene.materials, &mut e);
            let ctx = LawContext {
                particle_materials: [dc.particles.material.as_str()].into(),
                rotation: scene.rotation.is_some(),
                growth: false,
                materials: &scene.materials,
                names: &names,
            };
            contact::validate(&scene.contact, "contact", &ctx, &mut e);
            materials::validate_hardening(&scene.materials, &mut e);
            physics::validate(scene, &mut e);
            run::validate_time_step(&scene.time_step, &mut e);
            run::validate_detection_limits_and_output(scene, &mut e);
            contact::validate(
                &dc.fill.contact,
                "die_compaction.fill.contact",
                &ctx,
                &mut e,
            );
        }
        e.finish()
    }
}

/// The `die_compaction` block: cold uniaxial compaction of a powder in a cylindrical
/// die (Rojek et al. 2016 §5), from the fill through the flattening of the top to the
/// pressing, and the RVE in which density is measured.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct DieCompactionSpec {
    /// Inner diameter of the cylindrical die, m.
    pub die_diameter: f64,
    /// Material of the die wall, its floor and the punch.
    pub wall_material: String,
    /// The powder poured into the die.
    pub particles: DieParticles,
    /// How the die is filled and the bed settled.
    pub fill: FillSpec,
    /// How the punch flattens the top of the settled bed before pressing.
    pub flatten: FlattenSpec,
    /// How the punch presses the powder.
    pub press: PressSpec,
    /// Diameter of the spherical RVE centred in the specimen, m (Rojek: 54 µm).
    pub rve_diameter: f64,
    /// The die's curvature in the contacts of the pressing and its replays: `flat`
    /// (R* = R) or `mean` (LAMMPS's cylinder wall). Left out of a flat scene's
    /// serialised form, so the scenes written before it keep their form.
    #[serde(default, skip_serializing_if = "is_flat")]
    pub die_curvature: Curvature,
    /// The press cycle after the peak (`process::press_cycle`): the upper punch
    /// withdrawn, the compact ejected, the free compact left to relax.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub unload: Option<UnloadSpec>,
    /// The lower punch pushing the compact out (needs `unload`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub eject: Option<EjectSpec>,
    /// The ejected compact left standing (needs `eject`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub relax: Option<RelaxSpec>,
    /// Height bands of the compact over which a cycle's records give the die wall's
    /// radial pressure (default 4).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub die_bands: Option<usize>,
}

impl DieCompactionSpec {
    /// The bands a press cycle measures the die wall in; none without a cycle.
    pub fn die_bands(&self) -> Option<usize> {
        self.unload.as_ref().map(|_| self.die_bands.unwrap_or(4))
    }
}

fn is_flat(c: &Curvature) -> bool {
    *c == Curvature::Flat
}

/// The powder of a die compaction: how many particles, of which radii and material.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct DieParticles {
    /// Number of particles (Rojek: 1751).
    pub count: usize,
    /// Distribution of the particle radii, m.
    pub radius: RadiusSpec,
    /// Name of an entry of the scene's `materials`.
    pub material: String,
}

/// The fill stage: how the particles reach the die and settle under (scaled) gravity.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct FillSpec {
    /// Contact law while the die is filled and flattened.
    pub contact: ContactSpec,
    /// Factor on the scene's gravity while filling (micrometre particles settle in
    /// hours of steps under 1 g).
    pub gravity_scale: f64,
    /// Solid fraction of the loose random column the particles start in.
    #[serde(default = "default_loose_fraction")]
    pub loose_fraction: f64,
    /// Safety factor α of the fill and flatten stages (default: the scene's); the
    /// paper's α = 0.1 is stated for pressing.
    #[serde(default)]
    pub alpha: Option<f64>,
    /// Longest settling time, s; settling ends earlier once the bed is at rest.
    pub max_duration: f64,
    /// The bed is at rest when its kinetic energy is below this fraction of
    /// M g' ⟨d⟩ (total mass, scaled gravity, mean diameter).
    #[serde(default = "default_rest_fraction")]
    pub rest_fraction: f64,
    /// How the particles reach the die; absent: `settled_column`.
    #[serde(default, skip_serializing_if = "FillMethod::is_default")]
    pub method: FillMethod,
    /// The funnel of `method: "funnel"` (absent: every dimension at its default).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub funnel: Option<FunnelSpec>,
}

fn default_loose_fraction() -> f64 {
    0.25
}

fn default_rest_fraction() -> f64 {
    1e-6
}

/// The flatten stage: the punch moves down into the settled bed, back up, and the bed
/// relaxes, so the pressing starts from a level top.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct FlattenSpec {
    /// How far the punch moves down from first contact, m (Rojek: 3 µm).
    pub depth: f64,
    /// Time to move down; the same time to move back up and again to relax, s.
    pub duration: f64,
}

/// The pressing stage: a punch of given mass under a pressure ramped linearly to its
/// final value, with records of the specimen along the ramp.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct PressSpec {
    /// Final pressure on the punch, Pa.
    pub pressure: f64,
    /// Time over which the pressure rises linearly from zero, s.
    pub ramp_time: f64,
    /// Mass of the punch, kg.
    pub punch_mass: f64,
    /// Number of records along the ramp (density, height, forces).
    #[serde(default = "default_records")]
    pub records: usize,
    /// Steps between re-estimates of the time step as contacts stiffen (Rojek §3.4).
    #[serde(default = "default_dt_every")]
    pub dt_every: u64,
    /// A fixed step for the press instead of the re-estimated one, s, shortened to the
    /// nearest step that divides the record interval `ramp_time / records`, so that
    /// every record falls on a step: a run an engine records has one step and a step
    /// count fixed in advance (docs/engines.md).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub time_step: Option<f64>,
}

impl PressSpec {
    /// With `time_step`: the step the press takes and the steps between records.
    pub fn fixed_step(&self) -> Option<(f64, u64)> {
        self.time_step.map(|dt| {
            let interval = self.ramp_time / self.records as f64;
            // A step that divides the interval up to round-off is kept as it is.
            let per_record = (interval / dt * (1.0 - 1e-12)).ceil().max(1.0);
            (interval / per_record, per_record as u64)
        })
    }
}

fn default_records() -> usize {
    100
}

fn default_dt_every() -> u64 {
    100
}

impl DieCompactionSpec {
    fn validate(&self, material_exists: &dyn Fn(&str) -> bool, e: &mut Errors) {
        let at = |f: &str| format!("die_compaction.{f}");
        e.positive(at("die_diameter"), self.die_diameter);
        for (field, name) in [
            ("wall_material", &self.wall_material),
            ("particles.material", &self.particles.material),
        ] {
            if !material_exists(name) {
                e.push(at(field), format!("unknown material '{name}'"));
            }
        }
        if self.particles.count == 0 {
            e.push(at("particles.count"), "must be >= 1, got 0");
        }
        let d = self.particles.radius.distribution();
        match d.validate() {
            Err(rule) => e.push(at("particles.radius"), rule),
            Ok(()) if 2.0 * d.max_radius() >= self.die_diameter || d.max_radius().is_nan() => e
                .push(
                    at("particles.radius"),
                    format!(
                        "the largest diameter {:e} m must be smaller than the die ({:e} m)",
                        2.0 * d.max_radius(),
                        self.die_diameter
                    ),
                ),
            Ok(()) => {}
        }
        e.positive(at("fill.gravity_scale"), self.fill.gravity_scale);
        if !(self.fill.loose_fraction > 0.0 && self.fill.loose_fraction <= 0.3) {
            e.push(
                at("fill.loose_fraction"),
                format!(
                    "must be in (0, 0.3] (random insertion jams well before 0.38), got {}",
                    self.fill.loose_fraction
                ),
            );
        }
        e.positive(at("fill.max_duration"), self.fill.max_duration);
        if let Some(alpha) = self.fill.alpha
            && !(alpha > 0.0 && alpha <= 1.0)
        {
            e.push(at("fill.alpha"), format!("must be in (0, 1], got {alpha}"));
        }
        e.positive(at("fill.rest_fraction"), self.fill.rest_fraction);
        super::funnel::validate(self, e);
        e.positive(at("flatten.depth"), self.flatten.depth);
        e.positive(at("flatten.duration"), self.flatten.duration);
        e.positive(at("press.pressure"), self.press.pressure);
        e.positive(at("press.ramp_time"), self.press.ramp_time);
        e.positive(at("press.punch_mass"), self.press.punch_mass);
        if self.press.records < 2 {
            e.push(
                at("press.records"),
                format!("must be >= 2, got {}", self.press.records),
            );
        }
        if self.press.dt_every == 0 {
            e.push(at("press.dt_every"), "must be >= 1, got 0");
        }
        if let Some(dt) = self.press.time_step {
            e.positive(at("press.time_step"), dt);
            let interval = self.press.ramp_time / self.press.records as f64;
            if dt > 0.0 && interval / dt > 1e9 {
                e.push(
                    at("press.time_step"),
                    format!(
                        "gives more than 1e9 steps per record (record interval {interval:e} s, step {dt:e} s)"
                    ),
                );
            }
        }
        super::press_cycle::validate(self, e);
        if !(self.rve_diameter > 0.0 && self.rve_diameter < self.die_diameter) {
            e.push(
                at("rve_diameter"),
                format!(
                    "must be > 0 and smaller than the die diameter {:e} m, got {:e}",
                    self.die_diameter, self.rve_diameter
                ),
            );
        }
    }
}
