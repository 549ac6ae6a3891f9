//! Source text to a flat list of Rust tokens, each with its line: by `proc-macro2` when the
//! text lexes, by the fallback lexer ([`super::lexer`]) when it does not.
//!
//! Both paths produce the same list for a text both can read: one token per identifier, per
//! literal and per punctuation character (`::` is two `:`), an opening and a closing token
//! per delimited group, and no comments. Doc comments, which `proc-macro2` turns into
//! `#[doc = "…"]` and `#![doc = "…"]` attributes, are removed afterwards from either list,
//! together with any `doc` attribute written out: prose is not code.

use super::lexer::{self, LexemeKind};
use proc_macro2::{Delimiter, TokenStream, TokenTree};
use std::str::FromStr;

/// The kind of a literal, the only thing the comparison keeps of it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum LiteralKind {
    /// Integer or float.
    Number,
    /// String, byte string, C string, raw or not.
    Str,
    /// Character or byte.
    Char,
}

/// A delimiter of a group.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Delim {
    /// `( … )`
    Paren,
    /// `[ … ]`
    Bracket,
    /// `{ … }`
    Brace,
}

/// What a token is, before normalisation.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum RawKind {
    /// An identifier or keyword, with its text.
    Ident(String),
    /// A literal, by kind.
    Literal(LiteralKind),
    /// One punctuation character (or, from the fallback lexer, any unclassified character).
    Punct(char),
    /// The opening delimiter of a group.
    Open(Delim),
    /// The closing delimiter of a group.
    Close(Delim),
}

/// One token and the 1-based line it starts on.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct RawToken {
    /// What it is.
    pub kind: RawKind,
    /// Its line, from 1.
    pub line: usize,
}

/// Larger texts skip `proc-macro2` and go to the fallback lexer: no exercise file comes
/// near this, and `proc-macro2` keeps a copy of every text it lexes (see [`raw_tokens_all`]).
const PROC_MACRO2_MAX_BYTES: usize = 1 << 22;

/// The tokens of each of `texts`, as [`raw_tokens`] gives them, lexed on a thread of its
/// own.
///
/// `proc-macro2` keeps every text it has lexed, for span lookups, in a thread-local source
/// map that only grows (with 32-bit offsets); lexing a task's files on a scoped thread frees
/// that map when the task is done, whoever calls this and however often. Should that
/// thread panic (a bug in a dependency), every text is read by the fallback lexer instead;
/// should it not start, the texts are lexed on the calling thread.
pub(crate) fn raw_tokens_all(texts: &[&str]) -> Vec<(Vec<RawToken>, bool)> {
    fn lex_all(texts: &[&str]) -> Vec<(Vec<RawToken>, bool)> {
        texts.iter().map(|text| raw_tokens(text)).collect()
    }
    std::thread::scope(|scope| {
        let lexer = std::thread::Builder::new()
            .name("similarity-lexer".to_string())
            .spawn_scoped(scope, move || lex_all(texts));
        match lexer {
            Ok(handle) => handle.join().unwrap_or_else(|_| {
                texts
                    .iter()
                    .map(|text| (without_doc_attributes(fallback_tokens(text)), true))
                    .collect()
            }),
            Err(_) => lex_all(texts),
        }
    })
}

/// The tokens of `text` without comments and doc attributes, and whether the fallback
/// lexer had to read it (the text is not valid Rust tokens, or is huge).
pub(crate) fn raw_tokens(text: &str) -> (Vec<RawToken>, bool) {
    let lexed = if text.len() > PROC_MACRO2_MAX_BYTES {
        None
    } else {
        TokenStream::from_str(text).ok()
    };
    let (tokens, fallback) = match lexed {
        Some(stream) => {
            let mut out = Vec::new();
            flatten(stream, &mut out);
            (out, false)
        }
        None => (fallback_tokens(text), true),
    };
    (without_doc_attributes(tokens), fallback)
}

/// Appends the tokens of `stream` to `out`, groups as opening token, content, closing token.
/// Iterative, with its own stack: a file of a million nested parentheses must not overflow
/// the thread's stack.
fn flatten(stream: TokenStream, out: &mut Vec<RawToken>) {
    let mut stack = vec![(stream.into_iter(), None::<(Delim, usize)>)];
    while let Some((trees, _)) = stack.last_mut() {
        let Some(tree) = trees.next() else {
            if let Some((_, Some((delim, line)))) = stack.pop() {
                out.push(RawToken {
                    kind: RawKind::Close(delim),
                    line,
                });
            }
            continue;
        };
        match tree {
            TokenTree::Ident(ident) => out.push(RawToken {
                kind: RawKind::Ident(ident.to_string()),
                line: ident.span().start().line,
            }),
            TokenTree::Punct(punct) => out.push(RawToken {
                kind: RawKind::Punct(punct.as_char()),
                line: punct.span().start().line,
            }),
            TokenTree::Literal(literal) => out.push(RawToken {
                kind: RawKind::Literal(literal_kind(&literal.to_string())),
                line: literal.span().start().line,
            }),
            TokenTree::Group(group) => {
                let delim = match group.delimiter() {
                    Delimiter::Parenthesis => Some(Delim::Paren),
                    Delimiter::Bracket => Some(Delim::Bracket),
                    Delimiter::Brace => Some(Delim::Brace),
                    // Never produced by lexing text; keep the content only.
                    Delimiter::None => None,
                };
                if let Some(d) = delim {
                    out.push(RawToken {
                        kind: RawKind::Open(d),
                        line: group.span_open().start().line,
                    });
                }
                let close = delim.map(|d| (d, group.span_close().start().line));
                stack.push((group.stream().into_iter(), close));
            }
        }
    }
}

