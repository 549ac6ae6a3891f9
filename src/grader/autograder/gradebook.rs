//! Gradebook exports of a class run: `canvas.csv` for Canvas's gradebook import and
//! `moodle.csv` for Moodle's CSV grade import, one column per task and scene and a total.
//!
//! Canvas reads the identity columns `Student, ID, SIS User ID, SIS Login ID, Section`
//! (matching a row by ID, then SIS User ID, then SIS Login ID, then name; Section may be
//! empty), an optional row whose first cell is `Points Possible`, and one column per
//! assignment: a header that names no existing assignment creates one. Moodle's import maps
//! one column to its users (username, email or ID number, chosen in the import form) and
//! every other column to a grade item, new or existing; a new item's maximum is 100, so its
//! total is a percentage. A student whose grading failed for reasons not theirs
//! (`not graded`) has empty cells, which both import as "no grade", never as 0.
//!
//! Submission names are rarely the gradebook's ids, so a class list ([`Roster`]) can map
//! them: the gradebook's own CSV export serves, or any CSV with a header.

use super::student_result::{StudentResult, SubmissionStatus};
use crate::grade::verdict::{format_points, total};
use anyhow::Context;
use std::collections::BTreeMap;
use std::path::Path;

/// The identity columns of a Canvas gradebook, in Canvas's order.
const CANVAS_IDENTITY: [&str; 5] = ["Student", "ID", "SIS User ID", "SIS Login ID", "Section"];

/// The columns of a class list that may hold a submission's name, most specific first.
const NAME_COLUMNS: [&str; 9] = [
    "SIS Login ID",
    "SIS User ID",
    "Username",
    "Login",
    "Email address",
    "Email",
    "ID number",
    "ID",
    "Student",
];

/// A class list: per student, the cells of its row by column name.
#[derive(Clone, Debug, Default)]
pub struct Roster {
    rows: Vec<BTreeMap<String, String>>,
}

impl Roster {
    /// Reads the CSV class list `path` (a header row, then one row per student; a Canvas
    /// export's `Points Possible` row is skipped).
    pub fn load(path: &Path) -> anyhow::Result<Self> {
        let text =
            std::fs::read_to_string(path).with_context(|| format!("reading {}", path.display()))?;
        Self::parse(&text).with_context(|| format!("reading the class list {}", path.display()))
    }

    /// Reads a CSV class list from `text`.
    pub fn parse(text: &str) -> anyhow::Result<Self> {
        let mut reader = csv::ReaderBuilder::new()
            .flexible(true)
            .trim(csv::Trim::All)
            .from_reader(text.trim_start_matches('\u{feff}').as_bytes());
        let header: Vec<String> = reader
            .headers()
            .context("the class list has no header row")?
            .iter()
            .map(str::to_string)
            .collect();
        anyhow::ensure!(
            NAME_COLUMNS
                .iter()
                .any(|c| header.iter().any(|h| h.eq_ignore_ascii_case(c))),
            "the class list has none of the columns that name a student ({})",
            NAME_COLUMNS.join(", ")
        );
        let mut rows = Vec::new();
        for (line, record) in reader.records().enumerate() {
            let record = record.with_context(|| format!("row {}", line + 2))?;
            if record.get(0).is_some_and(|c| c.contains("Points Possible")) {
                continue;
            }
            rows.push(
                header
                    .iter()
                    .zip(record.iter())
                    .map(|(h, c)| (h.clone(), c.to_string()))
                    .collect(),
            );
        }
        Ok(Self { rows })
    }

    /// The row of the student whose submission is named `name`: the first whose cell in one
    /// of [`NAME_COLUMNS`] (tried in that order) is `name`, ignoring case.
    fn row(&self, name: &str) -> Option<&BTreeMap<String, String>> {
        NAME_COLUMNS.iter().find_map(|column| {
            self.rows.iter().find(|row| {
                row.iter()
                    .any(|(h, c)| h.eq_ignore_ascii_case(column) && c.eq_ignore_ascii_case(name))
            })
        })
    }

