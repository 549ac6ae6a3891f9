//! Grading a whole class: autograder packages for Gradescope and PrairieLearn, a GitHub
//! Classroom template repository ([`github_classroom`]: public cases only), and batch
//! regrades (`grade-class`). Every submission is graded the same way: only its exercise
//! files are taken ([`submission`]), written over the shipped stubs in a scratch folder,
//! built into a worker of its own with a compile error costing only its task
//! ([`crate::grade::student_build`]), and graded with the hidden cases; the results file is
//! always written, and valid ([`schema`]).

pub mod class;
pub mod config;
pub mod github_classroom;
pub mod gradebook;
pub mod item_analysis;
pub mod package;
pub mod regrade;
pub mod run;
pub mod schema;
pub mod student_result;
pub mod submission;
pub mod try_package;

use crate::worksheet::TaskId;
use std::path::Path;

/// The shipped stub of `task` in a package or repository whose `exercises/` holds the stubs
/// as shipped (a package always does: it is written from them).
pub fn stub_in(root: &Path, task: TaskId) -> anyhow::Result<String> {
    let file = root.join("exercises").join(format!("{}.rs", task.name()));
    std::fs::read_to_string(&file)
        .map_err(|e| anyhow::anyhow!("reading the stub {}: {e}", file.display()))
}
