//! The report: one self-contained HTML page (inline CSS, no script, no external resource).
//!
//! Student code and names are untrusted: every piece of them goes through [`escape`], and
//! anchors are built from indices, never from names.

use super::{PairScore, PairSummary, TaskComparison, TaskScore};
use pbrlab_course::html_escape::escape;
use std::collections::{BTreeMap, HashMap};
use std::fmt::Write;

/// Rows of the ranked table beyond the flagged pairs: the next-highest pairs, for context.
const UNFLAGGED_ROWS: usize = 100;

/// Region colours; region `i` of a pair's task gets colour `i % COLOURS`.
const COLOURS: usize = 8;

const STYLE: &str = "
body { font-family: system-ui, sans-serif; margin: 1.5em; color: #222; }
table.rank { border-collapse: collapse; font-size: 90%; }
table.rank th, table.rank td { border: 1px solid #ccc; padding: 2px 6px; text-align: right; }
table.rank td.name { text-align: left; }
table.rank tr.flagged td.agg { background: #f8c4c4; font-weight: bold; }
table.rank td.hit { background: #fde2b8; font-weight: bold; }
table.rank th.task { writing-mode: vertical-rl; transform: rotate(180deg); }
.sbs { display: flex; gap: 1em; align-items: flex-start; }
.file { flex: 1 1 0; min-width: 0; overflow-x: auto; border: 1px solid #ccc; }
.file .who { background: #eee; padding: 2px 6px; font-weight: bold; }
pre { margin: 0; font-size: 85%; line-height: 1.3; }
pre span.l { display: block; white-space: pre; }
pre span.n { display: inline-block; width: 3.5em; color: #888; user-select: none; }
ol.regions { font-size: 90%; }
.m0 { background: #ffd6d6; } .m1 { background: #d6f0ff; } .m2 { background: #dcf5d0; }
.m3 { background: #fff1b8; } .m4 { background: #ead6ff; } .m5 { background: #ffe0c2; }
.m6 { background: #cff5ef; } .m7 { background: #f5d0e6; }
";

/// The report page for `ranked` (as [`super::rank()`] returns it) and the task comparisons it
/// came from.
///
/// The ranked table lists every flagged pair (over all tasks or in any task) and the
/// 100 highest-ranked others, with the aggregate score and the score of every task. Below,
/// for each pair flagged on its own or in some task, every task that is flagged (or, for a
/// pair flagged over all tasks, that shares anything) shows both files side by side, the
/// matched regions in matching colours. `sources` holds the text of each (task, student)
/// file; a file missing from it is shown as missing.
pub fn html(
    ranked: &[PairSummary],
    tasks: &[TaskComparison],
    sources: &BTreeMap<(String, String), String>,
) -> String {
    let pair_scores: HashMap<(&str, &str, &str), &PairScore> = tasks
        .iter()
        .flat_map(|t| {
            t.pairs
                .iter()
                .map(move |p| ((t.task.as_str(), p.a.as_str(), p.b.as_str()), p))
        })
        .collect();
    let mut task_names: Vec<&str> = Vec::new();
    for t in tasks {
        if !task_names.contains(&t.task.as_str()) {
            task_names.push(&t.task);
        }
    }
    let detailed = |p: &PairSummary| p.flagged || p.flagged_tasks > 0;
    // A task of a pair gets a side-by-side view when it is flagged, or when the pair is
    // flagged over all tasks and shares anything in it.
    let shown = |p: &PairSummary, s: &TaskScore| s.flagged || p.flagged && s.shared > 0;

    let mut page = String::new();
    page.push_str("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n");
    page.push_str("<title>Code similarity</title>\n<style>");
    page.push_str(STYLE);
    page.push_str("</style>\n</head>\n<body>\n<h1>Code similarity</h1>\n");
    let flagged = ranked.iter().filter(|p| p.flagged).count();
    let _ = writeln!(
        page,
        "<p>{} pairs share code; {flagged} are flagged over all tasks, {} in some task. \
         A score is the share of the smaller file's fingerprints (winnowed k-grams of \
         normalised tokens, the stub's and the class's common code left out) that the \
         other file has too; over all tasks, shared fingerprints and denominators are summed \
         first. Scores are evidence for a human to look at, not a verdict.</p>",
        ranked.len(),
        ranked.iter().filter(|p| p.flagged_tasks > 0).count(),
    );

    // The ranked table.
    page.push_str("<table class=\"rank\">\n<thead><tr><th>#</th><th>A</th><th>B</th>");
    page.push_str("<th>all tasks</th><th>shared</th>");
    for name in &task_names {
        let _ = write!(page, "<th class=\"task\">{}</th>", escape(name));
    }
    page.push_str("</tr></thead>\n<tbody>\n");
    let mut unflagged_shown = 0;
    let mut left_out = 0;
    for (rank, pair) in ranked.iter().enumerate() {
        if !detailed(pair) {
            if unflagged_shown >= UNFLAGGED_ROWS {
                left_out += 1;
                continue;
            }
            unflagged_shown += 1;
        }
        let row_class = if pair.flagged {
            " class=\"flagged\""
        } else {
            ""
        };
        let _ = write!(
            page,
            "<tr{row_class}><td>{}</td><td class=\"name\">{}</td><td class=\"name\">{}</td>",
            rank + 1,
            escape(&pair.a),
            escape(&pair.b)
        );
        let aggregate = percent(pair.score);
        if detailed(pair) {
            let _ = write!(
                page,
                "<td class=\"agg\"><a href=\"#p{rank}\">{aggregate}</a></td>"
            );
        } else {
            let _ = write!(page, "<td class=\"agg\">{aggregate}</td>");
        }
        let _ = write!(page, "<td>{}/{}</td>", pair.shared, pair.compared);
        for (t, name) in task_names.iter().enumerate() {
            match pair.tasks.iter().find(|s| s.task == *name) {
                Some(s) if shown(pair, s) => {
                    let class = if s.flagged { " class=\"hit\"" } else { "" };
                    let _ = write!(
                        page,
                        "<td{class}><a href=\"#p{rank}-t{t}\">{}</a></td>",
                        percent(s.score)
                    );
                }
                Some(s) => {
                    let _ = write!(page, "<td>{}</td>", percent(s.score));
                }
                None => page.push_str("<td></td>"),
            }
        }
        page.push_str("</tr>\n");
    }
    page.push_str("</tbody>\n</table>\n");
    if left_out > 0 {
        let _ = writeln!(
            page,
            "<p>{left_out} lower-ranked pairs, none flagged, left out.</p>"
        );
    }

    // The side-by-side views.
    page.push_str("<h2>Flagged pairs</h2>\n");
    for (rank, pair) in ranked.iter().enumerate() {
        if !detailed(pair) {
            continue;
        }
        let _ = writeln!(
            page,
            "<section id=\"p{rank}\">\n<h3>{}. {} and {}: {} over all tasks ({} of {} \
             fingerprints){}</h3>",
            rank + 1,
            escape(&pair.a),
            escape(&pair.b),
            percent(pair.score),
            pair.shared,
            pair.compared,
            if pair.flagged { ", flagged" } else { "" }
        );
        for (t, name) in task_names.iter().enumerate() {
            let Some(score) = pair.tasks.iter().find(|s| s.task == *name) else {
                continue;
            };
            if !shown(pair, score) {
                continue;
            }
            let Some(detail) = pair_scores.get(&(*name, pair.a.as_str(), pair.b.as_str())) else {
                continue;
            };
            let _ = writeln!(
                page,
                "<section id=\"p{rank}-t{t}\">\n<h4>{}: {}, {} shared fingerprints{}</h4>",
                escape(name),
                percent(score.score),
                score.shared,
                if score.flagged { ", flagged" } else { "" }
            );
            side_by_side(&mut page, name, detail, sources);
            page.push_str("</section>\n");
        }
        page.push_str("</section>\n");
    }
    page.push_str("</body>\n</html>\n");
    page
}

/// The region list and both files of one pair's task.
fn side_by_side(
    page: &mut String,
    task: &str,
    pair: &PairScore,
    sources: &BTreeMap<(String, String), String>,
) {
    page.push_str("<ol class=\"regions\">\n");
    for (i, r) in pair.regions.iter().enumerate() {
        let _ = writeln!(
            page,
            "<li class=\"m{}\">{} lines {}–{} and {} lines {}–{}</li>",
            i % COLOURS,
            escape(&pair.a),
            r.a_lines.0,
            r.a_lines.1,
            escape(&pair.b),
            r.b_lines.0,
            r.b_lines.1
        );
    }
    page.push_str("</ol>\n<div class=\"sbs\">\n");
    let a_ranges: Vec<(usize, usize)> = pair.regions.iter().map(|r| r.a_lines).collect();
    let b_ranges: Vec<(usize, usize)> = pair.regions.iter().map(|r| r.b_lines).collect();
    for (student, ranges) in [(&pair.a, a_ranges), (&pair.b, b_ranges)] {
        let _ = writeln!(
            page,
            "<div class=\"file\"><div class=\"who\">{} — {}</div>",
            escape(student),
            escape(task)
        );
        match sources.get(&(task.to_string(), student.clone())) {
            Some(text) => file_lines(page, text, &ranges),
            None => page.push_str("<p>(file not given)</p>"),
        }
        page.push_str("</div>\n");
    }
    page.push_str("</div>\n");
}

/// `text` as numbered lines, each inside the first region of `ranges` that covers it
/// coloured as that region.
fn file_lines(page: &mut String, text: &str, ranges: &[(usize, usize)]) {
    page.push_str("<pre>");
    for (i, line) in text.lines().enumerate() {
        let number = i + 1;
        let region = ranges
            .iter()
            .position(|&(first, last)| first <= number && number <= last);
        match region {
            Some(r) => {
                let _ = write!(
                    page,
                    "<span class=\"l m{}\" title=\"region {}\">",
                    r % COLOURS,
                    r + 1
                );
            }
            None => page.push_str("<span class=\"l\">"),
        }
        let _ = write!(
            page,
            "<span class=\"n\">{number}</span>{}</span>",
            escape(line)
        );
    }
    page.push_str("</pre>");
}

fn percent(score: f64) -> String {
    format!("{:.0} %", score * 100.0)
}
