//! The audit of a regrade (`grade-class --regrade`): for each student, what changed between
//! the grade saved by an earlier run and the new one, entry by entry (tasks and scenes) and
//! check by check, and a class summary. A new result that is not a grade (the grading
//! machinery failed) never replaces a saved grade: it is listed as kept.

use super::student_result::{StudentResult, SubmissionStatus};
use crate::grade::verdict::{GradeReport, format_points};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::fmt::Write;

/// What a regrade changed for one student.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StudentChange {
    /// The student.
    pub student: String,
    /// The status before and after (`graded`, `build error`, `not graded`).
    pub status: (SubmissionStatus, SubmissionStatus),
    /// The score before and after (none without a grade).
    pub score: (Option<f64>, Option<f64>),
    /// The entries whose points or checks changed.
    pub entries: Vec<EntryChange>,
    /// Why the saved grade was kept: the regrade failed for a reason that is not the
    /// student's (the new status was `not graded`).
    pub kept: Option<String>,
    /// The variant graded before and after (none without `--variant-key`): a regrade with
    /// another key, or none, grades other hidden cases.
    #[serde(default)]
    pub variant: (Option<String>, Option<String>),
}

/// What changed in one entry (a task or a scene) of a student's grade.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct EntryChange {
    /// The entry (`smith_g1`, `scene: cornell`).
    pub entry: String,
    /// Points before and after.
    pub points: (f64, f64),
    /// The checks whose verdict changed: name, passed before (none: no such check then),
    /// passed after (none: no such check now).
    pub checks: Vec<(String, Option<bool>, Option<bool>)>,
}

impl StudentChange {
    /// True when nothing about the grade changed (only timings may differ).
    pub fn unchanged(&self) -> bool {
        self.status.0 == self.status.1
            && self.variant.0 == self.variant.1
            && self.entries.is_empty()
            && self.kept.is_none()
            && same_points(self.score.0, self.score.1)
    }
}

fn same_points(a: Option<f64>, b: Option<f64>) -> bool {
    match (a, b) {
        (Some(a), Some(b)) => (a - b).abs() < 1e-9,
        (a, b) => a.is_none() && b.is_none(),
    }
}

/// Each entry's points and each check's verdict in `report`.
fn verdicts(report: Option<&GradeReport>) -> BTreeMap<String, (f64, BTreeMap<String, bool>)> {
    report
        .map(|r| {
            r.tasks
                .iter()
                .map(|t| {
                    let checks = t
                        .checks
                        .iter()
                        .map(|c| (c.name.clone(), c.passed))
                        .collect();
                    (t.task.clone(), (t.points, checks))
                })
                .collect()
        })
        .unwrap_or_default()
}

/// What changed from the saved result `old` to the new one, `new`.
pub fn compare(old: &StudentResult, new: &StudentResult) -> StudentChange {
    let kept = (new.status == SubmissionStatus::NotGraded
        && old.status != SubmissionStatus::NotGraded)
        .then(|| new.message.clone());
    let (before, after) = (verdicts(old.report.as_ref()), verdicts(new.report.as_ref()));
    let mut entries = Vec::new();
    if kept.is_none() {
        let names: std::collections::BTreeSet<&String> =
            before.keys().chain(after.keys()).collect();
        for name in names {
            let empty = (0.0, BTreeMap::new());
            let (old_points, old_checks) = before.get(name).unwrap_or(&empty);
            let (new_points, new_checks) = after.get(name).unwrap_or(&empty);
            let check_names: std::collections::BTreeSet<&String> =
                old_checks.keys().chain(new_checks.keys()).collect();
            let checks: Vec<(String, Option<bool>, Option<bool>)> = check_names
                .into_iter()
                .map(|c| {
                    (
                        c.clone(),
                        old_checks.get(c).copied(),
                        new_checks.get(c).copied(),
                    )
                })
                .filter(|(_, was, now)| was != now)
                .collect();
            if (old_points - new_points).abs() > 1e-9 || !checks.is_empty() {
                entries.push(EntryChange {
                    entry: name.clone(),
                    points: (*old_points, *new_points),
                    checks,
                });
            }
        }
    }
    StudentChange {
        student: new.student.clone(),
        status: (old.status, new.status),
        score: (
            old.report.as_ref().map(|r| r.score),
            new.report.as_ref().map(|r| r.score),
        ),
        entries,
        kept,
        variant: (
            old.report.as_ref().and_then(|r| r.variant.clone()),
            new.report.as_ref().and_then(|r| r.variant.clone()),
        ),
    }
}

/// `old → new`.
fn old_new(old: impl std::fmt::Display, new: impl std::fmt::Display) -> String {
    format!("{old} → {new}")
}

