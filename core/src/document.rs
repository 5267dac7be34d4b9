//! What a file given to `tamp run` holds: an ordinary scene, or a die-compaction
//! process whose stages are scenes (`process::die_compaction_file`). The file is read
//! once (so standard input works) and its kind is recognised from its JSON object,
//! by whether it has a `die_compaction` block; then it is parsed as that kind, with
//! every error naming its JSON path and rule.

use crate::error::{Result, TampError};
use crate::process::die_compaction_file::DieCompactionFile;
use crate::scene::{self, Scene};
use std::path::Path;

/// A scene or process file, parsed and validated.
#[derive(Clone, Debug)]
pub enum Document {
    /// An ordinary scene, run as it stands.
    Scene(Box<Scene>),
    /// The die compaction of Rojek 2016 §5, run as its stage scenes.
    DieCompaction(Box<DieCompactionFile>),
}

/// Parse and validate a file's JSON text as the kind it is.
pub fn parse(text: &str) -> Result<Document> {
    let process = || {
        Ok(Document::DieCompaction(Box::new(
            DieCompactionFile::parse_known(text)?,
        )))
    };
    match scene::is_process(text) {
        Some(true) => process(),
        Some(false) => Ok(Document::Scene(Box::new(scene::parse_known_scene(text)?))),
        // Malformed: the scene reader names the error's path, unless the file is a
        // process, which it finds before the error as an unknown `die_compaction`.
        None => match scene::parse_known_scene(text) {
            Err(TampError::Input { rule, .. })
                if rule.starts_with("unknown field `die_compaction`") =>
            {
                process()
            }
            Err(e) => Err(e),
            Ok(_) => unreachable!("malformed JSON parses as no scene"),
        },
    }
}

/// Read a file once (`-` or `/dev/stdin`: standard input), parse and validate it as
/// the kind it is; also returns the SHA-256 of its bytes.
pub fn load(path: &Path) -> Result<(Document, String)> {
    let input = scene::read_input(path)?;
    let document = match parse(&input.text)? {
        Document::Scene(mut s) => {
            s.base_dir = input.base_dir;
            Document::Scene(s)
        }
        Document::DieCompaction(mut d) => {
            d.scene.base_dir = input.base_dir;
            Document::DieCompaction(d)
        }
    };
    Ok((document, input.sha256))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn checked_in(name: &str) -> String {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../verification")
            .join(format!("{name}.scene.json"));
        std::fs::read_to_string(path).unwrap()
    }

    #[test]
    fn each_kind_is_recognised_and_each_reader_refuses_the_other() {
        let die = checked_in("nial_die_compaction_small");
        let plain = checked_in("hertz_collision_time");
        assert!(matches!(parse(&die), Ok(Document::DieCompaction(_))));
        assert!(matches!(parse(&plain), Ok(Document::Scene(_))));
        let as_scene = scene::parse(&die).unwrap_err().to_string();
        assert!(as_scene.starts_with("die_compaction: makes this file a die-compaction process"));
        let as_die = DieCompactionFile::parse(&plain).unwrap_err().to_string();
        assert!(as_die.starts_with("die_compaction: is required"));
    }

    /// The process file serialises back to the object it was read from, so a stage or a
    /// cache key made from it sees every field the file gave.
    #[test]
    fn a_die_compaction_file_round_trips_through_its_json() {
        let text = checked_in("lammps_die_compaction_small");
        let file = DieCompactionFile::parse(&text).unwrap();
        let again = serde_json::to_value(&file).unwrap();
        let read: serde_json::Value = serde_json::from_str(&text).unwrap();
        for key in read.as_object().unwrap().keys() {
            assert!(again.get(key).is_some(), "{key} lost");
        }
        let reparsed = DieCompactionFile::parse(&again.to_string()).unwrap();
        assert_eq!(serde_json::to_value(&reparsed).unwrap(), again);
    }
}
