//! The HTML report: one self-contained page (pictures embedded) with, per task, the
//! verdict and failing cases, observed against expected histograms of sampling checks,
//! estimator runs with their 95 % intervals against the analytic value, and for each
//! render check the student's render against the reference (a slider wipes between them),
//! the z-map with its legend, the failed pixels, and every pixel's values under the cursor.

use super::svg;
use crate::grade::output::fmt_num;
use crate::grade::verdict::{
    CheckResult, Detail, GradeReport, TaskOutcome, TaskStatus, Visibility,
};
use anyhow::Context;
use std::fmt::Write;
use std::path::{Path, PathBuf};

pub(crate) use crate::html_escape::escape;

const STYLE: &str = "body{font-family:system-ui,sans-serif;max-width:70em;margin:2em auto;padding:0 1em}\
table{border-collapse:collapse}td,th{padding:.2em .6em;border-bottom:1px solid #ddd;text-align:left}\
.passed{color:#176b2c}.partial{color:#8a5a00}.failed{color:#a11}.muted{color:#777}pre{background:#f6f6f6;padding:.5em;overflow-x:auto;white-space:pre-wrap}\
.maps{display:flex;gap:1em;flex-wrap:wrap}figure{margin:0}figcaption{font-size:.8em;color:#555}\
details.check{margin:.3em 0}details.check>summary{cursor:pointer}details.check[open]>summary{margin-bottom:.4em}\
.render{display:flex;gap:1.5em;flex-wrap:wrap;align-items:flex-start}.pixels{width:448px;height:448px;image-rendering:pixelated;display:block;cursor:crosshair}.wipe{position:relative;width:448px;height:448px}.wipe img{position:absolute;top:0;left:0}.legend{display:flex;align-items:center;gap:.4em;font-size:.8em;color:#555}.ramp{display:inline-block;width:120px;height:10px;background:linear-gradient(to right,#00f,#fff,#f00)}.swatch{display:inline-block;width:10px;height:10px}.probe{font-family:monospace;font-size:.85em;min-height:1.2em}";

/// Wires each render block: the slider wipes between the student's render (left) and
/// the reference (right); the cursor over any picture shows that pixel's values.
const SCRIPT: &str = r#"document.querySelectorAll('.render-check').forEach(function(r){
var v=JSON.parse(r.querySelector('script.values').textContent);
var mine=r.querySelector('img.mine'),slider=r.querySelector('input.wipe-at'),probe=r.querySelector('.probe');
function wipe(){mine.style.clipPath='inset(0 '+(100-slider.value)+'% 0 0)';}
slider.addEventListener('input',wipe);wipe();
function show(e){var b=e.currentTarget.getBoundingClientRect();
var x=Math.floor((e.clientX-b.left)/b.width*v.width),y=Math.floor((e.clientY-b.top)/b.height*v.height);
if(x<0||y<0||x>=v.width||y>=v.height)return;var i=3*(y*v.width+x);
function f(a){return a.slice(i,i+3).map(function(t){return t===null?'NaN':Number(t).toPrecision(4);}).join(', ');}
probe.textContent='pixel ('+x+', '+y+'): yours ['+f(v.student)+'], reference ['+f(v.reference)+'], z ['+f(v.z)+']';}
r.querySelectorAll('.pixels').forEach(function(p){p.addEventListener('mousemove',show);});});
window.addEventListener('load',function(){var n=0;document.querySelectorAll('img').forEach(function(i){if(i.complete&&i.naturalWidth>0)n++;});
document.body.dataset.imagesLoaded=String(n);});
document.body.dataset.ready='1';"#;

/// The pictures of a render check, read from the report folder: embedded as data URIs, or
/// linked by name where a file cannot be read.
struct Pictures<'a> {
    dir: Option<&'a Path>,
}

impl Pictures<'_> {
    /// The `src` of picture `file`.
    fn src(&self, file: &str) -> String {
        match self.dir.and_then(|d| std::fs::read(d.join(file)).ok()) {
            Some(bytes) => format!(
                "data:image/png;base64,{}",
                base64::Engine::encode(&base64::engine::general_purpose::STANDARD, bytes)
            ),
            None => escape(file),
        }
    }

    /// The text of file `file` (the values), or an empty JSON object.
    fn text(&self, file: &str) -> String {
        self.dir
            .and_then(|d| std::fs::read_to_string(d.join(file)).ok())
            .unwrap_or_else(|| "{}".into())
    }
}

