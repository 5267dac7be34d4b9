//! What a LIGGGHTS deck and a LAMMPS deck share, whichever peer reads it: the scene
//! file read with an optional new seed, the neighbour skin, the interval between
//! dumped frames, the dump's columns and number format, the choice between a scene and
//! a die-compaction file, what neither peer can express, the deck's head, time step,
//! gravity, integration, dumps and run, and what an export reports. Each peer's own
//! commands are in `liggghts::export` and `lammps::export`.

use crate::decimal::g;
use crate::document::Document;
use crate::error::Result;
use crate::process::die_compaction_file::DieCompactionFile;
use crate::scene::Scene;
use crate::simulation::Simulation;
use std::fmt::Write as _;
use std::path::Path;

/// The peer a deck is for: its name in messages and file names, and how its
/// `dump_modify` spells a line format.
#[derive(Clone, Copy, Debug)]
pub struct Peer {
    /// `LIGGGHTS` or `LAMMPS`, in refusals.
    pub name: &'static str,
    /// The dump files' extension: `liggghts` or `lammps`.
    pub extension: &'static str,
    /// `format` (LIGGGHTS 3.8) or `format line` (LAMMPS).
    pub format_keyword: &'static str,
}

/// LIGGGHTS 3.8.
pub const LIGGGHTS: Peer = Peer {
    name: "LIGGGHTS",
    extension: "liggghts",
    format_keyword: "format",
};

/// LAMMPS 22 Jul 2025.
pub const LAMMPS: Peer = Peer {
    name: "LAMMPS",
    extension: "lammps",
    format_keyword: "format line",
};

/// What neither peer's deck expresses, whatever the laws: a growth stage, pouring
/// during the run and prescribed particles, as (field, reason).
pub fn scene_refusals(scene: &Scene, peer: Peer) -> Vec<(String, String)> {
    let name = peer.name;
    let mut out = Vec::new();
    if scene.growth.is_some() {
        out.push((
            "growth".to_string(),
            format!("{name} has no radius growth stage; export the grown state instead"),
        ));
    }
    for (k, ins) in scene.insert.iter().enumerate() {
        if ins.schedule.is_some() {
            out.push((
                format!("insert[{k}].schedule"),
                format!("{name} pours with its own random placement; export scenes whose particles are all placed at t = 0"),
            ));
        }
    }
    for (k, p) in scene.particles.iter().enumerate() {
        if p.prescribed_velocity.is_some() {
            out.push((
                format!("particles[{k}].prescribed_velocity"),
                format!("not exported ({name} would need a separate fix for each driven particle)"),
            ));
        }
    }
    out
}

/// The scene built, unless the peer refuses any of its fields (`refusals`, all of
/// them listed at once, exit 2); `peer` names it in the messages.
pub fn build_unless_refused(
    scene: &Scene,
    refusals: Vec<(String, String)>,
    peer: &str,
) -> Result<crate::scene::build::BuiltScene> {
    if !refusals.is_empty() {
        return Err(crate::error::cannot_export(peer, refusals));
    }
    crate::scene::build(scene)
}

/// The simulation box: each periodic axis exactly (`p`), every other one from `lo` to
/// `hi` widened by `margin` on both sides, shrink-wrapping with that minimum (`m`).
/// Returns the `boundary` flags and the bounds.
pub fn box_axes(
    periodic: [Option<[f64; 2]>; 3],
    (lo, hi): ([f64; 3], [f64; 3]),
    margin: f64,
) -> (Vec<&'static str>, [[f64; 2]; 3]) {
    let mut boundary = Vec::new();
    let mut bounds = [[0.0; 2]; 3];
    for a in 0..3 {
        let (l, h, flag) = match periodic[a] {
            Some([l, h]) => (l, h, "p"),
            None => (lo[a] - margin, hi[a] + margin, "m"),
        };
        boundary.push(flag);
        bounds[a] = [l, h];
    }
    (boundary, bounds)
}

/// The deck's first lines: which peer and tamp wrote it, from which scene (and
/// `more` after the seed, e.g. the step), and the command that `run`s it.
pub fn head(
    deck: &mut String,
    peer_version: &str,
    (scene, sha): (&Scene, &str),
    more: &str,
    run: &str,
) {
    let _ = writeln!(
        deck,
        "# {peer_version} deck exported by tamp {} (commit {})",
        crate::VERSION,
        crate::GIT_COMMIT
    );
    let _ = writeln!(
        deck,
        "# scene '{}', sha256 {sha}, seed {}{more}\n# run: {run}",
        scene.name.replace(['\n', '\r'], " "),
        scene.seed,
    );
}

