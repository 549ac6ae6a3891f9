//! Which files of the instructor repository go into the student handout, and how
//! Cargo.toml changes there.
//!
//! Left out: `solutions/`, build output and local state, every test but the student's
//! ([`STUDENT_TESTS`]: the framework's own tests stay with the instructor, and many use the
//! reference), any bench that uses the reference, the tests' variants of each task
//! (`src/grader/tasks/<task>/variants.rs`: they hold correct implementations) and its reference
//! library (`library.rs`, built from `solutions/`). The grader's data stays (each task's
//! `src/grader/tasks/<task>/expected.snap` and `src/grader/renders/`): it holds the public
//! cases and the reference renders only, which is what lets the handout grade without
//! solutions.

use anyhow::{Context, bail};
use std::path::{Path, PathBuf};

/// Top-level entries copied into the handout (when present).
const TOP_LEVEL: &[&str] = &[
    "Cargo.toml",
    "Cargo.lock",
    "src",
    "exercises",
    "tests",
    "scenes",
    "benches",
    ".ci",
    ".gitignore",
    "rust-toolchain.toml",
    "LICENSE-MIT",
    "LICENSE-APACHE",
];

/// True for the files of a task's folder that only the instructor's side compiles:
/// `src/grader/tasks/<task>/variants.rs`, the implementations the instructor tests grade the
/// grader with (correct ones among them), and `library.rs`, the task's reference library
/// (`tools/reference-library/`, built from `solutions/`).
fn is_instructor_only(file: &Path) -> bool {
    let parts: Vec<_> = file.components().map(|c| c.as_os_str()).collect();
    matches!(parts.as_slice(), [src, grader, tasks, _, name]
        if *src == "src" && *grader == "grader" && *tasks == "tasks"
            && (*name == "variants.rs" || *name == "library.rs" || *name == "contract.rs"))
}

/// The members' manifests that name the reference, rewritten as the root's is: the
/// `pbrlab-commands` package links it in the instructor build.
const REWRITTEN_MEMBERS: &[&str] = &["src/commands/Cargo.toml"];

/// The files of the handout, relative to the repository root, and its Cargo.toml.
#[derive(Clone, Debug)]
pub struct Manifest {
    /// Files copied unchanged.
    pub files: Vec<PathBuf>,
    /// The handout's Cargo.toml.
    pub cargo_toml: String,
    /// The members' manifests the handout has rewritten (path from the root, text).
    pub members: Vec<(PathBuf, String)>,
}

/// True when a test or bench source needs the reference solutions to build, or is about
/// them: it names the reference, the mix, or the feature.
pub fn needs_solutions(source: &str) -> bool {
    source
        .lines()
        .map(str::trim_start)
        .filter(|l| !l.starts_with("//"))
        .any(|l| {
            l.contains("feature = \"solutions\"")
                || l.contains("pbrlab_solutions")
                || l.contains("Reference")
                || l.contains("Mixed")
        })
}

fn files_under(root: &Path, dir: &Path, out: &mut Vec<PathBuf>) -> anyhow::Result<()> {
    let full = root.join(dir);
    let mut entries: Vec<_> = std::fs::read_dir(&full)
        .with_context(|| format!("reading {}", full.display()))?
        .collect::<Result<_, _>>()?;
    entries.sort_by_key(|e| e.file_name());
    for entry in entries {
        let rel = dir.join(entry.file_name());
        let name = entry.file_name().to_string_lossy().into_owned();
        if name.ends_with(".snap.new") || name.ends_with(".pending-snap") || name.ends_with('~') {
            continue;
        }
        if entry.file_type()?.is_dir() {
            files_under(root, &rel, out)?;
        } else {
            out.push(rel);
        }
    }
    Ok(())
}

/// The test target the handout keeps: the student's tests, one per task, which grade
/// `exercises/` with the grader (`tests/exercises.rs`). Every other test is the
/// framework's own and stays in the instructor repository: a student cannot act on it.
pub const STUDENT_TESTS: &str = "tests/exercises.rs";

/// Applies the rules for `tests/` to the candidate files under it: only the student's
/// tests ([`STUDENT_TESTS`]) stay.
fn select_tests(candidates: Vec<PathBuf>) -> Vec<PathBuf> {
    candidates
        .into_iter()
        .filter(|file| file == Path::new(STUDENT_TESTS))
        .collect()
}

