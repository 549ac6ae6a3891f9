//! What grading produces: one result per check, one outcome per task, one report per run.
//! All of it is serialisable: a worker sends its checks to the grader as JSON, and the
//! report is stored for `pbrlab tasks` and written for Gradescope.

use super::tolerance::Error;
use crate::panics::Panic;
pub use pbrlab_course::status::TaskStatus;
use serde::{Deserialize, Serialize};

/// The kinds of check (DESIGN.md §4).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CheckKind {
    /// Fixed and random cases against the reference's outputs.
    Values,
    /// Pearson χ² of the student's samples against the reference density.
    Sampling,
    /// Student's t-test of an estimator against an analytic value.
    Estimator,
    /// Per-pixel z-test of a render against a reference image.
    Image,
    /// Extreme inputs: finite, in range, right limit.
    Stability,
}

impl CheckKind {
    /// The kind's name in reports.
    pub fn name(self) -> &'static str {
        match self {
            CheckKind::Values => "values",
            CheckKind::Sampling => "sampling",
            CheckKind::Estimator => "estimator",
            CheckKind::Image => "image",
            CheckKind::Stability => "stability",
        }
    }
}

/// Who may see a check's result (Gradescope's `visibility`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Visibility {
    /// Shown to the student at once.
    #[default]
    Visible,
    /// Shown only to the instructor: the hidden cases of `--hidden-seed`.
    Hidden,
}

/// The result of one check of one task.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CheckResult {
    /// What was checked, e.g. `values` or `sampling: ndf_sample wo=30° α=0.3`.
    pub name: String,
    /// The kind of check.
    pub kind: CheckKind,
    /// Who may see it.
    pub visibility: Visibility,
    /// Whether it passed.
    pub passed: bool,
    /// The fraction of its share of the points it earned, in [0, 1]: 1 when it passed,
    /// else as the course's credit policy gives ([`super::credit::Credit`]).
    #[serde(default)]
    pub credit: f64,
    /// Its share of the task's points, relative to the task's other checks.
    pub weight: f64,
    /// One line: what was measured and the verdict.
    pub summary: String,
    /// Failing cases, each naming its input (at most [`MAX_MESSAGES`]).
    pub failures: Vec<String>,
    /// The same failing cases with nothing of the expected answer in them (the input and
    /// what the student's code returned, or what went wrong with it): what a course that
    /// gives feedback at [`super::feedback::Feedback::Actual`] shows.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub shown: Vec<String>,
    /// A failing case shrunk to a simpler input that still fails ([`super::shrink`]): the
    /// message in full and as [`CheckResult::shown`] words it. Not a graded case: it is
    /// counted in neither `failed` nor `total`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shrunk: Option<(String, String)>,
    /// Number of failing cases (may exceed `failures.len()`).
    pub failed: usize,
    /// Number of cases run.
    pub total: usize,
    /// The largest error over the cases and the case where it occurred.
    pub worst: Option<Worst>,
    /// The declared false-failure rate of a statistical check (0 for exact checks).
    pub alpha: f64,
    /// p-values of the statistical sub-tests, for calibration studies.
    pub p_values: Vec<f64>,
    /// True when every case stopped at a `todo!()` stub.
    pub not_attempted: bool,
    /// The tasks whose `todo!()` stubs stopped cases of this check.
    pub todo_in: Vec<String>,
    /// How many failing cases stopped at a `todo!()` stub.
    pub todo_failed: usize,
    /// Data for the HTML report.
    pub detail: Option<Detail>,
    /// Wall time spent in the check, in seconds.
    pub seconds: f64,
    /// The most resident memory the worker had held by the end of the check, in KiB, as
    /// the worker reported it (statistics, never a verdict); none where it did not.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub peak_memory_kib: Option<u64>,
    /// The declared regions of the domain its cases lie in, each with its count of cases
    /// and of failing ones (a values check; empty for the others): the split its credit
    /// follows ([`super::credit::Credit::PerRegion`]).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub regions: Vec<RegionTally>,
}

