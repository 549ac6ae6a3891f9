//! Compile-time attacks on the build, as a hostile student writes them: macros assemble the
//! constructs the exercise check refuses (`include!`, `include_bytes!`, `#[path]`, `env!`)
//! from pieces it accepts, and aim them at everything worth reading on the grader's machine.
//!
//! Each attack is a `smith_g1.rs` that returns the correct answer (the reference's code,
//! which a student could have written) only when what it read is not empty or holds the
//! secret it looks for, and NaN (never right) otherwise; a read that fails is a compile
//! error. So an attack
//! scores 0 exactly when the build could not see its target: graded with the exercise
//! check switched off, that proves the build's view is the boundary, not the check. The
//! control reads its own file, which the build may see, and scores full marks with the
//! check off: the mechanism works where there is something to read.

use std::path::Path;

/// The secret put in the grader's environment (`PBRLAB_CANARY`).
pub const CANARY: &str = "pbrlab-canary-7f3c9a1e5b";

/// The hidden seed on the grader's command line.
pub const HIDDEN_SEED: &str = "4242424242";

/// One attack: the student's name (its folder), what it tries, and its `smith_g1.rs`.
pub struct Attack {
    pub student: String,
    pub what: &'static str,
    pub file: String,
}

/// The reference's `smith_g1` as a module `right` (what a correct student would write).
fn right(repository: &Path) -> String {
    let text = std::fs::read_to_string(repository.join("solutions/smith_g1.rs")).unwrap();
    let body: String = text
        .lines()
        .filter(|l| !l.starts_with("//!"))
        .map(|l| format!("    {l}\n"))
        .collect();
    format!("mod right {{\n{body}}}\n")
}

/// A file that reads `path` with `include_bytes!` assembled by a macro, and answers right
/// when `seen` (an expression over the bytes `X`) holds.
fn read(repository: &Path, path: &str, seen: &str) -> String {
    format!(
        "use crate::prelude::*;\n\
         {right}\
         macro_rules! grab {{ ($m:ident, $p:expr) => {{ $m!($p) }}; }}\n\
         const X: &[u8] = grab!(include_bytes, {path:?});\n\
         fn seen() -> bool {{ {seen} }}\n\
         pub fn smith_g1(w: Vec3, alpha: f32) -> f32 {{\n    \
             if seen() {{ right::smith_g1(w, alpha) }} else {{ f32::NAN }}\n\
         }}\n",
        right = right(repository),
    )
}

/// `X` holds `needle`.
fn holds(needle: &str) -> String {
    format!(
        "X.windows({}).any(|w| w == {:?}.as_bytes())",
        needle.len(),
        needle
    )
}

