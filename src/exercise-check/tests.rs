//! The check on correct code (nothing refused, whatever the names) and on each refused
//! construct (refused at its line).

use super::{Finding, check};
use std::path::Path;

/// A task file with `items` after the usual first line.
fn file(items: &str) -> String {
    format!("use crate::prelude::*;\n{items}\n")
}

fn lines(findings: &[Finding]) -> Vec<usize> {
    findings.iter().map(|f| f.line).collect()
}

#[test]
fn correct_code_with_natural_names_is_accepted() {
    let text = file(
        r#"
/// Mentions `include_str!`, `#[path]`, `env!` and `mod x;` in prose: a doc comment is text.
pub fn path_trace(path: &[f32], env: f32, include: bool, asm: u32) -> f32 {
    // include_str!("/etc/passwd") in a comment is not code.
    let mut radiance = env;
    if include && !path.is_empty() && asm != 0 {
        radiance += path.iter().sum::<f32>();
    }
    let path_length = path.len();
    let env_map = [env; 2];
    let s = "include!(\"x\") and #[path] in a string";
    assert!(radiance >= 0.0, "{s} {path_length} {:?}", env_map);
    radiance
}

#[derive(Clone, Copy, Debug, PartialEq)]
struct Vertex { path: u32, env: f32, include: bool }

fn include(v: Vertex) -> bool { v.include }
fn asm(v: Vertex) -> u32 { v.path }

macro_rules! square { ($x:expr) => { $x * $x }; }

#[inline]
#[must_use]
#[allow(clippy::float_cmp)]
#[cfg_attr(test, allow(dead_code))]
fn env_weight(env: f32) -> f32 { square!(env) }

use std::path::Path;
use std::{f32::consts::PI, env};

mod helpers {
    pub fn path(x: f32) -> f32 { x }
}

#[cfg(test)]
mod tests {
    #[test]
    fn t() { assert_eq!(super::helpers::path(1.0), 1.0); }
}
"#,
    );
    assert_eq!(check(&text), vec![], "{text}");
    assert_eq!(check("#![allow(unused)]\nfn f() {}\n"), vec![]);
}

#[test]
fn every_shipped_exercise_and_reference_file_is_accepted() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    // The student handout has no solutions/.
    let folders: Vec<_> = ["exercises", "solutions"]
        .into_iter()
        .filter(|f| root.join(f).is_dir())
        .collect();
    let mut seen = 0;
    for folder in &folders {
        for entry in std::fs::read_dir(root.join(folder)).unwrap().flatten() {
            let path = entry.path();
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            if path.extension().is_some_and(|e| e == "rs") && name != "lib.rs" && name != "build.rs"
            {
                let text = std::fs::read_to_string(&path).unwrap();
                assert_eq!(check(&text), vec![], "{}", path.display());
                seen += 1;
            }
        }
    }
    assert!(seen >= 15 * folders.len(), "only {seen} files found");
}