/// The cases of one region of a check ([`CheckResult::regions`]).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RegionTally {
    /// The region, as [`crate::grade::value_cases::region`] names it.
    pub name: String,
    /// Cases in it.
    pub total: usize,
    /// Failing cases in it.
    pub failed: usize,
}

/// The sum of points or weights, +0 when empty (`Iterator::sum` of no f64 is −0, which
/// prints as "-0.0").
pub fn total(values: impl IntoIterator<Item = f64>) -> f64 {
    values.into_iter().fold(0.0, |a, b| a + b)
}

/// `points` rounded to hundredths, for what a person reads (a results file's score, a
/// table's cell); sums are taken of the exact values first.
pub fn display_points(points: f64) -> f64 {
    (points * 100.0).round() / 100.0 + 0.0
}

/// `points` as a person reads them: at most two decimals, no trailing zeros (`3.33`, `24.7`,
/// `6`).
pub fn format_points(points: f64) -> String {
    let text = format!("{:.2}", display_points(points));
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// Serialises points rounded to hundredths ([`display_points`]): serde's
/// `serialize_with`.
pub fn serialize_points<S: serde::Serializer>(points: &f64, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_f64(display_points(*points))
}

/// The maximum number of failure messages a check keeps.
pub const MAX_MESSAGES: usize = 8;

impl CheckResult {
    /// An empty result of `kind` named `name`, to be filled in by a check.
    pub fn new(name: impl Into<String>, kind: CheckKind) -> Self {
        Self {
            name: name.into(),
            kind,
            visibility: Visibility::Visible,
            passed: false,
            credit: 0.0,
            weight: 1.0,
            summary: String::new(),
            failures: Vec::new(),
            shown: Vec::new(),
            shrunk: None,
            failed: 0,
            total: 0,
            worst: None,
            alpha: 0.0,
            p_values: Vec::new(),
            not_attempted: false,
            todo_in: Vec::new(),
            todo_failed: 0,
            detail: None,
            seconds: 0.0,
            peak_memory_kib: None,
            regions: Vec::new(),
        }
    }

    /// Records one failing case: `message` in full (its input, what came back, what was
    /// expected), and `shown`, the same case without anything of the expected answer (its
    /// input and what came back).
    pub fn fail(&mut self, message: String, shown: String) {
        self.failed += 1;
        if self.failures.len() < MAX_MESSAGES {
            self.failures.push(message);
            self.shown.push(shown);
        }
    }

    /// Records one failing case whose message holds nothing of the expected answer (what
    /// the student's code did, or that no output came back): shown as it is.
    pub fn fail_own(&mut self, message: String) {
        self.fail(message.clone(), message);
    }

    /// Records a case that panicked; `context` names the case.
    pub fn fail_panic(&mut self, context: &str, panic: &Panic) {
        if let Some(task) = &panic.todo_in {
            self.todo_failed += 1;
            if !self.todo_in.contains(task) {
                self.todo_in.push(task.clone());
            }
        }
        // What the student's own code did: the same in full and shown.
        self.fail_own(format!("{context}: {}", panic.describe()));
    }

    /// Sets the verdict from the cases recorded: passed when none failed, not attempted when
    /// every case stopped at a stub.
    pub fn finish(&mut self) {
        self.passed = self.failed == 0;
        self.not_attempted = self.total > 0 && self.todo_failed == self.total;
    }
}

/// The worst error of a check and where it happened.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Worst {
    /// The case, with its input.
    pub case: String,
    /// The error there.
    pub error: Error,
    /// The error as a share of the case's tolerance (`abs + rel·|expected|`), where a
    /// tolerance decides the case: at most 1 where it passed. What a report shows, since a
    /// relative error alone is large wherever the expected value is near 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub share: Option<f64>,
}

