//! The direction of data, checked. Cargo already forbids the core crate (`core/`) to
//! import the checking crate (`src/`), because a crate cannot depend on its dependent.
//! Within each crate nothing forbids two top-level modules importing each other; this
//! test does. It reads every `crate::…` path in the code (comments aside, test modules
//! included), draws an edge from the importing top-level module to the imported one, and
//! fails naming a cycle if there is one.
//!
//! The map of the modules, checked too: the module map of docs/architecture.md names
//! every source file of both crates, and every file it names exists, so a file added,
//! renamed or deleted without its entry fails here rather than leaving the map stale.

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

/// Each crate's source files as the module map writes them: paths below the crate's
/// `src/`, separated by `/`.
fn crate_files(src: &Path) -> BTreeSet<String> {
    let mut files = Vec::new();
    collect_rs(src, &mut files);
    files
        .iter()
        .map(|file| {
            let relative = file.strip_prefix(src).unwrap().components();
            let parts: Vec<_> = relative.map(|c| c.as_os_str().to_string_lossy()).collect();
            parts.join("/")
        })
        .collect()
}

/// One row of the module map. The first cell names the module by its files
/// (`scene/walls.rs`, or a brace list, `detect/{brute,cells}.rs`) or by a whole
/// directory (`verify/`); either cell may name more files in backticks. A file name is
/// written below a crate's `src/` or, shorter, below the directory of the row's module
/// or one of its ancestors: in the `accuracy/` row `model.rs` is `accuracy/model.rs`,
/// in the `boundary/shape/{…}.rs` row `shape/mod.rs` is `boundary/shape/mod.rs`.
struct Row {
    /// The first cell as written, to point at the row in messages.
    module: String,
    /// Directories the first cell names whole, each ending in `/`.
    directories: Vec<String>,
    /// Each `*.rs` name in the row, with every path it can stand for.
    files: Vec<(String, Vec<String>)>,
}

/// The rows of the table under the `## Module map` heading.
fn module_map(doc: &str) -> Vec<Row> {
    let section = doc
        .lines()
        .skip_while(|l| *l != "## Module map")
        .skip(1)
        .take_while(|l| !l.starts_with("## "));
    // The first two lines of the table are its header and the separator.
    let lines = section.filter(|l| l.starts_with('|')).skip(2);
    lines.map(row).collect()
}

fn row(line: &str) -> Row {
    let inner = line.trim().trim_start_matches('|').trim_end_matches('|');
    let cells: Vec<&str> = inner.split('|').collect();
    assert_eq!(cells.len(), 2, "a module map row without two cells: {line}");
    let code_names = |cell: &str| -> Vec<String> {
        let code_spans = cell.split('`').skip(1).step_by(2);
        code_spans.flat_map(expand_braces).collect()
    };
    let module = code_names(cells[0]);
    let homes: Vec<&str> = module
        .iter()
        .map(|name| match name.rfind('/') {
            Some(at) => &name[..=at],
            None => "",
        })
        .collect();
    let directories = module
        .iter()
        .filter(|n| n.ends_with('/'))
        .cloned()
        .collect();
    let files = [code_names(cells[0]), code_names(cells[1])]
        .concat()
        .into_iter()
        .filter(|n| n.ends_with(".rs") && !n.contains(char::is_whitespace))
        .map(|name| {
            let paths = homes
                .iter()
                .flat_map(|home| ancestors(home))
                .map(|dir| format!("{dir}{name}"))
                .collect();
            (name, paths)
        })
        .collect();
    Row {
        module: cells[0].trim().to_string(),
        directories,
        files,
    }
}

/// `a/{b,c}.rs` as `a/b.rs` and `a/c.rs`, the shell's brace expansion.
fn expand_braces(name: &str) -> Vec<String> {
    match (name.find('{'), name.find('}')) {
        (Some(open), Some(close)) if open < close => name[open + 1..close]
            .split(',')
            .flat_map(|alternative| {
                expand_braces(&format!(
                    "{}{alternative}{}",
                    &name[..open],
                    &name[close + 1..]
                ))
            })
            .collect(),
        _ => vec![name.to_string()],
    }
}

