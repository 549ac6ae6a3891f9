//! Planted copies: the rewrites a student makes to hide a copy, applied to a source file.
//!
//! Every rewrite works on the fallback lexer's lexemes (comments included), keeps the
//! program's meaning where it can, and produces text that still lexes as Rust.

use pbrlab::similarity::lexer::{Lexeme, LexemeKind, lex};
use std::collections::{BTreeMap, BTreeSet};

/// One way of disguising a copy.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(super) enum Disguise {
    /// Consistent renaming of every local name (variables, parameters, helper functions,
    /// constants, closure parameters), shorthand struct fields written out.
    Rename,
    /// Another layout: Allman braces with tabs and spaced parentheses, or a compact style
    /// with short blocks on one line, several statements per line and no spaces around
    /// arithmetic.
    Reformat,
    /// Independent `let` statements swapped, top-level items in reverse order, `if/else`
    /// branches swapped under a negated condition.
    Reorder,
    /// Every comment removed and new ones added.
    Recomment,
    /// All of the above.
    All,
    /// All of the above, and a closing brace deleted: the copy no longer lexes, so the
    /// fallback lexer reads it.
    AllBroken,
}

impl Disguise {
    /// Every disguise.
    pub(super) const ALL: [Disguise; 6] = [
        Disguise::Rename,
        Disguise::Reformat,
        Disguise::Reorder,
        Disguise::Recomment,
        Disguise::All,
        Disguise::AllBroken,
    ];
}

/// `text` disguised; `seed` picks among variants (the layout style).
pub(super) fn disguise(text: &str, how: Disguise, seed: u64) -> String {
    match how {
        Disguise::Rename => rename(text),
        Disguise::Reformat => reformat(text, seed.is_multiple_of(2)),
        Disguise::Reorder => swap_if_else(&reverse_items(&swap_lets(text))),
        Disguise::Recomment => recomment(text),
        Disguise::All => {
            let text = rename(&recomment(text));
            let text = swap_if_else(&reverse_items(&swap_lets(&text)));
            reformat(&text, seed.is_multiple_of(2))
        }
        Disguise::AllBroken => {
            let mut text = disguise(text, Disguise::All, seed);
            if let Some(i) = text.rfind('}') {
                text.remove(i);
            }
            text
        }
    }
}

/// A text and its lexemes without comments, with helpers to look at them.
struct Code<'a> {
    text: &'a str,
    lexemes: Vec<Lexeme>,
}

impl<'a> Code<'a> {
    fn new(text: &'a str) -> Self {
        let lexemes = lex(text)
            .into_iter()
            .filter(|l| !matches!(l.kind, LexemeKind::LineComment | LexemeKind::BlockComment))
            .collect();
        Code { text, lexemes }
    }

    fn len(&self) -> usize {
        self.lexemes.len()
    }

