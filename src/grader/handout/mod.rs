//! `pbrlab handout DIR`: the student repository.
//!
//! The handout is this repository without the solutions and without anything that
//! reveals them ([`manifest`] decides what goes in), with its own README (the student
//! workflow) and a Cargo.toml whose default features leave the solutions out. Its exercise
//! files are the shipped stubs as committed ([`stubs::shipped`]), not whatever the
//! instructor's working copy holds. It builds, renders what the student has written, and
//! grades the public cases from the stored expected data. [`compiled_reference`] adds the
//! reference as a shared library, so mixed renders work there without its source.

pub mod compiled_reference;
pub mod manifest;
pub use pbrlab_course::stubs;

use crate::atomic_file::write as write_atomic;
use anyhow::{Context, bail};
use std::path::{Path, PathBuf};

/// The handout's README: the student workflow.
pub const README: &str = include_str!("README.md");

/// Writes the handout of the repository at `root` into `dest`, which must not exist or be
/// empty. Returns the files written, relative to `dest`.
pub fn write(root: &Path, dest: &Path) -> anyhow::Result<Vec<PathBuf>> {
    refuse_non_empty(dest)?;
    let root_abs = root
        .canonicalize()
        .with_context(|| format!("reading {}", root.display()))?;
    std::fs::create_dir_all(dest).with_context(|| format!("creating {}", dest.display()))?;
    let dest_abs = dest.canonicalize()?;
    let manifest = manifest::select(&root_abs)?;
    let mut written = Vec::new();
    for file in &manifest.files {
        let from = root_abs.join(file);
        if from.starts_with(&dest_abs) {
            continue;
        }
        let to = dest_abs.join(file);
        if let Some(dir) = to.parent() {
            std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
        }
        match committed_stub(&root_abs, file) {
            Some(stub) => write_atomic(&to, stub.as_bytes())?,
            None => {
                std::fs::copy(&from, &to).with_context(|| format!("copying {}", file.display()))?;
            }
        }
        written.push(file.clone());
    }
    // The stubs once more, where the grader and `reset` find them without git history.
    for task in crate::worksheet::TaskId::ALL {
        let name = PathBuf::from(stubs::SHIPPED).join(format!("{}.rs", task.name()));
        let stub = stubs::shipped(&root_abs, task)?;
        let to = dest_abs.join(&name);
        if let Some(dir) = to.parent() {
            std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
        }
        write_atomic(&to, stub.as_bytes())?;
        written.push(name);
    }
    write_atomic(&dest_abs.join("Cargo.toml"), manifest.cargo_toml.as_bytes())?;
    for (member, text) in &manifest.members {
        write_atomic(&dest_abs.join(member), text.as_bytes())?;
        written.push(member.clone());
    }
    write_atomic(&dest_abs.join("README.md"), README.as_bytes())?;
    prune_lock_file(&dest_abs)?;
    written.push("Cargo.toml".into());
    written.push("README.md".into());
    written.sort();
    Ok(written)
}

/// Brings the copied `Cargo.lock` in line with the handout's workspace (which lacks the
/// reference's crates), with the same versions of everything else, so that the student's
/// first build does not rewrite it: `cargo update --workspace` resolves offline against
/// the lock and changes only the workspace's own entries.
fn prune_lock_file(handout: &Path) -> anyhow::Result<()> {
    if !handout.join("Cargo.lock").is_file() {
        return Ok(());
    }
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let output = std::process::Command::new(&cargo)
        .current_dir(handout)
        .args(["update", "--workspace", "--offline", "--quiet"])
        .env_remove("CARGO_TARGET_DIR")
        .output()
        .with_context(|| format!("running {}", cargo.to_string_lossy()))?;
    if !output.status.success() {
        bail!(
            "updating the handout's Cargo.lock: {}",
            String::from_utf8_lossy(&output.stderr).trim()
        );
    }
    Ok(())
}

/// The committed stub when `file` is a task's exercise file (`exercises/<task>.rs`) and git
/// has it; `None` for every other file.
fn committed_stub(root: &Path, file: &Path) -> Option<String> {
    if file.parent() != Some(Path::new("exercises")) {
        return None;
    }
    let stem = file.file_stem()?.to_str()?;
    let task = crate::worksheet::TaskId::ALL
        .into_iter()
        .find(|t| t.name() == stem)?;
    stubs::shipped(root, task).ok()
}

/// Fails when `dir` exists and holds anything: a handout or a package is not written over
/// another folder's files.
pub fn refuse_non_empty(dir: &Path) -> anyhow::Result<()> {
    if dir.exists()
        && std::fs::read_dir(dir)
            .map(|mut d| d.next().is_some())
            .unwrap_or(true)
    {
        bail!("{} exists and is not empty", dir.display());
    }
    Ok(())
}
