//! `pbrlab grade-class` in this repository: a regrade that lists what changed, compile-time
//! attacks on what the build can read (`attacks.rs`), and (slow) compile-time bombs stopped
//! by the build's bounds.
//!
//! A test binary of its own because a class run builds each submission's worker in the
//! repository's own target folder, overwriting `target/release/pbrlab-worker` with that
//! submission's code while it grades. Cargo runs test binaries one after another, so no
//! other test grades the shipped exercises with a worker that is a submission's. Not in the
//! student handout (it grades with the reference).
#![cfg(feature = "solutions")]

mod attacks;
#[path = "../junit_schema.rs"]
mod junit_schema;

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

fn repository() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn read_json(file: &Path) -> Value {
    let text = std::fs::read_to_string(file)
        .unwrap_or_else(|e| panic!("{} was not written: {e}", file.display()));
    serde_json::from_str(&text).unwrap()
}

/// Runs `pbrlab grade-class SUBMISSIONS --out OUT` with `args` (and `--regrade`), which
/// must succeed; returns what it wrote on stderr.
fn grade_class(submissions: &Path, out: &Path, args: &[&std::ffi::OsStr], regrade: bool) -> String {
    let mut command = Command::new(env!("CARGO_BIN_EXE_pbrlab"));
    command
        .arg("grade-class")
        .arg(submissions)
        .arg("--out")
        .arg(out)
        .args(args);
    if regrade {
        command.arg("--regrade");
    }
    let output = command.output().unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
    assert!(output.status.success(), "{stderr}");
    stderr
}

/// The processes whose command line mentions `needle`.
fn processes_mentioning(needle: &str) -> Vec<String> {
    std::fs::read_dir("/proc")
        .unwrap()
        .flatten()
        .filter_map(|e| std::fs::read(e.path().join("cmdline")).ok())
        .map(|c| String::from_utf8_lossy(&c).replace('\0', " "))
        .filter(|c| c.contains(needle) && !c.contains("cargo test"))
        .collect()
}

/// Compile-time attacks on the build beside an honest `reflect`, by student: 8 GiB of
/// static data, a macro that expands exponentially, a type that grows with every
/// instantiation, and a flood of compiler errors (10⁵ of them, megabytes of messages).
const COMPILE_TIME_BOMBS: &[(&str, &str)] = &[
    (
        "static_bomb",
        "use crate::prelude::*;\n\
         static BIG: [u8; 1 << 33] = [1; 1 << 33];\n\
         pub fn smith_g1(w: Vec3, alpha: f32) -> f32 { let _ = (w, alpha); BIG[7] as f32 }\n",
    ),
    (
        "macro_bomb",
        "use crate::prelude::*;\n\
         macro_rules! double {\n\
             () => { 0u8 };\n\
             (x $($rest:tt)*) => { [double!($($rest)*), double!($($rest)*)] };\n\
         }\n\
         const LEAVES: usize = std::mem::size_of_val(&double!(x x x x x x x x x x x x x x x x \
         x x x x x x x x x x x x x x x x));\n\
         pub fn smith_g1(w: Vec3, alpha: f32) -> f32 { let _ = (w, alpha); LEAVES as f32 }\n",
    ),
    (
        "type_bomb",
        "use crate::prelude::*;\n\
         fn grow<T: Copy>(x: T, n: u32) -> f32 { if n == 0 { 0.0 } else { grow((x, x), n - 1) } }\n\
         pub fn smith_g1(w: Vec3, alpha: f32) -> f32 { let _ = w; grow(alpha, 40) }\n",
    ),
    (
        "error_flood",
        "use crate::prelude::*;\n\
         macro_rules! e0 { () => { let _: u8 = \"not a number\"; }; }\n\
         macro_rules! e1 { () => { e0!(); e0!(); e0!(); e0!(); e0!(); e0!(); e0!(); e0!(); e0!(); e0!(); }; }\n\
         macro_rules! e2 { () => { e1!(); e1!(); e1!(); e1!(); e1!(); e1!(); e1!(); e1!(); e1!(); e1!(); }; }\n\
         macro_rules! e3 { () => { e2!(); e2!(); e2!(); e2!(); e2!(); e2!(); e2!(); e2!(); e2!(); e2!(); }; }\n\
         macro_rules! e4 { () => { e3!(); e3!(); e3!(); e3!(); e3!(); e3!(); e3!(); e3!(); e3!(); e3!(); }; }\n\
         macro_rules! e5 { () => { e4!(); e4!(); e4!(); e4!(); e4!(); e4!(); e4!(); e4!(); e4!(); e4!(); }; }\n\
         #[allow(dead_code)]\n\
         fn flood() { e5!(); }\n\
         pub fn smith_g1(w: Vec3, alpha: f32) -> f32 { let _ = (w, alpha); 0.0 }\n",
    ),
];

