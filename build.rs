//! Records the git commit tamp was built from, for the provenance block of every output,
//! and the git objects of the code that decides results (`src/`, `Cargo.lock`), so work
//! saved by one build can be recognised by another build of the same code.
use std::process::Command;

fn main() {
    let commit = Command::new("git")
        .args(["rev-parse", "HEAD"])
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
        .unwrap_or_else(|| "unknown".to_string());
    // --no-optional-locks: a plain `git status` may refresh and rewrite .git/index,
    // which this script watches, so the next cargo command would rebuild tamp again.
    let dirty = Command::new("git")
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
    let source = Command::new("git")
        .args(["rev-parse", "HEAD:src", "HEAD:Cargo.lock"])
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
    let source_dirty = Command::new("git")
        .args([
            "--no-optional-locks",
            "status",
            "--porcelain",
            "--",
            "src",
            "Cargo.lock",
            "Cargo.toml",
            "build.rs",
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
    let git_dir = Command::new("git")
        .args(["rev-parse", "--git-dir"])
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| std::path::PathBuf::from(String::from_utf8_lossy(&o.stdout).trim()));
    println!("cargo:rerun-if-changed=build.rs");
    if let Some(dir) = git_dir {
        for name in ["HEAD", "index"] {
            let path = dir.join(name);
            if path.exists() {
                println!("cargo:rerun-if-changed={}", path.display());
            }
        }
    }
}
