//! The student's tests: `cargo test --release` grades each task of `exercises/` with the
//! course's grader (`pbrlab grade`, the same sandboxed worker and messages) and reports one
//! test per task, named by the task, so `cargo test --release smith_g1` grades one.
//!
//! A task still the shipped `todo!()` stub is an ignored test (`[not attempted]`), as in
//! Exercism's Rust track, where the tests of what is not started yet are `#[ignore]`d: a
//! fresh handout's `cargo test` is green and says what is left, and nothing is called done
//! that is not. A task that waits for another (without the reference, the tasks it builds
//! on are the student's own) is ignored too, naming that task. An attempted task passes when
//! every check passes; otherwise it fails with the grader's report of that task. Render
//! checks are left out (a render takes minutes): `cargo run --release -- grade` runs them.
//!
//! libtest-mimic gives the test binary libtest's command line and output, so filters,
//! `--list`, `--ignored` and test runners that read them work as with `#[test]`s.
//!
//! It links the course's table alone (`pbrlab-course`), not the grader: the grader is
//! `pbrlab`'s, built once, and this test compiles in seconds and never links the student's
//! crate (one exercise that does not compile cannot stop it).

use libtest_mimic::{Arguments, Failed, Trial};
use pbrlab_course::status::TaskStatus;
use pbrlab_course::task::TaskId;
use std::process::{Command, ExitCode};

/// What this test reads of the grader's JSON report: each task's name and how it ended.
#[derive(serde::Deserialize)]
struct GradeReport {
    tasks: Vec<TaskOutcome>,
}

/// One task of [`GradeReport`].
#[derive(serde::Deserialize)]
struct TaskOutcome {
    task: String,
    status: TaskStatus,
}

fn main() -> ExitCode {
    let args = Arguments::from_args();
    let tasks = TaskId::ALL;
    let chosen: Vec<TaskId> = tasks
        .iter()
        .copied()
        .filter(|t| selected(&args, t.name()))
        .collect();
    // `--list` (and a filter that selects nothing) grades nothing.
    let graded = if args.list || chosen.is_empty() {
        Ok(None)
    } else {
        grade(&chosen).map(Some)
    };
    // Every task is a trial, so that libtest counts those a filter leaves out.
    let trials = tasks
        .iter()
        .map(|&task| match &graded {
            Ok(Some(report)) if chosen.contains(&task) => trial(task, Ok(report)),
            Err(why) if chosen.contains(&task) => trial(task, Err(why)),
            // Filtered out by libtest-mimic as well, or only listed: never run.
            _ => Trial::test(task.name(), || Ok(())),
        })
        .collect::<Vec<_>>();
    let conclusion = libtest_mimic::run(&args, trials);
    if let Ok(Some(report)) = &graded {
        println!("{}", summary(report));
    }
    conclusion.exit_code()
}

/// True when libtest's filters select the test `name` (libtest-mimic applies them again to
/// the trials; this only spares grading what would not be shown).
fn selected(args: &Arguments, name: &str) -> bool {
    let matches = |pattern: &str| {
        if args.exact {
            name == pattern
        } else {
            name.contains(pattern)
        }
    };
    args.filter.as_deref().is_none_or(matches) && !args.skip.iter().any(|s| matches(s))
}

/// `pbrlab grade` of `tasks`, without the render checks, in `format` (with `--verbose`, every
/// line of what failed): its standard output, or why there is none. Its progress (a build
/// of the grader or the worker among it) goes to the terminal as it happens.
fn pbrlab_grade(tasks: &[&str], format: &str) -> Result<Vec<u8>, String> {
    let output = Command::new(env!("CARGO_BIN_EXE_pbrlab"))
        .arg("grade")
        .args(tasks)
        .args(["--format", format, "--no-renders", "--verbose"])
        .stderr(std::process::Stdio::inherit())
        .output()
        .map_err(|e| format!("could not start pbrlab: {e}"))?;
    if !output.status.success() {
        return Err(format!(
            "`cargo run --release -- grade` failed ({}): its messages are above",
            output.status
        ));
    }
    Ok(output.stdout)
}

