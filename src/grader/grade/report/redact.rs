//! A report as a student sees it at a course's [`Feedback`] level: the checks' verdicts and
//! counts always, failing inputs and outputs at `actual`, everything at `full`.

use crate::grade::feedback::Feedback;
use crate::grade::verdict::{CheckResult, GradeReport, TaskStatus, Visibility};

/// `report` as a student sees it at `level`: at [`Feedback::Full`] unchanged; otherwise
/// every check keeps its name, kind, verdict, credit and counts, and loses its worst case,
/// its statistics and pictures, and its messages: a summary from its counts replaces its
/// own, and at [`Feedback::Actual`] a visible check's failures are its student-safe lines
/// ([`CheckResult::shown`]).
pub fn redact(report: &GradeReport, level: Feedback) -> GradeReport {
    let mut shown = report.clone();
    shown.feedback = level;
    if level == Feedback::Full {
        return shown;
    }
    for task in &mut shown.tasks {
        for check in &mut task.checks {
            redact_check(check, level);
        }
        // Where a crash happened names the step, a public case's input: not at `none`.
        if let (Feedback::None, TaskStatus::Crashed { reason }) = (level, &mut task.status)
            && let Some((what, _)) = reason.split_once(", while running ")
        {
            *reason = what.to_string();
        }
    }
    shown
}

/// One check at `level` (not [`Feedback::Full`]): a summary from its counts alone; at
/// [`Feedback::Actual`] the student-safe form of each failing case it kept, for a visible
/// check; no worst case, p-values or detail (histograms, estimates, pictures); its regions'
/// counts without their names.
fn redact_check(check: &mut CheckResult, level: Feedback) {
    check.summary = if check.passed {
        format!("{}/{} cases pass", check.total, check.total)
    } else if check.not_attempted {
        "not attempted".into()
    } else if check.total > 1 {
        format!("{}/{} cases fail", check.failed, check.total)
    } else {
        "failed".into()
    };
    check.failures = match (level, check.visibility) {
        (Feedback::Actual, Visibility::Visible) => std::mem::take(&mut check.shown),
        _ => Vec::new(),
    };
    check.shown.clear();
    check.shrunk = match level {
        Feedback::Actual => check.shrunk.take().map(|(_, shown)| (shown.clone(), shown)),
        _ => None,
    };
    check.worst = None;
    check.p_values.clear();
    check.detail = None;
    // A region is named by the values it lies at (`|n| = 0.999`), which may be a case's
    // input or answer: below `full`, regions keep their counts (the credit's split) and
    // lose their names.
    for (k, region) in check.regions.iter_mut().enumerate() {
        region.name = format!("region {}", k + 1);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grade::verdict::{CheckKind, TaskOutcome, TaskStatus};

    fn report() -> GradeReport {
        let mut check = CheckResult::new("values", CheckKind::Values);
        check.total = 3;
        check.fail(
            "f(1): got 2, expected 3.25 [random 4]".into(),
            "f(1): got 2 [random 4]".into(),
        );
        check.finish();
        check.summary = "2/3 cases agree; simplest failing input: f(1): expected 3.25".into();
        let mut hidden = check.clone();
        hidden.name = "values (hidden cases)".into();
        hidden.visibility = Visibility::Hidden;
        let task = TaskOutcome {
            task: "reflect".into(),
            status: TaskStatus::Failed,
            points: 1.0,
            max_points: 5.0,
            checks: vec![check, hidden],
            output: String::new(),
            seconds: 0.0,
        };
        GradeReport::new("student", 1, true, vec![task], 1.0)
    }

    #[test]
    fn each_level_shows_what_it_says_and_keeps_the_points() {
        let full = redact(&report(), Feedback::Full);
        assert_eq!(full.tasks, report().tasks);
        let actual = redact(&report(), Feedback::Actual);
        let none = redact(&report(), Feedback::None);
        for shown in [&actual, &none] {
            assert_eq!(shown.score, report().score);
            let json = serde_json::to_string(shown).unwrap();
            assert!(!json.contains("3.25"), "{json}");
            assert!(!json.contains("expected"), "{json}");
            assert_eq!(shown.tasks[0].checks[1].failures, Vec::<String>::new());
            assert_eq!(shown.tasks[0].checks[0].summary, "1/3 cases fail");
        }
        assert_eq!(
            actual.tasks[0].checks[0].failures,
            ["f(1): got 2 [random 4]"]
        );
        assert!(none.tasks[0].checks[0].failures.is_empty());
        assert_eq!(actual.feedback, Feedback::Actual);
    }
}
