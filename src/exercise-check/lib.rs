//! The compile-time trust check on exercise files: refuses every construct by which a task
//! file could reach outside the student's crate while it is compiled, before rustc sees the
//! file. `exercises/build.rs` runs it on every task file and turns each [`Finding`] into a
//! `cargo::error` naming `exercises/<task>.rs:line:column`; the grader then builds the task's
//! shipped stub in that file's place (`pbrlab::grade::student_build`).
//!
//! Two principles:
//! - **Fail closed.** A file the check cannot read as Rust tokens is refused at the line
//!   where reading stopped (at the unusual character that stopped it, where one did: a
//!   control or invisible character in code), never handed to rustc unchecked. (Its lexer
//!   skips every Unicode space, rustc only Rust's: a no-break space in code passes here and
//!   rustc refuses it, with its own message.) So are a leading `#!` line (rustc skips it unread) and text-direction
//!   characters anywhere (they make code read differently from how it compiles). What the
//!   lexer reads as a comment or a literal is free: a no-break space pasted into a comment
//!   compiles, as it does with rustc. A leading byte-order mark is skipped, as rustc skips
//!   it. Brackets nest at most [`MAX_DEPTH`] deep. Attributes come from an allow-list.
//! - **A second line.** What the build can read is bounded by its view of the file system
//!   (`pbrlab::grade::build_view`), not by this check: macro expansion can assemble any
//!   construct from accepted pieces. The check refuses only what a correct solution never
//!   needs, so that a student learns of a reach outside the crate at its line.
//! - **Refuse constructs, never names.** `let path = …`, `let env = …`, `fn include(…)` and
//!   `let asm = …` are ordinary code. What is refused is the attribute (`#[path]`), the macro
//!   call (`include!`, `env!`, `asm!`, …), the declaration (`mod x;`, `extern crate`), and the
//!   ways to assemble one of those from parts (a macro invoked through a metavariable, a
//!   `use … as` renaming of one of those macros, a metavariable in a `use` path or in an
//!   attribute's place). The only names refused wherever they occur are the framework's crate
//!   names (`pbrlab…`) and macro names no one uses as a variable (`include_str`,
//!   `include_bytes`, `option_env`, `global_asm`, `naked_asm`).
//!
//! What each construct could do: `#[path]` and `mod x;` compile another file (task files
//! are leaves); `include!`, `include_str!`, `include_bytes!` read a file at compile time;
//! `env!` and `option_env!` read the build environment; `extern crate` loads any crate in
//! the build's dependency folder, the reference's included; inline assembly is machine
//! code. `unsafe` is refused by the compiler itself (`#![forbid(unsafe_code)]` in the crate
//! root, which a file cannot lower).

use proc_macro2::{Delimiter, Spacing, TokenStream, TokenTree};

/// One refused construct: its 1-based line and column, and why it is refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Finding {
    /// The line, from 1.
    pub line: usize,
    /// The column in characters, from 1.
    pub column: usize,
    /// What the construct is and what it could do.
    pub why: String,
}

/// Macros that read files or the build environment at compile time, or emit machine code,
/// with what each does.
const MACROS: &[(&str, &str)] = &[
    ("include", "compiles a file from outside exercises/"),
    ("include_str", "reads a file at compile time"),
    ("include_bytes", "reads a file at compile time"),
    ("env", "reads the build environment"),
    ("option_env", "reads the build environment"),
    ("asm", "is inline assembly"),
    ("global_asm", "is inline assembly"),
    ("naked_asm", "is inline assembly"),
];

/// Macro names refused wherever they occur, because nobody names a variable so and a macro
/// could otherwise assemble a call to them from an identifier passed in.
const UNNATURAL: &[&str] = &[
    "include_str",
    "include_bytes",
    "option_env",
    "global_asm",
    "naked_asm",
];

/// The attributes an exercise file may use: lints, documentation, derives, conditional
/// compilation, tests, code-generation hints and tool attributes. Any other is refused.
const ATTRIBUTES: &[&str] = &[
    "allow",
    "warn",
    "deny",
    "forbid",
    "expect",
    "doc",
    "derive",
    "cfg",
    "cfg_attr",
    "test",
    "ignore",
    "should_panic",
    "inline",
    "cold",
    "track_caller",
    "must_use",
    "deprecated",
    "non_exhaustive",
    "repr",
    "rustfmt",
    "clippy",
    "diagnostic",
];

/// The deepest nesting of brackets an exercise file may have (no solution comes near it; a
/// deeper file would only test the stack of whatever reads it).
pub const MAX_DEPTH: usize = 256;

