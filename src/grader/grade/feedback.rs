//! Feedback levels: how much of a failing case a student sees, a per-course setting
//! (`--feedback full|actual|none`, and `feedback` in an autograder package's settings).
//!
//! A course that does not hand out answers grades as always and then shows the student a
//! redacted copy of the report ([`super::report::redact`]): at [`Feedback::Actual`] each failing case
//! gives its input and what the student's code returned (or how it went wrong), never what
//! was expected; at [`Feedback::None`] a check says only that it failed and how many of its
//! cases did. The redaction works on what every check records apart for the purpose
//! ([`super::verdict::CheckResult::shown`]), not by editing its messages, so a new check cannot leak an
//! expected value through a message it words differently. Hidden cases are never shown at
//! any level: their checks carry only a count. The instructor's own records (a class run's
//! `students/<name>.json`) stay in full.

use serde::{Deserialize, Serialize};

/// How much of a failing case a student-visible report shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "snake_case")]
pub enum Feedback {
    /// The input, what came back, what was expected, and every statistic (histograms,
    /// estimates against their analytic values, renders beside the reference).
    #[default]
    Full,
    /// The input and what came back, nothing of the expected answer.
    Actual,
    /// Only that a check failed, and how many of its cases.
    None,
}

impl Feedback {
    /// One sentence for the top of a report that is not in full.
    pub fn notice(self) -> Option<&'static str> {
        match self {
            Feedback::Full => None,
            Feedback::Actual => Some(
                "This course shows the input of a failing case and what your code returned, \
                 not the expected answer.",
            ),
            Feedback::None => Some(
                "This course shows which checks failed and how many of their cases, not the \
                 cases themselves.",
            ),
        }
    }
}