    /// The text of lexeme `i` ("" outside the list).
    fn s(&self, i: usize) -> &'a str {
        self.lexemes
            .get(i)
            .and_then(|l| self.text.get(l.start..l.end))
            .unwrap_or("")
    }

    /// The text of lexeme `i - back` ("" before the start).
    fn before(&self, i: usize, back: usize) -> &'a str {
        i.checked_sub(back).map_or("", |j| self.s(j))
    }

    fn is_ident(&self, i: usize) -> bool {
        self.lexemes
            .get(i)
            .is_some_and(|l| l.kind == LexemeKind::Ident)
    }

    /// Whether lexemes `i` and `i + 1` touch in the text.
    fn adjacent(&self, i: usize) -> bool {
        match (self.lexemes.get(i), self.lexemes.get(i + 1)) {
            (Some(a), Some(b)) => a.end == b.start,
            _ => false,
        }
    }

    /// The index of the delimiter that closes the one opened at `open`.
    fn closing(&self, open: usize) -> Option<usize> {
        let mut depth = 0usize;
        for i in open..self.len() {
            match self.s(i) {
                "(" | "[" | "{" => depth += 1,
                ")" | "]" | "}" => {
                    depth = depth.checked_sub(1)?;
                    if depth == 0 {
                        return Some(i);
                    }
                }
                _ => {}
            }
        }
        None
    }

    /// The first index from `from` where `stop` holds at nesting depth 0, before the
    /// enclosing group closes.
    fn find_at_depth0(&self, from: usize, stop: impl Fn(usize) -> bool) -> Option<usize> {
        let mut depth = 0i64;
        for i in from..self.len() {
            if depth == 0 && stop(i) {
                return Some(i);
            }
            match self.s(i) {
                "(" | "[" | "{" => depth += 1,
                ")" | "]" | "}" => {
                    depth -= 1;
                    if depth < 0 {
                        return None;
                    }
                }
                _ => {}
            }
        }
        None
    }

    /// Whether the `:` at `i` is a single colon (not part of `::`).
    fn single_colon(&self, i: usize) -> bool {
        self.s(i) == ":" && !(self.s(i + 1) == ":" && self.adjacent(i)) && self.before(i, 1) != ":"
    }
}

const KEYWORDS: &[&str] = &[
    "as", "break", "const", "continue", "crate", "dyn", "else", "enum", "false", "fn", "for", "if",
    "impl", "in", "let", "loop", "match", "mod", "move", "mut", "pub", "ref", "return", "self",
    "Self", "static", "struct", "super", "trait", "true", "type", "unsafe", "use", "where",
    "while", "_",
];

const PRIMITIVES: &[&str] = &[
    "bool", "char", "str", "f32", "f64", "i8", "i16", "i32", "i64", "isize", "u8", "u16", "u32",
    "u64", "usize",
];

/// Whether `name` at `i` looks like a binding in a pattern: a lower-case name that is not a
/// path, a call, a field, a macro or a type.
fn binding_like(code: &Code, i: usize) -> bool {
    let name = code.s(i);
    let lower = name
        .chars()
        .next()
        .is_some_and(|c| c.is_lowercase() || c == '_');
    let path = (code.s(i + 1) == ":" && code.s(i + 2) == ":")
        || (code.before(i, 1) == ":" && code.before(i, 2) == ":");
    let member = code.before(i, 1) == "." && code.before(i, 2) != ".";
    let call_or_macro = matches!(code.s(i + 1), "(" | "{" | "!");
    code.is_ident(i)
        && lower
        && !KEYWORDS.contains(&name)
        && !PRIMITIVES.contains(&name)
        && !path
        && !member
        && !call_or_macro
}

