//! Verification cases. A case is data plus one function:
//! - `verification/<name>.json` holds the tier, the scene file, and per quantity its
//!   unit, tolerance (and kind), source, and the one-sentence reason for the tolerance;
//! - `cases/<name>.rs` runs the scene(s) and returns, per quantity, the value tamp
//!   computed and the reference computed independently from the inputs.
//!
//! The runner joins the two, judges each quantity, and writes the report. A quantity
//! present on one side only is an error of the case, never silently skipped.
//!
//! A case runs on an engine (`engine`): it hands its scenes to `CaseContext::record`
//! and measures only the recordings it gets back, so the same case verifies tamp,
//! LIGGGHTS, LAMMPS or any program behind an adapter. A case whose file says
//! `tamp_only` (a calculation, or a measurement of tamp's internals) runs on tamp
//! alone and is `not_expressible` on the others.

pub mod cases;
pub mod crosscheck;
pub mod engine;
pub mod measure;
pub mod parallel;
pub mod recording;
pub mod report;
pub mod store;

use crate::error::{Result, TampError};
use crate::process::die_compaction_file::DieCompactionFile;
use crate::scene::{self, Scene};
use engine::peer_record::{self, PeerRecord, PeerRun, PeerRuns};
use engine::{Engine, Refusal};
use recording::{Frame, RecordSpec, Recording};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum Tier {
    Quick,
    Full,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ToleranceKind {
    Relative,
    Absolute,
    /// One-sided: the value must not exceed the reference by more than the
    /// tolerance (a bound such as "friction lowers the density", "no density drop").
    Below,
    /// The value must lie in an interval the case computes (`Measured::between`),
    /// shown as its centre; the error is the distance outside it.
    Between,
}

#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct QuantitySpec {
    pub name: String,
    pub unit: String,
    pub tolerance: f64,
    pub tolerance_kind: ToleranceKind,
    pub source: String,
    /// Why this tolerance (one sentence).
    pub why: String,
    /// The value a paper states, when it differs from the recomputed reference.
    #[serde(default)]
    pub paper_value: Option<f64>,
    /// Where `docs/` records why tamp departs from this reference, as
    /// `docs/<page>.md §N`: the quantity is measured and judged as usual, but a
    /// failure is reported as `known_deviation` and does not fail the tier, while a
    /// pass fails it as `unexpected_pass` (the record is stale and must be revisited).
    #[serde(default)]
    pub known_deviation: Option<String>,
}

#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CaseSpec {
    pub name: String,
    pub tier: Tier,
    pub description: String,
    /// Scene file relative to `verification/`.
    #[serde(default)]
    pub scene: Option<String>,
    /// The scenario of a case whose runs are not one scene (box width, seeds, the
    /// runs on each deposit): read by the case with `CaseContext::parameters`.
    #[serde(default)]
    pub parameters: Option<serde_json::Value>,
    /// Why the case runs on tamp only (a calculation, or a measurement of tamp's
    /// internals rather than of recorded outputs); absent: it runs on every engine.
    #[serde(default)]
    pub tamp_only: Option<String>,
    /// Engines that run the same algorithm as tamp and must give tamp's values to a
    /// stated relative tolerance, beside meeting the references.
    #[serde(default)]
    pub agreement: Vec<Agreement>,
    pub quantities: Vec<QuantitySpec>,
}

/// An engine's promised agreement with tamp in one case: every quantity within
/// `relative` of tamp's value of it, checked against a run of the case on tamp.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Agreement {
    pub engine: String,
    pub relative: f64,
    /// Why this tolerance (one sentence).
    pub why: String,
}

impl CaseSpec {
    /// Whether the case file lists the quantity `name` (a case that can measure
    /// more than one tier needs measures only what its file asks for).
    pub fn asks_for(&self, name: &str) -> bool {
        self.quantities.iter().any(|q| q.name == name)
    }
}

/// What a case function returns for one quantity.
#[derive(Clone, Debug)]
pub struct Measured {
    pub name: String,
    pub value: f64,
    pub reference: f64,
    /// Half-width of the interval about `reference` (tolerance kind `between`).
    pub half_width: f64,
}

impl Measured {
    pub fn new(name: &str, value: f64, reference: f64) -> Self {
        Measured {
            name: name.to_string(),
            value,
            reference,
            half_width: 0.0,
        }
    }

    /// A value that must lie in [lo, hi], bounds the case derives from its run.
    pub fn between(name: &str, value: f64, lo: f64, hi: f64) -> Self {
        Measured {
            half_width: 0.5 * (hi - lo).abs(),
            ..Measured::new(name, value, 0.5 * (lo + hi))
        }
    }
}

pub struct CaseContext<'a> {
    pub spec: &'a CaseSpec,
    pub dir: PathBuf,
    /// Where a case may write extra artefacts (CSV curves, plots).
    pub report_dir: PathBuf,
    /// Replaces `reference_data/` (the live cross-check points it at fresh LIGGGHTS runs).
    pub reference_data: Option<PathBuf>,
    /// Numerical settings the accuracy-cost study changes; the default leaves the
    /// case's scene as written.
    pub variant: Variant,
    /// The engine the case's scenes run on (`record`).
    pub engine: Engine,
    /// Whether a peer engine runs now or gives its recorded values.
    pub peer_runs: PeerRuns,
    /// How many of its own runs the case may make at once (`map`): `tamp verify --jobs`.
    pub jobs: usize,
    /// The runs a peer engine made for this case, as its record keeps them.
    peer_log: Mutex<Vec<PeerRun>>,
    /// The peer's record of this case, once read.
    peer_record: Mutex<Option<PeerRecord>>,
    /// Set by `record` when the engine cannot express a scene: the reason.
    not_expressible: Mutex<Option<String>>,
    /// Whether the case recorded anything (a case that is not `tamp_only` must).
    recorded: AtomicBool,
}

