//! Scene files: parse (with JSON paths in every error), validate, build a `Simulation`.

pub mod build;
pub mod contact;
mod json_error;
pub mod materials;
pub mod memory;
pub mod particles;
pub mod physics;
pub mod run;
pub mod schema;
pub mod validate;
pub mod walls;

pub use build::{BuiltScene, build};
pub use schema::Scene;

use crate::error::{Result, TampError};
use sha2::{Digest, Sha256};

/// Parse scene JSON text. Errors name the JSON path (`particles[3].radius`) and the rule;
/// anything after the scene's JSON is an error too, not ignored. A die-compaction file
/// is not a scene: it is refused naming `die_compaction` (`document::parse` reads either).
pub fn parse(text: &str) -> Result<Scene> {
    if is_process(text) == Some(true) {
        return Err(TampError::input(
            "die_compaction",
            "makes this file a die-compaction process, not a scene: `tamp run` runs it, and `process::die_compaction_file::DieCompactionFile` reads it",
        ));
    }
    parse_known_scene(text)
}

/// `parse` of a text already known to be a scene (`document::parse` has looked).
pub(crate) fn parse_known_scene(text: &str) -> Result<Scene> {
    let scene: Scene = parse_json(text)?;
    validate::validate(&scene)?;
    Ok(scene)
}

/// Whether a file's JSON object has a `die_compaction` block, which makes it a process
/// document rather than a scene; `None` when the JSON is malformed, so that the kind
/// cannot be told. Every other value is skipped unchecked, so this pass cannot name
/// the path of an error inside one: the reader of the file's kind names it instead.
pub fn is_process(text: &str) -> Option<bool> {
    #[derive(serde::Deserialize)]
    struct Kind {
        #[serde(default)]
        die_compaction: Option<serde::de::IgnoredAny>,
    }
    let kind: Kind = serde_json::from_str(text).ok()?;
    Some(kind.die_compaction.is_some())
}

/// One JSON object of type `T` from a file's text, unvalidated. Errors name the JSON
/// path and the rule (`scene` for the top level and for malformed JSON); a byte-order
/// mark and anything after the object are errors, not ignored.
pub fn parse_json<T: serde::de::DeserializeOwned>(text: &str) -> Result<T> {
    if text.starts_with('\u{feff}') {
        return Err(TampError::input(
            "scene",
            "starts with a UTF-8 byte-order mark (U+FEFF), which JSON does not allow; save the file without it",
        ));
    }
    let de = &mut serde_json::Deserializer::from_str(text);
    let value: T = serde_path_to_error::deserialize(&mut *de).map_err(|e| {
        let path = e.path().to_string();
        let inner = e.into_inner();
        let (path, rule) = if inner.is_syntax() || inner.is_eof() {
            (path, format!("malformed JSON: {inner}"))
        } else {
            let rule = inner.to_string();
            (json_error::refine(text, &path, &rule), rule)
        };
        // `.` is the top level; `?` is a key a syntax error cut short, so the path
        // ends at the object that holds it.
        let path = path
            .split('.')
            .filter(|part| !part.is_empty() && *part != "?")
            .collect::<Vec<_>>()
            .join(".");
        let path = if path.is_empty() {
            "scene".to_string()
        } else {
            path
        };
        TampError::input(path, rule)
    })?;
    de.end().map_err(|e| {
        TampError::input(
            "scene",
            format!(
                "trailing data after the scene's JSON at line {} column {}: a scene file holds one JSON object",
                e.line(),
                e.column()
            ),
        )
    })?;
    Ok(value)
}

/// A file's text as read once, with what a run needs to know of where it came from.
pub struct Input {
    /// The file's text (UTF-8).
    pub text: String,
    /// SHA-256 of its bytes, hex.
    pub sha256: String,
    /// Directory relative file references are found from (empty for standard input:
    /// the current directory).
    pub base_dir: std::path::PathBuf,
}

/// Read a scene or process file once. The path `-` (or `/dev/stdin`) reads standard
/// input; the files a scene read that way names (meshes, particle files) are then found
/// from the current directory.
pub fn read_input(path: &std::path::Path) -> Result<Input> {
    let stdin = is_stdin(path);
    let bytes = if stdin {
        let mut bytes = Vec::new();
        std::io::Read::read_to_end(&mut std::io::stdin(), &mut bytes)
            .map_err(|e| TampError::io("reading the scene from standard input", e))?;
        bytes
    } else {
        std::fs::read(path)
            .map_err(|e| TampError::io(format!("reading scene {}", path.display()), e))?
    };
    let sha256 = sha256_hex(&bytes);
    let text = String::from_utf8(bytes)
        .map_err(|_| TampError::input(path.display().to_string(), "must be UTF-8 text"))?;
    let base_dir = match path.parent() {
        Some(dir) if !stdin => dir.to_path_buf(),
        _ => std::path::PathBuf::new(),
    };
    Ok(Input {
        text,
        sha256,
        base_dir,
    })
}

/// Read, parse and validate a scene file; also returns the SHA-256 of its bytes
/// (`read_input` says how `-` reads standard input).
pub fn load(path: &std::path::Path) -> Result<(Scene, String)> {
    let input = read_input(path)?;
    let mut scene = parse(&input.text)?;
    scene.base_dir = input.base_dir;
    Ok((scene, input.sha256))
}

/// Whether `path` names standard input rather than a file.
pub fn is_stdin(path: &std::path::Path) -> bool {
    path == std::path::Path::new("-") || path == std::path::Path::new("/dev/stdin")
}

/// SHA-256 of `bytes` in lowercase hex: the scene's fingerprint in the provenance and in
/// checkpoints, which a resumed run must match.
pub fn sha256_hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}