    /// The cell of `column` in `name`'s row, if the list has one.
    fn cell(&self, name: &str, column: &str) -> Option<&str> {
        self.row(name)?
            .iter()
            .find(|(h, _)| h.eq_ignore_ascii_case(column))
            .map(|(_, c)| c.as_str())
            .filter(|c| !c.is_empty())
    }

    /// The submission names the list does not know.
    pub fn unmatched<'a>(&self, names: impl IntoIterator<Item = &'a str>) -> Vec<&'a str> {
        names
            .into_iter()
            .filter(|n| self.row(n).is_none())
            .collect()
    }
}

/// A student's points in `entry`: `None` without a grade (the cell stays empty), 0 for a
/// build error.
fn points(result: &StudentResult, entry: &str) -> Option<f64> {
    match &result.report {
        Some(report) => Some(report.task(entry).map_or(0.0, |t| t.points)),
        None if result.status == SubmissionStatus::BuildError => Some(0.0),
        None => None,
    }
}

/// A student's total: `None` without a grade, 0 for a build error.
fn score(result: &StudentResult) -> Option<f64> {
    match &result.report {
        Some(report) => Some(report.score),
        None => points(result, ""),
    }
}

/// The most points of `entry` in any report (every graded report has the same).
fn possible(results: &[StudentResult], entry: &str) -> f64 {
    results
        .iter()
        .filter_map(|r| r.report.as_ref()?.task(entry))
        .map(|t| t.max_points)
        .fold(0.0, f64::max)
}

/// The CSV of `rows` (a header first), quoted as RFC 4180 has it, every cell neutralised
/// against formula injection ([`neutral`]): every file a class run writes for other
/// programs goes through here.
pub(crate) fn write(rows: Vec<Vec<String>>) -> anyhow::Result<String> {
    let mut out = csv::Writer::from_writer(Vec::new());
    for row in rows {
        out.write_record(row.iter().map(|cell| neutral(cell).into_owned()))?;
    }
    Ok(String::from_utf8(out.into_inner()?)?)
}

/// `cell` as a spreadsheet reads it as text: OWASP's rule against CSV injection, a cell
/// that starts with `=`, `+`, `-`, `@`, a tab or a carriage return gets a `'` in front,
/// unless it is a plain number (`-0.5`, points). Student names and class-list cells are
/// anyone's to choose.
fn neutral(cell: &str) -> std::borrow::Cow<'_, str> {
    let risky = cell.starts_with(['=', '+', '-', '@', '\t', '\r']);
    if risky && !plain_number(cell) {
        format!("'{cell}").into()
    } else {
        cell.into()
    }
}

/// A decimal number: a sign, digits, a fraction, an exponent (`-1.5e3`); nothing a
/// spreadsheet could read as a name or a formula (`-inf`, `+A1`).
fn plain_number(cell: &str) -> bool {
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    let unsigned = cell.strip_prefix(['+', '-']).unwrap_or(cell);
    let (mantissa, exponent) = match unsigned.split_once(['e', 'E']) {
        Some((m, e)) => (m, Some(e.strip_prefix(['+', '-']).unwrap_or(e))),
        None => (unsigned, None),
    };
    let mantissa_ok = match mantissa.split_once('.') {
        Some((whole, fraction)) => {
            (digits(whole) || whole.is_empty())
                && (digits(fraction) || fraction.is_empty())
                && !(whole.is_empty() && fraction.is_empty())
        }
        None => digits(mantissa),
    };
    mantissa_ok && exponent.is_none_or(digits)
}

fn cell(points: Option<f64>) -> String {
    points.map(format_points).unwrap_or_default()
}

/// The gradebook column of an entry: `pbrlab reflect`, `pbrlab scene: cornell`.
fn column(entry: &str) -> String {
    format!("pbrlab {entry}")
}