/// The handout's Cargo.toml: without the reference's crate (every line that names
/// `solutions`: the workspace member, the dependency and the default feature; the feature
/// itself stays, empty, so `cfg(feature = "solutions")` is still a known condition),
/// without workspace members whose folder is left out (the reference library's), without
/// any bench or test target whose file is left out, and without the dev-dependencies no
/// kept test names (`tests` is the text of the kept tests): the instructor's tests link the
/// student's crate, and the student's tests must not, or one exercise that does not compile
/// would stop them all. Its default member is the root package alone, so `cargo test` runs
/// the student's tests and not the framework's.
fn rewrite_cargo_toml(text: &str, kept: &[PathBuf], tests: &str) -> anyhow::Result<String> {
    let mut out = String::new();
    let mut section_header = String::new();
    let mut section = String::new();
    // Comment lines waiting for the dev-dependency they describe.
    let mut comments = String::new();
    // Inside the instructor's `default-members = [` list (replaced by the handout's).
    let mut in_default_members = false;
    let flush = |header: &str, body: &str, out: &mut String| {
        let is_target = header.starts_with("[[bench]]") || header.starts_with("[[test]]");
        if is_target {
            let value = |key: &str| {
                body.lines().find_map(|l| {
                    let (k, v) = l.split_once('=')?;
                    (k.trim() == key).then(|| v.trim().trim_matches('"').to_string())
                })
            };
            let dir = if header.starts_with("[[bench]]") {
                "benches"
            } else {
                "tests"
            };
            let path = value("path").or_else(|| value("name").map(|n| format!("{dir}/{n}.rs")));
            if let Some(path) = path
                && !kept.iter().any(|k| k == Path::new(&path))
            {
                return;
            }
        }
        out.push_str(header);
        out.push_str(body);
    };
    for line in text.split_inclusive('\n') {
        if in_default_members {
            in_default_members = !line.contains(']');
        } else if line.starts_with('[') {
            flush(&section_header, &section, &mut out);
            section_header = line.to_string();
            section.clear();
        } else if section_header.trim() == "[features]" && line.starts_with("solutions") {
            section.push_str(EMPTY_SOLUTIONS_FEATURE);
        } else if section_header.trim() == "[workspace]" && line.starts_with("default-members") {
            section.push_str(HANDOUT_DEFAULT_MEMBERS);
            in_default_members = !line.contains(']');
        } else if section_header.trim() == "[dev-dependencies]" && line.starts_with('#') {
            comments.push_str(line);
        } else if section_header.trim() == "[dev-dependencies]" && line.contains('=') {
            let name = line.split('=').next().unwrap_or_default().trim();
            if tests.contains(&format!("{}::", name.replace('-', "_"))) {
                section.push_str(&comments);
                section.push_str(line);
            }
            comments.clear();
        } else if !line.contains("solutions") && !names_missing_member(&section_header, line, kept)
        {
            section.push_str(line);
        }
    }
    flush(&section_header, &section, &mut out);
    if let Some(line) = out
        .split_inclusive('\n')
        .find(|l| l.contains("solutions") && *l != EMPTY_SOLUTIONS_FEATURE)
    {
        bail!("cannot leave the solutions out of Cargo.toml: `{line}` names them");
    }
    Ok(out)
}

/// True when `line` of the `[workspace]` section is a member (`    "dir",`) whose folder has
/// no file in the handout.
fn names_missing_member(section_header: &str, line: &str, kept: &[PathBuf]) -> bool {
    let Some(dir) = line
        .trim()
        .trim_end_matches(',')
        .strip_prefix('"')
        .and_then(|l| l.strip_suffix('"'))
    else {
        return false;
    };
    section_header.trim() == "[workspace]" && !kept.iter().any(|f| f.starts_with(dir))
}

/// The handout's default members: the root package, whose tests are the student's.
const HANDOUT_DEFAULT_MEMBERS: &str = "default-members = [\".\"]\n";

/// The handout's `solutions` feature: declared, and empty.
const EMPTY_SOLUTIONS_FEATURE: &str = "solutions = []\n";

