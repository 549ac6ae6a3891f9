//! The autograder packages end to end, without the services: the packages are written by the
//! real binary, their scripts run against a fake `/autograder` (Gradescope) and `/grade`
//! (PrairieLearn) tree in a temporary folder, and every results file is checked against
//! its format's specification (`pbrlab::autograder::schema`).
//!
//! The default suite checks the packages' files and that a results file is written when
//! grading cannot even start; the slow suite builds a package as its setup script does (the
//! framework from scratch: minutes) and grades a correct, a stub, a non-compiling and a
//! hostile submission through both services' scripts.

use pbrlab::autograder::schema::{Service, validate};
use pbrlab::worksheet::TaskId;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

fn repository() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Writes the `service` package into `out` with the real binary.
fn package(service: &str, out: &Path) {
    let done = Command::new(env!("CARGO_BIN_EXE_pbrlab"))
        .args(["autograder", service])
        .arg(out)
        .env("PBRLAB_REBUILT", "1")
        .output()
        .unwrap();
    assert!(
        done.status.success(),
        "{}",
        String::from_utf8_lossy(&done.stderr)
    );
}

/// A command with none of the outer cargo's target settings (the package builds in its own
/// tree).
fn clean(mut command: Command) -> Command {
    for key in [
        "CARGO_TARGET_DIR",
        "CARGO_BUILD_TARGET_DIR",
        "PBRLAB_EXERCISES",
    ] {
        command.env_remove(key);
    }
    command
}

fn read_json(file: &Path) -> Value {
    let text = std::fs::read_to_string(file)
        .unwrap_or_else(|e| panic!("{} was not written: {e}", file.display()));
    serde_json::from_str(&text).unwrap()
}

#[test]
fn the_packages_hold_what_each_service_runs() {
    let dir = tempfile::tempdir().unwrap();
    let (gs, pl) = (dir.path().join("gs"), dir.path().join("pl"));
    package("gradescope", &gs);
    package("prairielearn", &pl);
    for script in ["setup.sh", "run_autograder"] {
        let file = gs.join(script);
        let mode = std::os::unix::fs::PermissionsExt::mode(&file.metadata().unwrap().permissions());
        assert!(mode & 0o111 != 0, "{script} is executable");
        let syntax = Command::new("bash").arg("-n").arg(&file).status().unwrap();
        assert!(syntax.success(), "{script} parses");
    }
    assert!(
        Command::new("bash")
            .arg("-n")
            .arg(pl.join("entrypoint.sh"))
            .status()
            .unwrap()
            .success()
    );
    let dockerfile = std::fs::read_to_string(pl.join("Dockerfile")).unwrap();
    assert!(dockerfile.contains("cargo build --release --locked --bins"));
    let info = read_json(&pl.join("question/info.json"));
    assert_eq!(info["gradingMethod"], "External");
    assert_eq!(info["externalGradingOptions"]["enabled"], true);
    assert_eq!(
        info["externalGradingOptions"]["entrypoint"],
        "/pbrlab-entrypoint.sh"
    );
    assert!(info["externalGradingOptions"]["timeout"].as_u64().unwrap() <= 600);
    for root in [&gs, &pl] {
        let source = root.join("pbrlab");
        for file in [
            "Cargo.toml",
            "Cargo.lock",
            "solutions/mis.rs",
            "src/grader/lib.rs",
            "scenes/cornell.yaml",
        ] {
            assert!(source.join(file).is_file(), "{file} in the package");
        }
        for task in TaskId::ALL {
            let name = format!("exercises/{}.rs", task.name());
            let shipped = pbrlab::handout::stubs::shipped(repository(), task).unwrap();
            assert_eq!(
                std::fs::read_to_string(source.join(&name)).unwrap(),
                shipped,
                "{name} is the shipped stub"
            );
        }
    }
    let seed = |root: &PathBuf| {
        read_json(&root.join("pbrlab/pbrlab-autograder.json"))["hidden_seed"].clone()
    };
    assert_ne!(
        seed(&gs),
        seed(&pl),
        "each package draws its own hidden seed"
    );
    let again = Command::new(env!("CARGO_BIN_EXE_pbrlab"))
        .args(["autograder", "gradescope"])
        .arg(&gs)
        .env("PBRLAB_REBUILT", "1")
        .output()
        .unwrap();
    assert!(
        !again.status.success(),
        "a package is not written over another"
    );
}

