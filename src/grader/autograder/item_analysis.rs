//! Item analysis of a class run: per entry (task or scene) and per check, how many of the
//! submissions that ran the check passed it, the failing input or configuration most of
//! them share, and what the check cost (wall time; the worker's peak resident memory by the
//! end of the check). `summary.md` has it as a table, `summary.html` as the same table with
//! a bar per check.
//!
//! A submission counts for a check when it ran it: a task not attempted or waiting for
//! another does not, and one stopped by a compile error has no checks to count. The failing input of a values or
//! stability check is the case's input (the part of its student-safe line before what the
//! code returned); for the other kinds the check's name is its configuration (`sampling:
//! cosine_sample …`, `estimator: furnace …`), so its most common failing input is the
//! check itself.

use crate::grade::report::escape;
use crate::grade::verdict::{CheckKind, CheckResult, GradeReport, TaskStatus};
use std::collections::BTreeMap;
use std::fmt::Write;

/// One check's row.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CheckRow {
    /// The entry (`smith_g1`, `scene: cornell`).
    pub entry: String,
    /// The check (`values`, `sampling: …`).
    pub check: String,
    /// Submissions that passed it.
    pub passed: usize,
    /// Submissions that ran it.
    pub ran: usize,
    /// The failing case most submissions share, with how many (values and stability).
    pub common_failure: Option<(String, usize)>,
    /// Mean and longest wall time, in seconds.
    pub seconds: (f64, f64),
    /// The largest peak memory a worker reported by the end of the check, in KiB.
    pub peak_kib: Option<u64>,
}

impl CheckRow {
    /// The share of the submissions that ran the check and passed it.
    pub fn pass_rate(&self) -> f64 {
        self.passed as f64 / self.ran.max(1) as f64
    }
}

/// The input of a failing case, from its student-safe line (`call: got … [case]`).
fn failing_input(check: &CheckResult, shown: &str) -> Option<String> {
    if !matches!(check.kind, CheckKind::Values | CheckKind::Stability) {
        return None;
    }
    let shown = shown
        .strip_prefix(crate::grade::values::SIMPLEST)
        .unwrap_or(shown);
    let (input, rest) = shown.split_once(": got ")?;
    // The case's name, where the line ends with one, makes the input unique.
    let case = rest
        .rsplit_once(" [")
        .map(|(_, name)| format!(" [{name}"))
        .unwrap_or_default();
    Some(format!("{input}{case}"))
}

/// The rows of `graded` for `entries`, hardest check first within each entry.
pub fn rows(graded: &[&GradeReport], entries: &[String]) -> Vec<CheckRow> {
    let mut all = Vec::new();
    for e in entries {
        let mut checks: BTreeMap<&str, (CheckRow, BTreeMap<String, usize>)> = BTreeMap::new();
        for outcome in graded.iter().filter_map(|g| g.task(e)) {
            if matches!(
                outcome.status,
                TaskStatus::NotAttempted | TaskStatus::NeedsTask { .. }
            ) {
                continue;
            }
            for c in &outcome.checks {
                let (row, failures) = checks.entry(c.name.as_str()).or_insert_with(|| {
                    (
                        CheckRow {
                            entry: e.clone(),
                            check: c.name.clone(),
                            ..CheckRow::default()
                        },
                        BTreeMap::new(),
                    )
                });
                row.ran += 1;
                row.passed += usize::from(c.passed);
                row.seconds.0 += c.seconds;
                row.seconds.1 = row.seconds.1.max(c.seconds);
                row.peak_kib = row.peak_kib.max(c.peak_memory_kib);
                for shown in c.shown.iter().filter_map(|s| failing_input(c, s)) {
                    *failures.entry(shown).or_default() += 1;
                }
            }
        }
        let mut rows: Vec<CheckRow> = checks
            .into_values()
            .map(|(mut row, failures)| {
                row.seconds.0 /= row.ran.max(1) as f64;
                row.common_failure = failures
                    .into_iter()
                    .max_by_key(|(input, n)| (*n, std::cmp::Reverse(input.clone())));
                row
            })
            .collect();
        rows.sort_by(|a, b| {
            a.pass_rate()
                .total_cmp(&b.pass_rate())
                .then(a.check.cmp(&b.check))
        });
        all.extend(rows);
    }
    all
}

