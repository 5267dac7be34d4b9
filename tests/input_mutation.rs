//! Inputs broken the ways users and other programs break them. Valid files (the
//! verification scenes, a trajectory.csv, a LIGGGHTS/LAMMPS dump) are mutated at
//! random: a number replaced by NaN, ±Infinity, 1e308, -0 or 5e-324, a field deleted
//! or given twice, a value of another type, the text cut short. Whatever the mutation,
//! the reader never panics: it accepts the file (and then every number it returns is
//! finite) or refuses it with an input error that starts with where the fault is (a
//! JSON path, or the file and its row). An accepted scene of explicit particles is
//! built and stepped too, and refused as input or stopped as unstable, never by a
//! panic. `tamp run` refusing a scene (exit 2) leaves no output directory.

use proptest::prelude::*;
use serde_json::Value;
use std::path::Path;
use std::sync::OnceLock;
use tamp::error::TampError;

mod common;

/// The verification scenes and die-compaction files, as text.
fn scenes() -> &'static Vec<(String, String)> {
    static SCENES: OnceLock<Vec<(String, String)>> = OnceLock::new();
    SCENES.get_or_init(|| {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("verification");
        let mut all: Vec<(String, String)> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.to_string_lossy().ends_with(".scene.json"))
            .map(|p| {
                let name = p.file_name().unwrap().to_string_lossy().to_string();
                (name, std::fs::read_to_string(&p).unwrap())
            })
            .collect();
        all.sort();
        all
    })
}

/// A mutation of one JSON value (the `k`-th, in document order, of the kinds it
/// applies to).
#[derive(Clone, Copy, Debug)]
enum Mutation {
    /// A number replaced by a literal: NaN, Infinity, -Infinity, 1e308, -0, 5e-324.
    Number(&'static str),
    /// An object member deleted.
    Delete,
    /// An object member written twice.
    Duplicate,
    /// A value replaced by one of another type.
    Retype,
    /// The text cut at a fraction of its length.
    Truncate(f64),
}

const LITERALS: [&str; 6] = ["NaN", "Infinity", "-Infinity", "1e308", "-0", "5e-324"];

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        (0..LITERALS.len()).prop_map(|i| Mutation::Number(LITERALS[i])),
        Just(Mutation::Delete),
        Just(Mutation::Duplicate),
        Just(Mutation::Retype),
        (0.0..1.0f64).prop_map(Mutation::Truncate),
    ]
}

/// Apply `m` to the `k`-th value it can apply to; None when nothing can take it.
fn mutate(text: &str, m: Mutation, k: usize) -> Option<String> {
    mutate_at(text, m, k).map(|(t, _)| t)
}