/// A bomb's submission is stopped within its bound: a build error for the whole submission,
/// or a compile error of the bomb's own task with the rest graded as written.
fn assert_bounded(student: &Value) {
    let seconds = student["seconds"].as_f64().unwrap();
    assert!(
        seconds < 150.0,
        "the build was stopped by its bound: {student}"
    );
    if student["status"] == "build error" {
        return;
    }
    assert_eq!(student["status"], "graded", "{student}");
    let tasks = student["report"]["tasks"].as_array().unwrap();
    let task = |name: &str| tasks.iter().find(|t| t["task"] == name).unwrap();
    assert_eq!(
        task("smith_g1")["status"]["status"],
        "compile_error",
        "{student}"
    );
    assert_eq!(
        task("reflect")["points"],
        task("reflect")["max_points"],
        "{student}"
    );
}

#[test]
#[ignore = "slow: compile-time bombs run into the build's bounds (about three minutes)"]
fn a_class_run_bounds_a_compile_time_bomb_and_retries_what_was_not_graded() {
    let dir = tempfile::tempdir().unwrap();
    let (submissions, out) = (dir.path().join("submissions"), dir.path().join("out"));
    for (name, smith_g1) in COMPILE_TIME_BOMBS {
        let folder = submissions.join(name);
        std::fs::create_dir_all(&folder).unwrap();
        std::fs::write(folder.join("smith_g1.rs"), smith_g1).unwrap();
        std::fs::copy(
            repository().join("solutions/reflect.rs"),
            folder.join("reflect.rs"),
        )
        .unwrap();
    }
    let bomb = submissions.join("bomb");
    std::fs::create_dir_all(&bomb).unwrap();
    // A constant evaluation that never ends, its lint lowered.
    std::fs::write(
        bomb.join("smith_g1.rs"),
        "#![allow(long_running_const_eval)]\nuse crate::prelude::*;\n\
         const fn spin() -> u64 { let mut i = 1u64; loop { i = i.wrapping_add(2); if i == 0 { return i; } } }\n\
         const X: u64 = spin();\n\
         pub fn smith_g1(w: Vec3, alpha: f32) -> f32 { let _ = (w, alpha); X as f32 }\n",
    )
    .unwrap();
    let honest = submissions.join("honest");
    std::fs::create_dir_all(&honest).unwrap();
    std::fs::copy(
        repository().join("solutions/reflect.rs"),
        honest.join("reflect.rs"),
    )
    .unwrap();
    // An earlier run's infrastructure failure: not a grade, so graded again.
    std::fs::create_dir_all(out.join("students")).unwrap();
    std::fs::write(
        out.join("students/honest.json"),
        r#"{"student": "honest", "status": "not graded", "message": "the build did not finish"}"#,
    )
    .unwrap();
    // This run's scratch folders in a folder of its own (other tests run classes at the
    // same time), which, like /tmp, lets a worker of another user through.
    let scratch = tempfile::Builder::new()
        .prefix("pbrlab-bomb-run-")
        .permissions(std::os::unix::fs::PermissionsExt::from_mode(0o711))
        .tempdir()
        .unwrap();
    let run = || {
        let output = Command::new(env!("CARGO_BIN_EXE_pbrlab"))
            .arg("grade-class")
            .arg(&submissions)
            .arg("--out")
            .arg(&out)
            .env("TMPDIR", scratch.path())
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
        assert!(output.status.success(), "{stderr}");
        stderr
    };
    let stderr = run();
    assert!(
        stderr.contains("0 graded already, 6 to grade (1 of them again"),
        "{stderr}"
    );
    let honest = read_json(&out.join("students/honest.json"));
    assert_eq!(honest["status"], "graded", "{honest}");
    let reflect = honest["report"]["tasks"]
        .as_array()
        .unwrap()
        .iter()
        .find(|t| t["task"] == "reflect")
        .unwrap();
    assert_eq!(reflect["points"], reflect["max_points"], "{reflect}");
    let bomb = read_json(&out.join("students/bomb.json"));
    assert_eq!(bomb["status"], "build error", "{bomb}");
    // Whichever bound comes first: the compiler's CPU time, or (on a busy machine) the
    // build's wall deadline.
    let message = bomb["message"].as_str().unwrap();
    assert!(
        message.contains("CPU-time bound") || message.contains("did not finish within"),
        "{bomb}"
    );
    assert!(
        bomb["seconds"].as_f64().unwrap() < 150.0,
        "the build was stopped by its bound: {bomb}"
    );
    for (name, _) in COMPILE_TIME_BOMBS {
        assert_bounded(&read_json(&out.join(format!("students/{name}.json"))));
    }
    assert_eq!(
        processes_mentioning(&scratch.path().to_string_lossy()),
        Vec::<String>::new(),
        "no compiler outlives the class run"
    );
    // A build error is a grade: the next run keeps both.
    let stderr = run();
    assert!(stderr.contains("6 graded already, 0 to grade"), "{stderr}");
}

