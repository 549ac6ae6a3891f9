//! The student handout: what goes in, and that it builds and grades without solutions.

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
    let shared = shipped_exercises();
    let mut windows = Vec::new();
    for text in reference_sources() {
        let lines: Vec<&str> = code_lines(&text)
            .into_iter()
            .filter(|l| !l.starts_with("use ") && !l.starts_with("pub mod") && !shared.contains(l))
            .collect();
        windows.extend(lines.windows(WINDOW).map(|w| w.join("\n")));
    }
    windows
}

/// The exercises as shipped, whatever the working copy holds: every stub, `lib.rs` and
/// `build.rs`.
fn shipped_exercises() -> String {
    let mut shared = String::new();
    for task in pbrlab::worksheet::TaskId::ALL {
        shared += &pbrlab::handout::stubs::shipped(root(), task).unwrap();
    }
    for other in ["lib.rs", "build.rs"] {
        shared += &std::fs::read_to_string(root().join("exercises").join(other)).unwrap();
    }
    shared
}

/// The shortest reference line that counts as distinctive.
const DISTINCTIVE: usize = 24;

/// Reference lines the handout's framework shares on purpose, each with the reason: a call
/// of the framework's API, a destructuring its types force, or a textbook identity the
/// framework needs for itself; none is a decision a task asks for.
const FRAMEWORK_LINES: &[(&str, &str)] = &[
    (
        "LightSample::Environment { wi, radiance, pdf } => {",
        "the fields of the framework's light sample",
    ),
    (
        "LightSample::Point { p, intensity, prob } => {",
        "the fields of the framework's light sample",
    ),
    (
        "Vec3::new(sin_theta * cos_phi, sin_theta * sin_phi, cos_theta)",
        "spherical to Cartesian coordinates (src/math/spherical.rs)",
    ),
    (
        "if scene.occluded(&ray, t_max) {",
        "the framework's shadow-ray query",
    ),
    (
        "let cos_i = cos_theta_i.abs().min(1.0);",
        "a cosine clamped to [0, 1] in the framework's exact Fresnel equations",
    ),
    (
        "let cos_t = (1.0 - sin2_t).max(0.0).sqrt();",
        "cos from sin² in the framework's exact Fresnel equations",
    ),
    ("let dist2 = d.length_squared();", "a squared distance"),
    (
        "let f = bsdf.eval(t, wo, wi);",
        "the framework's BSDF evaluation",
    ),
    (
        "let majorant = medium.majorant();",
        "the framework's medium query",
    ),
    ("let mut radiance = Vec3::ZERO;", "an accumulator"),
];

/// Every distinctive line of the reference: a code line of at least [`DISTINCTIVE`]
/// characters that the shipped exercises do not already give (their text states some steps
/// on purpose) and that is not one of the [`FRAMEWORK_LINES`].
fn distinctive_lines() -> Vec<String> {
    let shared = shipped_exercises();
    let mut lines = Vec::new();
    for text in reference_sources() {
        lines.extend(
            code_lines(&text)
                .into_iter()
                .filter(|l| l.len() >= DISTINCTIVE && !l.starts_with("use "))
                .filter(|l| !shared.contains(l))
                .filter(|l| !FRAMEWORK_LINES.iter().any(|(f, _)| f == l))
                .map(str::to_string),
        );
    }
    lines.sort();
    lines.dedup();
    lines
}

/// The text of every source file of the reference.
fn reference_sources() -> Vec<String> {
    std::fs::read_dir(root().join("solutions"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "rs"))
        .map(|p| std::fs::read_to_string(p).unwrap())
        .collect()
}

/// The distinctive reference lines that occur in `text`, anywhere in a line.
fn reference_lines_in<'a>(text: &str, lines: &'a [String]) -> Vec<&'a str> {
    lines
        .iter()
        .filter(|l| text.contains(l.as_str()))
        .map(String::as_str)
        .collect()
}

