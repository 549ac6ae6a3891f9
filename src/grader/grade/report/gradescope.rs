//! Gradescope's results.json (<https://gradescope-autograders.readthedocs.io>): one test per
//! task, and one more per task for its hidden cases.

use super::text::details;
use crate::grade::verdict::{GradeReport, TaskOutcome, TaskStatus, Visibility, total};
use crate::worksheet::TaskId;
use serde::Serialize;

/// The top level of results.json: the keys of Gradescope's specification only (the total
/// available is the sum of the tests' `max_score`; the spec has no top-level one).
#[derive(Debug, Serialize)]
pub struct Results {
    /// Total score: the exact sum of the tests' scores, shown to hundredths.
    #[serde(serialize_with = "crate::grade::verdict::serialize_points")]
    pub score: f64,
    /// Seconds the grade took.
    pub execution_time: f64,
    /// Shown above the tests.
    pub output: String,
    /// Visibility of the whole result.
    pub visibility: &'static str,
    /// Visibility of the autograder's stdout.
    pub stdout_visibility: &'static str,
    /// One entry per graded part.
    pub tests: Vec<Test>,
    /// Stored with the result, not shown: the variant graded (`{"variant": id}`), so a
    /// regrade reproduces it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub extra_data: Option<serde_json::Value>,
}

/// One test entry.
#[derive(Debug, Serialize)]
pub struct Test {
    /// The task and its title.
    pub name: String,
    /// Points scored (exact; shown to hundredths).
    #[serde(serialize_with = "crate::grade::verdict::serialize_points")]
    pub score: f64,
    /// Points available (exact; shown to hundredths).
    #[serde(serialize_with = "crate::grade::verdict::serialize_points")]
    pub max_score: f64,
    /// `passed` or `failed`.
    pub status: &'static str,
    /// What was checked and what failed.
    pub output: String,
    /// `visible`, or `after_published` for the hidden cases (shown once the instructor
    /// publishes the grades).
    pub visibility: &'static str,
}

fn title(task: &str) -> String {
    TaskId::parse(task).map_or_else(
        |_| task.to_string(),
        |t| format!("{task} — {}", t.info().title),
    )
}

/// The tests of one task: its visible checks, and its hidden ones when there are any. The
/// task's points are split by check weight; a task that crashed or was not attempted scores
/// 0 in both.
fn tests_of(t: &TaskOutcome) -> Vec<Test> {
    let of = |vis: Visibility| t.checks.iter().filter(move |c| c.visibility == vis);
    let all = total(t.checks.iter().map(|c| c.weight));
    let share = |w: f64| {
        if all > 0.0 {
            t.max_points * w / all
        } else {
            t.max_points
        }
    };
    let scored = matches!(
        t.status,
        TaskStatus::Passed | TaskStatus::Partial | TaskStatus::Failed
    );
    // Each check earns its weight times its credit (the course's policy for partly right
    // checks); the group passed when every check in it did.
    let group = |vis: Visibility| {
        let weight = total(of(vis).map(|c| c.weight));
        let earned = total(of(vis).map(|c| c.weight * c.credit));
        let passed = scored && of(vis).all(|c| c.passed);
        (
            share(weight),
            if scored { share(earned) } else { 0.0 },
            passed,
        )
    };
    let mut output = match &t.status {
        TaskStatus::Passed => "All checks pass.".to_string(),
        TaskStatus::NotAttempted => "Not attempted: the functions still stop at todo!().".into(),
        other => format!("{}.", other.label()),
    };
    for c in t
        .checks
        .iter()
        .filter(|c| c.visibility == Visibility::Visible)
    {
        output += &format!(
            "\n{} {}: {}",
            if c.passed { "✓" } else { "✗" },
            c.name,
            c.summary
        );
    }
    let d = details(t);
    if !d.is_empty() {
        output += "\n\n";
        output += &d;
    }
    let (max_score, score, passed) = group(Visibility::Visible);
    let mut tests = vec![Test {
        name: title(&t.task),
        score,
        max_score,
        status: if passed { "passed" } else { "failed" },
        output,
        visibility: "visible",
    }];
    if of(Visibility::Hidden).next().is_some() {
        let (max_score, score, passed) = group(Visibility::Hidden);
        tests.push(Test {
            name: format!("{} (hidden cases)", title(&t.task)),
            score,
            max_score,
            status: if passed { "passed" } else { "failed" },
            output: t
                .checks
                .iter()
                .filter(|c| c.visibility == Visibility::Hidden)
                .map(|c| format!("{}: {}", c.name, c.summary))
                .collect::<Vec<_>>()
                .join("\n"),
            visibility: "after_published",
        });
    }
    tests
}