#[test]
fn a_regrade_lists_what_changed_keeps_the_old_results_and_changes_nothing_for_the_same_code() {
    let dir = tempfile::tempdir().unwrap();
    let (submissions, out) = (dir.path().join("submissions"), dir.path().join("out"));
    let solution = |task: &str| std::fs::read_to_string(repository().join(task)).unwrap();
    let (ada, bob) = (submissions.join("ada"), submissions.join("bob"));
    std::fs::create_dir_all(&ada).unwrap();
    std::fs::create_dir_all(&bob).unwrap();
    std::fs::write(ada.join("reflect.rs"), solution("solutions/reflect.rs")).unwrap();
    let right = solution("solutions/smith_g1.rs");
    let wrong = right.replace("2.0 * c / (c + root)", "2.0 * c / (c + root + 0.01)");
    assert_ne!(wrong, right);
    std::fs::write(bob.join("smith_g1.rs"), &wrong).unwrap();
    // Cy handed in notes and no exercise file: graded as the stubs, and told so.
    let cy = submissions.join("cy");
    std::fs::create_dir_all(&cy).unwrap();
    std::fs::write(cy.join("notes.txt"), "my answers are in my head\n").unwrap();
    // The seed from a file, as the README has it (a command line is every user's to read).
    let seed = dir.path().join("seed");
    std::fs::write(&seed, "7\n").unwrap();
    let grade_class = |regrade: bool| {
        grade_class(
            &submissions,
            &out,
            &["--hidden-seed-file".as_ref(), seed.as_os_str()],
            regrade,
        );
        std::fs::read_to_string(out.join("changes.md")).unwrap_or_default()
    };
    grade_class(false);
    let first = read_json(&out.join("students/bob.json"));
    assert_eq!(first["status"], "graded", "{first}");
    let empty = read_json(&out.join("students/cy.json"));
    assert!(
        empty["message"]
            .as_str()
            .unwrap()
            .contains("no exercise file"),
        "{empty}"
    );
    let feedback = std::fs::read_to_string(out.join("students/cy.txt")).unwrap();
    assert!(
        feedback.starts_with("no exercise file") && feedback.contains("ignored: notes.txt"),
        "{feedback}"
    );
    let summary = std::fs::read_to_string(out.join("summary.md")).unwrap();
    assert!(
        summary.contains("- cy graded: no exercise file"),
        "{summary}"
    );
    // The same files and seed: nothing changes.
    let changes = grade_class(true);
    assert!(
        changes.contains("3 submissions regraded: 3 unchanged, 0 changed"),
        "{changes}"
    );
    let history: Vec<PathBuf> = std::fs::read_dir(out.join("history"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    assert_eq!(history.len(), 1, "{history:?}");
    assert_eq!(
        read_json(&history[0].join("students/bob.json"))["report"],
        first["report"],
        "the replaced result is kept"
    );
    // Bob fixes his file: the regrade names the task, its points and the checks.
    std::fs::write(bob.join("smith_g1.rs"), &right).unwrap();
    std::thread::sleep(std::time::Duration::from_secs(1));
    let changes = grade_class(true);
    assert!(
        changes.contains("2 unchanged, 1 changed (1 up"),
        "{changes}"
    );
    assert!(changes.contains("## bob"), "{changes}");
    assert!(changes.contains("- smith_g1: "), "{changes}");
    assert!(changes.contains(": failed → passed"), "{changes}");
    assert!(!changes.contains("## ada"), "{changes}");
}

/// A class graded with per-student variants, feedback at `actual` and a class list: each
/// student gets a variant of their own, recorded in the result and reproduced by a regrade
/// with the same key; the feedback handed back names no expected value; the gradebooks
/// have Canvas's and Moodle's columns, a column per task and a total, the class list's
/// students; summary.html has the item analysis.
#[test]
fn a_class_with_variants_gets_its_gradebooks_item_analysis_and_restricted_feedback() {
    let dir = tempfile::tempdir().unwrap();
    let (submissions, out) = (dir.path().join("submissions"), dir.path().join("out"));
    let solution = |task: &str| std::fs::read_to_string(repository().join(task)).unwrap();
    for student in ["ada", "bob"] {
        std::fs::create_dir_all(submissions.join(student)).unwrap();
    }
    std::fs::write(
        submissions.join("ada/reflect.rs"),
        solution("solutions/reflect.rs"),
    )
    .unwrap();
    let wrong = solution("solutions/smith_g1.rs")
        .replace("2.0 * c / (c + root)", "2.0 * c / (c + root + 0.01)");
    std::fs::write(submissions.join("bob/smith_g1.rs"), wrong).unwrap();
    let roster = dir.path().join("roster.csv");
    std::fs::write(
        &roster,
        "Student,ID,SIS User ID,SIS Login ID,Section\n\
         Points Possible,,,,\n\
         \"Lovelace, Ada\",101,s101,ada,A\n",
    )
    .unwrap();
    let args: Vec<&std::ffi::OsStr> = [
        "--variant-key",
        "course secret",
        "--feedback",
        "actual",
        "--roster",
    ]
    .iter()
    .map(|a| a.as_ref())
    .chain([roster.as_os_str()])
    .collect();
    let grade_class = |regrade: bool| grade_class(&submissions, &out, &args, regrade);
    let stderr = grade_class(false);
    assert!(
        stderr.contains("bob"),
        "bob is not in the class list: {stderr}"
    );
    let variant = |student: &str| {
        read_json(&out.join(format!("students/{student}.json")))["report"]["variant"].clone()
    };
    let (ada, bob) = (variant("ada"), variant("bob"));
    assert!(
        ada.is_string() && bob.is_string() && ada != bob,
        "{ada} {bob}"
    );
    // The feedback handed back: the failing case's input and output, no expected value.
    let feedback = std::fs::read_to_string(out.join("students/bob.txt")).unwrap();
    assert!(
        feedback.contains("smith_g1(") && feedback.contains(": got "),
        "{feedback}"
    );
    assert!(!feedback.contains(", expected "), "{feedback}");
    assert!(
        feedback.contains("shrunk to smith_g1("),
        "shrunk in the runner: {feedback}"
    );
    assert!(
        feedback.contains(&format!("variant {}", bob.as_str().unwrap())),
        "{feedback}"
    );
    // The saved result stays in full for the instructor.
    let saved = std::fs::read_to_string(out.join("students/bob.json")).unwrap();
    assert!(
        saved.contains(", expected "),
        "the instructor's record is in full"
    );
    let canvas = std::fs::read_to_string(out.join("canvas.csv")).unwrap();
    let lines: Vec<&str> = canvas.lines().collect();
    assert!(
        lines[0].starts_with("Student,ID,SIS User ID,SIS Login ID,Section,pbrlab reflect,"),
        "{canvas}"
    );
    assert!(lines[0].ends_with(",pbrlab total"), "{canvas}");
    assert!(lines[1].starts_with("Points Possible,,,,,"), "{canvas}");
    assert!(
        lines[2].starts_with("\"Lovelace, Ada\",101,s101,ada,A,"),
        "{canvas}"
    );
    assert!(lines[3].starts_with("bob,,,bob,,0,"), "{canvas}");
    let moodle = std::fs::read_to_string(out.join("moodle.csv")).unwrap();
    assert!(
        moodle.starts_with("Username,Email address,pbrlab reflect (%),"),
        "{moodle}"
    );
    let page = std::fs::read_to_string(out.join("summary.html")).unwrap();
    assert!(page.contains("<svg") && page.contains("smith_g1"), "{page}");
    // The class's table is a table, every column of it.
    assert!(
        page.contains("<th>most common failing check</th>"),
        "{page}"
    );
    // junit.xml: a suite per student and task; bob's wrong smith_g1 fails with its input.
    let junit = std::fs::read_to_string(out.join("junit.xml")).unwrap();
    let (_, failures, _) = junit_schema::validate(&junit);
    assert!(failures >= 1, "{junit}");
    let suite = &junit[junit
        .find("<testsuite name=\"bob: smith_g1\"")
        .expect("bob's suite")..];
    let suite = &suite[..suite.find("</testsuite>").unwrap()];
    assert!(
        suite.contains("<failure") && suite.contains("smith_g1(w="),
        "{suite}"
    );
    // The same key regrades the same variants: nothing changes.
    grade_class(true);
    let changes = std::fs::read_to_string(out.join("changes.md")).unwrap();
    assert!(
        changes.contains("2 submissions regraded: 2 unchanged, 0 changed"),
        "{changes}"
    );
    assert_eq!(variant("bob"), bob);
}

/// Grades the attack catalogue (`attacks.rs`), the control and an honest student in one class
/// run, with the exercise check on or off and the build view's `mechanism` (`None`: the
/// first that works here), and returns each student's result.
fn grade_attacks(
    check: bool,
    mechanism: Option<&str>,
    scope: Scope,
) -> (
    Vec<attacks::Attack>,
    std::collections::BTreeMap<String, Value>,
) {
    let dir = tempfile::tempdir().unwrap();
    let (submissions, out) = (dir.path().join("submissions"), dir.path().join("out"));
    let mut catalogue = attacks::catalogue(repository(), &submissions, &out);
    if scope == Scope::Sample {
        catalogue.retain(|a| SAMPLE.contains(&a.student.as_str()));
    }
    let write = |student: &str, file: &str, text: &str| {
        let folder = submissions.join(student);
        std::fs::create_dir_all(&folder).unwrap();
        std::fs::write(folder.join(file), text).unwrap();
    };
    for attack in &catalogue {
        write(&attack.student, "smith_g1.rs", &attack.file);
    }
    write("control", "smith_g1.rs", &attacks::control(repository()));
    let solution = |task: &str| {
        std::fs::read_to_string(repository().join(format!("solutions/{task}.rs"))).unwrap()
    };
    for task in ["reflect", "smith_g1"] {
        write("honest", &format!("{task}.rs"), &solution(task));
    }
    if scope == Scope::Full {
        // Names that collide as file names, or that a spreadsheet would run as formulas.
        for student in HOSTILE_NAMES {
            write(student, "reflect.rs", &solution("reflect"));
        }
        // An honest slip whose error is in the framework's task table, not in the file.
        write("renamed", "reflect.rs", &solution("reflect"));
        let renamed = solution("smith_g1").replace("pub fn smith_g1(", "pub fn g1_ggx(");
        write("renamed", "smith_g1.rs", &renamed);
    }
    let mut command = Command::new(env!("CARGO_BIN_EXE_pbrlab"));
    command
        .arg("grade-class")
        .arg(&submissions)
        .arg("--out")
        .arg(&out)
        .args(["--hidden-seed", attacks::HIDDEN_SEED])
        .env("PBRLAB_CANARY", attacks::CANARY)
        .env("PBRLAB_SOURCE_CHECK", if check { "on" } else { "off" });
    if let Some(mechanism) = mechanism {
        command.env("PBRLAB_BUILD_VIEW", mechanism);
    }
    let output = command.output().unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "{stderr}");
    // Every name has a result of its own, and class.csv read back shows each name as text.
    let hostile = if scope == Scope::Full {
        HOSTILE_NAMES
    } else {
        &[]
    };
    let table = std::fs::read_to_string(out.join("class.csv")).unwrap();
    let mut reader = csv::Reader::from_reader(table.as_bytes());
    let names: Vec<String> = reader
        .records()
        .map(|r| r.unwrap().get(0).unwrap().to_string())
        .collect();
    for student in hostile {
        let shown = if student.starts_with(['=', '+', '-', '@']) {
            format!("'{student}")
        } else {
            student.to_string()
        };
        assert!(names.contains(&shown), "{shown:?} in {names:?}");
    }
    // No file the run wrote holds the secret.
    for entry in walk(&out) {
        let text = std::fs::read(&entry).unwrap();
        assert!(
            !text
                .windows(attacks::CANARY.len())
                .any(|w| w == attacks::CANARY.as_bytes()),
            "{} holds the grader's secret",
            entry.display()
        );
    }
    let results = std::fs::read_dir(out.join("students"))
        .unwrap()
        .flatten()
        .filter(|e| e.path().extension().is_some_and(|x| x == "json"))
        .map(|e| {
            let name = e.path().file_stem().unwrap().to_string_lossy().into_owned();
            (name, read_json(&e.path()))
        })
        .collect();
    (catalogue, results)
}

/// What a class run of the attack catalogue grades beside the control and the honest
/// student.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Scope {
    /// Every attack, the hostile names and a renamed task function.
    Full,
    /// Every attack.
    Attacks,
    /// One attack of each construct ([`SAMPLE`]): with the exercise check on, each is
    /// refused by the same rule (a macro called through a macro variable) as the rest.
    Sample,
}