/// The kind of a literal from its source text (`proc-macro2` keeps the text only).
fn literal_kind(repr: &str) -> LiteralKind {
    let mut chars = repr.chars();
    match (chars.next(), chars.next()) {
        (Some('\''), _) | (Some('b'), Some('\'')) => LiteralKind::Char,
        (Some('"' | 'r' | 'b' | 'c'), _) => LiteralKind::Str,
        _ => LiteralKind::Number,
    }
}

/// The fallback: the hand lexer's lexemes as tokens, comments dropped. Delimiters are
/// tokens whether they balance or not.
fn fallback_tokens(text: &str) -> Vec<RawToken> {
    // As proc-macro2 does: a byte-order mark is not a token.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut out = Vec::new();
    for lexeme in lexer::lex(text) {
        let source = text.get(lexeme.start..lexeme.end).unwrap_or("");
        let kind = match lexeme.kind {
            LexemeKind::LineComment | LexemeKind::BlockComment => continue,
            LexemeKind::Ident => RawKind::Ident(source.to_string()),
            LexemeKind::Number => RawKind::Literal(LiteralKind::Number),
            LexemeKind::Str => RawKind::Literal(LiteralKind::Str),
            LexemeKind::Char => RawKind::Literal(LiteralKind::Char),
            LexemeKind::Punct => match source.chars().next() {
                Some('(') => RawKind::Open(Delim::Paren),
                Some('[') => RawKind::Open(Delim::Bracket),
                Some('{') => RawKind::Open(Delim::Brace),
                Some(')') => RawKind::Close(Delim::Paren),
                Some(']') => RawKind::Close(Delim::Bracket),
                Some('}') => RawKind::Close(Delim::Brace),
                Some(c) => RawKind::Punct(c),
                None => continue,
            },
        };
        out.push(RawToken {
            kind,
            line: lexeme.line,
        });
    }
    out
}

/// Removes every `#[doc …]` and `#![doc …]` attribute: doc comments, as `proc-macro2`
/// delivers them, and the same attributes written out.
fn without_doc_attributes(tokens: Vec<RawToken>) -> Vec<RawToken> {
    let mut out = Vec::with_capacity(tokens.len());
    let mut i = 0;
    while i < tokens.len() {
        if let Some(end) = doc_attribute_end(&tokens, i) {
            i = end;
        } else {
            if let Some(token) = tokens.get(i) {
                out.push(token.clone());
            }
            i += 1;
        }
    }
    out
}

/// If a doc attribute starts at `start`, the index just past its closing bracket.
fn doc_attribute_end(tokens: &[RawToken], start: usize) -> Option<usize> {
    let kind = |i: usize| tokens.get(i).map(|t| &t.kind);
    if kind(start) != Some(&RawKind::Punct('#')) {
        return None;
    }
    let mut i = start + 1;
    if kind(i) == Some(&RawKind::Punct('!')) {
        i += 1;
    }
    if kind(i) != Some(&RawKind::Open(Delim::Bracket)) {
        return None;
    }
    match kind(i + 1) {
        Some(RawKind::Ident(name)) if name == "doc" => {}
        _ => return None,
    }
    let mut depth = 0usize;
    for (j, token) in tokens.iter().enumerate().skip(i) {
        match token.kind {
            RawKind::Open(_) => depth += 1,
            RawKind::Close(_) => {
                depth = depth.saturating_sub(1);
                if depth == 0 {
                    return Some(j + 1);
                }
            }
            _ => {}
        }
    }
    // An unclosed doc attribute (fallback lexer only) runs to the end.
    Some(tokens.len())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(text: &str) -> Vec<RawKind> {
        raw_tokens(text).0.into_iter().map(|t| t.kind).collect()
    }

    #[test]
    fn both_lexers_agree_on_valid_rust() {
        let text = "//! Module doc.\n/// Item doc.\n#[inline]\npub fn f<'a>(x: &'a [f32; 3]) \
                    -> Option<f32> {\n    /* block /* nested */ */ let s = r#\"raw \"str\"#;\n    \
                    let c = b'x'; let d = '\\n'; // line\n    let r = 0..10; let m = 1.0f32.max(2.);\n    \
                    x.get(0).copied().map(|v| v * 1e-5 + 0x1F as f32 - 1_000.5e+3) \n}\n";
        let (proc_tokens, fallback) = raw_tokens(text);
        assert!(!fallback);
        let hand = without_doc_attributes(fallback_tokens(text));
        assert_eq!(proc_tokens, hand);
    }

    #[test]
    fn doc_comments_are_dropped_and_other_attributes_kept() {
        let k = kinds("/// a\n#[doc = \"b\"]\n#[inline]\nfn f() {}\n//! c\n");
        assert_eq!(k.first(), Some(&RawKind::Punct('#')));
        assert!(!k.contains(&RawKind::Literal(LiteralKind::Str)));
    }

    #[test]
    fn broken_files_fall_back_and_keep_lines() {
        let (tokens, fallback) = raw_tokens("fn f() {\n  let x = \"open\n}\n");
        assert!(fallback);
        assert_eq!(tokens.last().map(|t| t.line), Some(2));
        let (tokens, fallback) = raw_tokens("fn f() { let x = (1;\n}\n}");
        assert!(fallback);
        assert_eq!(tokens.last().map(|t| t.line), Some(3));
    }
}