/// What `tamp study accuracy-cost` varies in a case's scene. Only numerical
/// settings: the physics a case verifies (laws, damping form, geometry) stays fixed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Variant {
    /// Multiplies the time step (α, or the fixed step) and divides `run.steps`, so
    /// the simulated time stays the same.
    pub step_scale: f64,
    /// Replaces the broad phase.
    pub detector: Option<crate::scene::schema::DetectorSpec>,
}

impl Default for Variant {
    fn default() -> Self {
        Variant {
            step_scale: 1.0,
            detector: None,
        }
    }
}

impl Variant {
    /// Apply to a validated scene (α may then exceed 1: the study looks for the edge).
    pub fn apply(&self, scene: &mut Scene) {
        let s = self.step_scale;
        if s != 1.0 {
            match &mut scene.time_step.fixed {
                Some(dt) => *dt *= s,
                None => scene.time_step.alpha = Some(scene.time_step.alpha() * s),
            }
            if let Some(steps) = &mut scene.run.steps {
                *steps = ((*steps as f64 / s).round() as u64).max(1);
            }
        }
        if let Some(kind) = self.detector {
            scene.broad_phase.kind = kind;
        }
    }
}

impl<'a> CaseContext<'a> {
    /// A context for `spec` on `engine`, writing into `report_dir`.
    pub fn new(
        spec: &'a CaseSpec,
        dir: &Path,
        report_dir: &Path,
        reference_data: Option<&Path>,
        variant: Variant,
        engine: Engine,
    ) -> Self {
        CaseContext {
            spec,
            dir: dir.to_path_buf(),
            report_dir: report_dir.to_path_buf(),
            reference_data: reference_data.map(Path::to_path_buf),
            variant,
            engine,
            peer_runs: PeerRuns::default(),
            jobs: default_jobs(),
            peer_log: Mutex::new(Vec::new()),
            peer_record: Mutex::new(None),
            not_expressible: Mutex::new(None),
            recorded: AtomicBool::new(false),
        }
    }

    /// The first and the last frame of `scene`'s run on the case's engine, recording
    /// nothing in between.
    pub fn first_and_last(&self, label: &str, scene: &Scene) -> Result<(Frame, Frame)> {
        let steps = scene::build(scene)?.steps;
        let rec = self.record(label, scene, RecordSpec::every(steps.max(1), false))?;
        match (rec.frames.first(), rec.frames.last()) {
            (Some(a), Some(b)) if b.step == steps => Ok((a.clone(), b.clone())),
            _ => Err(TampError::Other(format!(
                "{label}: the recording has no frame at step 0 and step {steps}"
            ))),
        }
    }

    /// Run `scene` on the case's engine and return what it recorded (`spec`): the
    /// only thing a case that runs on every engine measures. `label` names the run
    /// among the case's runs (its directory, for an external engine:
    /// `<report>/<engine>/<case>_engine/<label>/`).
    pub fn record(&self, label: &str, scene: &Scene, spec: RecordSpec) -> Result<Recording> {
        self.recorded.store(true, Ordering::Relaxed);
        if scene.run.until.is_some() {
            return Err(TampError::Other(format!(
                "{}: run.until: a recorded run has a fixed step count, so a case's scene must not end when it settles",
                self.spec.name
            )));
        }
        let dir = self
            .report_dir
            .join(format!("{}_engine", self.spec.name))
            .join(label);
        let refused = |refusal| match refusal {
            Refusal::Failed(e) => e,
            Refusal::NotExpressible(why) => {
                let message = format!("{}: {why}", self.engine);
                *self.not_expressible.lock().expect("not poisoned") = Some(message.clone());
                TampError::Other(message)
            }
        };
        if let (Some(peer), PeerRuns::Recorded) = (self.engine.peer(), self.peer_runs) {
            // The recorded values stand in for the peer's: its deck must be the one
            // recorded, and tamp's own run gives the case its quantities and references.
            let deck = engine::peer_deck(peer, scene, spec, &dir).map_err(refused)?;
            let path = self.peer_record_path(peer);
            let mut cached = self.peer_record.lock().expect("not poisoned");
            if cached.is_none() {
                *cached = Some(peer_record::load(&path)?.ok_or_else(|| {
                    TampError::Other(format!(
                        "{}: no recorded {} run of this case; record one with `tamp verify --engine {} --live --record --case {}` (the peer installed)",
                        path.display(),
                        self.engine,
                        self.engine,
                        self.spec.name
                    ))
                })?);
            }
            if let Some(record) = cached.as_ref() {
                record.check_run(label, &deck, &path)?;
            }
            drop(cached);
            return engine::tamp::record(scene, spec);
        }
        let (recording, run) =
            engine::record(&self.engine, label, scene, spec, &dir).map_err(refused)?;
        if let Some(run) = run {
            self.peer_log.lock().expect("not poisoned").push(run);
        }
        Ok(recording)
    }

