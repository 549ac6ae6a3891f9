//! How grading a task ended ([`TaskStatus`]): written by the grader into each task's
//! outcome and the student's progress record, read by `pbrlab tasks` and `pbrlab hint`.

use serde::{Deserialize, Serialize};

/// How grading a task ended.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "status", rename_all = "snake_case")]
pub enum TaskStatus {
    /// Every check passed.
    Passed,
    /// At least one check failed and the task lost more than its pass threshold
    /// (the grader's pass share of its points kept).
    Failed,
    /// Some check failed, but the task kept at least the grader's pass share of its points (a bug confined to a region or
    /// two): not failed, and the scenes that need it are not withheld.
    Partial,
    /// The task is still the shipped `todo!()` stub.
    NotAttempted,
    /// The checks stopped at another task's stub (only without the reference, where the
    /// student's own dependencies are used).
    NeedsTask {
        /// The task that must be written first.
        task: String,
    },
    /// The student's code brought the worker process down; the task scores 0.
    Crashed {
        /// What happened, in words (timeout, stack overflow, out of memory, …).
        reason: String,
    },
    /// The task's file did not compile; its shipped stub was built in its place, so the
    /// other tasks could be graded. The task scores 0.
    CompileError {
        /// The compiler's messages.
        message: String,
    },
    /// The task has no checks yet (its code arrives with the renderer).
    NoChecks,
    /// The grader itself failed on this task (not the student's code); grade again.
    GraderError {
        /// What went wrong.
        message: String,
    },
}

impl TaskStatus {
    /// A short label for tables.
    pub fn label(&self) -> String {
        match self {
            TaskStatus::Passed => "passed".into(),
            TaskStatus::Failed => "FAILED".into(),
            TaskStatus::Partial => "partly right".into(),
            TaskStatus::NotAttempted => "not attempted".into(),
            TaskStatus::NeedsTask { task } => format!("needs {task}"),
            TaskStatus::Crashed { .. } => "CRASHED".into(),
            TaskStatus::CompileError { .. } => "COMPILE ERROR".into(),
            TaskStatus::NoChecks => "no checks yet".into(),
            TaskStatus::GraderError { .. } => "GRADER ERROR".into(),
        }
    }
}