/// The names the file declares: `let`, `for` and match-arm bindings, parameters of
/// functions and closures, private functions, constants and statics.
fn declared_names(code: &Code) -> BTreeSet<String> {
    let mut names = BTreeSet::new();
    let mut kept = BTreeSet::new();
    let n = code.len();
    for i in 0..n {
        match code.s(i) {
            "use" => {
                let end = (i..n).find(|&j| code.s(j) == ";").unwrap_or(n);
                kept.extend((i..end).map(|j| code.s(j).to_string()));
            }
            "fn" => {
                if code.before(i, 1) == "pub" {
                    kept.insert(code.s(i + 1).to_string());
                } else {
                    names.insert(code.s(i + 1).to_string());
                }
                // Parameters: `name:` directly inside the parameter list.
                let Some(open) = (i..n).find(|&j| code.s(j) == "(") else {
                    continue;
                };
                let close = code.closing(open).unwrap_or(n);
                let mut depth = 0;
                for j in open..close {
                    match code.s(j) {
                        "(" | "[" | "<" => depth += 1,
                        ")" | "]" => depth -= 1,
                        ">" if code.before(j, 1) != "-" => depth -= 1,
                        _ => {}
                    }
                    if depth == 1 && code.single_colon(j + 1) && binding_like(code, j) {
                        names.insert(code.s(j).to_string());
                    }
                }
            }
            "const" | "static" => {
                names.insert(code.s(i + 1).to_string());
            }
            "let" => {
                let end = code
                    .find_at_depth0(i + 1, |j| {
                        matches!(code.s(j), ";" | "else")
                            || (code.s(j) == "=" && !matches!(code.s(j + 1), "=" | ">"))
                    })
                    .unwrap_or(i + 1);
                let mut in_type = false;
                for j in i + 1..end {
                    if code.single_colon(j) {
                        in_type = true;
                    }
                    if !in_type && binding_like(code, j) {
                        names.insert(code.s(j).to_string());
                    }
                }
            }
            "for" => {
                let end = (i..n).find(|&j| code.s(j) == "in").unwrap_or(i);
                for j in i + 1..end {
                    if binding_like(code, j) {
                        names.insert(code.s(j).to_string());
                    }
                }
            }
            "=" if code.s(i + 1) == ">" && code.adjacent(i) => {
                // A match arm: its pattern runs back to the previous `,`, `{` or `}` at
                // the arm's depth.
                let mut depth = 0i64;
                let mut j = i;
                while j > 0 {
                    j -= 1;
                    match code.s(j) {
                        // The closing brace of a struct pattern right before the arrow.
                        "}" if j + 1 == i => depth += 1,
                        ")" | "]" => depth += 1,
                        "(" | "[" | "{" | "}" | "," if depth == 0 => break,
                        "(" | "[" | "{" => depth -= 1,
                        "}" => depth += 1,
                        _ => {
                            if binding_like(code, j) && code.s(j + 1) != ":" {
                                names.insert(code.s(j).to_string());
                            }
                        }
                    }
                }
            }
            "|" => {
                let opens = matches!(code.before(i, 1), "=" | "(" | "," | "move" | "{" | ";")
                    && code.s(i + 1) != "|";
                if opens {
                    let close = (i + 1..n).find(|&j| code.s(j) == "|").unwrap_or(i);
                    for j in i + 1..close {
                        if binding_like(code, j) && matches!(code.s(j + 1), ":" | "," | "|") {
                            names.insert(code.s(j).to_string());
                        }
                    }
                }
            }
            _ => {}
        }
    }
    names.retain(|name| {
        !kept.contains(name)
            && !KEYWORDS.contains(&name.as_str())
            && !PRIMITIVES.contains(&name.as_str())
            && name != "_"
            && name
                .chars()
                .next()
                .is_some_and(|c| c.is_alphabetic() || c == '_')
    });
    names
}

/// Whether the brace at `open` opens a struct literal or struct pattern: a CamelCase path
/// before it (not a return type), fields inside.
fn struct_brace(code: &Code, open: usize) -> bool {
    let before = code.before(open, 1);
    let camel = before.chars().next().is_some_and(char::is_uppercase)
        && before.chars().any(char::is_lowercase);
    let return_type = code.before(open, 2) == ">" && code.before(open, 3) == "-";
    let first = open + 1;
    let fields = (code.is_ident(first) && matches!(code.s(first + 1), ":" | "," | "}"))
        || code.s(first) == "."
        || code.s(first) == "}";
    camel && !return_type && fields && !(code.s(first + 1) == ":" && code.s(first + 2) == ":")
}

/// New names for `names`, none of them a name the file uses.
fn fresh_names(names: &BTreeSet<String>, used: &BTreeSet<&str>) -> BTreeMap<String, String> {
    const WORDS: &[&str] = &[
        "val", "acc", "res", "dirn", "tmp", "fac", "cur", "aux", "num", "vv", "pt", "ww", "qq",
        "elem", "part", "amt",
    ];
    let mut map = BTreeMap::new();
    let mut counter = 0usize;
    for name in names {
        let fresh = loop {
            let word = WORDS.get(counter % WORDS.len()).copied().unwrap_or("v");
            let candidate = if name
                .chars()
                .all(|c| c.is_uppercase() || c == '_' || c.is_numeric())
            {
                format!("{}_{}", word.to_uppercase(), counter)
            } else {
                format!("{word}_{counter}")
            };
            counter += 1;
            if !used.contains(candidate.as_str()) {
                break candidate;
            }
        };
        map.insert(name.clone(), fresh);
    }
    map
}

