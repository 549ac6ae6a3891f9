//! PrairieLearn's external-grader results.json
//! (<https://prairielearn.readthedocs.io/en/latest/externalGrading/>): a score in [0, 1] and
//! one test per task, built from the same split of points as Gradescope's. PrairieLearn has
//! no per-test visibility, so the hidden cases count in the score but are not listed.

use super::gradescope::gradescope;
use crate::grade::verdict::{GradeReport, format_points, total};
use serde::Serialize;

/// The top level of results.json.
#[derive(Debug, Serialize)]
pub struct Results {
    /// Whether the submission could be graded (a failed build is graded: score 0).
    pub gradable: bool,
    /// The score as a fraction of the points available, in [0, 1].
    pub score: f64,
    /// Shown above the tests.
    pub message: String,
    /// Shown below the message, monospaced.
    pub output: String,
    /// One entry per task (its visible checks).
    pub tests: Vec<Test>,
}

/// One test entry.
#[derive(Debug, Serialize)]
pub struct Test {
    /// The task and its title.
    pub name: String,
    /// Points scored (exact; shown to hundredths).
    #[serde(serialize_with = "crate::grade::verdict::serialize_points")]
    pub points: f64,
    /// Points available (exact; shown to hundredths).
    #[serde(serialize_with = "crate::grade::verdict::serialize_points")]
    pub max_points: f64,
    /// What was checked and what failed.
    pub output: String,
}

/// The PrairieLearn results of `report`; `message` goes first (e.g. the ignored files).
pub fn prairielearn(report: &GradeReport, message: &str) -> Results {
    let all = gradescope(report);
    let available = total(all.tests.iter().map(|t| t.max_score));
    let hidden = total(
        all.tests
            .iter()
            .filter(|t| t.visibility != "visible")
            .map(|t| t.max_score),
    );
    let mut text = message.to_string();
    if hidden > 0.0 {
        text += &format!(
            "{} of the {} points are hidden cases, counted in the score.\n",
            format_points(hidden),
            format_points(available)
        );
    }
    text += &all.output;
    Results {
        gradable: true,
        score: if available > 0.0 {
            (all.score / available).clamp(0.0, 1.0)
        } else {
            0.0
        },
        message: text,
        output: String::new(),
        tests: all
            .tests
            .into_iter()
            .filter(|t| t.visibility == "visible")
            .map(|t| Test {
                name: t.name,
                points: t.score,
                max_points: t.max_score,
                output: t.output,
            })
            .collect(),
    }
}

/// The results of a submission that could not be graded at all: score 0 and why.
pub fn failed(reason: &str) -> Results {
    Results {
        gradable: true,
        score: 0.0,
        message: format!("Not graded: {reason}"),
        output: String::new(),
        tests: Vec::new(),
    }
}
