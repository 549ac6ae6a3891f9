//! Checks the exercise files before the compiler sees them: nothing in them may reach outside
//! the student's crate at compile time. Framework-owned, like `lib.rs` and `Cargo.toml`: the
//! grader builds the exercise files with its own copy.
//!
//! It also writes the list of task modules that `lib.rs` includes, each compiled from
//! `exercises/<task>.rs`, or from the folder named by `PBRLAB_EXERCISES` (a submission's
//! copy), and from the shipped stub in the folder named by `PBRLAB_STUBS` for a task whose
//! file the grader found not to compile (`pbrlab::grade::build`).
//!
//! The rules, and why each one is needed beyond what the compiler already refuses:
//! - no `#[path]` (a module compiled from another file, e.g. `solutions/…`), no
//!   `include!`, `include_str!`, `include_bytes!` (a file's contents), no `env!` or
//!   `option_env!` (the build environment): the identifiers are refused anywhere, so a
//!   macro cannot assemble them either;
//! - no identifier starting with `pbrlab` (the framework is reached through `crate::prelude`
//!   and the modules `lib.rs` re-exports, which hold no answers; `pbrlab_solutions` and the
//!   grader are not for this crate) and no `extern crate` (which loads any crate in the
//!   build's dependency folder, the reference's included);
//! - no inline assembly (`asm!`, `global_asm!`, `naked_asm!`).
//!
//! `unsafe` is refused by the compiler itself (`#![forbid(unsafe_code)]` in `lib.rs`, which
//! a file's own attributes cannot lower).
//!
//! The check works on tokens (comments are not tokens; doc comments are, as attributes, and
//! a doc comment may of course mention any of these words in its text).

use proc_macro2::{TokenStream, TokenTree};

/// Identifiers no exercise file may contain, with what each could do.
const REFUSED: &[(&str, &str)] = &[
    ("path", "`#[path]` compiles a file from outside exercises/"),
    (
        "include",
        "`include!` compiles a file from outside exercises/",
    ),
    ("include_str", "`include_str!` reads a file at compile time"),
    (
        "include_bytes",
        "`include_bytes!` reads a file at compile time",
    ),
    ("env", "`env!` reads the build environment"),
    ("option_env", "`option_env!` reads the build environment"),
    ("asm", "inline assembly"),
    ("global_asm", "inline assembly"),
    ("naked_asm", "inline assembly"),
];

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

/// A folder of shipped stubs that stand in for the exercise files of the same name (the
/// grader's fallback for a task that does not compile).
const STUBS: &str = "PBRLAB_STUBS";

fn main() {
    println!("cargo::rerun-if-env-changed={EXERCISES}");
    println!("cargo::rerun-if-env-changed={STUBS}");
    let own = std::env::current_dir().expect("the build script runs in exercises/");
    let exercises = std::env::var_os(EXERCISES).map_or_else(|| own.clone(), Into::into);
    let stubs = std::env::var_os(STUBS).map(std::path::PathBuf::from);
    println!("cargo::rerun-if-changed={}", exercises.display());
    if let Some(stubs) = &stubs {
        println!("cargo::rerun-if-changed={}", stubs.display());
    }
    let mut modules = String::new();
    let mut refused = 0;
    for task in TASKS {
        let file = format!("{task}.rs");
        let stub = stubs
            .as_ref()
            .map(|s| s.join(&file))
            .filter(|s| s.is_file());
        let source = stub.clone().unwrap_or_else(|| exercises.join(&file));
        println!("cargo::rerun-if-changed={}", source.display());
        modules.push_str(&format!(
            "#[path = {:?}]\npub mod {task};\n",
            source.display().to_string()
        ));
        if stub.is_some() {
            // The shipped stub: the framework's text, not the student's.
            continue;
        }
        let Ok(text) = std::fs::read_to_string(&source) else {
            continue;
        };
        // A file that does not lex is left to the compiler, whose message is better.
        let Ok(tokens) = text.parse::<TokenStream>() else {
            continue;
        };
        for (line, column, why) in findings(tokens) {
            println!(
                "cargo::error=exercises/{file}:{line}:{column}: not allowed in an exercise file: {why}"
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

/// Every refused construct in `tokens`: line, column and the reason.
fn findings(tokens: TokenStream) -> Vec<(usize, usize, String)> {
    let mut found = Vec::new();
    walk(tokens, &mut found);
    found
}

fn walk(tokens: TokenStream, found: &mut Vec<(usize, usize, String)>) {
    let mut previous_extern = false;
    for token in tokens {
        let start = token.span().start();
        let at = (start.line, start.column + 1);
        match &token {
            TokenTree::Group(group) => walk(group.stream(), found),
            TokenTree::Ident(ident) => {
                let text = ident.to_string();
                let name = text.strip_prefix("r#").unwrap_or(&text);
                if let Some((_, why)) = REFUSED.iter().find(|(word, _)| *word == name) {
                    found.push((at.0, at.1, format!("`{name}`: {why}")));
                } else if name.starts_with("pbrlab") {
                    found.push((
                        at.0,
                        at.1,
                        format!("`{name}`: the framework's crates are not named directly"),
                    ));
                } else if previous_extern && name == "crate" {
                    found.push((
                        at.0,
                        at.1,
                        "`extern crate` loads crates this one does not depend on".into(),
                    ));
                }
            }
            _ => {}
        }
        previous_extern = matches!(&token, TokenTree::Ident(i) if *i == "extern");
    }
}