/// The render block of an image check with pictures `files` (as
/// [`super::images::write_pictures`] names them).
fn render_html(files: &[String], pictures: &Pictures<'_>) -> String {
    let find = |suffix: &str| files.iter().find(|f| f.ends_with(suffix));
    let (Some(student), Some(reference), Some(zmap), Some(failed), Some(values)) = (
        find("-student.png"),
        find("-reference.png"),
        find("-difference.png"),
        find("-failed.png"),
        find("-values.json"),
    ) else {
        return String::new();
    };
    format!(
        "<div class=\"render-check\"><div class=\"render\">\
         <figure><div class=\"wipe\"><img class=\"pixels\" src=\"{ref_src}\" alt=\"reference render\">\
         <img class=\"pixels mine\" src=\"{mine_src}\" alt=\"your render\"></div>\
         <figcaption>yours ◀ <input class=\"wipe-at\" type=\"range\" min=\"0\" max=\"100\" value=\"50\" \
         aria-label=\"wipe between your render and the reference\"> ▶ reference</figcaption></figure>\
         <figure><img class=\"pixels\" src=\"{zmap_src}\" alt=\"z-map\"><figcaption>z-map: \
         (yours − reference) / noise, per pixel the channel furthest off\
         <span class=\"legend\">yours darker <span class=\"ramp\"></span> yours brighter \
         (white: within noise; full colour at |z| ≥ {sat:.1}) \
         <span class=\"swatch\" style=\"background:#0c0\"></span> NaN or ∞</span></figcaption></figure>\
         <figure><img class=\"pixels\" src=\"{failed_src}\" alt=\"failed pixels\"><figcaption>\
         <span class=\"swatch\" style=\"background:#ffd200\"></span> failed pixels (|z| &gt; {crit:.2} \
         in a channel)</figcaption></figure></div>\
         <p class=\"probe\">Point at a picture for a pixel's values.</p>\
         <script type=\"application/json\" class=\"values\">{values_json}</script></div>",
        ref_src = pictures.src(reference),
        mine_src = pictures.src(student),
        zmap_src = pictures.src(zmap),
        failed_src = pictures.src(failed),
        sat = 2.0 * crate::grade::image_check::Z_CRITICAL,
        crit = crate::grade::image_check::Z_CRITICAL,
        values_json = pictures.text(values).replace("</", "<\\/"),
    )
}

/// One check: a line with its verdict, name and summary, which opens on what it measured.
/// A passed check is folded to that line; a failed one is open.
fn check_html(c: &CheckResult, pictures: &Pictures<'_>) -> String {
    let class = if c.passed { "passed" } else { "failed" };
    let head = format!(
        "<details class=\"check\"{}><summary><span class=\"{class}\">{} {}</span> — {}</summary>",
        if c.passed { "" } else { " open" },
        if c.passed { "✓" } else { "✗" },
        escape(&c.name),
        escape(&c.summary)
    );
    format!("{head}{}</details>", check_body(c, pictures))
}