/// Consistent renaming of every declared local name.
pub(super) fn rename(text: &str) -> String {
    let code = Code::new(text);
    let declared = declared_names(&code);
    let used: BTreeSet<&str> = (0..code.len()).map(|i| code.s(i)).collect();
    let map = fresh_names(&declared, &used);
    let mut out = String::with_capacity(text.len() + 256);
    let mut copied = 0;
    // The innermost open delimiters: whether each is a struct brace.
    let mut open: Vec<bool> = Vec::new();
    for i in 0..code.len() {
        let s = code.s(i);
        match s {
            "{" => open.push(struct_brace(&code, i)),
            "(" | "[" => open.push(false),
            ")" | "]" | "}" => {
                open.pop();
            }
            _ => {}
        }
        let Some(new) = map.get(s) else {
            continue;
        };
        let member = code.before(i, 1) == "." && code.before(i, 2) != ".";
        let path = (code.before(i, 1) == ":" && code.before(i, 2) == ":")
            || (code.s(i + 1) == ":" && code.s(i + 2) == ":");
        let is_macro = code.s(i + 1) == "!" && matches!(code.s(i + 2), "(" | "[" | "{");
        if !code.is_ident(i) || member || path || is_macro {
            continue;
        }
        let in_struct = open.last() == Some(&true) && matches!(code.before(i, 1), "{" | ",");
        let replacement = if in_struct && code.single_colon(i + 1) {
            continue; // a field name
        } else if in_struct && matches!(code.s(i + 1), "," | "}") {
            format!("{s}: {new}") // shorthand field
        } else {
            new.clone()
        };
        let Some(lexeme) = code.lexemes.get(i) else {
            continue;
        };
        out.push_str(text.get(copied..lexeme.start).unwrap_or(""));
        out.push_str(&replacement);
        copied = lexeme.end;
    }
    out.push_str(text.get(copied..).unwrap_or(""));
    out
}