/// Every refused construct in the exercise file `text`, in file order. Empty means the file
/// may be compiled.
pub fn check(text: &str) -> Vec<Finding> {
    // rustc skips a byte-order mark at the start; so does this check.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let direction = direction_controls(text);
    if !direction.is_empty() {
        return direction;
    }
    if text.starts_with("#!") && !text.starts_with("#![") {
        return vec![Finding {
            line: 1,
            column: 1,
            why: "a first line starting with `#!` (the compiler skips it unread, so this check \
                  cannot vouch for it): remove the line"
                .into(),
        }];
    }
    let tokens = match text.parse::<TokenStream>() {
        Ok(tokens) => tokens,
        Err(e) => {
            // The lexer stopped: at an unusual character, where the file has one.
            let characters = unusual_characters(text);
            if !characters.is_empty() {
                return characters;
            }
            let at = e.span().start();
            return vec![Finding {
                line: at.line.max(1),
                column: at.column + 1,
                why: "the file cannot be read as Rust tokens from here on (an unclosed \
                      bracket, string or comment?), so it is refused unchecked: fix it and \
                      build again"
                    .into(),
            }];
        }
    };
    let mut found = Vec::new();
    walk(tokens, false, 0, &mut found);
    found.sort_by_key(|f| (f.line, f.column));
    found
}

/// Text-direction controls anywhere in `text` (CVE-2021-42574, "Trojan Source").
fn direction_controls(text: &str) -> Vec<Finding> {
    unusual_characters(text)
        .into_iter()
        .filter(|f| f.why.starts_with("the text-direction control"))
        .collect()
}

/// Characters outside printable text, spaces and tabs, each with what it is: where the
/// lexer fails, the likely reason.
fn unusual_characters(text: &str) -> Vec<Finding> {
    let mut found = Vec::new();
    for (index, line) in text.split('\n').enumerate() {
        for (column, ch) in line.chars().enumerate() {
            let why = match ch {
                ' ' | '\t' | '\r' => continue,
                '\u{feff}' => "a byte-order mark, which the compiler skips: save the file as \
                               UTF-8 without it"
                    .to_string(),
                '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}' => format!(
                    "the text-direction control U+{:04X}, which makes code read differently \
                     from how it compiles",
                    ch as u32
                ),
                '\u{200b}'..='\u{200f}' | '\u{2060}' => {
                    format!("the invisible character U+{:04X}: delete it", ch as u32)
                }
                c if c.is_control() => {
                    format!("the control character U+{:04X}: delete it", c as u32)
                }
                c if c.is_whitespace() => format!(
                    "the unusual whitespace U+{:04X}, which compilers and tools split \
                     differently: use spaces",
                    c as u32
                ),
                _ => continue,
            };
            found.push(Finding {
                line: index + 1,
                column: column + 1,
                why,
            });
        }
    }
    found
}

/// The identifier's text without a raw prefix: `r#include_str` names `include_str!` too.
fn unraw(text: &str) -> &str {
    text.strip_prefix("r#").unwrap_or(text)
}

fn ident(token: Option<&TokenTree>) -> Option<String> {
    match token {
        Some(TokenTree::Ident(i)) => Some(i.to_string()),
        _ => None,
    }
}

fn punct(token: Option<&TokenTree>, ch: char) -> bool {
    matches!(token, Some(TokenTree::Punct(p)) if p.as_char() == ch)
}

fn brace_group(token: Option<&TokenTree>) -> bool {
    matches!(token, Some(TokenTree::Group(g)) if g.delimiter() == Delimiter::Brace)
}

fn finding(token: &TokenTree, why: String) -> Finding {
    let start = token.span().start();
    Finding {
        line: start.line,
        column: start.column + 1,
        why,
    }
}

/// Walks one level of tokens, `depth` brackets deep; `in_use` is true inside a `use`
/// declaration.
fn walk(stream: TokenStream, in_use: bool, depth: usize, found: &mut Vec<Finding>) {
    let tokens: Vec<TokenTree> = stream.into_iter().collect();
    let mut in_use = in_use;
    for (i, token) in tokens.iter().enumerate() {
        let at = |offset: isize| i.checked_add_signed(offset).and_then(|j| tokens.get(j));
        match token {
            TokenTree::Group(_) if depth >= MAX_DEPTH => {
                found.push(finding(
                    token,
                    format!(
                        "brackets nested more than {MAX_DEPTH} deep: split the expression with \
                         `let` bindings or functions"
                    ),
                ));
                return;
            }
            TokenTree::Group(group) => {
                let attribute = group.delimiter() == Delimiter::Bracket
                    && (punct(at(-1), '#') || (punct(at(-1), '!') && punct(at(-2), '#')));
                if attribute {
                    attribute_paths(group.stream(), depth, found);
                }
                walk(group.stream(), in_use, depth + 1, found);
            }
            TokenTree::Ident(id) => {
                let text = id.to_string();
                let name = unraw(&text);
                if text == "use" {
                    in_use = true;
                } else if text == "mod" && !(ident(at(1)).is_some() && brace_group(at(2))) {
                    found.push(finding(
                        token,
                        "`mod` declaring a module in another file: task files are leaves, \
                         so put helpers in this file (an inline `mod name { … }` is fine)"
                            .into(),
                    ));
                } else if text == "extern"
                    && !(matches!(at(1), Some(TokenTree::Literal(_)))
                        || ident(at(1)).as_deref() == Some("fn"))
                {
                    found.push(finding(
                        token,
                        "`extern crate` loads crates this one does not depend on".into(),
                    ));
                } else if name.starts_with("pbrlab") {
                    found.push(finding(
                        token,
                        format!("`{name}`: the framework's crates are not named directly"),
                    ));
                } else if UNNATURAL.contains(&name) {
                    found.push(finding(token, macro_reason(name)));
                } else if in_use
                    && MACROS.iter().any(|(m, _)| *m == name)
                    && ident(at(1)).as_deref() == Some("as")
                {
                    found.push(finding(
                        token,
                        format!(
                            "renaming `{name}` with `use … as` renames the macro `{name}!` too, \
                             which {}: write the path out instead",
                            macro_what(name)
                        ),
                    ));
                }
            }
            TokenTree::Punct(p) => match p.as_char() {
                ';' => in_use = false,
                '$' if in_use => found.push(finding(
                    token,
                    "a macro variable in a `use` path (it could import a refused macro under \
                     another name)"
                        .into(),
                )),
                '!' if !(p.spacing() == Spacing::Joint && punct(at(1), '=')) => {
                    if let Some(why) = bang(&tokens[..i]) {
                        found.push(finding(token, why));
                    }
                }
                _ => {}
            },
            TokenTree::Literal(_) => {}
        }
    }
}