/// `canvas.csv`: Canvas's identity columns (from `roster` where it knows the student,
/// else the submission name as SIS Login ID), a `Points Possible` row, a column per entry
/// and `pbrlab total`.
pub fn canvas(
    results: &[StudentResult],
    entries: &[String],
    roster: &Roster,
) -> anyhow::Result<String> {
    let mut header: Vec<String> = CANVAS_IDENTITY.iter().map(|s| s.to_string()).collect();
    header.extend(entries.iter().map(|e| column(e)));
    header.push(column("total"));
    let mut rows = vec![header];
    let maxima: Vec<f64> = entries.iter().map(|e| possible(results, e)).collect();
    let mut points_possible = vec!["Points Possible".to_string()];
    points_possible.extend(std::iter::repeat_n(
        String::new(),
        CANVAS_IDENTITY.len() - 1,
    ));
    points_possible.extend(maxima.iter().map(|m| format_points(*m)));
    points_possible.push(format_points(total(maxima.iter().copied())));
    rows.push(points_possible);
    for r in results {
        let name = r.student.as_str();
        let mut row: Vec<String> = CANVAS_IDENTITY
            .iter()
            .map(|column| {
                roster
                    .cell(name, column)
                    .map(str::to_string)
                    .unwrap_or_else(|| match *column {
                        "Student" | "SIS Login ID" if roster.row(name).is_none() => name.into(),
                        _ => String::new(),
                    })
            })
            .collect();
        let scores: Vec<Option<f64>> = entries.iter().map(|e| points(r, e)).collect();
        row.extend(scores.iter().map(|p| cell(*p)));
        row.push(cell(score(r)));
        rows.push(row);
    }
    write(rows)
}