    /// A recorded run whose measurement is kept in the case's store: `scene` builds the
    /// run's scene (and what `measure` needs beside the recording), the engine records
    /// it as `spec` asks under `label`, and `measure` reads the recording. On the tamp
    /// engine the result is saved as `name`, keyed by `key` (everything the scene and
    /// the measurement are made from) with `spec` and the source tree, and a saved
    /// result skips both the building and the run; an outside engine, which the source
    /// tree does not name, runs every time.
    pub fn record_and_keep<K: Serialize, C, T: Serialize + serde::de::DeserializeOwned>(
        &self,
        store: &store::Store,
        (name, key): (&str, &K),
        (label, spec): (&str, RecordSpec),
        scene: impl FnOnce() -> Result<(Scene, C)>,
        measure: impl FnOnce(&Recording, &C) -> Result<T>,
    ) -> Result<T> {
        let run = || {
            let (scene, context) = scene()?;
            measure(&self.record(label, &scene, spec)?, &context)
        };
        if self.engine != Engine::Tamp {
            return run();
        }
        self.recorded.store(true, Ordering::Relaxed);
        store.cached(name, &store::key_of(&(key, spec)), run)
    }

    /// `reference_data/<peer>/engine/<case>.json`.
    fn peer_record_path(&self, peer: engine::peer::Peer) -> PathBuf {
        peer_record::path(&reference_data_beside(&self.dir), peer, &self.spec.name)
    }

    /// A peer engine's values, as `peer_runs` says: the recorded ones in place of those
    /// measured on tamp's run (`Recorded`), the fresh ones checked against the record
    /// (`Live`), or the fresh ones written as the record (`Record`).
    fn peer_values(&self, mut measured: Vec<Measured>) -> Result<Vec<Measured>> {
        let Some(peer) = self.engine.peer() else {
            return Ok(measured);
        };
        let path = self.peer_record_path(peer);
        match self.peer_runs {
            PeerRuns::Recorded => {
                let record = self
                    .peer_record
                    .lock()
                    .expect("not poisoned")
                    .take()
                    .ok_or_else(|| {
                        TampError::Other(format!(
                            "{}: the case recorded no run on {}",
                            path.display(),
                            self.engine
                        ))
                    })?;
                for m in &mut measured {
                    m.value = *record.quantities.get(&m.name).ok_or_else(|| {
                        TampError::Other(format!(
                            "{}: has no value of '{}'",
                            path.display(),
                            m.name
                        ))
                    })?;
                }
            }
            PeerRuns::Live => {
                let runs = self.peer_log.lock().expect("not poisoned").clone();
                let values = measured.iter().map(|m| (m.name.clone(), m.value)).collect();
                if let Some(record) = peer_record::load(&path)? {
                    let drift = record.drift(&runs, &values);
                    if !drift.is_empty() {
                        return Err(TampError::Other(format!(
                            "{} drifted from its record {}: {}; find out why, then re-record with --live --record",
                            self.engine,
                            path.display(),
                            drift.join("; ")
                        )));
                    }
                }
            }
            PeerRuns::Record => {
                let record = PeerRecord {
                    case: self.spec.name.clone(),
                    engine: self.engine.to_string(),
                    tamp_version: crate::VERSION.to_string(),
                    git_commit: crate::GIT_COMMIT.to_string(),
                    runs: self.peer_log.lock().expect("not poisoned").clone(),
                    quantities: measured.iter().map(|m| (m.name.clone(), m.value)).collect(),
                };
                peer_record::save(&path, &record)?;
            }
        }
        Ok(measured)
    }

    /// The case file's `parameters`, as the case's own type; an absent or wrong field
    /// is an input error naming `parameters.<path>` in the case file.
    pub fn parameters<T: serde::de::DeserializeOwned>(&self) -> Result<T> {
        let file = format!("verification/{}.json", self.spec.name);
        let value = self.spec.parameters.clone().ok_or_else(|| {
            TampError::input(format!("{file}: parameters"), "required by this case")
        })?;
        serde_path_to_error::deserialize(value).map_err(|e| {
            TampError::input(
                format!("{file}: parameters.{}", e.path()),
                e.inner().to_string(),
            )
        })
    }

    /// `reference_data/` beside the verification directory: results recorded by
    /// other codes (LIGGGHTS), with their decks, logs and provenance.
    pub fn reference_data_dir(&self) -> PathBuf {
        match &self.reference_data {
            Some(dir) => dir.clone(),
            None => reference_data_beside(&self.dir),
        }
    }

    /// The rows of `reference_data/<peer>/<case>/results.csv` (at least one), `peer`
    /// being `liggghts` or `lammps`.
    pub fn peer_results<T: serde::de::DeserializeOwned>(&self, peer: &str) -> Result<Vec<T>> {
        let path = self
            .reference_data_dir()
            .join(peer)
            .join(&self.spec.name)
            .join("results.csv");
        let rows = read_csv(&path)?;
        if rows.is_empty() {
            return Err(TampError::Other(format!(
                "{}: no {peer} runs recorded",
                path.display()
            )));
        }
        Ok(rows)
    }

