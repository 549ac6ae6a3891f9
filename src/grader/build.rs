//! Embeds the grader's expected data (tasks/<task>/expected.snap, written from the
//! reference by tests/instructor/expected.rs) and reference renders (renders/*.exr,
//! written by tests/instructor/renders.rs), both files of this package, into the binary,
//! so `pbrlab grade` needs no such files at run time and works in the student handout,
//! which has no solutions.

use std::fmt::Write;
use std::path::{Path, PathBuf};

fn main() {
    // One folder per task, each with its expected.snap when it has public cases (a
    // directory is watched whole).
    let tasks = Path::new("tasks");
    println!("cargo::rerun-if-changed={}", tasks.display());
    let mut expected: Vec<(String, PathBuf)> = Vec::new();
    for folder in std::fs::read_dir(tasks).into_iter().flatten().flatten() {
        let file = folder.path().join("expected.snap");
        if file.is_file() {
            let task = folder.file_name().to_string_lossy().into_owned();
            expected.push((task, file));
        }
    }
    embed(
        "tasks/<task>/expected.snap",
        expected,
        "expected_files.rs",
        "FILES",
        false,
    );
    let renders = Path::new("renders");
    println!("cargo::rerun-if-changed={}", renders.display());
    let renders = std::fs::read_dir(renders)
        .into_iter()
        .flatten()
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "exr"))
        .filter_map(|p| Some((p.file_stem()?.to_str()?.to_owned(), p)))
        .collect();
    embed(
        "renders/*.exr",
        renders,
        "render_files.rs",
        "RENDER_FILES",
        true,
    );
}

/// Writes `OUT_DIR/<out>`: a static `name` listing `(key, contents)` of every file of
/// `files` (`include_bytes!` when `binary`, else `include_str!`), by key; `what` names
/// the files in the static's doc.
fn embed(what: &str, mut files: Vec<(String, PathBuf)>, out: &str, name: &str, binary: bool) {
    files.sort();
    let (ty, include) = if binary {
        ("&[u8]", "include_bytes")
    } else {
        ("&str", "include_str")
    };
    let mut code = format!(
        "/// `(key, contents)` of every `{what}` file.\npub(crate) static {name}: &[(&str, {ty})] = &[\n"
    );
    for (stem, path) in files {
        let absolute = std::fs::canonicalize(&path).expect("readable data file");
        writeln!(
            code,
            "    ({stem:?}, {include}!({:?})),",
            absolute.display().to_string()
        )
        .unwrap();
    }
    code.push_str("];\n");
    let out_dir = std::env::var("OUT_DIR").expect("cargo sets OUT_DIR");
    std::fs::write(Path::new(&out_dir).join(out), code).expect("writable OUT_DIR");
}
