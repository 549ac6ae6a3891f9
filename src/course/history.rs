//! The student's grades as pbrlab keeps them, in `.pbrlab/` at the project root (or in
//! `$PBRLAB_STATE_DIR`): the JSON report of the last `pbrlab grade` of the student's code
//! (`last-grade.json`), and the latest outcome of every task and scene ever graded with the
//! time it was graded (`progress.json`), so grading two tasks does not forget the others.
//! The grader writes them (its `grade::history`); `pbrlab tasks` and `pbrlab hint` read
//! the part of each outcome they show, a [`Standing`].

use crate::status::TaskStatus;
use serde::de::DeserializeOwned;
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

/// A task's (or scene's) latest outcome `O` and when it was graded.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Graded<O> {
    /// The outcome.
    pub outcome: O,
    /// When, in seconds since the Unix epoch.
    pub at: u64,
}

impl<O> Graded<O> {
    /// When it was graded.
    pub fn time(&self) -> SystemTime {
        SystemTime::UNIX_EPOCH + Duration::from_secs(self.at)
    }
}

/// What the commands that run no student code read of a task's outcome: how grading ended
/// and the points (the grader's outcome holds these fields and its checks besides).
#[derive(Clone, Debug, PartialEq, Deserialize)]
pub struct Standing {
    /// How grading ended.
    pub status: TaskStatus,
    /// Points scored.
    pub points: f64,
    /// Points available (0 for a task without checks).
    pub max_points: f64,
}

/// Every task's and scene's latest outcome, by name (`smith_g1`, `scene: cornell`).
pub type Progress<O = Standing> = BTreeMap<String, Graded<O>>;

/// The progress record (empty when there is none or it cannot be read).
pub fn load_progress<O: DeserializeOwned>() -> Progress<O> {
    std::fs::read_to_string(progress_path())
        .ok()
        .and_then(|text| serde_json::from_str(&text).ok())
        .unwrap_or_default()
}