    /// The path of the scene or die-compaction file the case names.
    fn scene_path(&self) -> Result<PathBuf> {
        let file =
            self.spec.scene.as_ref().ok_or_else(|| {
                TampError::Other(format!("case {} names no scene", self.spec.name))
            })?;
        Ok(self.dir.join(file))
    }

    /// The case's scene, parsed and validated like any user scene.
    pub fn scene(&self) -> Result<Scene> {
        let mut scene = scene::load(&self.scene_path()?)?.0;
        self.variant.apply(&mut scene);
        Ok(scene)
    }

    /// The case's store of finished and interrupted runs, `<report>/<case>_runs/`
    /// (`store`): for cases that run long enough to be worth resuming.
    pub fn store(&self) -> Result<store::Store> {
        let dir = self.report_dir.join(format!("{}_runs", self.spec.name));
        crate::output::create_dir(&dir)?;
        Ok(store::Store { dir })
    }

    /// `items.iter().map(run).collect()` on up to `jobs` threads, results in the
    /// order of the items (`parallel::map`): the independent runs of one case.
    pub fn map<T: Sync, R: Send>(&self, items: &[T], run: impl Fn(&T) -> R + Sync) -> Vec<R> {
        parallel::map(items, self.jobs, run)
    }

    /// The case's die-compaction file, with the variant's step and detector applied to
    /// the scenes its stages share.
    pub fn die_compaction(&self) -> Result<DieCompactionFile> {
        self.die_compaction_at(&self.scene_path()?)
    }

    /// A die-compaction file of the case other than its scene (a case that presses
    /// more than one, named in its parameters), read as `die_compaction` reads the
    /// scene.
    pub fn die_compaction_at(&self, path: &Path) -> Result<DieCompactionFile> {
        let mut process = DieCompactionFile::load(path)?.0;
        let mut shared = process.shared_scene();
        self.variant.apply(&mut shared);
        process.scene.time_step = shared.time_step;
        process.scene.broad_phase = shared.broad_phase;
        Ok(process)
    }
}

pub type CaseFn = fn(&CaseContext) -> Result<Vec<Measured>>;

#[derive(Clone, Debug, Serialize)]
pub struct QuantityResult {
    pub name: String,
    pub value: f64,
    pub reference: f64,
    /// Half-width of the interval about `reference` (kind `between`).
    #[serde(skip_serializing_if = "is_zero")]
    pub half_width: f64,
    pub error: f64,
    pub tolerance: f64,
    pub tolerance_kind: ToleranceKind,
    pub unit: String,
    pub source: String,
    pub why: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub paper_value: Option<f64>,
    /// Where `docs/` records the deviation (`QuantitySpec::known_deviation`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub known_deviation: Option<String>,
    pub status: Status,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    Pass,
    Fail,
    Error,
    /// Outside its tolerance, as `docs/` records (`QuantitySpec::known_deviation`).
    KnownDeviation,
    /// Recorded as a known deviation but within its tolerance: the record is stale.
    UnexpectedPass,
    /// The engine cannot express the case's scene (an exporter's refusal, an
    /// adapter's exit code 4), or the case runs on tamp only.
    NotExpressible,
}

impl Status {
    /// Whether this status lets the tier pass.
    pub fn is_ok(self) -> bool {
        matches!(
            self,
            Status::Pass | Status::KnownDeviation | Status::NotExpressible
        )
    }
}

#[derive(Clone, Debug, Serialize)]
pub struct CaseResult {
    pub name: String,
    /// The engine the case ran on (`engine::Engine`, as on the command line).
    pub engine: String,
    pub tier: Tier,
    pub status: Status,
    pub wall_s: f64,
    pub description: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
    pub quantities: Vec<QuantityResult>,
    /// Plots the case wrote into the report directory (`<case>*.svg`), shown in the
    /// report under the case.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub plots: Vec<String>,
}

#[derive(Clone, Debug, Serialize)]
pub struct VerificationReport {
    pub tamp_version: String,
    pub git_commit: String,
    pub cases: Vec<CaseResult>,
}

fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

/// `reference_data/` beside the verification directory `dir`.
pub fn reference_data_beside(dir: &Path) -> PathBuf {
    dir.parent().unwrap_or(dir).join("reference_data")
}

