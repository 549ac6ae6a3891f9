//! The HTML report: one page with, per task, the verdict and failing cases, histograms of
//! sampling checks, estimator runs against the reference, and student | reference |
//! difference images of render checks.

use super::svg;
use crate::grade::output::fmt_num;
use crate::grade::verdict::{CheckResult, Detail, GradeReport, TaskStatus, Visibility};
use anyhow::Context;
use std::fmt::Write;
use std::path::{Path, PathBuf};

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

const STYLE: &str = "body{font-family:system-ui,sans-serif;max-width:70em;margin:2em auto;padding:0 1em}\
table{border-collapse:collapse}td,th{padding:.2em .6em;border-bottom:1px solid #ddd;text-align:left}\
.passed{color:#176b2c}.failed{color:#a11}.muted{color:#777}pre{background:#f6f6f6;padding:.5em;overflow-x:auto;white-space:pre-wrap}\
.maps{display:flex;gap:1em;flex-wrap:wrap}figure{margin:0}figcaption{font-size:.8em;color:#555}\
.images img{image-rendering:pixelated;max-width:32%}";

fn check_html(c: &CheckResult) -> String {
    let mut s = String::new();
    let class = if c.passed { "passed" } else { "failed" };
    let _ = write!(
        s,
        "<h4 class=\"{class}\">{} {}</h4><p>{}</p>",
        if c.passed { "✓" } else { "✗" },
        escape(&c.name),
        escape(&c.summary)
    );
    if c.visibility == Visibility::Hidden {
        let _ = write!(
            s,
            "<p class=\"muted\">Hidden cases: {} of {} fail.</p>",
            c.failed, c.total
        );
        return s;
    }
    if !c.failures.is_empty() {
        let mut text = c.failures.join("\n");
        if c.failed > c.failures.len() {
            text += &format!("\n… and {} more", c.failed - c.failures.len());
        }
        let _ = write!(s, "<pre>{}</pre>", escape(&text));
    }
    match &c.detail {
        Some(Detail::Sampling(h)) => {
            let _ = write!(
                s,
                "<p>{}: χ² = {:.1} with {} degrees of freedom, p = {}; rejected {} (expected {}).</p>{}",
                escape(&h.name),
                h.chi2,
                h.dof,
                fmt_num(h.p_value),
                h.rejected.0,
                fmt_num(h.rejected.1),
                svg::histogram(h)
            );
        }
        Some(Detail::Estimator(e)) => {
            let row = |who: &str, r: &crate::grade::estimator::EstimatorRun| {
                let (lo, hi) = r.interval();
                let covers = if (lo..=hi).contains(&e.analytic) {
                    ""
                } else {
                    " class=\"failed\""
                };
                format!(
                    "<tr><td>{who}</td><td>{}</td><td>{}</td><td{covers}>[{}, {}]</td><td>{}</td><td>{} s</td><td>{}</td></tr>",
                    fmt_num(r.mean),
                    fmt_num(r.std_error),
                    fmt_num(lo),
                    fmt_num(hi),
                    fmt_num(r.error),
                    fmt_num(r.seconds),
                    r.efficiency(e.samples).map_or("—".into(), fmt_num)
                )
            };
            let _ = write!(
                s,
                "<table><tr><th>{} samples</th><th>mean</th><th>std. error</th><th>95 % interval</th><th>rel. error</th><th>time</th><th>efficiency 1/(σ²t)</th></tr>{}{}</table><p>Analytic value {}.</p>",
                e.samples,
                row("yours", &e.student),
                e.reference
                    .as_ref()
                    .map(|r| row("reference", r))
                    .unwrap_or_default(),
                fmt_num(e.analytic)
            );
        }
        Some(Detail::Image(img)) => {
            // Its numbers are the summary above.
            s += "<div class=\"images\">";
            for f in &img.files {
                let _ = write!(s, "<img src=\"{}\" alt=\"{}\">", escape(f), escape(f));
            }
            s += "</div>";
        }
        None => {}
    }
    s
}

/// The page for `report`.
pub fn page(report: &GradeReport) -> String {
    let mut s = format!(
        "<!doctype html><html lang=\"en\"><meta charset=\"utf-8\"><title>pbrlab grade</title><style>{STYLE}</style>\
         <h1>pbrlab grade: {:.1} / {}</h1><p class=\"muted\">{} implementation, seed {}, {:.1} s</p><table>\
         <tr><th>task</th><th>status</th><th>points</th><th>time</th></tr>",
        report.score, report.max_score, report.implementation, report.seed, report.seconds
    );
    for t in &report.tasks {
        let class = if t.status == TaskStatus::Passed {
            "passed"
        } else {
            "failed"
        };
        let _ = write!(
            s,
            "<tr><td><a href=\"#{0}\">{0}</a></td><td class=\"{class}\">{1}</td><td>{2:.1}/{3}</td><td>{4:.2} s</td></tr>",
            t.task,
            escape(&t.status.label()),
            t.points,
            t.max_points,
            t.seconds
        );
    }
    s += "</table>";
    for t in &report.tasks {
        let _ = write!(
            s,
            "<section id=\"{0}\"><h2>{0}: {1} ({2:.1}/{3})</h2>",
            t.task,
            escape(&t.status.label()),
            t.points,
            t.max_points
        );
        if let TaskStatus::Crashed { reason } = &t.status {
            let _ = write!(s, "<p class=\"failed\">The code {}.</p>", escape(reason));
        }
        if let TaskStatus::CompileError { message } = &t.status {
            let _ = write!(
                s,
                "<p class=\"failed\">exercises/{}.rs does not compile; its stub was graded.</p>\
                 <pre>{}</pre>",
                t.task,
                escape(message)
            );
        }
        for c in &t.checks {
            s += &check_html(c);
        }
        if !t.output.trim().is_empty() {
            let _ = write!(
                s,
                "<details><summary>output</summary><pre>{}</pre></details>",
                escape(&t.output)
            );
        }
        s += "</section>";
    }
    s += "</html>\n";
    s
}

/// Writes `dir/index.html` (creating `dir`); image files named by render checks are expected
/// in `dir` already. Returns the page's path.
pub fn write_html(report: &GradeReport, dir: &Path) -> anyhow::Result<PathBuf> {
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    let path = dir.join("index.html");
    crate::atomic_file::write(&path, page(report).as_bytes())?;
    Ok(path)
}