/// `timestep`, and the `fix gravity` of a scene with gravity.
pub fn timestep_and_gravity(deck: &mut String, sim: &Simulation) {
    let _ = writeln!(deck, "timestep     {}", g(sim.dt()));
    if let Some(gv) = sim.model().gravity {
        let norm = gv.norm();
        if norm > 0.0 {
            let d = gv / norm;
            let _ = writeln!(
                deck,
                "fix          gravi all gravity {} vector {} {} {}",
                g(norm),
                g(d.x),
                g(d.y),
                g(d.z)
            );
        }
    }
}

/// The deck's last lines: velocity Verlet with spins, a frame every `every` steps in
/// `dump.<peer>`, thermo output, the run of `steps`, and the final state in
/// `final.<peer>`.
pub fn integrate_and_run(deck: &mut String, peer: Peer, every: u64, steps: u64) {
    let (ext, keyword) = (peer.extension, peer.format_keyword);
    let format = dump_format();
    deck.push_str("fix          integr all nve/sphere\n");
    let _ = writeln!(
        deck,
        "dump         dmp all custom {every} dump.{ext} {DUMP_COLUMNS}\ndump_modify  dmp {keyword} \"{format}\" sort id"
    );
    deck.push_str("thermo_style custom step time atoms ke\nthermo_modify norm no lost ignore\n");
    let _ = writeln!(deck, "thermo       {}", (steps / 20).max(1));
    let _ = writeln!(deck, "run          {steps}");
    let _ = writeln!(
        deck,
        "write_dump   all custom final.{ext} {DUMP_COLUMNS} modify {keyword} \"{format}\" sort id"
    );
}

/// Columns of every dump a deck writes (`liggghts::dump::Frame` reads them back, from
/// either peer: both write `dump custom` the same way).
pub const DUMP_COLUMNS: &str = "id type radius mass x y z vx vy vz omegax omegay omegaz fx fy fz";

/// The `dump_modify format` of `DUMP_COLUMNS`: the two integers, then every number to
/// the last bit.
pub fn dump_format() -> String {
    std::iter::once("%d %d")
        .chain(std::iter::repeat_n("%.17g", 14))
        .collect::<Vec<_>>()
        .join(" ")
}

/// What an export wrote.
#[derive(Debug)]
pub struct Exported {
    pub particles: usize,
    pub steps: u64,
    pub dt: f64,
    pub files: Vec<String>,
    /// Differences the deck cannot avoid (printed, and written into the deck).
    pub notes: Vec<String>,
}

/// The scene or die-compaction file and its hash, with `--seed` replacing the file's
/// seed (a new random placement, the same scene otherwise).
pub fn load_with_seed(path: &Path, seed: Option<u64>) -> Result<(Document, String)> {
    let (mut document, sha) = crate::document::load(path)?;
    if let Some(seed) = seed {
        match &mut document {
            Document::Scene(s) => s.seed = seed,
            Document::DieCompaction(d) => d.scene.seed = seed,
        }
    }
    Ok((document, sha))
}

/// The peer's neighbour skin: the scene's skin fraction of the smallest radius.
pub fn neighbor_skin(scene: &Scene, radius: &[f64]) -> f64 {
    let min_r = radius.iter().copied().fold(f64::INFINITY, f64::min);
    if min_r.is_finite() {
        scene.broad_phase.skin_fraction * min_r
    } else {
        1e-3
    }
}

/// Steps between dumped frames when none is asked for: as the scene's own
/// trajectory.csv (else series.csv) has them, so the two compare row by row.
pub fn frame_every(scene: &Scene, steps: u64) -> u64 {
    match (scene.output.trajectory_every, scene.output.series_every) {
        (0, 0) => (steps / 100).max(1),
        (0, n) | (n, _) => n,
    }
}

/// Write a peer's deck for the file at `path` into `out_dir`: a scene through
/// `scene`, a die-compaction file through `pressing`. A die-compaction file's particles
/// exist only after tamp's fill and flatten, so what is exported is its pressing,
/// replaying tamp's stroke.
pub fn export_file(
    path: &Path,
    out_dir: &Path,
    (dump_every, seed): (Option<u64>, Option<u64>),
    scene: impl FnOnce(&Scene, &str, &Path, Option<u64>) -> Result<Exported>,
    pressing: impl FnOnce(&DieCompactionFile, &str, &Path) -> Result<Exported>,
) -> Result<Exported> {
    match load_with_seed(path, seed)? {
        (Document::Scene(s), sha) => scene(&s, &sha, out_dir, dump_every),
        (Document::DieCompaction(file), sha) => pressing(&file, &sha, out_dir),
    }
}