/// The verification directory: `$TAMP_VERIFICATION_DIR`, else the crate's own.
pub fn verification_dir() -> PathBuf {
    std::env::var_os("TAMP_VERIFICATION_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("verification"))
}

pub fn load_specs(dir: &Path) -> Result<Vec<CaseSpec>> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(|e| TampError::io(format!("reading {}", dir.display()), e))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            p.extension().is_some_and(|x| x == "json")
                && !p.to_string_lossy().ends_with(".scene.json")
        })
        .collect();
    files.sort();
    files
        .iter()
        .map(|f| {
            let text = std::fs::read_to_string(f)
                .map_err(|e| TampError::io(format!("reading {}", f.display()), e))?;
            let de = &mut serde_json::Deserializer::from_str(&text);
            let spec: CaseSpec = serde_path_to_error::deserialize(de).map_err(|e| {
                TampError::input(
                    format!("{}: {}", f.display(), e.path()),
                    e.into_inner().to_string(),
                )
            })?;
            for (k, q) in spec.quantities.iter().enumerate() {
                if let Some(record) = &q.known_deviation {
                    let root = dir.parent().unwrap_or(dir);
                    check_deviation_record(root, record).map_err(|rule| {
                        TampError::input(
                            format!("{}: quantities[{k}].known_deviation", f.display()),
                            rule,
                        )
                    })?;
                }
            }
            for (k, a) in spec.agreement.iter().enumerate() {
                let path = |field: &str| format!("{}: agreement[{k}].{field}", f.display());
                if let Err(why) = a.engine.parse::<Engine>() {
                    return Err(TampError::input(path("engine"), why));
                }
                if a.engine == "tamp" {
                    return Err(TampError::input(
                        path("engine"),
                        "tamp agrees with itself; name another engine",
                    ));
                }
                if !(a.relative >= 0.0 && a.relative.is_finite()) {
                    return Err(TampError::input(
                        path("relative"),
                        format!("must be a finite number >= 0, got {}", a.relative),
                    ));
                }
            }
            Ok(spec)
        })
        .collect()
}

/// A known deviation must point at a section that exists: `docs/<page>.md §N`, with
/// `## N.` a heading of that page. A dangling pointer would let a failure pass with
/// nothing written down.
fn check_deviation_record(root: &Path, record: &str) -> std::result::Result<(), String> {
    let rule =
        "must be `docs/<page>.md §N`, naming a page under docs/ and one of its `## N.` headings";
    let (page, section) = record
        .split_once(" §")
        .ok_or_else(|| format!("'{record}' {rule}"))?;
    if !page.starts_with("docs/") || !page.ends_with(".md") || section.is_empty() {
        return Err(format!("'{record}' {rule}"));
    }
    let text = std::fs::read_to_string(root.join(page))
        .map_err(|e| format!("'{record}': cannot read {page} ({e}); {rule}"))?;
    let heading = format!("## {section}.");
    if text.lines().any(|l| l.starts_with(&heading)) {
        Ok(())
    } else {
        Err(format!(
            "'{record}': {page} has no heading '{heading}'; {rule}"
        ))
    }
}

fn judge(spec: &QuantitySpec, m: &Measured) -> QuantityResult {
    let error = match spec.tolerance_kind {
        ToleranceKind::Absolute => (m.value - m.reference).abs(),
        ToleranceKind::Relative => (m.value - m.reference).abs() / m.reference.abs(),
        ToleranceKind::Below => (m.value - m.reference).max(0.0),
        ToleranceKind::Between => ((m.value - m.reference).abs() - m.half_width).max(0.0),
    };
    let within = error.is_finite() && error <= spec.tolerance;
    let status = match (within, spec.known_deviation.is_some()) {
        (true, false) => Status::Pass,
        (false, false) => Status::Fail,
        // A NaN is a broken measurement, not the recorded deviation.
        (false, true) if error.is_finite() => Status::KnownDeviation,
        (false, true) => Status::Fail,
        (true, true) => Status::UnexpectedPass,
    };
    QuantityResult {
        name: spec.name.clone(),
        value: m.value,
        reference: m.reference,
        half_width: m.half_width,
        error,
        tolerance: spec.tolerance,
        tolerance_kind: spec.tolerance_kind,
        unit: spec.unit.clone(),
        source: spec.source.clone(),
        why: spec.why.clone(),
        paper_value: spec.paper_value,
        known_deviation: spec.known_deviation.clone(),
        status,
    }
}