#[test]
fn the_framework_lines_the_reference_shares_are_still_reference_lines() {
    let all = reference_sources().concat();
    let all = code_lines(&all);
    for (line, why) in FRAMEWORK_LINES {
        assert!(
            all.contains(line),
            "no longer a reference line ({why}): {line}"
        );
    }
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
        assert!(
            !name.contains("instructor_") && !name.starts_with("tests/instructor/"),
            "{name}"
        );
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
    // Of the tests, the student's alone: the framework's stay here.
    let tests: Vec<&String> = names
        .iter()
        .filter(|n| n.starts_with("tests/") && n.ends_with(".rs"))
        .collect();
    assert_eq!(
        tests,
        [pbrlab::handout::manifest::STUDENT_TESTS],
        "{tests:?}"
    );
    assert!(
        !manifest.cargo_toml.contains("pbrlab-exercises ="),
        "the student's tests link no student code"
    );
    // The stubs and the grader's public data are in; the data has no hidden cases.
    for task in pbrlab::worksheet::TaskId::ALL {
        if pbrlab::worksheet::task_functions(task).is_empty() {
            continue;
        }
        assert!(
            names.contains(&format!("exercises/{task}.rs")),
            "exercises/{task}.rs"
        );
        let stored = !pbrlab::grade::value_cases::public_inputs(task).is_empty()
            || !pbrlab::grade::catalogue::sampling_setups(task).is_empty();
        let snap = format!("src/grader/tasks/{task}/expected.snap");
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
            let exr = format!("src/grader/renders/{}.{kind}.exr", check.scene);
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
    // No handout file has a distinctive reference line, in code, comments or data.
    let lines = distinctive_lines();
    assert!(
        lines.len() > 150,
        "too few reference lines ({})",
        lines.len()
    );
    let roulette = std::fs::read_to_string(root().join("solutions/path_trace.rs")).unwrap();
    assert!(
        !reference_lines_in(&roulette, &lines).is_empty(),
        "the comparison finds a reference line"
    );
    // The handout as written (its exercises are the committed stubs).
    let handout = tempfile::tempdir().unwrap();
    pbrlab::handout::write(root(), handout.path()).expect("handout written");
    for name in &names {
        let Ok(text) = std::fs::read_to_string(handout.path().join(name)) else {
            continue;
        };
        let found = reference_lines_in(&text, &lines);
        assert!(
            found.is_empty(),
            "{name} has reference lines:\n{}",
            found.join("\n")
        );
        if name.ends_with(".rs") {
            let code = code_lines(&text).join("\n");
            for window in &windows {
                assert!(
                    !code.contains(window.as_str()),
                    "{name} contains reference code:\n{window}"
                );
            }
        }
    }
}

#[test]
fn the_handout_ships_the_lock_file_it_builds_with() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("student");
    pbrlab::handout::write(root(), &dir).expect("handout written");
    let lock = std::fs::read_to_string(dir.join("Cargo.lock")).unwrap();
    assert!(
        !lock.contains("pbrlab-solutions"),
        "the reference's crate is left out"
    );
    // `--locked` refuses to build when the lock file would change.
    let out = cargo(&dir, &["tree", "--locked", "--offline", "--quiet"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn the_handout_refuses_a_non_empty_directory() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("x"), "x").unwrap();
    let err = pbrlab::handout::write(root(), dir.path()).unwrap_err();
    assert!(err.to_string().contains("not empty"), "{err}");
}

/// `cargo` with `args` in the handout at `dir`.
fn cargo_command(dir: &Path, args: &[&str]) -> Command {
    let mut cargo = Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()));
    cargo
        .args(args)
        .current_dir(dir)
        .env("PBRLAB_STATE_DIR", dir.join(".state"))
        // The handout builds in its own target folder, as on a student's machine (a shared
        // one would mix its build-script outputs with the repository's).
        .env_remove("CARGO_TARGET_DIR");
    cargo
}

fn cargo(dir: &Path, args: &[&str]) -> std::process::Output {
    cargo_command(dir, args).output().expect("cargo runs")
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
        let ok = Command::new("git")
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
    assert_eq!(std::fs::read_to_string(&kept).unwrap(), "// my work\n");
    assert_eq!(stubs::reset(&dir, TaskId::SmithG1, &keep).unwrap(), None);
    // Undone: the work comes back and its copy goes; work done on the stub since is kept.
    std::fs::write(&file, "// started again\n").unwrap();
    let restored = stubs::undo_reset(&dir, TaskId::SmithG1, &keep).unwrap();
    assert_eq!(restored.as_ref(), Some(&kept));
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "// my work\n");
    assert!(!kept.exists());
    let aside: Vec<String> = std::fs::read_dir(&keep)
        .unwrap()
        .map(|e| std::fs::read_to_string(e.unwrap().path()).unwrap())
        .collect();
    assert_eq!(aside, ["// started again\n"]);
    assert_eq!(
        stubs::undo_reset(&dir, TaskId::SmithG1, &keep).unwrap(),
        None
    );
}

