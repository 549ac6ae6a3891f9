//! The terminal table.

use crate::grade::output::fmt_num;
use crate::grade::verdict::{GradeReport, TaskOutcome, TaskStatus, Visibility};
use std::fmt::Write;

/// The worst error of a task, short: `abs 2.1e-3 (rel 0.8 %)`.
fn worst(outcome: &TaskOutcome) -> String {
    if !matches!(outcome.status, TaskStatus::Passed | TaskStatus::Failed) {
        return "-".into();
    }
    match outcome.worst() {
        Some(w) if w.error.abs.is_infinite() => "not comparable".into(),
        Some(w) if w.error.abs == 0.0 => "0".into(),
        Some(w) => format!("{} (rel {})", fmt_num(w.error.abs), fmt_num(w.error.rel)),
        None => "-".into(),
    }
}

/// The table: task, status, points, worst error, time; then what failed, per task; then the
/// total.
pub fn text(report: &GradeReport) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{:<16} {:<16} {:>11}  {:<26} {:>7}",
        "task", "status", "points", "worst error", "time"
    );
    let _ = writeln!(s, "{}", "-".repeat(82));
    for t in &report.tasks {
        let points = if t.max_points > 0.0 {
            format!("{:.1}/{}", t.points, t.max_points)
        } else {
            "-".into()
        };
        let _ = writeln!(
            s,
            "{:<16} {:<16} {:>11}  {:<26} {:>6.2}s",
            t.task,
            t.status.label(),
            points,
            worst(t),
            t.seconds
        );
    }
    let _ = writeln!(s, "{}", "-".repeat(82));
    let _ = writeln!(
        s,
        "{:<16} {:<16} {:>11}  {:<26} {:>6.2}s",
        "total",
        format!("{} implementation", report.implementation),
        format!("{:.1}/{}", report.score, report.max_score),
        "",
        report.seconds
    );
    for protections in &report.sandbox {
        let _ = writeln!(s, "sandbox of the workers: {protections}");
    }
    for t in &report.tasks {
        let details = details(t);
        if !details.is_empty() {
            let _ = write!(s, "\n{}: {}\n{details}", t.task, t.status.label());
        }
    }
    s
}

/// What went wrong in a task, one line per message, hidden checks shown by count only.
pub fn details(t: &TaskOutcome) -> String {
    let mut s = String::new();
    match &t.status {
        TaskStatus::Crashed { reason } => {
            let _ = writeln!(s, "  the code {reason}");
            if !t.checks.is_empty() {
                let _ = writeln!(s, "  finished before that:");
            }
            for c in &t.checks {
                let _ = if c.passed {
                    writeln!(s, "    ✓ {}", c.name)
                } else {
                    writeln!(s, "    ✗ {}: {}", c.name, c.summary)
                };
            }
        }
        TaskStatus::GraderError { message } => {
            let _ = writeln!(
                s,
                "  the grader failed here, not your code ({message}); grade again"
            );
        }
        TaskStatus::CompileError { message } => {
            let _ = writeln!(
                s,
                "  exercises/{}.rs does not compile (the other tasks were graded as \
                 written):",
                t.task
            );
            for line in message.lines() {
                let _ = writeln!(s, "    {line}");
            }
        }
        TaskStatus::NeedsTask { task } if t.task.starts_with("scene: ") => {
            let _ = writeln!(s, "  the render is graded once these tasks pass: {task}");
        }
        TaskStatus::NeedsTask { task } => {
            let _ = writeln!(s, "  grading stops at `{task}`, which is not written yet");
        }
        TaskStatus::Passed
        | TaskStatus::NotAttempted
        | TaskStatus::NoChecks
        | TaskStatus::Failed => {}
    }
    if t.status == TaskStatus::Failed {
        for c in t.checks.iter().filter(|c| !c.passed) {
            if c.visibility == Visibility::Hidden {
                let _ = writeln!(
                    s,
                    "  ✗ {}: {} of {} hidden cases fail",
                    c.name, c.failed, c.total
                );
                continue;
            }
            let _ = writeln!(s, "  ✗ {}: {}", c.name, c.summary);
            for m in &c.failures {
                let _ = writeln!(s, "      {m}");
            }
            if c.failed > c.failures.len() {
                let _ = writeln!(s, "      … and {} more", c.failed - c.failures.len());
            }
        }
        let chance: f64 = t
            .checks
            .iter()
            .filter(|c| !c.passed && c.visibility == Visibility::Visible)
            .map(|c| c.alpha)
            .fold(0.0, f64::max);
        if chance > 0.0 {
            let _ = writeln!(
                s,
                "  (a statistical check: correct code fails it with probability {chance:.0e}; \
                 if it fails again with another --seed, the error is real)"
            );
        }
    }
    if !t.output.trim().is_empty() && t.status != TaskStatus::Passed {
        let lines: Vec<&str> = t.output.lines().take(5).collect();
        let _ = writeln!(s, "  output:\n    {}", lines.join("\n    "));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grade::verdict::{CheckKind, CheckResult, TaskOutcome};

    fn failed_with(kind: CheckKind, alpha: f64) -> TaskOutcome {
        let mut check = CheckResult::new("a check", kind);
        check.total = 1;
        check.alpha = alpha;
        check.fail("case 1 is off".into());
        check.finish();
        TaskOutcome {
            task: "cosine_sample".into(),
            status: TaskStatus::Failed,
            points: 0.0,
            max_points: 8.0,
            checks: vec![check],
            output: String::new(),
            seconds: 0.0,
        }
    }

    #[test]
    fn a_failed_statistical_check_says_how_often_correct_code_fails_it() {
        let text = details(&failed_with(CheckKind::Sampling, 5e-4));
        assert!(text.contains("probability 5e-4"), "{text}");
        let text = details(&failed_with(CheckKind::Values, 0.0));
        assert!(!text.contains("probability"), "{text}");
    }
}