#[allow(clippy::too_many_arguments)]
pub fn run_case(
    spec: &CaseSpec,
    dir: &Path,
    report_dir: &Path,
    reference_data: Option<&Path>,
    variant: Variant,
    engine: &Engine,
    peer_runs: PeerRuns,
    jobs: usize,
) -> CaseResult {
    let started = Instant::now();
    let started_at = std::time::SystemTime::now();
    // Another engine's artefacts (plots, CSVs, run directories) go to a directory of
    // its own, so that no engine's files stand in for another's.
    let own_dir = match engine {
        Engine::Tamp => report_dir.to_path_buf(),
        other => report_dir.join(other.slug()),
    };
    let mut ctx = CaseContext::new(spec, dir, &own_dir, reference_data, variant, engine.clone());
    ctx.peer_runs = peer_runs;
    ctx.jobs = jobs;
    let outcome = match (cases::find(&spec.name), &spec.tamp_only) {
        (None, _) => Err(TampError::Other(format!(
            "no code registered for case '{}' in src/verify/cases",
            spec.name
        ))),
        (Some(_), Some(why)) if *engine != Engine::Tamp => {
            let why = format!("runs on tamp only: {why}");
            *ctx.not_expressible.lock().expect("not poisoned") = Some(why.clone());
            Err(TampError::Other(why))
        }
        (Some(f), tamp_only) => f(&ctx).and_then(|measured| {
            match tamp_only.is_none() && !ctx.recorded.load(Ordering::Relaxed) {
                true => Err(TampError::Other(format!(
                    "case '{}' is not tamp_only in its file, yet it measured nothing an engine recorded",
                    spec.name
                ))),
                false => ctx.peer_values(measured),
            }
        }),
    };
    let wall_s = started.elapsed().as_secs_f64();
    let mut result = CaseResult {
        name: spec.name.clone(),
        engine: engine.to_string(),
        tier: spec.tier,
        status: Status::Pass,
        wall_s,
        description: spec.description.clone(),
        error: None,
        quantities: Vec::new(),
        plots: case_plots(&own_dir, &spec.name, started_at)
            .into_iter()
            .map(|plot| match engine {
                Engine::Tamp => plot,
                other => format!("{}/{plot}", other.slug()),
            })
            .collect(),
    };
    let not_expressible = ctx.not_expressible.lock().expect("not poisoned").take();
    match outcome {
        Err(_) if not_expressible.is_some() => {
            result.status = Status::NotExpressible;
            result.error = not_expressible;
        }
        Err(e) => {
            result.status = Status::Error;
            result.error = Some(e.to_string());
        }
        Ok(measured) => {
            let mut problems = Vec::new();
            for q in &spec.quantities {
                match measured.iter().find(|m| m.name == q.name) {
                    Some(m) => result.quantities.push(judge(q, m)),
                    None => problems.push(format!("quantity '{}' was not measured", q.name)),
                }
            }
            for m in &measured {
                if !spec.quantities.iter().any(|q| q.name == m.name) {
                    problems.push(format!(
                        "measured quantity '{}' has no entry in the case file",
                        m.name
                    ));
                }
            }
            let disagreement = match problems.is_empty() {
                true => disagreement(
                    spec,
                    dir,
                    &own_dir,
                    reference_data,
                    variant,
                    engine,
                    &result,
                ),
                false => None,
            };
            if !problems.is_empty() {
                result.status = Status::Error;
                result.error = Some(problems.join("; "));
            } else if let Some(why) = disagreement {
                result.status = Status::Fail;
                result.error = Some(why);
            } else if result.quantities.iter().any(|q| !q.status.is_ok()) {
                result.status = Status::Fail;
            } else if result
                .quantities
                .iter()
                .any(|q| q.status == Status::KnownDeviation)
            {
                result.status = Status::KnownDeviation;
            }
        }
    }
    result
}

/// Where `engine` gives values farther from tamp's than the case file's `agreement`
/// allows: tamp's values come from the case run on tamp beside it (its artefacts in
/// `<engine dir>/<case>_agreement/`), an error of that run is one of the check.
fn disagreement(
    spec: &CaseSpec,
    dir: &Path,
    own_dir: &Path,
    reference_data: Option<&Path>,
    variant: Variant,
    engine: &Engine,
    result: &CaseResult,
) -> Option<String> {
    let promise = spec
        .agreement
        .iter()
        .find(|a| a.engine == engine.to_string())?;
    let scratch = own_dir.join(format!("{}_agreement", spec.name));
    let ctx = CaseContext::new(spec, dir, &scratch, reference_data, variant, Engine::Tamp);
    let tamp = match cases::find(&spec.name).map(|f| f(&ctx)) {
        Some(Ok(measured)) => measured,
        Some(Err(e)) => {
            return Some(format!(
                "the run on tamp for the agreement check failed: {e}"
            ));
        }
        None => return None,
    };
    let mut far = Vec::new();
    for q in &result.quantities {
        let Some(t) = tamp.iter().find(|m| m.name == q.name) else {
            continue;
        };
        let difference = (q.value - t.value).abs() / t.value.abs().max(f64::MIN_POSITIVE);
        if difference.is_nan() || difference > promise.relative {
            far.push(format!(
                "{}: {engine} {:e}, tamp {:e} (relative {difference:.1e})",
                q.name, q.value, t.value
            ));
        }
    }
    (!far.is_empty()).then(|| {
        format!(
            "{engine} departs from tamp by more than the {:e} the case file states ({}): {}",
            promise.relative,
            promise.why,
            far.join("; ")
        )
    })
}

/// The SVG files a case wrote into the report directory during its run, sorted:
/// named after the case (its name followed by `.` or `_`) and modified since `since`.
fn case_plots(report_dir: &Path, case: &str, since: std::time::SystemTime) -> Vec<String> {
    let mut plots: Vec<String> = std::fs::read_dir(report_dir)
        .into_iter()
        .flatten()
        .filter_map(|entry| {
            let entry = entry.ok()?;
            let fresh = entry.metadata().ok()?.modified().ok()? >= since;
            fresh.then(|| entry.file_name().into_string().ok())?
        })
        .filter(|name| {
            name.ends_with(".svg")
                && name
                    .strip_prefix(case)
                    .is_some_and(|rest| rest.starts_with('.') || rest.starts_with('_'))
        })
        .collect();
    plots.sort();
    plots
}