/// The attacks of [`Scope::Sample`]: `include_bytes!` by path and through `/proc`,
/// `include!`, `#[path]` and `env!`, each assembled in a macro.
const SAMPLE: &[&str] = &[
    "read_reference",
    "read_own_environment",
    "include_reference",
    "path_reference",
    "env_secret",
];

/// Submission names that map to one file name if taken as they are, or that a spreadsheet
/// would run as formulas.
const HOSTILE_NAMES: &[&str] = &[
    "eve x",
    "eve_x",
    "eve.json",
    "=HYPERLINK(\"x\")",
    "@SUM(A1)",
];

/// Every file below `dir`.
fn walk(dir: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    for entry in std::fs::read_dir(dir).into_iter().flatten().flatten() {
        let path = entry.path();
        if path.is_dir() {
            files.extend(walk(&path));
        } else {
            files.push(path);
        }
    }
    files
}

/// The points `student` got on `task`, and the task's maximum.
fn points(student: &Value, task: &str) -> (f64, f64) {
    assert_eq!(
        student["status"], "graded",
        "{}: {}",
        student["student"], student["message"]
    );
    let tasks = student["report"]["tasks"].as_array().unwrap();
    let found = tasks.iter().find(|t| t["task"] == task).unwrap();
    (
        found["points"].as_f64().unwrap(),
        found["max_points"].as_f64().unwrap(),
    )
}

