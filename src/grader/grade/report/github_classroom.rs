//! GitHub Classroom's autograding: the result each test runner hands the grading reporter
//! (`classroom-resources/autograding-grading-reporter`), one runner per task. A runner's
//! result is JSON (`version`, `status`, `max_score`, `tests`: each with `name`, `status`,
//! `score`, `message`), base64-encoded, read by the reporter from the environment variable
//! `<RUNNER>_RESULTS`; the reporter adds the tests' scores of every runner and sends the
//! total, out of the sum of the runners' `max_score`, to GitHub Classroom.
//!
//! [`github_classroom`] writes one `TASK=BASE64` line per task, the step outputs the
//! package's workflow appends to `$GITHUB_OUTPUT` (`crate::autograder::github_classroom`).
//! A task's points are split over its checks by weight, each earning its weight times its
//! credit, as in the Gradescope report.

use super::text::details;
use crate::grade::verdict::{CheckResult, GradeReport, TaskOutcome, TaskStatus, total};
use base64::Engine;
use serde::{Deserialize, Serialize};

/// The result of one runner (one task), as the grading reporter reads it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RunnerResult {
    /// The format's version: 1.
    pub version: u32,
    /// `pass` when every test passed, `error` when the grader failed, else `fail`.
    pub status: String,
    /// The task's points.
    pub max_score: f64,
    /// One test per check, or one for the whole task when it has no checks to show (not
    /// attempted, did not compile, crashed).
    pub tests: Vec<Test>,
}

/// One test of a runner.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Test {
    /// The check's name, after the task's (`smith_g1: values`).
    pub name: String,
    /// `pass`, `fail` or `error`.
    pub status: String,
    /// The points it earned.
    pub score: f64,
    /// What was checked and what failed (at the report's feedback level).
    pub message: String,
}

/// The runner result of one task.
pub fn runner_result(task: &TaskOutcome) -> RunnerResult {
    let all = total(task.checks.iter().map(|c| c.weight));
    let scored = matches!(
        task.status,
        TaskStatus::Passed | TaskStatus::Partial | TaskStatus::Failed
    );
    let grader_failed = matches!(task.status, TaskStatus::GraderError { .. });
    let tests: Vec<Test> = if scored && all > 0.0 {
        task.checks
            .iter()
            .map(|c| check_test(task, c, task.max_points * c.weight / all))
            .collect()
    } else {
        let mut message = format!("{}.", task.status.label());
        let d = details(task);
        if !d.is_empty() {
            message += "\n";
            message += &d;
        }
        vec![Test {
            name: task.task.clone(),
            status: if grader_failed { "error" } else { "fail" }.into(),
            score: if scored { task.points } else { 0.0 },
            message,
        }]
    };
    let status = if grader_failed {
        "error"
    } else if tests.iter().all(|t| t.status == "pass") {
        "pass"
    } else {
        "fail"
    };
    RunnerResult {
        version: 1,
        status: status.into(),
        max_score: task.max_points,
        tests,
    }
}

/// The test of one check worth `share` of its task's points.
fn check_test(task: &TaskOutcome, check: &CheckResult, share: f64) -> Test {
    let mut message = check.summary.clone();
    // Already redacted to the course's feedback level (`super::redact`).
    for line in check
        .shrunk
        .iter()
        .map(|(full, _)| full)
        .chain(&check.failures)
    {
        message += "\n  ";
        message += line;
    }
    Test {
        name: format!("{}: {}", task.task, check.name),
        status: if check.passed { "pass" } else { "fail" }.into(),
        score: share * check.credit,
        message,
    }
}

/// The runner id of a report entry: the task's id (`smith_g1`), or a scene's render check
/// as `scene_cornell`. Letters, digits and `_` only: the reporter reads the result from the
/// environment variable `<ID>_RESULTS`, and the workflow from the step output `<id>`.
pub fn runner_id(entry: &str) -> String {
    let id: String = entry
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    id.split('_')
        .filter(|part| !part.is_empty())
        .collect::<Vec<_>>()
        .join("_")
}

/// The runner results of `report`, one `ID=BASE64` line per entry that has points, in the
/// report's order: the lines a workflow step appends to `$GITHUB_OUTPUT`.
pub fn github_classroom(report: &GradeReport) -> String {
    let engine = base64::engine::general_purpose::STANDARD;
    report
        .tasks
        .iter()
        .filter(|t| t.max_points > 0.0)
        .map(|t| {
            let json = serde_json::to_vec(&runner_result(t)).unwrap_or_default();
            format!("{}={}\n", runner_id(&t.task), engine.encode(json))
        })
        .collect()
}