/// `tamp verify`: returns the exit code (0 when every case passes or deviates only
/// where `docs/` records it, 1 otherwise).
#[allow(clippy::too_many_arguments)]
pub fn run_cli(
    tier: Tier,
    names: &[String],
    skip: &[String],
    engines: &[Engine],
    peer_runs: PeerRuns,
    json: Option<&Path>,
    report_dir: &Path,
    jobs: usize,
) -> Result<u8> {
    let names = match skip {
        [] => names.to_vec(),
        skip => {
            let specs = load_specs(&verification_dir())?;
            if let Some(n) = skip.iter().find(|n| !specs.iter().any(|s| &s.name == *n)) {
                return Err(TampError::input(
                    "--skip-case",
                    format!("unknown case '{n}'"),
                ));
            }
            specs
                .into_iter()
                .filter(|s| tier == Tier::Full || s.tier == Tier::Quick)
                .map(|s| s.name)
                .filter(|n| !skip.contains(n))
                .collect()
        }
    };
    // An empty list would mean the whole tier to `run_cases`.
    if names.is_empty() && !skip.is_empty() {
        return Err(TampError::input(
            "--skip-case",
            "skips every case of the tier".to_string(),
        ));
    }
    run_cases(
        tier, &names, engines, peer_runs, json, report_dir, None, jobs,
    )
}

/// The number of cases `tamp verify` runs at once unless told: one per core.
pub fn default_jobs() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

/// `run_cli` with `reference_data/` replaced by `reference_data` when given. Each
/// case runs once per engine (tamp alone when `engines` is empty).
#[allow(clippy::too_many_arguments)]
pub fn run_cases(
    tier: Tier,
    names: &[String],
    engines: &[Engine],
    peer_runs: PeerRuns,
    json: Option<&Path>,
    report_dir: &Path,
    reference_data: Option<&Path>,
    jobs: usize,
) -> Result<u8> {
    let engines = match engines {
        [] => &[Engine::Tamp][..],
        some => some,
    };
    let dir = verification_dir();
    let specs = load_specs(&dir)?;
    for n in names {
        if !specs.iter().any(|s| &s.name == n) {
            return Err(TampError::input("--case", format!("unknown case '{n}'")));
        }
    }
    let selected: Vec<&CaseSpec> = specs
        .iter()
        .filter(|s| {
            if names.is_empty() {
                tier == Tier::Full || s.tier == Tier::Quick
            } else {
                names.contains(&s.name)
            }
        })
        .collect();
    crate::output::create_dir(report_dir)?;
    // Each case builds its scenes from its own seeds and writes only files named after
    // itself, so what it measures does not depend on what runs beside it; only its
    // wall_s does (cores are shared). Bars would overwrite each other: log lines.
    crate::progress::set_lines_only(jobs > 1);
    let runs: Vec<(&CaseSpec, &Engine)> = engines
        .iter()
        .flat_map(|e| selected.iter().map(move |s| (*s, e)))
        .collect();
    let several = engines.len() > 1;
    let results = parallel::map(&runs, jobs, |(spec, engine)| {
        let r = run_case(
            spec,
            &dir,
            report_dir,
            reference_data,
            Variant::default(),
            engine,
            peer_runs,
            jobs,
        );
        let name = match several {
            true => format!("{} [{engine}]", spec.name),
            false => spec.name.clone(),
        };
        eprintln!(
            "{:<32} {:?} ({:.2} s){}",
            name,
            r.status,
            r.wall_s,
            r.error
                .as_deref()
                .map(|e| format!(": {e}"))
                .unwrap_or_default()
        );
        r
    });
    crate::progress::set_lines_only(false);
    let report = VerificationReport {
        tamp_version: crate::VERSION.to_string(),
        git_commit: crate::GIT_COMMIT.to_string(),
        cases: results,
    };
    let json_path = json
        .map(Path::to_path_buf)
        .unwrap_or_else(|| report_dir.join("verification.json"));
    crate::output::write_atomic(&json_path, &crate::output::json_bytes(&report))?;
    crate::output::write_atomic(
        &report_dir.join("verification.md"),
        report::markdown(&report).as_bytes(),
    )?;
    crate::output::write_atomic(
        &report_dir.join("verification.html"),
        report::html(&report).as_bytes(),
    )?;
    let failed = report.cases.iter().filter(|c| !c.status.is_ok()).count();
    let deviating = report
        .cases
        .iter()
        .filter(|c| c.status == Status::KnownDeviation)
        .count();
    let inexpressible = report
        .cases
        .iter()
        .filter(|c| c.status == Status::NotExpressible)
        .count();
    let quantities: usize = report.cases.iter().map(|c| c.quantities.len()).sum();
    let known: usize = report
        .cases
        .iter()
        .flat_map(|c| &c.quantities)
        .filter(|q| q.status == Status::KnownDeviation)
        .count();
    let not_expressible = match inexpressible {
        0 => String::new(),
        n => format!(", {n} not expressible on their engine"),
    };
    println!(
        "{} passed, {} with known deviations ({} quantities, recorded in docs/), {} failed{}: \
         verification ({} quantities); report in {}",
        report.cases.len() - failed - deviating - inexpressible,
        deviating,
        known,
        failed,
        not_expressible,
        quantities,
        report_dir.join("verification.md").display()
    );
    Ok(if failed == 0 { 0 } else { 1 })
}