/// Extra data of a check, drawn by the HTML report.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Detail {
    /// Observed against expected counts of a sampling check.
    Sampling(super::sampling::Histogram),
    /// Mean, error and time of an estimator, the student's against the reference's.
    Estimator(super::estimator::EstimatorStats),
    /// A render against the reference.
    Image(super::image_check::ImageDetail),
}

/// The outcome of grading one task.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TaskOutcome {
    /// The task id (`reflect`, …).
    pub task: String,
    /// How grading ended.
    pub status: TaskStatus,
    /// Points scored.
    pub points: f64,
    /// Points available (the task table's; 0 for a task without checks).
    pub max_points: f64,
    /// Every check that ran.
    pub checks: Vec<CheckResult>,
    /// What the student's code printed, truncated.
    pub output: String,
    /// Wall time for the task including process start, in seconds.
    pub seconds: f64,
}

impl TaskOutcome {
    /// The worst error over the task's checks, if any check measured one.
    pub fn worst(&self) -> Option<&Worst> {
        self.checks
            .iter()
            .filter_map(|c| c.worst.as_ref())
            .max_by(|a, b| a.error.abs.total_cmp(&b.error.abs))
    }
}

/// A whole grading run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct GradeReport {
    /// Which implementation was graded (`student`, `reference`, `mixed`).
    pub implementation: String,
    /// The seed of the statistical checks.
    pub seed: u64,
    /// Whether hidden cases were added (the hidden seed itself is never recorded).
    pub hidden: bool,
    /// One outcome per graded task, in worksheet order.
    pub tasks: Vec<TaskOutcome>,
    /// Points scored in total.
    pub score: f64,
    /// Points available in total.
    pub max_score: f64,
    /// Wall time of the run, in seconds.
    pub seconds: f64,
    /// The protections the workers that ran student code reported in force, each distinct
    /// set once (see [`crate::grade::sandbox`]); empty when no worker ran.
    #[serde(default)]
    pub sandbox: Vec<String>,
    /// How much of a failing case this report shows ([`super::feedback`]).
    #[serde(default)]
    pub feedback: super::feedback::Feedback,
    /// The variant graded, when the course gives each student their own hidden cases and
    /// seeds (`--variant-key`): its public id, which a regrade with the same key and
    /// student reproduces ([`super::variant`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub variant: Option<String>,
}

impl TaskOutcome {
    /// True for a scene whose render check waits for tasks it calls that do not pass yet.
    pub fn scene_waits(&self) -> bool {
        self.task.starts_with("scene: ") && matches!(self.status, TaskStatus::NeedsTask { .. })
    }

    /// True for an entry a report shows in one line with its kind rather than in a row and
    /// a section of its own: a task not attempted yet, a scene waiting for its tasks.
    pub fn folds(&self) -> bool {
        self.status == TaskStatus::NotAttempted || self.scene_waits()
    }
}

impl GradeReport {
    /// A report of `tasks`, with totals summed.
    pub fn new(
        implementation: &str,
        seed: u64,
        hidden: bool,
        tasks: Vec<TaskOutcome>,
        seconds: f64,
    ) -> Self {
        let score = total(tasks.iter().map(|t| t.points));
        let max_score = total(tasks.iter().map(|t| t.max_points));
        Self {
            implementation: implementation.into(),
            seed,
            hidden,
            tasks,
            score,
            max_score,
            seconds,
            sandbox: Vec::new(),
            feedback: super::feedback::Feedback::default(),
            variant: None,
        }
    }

    /// The outcome of `task`, if it was graded.
    pub fn task(&self, task: &str) -> Option<&TaskOutcome> {
        self.tasks.iter().find(|t| t.task == task)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_read_with_two_decimals_at_most() {
        assert_eq!(format_points(10.0 / 3.0), "3.33");
        assert_eq!(format_points(24.700000000000003), "24.7");
        assert_eq!(format_points(6.0), "6");
        assert_eq!(format_points(6.273015873015873), "6.27");
        assert_eq!(format_points(-0.0), "0");
        assert_eq!(display_points(0.125), 0.13);
    }
}
