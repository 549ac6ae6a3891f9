//! The HTML report in a real browser: headless Chromium loads the report of a failing
//! submission, runs its script without a console error, and has the render pictures
//! (loaded), the z-map legend and a sampling histogram; a screenshot is left in the
//! target folder for people to look at. Not part of the student handout.

use crate::support::{grade, inputs, variants};
use pbrlab::grade::report::write_html;
use pbrlab::grade::runner::student_tasks_for;
use pbrlab::grade::verdict::{GradeReport, TaskOutcome, TaskStatus};
use pbrlab::implementation::ImplChoice;
use pbrlab::worksheet::TaskId;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Debian's Chromium, or `None` (and a note) where it is not installed; in CI, which
/// installs it (`.ci/run`), a missing browser is a failure.
fn chromium() -> Option<PathBuf> {
    let found = ["chromium", "chromium-browser", "google-chrome"]
        .into_iter()
        .find_map(|name| {
            let out = Command::new("which").arg(name).output().ok()?;
            out.status
                .success()
                .then(|| PathBuf::from(String::from_utf8_lossy(&out.stdout).trim()))
        });
    if found.is_none() {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI needs Chromium for the report test (.ci/run installs it)"
        );
        eprintln!("no Chromium on this machine: the browser test of the report is skipped");
    }
    found
}

/// Runs headless Chromium on `page` with `args`; returns its stdout and stderr.
fn headless(browser: &Path, profile: &Path, page: &Path, args: &[&str]) -> (String, String) {
    let out = Command::new(browser)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--enable-logging=stderr",
            "--v=0",
            "--virtual-time-budget=5000",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .args(args)
        .arg(format!("file://{}", page.display()))
        .output()
        .expect("Chromium runs");
    (
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The report of a submission whose path tracer counts emission twice (the Cornell box's
/// render check fails, with its pictures) and whose cosine sampler draws uniform
/// directions (the sampling check fails, with its histogram).
fn failing_report(dir: &Path) -> PathBuf {
    let catalogue = variants::wrong();
    let find = |name: &str| {
        catalogue
            .iter()
            .find(|w| w.name == name)
            .unwrap_or_else(|| panic!("`{name}` is in the wrong catalogue"))
    };
    let path_tracer = find("emission counted twice");
    let render = pbrlab::grade::render_check::check(&path_tracer.patch, "cornell", 7, Some(dir));
    assert!(!render.passed, "{}", render.summary);
    let sampler = find("uniform samples with the cosine pdf");
    let inputs = inputs(1);
    let task = TaskId::CosineSample;
    let student = student_tasks_for(task, ImplChoice::Student, &[]);
    let sampled = crate::support::outcome(
        task,
        grade(&sampler.patch.only(student), task, &inputs[&task]),
    );
    assert_eq!(sampled.status, TaskStatus::Failed);
    let tasks = vec![
        sampled,
        TaskOutcome {
            task: "scene: cornell".into(),
            status: TaskStatus::Failed,
            points: 0.0,
            max_points: 4.0,
            checks: vec![render],
            output: String::new(),
            seconds: 0.0,
        },
    ];
    write_html(&GradeReport::new("student", 1, false, tasks, 1.0), dir).unwrap()
}

#[test]
#[ignore = "slow: a render check, and headless Chromium (CI installs it)"]
fn the_report_of_a_failing_submission_works_in_a_browser() {
    let Some(browser) = chromium() else {
        return;
    };
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("report-in-a-browser");
    let _ = std::fs::remove_dir_all(&dir);
    let page = failing_report(&dir);
    let profile = tempfile::tempdir().unwrap();
    // The page after its script ran and its pictures loaded.
    let (dom, log) = headless(&browser, profile.path(), &page, &["--dump-dom"]);
    assert!(
        dom.contains("data-ready=\"1\""),
        "the script did not run:\n{log}"
    );
    // Four pictures of the render check, all decoded.
    assert!(
        dom.contains("data-images-loaded=\"4\""),
        "not every picture loaded: {}\n{log}",
        dom.split("<body")
            .nth(1)
            .unwrap_or("")
            .chars()
            .take(200)
            .collect::<String>()
    );
    for (what, text) in [
        ("the wipe between the renders", "class=\"wipe-at\""),
        ("the z-map's legend", "yours brighter"),
        ("the failed pixels", "failed pixels"),
        ("the sampling histogram", "<svg"),
        ("the render check's failure", "image: cornell"),
    ] {
        assert!(dom.contains(text), "no {what} on the page");
    }
    let errors: Vec<&str> = log
        .lines()
        .filter(|l| l.contains("CONSOLE") || l.contains("Uncaught"))
        .collect();
    assert!(errors.is_empty(), "console messages: {errors:#?}");
    // A screenshot, for people.
    let shot = dir.join("report.png");
    let screenshot = format!("--screenshot={}", shot.display());
    headless(
        &browser,
        profile.path(),
        &page,
        &[&screenshot, "--window-size=1280,2400"],
    );
    let size = std::fs::metadata(&shot).map_or(0, |m| m.len());
    assert!(size > 20_000, "screenshot of {size} bytes");
}