/// `task`'s status and its checks' summaries in `student`'s result (a failure message a
/// person can read).
fn summary(student: &Value, task: &str) -> String {
    let tasks = student["report"]["tasks"].as_array().unwrap();
    let found = tasks.iter().find(|t| t["task"] == task).unwrap();
    let checks: Vec<String> = found["checks"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| format!("{}: {}", c["name"], c["summary"]))
        .collect();
    format!("{} {}", found["status"], checks.join("; "))
}

/// Asserts what a class run of the attack catalogue must give: every attack 0 on its task and
/// graded (never "not graded"), the honest student full marks, a student who renamed a task
/// function 0 on that task only, and the control full marks exactly when the exercise check
/// is off.
fn assert_attacks_fail(check: bool, mechanism: Option<&str>, scope: Scope) {
    let (catalogue, results) = grade_attacks(check, mechanism, scope);
    for attack in &catalogue {
        let student = &results[&attack.student];
        assert_eq!(
            points(student, "smith_g1").0,
            0.0,
            "an exercise file that {} scored (check {}): {}",
            attack.what,
            if check { "on" } else { "off" },
            summary(student, "smith_g1")
        );
    }
    // Each name graded as itself, into a file of its own.
    let names = if scope == Scope::Full {
        HOSTILE_NAMES
    } else {
        &[]
    };
    for student in names {
        let result = results
            .values()
            .find(|r| r["student"] == *student)
            .unwrap_or_else(|| panic!("no result for {student:?}"));
        let (got, max) = points(result, "reflect");
        assert_eq!(got, max, "{student:?}: {}", summary(result, "reflect"));
    }
    let honest = &results["honest"];
    for task in ["reflect", "smith_g1"] {
        let (got, max) = points(honest, task);
        assert_eq!(got, max, "{task}: {}", summary(honest, task));
    }
    // A renamed task function costs its task, not the submission.
    if scope == Scope::Full {
        let renamed = &results["renamed"];
        assert_eq!(points(renamed, "smith_g1").0, 0.0);
        let (got, max) = points(renamed, "reflect");
        assert_eq!(got, max, "{}", summary(renamed, "reflect"));
    }
    let (got, max) = points(&results["control"], "smith_g1");
    let expected = if check { 0.0 } else { max };
    assert_eq!(
        got, expected,
        "the control reads its own file: full marks without the check, 0 with it"
    );
}

