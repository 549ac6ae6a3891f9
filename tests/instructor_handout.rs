//! The student handout: what goes in, and that it builds and grades without solutions.
#![cfg(feature = "solutions")]

use pbrlab::handout::manifest::{needs_solutions, select};
use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The code lines of a source (trimmed; no blank lines, comments or attributes).
fn code_lines(text: &str) -> Vec<&str> {
    text.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with("//") && !l.starts_with('#'))
        .collect()
}

/// Consecutive code lines that make a match.
const WINDOW: usize = 4;

/// Every run of [`WINDOW`] consecutive code lines of the reference that are not in the
/// exercises (which share the signatures by design): copying any part of a reference body
/// into the handout brings one along, while a guard or two in common with framework code
/// (an early return when a cosine is negative) does not.
fn solution_windows() -> Vec<String> {
    let mut shared = String::new();
    for entry in std::fs::read_dir(root().join("exercises")).unwrap() {
        shared += &std::fs::read_to_string(entry.unwrap().path()).unwrap();
    }
    let mut windows = Vec::new();
    for entry in std::fs::read_dir(root().join("solutions")).unwrap() {
        let text = std::fs::read_to_string(entry.unwrap().path()).unwrap();
        let lines: Vec<&str> = code_lines(&text)
            .into_iter()
            .filter(|l| !l.starts_with("use ") && !l.starts_with("pub mod") && !shared.contains(l))
            .collect();
        windows.extend(lines.windows(WINDOW).map(|w| w.join("\n")));
    }
    windows
}

#[test]
fn the_handout_leaves_out_the_solutions_and_everything_that_reveals_them() {
    let manifest = select(root()).expect("the repository has a handout");
    let files = &manifest.files;
    let names: Vec<String> = files
        .iter()
        .map(|f| f.to_string_lossy().replace('\\', "/"))
        .collect();
    for name in &names {
        assert!(
            !name.starts_with("solutions/") && !name.contains("/solutions/"),
            "{name}"
        );
        assert!(!name.contains("instructor_"), "{name}");
        assert!(
            !name.starts_with("target/")
                && !name.starts_with(".git/")
                && !name.starts_with(".pbrlab/"),
            "{name}"
        );
        if (name.starts_with("tests/") || name.starts_with("benches/")) && name.ends_with(".rs") {
            let text = std::fs::read_to_string(root().join(name)).unwrap();
            assert!(!needs_solutions(&text), "{name} uses the reference");
        }
    }
    // The stubs and the grader's public data are in; the data has no hidden cases.
    for task in pbrlab::worksheet::TaskId::ALL {
        if pbrlab::worksheet::task_functions(task).is_empty() {
            continue;
        }
        assert!(
            names.contains(&format!("exercises/{task}.rs")),
            "exercises/{task}.rs"
        );
        let stored = !pbrlab::grade::catalogue::public_inputs(task).is_empty()
            || !pbrlab::grade::catalogue::sampling_setups(task).is_empty();
        let snap = format!("tests/snapshots/expected/{task}.snap");
        assert_eq!(names.contains(&snap), stored, "{snap}");
        if !stored {
            continue;
        }
        let text = std::fs::read_to_string(root().join(&snap)).unwrap();
        assert!(
            !text.contains("\"name\": \"hidden"),
            "{snap} holds hidden cases"
        );
    }
    for check in pbrlab::grade::renders::RENDER_CHECKS {
        for kind in ["mean", "variance"] {
            let exr = format!("tests/snapshots/renders/{}.{kind}.exr", check.scene);
            assert!(names.contains(&exr), "{exr}");
        }
    }
    // The manifest names no reference crate: no member, dependency or default feature.
    assert!(!manifest.cargo_toml.contains("pbrlab-solutions"));
    assert!(!manifest.cargo_toml.contains("\"solutions\""));
    assert!(manifest.cargo_toml.contains("solutions = []\n"));
    // No handout file carries the reference's code.
    let windows = solution_windows();
    assert!(
        windows.len() > 50,
        "too little reference code to compare ({})",
        windows.len()
    );
    let copied = std::fs::read_to_string(root().join("solutions/cosine_sample.rs")).unwrap();
    let copied = code_lines(&copied).join("\n");
    assert!(
        windows.iter().any(|w| copied.contains(w.as_str())),
        "the comparison finds copied code"
    );
    for name in names.iter().filter(|n| n.ends_with(".rs")) {
        let text = std::fs::read_to_string(root().join(name)).unwrap();
        let code = code_lines(&text).join("\n");
        for window in &windows {
            assert!(
                !code.contains(window.as_str()),
                "{name} contains reference code:\n{window}"
            );
        }
    }
}