/// The rows of a CSV file with a header, each read as a `T`; an error names the file.
pub fn read_csv<T: serde::de::DeserializeOwned>(path: &Path) -> Result<Vec<T>> {
    let bad = |e: String| TampError::Other(format!("{}: {e}", path.display()));
    let mut reader = csv::Reader::from_path(path).map_err(|e| bad(e.to_string()))?;
    reader
        .deserialize()
        .collect::<std::result::Result<Vec<T>, _>>()
        .map_err(|e| bad(e.to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(known_deviation: Option<&str>) -> QuantitySpec {
        QuantitySpec {
            name: "q".into(),
            unit: "1".into(),
            tolerance: 0.1,
            tolerance_kind: ToleranceKind::Absolute,
            source: "s".into(),
            why: "w".into(),
            paper_value: None,
            known_deviation: known_deviation.map(str::to_string),
        }
    }

    #[test]
    fn a_known_deviation_is_reported_as_such_and_a_pass_of_one_is_not_a_pass() {
        let record = Some("docs/paper-discrepancies.md §24");
        let judged = |record, value| judge(&spec(record), &Measured::new("q", value, 1.0)).status;
        assert_eq!(judged(None, 1.05), Status::Pass);
        assert_eq!(judged(None, 1.5), Status::Fail);
        assert_eq!(judged(record, 1.5), Status::KnownDeviation);
        assert_eq!(judged(record, 1.05), Status::UnexpectedPass);
        // A NaN is a broken measurement, whatever the record says.
        assert_eq!(judged(record, f64::NAN), Status::Fail);
        assert!(Status::KnownDeviation.is_ok() && !Status::UnexpectedPass.is_ok());
    }

    /// A context of `spec` that reads and writes nothing of a checkout.
    fn bare_context(spec: &CaseSpec) -> CaseContext<'_> {
        CaseContext::new(
            spec,
            Path::new(""),
            Path::new(""),
            None,
            Variant::default(),
            Engine::Tamp,
        )
    }

    #[test]
    fn a_case_maps_its_runs_no_more_than_jobs_at_a_time() {
        use std::sync::atomic::{AtomicUsize, Ordering};
        let spec: CaseSpec = serde_json::from_str(
            r#"{"name": "c", "tier": "quick", "description": "d", "quantities": []}"#,
        )
        .unwrap();
        let mut ctx = bare_context(&spec);
        for jobs in [1, 3] {
            ctx.jobs = jobs;
            let (running, most) = (AtomicUsize::new(0), AtomicUsize::new(0));
            let order = ctx.map(&[0u64; 12], |_| {
                let now = running.fetch_add(1, Ordering::SeqCst) + 1;
                most.fetch_max(now, Ordering::SeqCst);
                std::thread::sleep(std::time::Duration::from_millis(5));
                running.fetch_sub(1, Ordering::SeqCst);
                now
            });
            assert_eq!(order.len(), 12);
            assert!(most.load(Ordering::SeqCst) <= jobs, "jobs {jobs}");
        }
    }

    #[test]
    fn case_parameters_are_read_as_the_case_s_type_and_a_wrong_one_names_its_path() {
        #[derive(Deserialize, Debug)]
        #[serde(deny_unknown_fields)]
        #[allow(dead_code)]
        struct Scenario {
            box_width_radii: f64,
            seeds: Vec<u64>,
        }
        let read = |parameters: &str| {
            let spec: CaseSpec = serde_json::from_str(&format!(
                r#"{{"name": "c", "tier": "quick", "description": "d", {parameters}
                    "quantities": []}}"#
            ))
            .unwrap();
            let ctx = bare_context(&spec);
            ctx.parameters::<Scenario>().map_err(|e| e.to_string())
        };
        let ok = read(r#""parameters": {"box_width_radii": 20, "seeds": [1, 2]},"#).unwrap();
        assert_eq!((ok.box_width_radii, ok.seeds), (20.0, vec![1, 2]));
        let bad = read(r#""parameters": {"box_width_radii": 20, "seeds": [1, "two"]},"#);
        assert!(
            bad.unwrap_err()
                .contains("verification/c.json: parameters.seeds[1]")
        );
        let absent = read("").unwrap_err();
        assert!(
            absent.contains("verification/c.json: parameters"),
            "{absent}"
        );
    }

    #[test]
    fn a_deviation_record_must_name_a_section_that_exists() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        assert!(check_deviation_record(root, "docs/paper-discrepancies.md §24").is_ok());
        for bad in [
            "docs/paper-discrepancies.md §999",
            "docs/no-such-page.md §1",
            "docs/paper-discrepancies.md",
            "README.md §1",
        ] {
            let rule = check_deviation_record(root, bad).expect_err(bad);
            assert!(rule.contains("docs/<page>.md §N"), "{bad}: {rule}");
        }
    }

    #[test]
    fn a_case_file_with_a_dangling_deviation_record_is_refused_naming_the_field() {
        let dir = std::env::temp_dir().join(format!("tamp-known-deviation-{}", std::process::id()));
        let cases = dir.join("verification");
        std::fs::create_dir_all(&cases).unwrap();
        std::fs::write(
            cases.join("c.json"),
            r#"{"name": "c", "tier": "quick", "description": "d", "quantities": [
                {"name": "q", "unit": "1", "tolerance": 0.1, "tolerance_kind": "absolute",
                 "source": "s", "why": "w", "known_deviation": "docs/nowhere.md §1"}]}"#,
        )
        .unwrap();
        let e = load_specs(&cases).expect_err("a dangling record loads");
        std::fs::remove_dir_all(&dir).unwrap();
        let message = e.to_string();
        assert!(
            message.contains("quantities[0].known_deviation"),
            "{message}"
        );
        assert!(matches!(e, TampError::Input { .. }), "{e:?}");
    }
}
