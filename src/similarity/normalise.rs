//! Raw tokens to the symbols that are compared: what a copy keeps when it renames, reformats
//! and recomments.
//!
//! - Keywords, punctuation and delimiters stay as they are.
//! - Literals become their kind (number, string, character, boolean): a copied formula with
//!   a changed constant is still the copied formula.
//! - Names a student chooses (variables, parameters, helper functions, constants, closures,
//!   lifetimes, generic parameters) become [`Symbol::Local`]: the k-gram hash
//!   ([`super::winnow`]) numbers them by first occurrence inside each k-gram, so a
//!   consistent renaming leaves every hash unchanged while `a = a + b` and `a = b + c`
//!   still differ.
//! - With [`Normalisation::keep_names`], names that a renaming cannot change without
//!   changing what the code does stay as they are: the name after `.` (a method or field of
//!   the framework's types), a segment of a `::` path (`Vec3::ZERO`, `Heuristic::Power`), a
//!   macro name, a CamelCase name (types and enum variants the task API defines) and the
//!   primitive types.

use super::tokens::{Delim, LiteralKind, RawKind, RawToken};

/// How identifiers are abstracted; both settings are measured in the tests.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Normalisation {
    /// Keep the names a renaming cannot change (see the module documentation) instead of
    /// abstracting every identifier.
    pub keep_names: bool,
    /// Number local names by first occurrence within each k-gram (`true`), or map them
    /// all to one placeholder, as MOSS does (`false`).
    pub number_locals: bool,
}

/// A normalised token.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Symbol {
    /// A token compared as it is: the hash of its class and text.
    Fixed(u64),
    /// A name the student chose: the hash of its text, used only to tell names apart
    /// within one k-gram.
    Local(u64),
}

/// A normalised token and the 1-based line it starts on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Token {
    /// What is compared.
    pub symbol: Symbol,
    /// Its line, from 1.
    pub line: usize,
}

/// Rust's strict and reserved keywords (2024 edition) and the weak keywords that read like
/// syntax; they are kept in every mode.
const KEYWORDS: &[&str] = &[
    "as", "async", "await", "break", "const", "continue", "crate", "dyn", "else", "enum", "extern",
    "fn", "for", "if", "impl", "in", "let", "loop", "match", "mod", "move", "mut", "pub", "ref",
    "return", "self", "Self", "static", "struct", "super", "trait", "type", "unsafe", "use",
    "where", "while", "abstract", "become", "box", "do", "final", "gen", "macro", "override",
    "priv", "try", "typeof", "unsized", "virtual", "yield", "union", "_",
];

/// Primitive types: names, but not ones a student can rename.
const PRIMITIVES: &[&str] = &[
    "bool", "char", "str", "f32", "f64", "i8", "i16", "i32", "i64", "i128", "isize", "u8", "u16",
    "u32", "u64", "u128", "usize",
];

/// The normalised tokens of `raw`.
pub(crate) fn normalise(raw: &[RawToken], mode: Normalisation) -> Vec<Token> {
    (0..raw.len())
        .filter_map(|i| {
            let token = raw.get(i)?;
            Some(Token {
                symbol: symbol(raw, i, mode),
                line: token.line,
            })
        })
        .collect()
}

/// The symbol of the token at `i`, which may depend on its neighbours.
fn symbol(raw: &[RawToken], i: usize, mode: Normalisation) -> Symbol {
    let Some(token) = raw.get(i) else {
        return Symbol::Fixed(0);
    };
    match &token.kind {
        RawKind::Punct(c) => Symbol::Fixed(hash_str(1, &c.to_string())),
        RawKind::Open(d) => Symbol::Fixed(hash_str(2, delim_name(*d))),
        RawKind::Close(d) => Symbol::Fixed(hash_str(3, delim_name(*d))),
        RawKind::Literal(kind) => Symbol::Fixed(hash_str(4, literal_name(*kind))),
        RawKind::Ident(name) if name == "true" || name == "false" => {
            Symbol::Fixed(hash_str(4, "bool"))
        }
        RawKind::Ident(name) if KEYWORDS.contains(&name.as_str()) => {
            Symbol::Fixed(hash_str(5, name))
        }
        RawKind::Ident(name) if mode.keep_names && is_fixed_name(raw, i, name) => {
            Symbol::Fixed(hash_str(6, name))
        }
        RawKind::Ident(name) => Symbol::Local(hash_str(7, name)),
    }
}