#[test]
fn the_handout_refuses_a_non_empty_directory() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("x"), "x").unwrap();
    let err = pbrlab::handout::write(root(), dir.path()).unwrap_err();
    assert!(err.to_string().contains("not empty"), "{err}");
}

fn cargo(dir: &Path, args: &[&str]) -> std::process::Output {
    Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()))
        .args(args)
        .current_dir(dir)
        .env("PBRLAB_STATE_DIR", dir.join(".state"))
        // The handout builds in its own target folder, as on a student's machine (a shared
        // one would mix its build-script outputs with the repository's).
        .env_remove("CARGO_TARGET_DIR")
        .output()
        .expect("cargo runs")
}

#[test]
fn the_handout_is_a_git_repository_that_can_put_a_stub_back() {
    use pbrlab::handout::stubs;
    use pbrlab::worksheet::TaskId;
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("student");
    pbrlab::handout::write(root(), &dir).expect("handout written");
    stubs::commit(&dir).expect("the handout committed");
    let file = dir.join("exercises/smith_g1.rs");
    let stub = std::fs::read_to_string(&file).unwrap();
    assert_eq!(stubs::shipped(&dir, TaskId::SmithG1).unwrap(), stub);
    // A student's work, committed: the stub still comes from the tagged first commit.
    std::fs::write(&file, "// my work\n").unwrap();
    let git = |args: &[&str]| {
        let ok = std::process::Command::new("git")
            .current_dir(&dir)
            .args(["-c", "user.name=s", "-c", "user.email=s@s"])
            .args(args)
            .status()
            .unwrap()
            .success();
        assert!(ok, "git {args:?}");
    };
    git(&["commit", "--quiet", "-am", "work"]);
    let keep = tmp.path().join("kept");
    let kept = stubs::reset(&dir, TaskId::SmithG1, &keep)
        .unwrap()
        .expect("the file was not the stub");
    assert_eq!(std::fs::read_to_string(&file).unwrap(), stub);
    assert_eq!(std::fs::read_to_string(kept).unwrap(), "// my work\n");
    assert_eq!(stubs::reset(&dir, TaskId::SmithG1, &keep).unwrap(), None);
}

#[test]
#[ignore = "slow: builds the handout (a second compile of the crate)"]
fn the_handout_builds_tests_and_grades_without_solutions() {
    let tmp = tempfile::tempdir().unwrap();
    let dir: PathBuf = tmp.path().join("student");
    pbrlab::handout::write(root(), &dir).expect("handout written");
    let test = cargo(&dir, &["test", "--release"]);
    assert!(
        test.status.success(),
        "{}",
        String::from_utf8_lossy(&test.stderr)
    );
    let grade = cargo(
        &dir,
        &["run", "--release", "-q", "--", "grade", "--format", "json"],
    );
    assert!(
        grade.status.success(),
        "{}",
        String::from_utf8_lossy(&grade.stderr)
    );
    let report: pbrlab::grade::verdict::GradeReport =
        serde_json::from_slice(&grade.stdout).expect("a JSON report");
    assert_eq!(report.score, 0.0);
    assert!(report.max_score > 0.0);
    assert!(
        report
            .tasks
            .iter()
            .filter(|t| t.max_points > 0.0 && !t.task.starts_with("scene: "))
            .all(|t| t.status == pbrlab::grade::verdict::TaskStatus::NotAttempted),
        "{}",
        pbrlab::grade::report::text(&report)
    );
    // Without the reference, reference grading is refused with a clear message.
    let refused = cargo(
        &dir,
        &[
            "run",
            "--release",
            "-q",
            "--",
            "grade",
            "--impl",
            "reference",
        ],
    );
    assert!(!refused.status.success());
    assert!(String::from_utf8_lossy(&refused.stderr).contains("needs the reference"));
    // Its help advertises neither the handout command nor what needs the reference.
    let help = |args: &[&str]| {
        let out = cargo(&dir, &[&["run", "--release", "-q", "--"], args].concat());
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8_lossy(&out.stdout).into_owned()
    };
    let top = help(&["--help"]);
    assert!(top.contains("grade") && !top.contains("handout"), "{top}");
    let grade = help(&["grade", "--help"]);
    assert!(grade.contains("student"), "{grade}");
    assert!(
        !grade.contains("mixed") && !grade.contains("- reference"),
        "{grade}"
    );
}
