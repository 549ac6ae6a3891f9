//! The terminal table.

use crate::grade::output::fmt_num;
use crate::grade::verdict::{
    GradeReport, TaskOutcome, TaskStatus, Visibility, Worst, format_points,
};
use std::fmt::Write;

/// The worst error of a task, short: `2.1e-3 (40 % of tol)` where a tolerance decides, else
/// `2.1e-3 (rel 8e-3)`.
pub(super) fn worst(outcome: &TaskOutcome) -> String {
    if !matches!(
        outcome.status,
        TaskStatus::Passed | TaskStatus::Partial | TaskStatus::Failed
    ) {
        return "-".into();
    }
    match outcome.worst() {
        Some(w) if w.error.abs.is_infinite() => "not comparable".into(),
        Some(w) if w.error.abs == 0.0 => "0".into(),
        Some(Worst {
            error,
            share: Some(share),
            ..
        }) if share.is_finite() => {
            let of = if *share < 10.0 {
                format!("{:.0} % of tol", 100.0 * share)
            } else {
                format!("{}× tol", fmt_num(*share))
            };
            format!("{} ({of})", fmt_num(error.abs))
        }
        Some(w) => format!("{} (rel {})", fmt_num(w.error.abs), fmt_num(w.error.rel)),
        None => "-".into(),
    }
}

/// `text` cut to `width` characters, with `…` where it was cut.
pub fn fit(text: &str, width: usize) -> String {
    if text.chars().count() <= width {
        return text.to_string();
    }
    let kept: String = text.chars().take(width.saturating_sub(1)).collect();
    format!("{kept}…")
}

/// A task's status as the table shows it: a scene waiting for several tasks says how many
/// (the details below, and `pbrlab needs SCENE`, name them).
pub(super) fn status_cell(t: &TaskOutcome) -> String {
    match &t.status {
        TaskStatus::NeedsTask { task } if task.contains(", ") => {
            format!("needs {} tasks", task.split(", ").count())
        }
        status => status.label(),
    }
}

/// The width of the terminal the table is laid out for: every line of a [`Detail::Compact`]
/// text fits it.
pub const WIDTH: usize = 80;

/// The most lines of detail [`Detail::Compact`] shows for one task (`--verbose` shows all).
pub const COMPACT_LINES: usize = 12;

/// How much of a report [`text`] shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Detail {
    /// What fits an 80×24 terminal: a row per task that has a grade, one line for the tasks
    /// not attempted yet and one for the scenes that wait for tasks, then at most
    /// [`COMPACT_LINES`] lines of detail per task that did not pass, every line at most
    /// [`WIDTH`] characters.
    #[default]
    Compact,
    /// A row per task and scene, every line of detail, and the protections of the workers'
    /// sandbox even when all were in force.
    Verbose,
}

