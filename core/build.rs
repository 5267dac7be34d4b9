//! Records the git commit tamp was built from, for the provenance block of every output,
//! and the git objects of the code that decides results (`core/`, `src/`, `Cargo.lock`),
//! so work saved by one build can be recognised by another build of the same code. Git
//! runs at the repository's top (this crate's parent directory), so that paths name the
//! same trees whichever crate is being built.
use std::path::{Path, PathBuf};
use std::process::Command;

fn git(top: &Path) -> Command {
    let mut command = Command::new("git");
    command.current_dir(top);
    command
}

fn main() {
    let top = PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets it"))
        .parent()
        .expect("core/ lies inside the repository")
        .to_path_buf();
    let commit = git(&top)
        .args(["rev-parse", "HEAD"])
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
        .unwrap_or_else(|| "unknown".to_string());
    // --no-optional-locks: a plain `git status` may refresh and rewrite .git/index,
    // which this script watches, so the next cargo command would rebuild tamp again.
    let dirty = git(&top)
        .args([
            "--no-optional-locks",
            "status",
            "--porcelain",
            "--untracked-files=no",
        ])
        .output()
        .ok()
        .map(|o| !o.stdout.is_empty())
        .unwrap_or(false);
    let commit = if dirty && commit != "unknown" {
        format!("{commit}-dirty")
    } else {
        commit
    };
    println!("cargo:rustc-env=TAMP_GIT_COMMIT={commit}");
    let source = git(&top)
        .args(["rev-parse", "HEAD:core", "HEAD:src", "HEAD:Cargo.lock"])
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| {
            String::from_utf8_lossy(&o.stdout)
                .split_whitespace()
                .collect::<Vec<_>>()
                .join("+")
        })
        .unwrap_or_else(|| "unknown".to_string());
    let source_dirty = git(&top)
        .args([
            "--no-optional-locks",
            "status",
            "--porcelain",
            "--",
            "core",
            "src",
            "Cargo.lock",
            "Cargo.toml",
        ])
        .output()
        .ok()
        .map(|o| !o.stdout.is_empty())
        .unwrap_or(true);
    let source = if source_dirty {
        format!("{source}-dirty")
    } else {
        source
    };
    println!("cargo:rustc-env=TAMP_SOURCE_TREE={source}");
    // Ask git where HEAD and the index are: in a worktree `.git` is a file, and a
    // path that does not exist would make cargo rebuild tamp on every command.
    let git_dir = git(&top)
        .args(["rev-parse", "--absolute-git-dir"])
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| std::path::PathBuf::from(String::from_utf8_lossy(&o.stdout).trim()));
    println!("cargo:rerun-if-changed=build.rs");
    // The code's own files too: an edit leaves HEAD and the index as they were, and the
    // stamp of a build from edited code must say `-dirty`.
    for path in [
        "core/src",
        "core/Cargo.toml",
        "src",
        "Cargo.toml",
        "Cargo.lock",
    ] {
        println!("cargo:rerun-if-changed={}", top.join(path).display());
    }
    if let Some(dir) = git_dir {
        for name in ["HEAD", "index"] {
            let path = dir.join(name);
            if path.exists() {
                println!("cargo:rerun-if-changed={}", path.display());
            }
        }
    }
}