/// What a check measured: its failing cases, histograms, estimator table or renders.
fn check_body(c: &CheckResult, pictures: &Pictures<'_>) -> String {
    let mut s = String::new();
    if c.visibility == Visibility::Hidden {
        let _ = write!(
            s,
            "<p class=\"muted\">Hidden cases: {} of {} fail.</p>",
            c.failed, c.total
        );
        return s;
    }
    if let Some((shrunk, _)) = &c.shrunk {
        let _ = write!(s, "<pre>{}</pre>", escape(shrunk));
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
            // An interval is red only where the check failed on it: a passing check may
            // miss the analytic value by less than its tolerance.
            let row = |who: &str, r: &crate::grade::estimator::EstimatorRun| {
                let (lo, hi) = r.interval();
                let covers = if c.passed || (lo..=hi).contains(&e.analytic) {
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
        // Its numbers are the summary above.
        Some(Detail::Image(img)) => s += &render_html(&img.files, pictures),
        None => {}
    }
    s
}

/// The page for `report`, with the pictures of render checks read from `dir` (the report
/// folder they were written to) and embedded.
pub fn page(report: &GradeReport, dir: Option<&Path>) -> String {
    let pictures = Pictures { dir };
    let mut s = format!(
        "<!doctype html><html lang=\"en\"><meta charset=\"utf-8\"><title>pbrlab grade</title><style>{STYLE}</style>\
         <h1>pbrlab grade: {:.1} / {}</h1><p class=\"muted\">{} implementation, seed {}, {:.1} s</p><table>\
         <tr><th>task</th><th>status</th><th>points</th><th>time</th></tr>",
        report.score, report.max_score, report.implementation, report.seed, report.seconds
    );
    for note in super::report_notes(report) {
        s += &format!("<p class=\"muted\">{}</p>", escape(&note));
    }
    for t in &report.tasks {
        let class = match t.status {
            TaskStatus::Passed => "passed",
            TaskStatus::Partial => "partial",
            _ => "failed",
        };
        let name = if t.folds() {
            t.task.clone()
        } else {
            format!("<a href=\"#{0}\">{0}</a>", t.task)
        };
        let _ = write!(
            s,
            "<tr><td>{0}</td><td class=\"{class}\">{1}</td><td>{2:.1}/{3}</td><td>{4:.2} s</td></tr>",
            name,
            escape(&t.status.label()),
            t.points,
            t.max_points,
            t.seconds
        );
    }
    s += "</table>";
    // Not-attempted tasks and scenes still waiting for tasks are one line each; the other
    // entries get a section, those that need work first.
    let untouched: Vec<&str> = report
        .tasks
        .iter()
        .filter(|t| t.status == TaskStatus::NotAttempted)
        .map(|t| t.task.as_str())
        .collect();
    if !untouched.is_empty() {
        let _ = write!(
            s,
            "<p class=\"muted\">Not attempted yet (each still stops at <code>todo!()</code>): {}.</p>",
            escape(&untouched.join(", "))
        );
    }
    let waiting: Vec<String> = report
        .tasks
        .iter()
        .filter(|t| t.scene_waits())
        .filter_map(|t| match &t.status {
            TaskStatus::NeedsTask { task } => {
                Some(format!("{} ({task})", t.task.trim_start_matches("scene: ")))
            }
            _ => None,
        })
        .collect();
    if !waiting.is_empty() {
        let _ = write!(
            s,
            "<p class=\"muted\">Scenes are graded once the tasks they call pass: {}.</p>",
            escape(&waiting.join("; "))
        );
    }
    let mut shown: Vec<&TaskOutcome> = report.tasks.iter().filter(|t| !t.folds()).collect();
    shown.sort_by_key(|t| matches!(t.status, TaskStatus::Passed | TaskStatus::NoChecks));
    for t in shown {
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
            s += &check_html(c, &pictures);
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
    let _ = writeln!(s, "<script>{SCRIPT}</script></html>");
    s
}

/// Writes `dir/index.html` (creating `dir`), embedding the pictures that render checks
/// wrote into `dir`: the page is one file that can be mailed or uploaded on its own.
/// Returns the page's path.
pub fn write_html(report: &GradeReport, dir: &Path) -> anyhow::Result<PathBuf> {
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    let path = dir.join("index.html");
    crate::atomic_file::write(&path, page(report, Some(dir)).as_bytes())?;
    Ok(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn entry(task: &str, status: TaskStatus) -> TaskOutcome {
        TaskOutcome {
            task: task.into(),
            status,
            points: 0.0,
            max_points: 5.0,
            checks: Vec::new(),
            output: String::new(),
            seconds: 0.0,
        }
    }

    #[test]
    fn untouched_tasks_and_waiting_scenes_are_one_line_and_failures_come_first() {
        let tasks = vec![
            entry("reflect", TaskStatus::Passed),
            entry("smith_g1", TaskStatus::Failed),
            entry("phong", TaskStatus::NotAttempted),
            entry("kajiya_kay", TaskStatus::NotAttempted),
            entry(
                "cook_torrance",
                TaskStatus::NeedsTask {
                    task: "smith_g1".into(),
                },
            ),
            entry(
                "scene: smoke",
                TaskStatus::NeedsTask {
                    task: "delta_tracking".into(),
                },
            ),
        ];
        let page = page(&GradeReport::new("student", 1, false, tasks, 1.0), None);
        assert!(page.contains("Not attempted yet"), "{page}");
        assert!(page.contains("phong, kajiya_kay."), "{page}");
        assert!(page.contains("smoke (delta_tracking)"), "{page}");
        // A task waiting for another is not a scene: it keeps its section.
        assert!(page.contains("<section id=\"cook_torrance\""), "{page}");
        assert!(!page.contains("cook_torrance (smith_g1)"), "{page}");
        for folded in ["phong", "kajiya_kay", "scene: smoke"] {
            assert!(
                !page.contains(&format!("<section id=\"{folded}\"")),
                "{folded}"
            );
            assert!(!page.contains(&format!("href=\"#{folded}\"")), "{folded}");
        }
        let failed = page
            .find("<section id=\"smith_g1\"")
            .expect("a failed task's section");
        let passed = page
            .find("<section id=\"reflect\"")
            .expect("a passed task's section");
        assert!(failed < passed, "failures first");
    }
}