#[test]
#[ignore = "slow: builds the handout (a second compile of the crate)"]
fn the_handout_builds_tests_and_grades_without_solutions() {
    let tmp = tempfile::tempdir().unwrap();
    let dir: PathBuf = tmp.path().join("student");
    // GitHub Classroom's template repository: the handout and one workflow.
    let files = pbrlab::autograder::github_classroom::write(root(), &dir).expect("handout written");
    assert!(files.contains(&PathBuf::from(
        pbrlab::autograder::github_classroom::WORKFLOW
    )));
    let library =
        pbrlab::handout::compiled_reference::build(root(), &dir).expect("reference compiled");
    pbrlab::handout::stubs::commit(&dir).expect("the handout committed");
    // `cargo test` grades the student's tasks, one test each: on the stubs, every one is
    // ignored as not attempted, and nothing else runs.
    let test = cargo(&dir, &["test", "--release"]);
    let stdout = String::from_utf8_lossy(&test.stdout);
    assert!(
        test.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&test.stderr)
    );
    let graded = graded_tasks();
    for task in &graded {
        assert_eq!(
            test_line(&stdout, task),
            Some(("[not attempted]".into(), "ignored".into())),
            "{stdout}"
        );
    }
    assert_eq!(stdout.matches("running ").count(), 1, "{stdout}");
    assert!(
        stdout.contains(&format!("0 passed; 0 failed; {} ignored", graded.len())),
        "{stdout}"
    );
    // `--try`: the workflow's grading step on a submission, in the template with its
    // files over the stubs (put back afterwards), and what the grading reporter would read.
    let submission = tmp.path().join("submission");
    std::fs::create_dir_all(&submission).unwrap();
    std::fs::copy(
        root().join("solutions/reflect.rs"),
        submission.join("reflect.rs"),
    )
    .unwrap();
    let tried = Command::new(env!("CARGO_BIN_EXE_pbrlab"))
        .args(["autograder", "github-classroom"])
        .arg(&dir)
        .arg("--try")
        .arg(&submission)
        .env_remove("CARGO_TARGET_DIR")
        .output()
        .unwrap();
    let view = String::from_utf8_lossy(&tried.stdout);
    assert!(
        tried.status.success(),
        "{view}{}",
        String::from_utf8_lossy(&tried.stderr)
    );
    assert!(view.contains("grading reporter would read"), "{view}");
    let reflect = view
        .lines()
        .find(|l| l.contains(" reflect ("))
        .expect("reflect");
    assert!(
        reflect.contains("5.00/5.00") && reflect.contains("pass"),
        "{view}"
    );
    let smith = view
        .lines()
        .find(|l| l.contains(" smith_g1 ("))
        .expect("smith_g1");
    assert!(
        smith.contains("0.00/6.00") && smith.contains("fail"),
        "{view}"
    );
    assert!(
        pbrlab::handout::stubs::edited(&dir).is_empty(),
        "the try put the stubs back"
    );
    let report = grade_through_cargo_run(&dir, &[]);
    assert_eq!(report.score, 0.0);
    assert!(report.max_score > 0.0);
    assert!(
        report
            .tasks
            .iter()
            .filter(|t| t.max_points > 0.0 && !t.task.starts_with("scene: "))
            .all(|t| t.status == pbrlab::grade::verdict::TaskStatus::NotAttempted),
        "{}",
        pbrlab::grade::report::text(&report, pbrlab::grade::report::Detail::Verbose)
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
    // `grade` offers nothing that needs the reference (another implementation, hidden
    // cases, variants); `render` offers every implementation, the compiled reference's too.
    let grade = help(&["grade", "--help"]);
    assert!(grade.contains("--format"), "{grade}");
    for option in ["--impl", "--hidden-seed", "--variant-key", "--student"] {
        assert!(!grade.contains(option), "{option} in {grade}");
    }
    let render = help(&["render", "--help"]);
    for choice in ["student", "reference", "mixed"] {
        assert!(render.contains(choice), "{choice} in {render}");
    }
    watch_shows_the_rebuild_the_table_a_hint_and_a_compile_error(&dir);
    one_broken_file_still_grades_through_cargo_run(&dir);
    // A student's own work never makes the README's test command fail: the tests about
    // the stubs check the files that are still stubs.
    for task in ["reflect", "smith_g1", "fresnel_schlick", "cosine_sample"] {
        let file = format!("{task}.rs");
        std::fs::copy(
            root().join("solutions").join(&file),
            dir.join("exercises").join(&file),
        )
        .unwrap();
    }
    let test = cargo_outside_ci(&dir, &["test", "--release"]);
    let stdout = String::from_utf8_lossy(&test.stdout);
    assert!(
        test.status.success(),
        "with four exercises written: {stdout}{}",
        String::from_utf8_lossy(&test.stderr)
    );
    for task in ["reflect", "smith_g1", "fresnel_schlick", "cosine_sample"] {
        assert_eq!(
            test_line(&stdout, task),
            Some((String::new(), "ok".into())),
            "{stdout}"
        );
    }
    // A wrong task fails its test, with the grader's report; a filter grades one task.
    let right = std::fs::read_to_string(dir.join("exercises/smith_g1.rs")).unwrap();
    let wrong = right.replace("2.0 * c / (c + root)", "2.0 * c / (c + root + 0.01)");
    assert_ne!(wrong, right);
    std::fs::write(dir.join("exercises/smith_g1.rs"), wrong).unwrap();
    let test = cargo_outside_ci(&dir, &["test", "--release", "smith_g1"]);
    std::fs::write(dir.join("exercises/smith_g1.rs"), right).unwrap();
    let stdout = String::from_utf8_lossy(&test.stdout);
    assert!(!test.status.success(), "{stdout}");
    assert_eq!(
        test_line(&stdout, "smith_g1"),
        Some((String::new(), "FAILED".into())),
        "{stdout}"
    );
    assert!(
        stdout.contains("smith_g1: FAILED"),
        "the grader's report: {stdout}"
    );
    let filtered = format!(
        "0 passed; 1 failed; 0 ignored; 0 measured; {} filtered out",
        graded.len() - 1
    );
    assert!(stdout.contains(&filtered), "{filtered} in {stdout}");
    the_classroom_workflow_reports_each_task_to_the_grading_reporter(
        &dir,
        &["reflect", "smith_g1", "fresnel_schlick", "cosine_sample"],
    );
    mixed_renders_take_the_compiled_reference_that_fits_the_build(&dir, &library);
    grade_sees_nothing_outside_the_handout(&dir);
}

