//! The one-screen view `pbrlab watch` redraws after each grade: whatever the grade, it fits
//! a terminal of [`WIDTH`] columns and the rows it is given. A line for the whole grade,
//! a row for each task whose grade changed since the last one and each task that fails
//! (the most [`MAX_ROWS`]), a line each for the tasks that pass, those not attempted
//! and the scenes, then the first failure: the changed task that fails, else the first
//! that fails, cut to the rows left. The rest (every row, every line) is the full report,
//! one key away in the watch.

use super::text::{WIDTH, details, fit, row, status_cell, worst, wrap};
use crate::grade::verdict::{GradeReport, TaskOutcome, TaskStatus, format_points};

/// The most task rows the view shows; the tasks past them are named on one line.
pub const MAX_ROWS: usize = 6;

/// True for an entry that was graded and did not pass.
fn fails(t: &TaskOutcome) -> bool {
    !matches!(
        t.status,
        TaskStatus::Passed | TaskStatus::NotAttempted | TaskStatus::NoChecks
    ) && !t.scene_waits()
        && !matches!(t.status, TaskStatus::NeedsTask { .. })
}

/// True when `t` has another status or other points than in `previous`, or is new.
fn changed(t: &TaskOutcome, previous: Option<&GradeReport>) -> bool {
    previous.is_some_and(|p| {
        p.tasks
            .iter()
            .find(|o| o.task == t.task)
            .is_none_or(|o| o.status.label() != t.status.label() || o.points != t.points)
    })
}

/// `label (n): a, b, c` on one line of [`WIDTH`], or nothing when `names` is empty.
fn names_line(label: &str, names: &[&str]) -> Option<String> {
    (!names.is_empty()).then(|| {
        fit(
            &format!("{label} ({}): {}", names.len(), names.join(", ")),
            WIDTH,
        )
    })
}