fn macro_what(name: &str) -> &'static str {
    MACROS
        .iter()
        .find(|(m, _)| *m == name)
        .map_or("is not for exercise files", |(_, w)| w)
}

fn macro_reason(name: &str) -> String {
    format!("`{name}!` {}", macro_what(name))
}

/// Why a `!` after the tokens `before` (on its level) is a refused macro call: a refused
/// macro, or a macro whose name comes from a macro variable (`$name!`, `$($path)::*!`),
/// which could be any of them.
fn bang(before: &[TokenTree]) -> Option<String> {
    let p1 = before.last();
    let p2 = before.len().checked_sub(2).map(|i| &before[i]);
    let through_variable = "a macro called through a macro variable (`$name!`), which could \
                            be a refused macro assembled from parts"
        .to_string();
    match p1? {
        TokenTree::Ident(id) => {
            let text = id.to_string();
            let name = unraw(&text);
            if punct(p2, '$') {
                Some(through_variable)
            } else if MACROS.iter().any(|(m, _)| *m == name) {
                Some(macro_reason(name))
            } else {
                None
            }
        }
        TokenTree::Group(_) if punct(p2, '$') => Some(through_variable),
        // `$( … ) sep op !`, the separator up to two tokens (`::`).
        TokenTree::Punct(p) if matches!(p.as_char(), '*' | '+' | '?') => {
            let repetition = before[..before.len() - 1]
                .iter()
                .rev()
                .take(4)
                .any(|t| punct(Some(t), '$'));
            repetition.then_some(through_variable)
        }
        _ => None,
    }
}

/// Checks the attribute paths in one attribute's brackets (`#[…]` or `#![…]`), and those a
/// `cfg_attr` applies.
fn attribute_paths(stream: TokenStream, depth: usize, found: &mut Vec<Finding>) {
    let tokens: Vec<TokenTree> = stream.into_iter().collect();
    let Some(first) = tokens.first() else {
        return;
    };
    let name = match first {
        TokenTree::Ident(id) => unraw(&id.to_string()).to_string(),
        _ => String::new(),
    };
    if !ATTRIBUTES.contains(&name.as_str()) {
        let why = match name.as_str() {
            "path" => "`#[path]` compiles a file from outside exercises/".to_string(),
            "" => "an attribute whose name is not written out (a macro variable?)".to_string(),
            other => format!(
                "the attribute `#[{other}]` is not for exercise files (allowed: lint levels, \
                 doc, derive, cfg, cfg_attr, test, inline, must_use and the like)"
            ),
        };
        found.push(finding(first, why));
        return;
    }
    if name == "cfg_attr"
        && let Some(TokenTree::Group(arguments)) = tokens.get(1)
    {
        // `cfg_attr(predicate, attribute, attribute, …)`: every attribute after the first
        // comma at the top level.
        let mut after_comma = false;
        let mut current = Vec::new();
        let mut parts = Vec::new();
        for token in arguments.stream() {
            if punct(Some(&token), ',') {
                if after_comma && !current.is_empty() {
                    parts.push(std::mem::take(&mut current));
                }
                current.clear();
                after_comma = true;
            } else if after_comma {
                current.push(token);
            }
        }
        if !current.is_empty() {
            parts.push(current);
        }
        // Nested deeper than `walk` goes, the attribute is refused there.
        if depth < MAX_DEPTH {
            for part in parts {
                attribute_paths(part.into_iter().collect(), depth + 1, found);
            }
        }
    }
}

#[cfg(test)]
mod tests;