/// The steps of a GitHub Actions workflow, as far as this test reads them.
#[derive(serde::Deserialize)]
struct Workflow {
    jobs: std::collections::BTreeMap<String, Job>,
}

#[derive(serde::Deserialize)]
struct Job {
    steps: Vec<Step>,
}

#[derive(serde::Deserialize)]
struct Step {
    id: Option<String>,
    uses: Option<String>,
    run: Option<String>,
    #[serde(default)]
    env: std::collections::BTreeMap<String, String>,
    #[serde(default)]
    with: std::collections::BTreeMap<String, String>,
}

/// The GitHub Classroom workflow of the template repository at `dir`, run as GitHub runs
/// it: its grading step's script in bash with `$GITHUB_OUTPUT`, then what the grading
/// reporter reads, for each runner it lists, from the environment its step sets: base64
/// JSON with the reporter's fields. The `passing` tasks score their points; the stubs 0.
fn the_classroom_workflow_reports_each_task_to_the_grading_reporter(dir: &Path, passing: &[&str]) {
    use base64::Engine;
    use pbrlab::autograder::github_classroom::{GRADE_STEP, WORKFLOW};
    let text = std::fs::read_to_string(dir.join(WORKFLOW)).unwrap();
    let workflow: Workflow = serde_saphyr::from_str(&text).expect("the workflow is YAML");
    let steps = &workflow.jobs.values().next().expect("a job").steps;
    let grade = steps
        .iter()
        .find(|s| s.id.as_deref() == Some(GRADE_STEP))
        .expect("the grading step");
    let reporter = steps
        .iter()
        .find(|s| {
            s.uses
                .as_deref()
                .is_some_and(|u| u.starts_with("classroom-resources/autograding-grading-reporter@"))
        })
        .expect("the grading reporter");
    let outputs_file = dir.join(".github-output");
    let run = Command::new("bash")
        .args(["-e", "-c", grade.run.as_deref().expect("a script")])
        .current_dir(dir)
        .env("GITHUB_OUTPUT", &outputs_file)
        .env("PBRLAB_STATE_DIR", dir.join(".state"))
        .env_remove("CARGO_TARGET_DIR")
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let outputs = std::fs::read_to_string(&outputs_file).unwrap();
    let output = |name: &str| {
        outputs
            .lines()
            .find_map(|l| l.strip_prefix(&format!("{name}=")))
            .map(str::to_string)
    };
    let runners: Vec<&str> = reporter.with["runners"].split(',').map(str::trim).collect();
    assert_eq!(
        runners.len(),
        graded_tasks().len() + pbrlab::grade::renders::RENDER_CHECKS.len()
    );
    for runner in runners {
        // The reporter reads `<RUNNER>_RESULTS`; the workflow sets it from the step output.
        let variable = format!("{}_RESULTS", runner.to_uppercase());
        assert_eq!(
            reporter.env.get(&variable).map(String::as_str),
            Some(format!("${{{{ steps.{GRADE_STEP}.outputs.{runner} }}}}").as_str()),
            "{variable}"
        );
        let encoded = output(runner).unwrap_or_else(|| panic!("no output {runner}: {outputs}"));
        let json = base64::engine::general_purpose::STANDARD
            .decode(encoded)
            .expect("base64");
        let result: serde_json::Value = serde_json::from_slice(&json).expect("JSON");
        assert_eq!(result["version"], 1, "{result}");
        let max = result["max_score"].as_f64().expect("max_score");
        assert!(max > 0.0, "{result}");
        let tests = result["tests"].as_array().expect("tests");
        assert!(!tests.is_empty(), "{result}");
        let mut score = 0.0;
        for test in tests {
            assert!(
                test["name"].is_string() && test["message"].is_string(),
                "{test}"
            );
            assert!(
                ["pass", "fail", "error"].contains(&test["status"].as_str().unwrap()),
                "{test}"
            );
            score += test["score"].as_f64().expect("score");
        }
        if passing.contains(&runner) {
            assert_eq!(result["status"], "pass", "{result}");
            assert!((score - max).abs() < 1e-9, "{result}");
        } else {
            assert_eq!(result["status"], "fail", "{result}");
            assert_eq!(score, 0.0, "{result}");
        }
    }
}