/// The results of a submission that could not be graded at all: score 0 and why.
pub fn failed(reason: &str, seconds: f64) -> Results {
    Results {
        score: 0.0,
        execution_time: seconds,
        output: format!("Not graded: {reason}"),
        visibility: "visible",
        stdout_visibility: "hidden",
        tests: Vec::new(),
        extra_data: None,
    }
}

/// The Gradescope results of `report`.
pub fn gradescope(report: &GradeReport) -> Results {
    let tests: Vec<Test> = report
        .tasks
        .iter()
        .filter(|t| t.max_points > 0.0)
        .flat_map(tests_of)
        .collect();
    let mut output = format!(
        "Graded {} tasks with pbrlab. Run `cargo run --release -- grade` locally for the same public checks.",
        tests.iter().filter(|t| t.visibility == "visible").count()
    );
    for note in super::report_notes(report) {
        output += &format!("\n{note}");
    }
    Results {
        score: total(tests.iter().map(|t| t.score)),
        execution_time: report.seconds,
        output,
        visibility: "visible",
        stdout_visibility: "hidden",
        tests,
        extra_data: report
            .variant
            .as_ref()
            .map(|v| serde_json::json!({ "variant": v })),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grade::checks::score;
    use crate::grade::credit::Credit;
    use crate::grade::verdict::{CheckKind, CheckResult, display_points};

    #[test]
    fn partial_credit_reaches_gradescope_as_the_grader_scored_it() {
        let mut values = CheckResult::new("values", CheckKind::Values);
        (values.total, values.failed, values.weight) = (30, 4, 2.0);
        let mut hidden = CheckResult::new("values (hidden cases)", CheckKind::Values);
        (hidden.total, hidden.failed, hidden.visibility) = (24, 12, Visibility::Hidden);
        let mut estimator = CheckResult::new("estimator", CheckKind::Estimator);
        (estimator.total, estimator.passed) = (1, true);
        let mut checks = vec![values, hidden, estimator];
        Credit::PerCase.apply(&mut checks);
        let (status, points) = score(TaskId::SmithG1, &checks);
        assert_eq!(status, TaskStatus::Failed);
        let expected = 6.0 * (2.0 * 26.0 / 30.0 + 0.5 + 1.0) / 4.0;
        assert!(
            (points - expected).abs() < 1e-9,
            "{points} against {expected}"
        );
        let outcome = TaskOutcome {
            task: "smith_g1".into(),
            status,
            points,
            max_points: 6.0,
            checks,
            output: String::new(),
            seconds: 0.0,
        };
        let tests = tests_of(&outcome);
        let sum = total(tests.iter().map(|t| t.score));
        assert!(
            (sum - points).abs() < 1e-9,
            "Gradescope {sum}, grader {points}"
        );
        assert!(tests.iter().all(|t| t.status == "failed"));
        // What Gradescope shows: hundredths, not 3.3333333333333335.
        for test in serde_json::to_value(&tests).unwrap().as_array().unwrap() {
            for key in ["score", "max_score"] {
                let shown = test[key].as_f64().unwrap();
                assert_eq!(shown, display_points(shown), "{test}");
            }
        }
    }
}