/// The grader's report of `tasks` (JSON from `pbrlab grade`), or why there is none.
fn grade(tasks: &[TaskId]) -> Result<GradeReport, String> {
    let names: Vec<&str> = tasks.iter().map(|t| t.name()).collect();
    let json = pbrlab_grade(&names, "json")?;
    serde_json::from_slice(&json).map_err(|e| format!("the grader's report could not be read: {e}"))
}

/// The test of `task`, from the grade, which graded it, or why there is none.
fn trial(task: TaskId, graded: Result<&GradeReport, &String>) -> Trial {
    let name = task.name();
    let report = match graded {
        Ok(report) => report,
        Err(why) => {
            let why = why.clone();
            return Trial::test(name, move || Err(Failed::from(why)));
        }
    };
    let Some(outcome) = report.tasks.iter().find(|t| t.task == name) else {
        return Trial::test(name, move || {
            Err(Failed::from(format!("the grader's report has no {name}")))
        });
    };
    let not_yet = |kind: String, step: String| {
        Trial::test(name, move || Err(Failed::from(step)))
            .with_kind(kind)
            .with_ignored_flag(true)
    };
    match &outcome.status {
        TaskStatus::Passed => Trial::test(name, || Ok(())),
        TaskStatus::NotAttempted => not_yet(
            "not attempted".into(),
            format!("not attempted: write exercises/{name}.rs, then `cargo test --release {name}`"),
        ),
        TaskStatus::NeedsTask { task } => not_yet(
            format!("needs {task}"),
            format!("{name} builds on {task}: write exercises/{task}.rs first"),
        ),
        TaskStatus::NoChecks => not_yet("no checks".into(), format!("{name} has no checks")),
        _ => {
            // The grader's text report of the task alone, every line of what failed (graded
            // again: the same seeds, so the same verdict).
            let message = pbrlab_grade(&[name], "text")
                .map(|text| String::from_utf8_lossy(&text).into_owned())
                .unwrap_or_else(|why| why);
            Trial::test(name, move || Err(Failed::from(message)))
        }
    }
}

/// True for a task that was graded and did not pass (failed, partly passed, crashed, did
/// not compile, or the grader failed on it).
fn fails(status: &TaskStatus) -> bool {
    !matches!(status, TaskStatus::Passed | TaskStatus::NoChecks) && !waits(status)
}

/// True for a task not attempted yet, or waiting for one that is not.
fn waits(status: &TaskStatus) -> bool {
    matches!(
        status,
        TaskStatus::NotAttempted | TaskStatus::NeedsTask { .. }
    )
}

/// One line after the tests: how many tasks pass, and the next step (the first task that
/// fails, else the first not written yet).
fn summary(report: &GradeReport) -> String {
    let tasks = &report.tasks;
    let count = |f: fn(&TaskStatus) -> bool| tasks.iter().filter(|t| f(&t.status)).count();
    let first = |f: fn(&TaskStatus) -> bool| tasks.iter().find(|t| f(&t.status));
    let next = if let Some(t) = first(fails) {
        format!("next: {}, whose report is above", t.task)
    } else if let Some(t) = first(waits) {
        let task = match &t.status {
            TaskStatus::NeedsTask { task } => task,
            _ => &t.task,
        };
        format!("next: exercises/{task}.rs (`cargo run --release -- hint {task}` when stuck)")
    } else {
        "`cargo run --release -- grade` adds the render checks".to_string()
    };
    format!(
        "pbrlab: {} of {} tasks pass, {} fail, {} not attempted; {next}",
        count(|s| *s == TaskStatus::Passed),
        tasks.len(),
        count(fails),
        count(waits),
    )
}