/// The kind (`[not attempted]`, or empty) and the outcome (`ok`, `FAILED`, `ignored`) of the
/// test `name` in libtest's output `stdout`.
fn test_line(stdout: &str, name: &str) -> Option<(String, String)> {
    stdout.lines().find_map(|line| {
        let words: Vec<&str> = line.split_whitespace().collect();
        match words.as_slice() {
            ["test", kind @ .., task, "...", outcome] if *task == name => {
                Some((kind.join(" "), outcome.to_string()))
            }
            _ => None,
        }
    })
}

/// The tasks the student writes, each a test of the handout's `cargo test`.
fn graded_tasks() -> Vec<&'static str> {
    pbrlab::worksheet::TaskId::ALL
        .into_iter()
        .filter(|t| !pbrlab::worksheet::task_functions(*t).is_empty())
        .map(|t| t.name())
        .collect()
}

/// `grade` in the handout, with the exercise check off: an exercise file that assembles an
/// `include!` of the instructor's reference (on this machine, by its absolute path) in a
/// macro does not compile, because the build's view holds nothing outside the handout, and
/// costs its own task only.
fn grade_sees_nothing_outside_the_handout(dir: &Path) {
    let reference = root().join("solutions/phong.rs");
    let file = dir.join("exercises/phong.rs");
    let shipped = std::fs::read_to_string(&file).unwrap();
    std::fs::write(
        &file,
        format!(
            "use crate::prelude::*;\n\
             macro_rules! grab {{ ($m:ident) => {{ $m!({:?}); }}; }}\n\
             mod stolen {{ grab!(include); }}\n\
             pub use stolen::*;\n",
            reference.display().to_string()
        ),
    )
    .unwrap();
    let out = cargo_command(
        dir,
        &[
            "run",
            "--release",
            "-q",
            "--",
            "grade",
            "phong",
            "--format",
            "json",
        ],
    )
    .env("PBRLAB_SOURCE_CHECK", "off")
    .output()
    .unwrap();
    std::fs::write(&file, shipped).unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let report: pbrlab::grade::verdict::GradeReport = serde_json::from_slice(&out.stdout).unwrap();
    let phong = report.tasks.iter().find(|t| t.task == "phong").unwrap();
    assert_eq!(phong.points, 0.0);
    assert!(
        matches!(
            phong.status,
            pbrlab::grade::verdict::TaskStatus::CompileError { .. }
        ),
        "{:?}",
        phong.status
    );
}

