//! Embeds the grader's expected data (tests/snapshots/expected/*.snap, written from the
//! reference by tests/instructor_expected.rs) into the binary, so `pbrlab grade` needs no
//! files at run time and works in the student handout, which has no solutions.

use std::fmt::Write;
use std::path::Path;

fn main() {
    let dir = Path::new("tests/snapshots/expected");
    println!("cargo::rerun-if-changed={}", dir.display());
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .into_iter()
        .flatten()
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "snap"))
        .collect();
    files.sort();
    let mut code = String::from(
        "/// `(task id, snapshot text)` of every stored expected-data file.\npub(crate) static FILES: &[(&str, &str)] = &[\n",
    );
    for path in files {
        let stem = path
            .file_stem()
            .and_then(|s| s.to_str())
            .unwrap_or_default();
        let absolute = std::fs::canonicalize(&path).expect("readable snapshot path");
        writeln!(
            code,
            "    ({stem:?}, include_str!({:?})),",
            absolute.display().to_string()
        )
        .unwrap();
    }
    code.push_str("];\n");
    let out = std::env::var("OUT_DIR").expect("cargo sets OUT_DIR");
    std::fs::write(Path::new(&out).join("expected_files.rs"), code).expect("writable OUT_DIR");
}
