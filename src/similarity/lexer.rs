//! The fallback lexer: a small hand-written lexer for files that `proc-macro2` refuses
//! (unbalanced delimiters, an unterminated string, characters Rust does not allow).
//!
//! It never fails: every byte of the input ends up in some lexeme, so a file that does not
//! compile is still compared with the rest of the class. It splits text the way
//! `proc-macro2` does where both succeed (identifiers, single-character punctuation,
//! literals as one token each), so a copy that lexes and one that does not still produce
//! the same token stream. It also keeps comments, with their position, for the tests that
//! rewrite sources (the comparison itself skips them).

/// What a lexeme is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LexemeKind {
    /// An identifier or keyword (including `_` and raw identifiers such as `r#type`).
    Ident,
    /// An integer or float literal, with its suffix.
    Number,
    /// A string literal of any kind: `"…"`, `r#"…"#`, `b"…"`, `c"…"`.
    Str,
    /// A character or byte literal: `'x'`, `b'x'`.
    Char,
    /// One punctuation character, or any other character the lexer has no class for.
    Punct,
    /// A `//` comment, doc comments included, without its line break.
    LineComment,
    /// A `/* … */` comment (nested ones included), doc comments included.
    BlockComment,
}

/// One lexeme: its kind and where it is in the text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Lexeme {
    /// What it is.
    pub kind: LexemeKind,
    /// Byte offset of its first character.
    pub start: usize,
    /// Byte offset just past its last character.
    pub end: usize,
    /// The 1-based line of its first character.
    pub line: usize,
}

/// Splits `text` into lexemes, comments included, whitespace left out. Never fails.
pub fn lex(text: &str) -> Vec<Lexeme> {
    let chars: Vec<(usize, char)> = text.char_indices().collect();
    let mut lexer = Lexer {
        text,
        chars: &chars,
        at: 0,
        line: 1,
    };
    let mut out = Vec::new();
    while let Some(lexeme) = lexer.next_lexeme() {
        out.push(lexeme);
    }
    out
}

/// The state of one pass over a text: the characters with their byte offsets, the index of
/// the next one, and the current line.
struct Lexer<'a> {
    text: &'a str,
    chars: &'a [(usize, char)],
    at: usize,
    line: usize,
}