/// Memory as a person reads it: `412 MiB`, `3.1 GiB`, `-` when unknown.
fn memory(kib: Option<u64>) -> String {
    match kib {
        None => "-".into(),
        Some(k) if k >= 1 << 20 => format!("{:.1} GiB", k as f64 / (1 << 20) as f64),
        Some(k) => format!("{} MiB", k.div_ceil(1 << 10)),
    }
}

fn common(row: &CheckRow) -> String {
    row.common_failure
        .as_ref()
        .map_or_else(|| "-".into(), |(input, n)| format!("{input} ({n})"))
}

/// The table of `summary.md`.
pub fn markdown(rows: &[CheckRow]) -> String {
    let mut s = String::from(
        "\n## Checks\n\nPer check, of the submissions that ran it: how many passed, the \
         failing case most of them share, the mean and longest time, and the largest peak \
         memory of a worker by the end of the check.\n\n\
         | entry | check | passed | ran | pass rate | most common failing case | time (mean / max) | peak memory |\n\
         |---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {:.0} % | {} | {:.2} / {:.2} s | {} |",
            r.entry,
            r.check.replace('|', "/"),
            r.passed,
            r.ran,
            100.0 * r.pass_rate(),
            common(r).replace('|', "/"),
            r.seconds.0,
            r.seconds.1,
            memory(r.peak_kib)
        );
    }
    s
}

/// `markdown` (the class summary: headings, lists, tables) as HTML. Raw HTML in it (a
/// student's name or message could hold some) is shown as text, never interpreted.
fn markdown_to_html(markdown: &str) -> String {
    use pulldown_cmark::{Event, Options, Parser};
    let events = Parser::new_ext(markdown, Options::ENABLE_TABLES).map(|event| match event {
        Event::Html(raw) | Event::InlineHtml(raw) => Event::Text(raw),
        other => other,
    });
    let mut html = String::new();
    pulldown_cmark::html::push_html(&mut html, events);
    html
}

