//! Scene files: parse (with JSON paths in every error), validate, build a `Simulation`.

pub mod build;
pub mod contact;
pub mod die_compaction;
pub mod funnel;
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
/// anything after the scene's JSON is an error too, not ignored.
pub fn parse(text: &str) -> Result<Scene> {
    if text.starts_with('\u{feff}') {
        return Err(TampError::input(
            "scene",
            "starts with a UTF-8 byte-order mark (U+FEFF), which JSON does not allow; save the file without it",
        ));
    }
    let de = &mut serde_json::Deserializer::from_str(text);
    let scene: Scene = serde_path_to_error::deserialize(&mut *de).map_err(|e| {
        let path = e.path().to_string();
        let inner = e.into_inner();
        // `.` is the top level; `?` is where a syntax error left the path unknown.
        let path = if path == "." || path == "?" {
            "scene".to_string()
        } else {
            path
        };
        let rule = if inner.is_syntax() || inner.is_eof() {
            format!("malformed JSON: {inner}")
        } else {
            inner.to_string()
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
    validate::validate(&scene)?;
    Ok(scene)
}

/// Read, parse and validate a scene file; also returns the SHA-256 of its bytes. The path
/// `-` (or `/dev/stdin`) reads standard input, once; the files a scene read that way names
/// (meshes, particle files) are then found from the current directory.
pub fn load(path: &std::path::Path) -> Result<(Scene, String)> {
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
    let text = String::from_utf8(bytes.clone())
        .map_err(|_| TampError::input(path.display().to_string(), "must be UTF-8 text"))?;
    let mut scene = parse(&text)?;
    scene.base_dir = match path.parent() {
        Some(dir) if !stdin => dir.to_path_buf(),
        _ => std::path::PathBuf::new(),
    };
    Ok((scene, sha256_hex(&bytes)))
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