/// Another layout for the same lexemes: `allman` (tabs, braces on their own lines, spaces
/// inside parentheses, one field or arm per line) or compact (three spaces, short blocks on
/// one line, statements joined up to 80 columns, arithmetic without spaces).
pub(super) fn reformat(text: &str, allman: bool) -> String {
    let lexemes = lex(text);
    let s = |i: usize| {
        lexemes
            .get(i)
            .and_then(|l| text.get(l.start..l.end))
            .unwrap_or("")
    };
    let is_punct = |i: usize| {
        lexemes
            .get(i)
            .is_some_and(|l| l.kind == LexemeKind::Punct && !"()[]{}".contains(s(i)))
    };
    let is_comment = |i: usize| {
        lexemes
            .get(i)
            .is_some_and(|l| matches!(l.kind, LexemeKind::LineComment | LexemeKind::BlockComment))
    };
    let adjacent = |i: usize| match (lexemes.get(i), lexemes.get(i + 1)) {
        (Some(a), Some(b)) => a.end == b.start,
        _ => false,
    };
    let indent_unit = if allman { "\t" } else { "   " };
    let mut out = String::new();
    let mut line_start = true;
    let mut depth = 0usize;
    let mut delims: Vec<&str> = Vec::new();
    let newline = |out: &mut String, line_start: &mut bool| {
        if !*line_start {
            out.push('\n');
            *line_start = true;
        }
    };
    let current_line_len = |out: &String| out.len() - out.rfind('\n').map_or(0, |p| p + 1);
    let mut i = 0;
    while i < lexemes.len() {
        let t = s(i);
        let space = if i == 0 || line_start {
            false
        } else {
            let prev = s(i - 1);
            let keep_joint = adjacent(i - 1)
                && ((is_punct(i - 1) && is_punct(i))
                    || prev == "'"
                    || matches!(t, "." | ":" | "!")
                    || matches!(prev, "." | ":"));
            if keep_joint {
                false
            } else if allman {
                (prev == "(" && t != ")") || (t == ")" && prev != "(") || !adjacent(i - 1)
            } else {
                let arith = |j: usize| matches!(s(j), "*" | "/" | "+" | "-");
                let operand = |j: usize| !is_punct(j) && !is_comment(j);
                let squeeze = (arith(i) && operand(i - 1) && operand(i + 1))
                    || (arith(i - 1) && operand(i) && i >= 2 && operand(i - 2));
                !adjacent(i - 1) && !squeeze
            }
        };
        let write_indented =
            |out: &mut String, line_start: &mut bool, piece: &str, depth: usize| {
                if *line_start {
                    for _ in 0..depth {
                        out.push_str(indent_unit);
                    }
                    *line_start = false;
                }
                out.push_str(piece);
            };
        if is_comment(i) {
            if !line_start {
                out.push(' ');
            }
            write_indented(&mut out, &mut line_start, t, depth);
            if lexemes
                .get(i)
                .is_some_and(|l| l.kind == LexemeKind::LineComment)
            {
                newline(&mut out, &mut line_start);
            }
            i += 1;
            continue;
        }
        match t {
            "{" => {
                // Compact: a short block without braces or comments inside goes on one line.
                let close = (i + 1..lexemes.len())
                    .find(|&j| matches!(s(j), "{" | "}"))
                    .filter(|&j| s(j) == "}");
                let inline = !allman
                    && close.is_some_and(|c| {
                        let body: usize = (i + 1..c).map(|j| s(j).len() + 1).sum();
                        body <= 50 && !(i + 1..c).any(is_comment)
                    });
                if let (true, Some(c)) = (inline, close) {
                    if space {
                        out.push(' ');
                    }
                    write_indented(&mut out, &mut line_start, "{", depth);
                    for j in i + 1..c {
                        if j == i + 1 || !adjacent(j - 1) {
                            out.push(' ');
                        }
                        out.push_str(s(j));
                    }
                    out.push_str(" }");
                    i = c + 1;
                    if !matches!(s(i), "," | ";" | ")" | "." | "else") {
                        newline(&mut out, &mut line_start);
                    }
                    continue;
                }
                if allman {
                    newline(&mut out, &mut line_start);
                } else if space {
                    out.push(' ');
                }
                write_indented(&mut out, &mut line_start, "{", depth);
                newline(&mut out, &mut line_start);
                depth += 1;
                delims.push("{");
            }
            "}" => {
                depth = depth.saturating_sub(1);
                delims.pop();
                newline(&mut out, &mut line_start);
                write_indented(&mut out, &mut line_start, "}", depth);
                if !matches!(s(i + 1), "," | ";" | ")" | ".") && (allman || s(i + 1) != "else") {
                    newline(&mut out, &mut line_start);
                }
            }
            ";" | "," => {
                write_indented(&mut out, &mut line_start, t, depth);
                let in_block = matches!(delims.last(), None | Some(&"{"));
                let wrap = if allman {
                    in_block
                } else {
                    in_block && (t == "," || current_line_len(&out) > 60)
                };
                if wrap {
                    newline(&mut out, &mut line_start);
                }
            }
            _ => {
                if matches!(t, "(" | "[") {
                    delims.push(t);
                } else if matches!(t, ")" | "]") {
                    delims.pop();
                }
                if space {
                    out.push(' ');
                }
                write_indented(&mut out, &mut line_start, t, depth);
            }
        }
        i += 1;
    }
    out.push('\n');
    out
}