/// `summary.html`: `head` (the class's counts and the table per entry, as Markdown, shown
/// as HTML) and the checks with a bar each for the pass rate, one self-contained page.
pub fn html(head: &str, rows: &[CheckRow]) -> String {
    let mut s = String::from(
        "<!doctype html><html lang=\"en\"><meta charset=\"utf-8\"><title>pbrlab class \
         summary</title><style>body{font:14px system-ui,sans-serif;margin:2em}\
         table{border-collapse:collapse}td,th{padding:2px 8px;border-bottom:1px solid #ddd;\
         text-align:left;vertical-align:top}.n{text-align:right}pre{white-space:pre-wrap}\
         </style>",
    );
    s += &markdown_to_html(head);
    s += "<h2>Checks, hardest first within each entry</h2><table><tr><th>entry</th>\
          <th>check</th><th>pass rate</th><th class=n>passed / ran</th>\
          <th>most common failing case</th><th class=n>time (mean / max)</th>\
          <th class=n>peak memory</th></tr>";
    for r in rows {
        let rate = r.pass_rate();
        // Red to green by pass rate; the bar's length is the rate.
        let hue = (120.0 * rate).round();
        let _ = write!(
            s,
            "<tr><td>{}</td><td>{}</td><td><svg width=\"160\" height=\"14\" role=\"img\">\
             <title>{:.0} %</title><rect width=\"160\" height=\"14\" fill=\"#eee\"/>\
             <rect width=\"{:.1}\" height=\"14\" fill=\"hsl({hue},60%,45%)\"/>\
             <text x=\"4\" y=\"11\" font-size=\"10\">{:.0} %</text></svg></td>\
             <td class=n>{} / {}</td><td>{}</td><td class=n>{:.2} / {:.2} s</td>\
             <td class=n>{}</td></tr>",
            escape(&r.entry),
            escape(&r.check),
            100.0 * rate,
            160.0 * rate,
            100.0 * rate,
            r.passed,
            r.ran,
            escape(&common(r)),
            r.seconds.0,
            r.seconds.1,
            memory(r.peak_kib)
        );
    }
    s += "</table></html>\n";
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grade::verdict::{CheckKind, CheckResult, TaskOutcome};

    fn report(status: TaskStatus, values: bool, failing: &str, kib: u64) -> GradeReport {
        let check = |name: &str, passed: bool| {
            let mut c = CheckResult::new(name, CheckKind::Values);
            c.total = 10;
            if !passed {
                c.fail(
                    format!("{failing}: got 1, expected 2 [random 3]"),
                    format!("{failing}: got 1 [random 3]"),
                );
            }
            c.finish();
            c.seconds = 0.5;
            c.peak_memory_kib = Some(kib);
            c
        };
        let task = TaskOutcome {
            task: "smith_g1".into(),
            status,
            points: 0.0,
            max_points: 6.0,
            checks: vec![check("values", values), check("stability", false)],
            output: String::new(),
            seconds: 0.0,
        };
        GradeReport::new("student", 1, false, vec![task], 1.0)
    }

    #[test]
    fn rows_count_who_ran_each_check_hardest_first_with_the_shared_failing_case() {
        let reports = [
            report(TaskStatus::Failed, true, "smith_g1(w=(0, 0, 1))", 2048),
            report(TaskStatus::Failed, false, "smith_g1(w=(0, 0, 1))", 4096),
            report(TaskStatus::Failed, false, "smith_g1(w=(1, 0, 0))", 1024),
            // Never ran: not counted.
            report(TaskStatus::NotAttempted, false, "x", 1 << 30),
        ];
        let graded: Vec<&GradeReport> = reports.iter().collect();
        let rows = rows(&graded, &["smith_g1".to_string()]);
        assert_eq!(rows[0].check, "stability", "hardest first");
        assert_eq!((rows[0].passed, rows[0].ran), (0, 3));
        let values = &rows[1];
        assert_eq!((values.passed, values.ran), (1, 3));
        assert_eq!(
            values.common_failure,
            Some(("smith_g1(w=(0, 0, 1)) [random 3]".to_string(), 1))
        );
        assert_eq!(values.peak_kib, Some(4096));
        assert!((values.seconds.0 - 0.5).abs() < 1e-12);
        let md = markdown(&rows);
        assert!(md.contains("| smith_g1 | values | 1 | 3 | 33 % |"), "{md}");
        assert!(md.contains("4 MiB"), "{md}");
        let page = html("2 submissions", &rows);
        assert!(page.contains("<svg") && page.contains("33 %"), "{page}");
        assert!(!page.contains("<script"), "a page without scripts");
    }

    #[test]
    fn student_text_in_the_page_is_escaped() {
        let row = CheckRow {
            entry: "reflect".into(),
            check: "values".into(),
            ran: 1,
            common_failure: Some(("<script>alert(1)</script>".into(), 1)),
            ..CheckRow::default()
        };
        let page = html("<b>", &[row]);
        assert!(
            !page.contains("<script>") && !page.contains("<b>"),
            "{page}"
        );
        // The summary's Markdown is a real table; a student's text in it stays text.
        let head = "# Class summary\n\n- eve <img src=x onerror=alert(1)>: not graded\n\n\
                    | entry | mean |\n|---|---|\n| reflect | 1.50 |\n";
        let page = html(head, &[]);
        assert!(page.contains("<h1>Class summary</h1>"), "{page}");
        assert!(
            page.contains("<th>entry</th>") && page.contains("<td>1.50</td>"),
            "{page}"
        );
        assert!(!page.contains("<img") && page.contains("&lt;img"), "{page}");
    }
}