/// A directory written `a/b/` and those above it, down to the crate's `src/` itself,
/// written as the empty path: `a/b/`, `a/`, ``.
fn ancestors(dir: &str) -> Vec<String> {
    let mut all = vec![dir.to_string()];
    let mut rest = dir.trim_end_matches('/');
    while !rest.is_empty() {
        rest = rest.rfind('/').map_or("", |at| &rest[..at]);
        all.push(if rest.is_empty() {
            String::new()
        } else {
            format!("{rest}/")
        });
    }
    all
}

/// Whether the map names the file at `path`, by one of its names or by its directory.
fn names(map: &[Row], path: &str) -> bool {
    map.iter().any(|row| {
        row.files
            .iter()
            .any(|(_, paths)| paths.iter().any(|p| p == path))
            || row.directories.iter().any(|d| path.starts_with(d.as_str()))
    })
}

fn read_module_map() -> Vec<Row> {
    let doc = std::fs::read_to_string(root().join("docs/architecture.md")).unwrap();
    let map = module_map(&doc);
    assert!(
        map.len() > 20,
        "docs/architecture.md has no module map the test can read"
    );
    map
}

#[test]
fn the_module_map_names_every_source_file() {
    let map = read_module_map();
    let tamp = crate_files(&root().join("src"));
    let core = crate_files(&root().join("core/src"));
    // A path of the map does not say its crate (the "(tamp)" marks are for the
    // reader), so it names one file only while the crates share no path. The crate
    // roots, `lib.rs`, are the Crates section's to describe, not the map's.
    let in_both: Vec<_> = tamp
        .intersection(&core)
        .filter(|p| *p != "lib.rs")
        .collect();
    assert!(
        in_both.is_empty(),
        "both crates have {in_both:?}: the module map cannot tell them apart"
    );
    let missing: Vec<String> = [("src", &tamp), ("core/src", &core)]
        .into_iter()
        .flat_map(|(src, files)| {
            files
                .iter()
                .filter(|path| *path != "lib.rs" && !names(&map, path))
                .map(move |path| format!("{src}/{path}"))
        })
        .collect();
    assert!(
        missing.is_empty(),
        "the module map of docs/architecture.md does not name these files; add each to \
         the row of its module, with a few words on what it holds:\n  {}",
        missing.join("\n  ")
    );
}

#[test]
fn every_file_the_module_map_names_exists() {
    let map = read_module_map();
    let crates = [root().join("src"), root().join("core/src")];
    let exists = |path: &str| crates.iter().any(|src| src.join(path).exists());
    let mut stale = Vec::new();
    for row in &map {
        for (name, paths) in &row.files {
            if !paths.iter().any(|p| exists(p)) {
                stale.push(format!("`{name}` in the row {}", row.module));
            }
        }
        for directory in &row.directories {
            if !exists(directory) {
                stale.push(format!("`{directory}` in the row {}", row.module));
            }
        }
    }
    assert!(
        stale.is_empty(),
        "the module map of docs/architecture.md names paths that do not exist; rename or \
         remove them:\n  {}",
        stale.join("\n  ")
    );
}

#[test]
fn the_module_map_reader_resolves_names_as_the_map_writes_them() {
    let doc = "## Module map\n| module | owns |\n|---|---|\n\
               | `a/{b,c}.rs` | `d.rs` and `e/f.rs`; `Scene`, `tamp run` |\n\
               | `v/` (tamp) | cases (`w/mod.rs`) |\n\
               ## Decisions\n| `z.rs` | no row of the map |\n";
    let map = module_map(doc);
    assert_eq!(map.len(), 2);
    assert_eq!(map[1].module, "`v/` (tamp)");
    for path in [
        "a/b.rs",
        "a/c.rs",
        "a/d.rs",
        "a/e/f.rs",
        "e/f.rs",
        "v/w/mod.rs",
        "v/x.rs",
    ] {
        assert!(names(&map, path), "{path}");
    }
    for path in ["b.rs", "a/b/d.rs", "z.rs", "w/x.rs"] {
        assert!(!names(&map, path), "{path}");
    }
}