/// Whether the identifier `name` at `i` is one a renaming cannot change.
fn is_fixed_name(raw: &[RawToken], i: usize, name: &str) -> bool {
    let punct = |j: Option<usize>, c: char| {
        j.and_then(|j| raw.get(j))
            .is_some_and(|t| t.kind == RawKind::Punct(c))
    };
    let before = |n: usize| i.checked_sub(n);
    let after = |n: usize| Some(i + n);
    // `x.name`, but not the end of a range `0..name`.
    let member = punct(before(1), '.') && !punct(before(2), '.');
    let path = (punct(before(1), ':') && punct(before(2), ':'))
        || (punct(after(1), ':') && punct(after(2), ':'));
    // `name!(…)`, but not `name != …`.
    let is_macro = punct(after(1), '!')
        && raw
            .get(i + 2)
            .is_some_and(|t| matches!(t.kind, RawKind::Open(_)));
    member || path || is_macro || is_camel_case(name) || PRIMITIVES.contains(&name)
}

/// `Vec3`, `Heuristic`, `Some`: an upper-case first letter and a lower-case letter
/// somewhere. `EPS` and `T` (constants and generic parameters a student names) are not.
fn is_camel_case(name: &str) -> bool {
    let name = name.strip_prefix("r#").unwrap_or(name);
    name.chars().next().is_some_and(char::is_uppercase) && name.chars().any(char::is_lowercase)
}

fn delim_name(d: Delim) -> &'static str {
    match d {
        Delim::Paren => "()",
        Delim::Bracket => "[]",
        Delim::Brace => "{}",
    }
}

fn literal_name(kind: LiteralKind) -> &'static str {
    match kind {
        LiteralKind::Number => "number",
        LiteralKind::Str => "string",
        LiteralKind::Char => "char",
    }
}

/// FNV-1a over a class byte and the text: stable across runs and platforms, so the same
/// code gives the same fingerprints in every report.
pub(crate) fn hash_str(class: u8, text: &str) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for byte in std::iter::once(class).chain(text.bytes()) {
        h ^= u64::from(byte);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

#[cfg(test)]
mod tests {
    use super::super::tokens::raw_tokens;
    use super::*;

    fn symbols(text: &str, keep_names: bool) -> Vec<Symbol> {
        let mode = Normalisation {
            keep_names,
            number_locals: true,
        };
        normalise(&raw_tokens(text).0, mode)
            .into_iter()
            .map(|t| t.symbol)
            .collect()
    }

    #[test]
    fn literals_are_abstracted_by_kind() {
        assert_eq!(
            symbols("f(1.5, \"a\")", false),
            symbols("f(2, r\"b\")", false)
        );
        assert_ne!(symbols("f(1.5)", false), symbols("f('c')", false));
    }

    #[test]
    fn kept_names_are_members_paths_macros_and_types() {
        let kept = |text: &str| {
            symbols(text, true)
                .iter()
                .filter(|s| matches!(s, Symbol::Fixed(_)))
                .count()
        };
        // x . dot ( y ): `.`, `dot`, `(`, `)`.
        assert_eq!(kept("x.dot(y)"), 4);
        // Vec3 : : ZERO
        assert_eq!(kept("Vec3::ZERO"), 4);
        // 0 . . n: n is a local.
        assert_eq!(kept("0..n"), 3);
        // a ! = b: neither is a macro.
        assert_eq!(kept("a != b"), 2);
        assert_eq!(kept("todo!()"), 4);
        assert_eq!(kept("const EPS: f32 = 1.0;"), 6);
    }
}
