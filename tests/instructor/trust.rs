//! Compile-time trust boundary: exercise files that try to reach the reference, the grader
//! or the stored data, or to use `unsafe`, do not compile, and the message names the file
//! and line. Each hostile file is built with cargo in a scratch copy of the student's crate
//! (its framework-owned lib.rs, build.rs and manifest, the framework by path), so the real
//! build script and the real compiler flags are what refuse it. The hostile code at run
//! time is in `tests/instructor/hostile.rs`.

use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// A scratch workspace holding a copy of `exercises/`, depending on this repository's
/// framework. Its build output goes to one folder under `target/`, kept between runs.
struct Scratch {
    _dir: tempfile::TempDir,
    root: PathBuf,
}

impl Scratch {
    fn new() -> Self {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let root = dir.path().to_path_buf();
        let exercises = root.join("exercises");
        std::fs::create_dir_all(&exercises).unwrap();
        for entry in std::fs::read_dir(root_exercises()).unwrap().flatten() {
            let name = entry.file_name();
            if name == "Cargo.toml" {
                continue;
            }
            std::fs::copy(entry.path(), exercises.join(&name)).unwrap();
        }
        let manifest = std::fs::read_to_string(root_exercises().join("Cargo.toml")).unwrap();
        // The framework by its real path, so its build in `target/trust-check` is reused.
        let framework = self::root().join("src");
        let manifest = manifest.replace("\"../src", &format!("\"{}", framework.display()));
        assert!(!manifest.contains("../src"), "{manifest}");
        std::fs::write(exercises.join("Cargo.toml"), manifest).unwrap();
        // The student's crate takes its lints from the workspace: the scratch one has the
        // repository's.
        let workspace = std::fs::read_to_string(self::root().join("Cargo.toml")).unwrap();
        let lints: String = workspace
            .split_inclusive('\n')
            .skip_while(|l| !l.starts_with("[workspace.lints"))
            .take_while(|l| !l.starts_with('[') || l.starts_with("[workspace.lints"))
            .collect();
        assert!(lints.contains("[workspace.lints"), "{workspace}");
        std::fs::write(
            root.join("Cargo.toml"),
            format!("[workspace]\nmembers = [\"exercises\"]\nresolver = \"3\"\n\n{lints}"),
        )
        .unwrap();
        std::fs::copy(self::root().join("Cargo.lock"), root.join("Cargo.lock")).unwrap();
        Self { _dir: dir, root }
    }

    /// Replaces `exercises/<file>` with `text`.
    fn write(&self, file: &str, text: &str) {
        std::fs::write(self.root.join("exercises").join(file), text).unwrap();
    }

    /// Restores `exercises/<file>` to the shipped one.
    fn restore(&self, file: &str) {
        std::fs::copy(
            root_exercises().join(file),
            self.root.join("exercises").join(file),
        )
        .unwrap();
    }

    /// `cargo check` of the student's crate: success, and what cargo printed.
    fn check(&self) -> (bool, String) {
        let out = Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()))
            .args(["check", "--offline", "--quiet", "--message-format", "short"])
            .current_dir(&self.root)
            .env("CARGO_TARGET_DIR", root().join("target/trust-check"))
            .env_remove("RUSTFLAGS")
            .output()
            .expect("cargo runs");
        (
            out.status.success(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        )
    }
}

fn root_exercises() -> PathBuf {
    root().join("exercises")
}

/// `exercises/smith_g1.rs` with `body` as the body of `smith_g1` and `items` after it.
fn smith_g1(body: &str, items: &str) -> String {
    format!(
        "use crate::prelude::*;\n\
         \n\
         pub fn smith_g1(w: Vec3, alpha: f32) -> f32 {{\n\
         {body}\n\
         }}\n\
         {items}\n"
    )
}

/// Hostile exercise files: what each does, the file, and the line the message must name.
fn catalogue() -> Vec<(&'static str, String, usize)> {
    vec![
        (
            "calls the reference crate",
            smith_g1("    pbrlab_solutions::smith_g1::smith_g1(w, alpha)", ""),
            4,
        ),
        (
            "loads the reference crate with extern crate",
            smith_g1(
                "    reference::smith_g1::smith_g1(w, alpha)",
                "extern crate pbrlab_solutions as reference;",
            ),
            6,
        ),
        (
            "compiles the reference's file with #[path]",
            smith_g1(
                "    stolen::smith_g1(w, alpha)",
                "#[path = \"../solutions/smith_g1.rs\"]\nmod stolen;",
            ),
            6,
        ),
        (
            "assembles #[path] in a macro",
            smith_g1(
                "    stolen::smith_g1(w, alpha)",
                "macro_rules! from { ($a:ident) => { #[$a = \"../solutions/smith_g1.rs\"] mod stolen; } }\nfrom!(path);",
            ),
            6,
        ),
        (
            "reads the expected data with include_str!",
            smith_g1(
                "    EXPECTED.len() as f32",
                "const EXPECTED: &str = include_str!(\"../src/grader/tasks/smith_g1/expected.snap\");",
            ),
            6,
        ),
        (
            "names the framework crate to reach the grader",
            smith_g1(
                "    pbrlab::grade::expected::load_all().map_or(0.0, |d| d.len() as f32)",
                "",
            ),
            4,
        ),
        (
            "asks the framework for the reference through the crate's re-exports",
            smith_g1(
                "    crate::implementation::reference().smith_g1(w, alpha)",
                "",
            ),
            4,
        ),
        (
            "reads the grader's stored data through the crate's re-exports",
            smith_g1(
                "    crate::grade::expected::load_all().map_or(0.0, |d| d.len() as f32)",
                "",
            ),
            4,
        ),
        (
            "forwards to the framework's volumetric path tracer",
            smith_g1(
                "    let _ = crate::integrator::volpath::MAX_TRACKING_STEPS;\n    0.0",
                "",
            ),
            4,
        ),
        (
            "uses unsafe code",
            smith_g1(
                "    unsafe { std::mem::transmute::<u32, f32>(0x3f80_0000) }",
                "",
            ),
            4,
        ),
        (
            "lifts the crate's forbid(unsafe_code)",
            format!(
                "#![allow(unsafe_code)]\n{}",
                smith_g1("    unsafe { std::mem::transmute::<u32, f32>(0) }", "")
            ),
            1,
        ),
    ]
}

#[test]
#[ignore = "slow: checks the framework once more in its own target folder, then each hostile file"]
fn hostile_exercise_files_do_not_compile_and_the_message_names_the_line() {
    let scratch = Scratch::new();
    let (ok, messages) = scratch.check();
    assert!(ok, "the shipped exercises must compile:\n{messages}");
    // A correct file in the same shape compiles: what fails below is the hostile line.
    scratch.write(
        "smith_g1.rs",
        &smith_g1("    let _ = (w, alpha);\n    1.0", ""),
    );
    let (ok, messages) = scratch.check();
    assert!(ok, "an honest smith_g1 must compile:\n{messages}");
    for (what, text, line) in catalogue() {
        scratch.write("smith_g1.rs", &text);
        let (ok, messages) = scratch.check();
        assert!(!ok, "an exercise file that {what} compiled:\n{text}");
        let place = format!("exercises/smith_g1.rs:{line}:");
        assert!(
            messages.contains(&place),
            "the message for a file that {what} does not name {place}:\n{messages}"
        );
    }
    scratch.restore("smith_g1.rs");
}
