//! Embeds the grader's expected data (tests/snapshots/expected/*.snap, written from the
//! reference by tests/instructor/expected.rs) and reference renders
//! (tests/snapshots/renders/*.exr, written by tests/instructor/renders.rs) into the binary,
//! so `pbrlab grade` needs no such files at run time and works in the student handout,
//! which has no solutions.
//!
//! Also sets `PBRLAB_ABI_BUILD`: what this copy of the framework was compiled from and with
//! (compiler, target, features, flags, a hash of its sources and of the locked dependency
//! versions), which the handout's compiled reference must share to be loaded
//! (`compiled_reference`).

use std::fmt::Write;
use std::hash::{DefaultHasher, Hash, Hasher};
use std::path::{Path, PathBuf};

fn main() {
    println!("cargo::rustc-env=PBRLAB_ABI_BUILD={}", abi_build());
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

/// One line saying what this compilation of the framework is made of: two builds with the
/// same line lay out the framework's types the same way.
fn abi_build() -> String {
    let env = |key: &str| std::env::var(key).unwrap_or_default();
    let rustc = std::process::Command::new(env("RUSTC"))
        .arg("-V")
        .output()
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
        .unwrap_or_default();
    // `default` is empty, and on only where the framework itself is a package being built.
    let mut features: Vec<String> = std::env::vars()
        .filter_map(|(k, _)| k.strip_prefix("CARGO_FEATURE_").map(str::to_lowercase))
        .filter(|f| f != "default")
        .collect();
    features.sort();
    let flags = env("CARGO_ENCODED_RUSTFLAGS").replace('\x1f', " ");
    // The framework's sources: every `.rs` file of this package.
    let mut sources = Vec::new();
    rust_files(Path::new("."), &mut sources);
    sources.sort();
    let mut hasher = DefaultHasher::new();
    for file in &sources {
        file.hash(&mut hasher);
        std::fs::read(file).unwrap_or_default().hash(&mut hasher);
    }
    println!("cargo::rerun-if-changed=.");
    let sources = hasher.finish();
    // The locked dependency versions, less the workspace's own packages (the handout has
    // fewer of those).
    let lock = std::fs::read_to_string("../Cargo.lock").unwrap_or_default();
    println!("cargo::rerun-if-changed=../Cargo.lock");
    let mut hasher = DefaultHasher::new();
    for package in lock.split("\n[[package]]\n").skip(1) {
        if !package.starts_with("name = \"pbrlab") {
            package.trim().hash(&mut hasher);
        }
    }
    format!(
        "{rustc}; target {}; features [{}]; rustflags [{flags}]; sources {sources:016x}; dependencies {:016x}",
        env("TARGET"),
        features.join(" "),
        hasher.finish()
    )
}

/// Every `.rs` file under `dir`, depth first.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).into_iter().flatten().flatten() {
        let path = entry.path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}
