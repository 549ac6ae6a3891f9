//! The shipped stubs of the exercises, so that a student can go back to one
//! (`pbrlab reset TASK`) and the grader can build a stub in place of a file that does not
//! compile. The handout carries a copy of each in [`SHIPPED`] (a repository made from it on
//! GitHub Classroom has neither the handout's history nor its tags), and is a git
//! repository whose first commit, tagged [`TAG`], is the handout as written; in the
//! instructor repository, which has neither, the committed exercises are the stubs.

use crate::task::TaskId;
use crate::task_set::TaskSet;
use anyhow::{Context, bail};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The tag of the handout's first commit.
pub const TAG: &str = "pbrlab-stubs";

/// The handout's folder of shipped stubs, one `<task>.rs` each, as written.
pub const SHIPPED: &str = ".pbrlab-stubs";

/// Runs git in `dir` with `args` and a fixed identity (a student's machine may have none).
fn git(dir: &Path, args: &[&str]) -> anyhow::Result<Output> {
    let out = Command::new("git")
        .current_dir(dir)
        .args([
            "-c",
            "user.name=pbrlab",
            "-c",
            "user.email=pbrlab@localhost",
            "-c",
            "commit.gpgsign=false",
        ])
        .args(args)
        .output()
        .context("running git (is it installed?)")?;
    if !out.status.success() {
        bail!(
            "git {}: {}",
            args.join(" "),
            String::from_utf8_lossy(&out.stderr).trim()
        );
    }
    Ok(out)
}

/// Makes `dest` a git repository whose first commit, tagged [`TAG`], holds every file in
/// it (the handout just written).
pub fn commit(dest: &Path) -> anyhow::Result<()> {
    git(dest, &["init", "--quiet"])?;
    git(dest, &["add", "--all"])?;
    git(dest, &["commit", "--quiet", "-m", "The pbrlab handout"])?;
    git(dest, &["tag", TAG])?;
    Ok(())
}

/// The shipped stub of `task` in the repository at `root`: its copy in [`SHIPPED`], else
/// `exercises/<task>.rs` as committed at [`TAG`], or at `HEAD` where there is no tag.
pub fn shipped(root: &Path, task: TaskId) -> anyhow::Result<String> {
    let copy = root.join(SHIPPED).join(format!("{}.rs", task.name()));
    if copy.is_file() {
        return std::fs::read_to_string(&copy)
            .with_context(|| format!("reading the shipped stub {}", copy.display()));
    }
    let tagged = git(
        root,
        &[
            "rev-parse",
            "--quiet",
            "--verify",
            &format!("refs/tags/{TAG}"),
        ],
    );
    let rev = if tagged.is_ok() { TAG } else { "HEAD" };
    let file = format!("{rev}:exercises/{}.rs", task.name());
    let out = git(root, &["show", &file])
        .with_context(|| format!("finding the shipped exercises/{}.rs", task.name()))?;
    String::from_utf8(out.stdout).context("the shipped stub is not UTF-8")
}

/// `exercises/<task>.rs` in the repository at `root`.
fn exercise_file(root: &Path, task: TaskId) -> PathBuf {
    root.join("exercises").join(format!("{}.rs", task.name()))
}

/// Whether `exercises/<task>.rs` in the repository at `root` is still the shipped stub;
/// `None` where that cannot be told (no git, no repository, no file).
pub fn unchanged(root: &Path, task: TaskId) -> Option<bool> {
    let stub = shipped(root, task).ok()?;
    let current = std::fs::read_to_string(exercise_file(root, task)).ok()?;
    Some(current == stub)
}

/// The tasks whose `exercises/<task>.rs` in the repository at `root` is no longer the
/// shipped stub (or cannot be compared with it): what the student has started, told from
/// the files alone, so that a command that shows it runs no student code and builds
/// nothing.
pub fn edited(root: &Path) -> TaskSet {
    TaskId::ALL
        .into_iter()
        .filter(|&task| unchanged(root, task) != Some(true))
        .collect()
}

/// Puts the shipped stub of `task` back in `root`'s `exercises/`, after copying the
/// student's version into the folder `keep`. Returns where that copy went, or `None` when
/// the file already was the stub.
pub fn reset(root: &Path, task: TaskId, keep: &Path) -> anyhow::Result<Option<PathBuf>> {
    let stub = shipped(root, task)?;
    let file = exercise_file(root, task);
    let current = std::fs::read_to_string(&file).unwrap_or_default();
    if current == stub {
        return Ok(None);
    }
    let kept = crate::timestamp::unused(keep, &format!("{}-", task.name()), ".rs");
    crate::atomic_file::write(&kept, current.as_bytes())?;
    crate::atomic_file::write(&file, stub.as_bytes())?;
    Ok(Some(kept))
}

/// Undoes the last [`reset`] of `task`: puts back the version it kept in `keep` (the newest
/// `<task>-<time>.rs` there) and removes it from `keep`, so a second undo goes one reset
/// further back. The file it replaces is kept in turn (as `undone-<task>-<time>.rs`) unless
/// it is the shipped stub: work done since the reset is not lost. Returns the version put back, or `None` when `keep`
/// holds none of `task`.
pub fn undo_reset(root: &Path, task: TaskId, keep: &Path) -> anyhow::Result<Option<PathBuf>> {
    let prefix = format!("{}-", task.name());
    let mut kept: Vec<PathBuf> = std::fs::read_dir(keep)
        .into_iter()
        .flatten()
        .flatten()
        .map(|e| e.path())
        .filter(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with(&prefix) && n.ends_with(".rs"))
        })
        .collect();
    // The newest last: by when each was written, then by name (`-2` after the same second's
    // first).
    kept.sort_by_key(|p| {
        let written = std::fs::metadata(p).and_then(|m| m.modified()).ok();
        (written, p.clone())
    });
    let Some(newest) = kept.pop() else {
        return Ok(None);
    };
    let version = std::fs::read_to_string(&newest)
        .with_context(|| format!("reading {}", newest.display()))?;
    let file = exercise_file(root, task);
    let current = std::fs::read_to_string(&file).unwrap_or_default();
    if current != shipped(root, task)? && current != version {
        let aside = crate::timestamp::unused(keep, &format!("undone-{}-", task.name()), ".rs");
        crate::atomic_file::write(&aside, current.as_bytes())?;
    }
    crate::atomic_file::write(&file, version.as_bytes())?;
    std::fs::remove_file(&newest).with_context(|| format!("removing {}", newest.display()))?;
    Ok(Some(newest))
}
