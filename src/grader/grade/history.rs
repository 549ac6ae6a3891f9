//! Saving the student's grades where `pbrlab tasks` and `pbrlab hint` read them
//! ([`pbrlab_course::history`]: the files, and what is read of them): the last report
//! whole, and each task's outcome over the earlier ones.

use super::verdict::{GradeReport, TaskOutcome};
use pbrlab_course::history::{Graded, Progress, last_grade_path, load_progress, progress_path};
use std::time::SystemTime;

/// Stores `report` as the last grade, and its outcomes over the earlier ones in the
/// progress record.
pub fn save(report: &GradeReport) -> anyhow::Result<()> {
    crate::atomic_file::write(
        &last_grade_path(),
        serde_json::to_string_pretty(report)?.as_bytes(),
    )?;
    let at = SystemTime::now()
        .duration_since(SystemTime::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let mut progress: Progress<TaskOutcome> = load_progress();
    for outcome in &report.tasks {
        let graded = Graded {
            outcome: outcome.clone(),
            at,
        };
        progress.insert(outcome.task.clone(), graded);
    }
    crate::atomic_file::write(
        &progress_path(),
        serde_json::to_string_pretty(&progress)?.as_bytes(),
    )
}
