//! Checks the exercise files before the compiler sees them: nothing in them may reach outside
//! the student's crate at compile time. Framework-owned, like `lib.rs` and `Cargo.toml`: the
//! grader builds the exercise files with its own copy. The rules, and why each is needed, are
//! in the check's crate (`src/exercise-check/`): it refuses constructs, never names, and
//! refuses a file it cannot read rather than skipping it.
//!
//! It also writes the list of task modules that `lib.rs` includes, each compiled from
//! `exercises/<task>.rs`, or from the folder named by `PBRLAB_EXERCISES` (the grader's copy
//! of a submission, in which a task file that does not compile has been replaced by its
//! shipped stub: `pbrlab::grade::student_build`). Only that one folder is compiled.

/// The task files, one module each (the framework's task table names them).
const TASKS: [&str; 15] = [
    "reflect",
    "refract_stack",
    "fresnel_schlick",
    "cosine_sample",
    "smith_g1",
    "beckmann_ndf",
    "cook_torrance",
    "ndf_sample",
    "aniso_ndf",
    "phong",
    "brdf_check",
    "kajiya_kay",
    "path_trace",
    "mis",
    "delta_tracking",
];

/// The folder of the exercise files to compile, when not this one (the grader builds a
/// submission from its own copy).
const EXERCISES: &str = "PBRLAB_EXERCISES";

/// `off` turns the check off: the grader's tests build hostile files without it, to prove
/// that what the build can read holds nothing worth taking (the check is a second line).
const SOURCE_CHECK: &str = "PBRLAB_SOURCE_CHECK";

fn main() {
    println!("cargo::rerun-if-env-changed={EXERCISES}");
    println!("cargo::rerun-if-env-changed={SOURCE_CHECK}");
    let checked = std::env::var(SOURCE_CHECK).map_or(true, |v| v != "off");
    let own = std::env::current_dir().expect("the build script runs in exercises/");
    let exercises = std::env::var_os(EXERCISES).map_or_else(|| own.clone(), Into::into);
    println!("cargo::rerun-if-changed={}", exercises.display());
    let mut modules = String::new();
    let mut refused = 0;
    for task in TASKS {
        let file = format!("{task}.rs");
        let source = exercises.join(&file);
        println!("cargo::rerun-if-changed={}", source.display());
        modules.push_str(&format!(
            "#[path = {:?}]\npub mod {task};\n",
            source.display().to_string()
        ));
        let findings = match std::fs::read(&source) {
            Err(e) => vec![pbrlab_exercise_check::Finding {
                line: 1,
                column: 1,
                why: format!(
                    "the file cannot be read ({e}): `pbrlab reset {task}` puts the stub back"
                ),
            }],
            Ok(bytes) => match String::from_utf8(bytes) {
                Ok(text) if checked => pbrlab_exercise_check::check(&text),
                Ok(_) => Vec::new(),
                Err(e) => {
                    let before = &e.as_bytes()[..e.utf8_error().valid_up_to()];
                    vec![pbrlab_exercise_check::Finding {
                        line: 1 + before.iter().filter(|&&b| b == b'\n').count(),
                        column: 1,
                        why: "the file is not UTF-8 text".into(),
                    }]
                }
            },
        };
        for f in findings {
            println!(
                "cargo::error=exercises/{file}:{}:{}: not allowed in an exercise file: {}",
                f.line, f.column, f.why
            );
            refused += 1;
        }
    }
    if refused > 0 {
        println!(
            "cargo::error=exercise files may use only their own crate and the framework's task \
             API (crate::prelude and the modules it names)"
        );
    }
    let out = std::path::PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    std::fs::write(out.join("tasks.rs"), modules).expect("OUT_DIR is writable");
}