/// The change report (`changes.md`): a class summary, then each student whose grade
/// changed or was kept, with old → new points per entry and the checks whose verdict
/// changed.
pub fn report(changes: &[StudentChange]) -> String {
    let changed: Vec<&StudentChange> = changes.iter().filter(|c| !c.unchanged()).collect();
    let kept = changed.iter().filter(|c| c.kept.is_some()).count();
    let delta = |c: &StudentChange| match c.score {
        (Some(a), Some(b)) => b - a,
        _ => 0.0,
    };
    let up = changed
        .iter()
        .filter(|c| c.kept.is_none() && delta(c) > 1e-9)
        .count();
    let down = changed
        .iter()
        .filter(|c| c.kept.is_none() && delta(c) < -1e-9)
        .count();
    let mut per_entry: BTreeMap<&str, usize> = BTreeMap::new();
    for change in &changed {
        for entry in &change.entries {
            *per_entry.entry(entry.entry.as_str()).or_default() += 1;
        }
    }
    let mut out = String::from("# Regrade: what changed\n\n");
    let _ = writeln!(
        out,
        "{} submissions regraded: {} unchanged, {} changed ({up} up, {down} down, {} other), \
         {kept} kept (the regrade failed for reasons not the student's; the saved grade stands).\n",
        changes.len(),
        changes.len() - changed.len(),
        changed.len() - kept,
        changed.len() - kept - up - down,
    );
    if !per_entry.is_empty() {
        out.push_str("| entry | students whose points or checks changed |\n|---|---|\n");
        for (entry, count) in &per_entry {
            let _ = writeln!(out, "| {entry} | {count} |");
        }
        out.push('\n');
    }
    let points = |p: Option<f64>| p.map_or("-".to_string(), format_points);
    let verdict = |v: Option<bool>| match v {
        Some(true) => "passed",
        Some(false) => "failed",
        None => "absent",
    };
    for change in changed {
        let mut heading = format!("## {}\n\n", change.student)
            + &old_new(points(change.score.0), points(change.score.1));
        if change.status.0 != change.status.1 {
            heading += &format!(
                " ({})",
                old_new(change.status.0.label(), change.status.1.label())
            );
        }
        if change.variant.0 != change.variant.1 && change.kept.is_none() {
            let name = |v: &Option<String>| v.clone().unwrap_or_else(|| "none".into());
            heading += &format!(
                " (variant {}: another key grades other hidden cases)",
                old_new(name(&change.variant.0), name(&change.variant.1))
            );
        }
        let _ = writeln!(out, "{heading}");
        if let Some(reason) = &change.kept {
            let _ = writeln!(out, "\nKept the saved grade; the regrade failed: {reason}");
        }
        for entry in &change.entries {
            let (from, to) = entry.points;
            let _ = writeln!(
                out,
                "- {}: {}",
                entry.entry,
                old_new(format_points(from), format_points(to))
            );
            for (check, was, now) in &entry.checks {
                let _ = writeln!(
                    out,
                    "  - {check}: {}",
                    old_new(verdict(*was), verdict(*now))
                );
            }
        }
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grade::verdict::{CheckKind, CheckResult, TaskOutcome, TaskStatus};

    fn result(status: SubmissionStatus, smith_g1: Option<(f64, bool)>) -> StudentResult {
        let report = smith_g1.map(|(points, passed)| {
            let mut check = CheckResult::new("values", CheckKind::Values);
            check.passed = passed;
            let task = TaskOutcome {
                task: "smith_g1".into(),
                status: TaskStatus::Passed,
                points,
                max_points: 6.0,
                checks: vec![check],
                output: String::new(),
                seconds: 0.1,
            };
            GradeReport::new("student", 1, false, vec![task], 1.0)
        });
        StudentResult {
            student: "ada".into(),
            status,
            message: if status == SubmissionStatus::NotGraded {
                "the worker binary is missing".into()
            } else {
                String::new()
            },
            taken: Vec::new(),
            ignored: Vec::new(),
            report,
            seconds: 2.0,
        }
    }

    #[test]
    fn a_changed_verdict_is_listed_with_old_and_new_points() {
        let change = compare(
            &result(SubmissionStatus::Graded, Some((6.0, true))),
            &result(SubmissionStatus::Graded, Some((0.0, false))),
        );
        assert!(!change.unchanged());
        assert_eq!(change.entries.len(), 1);
        assert_eq!(change.entries[0].points, (6.0, 0.0));
        assert_eq!(
            change.entries[0].checks,
            vec![("values".to_string(), Some(true), Some(false))]
        );
        let text = report(&[change]);
        assert!(text.contains("1 changed (0 up, 1 down"), "{text}");
        assert!(text.contains("- smith_g1: 6 → 0"), "{text}");
        assert!(text.contains("  - values: passed → failed"), "{text}");
    }

    #[test]
    fn the_same_grade_is_no_change_and_a_failed_regrade_keeps_the_saved_grade() {
        let graded = result(SubmissionStatus::Graded, Some((6.0, true)));
        assert!(compare(&graded, &graded.clone()).unchanged());
        let failed = compare(&graded, &result(SubmissionStatus::NotGraded, None));
        assert_eq!(failed.kept.as_deref(), Some("the worker binary is missing"));
        assert!(failed.entries.is_empty());
        let text = report(&[failed]);
        assert!(text.contains("1 kept"), "{text}");
        assert!(text.contains("Kept the saved grade"), "{text}");
    }
}