/// The view of `report`, `previous` being the grade before it (rows that changed are
/// marked `›`), in at most `rows` lines of at most [`WIDTH`] characters.
pub fn screen(report: &GradeReport, previous: Option<&GradeReport>, rows: usize) -> Vec<String> {
    let tasks: Vec<&TaskOutcome> = report
        .tasks
        .iter()
        .filter(|t| !t.task.starts_with("scene: "))
        .collect();
    let scenes: Vec<&TaskOutcome> = report
        .tasks
        .iter()
        .filter(|t| t.task.starts_with("scene: "))
        .collect();
    let passed = tasks
        .iter()
        .filter(|t| t.status == TaskStatus::Passed)
        .count();
    let mut lines = vec![fit(
        &format!(
            "{passed} of {} tasks pass · {}/{} points · graded in {:.1} s",
            tasks.len(),
            format_points(report.score),
            format_points(report.max_score),
            report.seconds
        ),
        WIDTH,
    )];
    // Changed rows first, then failing ones, in worksheet order within each.
    let mut shown: Vec<&TaskOutcome> = tasks
        .iter()
        .chain(&scenes)
        .copied()
        .filter(|t| changed(t, previous))
        .collect();
    let failing: Vec<&TaskOutcome> = tasks
        .iter()
        .chain(&scenes)
        .copied()
        .filter(|t| fails(t) && !shown.iter().any(|s| s.task == t.task))
        .collect();
    shown.extend(failing);
    let more: Vec<&str> = shown
        .iter()
        .skip(MAX_ROWS)
        .map(|t| t.task.as_str())
        .collect();
    shown.truncate(MAX_ROWS);
    if !shown.is_empty() {
        let mut table = String::new();
        row(
            &mut table,
            "task",
            "status",
            "points",
            "worst error",
            "time",
        );
        for t in &shown {
            let mark = if changed(t, previous) { "› " } else { "" };
            let points = format!(
                "{}/{}",
                format_points(t.points),
                format_points(t.max_points)
            );
            row(
                &mut table,
                &format!("{mark}{}", t.task),
                &status_cell(t),
                &points,
                &worst(t),
                &format!("{:.2}s", t.seconds),
            );
        }
        lines.extend(table.lines().map(str::to_string));
    }
    let named = |keep: fn(&TaskOutcome) -> bool, of: &[&TaskOutcome]| -> Vec<String> {
        of.iter()
            .filter(|t| keep(t) && !shown.iter().any(|s| s.task == t.task))
            .map(|t| t.task.trim_start_matches("scene: ").to_string())
            .collect()
    };
    let groups = [
        (
            "… and more that changed or fail",
            more.iter().map(|s| s.to_string()).collect(),
        ),
        ("pass", named(|t| t.status == TaskStatus::Passed, &tasks)),
        (
            "not attempted",
            named(
                |t| {
                    matches!(
                        t.status,
                        TaskStatus::NotAttempted | TaskStatus::NeedsTask { .. }
                    )
                },
                &tasks,
            ),
        ),
        (
            "scenes that pass",
            named(|t| t.status == TaskStatus::Passed, &scenes),
        ),
        (
            "scenes waiting for their tasks",
            named(TaskOutcome::scene_waits, &scenes),
        ),
    ];
    for (label, names) in &groups {
        let names: Vec<&str> = names.iter().map(String::as_str).collect();
        lines.extend(names_line(label, &names));
    }
    let focus = shown
        .iter()
        .find(|t| fails(t) && changed(t, previous))
        .or_else(|| shown.iter().find(|t| fails(t)));
    if let Some(t) = focus {
        let room = rows.saturating_sub(lines.len() + 2);
        let detail: Vec<String> = details(t).lines().flat_map(wrap).collect();
        if room > 0 && !detail.is_empty() {
            lines.push(String::new());
            lines.push(fit(&format!("{}: {}", t.task, t.status.label()), WIDTH));
            let cut = detail.len() > room;
            let keep = if cut { room - 1 } else { detail.len() };
            lines.extend(detail.into_iter().take(keep));
            if cut {
                lines.push("  … (f: the full report)".into());
            }
        }
    }
    lines.truncate(rows);
    lines
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grade::verdict::{CheckKind, CheckResult};

    fn outcome(task: &str, status: TaskStatus) -> TaskOutcome {
        let mut check = CheckResult::new("values", CheckKind::Values);
        check.passed = status == TaskStatus::Passed;
        check.summary = "12/262 cases agree with the reference; ".repeat(6);
        check.failures = (0..40)
            .map(|i| {
                format!(
                    "{task}(w=(0.0, 0.0, 1.0), α=0.{i}): got 0.995, expected 1 {}",
                    "x".repeat(90)
                )
            })
            .collect();
        check.failed = 200;
        TaskOutcome {
            task: task.into(),
            status,
            points: 1.0,
            max_points: 6.0,
            checks: vec![check],
            output: "printed\n".repeat(30),
            seconds: 0.5,
        }
    }

    fn report(tasks: Vec<TaskOutcome>) -> GradeReport {
        GradeReport {
            implementation: "student".into(),
            seed: 1,
            hidden: false,
            tasks,
            score: 3.0,
            max_score: 141.0,
            seconds: 2.0,
            sandbox: Vec::new(),
            feedback: Default::default(),
            variant: None,
        }
    }

    /// Every state the watch meets: nothing written, every task failing, a compiler's
    /// flood of messages, crashes, scenes, and a grade that changed everything.
    #[test]
    fn every_state_fits_80_by_24() {
        let names: Vec<&str> = crate::worksheet::TaskId::ALL
            .iter()
            .map(|t| t.name())
            .collect();
        let all = |status: &dyn Fn(usize) -> TaskStatus| {
            let mut tasks: Vec<TaskOutcome> = names
                .iter()
                .enumerate()
                .map(|(i, n)| outcome(n, status(i)))
                .collect();
            for scene in ["cornell", "materials", "glass", "smoke"] {
                tasks.push(outcome(
                    &format!("scene: {scene}"),
                    TaskStatus::NeedsTask {
                        task: "path_trace, mis".into(),
                    },
                ));
            }
            report(tasks)
        };
        let flood = "error[E0308]: mismatched types\n".repeat(400) + &"x".repeat(300);
        let states = [
            all(&|_| TaskStatus::NotAttempted),
            all(&|_| TaskStatus::Failed),
            all(&|i| {
                if i % 2 == 0 {
                    TaskStatus::Passed
                } else {
                    TaskStatus::Partial
                }
            }),
            all(&|_| TaskStatus::CompileError {
                message: flood.clone(),
            }),
            all(&|_| TaskStatus::Crashed {
                reason: "ran out of time ".repeat(20),
            }),
        ];
        for (i, state) in states.iter().enumerate() {
            for previous in [None, Some(&states[(i + 1) % states.len()])] {
                let lines = screen(state, previous, 22);
                assert!(lines.len() <= 22, "{}", lines.join("\n"));
                for line in &lines {
                    assert!(line.chars().count() <= WIDTH, "{line}");
                }
            }
        }
        // What fails is shown, first the task whose grade changed.
        let before = all(&|_| TaskStatus::NotAttempted);
        let mut now = all(&|_| TaskStatus::NotAttempted);
        now.tasks[4] = outcome("smith_g1", TaskStatus::Failed);
        let lines = screen(&now, Some(&before), 22).join("\n");
        assert!(lines.contains("› smith_g1"), "{lines}");
        assert!(lines.contains("smith_g1: FAILED"), "{lines}");
        assert!(lines.contains("not attempted (14)"), "{lines}");
    }
}
