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
/// segment (`src/grader/tasks/*/cases.rs`, `exercises/*.rs`).
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

/// The Rust source of `file` without its comments and its unit tests (a test may reach
/// anywhere), so that only what the code imports counts.
fn code(file: &Path) -> String {
    let text = std::fs::read_to_string(file).unwrap();
    let text = match text.find("#[cfg(test)]\nmod tests") {
        Some(i) => &text[..i],
        None => &text[..],
    };
    text.lines()
        .map(|line| match line.find("//") {
            // A `//` inside a string literal is rare in this code and only adds imports.
            Some(i) => &line[..i],
            None => line,
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// Every path `code` names from `prefix` (`super::`, `crate::grade::`), with `use` groups
/// expanded: `use super::{a, b::{c, d}}` names `super::a`, `super::b::c`, `super::b::d`.
fn paths(code: &str) -> Vec<String> {
    fn expand(prefix: &str, tree: &str, out: &mut Vec<String>) {
        let tree = tree.trim();
        match tree.find('{') {
            Some(open) if tree.ends_with('}') => {
                let head = format!("{prefix}{}", &tree[..open]);
                let inner = &tree[open + 1..tree.len() - 1];
                let (mut depth, mut start) = (0, 0);
                for (i, c) in inner.char_indices() {
                    match c {
                        '{' => depth += 1,
                        '}' => depth -= 1,
                        ',' if depth == 0 => {
                            expand(&head, &inner[start..i], out);
                            start = i + 1;
                        }
                        _ => {}
                    }
                }
                expand(&head, &inner[start..], out);
            }
            _ if !tree.is_empty() => out.push(format!("{prefix}{tree}")),
            _ => {}
        }
    }
    let mut out = Vec::new();
    for statement in code.split(';') {
        if let Some(i) = statement.find("use ") {
            let tree: String = statement[i + 4..].split_whitespace().collect();
            expand("", &tree, &mut out);
        }
    }
    // Qualified paths in the code itself.
    let bytes = code.as_bytes();
    for start in ["super::", "crate::"] {
        let mut from = 0;
        while let Some(i) = code[from..].find(start) {
            let at = from + i;
            let end = code[at..]
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                .map_or(code.len(), |e| at + e);
            if at == 0 || !(bytes[at - 1].is_ascii_alphanumeric() || bytes[at - 1] == b':') {
                out.push(code[at..end].to_string());
            }
            from = end.max(at + 1);
        }
    }
    out
}

/// The module files of the package folder `root` (`src/grader/grade`), by module path relative to
/// it: `values` for `values.rs`, `report` for `report/mod.rs`.
fn modules(root: &Path) -> Vec<(String, PathBuf)> {
    let mut files = Vec::new();
    rust_files(root, root, &mut files);
    files
        .into_iter()
        .map(|f| {
            let module = f
                .trim_end_matches(".rs")
                .trim_end_matches("/mod")
                .to_string();
            let module = if module == "mod" {
                String::new()
            } else {
                module
            };
            (module, root.join(f))
        })
        .collect()
}

/// The modules of `root` (a folder whose `mod.rs` is the module `crate::<name>`) that each
/// module of it imports.
fn imports(root: &Path, name: &str) -> Vec<(String, Vec<String>)> {
    let modules = modules(root);
    let known = |path: &[&str]| -> Option<String> {
        (1..=path.len())
            .rev()
            .map(|k| path[..k].join("/"))
            .find(|m| modules.iter().any(|(module, _)| module == m))
    };
    modules
        .iter()
        .map(|(module, file)| {
            let is_mod = file.ends_with("mod.rs");
            let here: Vec<&str> = module.split('/').filter(|s| !s.is_empty()).collect();
            let parent: Vec<&str> = if is_mod {
                here.clone()
            } else {
                here[..here.len().saturating_sub(1)].to_vec()
            };
            let mut deps: Vec<String> = Vec::new();
            for path in paths(&code(file)) {
                let segments: Vec<&str> = path.split("::").collect();
                let target: Option<Vec<&str>> = if segments.first() == Some(&"crate") {
                    (segments.get(1) == Some(&name)).then(|| segments[2..].to_vec())
                } else if segments.first() == Some(&"super") {
                    let ups = segments.iter().take_while(|s| **s == "super").count();
                    (ups <= parent.len() + 1).then(|| {
                        let base = &parent[..(parent.len() + 1).saturating_sub(ups)];
                        base.iter().chain(&segments[ups..]).copied().collect()
                    })
                } else {
                    None
                };
                let dep = target.and_then(|t| known(&t)).unwrap_or_default();
                if !dep.is_empty() && dep != *module && !deps.contains(&dep) {
                    deps.push(dep);
                }
            }
            (module.clone(), deps)
        })
        .collect()
}

/// The import circles among `graph`'s modules (Tarjan's strongly connected components of
/// more than one module).
fn circles(graph: &[(String, Vec<String>)]) -> Vec<Vec<String>> {
    struct Search<'g> {
        graph: &'g [(String, Vec<String>)],
        index: Vec<Option<usize>>,
        low: Vec<usize>,
        stack: Vec<usize>,
        on_stack: Vec<bool>,
        next: usize,
        found: Vec<Vec<String>>,
    }
    impl Search<'_> {
        fn visit(&mut self, v: usize) {
            self.index[v] = Some(self.next);
            self.low[v] = self.next;
            self.next += 1;
            self.stack.push(v);
            self.on_stack[v] = true;
            for dep in &self.graph[v].1 {
                let Some(w) = self.graph.iter().position(|(m, _)| m == dep) else {
                    continue;
                };
                match self.index[w] {
                    None => {
                        self.visit(w);
                        self.low[v] = self.low[v].min(self.low[w]);
                    }
                    Some(i) if self.on_stack[w] => self.low[v] = self.low[v].min(i),
                    Some(_) => {}
                }
            }
            if Some(self.low[v]) == self.index[v] {
                let mut circle = Vec::new();
                while let Some(w) = self.stack.pop() {
                    self.on_stack[w] = false;
                    circle.push(self.graph[w].0.clone());
                    if w == v {
                        break;
                    }
                }
                if circle.len() > 1 {
                    circle.sort();
                    self.found.push(circle);
                }
            }
        }
    }
    let n = graph.len();
    let mut search = Search {
        graph,
        index: vec![None; n],
        low: vec![0; n],
        stack: Vec::new(),
        on_stack: vec![false; n],
        next: 0,
        found: Vec::new(),
    };
    for v in 0..n {
        if search.index[v].is_none() {
            search.visit(v);
        }
    }
    search.found
}

#[test]
fn the_grader_the_class_runs_and_the_commands_import_in_one_direction() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/grader");
    for name in ["grade", "autograder", "cli"] {
        let graph = imports(&root.join(name), name);
        assert!(graph.len() > 5, "src/grader/{name}: {graph:?}");
        let found = circles(&graph);
        assert!(
            found.is_empty(),
            "import circles in src/grader/{name}/: {found:?}"
        );
    }
}