#[test]
fn a_results_file_is_written_even_when_grading_cannot_start() {
    let dir = tempfile::tempdir().unwrap();
    // The grader binary is missing (setup failed): the script writes the results itself.
    for (script, service, root_var, submission) in [
        (
            "run_autograder",
            Service::Gradescope,
            "PBRLAB_AUTOGRADER_ROOT",
            "submission",
        ),
        (
            "entrypoint.sh",
            Service::Prairielearn,
            "PBRLAB_GRADE_ROOT",
            "student",
        ),
    ] {
        let root = dir.path().join(script);
        std::fs::create_dir_all(root.join(submission)).unwrap();
        let template = repository()
            .join("src/grader/autograder/templates")
            .join(script);
        let mut command = Command::new("bash");
        command
            .arg(&template)
            .env(root_var, &root)
            .env("PBRLAB_SOURCE", dir.path().join("no-such-package"));
        let out = clean(command).output().unwrap();
        let results = std::fs::read_to_string(root.join("results/results.json"))
            .unwrap_or_else(|_| panic!("{script}: {}", String::from_utf8_lossy(&out.stderr)));
        validate(service, &results).unwrap_or_else(|e| panic!("{script}: {e:#}\n{results}"));
        assert!(results.contains("did not start"), "{results}");
    }
    // The settings are unreadable: the grader writes score 0 with the reason.
    let results = dir.path().join("r/results.json");
    let out = Command::new(env!("CARGO_BIN_EXE_pbrlab"))
        .args(["autograder", "run", "--service", "gradescope", "--config"])
        .arg(dir.path().join("missing.json"))
        .arg("--submission")
        .arg(dir.path())
        .arg("--results")
        .arg(&results)
        .env("PBRLAB_REBUILT", "1")
        .output()
        .unwrap();
    assert!(!out.status.success());
    let json = std::fs::read_to_string(&results).unwrap();
    validate(Service::Gradescope, &json).unwrap();
    assert_eq!(read_json(&results)["score"], 0.0);
    assert!(json.contains("missing.json"), "{json}");
}

/// The submissions of the end-to-end test, by name: (file, text) pairs; the hostile one
/// tries to write `results` itself.
fn submissions(results: &Path) -> Vec<(&'static str, Vec<(String, String)>)> {
    let solution = |t: TaskId| {
        std::fs::read_to_string(repository().join(format!("solutions/{}.rs", t.name()))).unwrap()
    };
    let every = |skip: &[TaskId]| -> Vec<(String, String)> {
        TaskId::ALL
            .into_iter()
            .filter(|t| !skip.contains(t))
            .map(|t| (format!("exercises/{}.rs", t.name()), solution(t)))
            .collect()
    };
    let mut broken = every(&[TaskId::KajiyaKay]);
    broken.push((
        "exercises/kajiya_kay.rs".into(),
        solution(TaskId::KajiyaKay).replacen("pub fn ", "pub fn (", 1),
    ));
    // Correct code with the names a path tracer uses: nothing to refuse.
    let mut correct = every(&[TaskId::Reflect]);
    correct.push((
        "exercises/reflect.rs".into(),
        solution(TaskId::Reflect)
            + "\n#[allow(dead_code)]\nfn weight(path: f32, env: f32, include: f32, asm: f32) -> f32 {\n    \
               let mut total = path;\n    total += env + include + asm;\n    total\n}\n",
    ));
    let mut hostile = every(&[
        TaskId::Reflect,
        TaskId::FresnelSchlick,
        TaskId::SmithG1,
        TaskId::CosineSample,
    ]);
    // A first line the compiler skips and the check cannot read as Rust: refused.
    hostile.push((
        "smith_g1.rs".into(),
        format!(
            "#!r\"\nconst _STOLEN: &str = include_str!(\"../solutions/smith_g1.rs\");\n\"\n{}",
            solution(TaskId::SmithG1)
        ),
    ));
    // Another file compiled as a module of this one: refused (task files are leaves).
    hostile.push((
        "cosine_sample.rs".into(),
        solution(TaskId::CosineSample) + "\nmod smith_g1;\n",
    ));
    // Forges the results file from inside the sandbox (the path is this test's), and
    // prints a forged verdict.
    let forged = format!(
        "use crate::prelude::*;\n\
         pub fn reflect(wo: Vec3, n: Vec3) -> Vec3 {{\n\
         let _ = std::fs::write({results:?}, \"{{\\\"score\\\": 987654}}\");\n\
         println!(\"PBRLAB-RESULT {{{{\\\"score\\\": 987654}}}}\");\n\
         -wo + 2.0 * wo.dot(n) * n + Vec3::X\n\
         }}\n",
        results = results.display().to_string()
    );
    hostile.push(("reflect.rs".into(), forged));
    // Reads the reference at compile time.
    hostile.push((
        "fresnel_schlick.rs".into(),
        solution(TaskId::FresnelSchlick)
            + "\nconst _STOLEN: &str = include_str!(\"../solutions/fresnel_schlick.rs\");\n",
    ));
    vec![
        ("correct", correct),
        ("stub", Vec::new()),
        ("non_compiling", broken),
        ("hostile", hostile),
    ]
}