/// One row of the table: at most 76 characters, so it fits an 80-column terminal.
pub(super) fn row(s: &mut String, task: &str, status: &str, points: &str, worst: &str, time: &str) {
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

/// `line` as it is when it fits [`WIDTH`] (a compiler's message keeps its alignment), else
/// broken at spaces into lines of at most that width (a longer word is cut), each
/// continuation indented like `line` and two more.
pub fn wrap(line: &str) -> Vec<String> {
    if line.chars().count() <= WIDTH {
        return vec![line.to_string()];
    }
    let indent = line.len() - line.trim_start().len();
    let mut lines = Vec::new();
    let mut current = " ".repeat(indent);
    let mut empty = true;
    for word in line.split_whitespace() {
        if !empty && current.chars().count() + 1 + word.chars().count() > WIDTH {
            lines.push(std::mem::replace(&mut current, " ".repeat(indent + 2)));
            empty = true;
        }
        if !empty {
            current.push(' ');
        }
        current.push_str(word);
        empty = false;
    }
    lines.push(current);
    lines.into_iter().map(|l| fit(&l, WIDTH)).collect()
}

/// `label (N nouns, P points): a, b, c`, wrapped to [`WIDTH`].
fn folded(s: &mut String, label: &str, noun: &str, names: &[&str], points: f64, after: &str) {
    if names.is_empty() {
        return;
    }
    let line = format!(
        "{label} ({} {noun}{}, {} points): {}{after}",
        names.len(),
        if names.len() == 1 { "" } else { "s" },
        format_points(points),
        names.join(", ")
    );
    for l in wrap(&line) {
        let _ = writeln!(s, "{l}");
    }
}

/// The table: task, status, points, worst error, time (one row per task and scene, 76
/// columns); the total; then what failed, per task. [`Detail::Compact`] folds the tasks not
/// attempted and the scenes that wait for tasks into a line each and keeps what follows
/// short (see [`Detail`]).
pub fn text(report: &GradeReport, detail: Detail) -> String {
    let verbose = detail == Detail::Verbose;
    let folds = |t: &TaskOutcome| !verbose && t.folds();
    let mut s = String::new();
    row(&mut s, "task", "status", "points", "worst error", "time");
    let rule = "-".repeat(76);
    let _ = writeln!(s, "{rule}");
    for t in report.tasks.iter().filter(|t| !folds(t)) {
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
    if !verbose {
        let group = |keep: &dyn Fn(&TaskOutcome) -> bool| {
            let chosen: Vec<&TaskOutcome> = report.tasks.iter().filter(|t| keep(t)).collect();
            let points = chosen.iter().map(|t| t.max_points).sum::<f64>();
            let names: Vec<&str> = chosen
                .iter()
                .map(|t| t.task.strip_prefix("scene: ").unwrap_or(&t.task))
                .collect();
            (names, points)
        };
        let (names, points) = group(&|t| t.status == TaskStatus::NotAttempted);
        folded(&mut s, "not attempted", "task", &names, points, "");
        let (names, points) = group(&TaskOutcome::scene_waits);
        folded(
            &mut s,
            "waiting for their tasks",
            "scene",
            &names,
            points,
            " (the `needs` command names them)",
        );
    }
    let _ = writeln!(s, "{rule}");
    let total = format!(
        "{}/{}",
        format_points(report.score),
        format_points(report.max_score)
    );
    let time = format!("{:.2}s", report.seconds);
    row(&mut s, "total", &report.implementation, &total, "", &time);
    for line in report_notes(report).iter().flat_map(|n| wrap(n)) {
        let _ = writeln!(s, "{line}");
    }
    // The compact table names the protections only when one of them was not in force.
    for protections in &report.sandbox {
        if verbose || !crate::grade::sandbox::all_in_force(protections) {
            for line in wrap(&format!("sandbox of the workers: {protections}")) {
                let _ = writeln!(s, "{line}");
            }
        }
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
        if details.is_empty() {
            continue;
        }
        let _ = write!(s, "\n{}: {}\n", t.task, t.status.label());
        if verbose {
            s += &details;
            continue;
        }
        let lines: Vec<String> = details.lines().flat_map(wrap).collect();
        for line in lines.iter().take(COMPACT_LINES) {
            let _ = writeln!(s, "{line}");
        }
        if lines.len() > COMPACT_LINES {
            let _ = writeln!(
                s,
                "  … and {} more lines (grade with --verbose to see them)",
                lines.len() - COMPACT_LINES
            );
        }
    }
    if verbose && !waiting.is_empty() {
        let _ = writeln!(
            s,
            "\nScenes are graded once the tasks they call pass: {}.",
            waiting.join("; ")
        );
    }
    s
}

/// The lines every report shows under its total: the variant graded and how much of a
/// failing case the course shows.
pub fn report_notes(report: &GradeReport) -> Vec<String> {
    let mut notes = Vec::new();
    if let Some(variant) = &report.variant {
        notes.push(format!(
            "variant {variant} (your own hidden cases and seeds)"
        ));
    }
    if let Some(notice) = report.feedback.notice() {
        notes.push(notice.to_string());
    }
    notes
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
        | TaskStatus::Failed
        | TaskStatus::Partial => {}
    }
    if matches!(t.status, TaskStatus::Failed | TaskStatus::Partial) {
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
            for m in c.shrunk.iter().map(|(full, _)| full).chain(&c.failures) {
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
        check.fail("case 1 is off".into(), "case 1".into());
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

    /// The worst error of a case that passed is shown against its tolerance, never as a
    /// relative error that is large only because the expected value is near 0.
    #[test]
    fn the_worst_error_is_shown_as_a_share_of_its_tolerance() {
        let mut t = failed_with(CheckKind::Values, 0.0);
        t.status = TaskStatus::Passed;
        let error = crate::grade::tolerance::Error {
            abs: 5.3e-10,
            rel: 1.64,
        };
        t.checks[0].worst = Some(Worst {
            case: "refract(…)".into(),
            error,
            share: Some(0.02),
        });
        assert_eq!(worst(&t), "5.3e-10 (2 % of tol)");
        t.status = TaskStatus::Failed;
        t.checks[0].worst.as_mut().unwrap().share = Some(90.0);
        assert_eq!(worst(&t), "5.3e-10 (90× tol)");
        t.checks[0].worst.as_mut().unwrap().share = None;
        assert!(worst(&t).contains("rel"), "{}", worst(&t));
    }

    /// A report in which every task of the worksheet failed with `lines` messages (one of
    /// them 205 characters long) after printing five lines, and two scenes wait.
    fn all_failing(lines: usize) -> GradeReport {
        let mut tasks: Vec<TaskOutcome> = crate::worksheet::TaskId::ALL
            .iter()
            .map(|task| {
                let mut check = CheckResult::new("values", CheckKind::Values);
                check.total = lines;
                check.fail(format!("{} long", "word ".repeat(40)), "long".into());
                for case in 1..lines {
                    check.fail(format!("case {case} is off"), format!("case {case}"));
                }
                check.finish();
                TaskOutcome {
                    task: task.name().into(),
                    status: TaskStatus::Failed,
                    points: 0.0,
                    max_points: 5.0,
                    checks: vec![check],
                    output: (1..=5).map(|i| format!("printed {i}\n")).collect(),
                    seconds: 0.0,
                }
            })
            .collect();
        for scene in ["cornell", "smoke"] {
            tasks.push(TaskOutcome {
                task: format!("scene: {scene}"),
                status: TaskStatus::NeedsTask {
                    task: "path_trace, mis".into(),
                },
                points: 0.0,
                max_points: 4.0,
                checks: Vec::new(),
                output: String::new(),
                seconds: 0.0,
            });
        }
        GradeReport::new("student", 1, false, tasks, 1.0)
    }

    #[test]
    fn the_compact_text_fits_80_columns_and_cuts_each_failure_short() {
        let report = all_failing(40);
        let compact = text(&report, Detail::Compact);
        for line in compact.lines() {
            assert!(line.chars().count() <= WIDTH, "{line}");
        }
        assert!(
            compact.contains("waiting for their tasks (2 scenes, 8 points): cornell, smoke"),
            "{compact}"
        );
        assert!(!compact.contains("scene: cornell"), "{compact}");
        // Per task: its heading, at most COMPACT_LINES lines, and the line that says more.
        let smith: Vec<&str> = compact
            .split("\nsmith_g1: FAILED\n")
            .nth(1)
            .expect("smith_g1's details")
            .split("\n\n")
            .next()
            .unwrap()
            .lines()
            .collect();
        assert_eq!(smith.len(), COMPACT_LINES + 1, "{smith:#?}");
        assert!(smith[COMPACT_LINES].contains("more lines"), "{smith:#?}");
        // Verbose has every row and every line, uncut.
        let verbose = text(&report, Detail::Verbose);
        assert!(verbose.contains("scene: cornell"), "{verbose}");
        assert!(verbose.contains("printed 5"), "{verbose}");
        assert!(
            verbose.contains(&format!("{} long", "word ".repeat(40))),
            "{verbose}"
        );
    }

    #[test]
    fn a_long_line_wraps_at_spaces_and_a_short_one_keeps_its_alignment() {
        let short = "   |     ^^^^ expected `f32`";
        assert_eq!(wrap(short), vec![short.to_string()]);
        let long = format!("  {}", "word ".repeat(30));
        let wrapped = wrap(&long);
        assert!(wrapped.len() >= 2, "{wrapped:#?}");
        assert!(wrapped.iter().all(|l| l.chars().count() <= WIDTH));
        assert!(wrapped[1].starts_with("    word"), "{wrapped:#?}");
        assert_eq!(
            wrapped
                .iter()
                .map(|l| l.split_whitespace().count())
                .sum::<usize>(),
            30
        );
    }

    #[test]
    fn a_failed_statistical_check_says_how_often_correct_code_fails_it() {
        let text = details(&failed_with(CheckKind::Sampling, 5e-4));
        assert!(text.contains("probability 5e-4"), "{text}");
        let text = details(&failed_with(CheckKind::Values, 0.0));
        assert!(!text.contains("probability"), "{text}");
    }
}