/// The proof that the build's view, not the exercise check, is the boundary: with the
/// check switched off, no attack reads anything worth reading.
#[test]
fn with_the_exercise_check_off_no_compile_time_attack_reads_anything_worth_reading() {
    assert_attacks_fail(false, None, Scope::Full);
}

/// The same where the kernel makes no namespaces (a container): the view made by Landlock
/// holds too.
#[test]
#[ignore = "slow: the attack catalogue once more, in the view made by Landlock"]
fn with_the_exercise_check_off_and_landlock_alone_no_attack_reads_anything_worth_reading() {
    assert_attacks_fail(false, Some("landlock"), Scope::Attacks);
}

/// One attack of each construct with the check on (refused by it first).
#[test]
#[ignore = "slow: the attack catalogue once more, with the exercise check on"]
fn with_the_exercise_check_on_every_compile_time_attack_scores_zero() {
    assert_attacks_fail(true, None, Scope::Sample);
}

/// A student whose `reflect`, `cosine_sample` and `smith_g1` each start 32 threads that spin
/// and spin themselves until the task's time limit, graded first, beside three honest
/// students: the honest students keep full marks (a submission that ran out of time while
/// others ran is graded again alone), and the hog loses those tasks only.
#[test]
#[ignore = "slow: a CPU hog beside three honest students (about half a minute)"]
fn a_cpu_hog_costs_no_other_student_a_point() {
    let dir = tempfile::tempdir().unwrap();
    let (submissions, out) = (dir.path().join("submissions"), dir.path().join("out"));
    let solution = |task: &str| {
        std::fs::read_to_string(repository().join(format!("solutions/{task}.rs"))).unwrap()
    };
    let tasks = [
        "reflect",
        "smith_g1",
        "cosine_sample",
        "path_trace",
        "delta_tracking",
    ];
    let hogs = ["aa_hog"];
    let spin = "    for _ in 0..32 { std::thread::spawn(|| loop { std::hint::black_box(0u64); }); }\n    \
                loop { std::hint::black_box(0u64); }\n";
    let hogging = [
        (
            "reflect",
            format!(
                "use crate::prelude::*;\npub fn reflect(wo: Vec3, n: Vec3) -> Vec3 {{\n    let _ = (wo, n);\n{spin}}}\n"
            ),
        ),
        (
            "smith_g1",
            format!(
                "use crate::prelude::*;\npub fn smith_g1(w: Vec3, alpha: f32) -> f32 {{\n    let _ = (w, alpha);\n{spin}}}\n"
            ),
        ),
        (
            "cosine_sample",
            format!(
                "use crate::prelude::*;\npub fn cosine_sample(u: Vec2) -> Vec3 {{\n    let _ = u;\n{spin}}}\n\
                 pub fn cosine_pdf(w: Vec3) -> f32 {{\n    let _ = w;\n{spin}}}\n"
            ),
        ),
    ];
    for student in ["ada", "bob", "cy"].into_iter().chain(hogs) {
        let folder = submissions.join(student);
        std::fs::create_dir_all(&folder).unwrap();
        for task in tasks {
            std::fs::write(folder.join(format!("{task}.rs")), solution(task)).unwrap();
        }
        if hogs.contains(&student) {
            for (task, text) in &hogging {
                std::fs::write(folder.join(format!("{task}.rs")), text).unwrap();
            }
        }
    }
    grade_class(
        &submissions,
        &out,
        &[
            "--timeout".as_ref(),
            "3".as_ref(),
            "--jobs".as_ref(),
            "2".as_ref(),
        ],
        false,
    );
    for student in ["ada", "bob", "cy"] {
        let result = read_json(&out.join(format!("students/{student}.json")));
        for task in tasks {
            let (got, max) = points(&result, task);
            assert_eq!(got, max, "{student} {task}: {}", summary(&result, task));
        }
    }
    for hog in hogs {
        let result = read_json(&out.join(format!("students/{hog}.json")));
        for (task, _) in &hogging {
            assert_eq!(points(&result, task).0, 0.0, "{hog} {task}");
        }
        let (got, max) = points(&result, "path_trace");
        assert_eq!(got, max, "{}", summary(&result, "path_trace"));
    }
}
