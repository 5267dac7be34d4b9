//! The JSON path of a value a file's reader refused, whatever block it is in.
//!
//! `serde_path_to_error` follows the reader into every struct, list and map, but not
//! into a block serde reads in two passes: an internally tagged enum (`{"law": …}`,
//! `{"kind": …}`), a flattened struct or an untagged one first buffer the whole
//! object, and an error found in the second pass carries only the object's path
//! (`contact.damping: invalid type: string "x", expected f64`). The message still says
//! what it found, so the value is looked for inside that object: the first member,
//! at any depth, that is what the message found (the string, number, boolean, null,
//! list or object it quotes, or the unknown variant's name), else the object itself.
//! A missing, unknown or repeated field is named by the object's path and the field's
//! name.

use serde_json::Value;

/// What an error message says it found.
#[derive(Debug, PartialEq)]
enum Found {
    Str(String),
    Num(f64),
    Bool(bool),
    Null,
    List,
    Object,
}

impl Found {
    /// The value quoted by a serde message: `invalid type: string "x", expected …`,
    /// `invalid value: integer `3`, expected …`, `unknown variant `x`, expected …`.
    fn in_message(rule: &str) -> Option<Found> {
        if let Some(rest) = rule.strip_prefix("unknown variant `") {
            return Some(Found::Str(rest.split('`').next()?.to_string()));
        }
        let rest = rule
            .strip_prefix("invalid type: ")
            .or_else(|| rule.strip_prefix("invalid value: "))?;
        let what = rest.split(", expected").next()?;
        let quoted = || what.split('`').nth(1);
        Some(if let Some(s) = what.strip_prefix("string ") {
            Found::Str(serde_json::from_str(s).ok()?)
        } else if what.starts_with("floating point") || what.starts_with("integer") {
            Found::Num(quoted()?.parse().ok()?)
        } else if what.starts_with("boolean") {
            Found::Bool(quoted()? == "true")
        } else if what == "null" || what == "unit value" {
            Found::Null
        } else if what == "sequence" {
            Found::List
        } else if what == "map" {
            Found::Object
        } else {
            return None;
        })
    }

    fn is(&self, v: &Value) -> bool {
        match (self, v) {
            (Found::Str(s), Value::String(t)) => s == t,
            (Found::Num(x), Value::Number(n)) => n.as_f64() == Some(*x),
            (Found::Bool(b), Value::Bool(c)) => b == c,
            (Found::Null, Value::Null) => true,
            (Found::List, Value::Array(_)) => true,
            (Found::Object, Value::Object(_)) => true,
            _ => false,
        }
    }
}

/// The value at `path` (`a.b[2].c`, or `.` for the whole file).
fn at<'a>(root: &'a Value, path: &str) -> Option<&'a Value> {
    let mut v = root;
    for part in path.split('.').filter(|p| !p.is_empty()) {
        let (key, indices) = part.split_at(part.find('[').unwrap_or(part.len()));
        if !key.is_empty() {
            v = v.get(key)?;
        }
        for index in indices.split('[').filter(|i| !i.is_empty()) {
            v = v.get(index.strip_suffix(']')?.parse::<usize>().ok()?)?;
        }
    }
    Some(v)
}

/// The path, below `path`, of the first value in `v` that is `found`.
fn first(v: &Value, path: &str, found: &Found) -> Option<String> {
    let join = |key: &str| match path {
        "" | "." => key.to_string(),
        _ => format!("{path}.{key}"),
    };
    match v {
        Value::Object(map) => map.iter().find_map(|(k, m)| match found.is(m) {
            true => Some(join(k)),
            false => first(m, &join(k), found),
        }),
        Value::Array(items) => items.iter().enumerate().find_map(|(i, m)| {
            let here = format!("{path}[{i}]");
            match found.is(m) {
                true => Some(here),
                false => first(m, &here, found),
            }
        }),
        _ => None,
    }
}

/// The full path of the value an error at `path` with message `rule` is about, in the
/// file `text` (which parsed as JSON); `path` itself when nothing more can be told.
pub(super) fn refine(text: &str, path: &str, rule: &str) -> String {
    // The reader's path ends at an unknown field's own name (it read the key before
    // refusing it), and at the object for a missing one.
    let join = |field: &str| match path {
        "" | "." => field.to_string(),
        _ if path.rsplit('.').next() == Some(field) => path.to_string(),
        _ => format!("{path}.{field}"),
    };
    for prefix in ["missing field `", "unknown field `", "duplicate field `"] {
        if let Some(field) = rule.strip_prefix(prefix).and_then(|r| r.split('`').next()) {
            return join(field);
        }
    }
    let Some(found) = Found::in_message(rule) else {
        return path.to_string();
    };
    let Ok(root) = serde_json::from_str::<Value>(text) else {
        return path.to_string();
    };
    // A block is itself an object, so a found object or list is first looked for
    // inside it.
    at(&root, path)
        .and_then(|v| first(v, path, &found))
        .unwrap_or_else(|| path.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_value_inside_a_buffered_block_is_found_by_what_the_message_quotes() {
        let text = r#"{"contact": {"damping": {"kind": "critical_fraction", "xi": "text"}},
                       "walls": [{"shape": {"kind": "plane", "point": [0, true, 0]}}]}"#;
        let refined = |path, rule| refine(text, path, rule);
        assert_eq!(
            refined(
                "contact.damping",
                "invalid type: string \"text\", expected f64 at line 1 column 70"
            ),
            "contact.damping.xi"
        );
        assert_eq!(
            refined(
                "walls[0].shape",
                "invalid type: boolean `true`, expected f64"
            ),
            "walls[0].shape.point[1]"
        );
        assert_eq!(
            refined(
                "contact.damping",
                "unknown variant `critical_fraction`, expected `tsuji`"
            ),
            "contact.damping.kind"
        );
        assert_eq!(
            refined("contact", "missing field `normal`"),
            "contact.normal"
        );
        assert_eq!(refined(".", "unknown field `colour`"), "colour");
        assert_eq!(refined("colour", "unknown field `colour`"), "colour");
        assert_eq!(
            refined("particles[1].colour", "unknown field `colour`"),
            "particles[1].colour"
        );
        // Nothing in the block is what the message found: the block's path stays.
        assert_eq!(
            refined("contact.damping", "invalid type: integer `7`, expected f64"),
            "contact.damping"
        );
    }
}