/// The JSON report of `cargo run --release -- grade TASKS` in the handout at `dir`, which
/// must succeed.
fn grade_through_cargo_run(dir: &Path, tasks: &[&str]) -> pbrlab::grade::verdict::GradeReport {
    let args = [
        &["run", "--release", "-q", "--", "grade"],
        tasks,
        &["--format", "json"],
    ];
    let grade = cargo(dir, &args.concat());
    assert!(
        grade.status.success(),
        "{}",
        String::from_utf8_lossy(&grade.stderr)
    );
    serde_json::from_slice(&grade.stdout).expect("a JSON report")
}

/// With `exercises/reflect.rs` not compiling (as the watch left it), the README's commands
/// still work: `pbrlab` links no student code, so `cargo run` starts it; `tasks` builds
/// nothing; and a grade charges the file to its task alone.
fn one_broken_file_still_grades_through_cargo_run(dir: &Path) {
    let broken = std::fs::read_to_string(dir.join("exercises/reflect.rs")).unwrap();
    assert!(
        !broken.contains("todo!"),
        "the watch left reflect.rs broken"
    );
    let tasks = cargo(dir, &["run", "--release", "-q", "--", "tasks"]);
    let stderr = String::from_utf8_lossy(&tasks.stderr);
    assert!(tasks.status.success(), "{stderr}");
    assert!(!stderr.contains("building the worker"), "{stderr}");
    let table = String::from_utf8_lossy(&tasks.stdout);
    let row = table.lines().find(|l| l.starts_with("reflect ")).unwrap();
    // Edited since its grade (`*`), edited and not graded, or graded as not compiling.
    assert!(
        row.contains('*') || row.contains("edited") || row.contains("COMPILE ERROR"),
        "{table}"
    );
    let report = grade_through_cargo_run(dir, &["reflect", "smith_g1"]);
    let status = |task: &str| {
        report
            .tasks
            .iter()
            .find(|t| t.task == task)
            .map(|t| t.status.clone())
            .unwrap_or_else(|| panic!("{task} graded"))
    };
    assert!(
        matches!(
            status("reflect"),
            pbrlab::grade::verdict::TaskStatus::CompileError { .. }
        ),
        "{:?}",
        status("reflect")
    );
    assert_eq!(
        status("smith_g1"),
        pbrlab::grade::verdict::TaskStatus::NotAttempted,
        "a stub beside a file that does not compile is still not attempted"
    );
}

/// `render --impl mixed` in the handout at `dir`: the student's written tasks with the
/// compiled reference at `library` for the rest; and, once the library's signature is
/// altered (as a library from another build would be), a refusal that says what differs.
fn mixed_renders_take_the_compiled_reference_that_fits_the_build(dir: &Path, library: &Path) {
    let render = |output: &str| {
        cargo(
            dir,
            &[
                "run",
                "--release",
                "-q",
                "--",
                "render",
                "scenes/cornell.yaml",
                "--impl",
                "mixed",
                "--spp",
                "1",
                "--quiet",
                "-o",
                output,
            ],
        )
    };
    let out = render("renders/mixed.exr");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(
        stderr.contains("your code renders: reflect, cosine_sample"),
        "{stderr}"
    );
    let image = image::open(dir.join("renders/mixed.exr")).expect("the render is an image");
    let pixels = image.to_rgb32f();
    assert!(
        pixels.pixels().any(|p| p.0.iter().any(|c| *c > 0.0)),
        "a black render"
    );
    let mut bytes = std::fs::read(library).unwrap();
    let at = bytes
        .windows(9)
        .position(|w| w == b"; sources")
        .expect("the signature is in the library")
        + 10;
    bytes[at] = if bytes[at] == b'0' { b'1' } else { b'0' };
    std::fs::write(library, bytes).unwrap();
    let out = render("renders/refused.exr");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success());
    assert!(
        stderr.contains("was built for another build") && stderr.contains("sources "),
        "{stderr}"
    );
}