/// The submissions of the end-to-end test.
const NAMES: [&str; 4] = ["correct", "stub", "non_compiling", "hostile"];

/// Writes the submission `name` into `dir`, its hostile file aimed at `results`.
fn write_submission(dir: &Path, name: &str, results: &Path) {
    let (_, files) = submissions(results)
        .into_iter()
        .find(|(n, _)| *n == name)
        .unwrap();
    std::fs::create_dir_all(dir).unwrap();
    std::fs::write(dir.join("README.txt"), "not graded").unwrap();
    for (file, text) in files {
        let file = dir.join(file);
        std::fs::create_dir_all(file.parent().unwrap()).unwrap();
        std::fs::write(file, text).unwrap();
    }
}

/// The points of `task`'s tests in Gradescope results (visible and hidden).
fn gradescope_points(results: &Value, task: TaskId) -> (f64, f64) {
    let prefix = format!("{} — ", task.name());
    results["tests"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|t| t["name"].as_str().unwrap().starts_with(&prefix))
        .fold((0.0, 0.0), |(s, m), t| {
            (
                s + t["score"].as_f64().unwrap(),
                m + t["max_score"].as_f64().unwrap(),
            )
        })
}

#[test]
#[ignore = "slow: builds a package from scratch (minutes)"]
fn both_packages_grade_real_submissions_end_to_end() {
    let dir = tempfile::tempdir().unwrap();
    let gs = dir.path().join("gs");
    package("gradescope", &gs);
    let mut setup = Command::new("bash");
    setup
        .arg(gs.join("setup.sh"))
        .env("PBRLAB_SKIP_TOOLCHAIN", "1");
    let built = clean(setup).output().unwrap();
    assert!(
        built.status.success(),
        "setup.sh: {}",
        String::from_utf8_lossy(&built.stderr)
    );
    let total = |results: &Value| -> f64 {
        results["tests"]
            .as_array()
            .unwrap()
            .iter()
            .map(|t| t["max_score"].as_f64().unwrap())
            .sum()
    };
    let mut scores = std::collections::BTreeMap::new();
    for name in NAMES {
        let root = dir.path().join("autograder").join(name);
        write_submission(
            &root.join("submission"),
            name,
            &root.join("results/results.json"),
        );
        let mut run = Command::new("bash");
        run.arg(gs.join("run_autograder"))
            .env("PBRLAB_AUTOGRADER_ROOT", &root)
            .env("PBRLAB_SOURCE", gs.join("pbrlab"));
        let out = clean(run).output().unwrap();
        let file = root.join("results/results.json");
        let text = std::fs::read_to_string(&file).unwrap_or_else(|_| {
            panic!(
                "{name}: no results\n{}",
                String::from_utf8_lossy(&out.stderr)
            )
        });
        validate(Service::Gradescope, &text).unwrap_or_else(|e| panic!("{name}: {e:#}\n{text}"));
        let results: Value = serde_json::from_str(&text).unwrap();
        let score = results["score"].as_f64().unwrap();
        assert!(
            text.contains("README.txt: not an exercise file"),
            "{name}: ignored files listed"
        );
        scores.insert(name, (score, total(&results)));
        match name {
            "correct" => assert!(
                (score - total(&results)).abs() < 1e-6 && score > 100.0,
                "the reference's files score full marks: {score}\n{text}"
            ),
            "stub" => assert_eq!(score, 0.0, "{text}"),
            "non_compiling" => {
                let (kk, kk_max) = gradescope_points(&results, TaskId::KajiyaKay);
                assert_eq!(kk, 0.0);
                assert!(text.contains("does not compile"), "{text}");
                assert!(
                    (score - (total(&results) - kk_max)).abs() < 1e-6,
                    "a syntax error in kajiya_kay.rs costs kajiya_kay only: {score} of {}",
                    total(&results)
                );
            }
            "hostile" => {
                // What the code printed is shown as its output (the visible checks' worker
                // saw no hidden input), and is only that: no score, no file, came of it.
                let mut scored = results.clone();
                for test in scored["tests"].as_array_mut().unwrap() {
                    test["output"] = Value::Null;
                }
                assert!(
                    !scored.to_string().contains("987654"),
                    "the forged results did not land: {text}"
                );
                assert!(
                    text.contains("PBRLAB-RESULT"),
                    "the output is shown: {text}"
                );
                assert_eq!(gradescope_points(&results, TaskId::Reflect).0, 0.0);
                assert_eq!(gradescope_points(&results, TaskId::FresnelSchlick).0, 0.0);
                assert!(
                    text.contains("include_str"),
                    "the refusal is reported: {text}"
                );
                for (task, refusal) in [
                    (TaskId::SmithG1, "`#!`"),
                    (TaskId::CosineSample, "task files are leaves"),
                ] {
                    assert_eq!(gradescope_points(&results, task).0, 0.0, "{task:?}");
                    assert!(text.contains(refusal), "{refusal}: {text}");
                }
                let (_, mis_max) = gradescope_points(&results, TaskId::Mis);
                assert_eq!(
                    gradescope_points(&results, TaskId::Mis).0,
                    mis_max,
                    "the rest still grades"
                );
            }
            _ => unreachable!(),
        }
    }
    // With the exercise check switched off, the build's view alone stops a macro-assembled
    // `include!` of the package's reference: that task scores 0, every other full marks.
    let stealer = dir.path().join("autograder").join("stealer");
    let reference = gs.join("pbrlab/solutions/smith_g1.rs");
    let mut files: Vec<(String, String)> = TaskId::ALL
        .into_iter()
        .filter(|t| *t != TaskId::SmithG1)
        .map(|t| {
            let text =
                std::fs::read_to_string(repository().join(format!("solutions/{}.rs", t.name())));
            (format!("{}.rs", t.name()), text.unwrap())
        })
        .collect();
    files.push((
        "smith_g1.rs".into(),
        format!(
            "use crate::prelude::*;\n\
             macro_rules! grab {{ ($m:ident) => {{ $m!({:?}); }}; }}\n\
             mod stolen {{ grab!(include); }}\n\
             pub fn smith_g1(w: Vec3, alpha: f32) -> f32 {{ stolen::smith_g1(w, alpha) }}\n",
            reference.display().to_string()
        ),
    ));
    std::fs::create_dir_all(stealer.join("submission")).unwrap();
    for (file, text) in files {
        std::fs::write(stealer.join("submission").join(file), text).unwrap();
    }
    let mut run = Command::new("bash");
    run.arg(gs.join("run_autograder"))
        .env("PBRLAB_AUTOGRADER_ROOT", &stealer)
        .env("PBRLAB_SOURCE", gs.join("pbrlab"))
        .env("PBRLAB_SOURCE_CHECK", "off");
    let out = clean(run).output().unwrap();
    let text = std::fs::read_to_string(stealer.join("results/results.json")).unwrap_or_else(|_| {
        panic!(
            "stealer: no results\n{}",
            String::from_utf8_lossy(&out.stderr)
        )
    });
    let results: Value = serde_json::from_str(&text).unwrap();
    assert_eq!(
        gradescope_points(&results, TaskId::SmithG1).0,
        0.0,
        "{text}"
    );
    let (got, max) = gradescope_points(&results, TaskId::Reflect);
    assert_eq!(got, max, "the rest grades: {text}");
    // PrairieLearn: the same built source (an image would hold exactly this), its entrypoint,
    // with the two submissions whose scores are fractions (the conversion of a partial score,
    // and a hostile file's output kept out of it).
    let pl = dir.path().join("pl");
    package("prairielearn", &pl);
    std::fs::remove_dir_all(pl.join("pbrlab")).unwrap();
    std::os::unix::fs::symlink(gs.join("pbrlab"), pl.join("pbrlab")).unwrap();
    for name in ["non_compiling", "hostile"] {
        let root = dir.path().join("grade").join(name);
        write_submission(
            &root.join("student"),
            name,
            &root.join("results/results.json"),
        );
        let mut run = Command::new("bash");
        run.arg(pl.join("entrypoint.sh"))
            .env("PBRLAB_GRADE_ROOT", &root)
            .env("PBRLAB_SOURCE", pl.join("pbrlab"));
        clean(run).output().unwrap();
        let file = root.join("results/results.json");
        let text = std::fs::read_to_string(&file).unwrap();
        validate(Service::Prairielearn, &text).unwrap_or_else(|e| panic!("{name}: {e:#}\n{text}"));
        let results: Value = serde_json::from_str(&text).unwrap();
        let (gs_score, gs_total) = scores[name];
        let score = results["score"].as_f64().unwrap();
        assert!(
            (score - gs_score / gs_total).abs() < 1e-6,
            "{name}: PrairieLearn {score} against Gradescope {gs_score}/{gs_total}"
        );
    }
    // `--try`: each built package run on a submission as its platform runs it, in a
    // scratch folder, and the platform's view printed.
    let try_package = |service: &str, package: &Path, submission: &str| {
        let mut command = Command::new(env!("CARGO_BIN_EXE_pbrlab"));
        command
            .args(["autograder", service])
            .arg(package)
            .arg("--try")
            .arg(
                dir.path()
                    .join("autograder")
                    .join(submission)
                    .join("submission"),
            );
        let out = clean(command).output().unwrap();
        assert!(
            out.status.success(),
            "{service} --try: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8_lossy(&out.stdout).into_owned()
    };
    // The stubs' submission: no render runs, so a try costs seconds here (the grading
    // itself is what the runs above check).
    let (score, total) = scores["stub"];
    let view = try_package("gradescope", &gs, "stub");
    assert!(
        view.contains(&format!("Gradescope would show {score:.2} / {total:.2}")),
        "{view}"
    );
    assert!(
        view.contains("failed") && !view.contains(" passed "),
        "{view}"
    );
    let view = try_package("prairielearn", &pl, "stub");
    assert!(view.contains("PrairieLearn would show 0.0 %"), "{view}");
}

/// `--try` on a submission that is not there says so, naming it, before building anything.
#[test]
fn trying_a_package_on_a_missing_submission_names_it() {
    let dir = tempfile::tempdir().unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_pbrlab"))
        .args(["autograder", "gradescope"])
        .arg(dir.path().join("gs"))
        .arg("--try")
        .arg(dir.path().join("no-such-submission"))
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success());
    assert!(
        stderr.contains("reading the submission") && stderr.contains("no-such-submission"),
        "{stderr}"
    );
    assert!(!stderr.contains("building the package"), "{stderr}");
}
