//! Build script: stamps the build with the git commit it was built from, so that a binary or a
//! Python wheel that is out of step with the source can be told apart (`wearfem --version`,
//! `wearfem_version` in every summary.json, `wearfem.__version__`).
//!
//! `WEARFEM_VERSION` is the crate version, plus `+g<12 hex digits of the commit>` when the
//! source is a git checkout and `git` runs (PEP 440 local version and SemVer build metadata
//! alike). Without git, or outside a checkout (a source tarball), it is the crate version
//! alone: the build never fails for want of git. A build from a tree with uncommitted changes
//! to tracked files adds `.modified` (`0.1.0+g1a2b3c4d5e6f.modified`): such a build is not
//! the commit it names (red team C: a binary with a new warning was stamped as the commit
//! before it).

use std::path::{Path, PathBuf};
use std::process::Command;

fn git(dir: &Path, args: &[&str]) -> Option<String> {
    let out = Command::new("git")
        .args(args)
        .current_dir(dir)
        .output()
        .ok()?;
    let text = String::from_utf8(out.stdout).ok()?.trim().to_string();
    (out.status.success() && !text.is_empty()).then_some(text)
}

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let version = std::env::var("CARGO_PKG_VERSION").unwrap_or_default();
    let root = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").unwrap_or_default());
    let commit = git(&root, &["rev-parse", "--short=12", "HEAD"]);
    // Rebuild the stamp when HEAD moves: HEAD itself (a checkout, a detached HEAD) and the
    // branch it points to (a commit). Only files that exist are watched; a missing one would
    // make cargo rerun this script on every build.
    let absolute = |p: String| {
        let p = PathBuf::from(p);
        if p.is_absolute() {
            p
        } else {
            root.join(p)
        }
    };
    let mut watch: Vec<PathBuf> = Vec::new();
    if let Some(dir) = git(&root, &["rev-parse", "--git-dir"]).map(absolute) {
        watch.push(dir.join("HEAD"));
    }
    if let (Some(common), Some(branch)) = (
        git(&root, &["rev-parse", "--git-common-dir"]).map(absolute),
        git(&root, &["symbolic-ref", "-q", "HEAD"]),
    ) {
        watch.push(common.join(branch));
        watch.push(common.join("packed-refs"));
    }
    for path in watch.iter().filter(|p| p.exists()) {
        println!("cargo:rerun-if-changed={}", path.display());
    }
    // Any change to the sources may change whether the tree is modified.
    for path in ["src", "Cargo.toml", "python/src", "python/wearfem"] {
        if root.join(path).exists() {
            println!("cargo:rerun-if-changed={}", root.join(path).display());
        }
    }
    let modified = git(&root, &["status", "--porcelain", "--untracked-files=no"]).is_some();
    let stamp = match (commit, modified) {
        (Some(c), false) => format!("{version}+g{c}"),
        (Some(c), true) => format!("{version}+g{c}.modified"),
        (None, _) => version,
    };
    println!("cargo:rustc-env=WEARFEM_VERSION={stamp}");
}