/// `moodle.csv`: `Username` and `Email address` (from `roster`, else the submission
/// name as username), then every entry and the total in percent of its points (a new
/// Moodle grade item's maximum is 100).
pub fn moodle(
    results: &[StudentResult],
    entries: &[String],
    roster: &Roster,
) -> anyhow::Result<String> {
    let mut header = vec!["Username".to_string(), "Email address".to_string()];
    header.extend(entries.iter().map(|e| column(&format!("{e} (%)"))));
    header.push(column("total (%)"));
    let mut rows = vec![header];
    let percent =
        |points: Option<f64>, of: f64| points.map(|p| if of > 0.0 { 100.0 * p / of } else { 0.0 });
    let available = total(entries.iter().map(|e| possible(results, e)));
    for r in results {
        let name = r.student.as_str();
        let username = ["Username", "SIS Login ID", "Login"]
            .iter()
            .find_map(|c| roster.cell(name, c))
            .unwrap_or(name);
        let email = ["Email address", "Email"]
            .iter()
            .find_map(|c| roster.cell(name, c))
            .unwrap_or_default();
        let mut row = vec![username.to_string(), email.to_string()];
        row.extend(
            entries
                .iter()
                .map(|e| cell(percent(points(r, e), possible(results, e)))),
        );
        row.push(cell(percent(score(r), available)));
        rows.push(row);
    }
    write(rows)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grade::verdict::{GradeReport, TaskOutcome, TaskStatus};

    fn result(student: &str, status: SubmissionStatus, points: Option<f64>) -> StudentResult {
        let report = points.map(|p| {
            let task = TaskOutcome {
                task: "reflect".into(),
                status: TaskStatus::Passed,
                points: p,
                max_points: 5.0,
                checks: Vec::new(),
                output: String::new(),
                seconds: 0.0,
            };
            GradeReport::new("student", 1, false, vec![task], 1.0)
        });
        StudentResult {
            student: student.into(),
            status,
            message: String::new(),
            taken: Vec::new(),
            ignored: Vec::new(),
            report,
            seconds: 1.0,
        }
    }

    fn class() -> Vec<StudentResult> {
        vec![
            result("ann", SubmissionStatus::Graded, Some(2.5)),
            result("bo", SubmissionStatus::BuildError, None),
            result("cy", SubmissionStatus::NotGraded, None),
        ]
    }

    fn parse(csv_text: &str) -> Vec<Vec<String>> {
        csv::ReaderBuilder::new()
            .has_headers(false)
            .flexible(true)
            .from_reader(csv_text.as_bytes())
            .records()
            .map(|r| r.unwrap().iter().map(str::to_string).collect())
            .collect()
    }

    #[test]
    fn canvas_reads_its_identity_columns_points_possible_and_empty_cells_for_no_grade() {
        let roster = Roster::parse(
            "Student,ID,SIS User ID,SIS Login ID,Section,Homework 1 (12)\n\
             Points Possible,,,,,10\n\
             \"Lee, Ann\",1001,s1,ann,A,7\n",
        )
        .unwrap();
        let entries = vec!["reflect".to_string()];
        let rows = parse(&canvas(&class(), &entries, &roster).unwrap());
        assert_eq!(
            rows[0],
            [
                "Student",
                "ID",
                "SIS User ID",
                "SIS Login ID",
                "Section",
                "pbrlab reflect",
                "pbrlab total"
            ]
        );
        assert_eq!(rows[1], ["Points Possible", "", "", "", "", "5", "5"]);
        assert_eq!(
            rows[2],
            ["Lee, Ann", "1001", "s1", "ann", "A", "2.5", "2.5"]
        );
        // Not in the class list: the submission name as name and SIS Login ID.
        assert_eq!(rows[3], ["bo", "", "", "bo", "", "0", "0"]);
        assert_eq!(rows[4], ["cy", "", "", "cy", "", "", ""], "no grade, not 0");
        assert_eq!(roster.unmatched(["ann", "bo"]), ["bo"]);
    }

    #[test]
    fn moodle_maps_users_by_username_or_email_and_totals_in_percent() {
        let roster = Roster::parse("Username,Email address\nann,ann@example.edu\n").unwrap();
        let rows = parse(&moodle(&class(), &["reflect".to_string()], &roster).unwrap());
        assert_eq!(rows[0][..2], ["Username", "Email address"]);
        assert_eq!(rows[0][2], "pbrlab reflect (%)");
        assert_eq!(rows[1], ["ann", "ann@example.edu", "50", "50"]);
        assert_eq!(rows[2], ["bo", "", "0", "0"]);
        assert_eq!(rows[3], ["cy", "", "", ""]);
    }

    #[test]
    fn cells_that_a_spreadsheet_would_run_are_written_as_text() {
        let hostile = [
            "=HYPERLINK(\"http://x\",\"y\")",
            "+1+cmd|' /C calc'!A0",
            "-2+3",
            "@SUM(A1:A9)",
            "\tx",
            "\r=1",
            "-inf",
        ];
        let plain = ["ada", "-2", "+1.5", "3.25e-2", "", "a=b"];
        let row: Vec<String> = hostile
            .iter()
            .chain(&plain)
            .map(|s| s.to_string())
            .collect();
        let text = write(vec![row.clone()]).unwrap();
        let mut reader = csv::ReaderBuilder::new()
            .has_headers(false)
            .from_reader(text.as_bytes());
        let back: Vec<String> = reader
            .records()
            .next()
            .unwrap()
            .unwrap()
            .iter()
            .map(String::from)
            .collect();
        for (cell, original) in back.iter().zip(&row) {
            if hostile.contains(&original.as_str()) {
                assert_eq!(*cell, format!("'{original}"), "{original:?}");
            } else {
                assert_eq!(cell, original);
            }
        }
    }

    #[test]
    fn a_class_list_without_a_name_column_is_refused() {
        let e = Roster::parse("Fruit,Colour\napple,red\n").unwrap_err();
        assert!(format!("{e:#}").contains("none of the columns"), "{e:#}");
    }
}