/// The side of the trust boundary the file map gives each file of `src/grader/grade/`, by module
/// path relative to it (`values`, `report/text`, `` for `mod.rs`).
fn sides() -> Vec<(String, String)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let doc = std::fs::read_to_string(root.join("src/ARCHITECTURE.md")).unwrap();
    doc.lines()
        .filter_map(|l| {
            let rest = l.strip_prefix("- `src/grader/grade/")?;
            let (file, rest) = rest.split_once("` — [")?;
            let (side, _) = rest.split_once(']')?;
            let module = file.trim_end_matches(".rs").trim_end_matches("mod");
            Some((module.trim_end_matches('/').to_string(), side.to_string()))
        })
        .collect()
}

/// Nothing that runs in the worker, and nothing both sides use, imports the grader's own
/// side (the expected data, the references, the runner, the isolation layer, the judges):
/// what a worker can reach is what the imports allow, and the file map says which side
/// each file is on.
#[test]
fn no_worker_side_or_shared_file_of_the_grader_imports_a_parent_side_one() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/grader/grade");
    let sides = sides();
    let side = |module: &str| {
        sides
            .iter()
            .find(|(m, _)| m == module)
            .map(|(_, s)| s.as_str())
            .unwrap_or_else(|| {
                panic!("src/ARCHITECTURE.md gives src/grader/grade/{module} no side")
            })
    };
    assert!(
        sides
            .iter()
            .all(|(_, s)| ["worker", "parent", "both"].contains(&s.as_str()))
    );
    assert!(side("worker") == "worker" && side("expected") == "parent");
    let mut crossings = Vec::new();
    for (module, deps) in imports(&root, "grade") {
        if side(&module) == "parent" {
            continue;
        }
        for dep in deps.iter().filter(|d| side(d) == "parent") {
            crossings.push(format!(
                "{module} ({}) imports {dep} (parent)",
                side(&module)
            ));
        }
    }
    assert!(
        crossings.is_empty(),
        "imports across the trust boundary: {crossings:?}"
    );
}
