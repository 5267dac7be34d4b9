//! The direction of data, checked. Cargo already forbids the core crate (`core/`) to
//! import the checking crate (`src/`), because a crate cannot depend on its dependent.
//! Within each crate nothing forbids two top-level modules importing each other; this
//! test does. It reads every `crate::…` path in the code (comments aside, test modules
//! included), draws an edge from the importing top-level module to the imported one, and
//! fails naming a cycle if there is one.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The top-level modules of the crate whose `lib.rs` lies in `src`, each with its files.
fn modules(src: &Path) -> BTreeMap<String, Vec<PathBuf>> {
    let mut modules = BTreeMap::new();
    for entry in std::fs::read_dir(src).expect("the crate's src/") {
        let path = entry.expect("a directory entry").path();
        let name = path.file_stem().unwrap().to_string_lossy().to_string();
        if name == "lib" || name == "main" {
            continue;
        }
        let mut files = Vec::new();
        collect_rs(&path, &mut files);
        modules.insert(name, files);
    }
    modules
}

fn collect_rs(path: &Path, files: &mut Vec<PathBuf>) {
    if path.is_dir() {
        for entry in std::fs::read_dir(path).unwrap() {
            collect_rs(&entry.unwrap().path(), files);
        }
    } else if path.extension().is_some_and(|e| e == "rs") {
        files.push(path.to_path_buf());
    }
}

/// The first path segment after each `crate::`, including every name of a grouped import
/// `crate::{a::X, b}`, in code (lines that are comments are skipped).
fn imported_roots(text: &str) -> BTreeSet<String> {
    let code: String = text
        .lines()
        .filter(|l| !l.trim_start().starts_with("//"))
        .collect::<Vec<_>>()
        .join("\n");
    let mut roots = BTreeSet::new();
    let mut rest = code.as_str();
    while let Some(at) = rest.find("crate::") {
        let after = &rest[at + "crate::".len()..];
        if let Some(group) = after.strip_prefix('{') {
            // Names at depth 0 of the group: split on commas outside nested braces.
            let mut depth = 0;
            let mut start = 0;
            for (i, c) in group.char_indices() {
                match c {
                    '{' => depth += 1,
                    '}' if depth == 0 => {
                        roots.insert(first_segment(&group[start..i]));
                        break;
                    }
                    '}' => depth -= 1,
                    ',' if depth == 0 => {
                        roots.insert(first_segment(&group[start..i]));
                        start = i + 1;
                    }
                    _ => {}
                }
            }
        } else {
            roots.insert(first_segment(after));
        }
        rest = after;
    }
    roots.remove("");
    roots
}

fn first_segment(path: &str) -> String {
    path.trim()
        .chars()
        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
        .collect()
}

/// Edges between the crate's own top-level modules.
fn graph(src: &Path) -> BTreeMap<String, BTreeSet<String>> {
    let modules = modules(src);
    let mut edges = BTreeMap::new();
    for (name, files) in &modules {
        let mut to = BTreeSet::new();
        for file in files {
            let text = std::fs::read_to_string(file).unwrap();
            for root in imported_roots(&text) {
                if root != *name && modules.contains_key(&root) {
                    to.insert(root);
                }
            }
        }
        edges.insert(name.clone(), to);
    }
    edges
}

/// A cycle of the graph, as the modules along it, if there is one (depth-first search).
fn cycle(edges: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        node: &str,
        edges: &BTreeMap<String, BTreeSet<String>>,
        done: &mut BTreeSet<String>,
        path: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        if let Some(at) = path.iter().position(|n| n == node) {
            let mut cycle = path[at..].to_vec();
            cycle.push(node.to_string());
            return Some(cycle);
        }
        if done.contains(node) {
            return None;
        }
        path.push(node.to_string());
        for next in &edges[node] {
            if let Some(c) = visit(next, edges, done, path) {
                return Some(c);
            }
        }
        path.pop();
        done.insert(node.to_string());
        None
    }
    let mut done = BTreeSet::new();
    edges
        .keys()
        .find_map(|n| visit(n, edges, &mut done, &mut Vec::new()))
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn the_core_has_no_module_cycle() {
    let edges = graph(&root().join("core/src"));
    assert!(edges.contains_key("simulation") && edges["scene"].contains("simulation"));
    assert_eq!(cycle(&edges), None);
}

#[test]
fn the_checking_crate_has_no_module_cycle() {
    let edges = graph(&root().join("src"));
    // verify reads dumps through liggghts, and studies run cases through verify.
    assert!(edges["verify"].contains("liggghts") && edges["study"].contains("verify"));
    assert_eq!(cycle(&edges), None);
}

#[test]
fn the_core_does_not_depend_on_the_command_line() {
    let manifest = std::fs::read_to_string(root().join("core/Cargo.toml")).unwrap();
    assert!(!manifest.contains("clap"), "core/Cargo.toml names clap");
}

#[test]
fn the_cycle_finder_finds_a_cycle() {
    let text = "use crate::{b::X, c};\nfn f() { crate::a::g(); }\n// crate::d is a comment";
    let roots: Vec<String> = imported_roots(text).into_iter().collect();
    assert_eq!(roots, ["a", "b", "c"]);
    let mut edges = BTreeMap::new();
    edges.insert("a".to_string(), BTreeSet::from(["b".to_string()]));
    edges.insert("b".to_string(), BTreeSet::from(["c".to_string()]));
    edges.insert("c".to_string(), BTreeSet::from(["a".to_string()]));
    assert_eq!(cycle(&edges).unwrap(), ["a", "b", "c", "a"]);
    edges.insert("c".to_string(), BTreeSet::new());
    assert_eq!(cycle(&edges), None);
}