/// `mutate`, and the JSON path of the value it changed (`a.b[2]`).
fn mutate_at(text: &str, m: Mutation, k: usize) -> Option<(String, String)> {
    const MARK: &str = "\"@@MUTATED@@\"";
    let mut root: Value = serde_json::from_str(text).unwrap();
    if let Mutation::Truncate(f) = m {
        let cut = (f * text.len() as f64) as usize;
        return Some((
            text[..text.floor_char_boundary(cut)].to_string(),
            String::new(),
        ));
    }
    let mut count = 0;
    let mut done = None;
    let mut at = String::new();
    #[allow(clippy::too_many_arguments)]
    fn walk(
        v: &mut Value,
        m: Mutation,
        k: usize,
        count: &mut usize,
        done: &mut Option<String>,
        here: &str,
        at: &mut String,
    ) {
        let join = |key: &str| match here {
            "" => key.to_string(),
            _ => format!("{here}.{key}"),
        };
        if done.is_some() {
            return;
        }
        match v {
            Value::Object(map) => {
                let keys: Vec<String> = map.keys().cloned().collect();
                for key in keys {
                    if done.is_some() {
                        return;
                    }
                    if matches!(m, Mutation::Delete | Mutation::Duplicate) {
                        if *count == k {
                            let value = map.get(&key).unwrap().clone();
                            match m {
                                Mutation::Delete => {
                                    *at = join(&key);
                                    map.remove(&key);
                                    *done = Some(String::new());
                                }
                                _ => {
                                    // Written twice: the marker member is replaced by
                                    // the pair in the text.
                                    *at = join(&key);
                                    map.insert(key.clone(), Value::String("@@MUTATED@@".into()));
                                    *done = Some(format!(
                                        "{}, {}: {}",
                                        serde_json::to_string(&value).unwrap(),
                                        serde_json::to_string(&key).unwrap(),
                                        serde_json::to_string(&value).unwrap()
                                    ));
                                }
                            }
                            return;
                        }
                        *count += 1;
                    }
                    walk(
                        map.get_mut(&key).unwrap(),
                        m,
                        k,
                        count,
                        done,
                        &join(&key),
                        at,
                    );
                }
            }
            Value::Array(items) => {
                for (i, item) in items.iter_mut().enumerate() {
                    walk(item, m, k, count, done, &format!("{here}[{i}]"), at);
                }
            }
            _ => {}
        }
        if done.is_some() {
            return;
        }
        let applies = match m {
            Mutation::Number(_) => v.is_number(),
            Mutation::Retype => true,
            _ => false,
        };
        if applies {
            if *count == k {
                *at = here.to_string();
                match m {
                    Mutation::Number(literal) => {
                        *v = Value::String("@@MUTATED@@".into());
                        *done = Some(literal.to_string());
                    }
                    _ => {
                        *v = match v {
                            Value::Number(_) => Value::String("text".into()),
                            Value::String(_) => serde_json::json!(1.5),
                            Value::Array(_) => serde_json::json!({}),
                            Value::Object(_) => serde_json::json!([]),
                            _ => serde_json::json!("text"),
                        };
                        *done = Some(String::new());
                    }
                }
                return;
            }
            *count += 1;
        }
    }
    walk(&mut root, m, k, &mut count, &mut done, "", &mut at);
    let replacement = done?;
    let text = serde_json::to_string_pretty(&root).unwrap();
    let text = match text.contains(MARK) {
        true => text.replacen(MARK, &replacement, 1),
        false => text,
    };
    Some((text, at))
}

/// Whether `message` starts with a JSON path (`scene`, `particles[0].radius`, …)
/// followed by ": ".
fn starts_with_path(message: &str) -> bool {
    let Some((path, _)) = message.split_once(": ") else {
        return false;
    };
    !path.is_empty()
        && path.split('.').all(|part| {
            let name = part.split('[').next().unwrap();
            let indices_ok = part.split('[').skip(1).all(|i| {
                i.strip_suffix(']')
                    .is_some_and(|n| n.chars().all(|c| c.is_ascii_digit()))
            });
            !name.is_empty()
                && name
                    .chars()
                    .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
                && indices_ok
        })
}