/// `cargo` in `dir` as a student runs it (CI's variable insists on untouched stubs).
fn cargo_outside_ci(dir: &Path, args: &[&str]) -> std::process::Output {
    cargo_command(dir, args)
        .env_remove("CI")
        .output()
        .expect("cargo runs")
}

/// `pbrlab watch reflect` in a pseudo-terminal of the built handout at `dir`: the first
/// screen, the next hint on `h`, a save that rebuilds (cargo's progress shown) and
/// regrades to full marks, a save that does not compile (the compiler's message and
/// COMPILE ERROR in the table), and `q` ending the watch. Every screen fits 80×24.
fn watch_shows_the_rebuild_the_table_a_hint_and_a_compile_error(dir: &Path) {
    let mut command = Command::new(dir.join("target/release/pbrlab"));
    command
        .args(["watch", "reflect", "--poll-ms", "100"])
        .current_dir(dir)
        .env("PBRLAB_STATE_DIR", dir.join(".watch-state"))
        .env_remove("CARGO_TARGET_DIR");
    let mut watch = rexpect::session::spawn_command(command, Some(180_000)).expect("a pty");
    let (_, screen) = next_screen(&mut watch, "at the start");
    assert!(screen.contains("not attempted (1): reflect"), "{screen}");
    assert!(screen.contains("h: next hint for reflect"), "{screen}");
    key(&mut watch, "h");
    let (_, screen) = next_screen(&mut watch, "after h");
    for what in [
        "hint 1/",
        "Still stuck? `h` again shows hint 2",
        "not attempted (1)",
    ] {
        assert!(screen.contains(what), "{what} in {screen}");
    }
    let file = dir.join("exercises/reflect.rs");
    std::fs::copy(root().join("solutions/reflect.rs"), &file).unwrap();
    let (scrolled, screen) = next_screen(&mut watch, "after a save");
    for what in ["rebuilding and regrading", "Compiling pbrlab-exercises"] {
        assert!(scrolled.contains(what), "{what} in {scrolled}");
    }
    assert!(screen.contains("5/5"), "{screen}");
    std::fs::write(&file, "pub fn reflect(wo: Vec3, n: Vec3) -> Vec3 {\n").unwrap();
    let (_, screen) = next_screen(&mut watch, "after a broken save");
    for what in [
        "› reflect",
        "COMPILE ERROR",
        "exercises/reflect.rs",
        "h: next hint for reflect",
    ] {
        assert!(screen.contains(what), "{what} in {screen}");
    }
    key(&mut watch, "q");
    watch.exp_eof().expect("q ends the watch");
}

/// Everything the watch printed up to its next keys line, and the screen it drew last (what
/// follows the last clear), which must fit 80×24.
fn next_screen(watch: &mut rexpect::session::PtySession, when: &str) -> (String, String) {
    let printed = watch
        .exp_string("q: quit")
        .unwrap_or_else(|e| panic!("{when}, the watch drew no screen: {e}"))
        + "q: quit";
    let printed = crate::support::pty_text(&printed).replace('\r', "");
    let screen = printed.rsplit("\x1b[2J\x1b[H").next().unwrap().to_string();
    let lines: Vec<&str> = screen.lines().collect();
    assert!(lines.len() <= 24, "{when}: {} rows\n{screen}", lines.len());
    for line in &lines {
        assert!(line.chars().count() <= 80, "{when}: {line}");
    }
    (printed, screen)
}

/// Presses `key` in the watch's terminal.
fn key(watch: &mut rexpect::session::PtySession, key: &str) {
    watch.send(key).unwrap();
    watch.flush().unwrap();
}