impl Lexer<'_> {
    fn peek(&self, ahead: usize) -> Option<char> {
        self.chars.get(self.at + ahead).map(|&(_, c)| c)
    }

    fn offset(&self) -> usize {
        self.chars.get(self.at).map_or(self.text.len(), |&(i, _)| i)
    }

    /// Moves past one character, counting lines.
    fn bump(&mut self) {
        if self.peek(0) == Some('\n') {
            self.line += 1;
        }
        self.at += 1;
    }

    fn bump_while(&mut self, keep: impl Fn(char) -> bool) {
        while self.peek(0).is_some_and(&keep) {
            self.bump();
        }
    }

    fn next_lexeme(&mut self) -> Option<Lexeme> {
        self.bump_while(char::is_whitespace);
        let first = self.peek(0)?;
        let (start, line) = (self.offset(), self.line);
        let kind = self.lexeme_kind(first);
        Some(Lexeme {
            kind,
            start,
            end: self.offset(),
            line,
        })
    }

    /// Consumes one lexeme that starts with `first` and says what it was.
    fn lexeme_kind(&mut self, first: char) -> LexemeKind {
        let second = self.peek(1);
        match first {
            '/' if second == Some('/') => {
                self.bump_while(|c| c != '\n');
                LexemeKind::LineComment
            }
            '/' if second == Some('*') => {
                self.block_comment();
                LexemeKind::BlockComment
            }
            '"' => {
                self.bump();
                self.quoted('"');
                LexemeKind::Str
            }
            '\'' => self.quote_or_lifetime(),
            'r' if matches!(second, Some('"')) || self.raw_string_ahead(1) => {
                self.bump();
                self.raw_string();
                LexemeKind::Str
            }
            'b' | 'c' if second == Some('"') => {
                self.bump();
                self.bump();
                self.quoted('"');
                LexemeKind::Str
            }
            'b' | 'c' if second == Some('r') && self.raw_string_ahead(2) => {
                self.bump();
                self.bump();
                self.raw_string();
                LexemeKind::Str
            }
            'b' if second == Some('\'') => {
                self.bump();
                self.bump();
                self.quoted('\'');
                LexemeKind::Char
            }
            'r' if second == Some('#') && self.peek(2).is_some_and(is_ident_start) => {
                // A raw identifier, `r#type`: one identifier, as for proc-macro2.
                self.bump();
                self.bump();
                self.bump_while(is_ident_continue);
                LexemeKind::Ident
            }
            c if c.is_ascii_digit() => {
                self.number();
                LexemeKind::Number
            }
            c if is_ident_start(c) => {
                self.bump_while(is_ident_continue);
                LexemeKind::Ident
            }
            _ => {
                self.bump();
                LexemeKind::Punct
            }
        }
    }

    /// True when a raw string (`#…#"`) starts `ahead` characters from here.
    fn raw_string_ahead(&self, ahead: usize) -> bool {
        let mut i = ahead;
        while self.peek(i) == Some('#') {
            i += 1;
        }
        self.peek(i) == Some('"') && (i > ahead || self.peek(ahead) == Some('"'))
    }

    /// After the `r`: hashes, a quote, the body up to a quote followed by as many hashes.
    fn raw_string(&mut self) {
        let mut hashes = 0;
        while self.peek(0) == Some('#') {
            hashes += 1;
            self.bump();
        }
        self.bump(); // the opening quote
        while let Some(c) = self.peek(0) {
            self.bump();
            if c == '"' && (0..hashes).all(|i| self.peek(i) == Some('#')) {
                for _ in 0..hashes {
                    self.bump();
                }
                return;
            }
        }
    }

    /// After the opening quote: up to the closing `quote`, skipping escapes; an unterminated
    /// literal runs to the end of the text.
    fn quoted(&mut self, quote: char) {
        while let Some(c) = self.peek(0) {
            self.bump();
            if c == '\\' {
                self.bump();
            } else if c == quote {
                return;
            }
        }
    }

    /// `'x'`, `'\n'` and `'\u{1F600}'` are characters; `'a` (no closing quote right after
    /// one character) is a lifetime, lexed like proc-macro2 as a `'` followed by an
    /// identifier.
    fn quote_or_lifetime(&mut self) -> LexemeKind {
        match (self.peek(1), self.peek(2)) {
            (Some('\\'), _) => {
                self.bump();
                self.quoted('\'');
                LexemeKind::Char
            }
            (Some(c), Some('\'')) if c != '\n' => {
                self.bump();
                self.bump();
                self.bump();
                LexemeKind::Char
            }
            _ => {
                self.bump();
                LexemeKind::Punct
            }
        }
    }

    /// `/* … */`, nested; an unterminated comment runs to the end of the text.
    fn block_comment(&mut self) {
        self.bump();
        self.bump();
        let mut depth = 1usize;
        while let Some(c) = self.peek(0) {
            if c == '/' && self.peek(1) == Some('*') {
                depth += 1;
                self.bump();
            } else if c == '*' && self.peek(1) == Some('/') {
                depth -= 1;
                self.bump();
                if depth == 0 {
                    self.bump();
                    return;
                }
            }
            self.bump();
        }
    }

    /// Digits, `_`, letters (hex digits, exponents, suffixes) and at most one fraction dot;
    /// `1..2` and `1.max(2)` keep the dot out, `1.5` and `2.` take it, as Rust's lexer does.
    fn number(&mut self) {
        let mut seen_dot = false;
        loop {
            match self.peek(0) {
                Some(c) if c.is_ascii_alphanumeric() || c == '_' => {
                    let exponent = matches!(c, 'e' | 'E')
                        && matches!(self.peek(1), Some('+' | '-'))
                        && self.peek(2).is_some_and(|d| d.is_ascii_digit());
                    self.bump();
                    if exponent {
                        self.bump();
                    }
                }
                Some('.')
                    if !seen_dot
                        && self.peek(1) != Some('.')
                        && !self.peek(1).is_some_and(is_ident_start) =>
                {
                    seen_dot = true;
                    self.bump();
                }
                _ => return,
            }
        }
    }
}

/// Whether `c` can start an identifier (ASCII letters, `_`, and the letters of other
/// scripts: students write `θ`).
pub(crate) fn is_ident_start(c: char) -> bool {
    c == '_' || c.is_alphabetic()
}

/// Whether `c` can continue an identifier.
pub(crate) fn is_ident_continue(c: char) -> bool {
    c == '_' || c.is_alphanumeric()
}
