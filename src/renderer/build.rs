//! Sets `PBRLAB_ABI_BUILD`: what this copy of the task API and renderer was compiled from
//! and with (compiler, target, features, flags, a hash of its sources and of the locked
//! dependency versions), which the handout's compiled reference must share to be loaded
//! (`compiled_reference`).

use std::hash::{DefaultHasher, Hash, Hasher};
use std::path::{Path, PathBuf};

fn main() {
    println!("cargo::rustc-env=PBRLAB_ABI_BUILD={}", abi_build());
}

/// One line saying what this compilation of the task API is made of: two builds with the
/// same line lay out its types the same way.
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
    // The crate's sources: every `.rs` file of this package.
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
    // The locked versions of what this crate links: its dependencies, transitively, less the
    // workspace's own packages. Not the whole lock file: the handout's has fewer packages
    // (no reference, no benchmarks) and must give the same line.
    let lock = std::fs::read_to_string("../../Cargo.lock").unwrap_or_default();
    println!("cargo::rerun-if-changed=../../Cargo.lock");
    let mut hasher = DefaultHasher::new();
    for package in locked_closure(&lock, env!("CARGO_PKG_NAME")) {
        if !package.starts_with("name = \"pbrlab") {
            // Name, version, source and checksum: not the dependency list, whose entries
            // carry a version only while the lock holds two of a name.
            package
                .lines()
                .filter(|l| !l.starts_with("dependencies") && !l.starts_with(' '))
                .filter(|l| !l.starts_with(']'))
                .for_each(|l| l.hash(&mut hasher));
        }
    }
    format!(
        "{rustc}; target {}; features [{}]; rustflags [{flags}]; sources {sources:016x}; dependencies {:016x}",
        env("TARGET"),
        features.join(" "),
        hasher.finish()
    )
}

/// The `[[package]]` entries of the lock file `lock` that `root` depends on, itself
/// included, in lock-file order. A dependency is written `name` when the lock has one
/// version of it, else `name version` (and a source after that).
fn locked_closure<'a>(lock: &'a str, root: &str) -> Vec<&'a str> {
    let field = |package: &'a str, key: &str| {
        package.lines().find_map(|l| {
            l.strip_prefix(key)
                .and_then(|v| v.strip_prefix(" = \""))
                .and_then(|v| v.strip_suffix('"'))
        })
    };
    let packages: Vec<&str> = lock.split("\n[[package]]\n").skip(1).collect();
    let dependencies = |package: &'a str| -> Vec<(&'a str, Option<&'a str>)> {
        let Some(start) = package.find("dependencies = [") else {
            return Vec::new();
        };
        package[start..]
            .lines()
            .skip(1)
            .take_while(|l| !l.starts_with(']'))
            .filter_map(|l| {
                let entry = l.trim().trim_end_matches(',').trim_matches('"');
                let mut words = entry.split(' ');
                Some((words.next()?, words.next()))
            })
            .collect()
    };
    let mut wanted = vec![(root, None)];
    let mut taken = vec![false; packages.len()];
    while let Some((name, version)) = wanted.pop() {
        for (i, package) in packages.iter().enumerate() {
            let matches = field(package, "name") == Some(name)
                && version.is_none_or(|v| field(package, "version") == Some(v));
            if matches && !taken[i] {
                taken[i] = true;
                wanted.extend(dependencies(package));
            }
        }
    }
    packages
        .into_iter()
        .zip(taken)
        .filter_map(|(p, t)| t.then_some(p))
        .collect()
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