fn check_scene_error(e: &TampError, text: &str) {
    let listed = match e {
        TampError::Input { .. } | TampError::InputMany(_) => e.to_string(),
        other => panic!("not an input error: {other}\n{text}"),
    };
    for line in listed.lines() {
        assert!(starts_with_path(line), "no JSON path first: {line}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn a_mutated_scene_is_read_or_refused_naming_its_json_path(
        scene in 0..64usize, m in mutation(), k in 0..150usize
    ) {
        let all = scenes();
        let (_, text) = &all[scene % all.len()];
        if let Some((mutated, at)) = mutate_at(text, m, k) {
            let read = std::panic::catch_unwind(|| tamp::document::parse(&mutated));
            match read {
                Err(_) => panic!("the reader panicked on:\n{mutated}"),
                Ok(Err(e)) => {
                    check_scene_error(&e, &mutated);
                    // A literal JSON cannot hold, or a value of the wrong type, is
                    // named by its own path.
                    let exact = matches!(m, Mutation::Number("NaN" | "Infinity" | "-Infinity") | Mutation::Retype);
                    if exact && !at.is_empty() {
                        let message = e.to_string();
                        let named = message.split_once(": ").map(|(p, _)| p).unwrap_or("");
                        prop_assert!(named == at || named.starts_with(&format!("{at}.")) || named.starts_with(&format!("{at}[")) || !message.contains("invalid type") && !message.contains("malformed JSON"),
                            "{m:?} at {at}, named {named}: {message}");
                    }
                }
                Ok(Ok(tamp::document::Document::Scene(scene))) if is_small(&scene) => {
                    build_and_step(&scene, &mutated);
                }
                Ok(Ok(_)) => {}
            }
        }
    }
}

/// A scene cheap enough to build and step in a property test: explicit particles only.
fn is_small(scene: &tamp::scene::Scene) -> bool {
    scene.insert.is_empty() && scene.deposit.is_empty() && scene.particles.len() <= 200
}

/// Build an accepted scene and take a few steps: no panic, and a refusal is an input
/// error (exit 2) naming a path, a failure in the steps an instability (exit 3).
fn build_and_step(scene: &tamp::scene::Scene, text: &str) {
    let run = std::panic::catch_unwind(|| -> Result<(), TampError> {
        let mut sim = tamp::scene::build(scene)?.sim;
        for _ in 0..5 {
            sim.step()?;
        }
        Ok(())
    });
    match run {
        Err(_) => panic!("building or stepping panicked on:\n{text}"),
        Ok(Err(e @ (TampError::Input { .. } | TampError::InputMany(_)))) => {
            check_scene_error(&e, text)
        }
        Ok(Err(TampError::Unstable { .. }) | Ok(())) => {}
        Ok(Err(other)) => panic!("neither an input error nor an instability: {other}\n{text}"),
    }
}

/// `tamp run` on a handful of mutated scenes: exit 0 or 2 (3 for a run that went
/// wrong), a path first on stderr, and no output directory after a refusal.
#[test]
fn tamp_run_refuses_mutated_scenes_without_leaving_an_output_directory() {
    let text = include_str!("scenes/base.json");
    for (m, k) in [
        (Mutation::Number("NaN"), 3),
        (Mutation::Number("1e308"), 5),
        (Mutation::Number("5e-324"), 2),
        (Mutation::Delete, 4),
        (Mutation::Duplicate, 1),
        (Mutation::Retype, 7),
        (Mutation::Truncate(0.5), 0),
    ] {
        let mutated = mutate(text, m, k).unwrap();
        let dir = tempfile::tempdir().unwrap();
        let (scene, out) = (dir.path().join("scene.json"), dir.path().join("out"));
        std::fs::write(&scene, &mutated).unwrap();
        let run = common::run(&scene, &out, &[]);
        let stderr = String::from_utf8_lossy(&run.stderr);
        match run.status.code() {
            Some(2) => {
                let message = stderr.trim_start_matches("error: ");
                assert!(starts_with_path(message), "{m:?}: {stderr}");
                assert!(!out.exists(), "{m:?}: exit 2 left {}", out.display());
            }
            Some(0 | 3) => {}
            other => panic!("{m:?}: exit {other:?}: {stderr}"),
        }
    }
}

/// A valid trajectory.csv of three particles at three steps, with forces.
fn trajectory() -> String {
    let mut s = String::from("step,id,radius,x,y,z,vx,vy,vz,omegax,omegay,omegaz,fx,fy,fz\n");
    for step in 0..3 {
        for id in 1..=3 {
            s.push_str(&format!(
                "{step},{id},1e-3,{},{},0.5,0.1,-0.2,0,0,0,1,0,0,-9.81e-5\n",
                id as f64 * 0.01,
                step as f64 * 1e-4
            ));
        }
    }
    s
}

/// A valid dump of three atoms at two steps, as LIGGGHTS and LAMMPS write it.
fn dump() -> String {
    let mut s = String::new();
    for step in [0, 100] {
        s.push_str(&format!(
            "ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ATOMS\n3\nITEM: BOX BOUNDS pp ff ff\n-0.1 0.1\n-0.1 0.1\n0 0.2\nITEM: ATOMS id type x y z vx vy vz omegax omegay omegaz radius mass fx fy fz\n"
        ));
        for id in 1..=3 {
            s.push_str(&format!(
                "{id} 1 {} 0 0.05 0.1 0 0 0 0 0 1e-3 1e-5 0 0 -9.81e-5\n",
                id as f64 * 0.01
            ));
        }
    }
    s
}

/// A text mutation of a table: one field replaced, a column dropped, a row given twice,
/// the text cut.
fn mutate_table(text: &str, sep: char, kind: usize, at: usize, value: &str) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let row = at % lines.len();
    let mut out: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
    match kind {
        0 => {
            let mut fields: Vec<String> = lines[row].split(sep).map(str::to_string).collect();
            let f = (at / lines.len()) % fields.len();
            fields[f] = value.to_string();
            out[row] = fields.join(&sep.to_string());
        }
        1 => {
            let f = at % lines[0].split(sep).count();
            out = lines
                .iter()
                .map(|l| {
                    let mut fields: Vec<&str> = l.split(sep).collect();
                    if f < fields.len() {
                        fields.remove(f);
                    }
                    fields.join(&sep.to_string())
                })
                .collect();
        }
        2 => out.insert(row, lines[row].to_string()),
        _ => {
            let cut = at % text.len();
            return text[..text.floor_char_boundary(cut)].to_string();
        }
    }
    out.join("\n") + "\n"
}

