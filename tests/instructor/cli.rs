//! `pbrlab grade` end to end through the real binary: the shipped stubs grade to zero with
//! every task "not attempted", the reference to full marks in every report format, and the
//! last grade feeds `pbrlab tasks`.

use pbrlab::grade::verdict::{GradeReport, TaskStatus};
use pbrlab::worksheet::TaskId;
use std::path::Path;
use std::process::{Command, Output};

fn pbrlab(state: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_pbrlab"))
        .args(args)
        .env("PBRLAB_STATE_DIR", state)
        .output()
        .expect("pbrlab runs")
}

fn stdout(out: &Output) -> String {
    String::from_utf8_lossy(&out.stdout).into_owned()
}

#[test]
fn the_stubs_grade_to_zero_and_tasks_shows_it() {
    let untouched = crate::shipped_stubs::untouched();
    let all_stubs = untouched.len() == TaskId::ALL.len();
    let state = tempfile::tempdir().unwrap();
    let out = pbrlab(state.path(), &["grade", "--format", "json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let report: GradeReport = serde_json::from_str(&stdout(&out)).expect("a JSON report");
    assert!(report.max_score > 0.0);
    for t in report.tasks.iter().filter(|t| t.max_points > 0.0) {
        if t.task.starts_with("scene: ") {
            // A scene waits for the tasks it needs.
            if all_stubs {
                assert!(
                    matches!(t.status, TaskStatus::NeedsTask { .. }),
                    "{}",
                    t.task
                );
            }
        } else if untouched.contains(&TaskId::parse(&t.task).unwrap()) {
            assert_eq!(t.status, TaskStatus::NotAttempted, "{}", t.task);
            assert_eq!(t.points, 0.0, "{}", t.task);
        }
    }
    assert!(report.tasks.iter().any(|t| t.task == "scene: cornell"));
    let tasks = stdout(&pbrlab(state.path(), &["tasks"]));
    // The table fits an 80-column terminal (long titles wrap in their column).
    for line in tasks.lines().filter(|l| !l.starts_with("Latest grades")) {
        assert!(
            line.chars().count() <= 80,
            "{} columns: {line}",
            line.chars().count()
        );
    }
    for task in &untouched {
        assert!(graded_not_attempted(row(&tasks, task.name())), "{tasks}");
    }
    if all_stubs {
        assert_eq!(report.score, 0.0);
        assert!(tasks.contains("Latest grades: 0.0/"), "{tasks}");
        // A results file of the stubs says so (an instructor who meant a submission).
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            stderr.contains("every task graded is still the shipped stub"),
            "{stderr}"
        );
    }
}

/// `grade --format junit` is JUnit XML as CI tools read it: the stubs' checks are skipped
/// as not attempted, the reference's all pass.
#[test]
fn junit_reports_follow_the_schema_and_say_what_the_grade_says() {
    let state = tempfile::tempdir().unwrap();
    let stubs = pbrlab(state.path(), &["grade", "--format", "junit"]);
    assert!(
        stubs.status.success(),
        "{}",
        String::from_utf8_lossy(&stubs.stderr)
    );
    let xml = stdout(&stubs);
    let (tests, failures, skipped) = crate::junit_schema::validate(&xml);
    if crate::shipped_stubs::untouched().len() == TaskId::ALL.len() {
        assert_eq!(failures, 0, "{xml}");
        assert_eq!(skipped, tests, "{xml}");
        assert!(xml.contains("not attempted: the functions still stop at todo!()"));
    }
    let reference = pbrlab(
        state.path(),
        &["grade", "--impl", "reference", "--format", "junit"],
    );
    assert!(reference.status.success());
    let xml = stdout(&reference);
    let (tests, failures, skipped) = crate::junit_schema::validate(&xml);
    assert!(tests > 40, "{xml}");
    assert_eq!((failures, skipped), (0, 0), "{xml}");
}

/// `pbrlab hint` without a task shows the next hint of the first task not passed yet.
#[test]
fn hint_without_a_task_shows_the_first_task_not_passed() {
    let state = tempfile::tempdir().unwrap();
    let out = pbrlab(state.path(), &["hint"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = stdout(&out);
    let first = TaskId::ALL[0].name();
    assert!(
        text.contains("the first task that has not passed yet"),
        "{text}"
    );
    assert!(text.contains(&format!("{first} — ")), "{text}");
    assert!(text.contains("hint 1/"), "{text}");
    // The next call goes one level further, as with the task named.
    let again = stdout(&pbrlab(state.path(), &["hint"]));
    assert!(again.contains("hint 2/"), "{again}");
}

/// The row of `task` in `pbrlab tasks`' table.
/// True for a row of a task graded 0 as not attempted: `reflect  0.0/5  not attempted …`.
fn graded_not_attempted(row: &str) -> bool {
    row.contains(" 0.0/") && row.contains("not attempted")
}

fn row<'t>(table: &'t str, task: &str) -> &'t str {
    table
        .lines()
        .find(|l| l.starts_with(&format!("{task} ")))
        .unwrap_or_else(|| panic!("no row {task} in\n{table}"))
}

#[test]
fn tasks_keeps_every_tasks_latest_grade_and_lists_the_scenes() {
    let untouched = crate::shipped_stubs::untouched();
    let state = tempfile::tempdir().unwrap();
    let grade = |task: &str| assert!(pbrlab(state.path(), &["grade", task]).status.success());
    // Two tasks still at their stubs (the worksheet's first two in a clean clone).
    if let [first, second, ..] = untouched[..] {
        let (first, second) = (first.name(), second.name());
        grade(first);
        let table = stdout(&pbrlab(state.path(), &["tasks"]));
        assert!(graded_not_attempted(row(&table, first)), "{table}");
        assert!(!row(&table, second).contains("0.0/"), "{table}");
        grade(second);
        let table = stdout(&pbrlab(state.path(), &["tasks"]));
        assert!(graded_not_attempted(row(&table, first)), "{table}");
        assert!(graded_not_attempted(row(&table, second)), "{table}");
    }
    // The scenes' render checks are rows too, and the total counts them, as grade's does.
    let table = stdout(&pbrlab(state.path(), &["tasks"]));
    assert!(table.contains("render of scenes/cornell.yaml"), "{table}");
    let full = pbrlab(state.path(), &["grade", "--format", "json"]);
    let report: GradeReport = serde_json::from_str(&stdout(&full)).expect("a JSON report");
    let table = stdout(&pbrlab(state.path(), &["tasks"]));
    let total = row(&table, "total");
    assert!(
        total
            .trim_end()
            .ends_with(&format!(" {}", report.max_score)),
        "{total}"
    );
    if untouched.contains(&TaskId::PathTrace) {
        assert!(
            row(&table, "scene: cornell").contains("waits for"),
            "{table}"
        );
    }
}

#[test]
fn the_reference_scores_full_marks_in_every_format() {
    let state = tempfile::tempdir().unwrap();
    let results = state.path().join("results.json");
    let html = state.path().join("html");
    let out = pbrlab(
        state.path(),
        &[
            "grade",
            "--impl",
            "reference",
            "--format",
            "gradescope",
            "--hidden-seed",
            "99",
            "-o",
            results.to_str().unwrap(),
            "--html",
            html.to_str().unwrap(),
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&results).unwrap()).unwrap();
    let tests = json["tests"].as_array().expect("tests[]");
    let score = json["score"].as_f64().unwrap();
    // Only the keys of Gradescope's specification at the top level (no `max_score`).
    let keys: Vec<&str> = json
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    let spec = [
        "score",
        "execution_time",
        "output",
        "visibility",
        "stdout_visibility",
        "tests",
    ];
    assert!(keys.iter().all(|k| spec.contains(k)), "{keys:?}");
    let sum: f64 = tests.iter().map(|t| t["score"].as_f64().unwrap()).sum();
    let available: f64 = tests.iter().map(|t| t["max_score"].as_f64().unwrap()).sum();
    assert!(score > 0.0 && (sum - score).abs() < 1e-9 && (available - score).abs() < 1e-9);
    assert!(tests.iter().all(|t| t["status"] == "passed"), "{json}");
    let hidden = tests
        .iter()
        .filter(|t| t["visibility"] == "after_published")
        .count();
    let visible = tests
        .iter()
        .filter(|t| t["visibility"] == "visible")
        .count();
    assert!(
        hidden > 0 && hidden < visible,
        "{hidden} hidden, {visible} visible"
    );
    let page = std::fs::read_to_string(html.join("index.html")).unwrap();
    assert!(
        page.contains("<svg") && page.contains("cosine_sample"),
        "no histograms"
    );
    // The grader draws the renders' pictures from the workers' raw images, and the page
    // embeds them: one self-contained file.
    for scene in ["cornell", "smoke"] {
        for picture in ["student", "reference", "difference", "failed"] {
            let file = std::fs::read_dir(&html)
                .unwrap()
                .flatten()
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .find(|f| f.contains(scene) && f.ends_with(&format!("-{picture}.png")));
            let file = file.unwrap_or_else(|| panic!("no {picture} picture of {scene}"));
            assert!(!page.contains(&file), "{file} is linked, not embedded");
        }
    }
    let renders = pbrlab::grade::renders::RENDER_CHECKS.len();
    assert_eq!(page.matches("class=\"render-check\"").count(), renders);
    assert_eq!(
        page.matches("src=\"data:image/png;base64,").count(),
        4 * renders
    );
    assert!(page.contains("z-map") && page.contains("yours brighter"));
    // A reference grade is not a student's progress.
    assert!(!state.path().join("last-grade.json").exists());
}

#[test]
fn text_report_has_a_row_per_task_and_a_total() {
    let state = tempfile::tempdir().unwrap();
    let out = pbrlab(
        state.path(),
        &["grade", "--impl", "reference", "smith", "reflect"],
    );
    let text = stdout(&out);
    assert!(out.status.success());
    assert!(
        text.contains("smith_g1") && text.contains("passed") && text.contains("6/6"),
        "{text}"
    );
    assert!(
        text.lines()
            .any(|l| l.starts_with("total") && l.contains("11/11")),
        "{text}"
    );
    assert!(!text.contains("cook_torrance"));
}

#[test]
fn an_unknown_task_is_an_error_that_lists_the_tasks() {
    let state = tempfile::tempdir().unwrap();
    let out = pbrlab(state.path(), &["grade", "no_such_task"]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("no task `no_such_task`") && err.contains("fresnel_schlick"),
        "{err}"
    );
}

#[test]
fn hint_shows_one_new_level_per_call_and_remembers_it() {
    let state = tempfile::tempdir().unwrap();
    let hint = |args: &[&str]| {
        let out = pbrlab(state.path(), &[&["hint", "fresnel"], args].concat());
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        stdout(&out)
    };
    let levels = TaskId::FresnelSchlick.info().hints.len();
    assert!(levels >= 2, "{levels} levels");
    let first = hint(&[]);
    assert!(first.contains(&format!("hint 1/{levels}")), "{first}");
    assert!(!first.contains(&format!("hint 2/{levels}")), "{first}");
    assert!(
        first.contains(" hint fresnel_schlick` again shows hint 2"),
        "{first}"
    );
    let second = hint(&[]);
    assert!(second.contains(&format!("hint 2/{levels}")), "{second}");
    assert!(!second.contains(&format!("hint 1/{levels}:")), "{second}");
    assert!(second.contains("shown before"), "{second}");
    let again = hint(&["--level", "1"]);
    assert!(again.contains(&format!("hint 1/{levels}")), "{again}");
    assert!(!again.contains(&format!("hint 2/{levels}")), "{again}");
    // Looking back does not move the next hint.
    let third = hint(&[]);
    let next = 3.min(levels);
    assert!(third.contains(&format!("hint {next}/{levels}")), "{third}");
    let all = hint(&["--all"]);
    for level in 1..=levels {
        assert!(all.contains(&format!("hint {level}/{levels}")), "{all}");
    }
}

/// `pbrlab watch` in a pseudo-terminal, laid out for 80×24: the first screen (what follows
/// the last clear, the view and the keys) has no line wider than 80 columns and at most 24
/// lines, so nothing of it scrolls away.
#[test]
fn the_first_watch_screen_fits_an_80_by_24_terminal() {
    let state = tempfile::tempdir().unwrap();
    let mut command = Command::new(env!("CARGO_BIN_EXE_pbrlab"));
    command
        .args(["watch", "--poll-ms", "100"])
        .env("PBRLAB_STATE_DIR", state.path());
    let mut watch = rexpect::session::spawn_command(command, Some(120_000)).expect("a pty");
    let keys = "q: quit";
    let before = watch
        .exp_string(keys)
        .unwrap_or_else(|e| panic!("watch never printed `{keys}`: {e}"));
    watch.send("q").unwrap();
    watch.flush().unwrap();
    watch.exp_eof().expect("q ends the watch");
    let printed = crate::support::pty_text(&format!("{before}{keys}"));
    let screen = printed.rsplit("\x1b[2J\x1b[H").next().unwrap();
    assert_ne!(
        screen, printed,
        "the watch clears the screen before it draws"
    );
    let lines: Vec<&str> = screen
        .trim_start_matches(['\r', '\n'])
        .lines()
        .map(|l| l.trim_end_matches('\r'))
        .collect();
    for line in &lines {
        assert!(
            line.chars().count() <= 80,
            "a line of {} columns:\n{line}\n\nin\n{screen}",
            line.chars().count()
        );
    }
    assert!(lines.len() <= 24, "{} lines:\n{screen}", lines.len());
    if crate::shipped_stubs::untouched().len() == TaskId::ALL.len() {
        assert!(screen.contains("not attempted (15): reflect"), "{screen}");
    }
}