/// Selects the handout's files from the repository at `root`.
pub fn select(root: &Path) -> anyhow::Result<Manifest> {
    let mut files = Vec::new();
    for entry in TOP_LEVEL {
        let path = root.join(entry);
        if path.is_dir() {
            files_under(root, Path::new(entry), &mut files)?;
        } else if path.is_file() && *entry != "Cargo.toml" {
            files.push(PathBuf::from(entry));
        }
    }
    files.retain(|f| !is_instructor_only(f));
    let (tests, mut rest): (Vec<_>, Vec<_>) =
        files.into_iter().partition(|f| f.starts_with("tests"));
    // benches/ is one package: kept whole when none of its sources needs the reference.
    let bench_needs_solutions = rest.iter().any(|f| {
        f.starts_with("benches")
            && f.extension().is_some_and(|e| e == "rs")
            && std::fs::read_to_string(root.join(f)).is_ok_and(|t| needs_solutions(&t))
    });
    if bench_needs_solutions {
        rest.retain(|f| !f.starts_with("benches"));
    }
    rest.extend(select_tests(tests));
    rest.retain(|f| !REWRITTEN_MEMBERS.iter().any(|m| f == Path::new(m)));
    rest.sort();
    let cargo_path = root.join("Cargo.toml");
    let cargo = std::fs::read_to_string(&cargo_path)
        .with_context(|| format!("reading {}", cargo_path.display()))?;
    let mut tests = String::new();
    for file in rest
        .iter()
        .filter(|f| f.starts_with("tests") && f.extension().is_some_and(|e| e == "rs"))
    {
        let path = root.join(file);
        tests += &std::fs::read_to_string(&path)
            .with_context(|| format!("reading {}", path.display()))?;
    }
    let cargo_toml = rewrite_cargo_toml(&cargo, &rest, &tests).context("Cargo.toml")?;
    let mut members = Vec::new();
    for member in REWRITTEN_MEMBERS {
        let path = root.join(member);
        let text = std::fs::read_to_string(&path)
            .with_context(|| format!("reading {}", path.display()))?;
        let rewritten = rewrite_cargo_toml(&text, &rest, &tests).context(*member)?;
        members.push((PathBuf::from(member), rewritten));
    }
    Ok(Manifest {
        files: rest,
        cargo_toml,
        members,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cargo_toml_loses_default_features_and_dropped_targets() {
        let text = "[workspace]\nmembers = [\n    \"src\",\n    \"solutions\",\n    \"tools/lib\",\n]\n\n[package]\nname = \"x\"\n\n[features]\ndefault = [\"solutions\"]\nsolutions = [\"dep:pbrlab-solutions\"]\n\n[dependencies]\npbrlab-solutions = { path = \"solutions\", optional = true }\n\n[[bench]]\nname = \"tasks\"\nharness = false\n\n[[bench]]\nname = \"render\"\nharness = false\n";
        let kept = [
            PathBuf::from("benches/render.rs"),
            PathBuf::from("src/grader/lib.rs"),
        ];
        let out = rewrite_cargo_toml(text, &kept, "").unwrap();
        assert!(
            !out.replace("solutions = []\n", "").contains("solutions"),
            "{out}"
        );
        assert!(out.contains("[features]\nsolutions = []\n"), "{out}");
        assert!(out.contains("members = [\n    \"src\",\n]"), "{out}");
        assert!(!out.contains("\"tasks\""), "{out}");
        assert!(out.contains("name = \"render\""), "{out}");
    }

    #[test]
    fn cargo_toml_keeps_the_dev_dependencies_the_student_tests_name_and_one_default_member() {
        let text = "[workspace]\nmembers = [\n    \"src\",\n]\ndefault-members = [\n    \".\",\n    \"src\",\n]\n\n[dev-dependencies]\n# The student's crate, linked in-process.\npbrlab-exercises = { path = \"exercises\" }\nserde_json = \"1\"\n# A harness.\nlibtest-mimic = \"0.8\"\n";
        let tests = "use libtest_mimic::Trial;\nfn f() { serde_json::from_str(\"1\"); }\n";
        let out = rewrite_cargo_toml(text, &[PathBuf::from("src/grader/lib.rs")], tests).unwrap();
        assert!(
            out.contains("default-members = [\".\"]\n\n[dev-dependencies]"),
            "{out}"
        );
        assert!(!out.contains("exercises"), "{out}");
        assert!(!out.contains("in-process"), "{out}");
        assert!(
            out.contains("serde_json = \"1\"\n# A harness.\nlibtest-mimic"),
            "{out}"
        );
    }

    #[test]
    fn the_instructor_only_files_of_a_task_are_recognised() {
        let only = |f: &str| is_instructor_only(Path::new(f));
        assert!(only("src/grader/tasks/smith_g1/variants.rs"));
        assert!(only("src/grader/tasks/smith_g1/library.rs"));
        assert!(!only("src/grader/tasks/smith_g1/cases.rs"));
        assert!(!only("src/grader/tasks/smith_g1/expected.snap"));
        assert!(!only("src/grader/tasks/variants.rs"));
        assert!(!only("tests/tasks/smith_g1/variants.rs"));
    }

    #[test]
    fn sources_that_use_the_reference_are_recognised() {
        assert!(needs_solutions(
            "use pbrlab::implementation::{Mixed, Reference};"
        ));
        assert!(needs_solutions("#![cfg(feature = \"solutions\")]"));
        assert!(!needs_solutions(
            "// compares with the Reference\nuse pbrlab::grade;"
        ));
    }
}
