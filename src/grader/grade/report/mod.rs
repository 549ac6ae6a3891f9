//! Reports of a grading run: a terminal table, JSON, Gradescope's and PrairieLearn's
//! results.json, JUnit XML and an HTML page.

pub mod github_classroom;
pub mod gradescope;
mod html;
pub mod images;
pub mod junit;
pub mod prairielearn;
pub mod redact;
pub mod screen;
mod svg;
mod text;

pub use gradescope::gradescope;
pub(crate) use html::escape;
pub use html::write_html;
pub use text::{COMPACT_LINES, Detail, WIDTH, details, fit, report_notes, text, wrap};

/// The output formats of `pbrlab grade --format`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// A table for the terminal.
    #[default]
    Text,
    /// The full report as JSON (what `pbrlab tasks` reads back).
    Json,
    /// Gradescope's results.json.
    Gradescope,
    /// PrairieLearn's external-grader results.json.
    Prairielearn,
    /// JUnit XML (GitLab CI, Jenkins, CodeGrade): a suite per task, a case per check.
    Junit,
    /// GitHub Classroom: a `TASK=BASE64` line per task, each the grading reporter's result
    /// of one runner (for `$GITHUB_OUTPUT`; `autograder github-classroom` writes the
    /// workflow).
    GithubClassroom,
}

/// `report` in `format` (`detail` is how much the text table shows).
pub fn render(
    report: &super::verdict::GradeReport,
    format: Format,
    detail: Detail,
) -> anyhow::Result<String> {
    Ok(match format {
        Format::Text => text(report, detail),
        Format::Json => serde_json::to_string_pretty(report)?,
        Format::Gradescope => serde_json::to_string_pretty(&gradescope(report))?,
        Format::Prairielearn => {
            serde_json::to_string_pretty(&prairielearn::prairielearn(report, ""))?
        }
        Format::Junit => junit::junit([(None, Ok(report))]),
        Format::GithubClassroom => github_classroom::github_classroom(report),
    })
}