/// Statement `let … ;` starting at `start` (a `let` at statement position): its end, the
/// names it binds and the identifiers it uses; `None` if it is not a plain one.
fn let_statement<'a>(
    code: &Code<'a>,
    start: usize,
) -> Option<(usize, BTreeSet<&'a str>, BTreeSet<&'a str>)> {
    if code.s(start) != "let" || !matches!(code.before(start, 1), ";" | "{" | "}") {
        return None;
    }
    let end = code.find_at_depth0(start + 1, |j| code.s(j) == ";")?;
    let eq = code.find_at_depth0(start + 1, |j| {
        matches!(code.s(j), ";" | "else")
            || (code.s(j) == "=" && !matches!(code.s(j + 1), "=" | ">"))
    })?;
    if code.s(eq) != "=" {
        return None;
    }
    if code
        .find_at_depth0(eq, |j| code.s(j) == "else")
        .is_some_and(|e| e < end)
    {
        return None; // `let … else { … };`
    }
    let bound = (start + 1..eq)
        .filter(|&j| binding_like(code, j))
        .map(|j| code.s(j))
        .collect();
    let used: BTreeSet<&str> = (start..=end)
        .filter(|&j| code.is_ident(j))
        .map(|j| code.s(j))
        .collect();
    // Order matters for the random stream and for anything mutated through a method.
    if used.contains("sampler") || used.contains("next_1d") {
        return None;
    }
    Some((end, bound, used))
}

/// Swaps adjacent `let` statements that do not depend on each other.
pub(super) fn swap_lets(text: &str) -> String {
    let code = Code::new(text);
    let mut swaps: Vec<(usize, usize, usize, usize)> = Vec::new();
    let mut i = 0;
    while i < code.len() {
        let first = let_statement(&code, i);
        let Some((end1, bound1, used1)) = first else {
            i += 1;
            continue;
        };
        match let_statement(&code, end1 + 1) {
            Some((end2, bound2, used2))
                if bound1.is_disjoint(&used2) && bound2.is_disjoint(&used1) =>
            {
                swaps.push((i, end1, end1 + 1, end2));
                i = end2 + 1;
            }
            _ => i = end1 + 1,
        }
    }
    let span = |from: usize, to: usize| -> (usize, usize) {
        let a = code.lexemes.get(from).map_or(0, |l| l.start);
        let b = code.lexemes.get(to).map_or(0, |l| l.end);
        (a, b)
    };
    let mut out = String::new();
    let mut copied = 0;
    for (s1, e1, s2, e2) in swaps {
        let (a1, b1) = span(s1, e1);
        let (a2, b2) = span(s2, e2);
        out.push_str(text.get(copied..a1).unwrap_or(""));
        out.push_str(text.get(a2..b2).unwrap_or(""));
        out.push_str(text.get(b1..a2).unwrap_or(""));
        out.push_str(text.get(a1..b1).unwrap_or(""));
        copied = b2;
    }
    out.push_str(text.get(copied..).unwrap_or(""));
    out
}

/// Reverses the order of the top-level items other than `use` declarations (helpers move
/// from before the task's function to after it and back); comments go with the item they
/// precede.
pub(super) fn reverse_items(text: &str) -> String {
    let code = Code::new(text);
    let mut items: Vec<(usize, usize, bool)> = Vec::new(); // byte range, is `use`
    let mut start_byte = 0;
    let mut first_lexeme = 0;
    let mut depth = 0i64;
    for i in 0..code.len() {
        match code.s(i) {
            "(" | "[" | "{" => depth += 1,
            ")" | "]" | "}" => depth -= 1,
            _ => {}
        }
        let ends = depth == 0 && (code.s(i) == ";" || (code.s(i) == "}" && code.s(i + 1) != ";"));
        if ends {
            let end_byte = code.lexemes.get(i).map_or(start_byte, |l| l.end);
            items.push((start_byte, end_byte, code.s(first_lexeme) == "use"));
            start_byte = end_byte;
            first_lexeme = i + 1;
        }
    }
    if depth != 0 {
        return text.to_string();
    }
    let piece = |(a, b, _): (usize, usize, bool)| text.get(a..b).unwrap_or("");
    let mut out = String::new();
    for &item in items.iter().filter(|i| i.2) {
        out.push_str(piece(item));
    }
    for &item in items.iter().rev().filter(|i| !i.2) {
        let p = piece(item);
        if !p.starts_with('\n') {
            out.push('\n');
        }
        out.push_str(p);
    }
    out.push_str(text.get(start_byte..).unwrap_or(""));
    out
}

