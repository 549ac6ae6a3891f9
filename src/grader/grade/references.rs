//! The grader's half of keeping the reference out of reach: which shared library holds the
//! reference of each task a worker takes from the reference ([`super::worker::Delivery`]).
//!
//! A worker runs student code, and a soundness hole in the compiler lets safe code read and
//! call anything in its process, so the worker links no reference. In the instructor's
//! build each task's reference is a library of its own, an example of
//! `tools/reference-library/` built with cargo the first time a process needs one (a no-op
//! when it is fresh); a job gets the libraries of the tasks it does not take from the
//! student, never the graded task's (`tests/instructor/hostile.rs` checks the files). The
//! student handout has only the whole compiled reference ([`crate::compiled_reference`]),
//! which the student's own worker may load: there the student grades their own code.

use super::worker::ImplSpec;
use crate::worksheet::TaskId;
use anyhow::{Context, anyhow, bail, ensure};
use pbrlab_course::selection::FRAMEWORK_SELECTION;
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::process::Command;
use std::sync::OnceLock;

/// The library of each task `spec` takes from the reference, by task name: empty when the
/// student's code runs every task.
pub fn for_spec(spec: &ImplSpec) -> anyhow::Result<BTreeMap<String, PathBuf>> {
    let student = spec.student_tasks();
    let reference: Vec<TaskId> = TaskId::ALL
        .into_iter()
        .filter(|t| !student.contains(*t))
        .collect();
    if reference.is_empty() {
        return Ok(BTreeMap::new());
    }
    if !cfg!(feature = "solutions") {
        // The handout: the whole compiled reference when this build can use it.
        let whole = crate::compiled_reference::path_in(crate::repository_root());
        return Ok(match crate::implementation::try_reference() {
            Some(_) => reference
                .into_iter()
                .map(|t| (t.name().to_string(), whole.clone()))
                .collect(),
            None => BTreeMap::new(),
        });
    }
    let libraries = task_libraries().as_ref().map_err(|e| anyhow!("{e}"))?;
    reference
        .into_iter()
        .map(|t| {
            let path = libraries
                .get(&t)
                .with_context(|| format!("no reference library of `{}` was built", t.name()))?;
            Ok((t.name().to_string(), path.clone()))
        })
        .collect()
}

/// The packages every build of the reference's libraries selects (the one-task libraries
/// here, the handout's whole compiled reference): `pbrlab-reference` in the framework's
/// selection ([`FRAMEWORK_SELECTION`]), so that features resolve as in the instructor's own
/// build and the libraries link the framework its binaries link (one compilation of it).
pub fn selection() -> Vec<&'static str> {
    let reference = ["-p", "pbrlab-reference"];
    FRAMEWORK_SELECTION
        .iter()
        .copied()
        .chain(reference)
        .collect()
}

/// The arguments of `cargo` that build the one-task libraries (add `--release` for the
/// release profile): [`selection`], every example, and without the dependencies' debug
/// information (1 MB each instead of 58 MB). The autograder packages' set-up runs the same
/// command.
pub fn cargo_args() -> Vec<&'static str> {
    let mut args = vec!["build", "--locked"];
    args.extend(selection());
    args.extend([
        "--examples",
        "--config",
        "profile.release.package.pbrlab-reference.strip=\"debuginfo\"",
    ]);
    args
}

/// [`cargo_args`] with `--release`, as one shell command line.
pub fn shell_command() -> String {
    let quoted: Vec<String> = cargo_args()
        .iter()
        .map(|a| {
            if a.contains('"') {
                format!("'{a}'")
            } else {
                a.to_string()
            }
        })
        .collect();
    format!("cargo {} --release", quoted.join(" "))
}

/// The one-task reference libraries, built once per process.
fn task_libraries() -> &'static Result<BTreeMap<TaskId, PathBuf>, String> {
    static LIBRARIES: OnceLock<Result<BTreeMap<TaskId, PathBuf>, String>> = OnceLock::new();
    LIBRARIES.get_or_init(|| build().map_err(|e| format!("{e:#}")))
}

/// Builds the examples of `tools/reference-library/` with the cargo that built this
/// program (`$CARGO`, else `cargo`), in the profile and with the framework features of this
/// build, so they link the framework this build's worker links (the loader checks that),
/// and returns each task's file as cargo reports it.
fn build() -> anyhow::Result<BTreeMap<TaskId, PathBuf>> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut command = Command::new(&cargo);
    command
        .current_dir(crate::repository_root())
        .args(cargo_args())
        .args(["--offline", "--message-format=json"]);
    if !cfg!(debug_assertions) {
        command.arg("--release");
    }
    // Whatever the grader's environment says about the exercises does not matter here.
    command.env_remove("PBRLAB_EXERCISES");
    let output = command
        .output()
        .with_context(|| format!("running {}", cargo.to_string_lossy()))?;
    if !output.status.success() {
        bail!(
            "building the reference libraries (tools/reference-library/) failed: {}\n{}",
            output.status,
            String::from_utf8_lossy(&output.stderr)
        );
    }
    let mut libraries = BTreeMap::new();
    for line in String::from_utf8_lossy(&output.stdout).lines() {
        let Ok(message) = serde_json::from_str::<serde_json::Value>(line) else {
            continue;
        };
        if message["reason"] != "compiler-artifact" {
            continue;
        }
        let name = message["target"]["name"].as_str().unwrap_or_default();
        let Some(task) = name
            .strip_prefix(crate::compiled_reference::TASK_LIBRARY_PREFIX)
            .and_then(|t| TaskId::parse(t).ok())
        else {
            continue;
        };
        let file = message["filenames"][0]
            .as_str()
            .with_context(|| format!("cargo named no file for {name}"))?;
        libraries.insert(task, PathBuf::from(file));
    }
    let missing: Vec<&str> = TaskId::ALL
        .iter()
        .filter(|t| !libraries.contains_key(t))
        .map(|t| t.name())
        .collect();
    ensure!(
        missing.is_empty(),
        "tools/reference-library/ has no library of {}",
        missing.join(", ")
    );
    Ok(libraries)
}