/// The catalogue, for a class run of `submissions` into `out` from `repository`.
pub fn catalogue(repository: &Path, submissions: &Path, out: &Path) -> Vec<Attack> {
    let r = repository.display().to_string();
    let not_empty = "!X.is_empty()";
    let reads: Vec<(&str, &'static str, String, String)> = vec![
        (
            "read_reference",
            "reads the reference's source by its absolute path",
            format!("{r}/solutions/smith_g1.rs"),
            not_empty.into(),
        ),
        (
            "read_through_cwd",
            "reads the reference through the compiler's /proc/self/cwd",
            "/proc/self/cwd/solutions/smith_g1.rs".into(),
            not_empty.into(),
        ),
        (
            "read_through_root",
            "reads the reference through /proc/self/root",
            format!("/proc/self/root{r}/solutions/smith_g1.rs"),
            not_empty.into(),
        ),
        (
            "read_variants",
            "reads the tests' variants (correct implementations among them)",
            format!("{r}/src/grader/tasks/smith_g1/variants.rs"),
            not_empty.into(),
        ),
        (
            "read_tests",
            "reads the instructor tests",
            format!("{r}/tests/instructor/hostile.rs"),
            not_empty.into(),
        ),
        (
            "read_git",
            "reads the repository's history",
            format!("{r}/.git/HEAD"),
            not_empty.into(),
        ),
        (
            "read_compiled_reference",
            "reads the compiled reference in the target folder",
            format!("{r}/target/release/libpbrlab_solutions.rlib"),
            not_empty.into(),
        ),
        (
            "read_pbrlab_binary",
            "reads the instructor's pbrlab binary (the reference linked in)",
            format!("{r}/target/release/pbrlab"),
            not_empty.into(),
        ),
        (
            "read_framework_source",
            "reads the grader's source",
            format!("{r}/src/grader/grade/checks.rs"),
            not_empty.into(),
        ),
        (
            "read_expected_data",
            "reads the stored expected data",
            format!("{r}/src/grader/tasks/smith_g1/expected.snap"),
            not_empty.into(),
        ),
        (
            "read_other_student",
            "reads another student's submission",
            submissions.join("honest/smith_g1.rs").display().to_string(),
            not_empty.into(),
        ),
        (
            "zz_read_results",
            "reads another student's result",
            out.join("students/honest.json").display().to_string(),
            not_empty.into(),
        ),
        (
            "read_own_environment",
            "looks for the grader's secret in the compiler's environment",
            "/proc/self/environ".into(),
            holds(CANARY),
        ),
        (
            "read_first_environment",
            "looks for the grader's secret in PID 1's environment",
            "/proc/1/environ".into(),
            holds(CANARY),
        ),
        (
            "read_first_command_line",
            "looks for the hidden seed on PID 1's command line",
            "/proc/1/cmdline".into(),
            holds(HIDDEN_SEED),
        ),
        (
            "read_parent_command_line",
            "looks for the hidden seed on the compiler's parent's command line",
            "/proc/self/../1/cmdline".into(),
            holds(HIDDEN_SEED),
        ),
    ];
    let mut attacks: Vec<Attack> = reads
        .into_iter()
        .map(|(student, what, path, seen)| Attack {
            student: student.into(),
            what,
            file: read(repository, &path, &seen),
        })
        .collect();
    attacks.push(Attack {
        student: "include_reference".into(),
        what: "compiles the reference's file with a macro-assembled include!",
        file: format!(
            "use crate::prelude::*;\n\
             macro_rules! grab {{ ($m:ident) => {{ $m!({:?}); }}; }}\n\
             mod stolen {{ grab!(include); }}\n\
             pub fn smith_g1(w: Vec3, alpha: f32) -> f32 {{ stolen::smith_g1(w, alpha) }}\n",
            format!("{r}/solutions/smith_g1.rs")
        ),
    });
    attacks.push(Attack {
        student: "path_reference".into(),
        what: "compiles the reference's file with a macro-assembled #[path]",
        file: format!(
            "use crate::prelude::*;\n\
             macro_rules! from {{ ($a:ident) => {{ #[$a = {:?}] mod stolen; }}; }}\n\
             from!(path);\n\
             pub fn smith_g1(w: Vec3, alpha: f32) -> f32 {{ stolen::smith_g1(w, alpha) }}\n",
            format!("{r}/solutions/smith_g1.rs")
        ),
    });
    attacks.push(Attack {
        student: "env_secret".into(),
        what: "reads the grader's secret with a macro-assembled env!",
        file: format!(
            "use crate::prelude::*;\n\
             {right}\
             macro_rules! grab {{ ($m:ident) => {{ $m!(\"PBRLAB_CANARY\") }}; }}\n\
             const X: &str = grab!(env);\n\
             pub fn smith_g1(w: Vec3, alpha: f32) -> f32 {{\n    \
                 if X.is_empty() {{ f32::NAN }} else {{ right::smith_g1(w, alpha) }}\n\
             }}\n",
            right = right(repository)
        ),
    });
    attacks
}

/// The control: the same assembled `include_bytes!`, of the student's own file, which the
/// build may read. With the exercise check off it scores full marks.
pub fn control(repository: &Path) -> String {
    read(repository, "smith_g1.rs", "!X.is_empty()")
}
