//! One student's result in a class run (`students/<name>.json`): how the run of the
//! submission ended and, when it was graded, the grade.

use crate::grade::verdict::GradeReport;
use serde::{Deserialize, Serialize};
use std::fmt;

/// How the run of one submission ended (written as `graded`, `build error` or `not graded`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum SubmissionStatus {
    /// Built and graded: the report is the grade.
    #[serde(rename = "graded")]
    Graded,
    /// The build ran into its bounds (a compile-time bomb): a grade of 0, which a rerun
    /// keeps.
    #[serde(rename = "build error")]
    BuildError,
    /// Not a grade: the grading machinery failed (the framework did not build, a crash of
    /// the grader). Graded again on the next run.
    #[serde(rename = "not graded")]
    NotGraded,
}

impl SubmissionStatus {
    /// The status as results and tables write it.
    pub fn label(self) -> &'static str {
        match self {
            SubmissionStatus::Graded => "graded",
            SubmissionStatus::BuildError => "build error",
            SubmissionStatus::NotGraded => "not graded",
        }
    }
}

impl fmt::Display for SubmissionStatus {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.label())
    }
}

/// The result of one student.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StudentResult {
    /// The student: the submission's folder or zip name.
    pub student: String,
    /// How the run ended, with the reason in `message`.
    pub status: SubmissionStatus,
    /// Why the submission was not graded, if it was not; for a graded one, what explains its
    /// grade (a submission with no exercise file in it), else empty.
    pub message: String,
    /// The files graded, as found in the submission.
    pub taken: Vec<String>,
    /// What was ignored, with the reasons.
    pub ignored: Vec<String>,
    /// The grade (none when the submission could not be built or graded).
    pub report: Option<GradeReport>,
    /// Wall time for the student, build included, in seconds.
    pub seconds: f64,
}