/// Each refused construct, and the line its finding must name.
fn refused() -> Vec<(&'static str, String, usize)> {
    vec![
        (
            "include_str!",
            file("const X: &str = include_str!(\"../x\");"),
            2,
        ),
        ("include!", file("\ninclude!(\"../solutions/mis.rs\");"), 3),
        (
            "include_bytes!",
            file("const X: &[u8] = include_bytes!(\"x\");"),
            2,
        ),
        ("env!", file("const X: &str = env!(\"PATH\");"), 2),
        (
            "option_env!",
            file("const X: Option<&str> = option_env!(\"PATH\");"),
            2,
        ),
        (
            "a path to env!",
            file("const X: &str = ::core::env!(\"PATH\");"),
            2,
        ),
        (
            "a raw identifier",
            file("const X: &str = r#include_str!(\"x\");"),
            2,
        ),
        ("asm!", file("fn f() { core::arch::asm!(\"nop\"); }"), 2),
        ("global_asm!", file("core::arch::global_asm!(\"\");"), 2),
        (
            "the macro's name passed to another macro",
            file("macro_rules! m { ($n:ident) => { use std::$n as y; } }\nm!(include_str);"),
            2,
        ),
        (
            "a renaming use",
            file("use std::env as e;\nconst X: &str = e!(\"PATH\");"),
            2,
        ),
        (
            "a renaming use in braces",
            file("use core::{panic, include as inc};"),
            2,
        ),
        (
            "a macro variable in a use path",
            file("macro_rules! m { ($n:ident) => { use core::$n as y; } }\nm!(env);"),
            2,
        ),
        (
            "a macro called through a macro variable",
            file("macro_rules! call { ($m:ident) => { $m!(\"x\") } }\nconst X: &str = call!(env);"),
            2,
        ),
        (
            "a macro called through a repetition",
            file("macro_rules! call { ($($p:ident)::*) => { $($p)::*!(\"x\") } }"),
            2,
        ),
        (
            "#[path] on a module",
            file("\n#[path = \"../solutions/mis.rs\"]\nmod stolen {}"),
            3,
        ),
        ("a module in another file", file("mod stolen;"), 2),
        (
            "a public module in another file",
            file("\n\npub mod stolen;"),
            4,
        ),
        (
            "the mod keyword passed to a macro",
            file("macro_rules! m { ($k:tt) => { $k stolen; } }\nm!(mod);"),
            3,
        ),
        (
            "#[path] in cfg_attr",
            file("#[cfg_attr(all(), allow(unused), path = \"x.rs\")]\nmod stolen {}"),
            2,
        ),
        (
            "an attribute from a macro variable",
            file("macro_rules! m { ($a:ident) => { #[$a = \"x.rs\"] mod s {} } }"),
            2,
        ),
        (
            "an attribute outside the allow-list",
            file("#[debugger_visualizer(gdb_script_file = \"../x\")]\nfn f() {}"),
            2,
        ),
        (
            "extern crate",
            file("extern crate pbrlab_solutions as r;"),
            2,
        ),
        (
            "extern crate by another name",
            file("extern crate core as c;"),
            2,
        ),
        (
            "extern passed to a macro",
            file("macro_rules! m { ($k:tt) => { $k crate std as s; } }\nm!(extern);"),
            3,
        ),
        (
            "a framework crate",
            file("\nfn f() { pbrlab::grade::x(); }"),
            3,
        ),
        (
            "a shebang line that hides code from the lexer",
            "#!r\"\nconst X: &str = include_str!(\"x\");\n\"\n".to_string(),
            1,
        ),
        (
            "a refused macro after a byte-order mark",
            "\u{feff}const X: &str = include_str!(\"x\");\n".to_string(),
            1,
        ),
        ("a zero-width space in code", file("fn f\u{200b}() {}"), 2),
        ("a control character in code", file("fn f() {}\u{7}"), 2),
        (
            "a text-direction override in a comment",
            file("// \u{202e} hidden"),
            2,
        ),
        (
            "a text-direction isolate in a string",
            file("const S: &str = \"\u{2066}x\";"),
            2,
        ),
        (
            "brackets nested deeper than the check reads",
            file(&format!(
                "const X: u8 = {}0{};",
                "(".repeat(30_000),
                ")".repeat(30_000)
            )),
            2,
        ),
        (
            "cfg_attr nested deeper than the check reads",
            file(&format!(
                "#[{}path = \"x\"{}]\nmod s {{}}",
                "cfg_attr(all(), ".repeat(5_000),
                ")".repeat(5_000)
            )),
            2,
        ),
        (
            "an unclosed string",
            file("fn f() {}\nconst S: &str = \"open;\n"),
            3,
        ),
        ("an unclosed bracket", file("fn f() {\n"), 2),
    ]
}

/// What rustc compiles and a correct solution may hold: unusual characters in comments and
/// literals (pasted from a PDF or another language), a leading byte-order mark, and the
/// whitespace rustc and the check's lexer both skip.
#[test]
fn comments_literals_and_a_byte_order_mark_are_free() {
    for (what, text) in [
        (
            "a no-break space in a comment",
            file("// cos\u{a0}θ, see §1.2\nfn f() {}"),
        ),
        (
            "a no-break space in a block comment",
            file("/* a\u{a0}b */ fn f() {}"),
        ),
        (
            "a zero-width space in a doc comment",
            file("/// x\u{200b}y\nfn f() {}"),
        ),
        (
            "a no-break space in a string",
            file("const S: &str = \"a\u{a0}b\";"),
        ),
        ("a byte-order mark", "\u{feff}fn f() {}\n".to_string()),
        (
            "a form feed between items",
            file("fn f() {}\u{c}\nfn g() {}"),
        ),
        (
            "brackets nested as deep as the check reads",
            file(&format!(
                "const X: u8 = {}0{};",
                "(".repeat(200),
                ")".repeat(200)
            )),
        ),
    ] {
        assert_eq!(check(&text), vec![], "{what}:\n{text}");
    }
}

#[test]
fn each_refused_construct_is_refused_at_its_line() {
    for (what, text, line) in refused() {
        let found = check(&text);
        assert!(
            lines(&found).contains(&line),
            "{what}: expected a finding at line {line}, got {found:?}\n{text}"
        );
        assert!(found.iter().all(|f| f.column >= 1 && !f.why.is_empty()));
    }
}

#[test]
fn a_finding_says_what_the_construct_does() {
    let found = check(&file("const X: &str = include_str!(\"x\");"));
    assert_eq!(found[0].column, 17);
    assert!(found[0].why.contains("reads a file"), "{found:?}");
    let found = check(&file("#[path = \"x\"]\nmod s {}"));
    assert!(found[0].why.contains("#[path]"), "{found:?}");
    let found = check(&file("mod s;"));
    assert!(found[0].why.contains("leaves"), "{found:?}");
}
