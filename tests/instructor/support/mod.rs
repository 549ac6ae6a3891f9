//! Implementations for grading the grader: the reference with functions replaced.
#![allow(dead_code)]

pub mod patch;
pub mod variants;
pub mod warps;

use pbrlab::grade::checks::{TaskInput, grade_task, score};
use pbrlab::grade::runner::{GradeOptions, prepare};
use pbrlab::grade::verdict::{CheckResult, TaskOutcome, TaskStatus};
use pbrlab::worksheet::{TaskId, Tasks};
use std::collections::BTreeMap;

/// Makes the shipped exercises and the reference the framework's student and reference
/// implementations in this test process, as the `pbrlab` binary does at start.
pub fn install() {
    pbrlab::implementation::install(pbrlab::implementation::Implementations {
        student: Some(pbrlab_exercises::TASKS),
        reference: Some(pbrlab_solutions::TASKS),
        reference_render: None,
    });
}

/// `pbrlab-commands`, the binary beside the `pbrlab` these tests run that every command but
/// `tasks`, `hint` and `reset` runs in (it links the reference), current: `pbrlab` builds it
/// when it is not, here on its first `--version`.
pub fn commands() -> std::path::PathBuf {
    static CURRENT: std::sync::OnceLock<std::path::PathBuf> = std::sync::OnceLock::new();
    CURRENT
        .get_or_init(|| {
            let pbrlab = std::path::Path::new(env!("CARGO_BIN_EXE_pbrlab"));
            let out = std::process::Command::new(pbrlab)
                .arg("--version")
                .output()
                .expect("pbrlab runs");
            assert!(out.status.success(), "pbrlab --version: {out:?}");
            pbrlab.with_file_name("pbrlab-commands")
        })
        .clone()
}

/// The worker binary that runs the student's code, beside the `pbrlab` these tests run
/// (built by the first test that asks, as `pbrlab` builds it before running student code).
pub fn worker() -> std::path::PathBuf {
    let built = pbrlab::cli::rebuild::ensure_student_binaries_beside(&commands())
        .expect("building pbrlab-worker");
    built.worker
}

/// The inputs of every task (stored data, no hidden cases) for statistical seed `seed`
/// (installs the implementations first: hidden cases and estimators use the reference).
pub fn inputs(seed: u64) -> BTreeMap<TaskId, TaskInput> {
    install();
    prepare(&GradeOptions {
        seed,
        ..GradeOptions::default()
    })
    .expect("stored expected data loads")
}

/// Grades `task` in this process.
pub fn grade(
    t: &impl Tasks,
    task: TaskId,
    input: &TaskInput,
) -> (TaskStatus, f64, Vec<CheckResult>) {
    let checks = grade_task(t, task, input);
    let (status, points) = score(task, &checks);
    (status, points, checks)
}

/// `task`'s outcome in a report, from what [`grade`] returned.
pub fn outcome(
    task: TaskId,
    (status, points, checks): (TaskStatus, f64, Vec<CheckResult>),
) -> TaskOutcome {
    TaskOutcome {
        task: task.name().into(),
        status,
        points,
        max_points: task.info().points as f64,
        checks,
        output: String::new(),
        seconds: 0.0,
    }
}

/// Tasks that have checks.
pub fn graded_tasks(inputs: &BTreeMap<TaskId, TaskInput>) -> Vec<TaskId> {
    inputs
        .iter()
        .filter(|(task, input)| pbrlab::grade::runner::task_has_checks(**task, input))
        .map(|(task, _)| *task)
        .collect()
}

/// The failure messages of `checks`, one per line.
pub fn messages(checks: &[CheckResult]) -> String {
    checks
        .iter()
        .filter(|c| !c.passed)
        .map(|c| format!("{}: {} {:?}", c.name, c.summary, c.failures))
        .collect::<Vec<_>>()
        .join("\n")
}

/// What a pseudo-terminal printed, as rexpect hands it over (a char per byte), read back as
/// the UTF-8 the program wrote: `…` is one column, not three.
pub fn pty_text(read: &str) -> String {
    let bytes: Vec<u8> = read.chars().map(|c| c as u32 as u8).collect();
    String::from_utf8_lossy(&bytes).into_owned()
}