const BAD_VALUES: [&str; 8] = ["NaN", "inf", "-inf", "1e999", "x", "", "-0", "5e-324"];

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn a_mutated_trajectory_is_read_finite_or_refused_naming_file_and_row(
        kind in 0..4usize, at in 0..10_000usize, value in 0..BAD_VALUES.len()
    ) {
        let text = mutate_table(&trajectory(), ',', kind, at, BAD_VALUES[value]);
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("trajectory.csv");
        std::fs::write(&path, &text).unwrap();
        match std::panic::catch_unwind(|| tamp::compare::read_trajectory(&path)) {
            Err(_) => panic!("the reader panicked on:\n{text}"),
            Ok(Err(TampError::Input { path: named, .. })) => {
                prop_assert!(named.contains("trajectory.csv"), "{named}");
            }
            Ok(Err(other)) => panic!("not an input error: {other}\n{text}"),
            Ok(Ok(rows)) => {
                for s in rows.values() {
                    let mut all = vec![s.radius, s.position.x, s.position.y, s.position.z];
                    for v in [s.velocity, s.omega, s.force].into_iter().flatten() {
                        all.extend([v.x, v.y, v.z]);
                    }
                    prop_assert!(all.iter().all(|v| v.is_finite()), "{text}");
                }
            }
        }
    }

    #[test]
    fn a_mutated_dump_is_read_finite_or_refused_naming_file_and_line(
        kind in 0..4usize, at in 0..10_000usize, value in 0..BAD_VALUES.len()
    ) {
        let text = mutate_table(&dump(), ' ', kind, at, BAD_VALUES[value]);
        let path = Path::new("dump.liggghts");
        match std::panic::catch_unwind(|| tamp::liggghts::dump::parse(&text, path)) {
            Err(_) => panic!("the reader panicked on:\n{text}"),
            Ok(Err(TampError::Input { path: named, .. })) => {
                prop_assert!(named.starts_with("dump.liggghts"), "{named}");
            }
            Ok(Err(other)) => panic!("not an input error: {other}\n{text}"),
            Ok(Ok(frames)) => {
                for f in &frames {
                    let vectors = f.position.iter().chain(&f.velocity).chain(&f.omega);
                    prop_assert!(vectors.flat_map(|v| v.iter()).all(|x| x.is_finite()), "{text}");
                    prop_assert!(f.radius.iter().all(|r| r.is_finite()), "{text}");
                }
            }
        }
    }
}
