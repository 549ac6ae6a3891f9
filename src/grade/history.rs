//! The student's grades, kept for `pbrlab tasks`: the JSON report of the last `pbrlab grade`
//! of the student's code (`last-grade.json`), and the latest outcome of every task and scene
//! ever graded with the time it was graded (`progress.json`), so grading two tasks does not
//! forget the others. Both live in `.pbrlab/` at the project root (or in
//! `$PBRLAB_STATE_DIR`).

use super::verdict::{GradeReport, TaskOutcome};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::time::{Duration, SystemTime};

/// Where pbrlab keeps its state.
pub fn state_dir() -> PathBuf {
    std::env::var_os("PBRLAB_STATE_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| crate::repository_root().join(".pbrlab"))
}

/// The file of the last grade.
pub fn last_grade_path() -> PathBuf {
    state_dir().join("last-grade.json")
}

/// The file of every task's latest outcome.
pub fn progress_path() -> PathBuf {
    state_dir().join("progress.json")
}

/// A task's (or scene's) latest outcome and when it was graded.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Graded {
    /// The outcome.
    pub outcome: TaskOutcome,
    /// When, in seconds since the Unix epoch.
    pub at: u64,
}

impl Graded {
    /// When it was graded.
    pub fn time(&self) -> SystemTime {
        SystemTime::UNIX_EPOCH + Duration::from_secs(self.at)
    }
}

/// Every task's and scene's latest outcome, by name (`smith_g1`, `scene: cornell`).
pub type Progress = BTreeMap<String, Graded>;

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
    let mut progress = load_progress();
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

/// The progress record (empty when there is none or it cannot be read).
pub fn load_progress() -> Progress {
    std::fs::read_to_string(progress_path())
        .ok()
        .and_then(|text| serde_json::from_str(&text).ok())
        .unwrap_or_default()
}
