//! `src/ARCHITECTURE.md` maps every Rust file in one line: a file it does not name, or a
//! line for a file that is gone, fails here, so the map and the tree move together.

use std::path::{Path, PathBuf};

/// Every `.rs` file under `dir`, relative to `root`, leaving out build output and dot
/// folders.
fn rust_files(root: &Path, dir: &Path, out: &mut Vec<String>) {
    for entry in std::fs::read_dir(dir).unwrap().map(Result::unwrap) {
        let path: PathBuf = entry.path();
        let name = entry.file_name().to_string_lossy().into_owned();
        if name.starts_with('.') || name == "target" {
            continue;
        }
        if path.is_dir() {
            rust_files(root, &path, out);
        } else if name.ends_with(".rs") {
            let relative = path.strip_prefix(root).unwrap();
            out.push(relative.to_string_lossy().replace('\\', "/"));
        }
    }
}

/// True when `file` is the map's `entry`, where a `*` stands for any part of one path
/// segment (`src/tasks/*/cases.rs`, `exercises/*.rs`).
fn matches(entry: &str, file: &str) -> bool {
    let segment = |e: &str, f: &str| match e.split_once('*') {
        Some((head, tail)) => {
            f.len() >= head.len() + tail.len() && f.starts_with(head) && f.ends_with(tail)
        }
        None => e == f,
    };
    let (e, f): (Vec<&str>, Vec<&str>) = (entry.split('/').collect(), file.split('/').collect());
    e.len() == f.len() && e.iter().zip(&f).all(|(e, f)| segment(e, f))
}

#[test]
fn the_file_map_names_every_rust_file_and_no_file_that_is_gone() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let doc = std::fs::read_to_string(root.join("src/ARCHITECTURE.md")).unwrap();
    let map = &doc[doc.find("## File map").expect("a File map section")..];
    // Each entry is a list item that starts with a path in backticks.
    let entries: Vec<&str> = map
        .lines()
        .filter_map(|l| l.strip_prefix("- `")?.split('`').next())
        .filter(|p| p.ends_with(".rs"))
        .collect();
    let mut files = Vec::new();
    for top in ["src", "exercises", "solutions", "tests", "benches", "tools"] {
        rust_files(root, &root.join(top), &mut files);
    }
    let unmapped: Vec<&String> = files
        .iter()
        .filter(|f| !entries.iter().any(|e| matches(e, f)))
        .collect();
    assert!(
        unmapped.is_empty(),
        "src/ARCHITECTURE.md's file map does not name {unmapped:?}: add a line each"
    );
    let gone: Vec<&&str> = entries
        .iter()
        .filter(|e| !files.iter().any(|f| matches(e, f)))
        .collect();
    assert!(
        gone.is_empty(),
        "src/ARCHITECTURE.md's file map names files that are gone: {gone:?}"
    );
}
