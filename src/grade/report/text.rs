//! The terminal table.

use crate::grade::output::fmt_num;
use crate::grade::verdict::{GradeReport, TaskOutcome, TaskStatus, Visibility, format_points};
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

/// `text` cut to `width` characters, with `…` where it was cut.
fn fit(text: &str, width: usize) -> String {
    if text.chars().count() <= width {
        return text.to_string();
    }
    let kept: String = text.chars().take(width.saturating_sub(1)).collect();
    format!("{kept}…")
}

/// A task's status as the table shows it: a scene waiting for several tasks says how many
/// (the details below, and `pbrlab needs SCENE`, name them).
fn status_cell(t: &TaskOutcome) -> String {
    match &t.status {
        TaskStatus::NeedsTask { task } if task.contains(", ") => {
            format!("needs {} tasks", task.split(", ").count())
        }
        status => status.label(),
    }
}

/// One row of the table: at most 76 characters, so it fits an 80-column terminal.
fn row(s: &mut String, task: &str, status: &str, points: &str, worst: &str, time: &str) {
    let _ = writeln!(
        s,
        "{:<16} {:<15} {:>9}  {:<24} {:>7}",
        fit(task, 16),
        fit(status, 15),
        points,
        fit(worst, 24),
        time
    );
}

/// The table: task, status, points, worst error, time (one row per task and scene, 76
/// columns); the total; then what failed, per task, and one line for the scenes that wait
/// for tasks to pass.
pub fn text(report: &GradeReport) -> String {
    let mut s = String::new();
    row(&mut s, "task", "status", "points", "worst error", "time");
    let rule = "-".repeat(76);
    let _ = writeln!(s, "{rule}");
    for t in &report.tasks {
        let points = if t.max_points > 0.0 {
            format!(
                "{}/{}",
                format_points(t.points),
                format_points(t.max_points)
            )
        } else {
            "-".into()
        };
        let time = format!("{:.2}s", t.seconds);
        row(&mut s, &t.task, &status_cell(t), &points, &worst(t), &time);
    }
    let _ = writeln!(s, "{rule}");
    let total = format!(
        "{}/{}",
        format_points(report.score),
        format_points(report.max_score)
    );
    let time = format!("{:.2}s", report.seconds);
    row(&mut s, "total", &report.implementation, &total, "", &time);
    for protections in &report.sandbox {
        let _ = writeln!(s, "sandbox of the workers: {protections}");
    }
    let mut waiting = Vec::new();
    for t in &report.tasks {
        if let (TaskStatus::NeedsTask { task }, Some(scene)) =
            (&t.status, t.task.strip_prefix("scene: "))
        {
            waiting.push(format!("{scene} ({task})"));
            continue;
        }
        let details = details(t);
        if !details.is_empty() {
            let _ = write!(s, "\n{}: {}\n{details}", t.task, t.status.label());
        }
    }
    if !waiting.is_empty() {
        let _ = writeln!(
            s,
            "\nScenes are graded once the tasks they call pass: {}.",
            waiting.join("; ")
        );
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
