//! Embeds the grader's expected data (tests/snapshots/expected/*.snap, written from the
//! reference by tests/instructor/expected.rs) and reference renders
//! (tests/snapshots/renders/*.exr, written by tests/instructor/renders.rs) into the binary,
//! so `pbrlab grade` needs no such files at run time and works in the student handout,
//! which has no solutions.

use std::fmt::Write;
use std::path::Path;

fn main() {
    embed(
        "../tests/snapshots/expected",
        "snap",
        "expected_files.rs",
        "FILES",
        false,
    );
    embed(
        "../tests/snapshots/renders",
        "exr",
        "render_files.rs",
        "RENDER_FILES",
        true,
    );
}

/// Writes `OUT_DIR/<out>`: a static `name` listing `(file stem, contents)` of every `*.ext`
/// file in `dir` (`include_bytes!` when `binary`, else `include_str!`).
fn embed(dir: &str, ext: &str, out: &str, name: &str, binary: bool) {
    let dir = Path::new(dir);
    println!("cargo::rerun-if-changed={}", dir.display());
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .into_iter()
        .flatten()
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == ext))
        .collect();
    files.sort();
    let (ty, include) = if binary {
        ("&[u8]", "include_bytes")
    } else {
        ("&str", "include_str")
    };
    let mut code = format!(
        "/// `(file stem, contents)` of every `{}/*.{ext}` file.\npub(crate) static {name}: &[(&str, {ty})] = &[\n",
        dir.display()
    );
    for path in files {
        let stem = path
            .file_stem()
            .and_then(|s| s.to_str())
            .unwrap_or_default();
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
