//! The settings a package grades with, written by `pbrlab autograder …` into the package as
//! [`FILE`] and read back for every submission. The package stays with the instructor (the
//! student never sees it), so the hidden seed is safe there.

use crate::grade::credit::Credit;
use crate::grade::feedback::Feedback;
use serde::{Deserialize, Serialize};
use std::path::Path;

/// The name of the settings file at the top of the package's source tree.
pub const FILE: &str = "pbrlab-autograder.json";

/// How a package grades a submission.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Config {
    /// The seed of the statistical checks.
    pub seed: u64,
    /// The seed of the hidden random cases.
    pub hidden_seed: u64,
    /// Time limit per task, in seconds.
    pub task_timeout: f64,
    /// Time for the whole submission (build and grade), in seconds: results are written by
    /// then, whatever happens. Below the service's own limit (10 minutes on both).
    pub deadline: f64,
    /// Memory (address space) limit per worker, in MiB.
    pub memory_limit_mb: u64,
    /// Tasks graded at once (Gradescope's default container has half a CPU).
    pub jobs: usize,
    /// How partly right checks are credited (`{"policy": "per_region"}`, `per_case`,
    /// `all_or_nothing`, or `{"policy": "threshold", "fraction": 0.9}`).
    #[serde(default)]
    pub credit: Credit,
    /// How much of a failing case a student sees (`"full"`, `"actual"`: input and output,
    /// never the expected answer, or `"none"`: which checks failed).
    #[serde(default)]
    pub feedback: Feedback,
    /// The course secret of per-student variants: set, each student's hidden cases and
    /// seeds come from it and the student's id (Gradescope's user id, PrairieLearn's
    /// variant seed) in place of `hidden_seed` and `seed`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub variant_key: Option<String>,
}

impl Config {
    /// The default settings, with `hidden_seed`.
    pub fn new(hidden_seed: u64) -> Self {
        Self {
            seed: crate::grade::runner::DEFAULT_SEED,
            hidden_seed,
            task_timeout: crate::grade::runner::DEFAULT_TASK_TIMEOUT_SECONDS,
            deadline: 540.0,
            memory_limit_mb: crate::grade::runner::DEFAULT_MEMORY_LIMIT_MIB,
            jobs: 1,
            credit: Credit::default(),
            feedback: Feedback::default(),
            variant_key: None,
        }
    }

    /// Reads the settings file `path`.
    pub fn load(path: &Path) -> anyhow::Result<Self> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| anyhow::anyhow!("reading {}: {e}", path.display()))?;
        serde_json::from_str(&text).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))
    }
}