/// `if c { a } else { b }` to `if !(c) { b } else { a }`, for every such `if` not inside
/// another one rewritten.
pub(super) fn swap_if_else(text: &str) -> String {
    let code = Code::new(text);
    let byte = |i: usize, end: bool| {
        code.lexemes
            .get(i)
            .map_or(0, |l| if end { l.end } else { l.start })
    };
    let mut out = String::new();
    let mut copied = 0;
    let mut i = 0;
    while i < code.len() {
        let candidate = (|| {
            if code.s(i) != "if" || code.s(i + 1) == "let" {
                return None;
            }
            let a_open = code.find_at_depth0(i + 1, |j| code.s(j) == "{")?;
            if (i + 1..a_open).any(|j| code.s(j) == "let") || a_open == i + 1 {
                return None;
            }
            let a_close = code.closing(a_open)?;
            if code.s(a_close + 1) != "else" || code.s(a_close + 2) != "{" {
                return None;
            }
            let b_close = code.closing(a_close + 2)?;
            Some((a_open, a_close, b_close))
        })();
        let Some((a_open, a_close, b_close)) = candidate else {
            i += 1;
            continue;
        };
        let condition = text
            .get(byte(i + 1, false)..byte(a_open - 1, true))
            .unwrap_or("");
        let a = text
            .get(byte(a_open, false)..byte(a_close, true))
            .unwrap_or("");
        let b = text
            .get(byte(a_close + 2, false)..byte(b_close, true))
            .unwrap_or("");
        out.push_str(text.get(copied..byte(i, false)).unwrap_or(""));
        out.push_str(&format!("if !({condition}) {b} else {a}"));
        copied = byte(b_close, true);
        i = b_close + 1;
    }
    out.push_str(text.get(copied..).unwrap_or(""));
    out
}

/// Every comment removed; a header comment, and a comment before every third statement
/// that starts a line, added.
pub(super) fn recomment(text: &str) -> String {
    const NOTES: &[&str] = &[
        "// compute the next value",
        "// careful with the edge case here",
        "// as in the lecture",
        "// see worksheet",
        "/* this part was tricky */",
    ];
    let lexemes = lex(text);
    let mut out = String::from("/* Exercise solution. */\n");
    let mut copied = 0;
    let mut statements = 0usize;
    for l in &lexemes {
        let gap = text.get(copied..l.start).unwrap_or("");
        let is_comment = matches!(l.kind, LexemeKind::LineComment | LexemeKind::BlockComment);
        let word = text.get(l.start..l.end).unwrap_or("");
        if is_comment {
            out.push_str(gap);
            copied = l.end;
            continue;
        }
        let starts_line = gap.contains('\n');
        if starts_line && matches!(word, "let" | "if" | "return" | "for" | "while" | "match") {
            statements += 1;
            if statements % 3 == 1 {
                let (before, indent) = gap.rsplit_once('\n').unwrap_or(("", gap));
                let note = NOTES
                    .get(statements / 3 % NOTES.len())
                    .copied()
                    .unwrap_or("//");
                out.push_str(before);
                out.push('\n');
                out.push_str(indent);
                out.push_str(note);
                out.push('\n');
                out.push_str(indent);
                out.push_str(word);
                copied = l.end;
                continue;
            }
        }
        out.push_str(gap);
        out.push_str(word);
        copied = l.end;
    }
    out.push_str(text.get(copied..).unwrap_or(""));
    out
}
