//! The compile-time trust check on exercise files: refuses every construct by which a task
//! file could reach outside the student's crate while it is compiled, before rustc sees the
//! file. `exercises/build.rs` runs it on every task file and turns each [`Finding`] into a
//! `cargo::error` naming `exercises/<task>.rs:line:column`; the grader then builds the task's
//! shipped stub in that file's place (`pbrlab::grade::student_build`).
//!
//! Two principles:
//! - **Fail closed.** A file the check cannot read as Rust tokens is refused at the line
//!   where reading stopped, never handed to rustc unchecked. So is every byte sequence the
//!   check and rustc could read differently: a byte-order mark, a leading `#!` line (rustc
//!   skips it), whitespace other than space, tab and newline, control and text-direction
//!   characters. Attributes come from an allow-list.
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

/// Every refused construct in the exercise file `text`, in file order. Empty means the file
/// may be compiled.
pub fn check(text: &str) -> Vec<Finding> {
    let characters = unusual_characters(text);
    if !characters.is_empty() {
        // The lexer below might split such a file differently from rustc: stop here.
        return characters;
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
    walk(tokens, false, &mut found);
    found.sort_by_key(|f| (f.line, f.column));
    found
}

/// Characters rustc and the token check could read differently, or that make code read
/// differently from how it compiles.
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

/// Walks one level of tokens; `in_use` is true inside a `use` declaration.
fn walk(stream: TokenStream, in_use: bool, found: &mut Vec<Finding>) {
    let tokens: Vec<TokenTree> = stream.into_iter().collect();
    let mut in_use = in_use;
    for (i, token) in tokens.iter().enumerate() {
        let at = |offset: isize| i.checked_add_signed(offset).and_then(|j| tokens.get(j));
        match token {
            TokenTree::Group(group) => {
                let attribute = group.delimiter() == Delimiter::Bracket
                    && (punct(at(-1), '#') || (punct(at(-1), '!') && punct(at(-2), '#')));
                if attribute {
                    attribute_paths(group.stream(), found);
                }
                walk(group.stream(), in_use, found);
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
fn attribute_paths(stream: TokenStream, found: &mut Vec<Finding>) {
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
        for part in parts {
            attribute_paths(part.into_iter().collect(), found);
        }
    }
}

#[cfg(test)]
mod tests;
