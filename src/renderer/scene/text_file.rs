//! Reading whitespace-separated numbers from the small text files a scene can refer to
//! (density grids, hair strands), with line and column for every error.

use super::error::SceneError;
use std::path::Path;

/// One number of a text file and where it stands.
#[derive(Clone, Copy, Debug)]
pub struct Token<'a> {
    /// The text of the number.
    pub text: &'a str,
    /// 1-based line.
    pub line: u64,
    /// 1-based column.
    pub column: u64,
}

/// The lines of `source`, each split into tokens; `#` starts a comment. Blank lines are
/// kept (as empty vectors), since strand files use them as separators.
pub fn tokenize(source: &str) -> Vec<Vec<Token<'_>>> {
    source
        .lines()
        .enumerate()
        .map(|(i, line)| {
            let content = line.split('#').next().unwrap_or("");
            let mut tokens = Vec::new();
            let mut offset = 0;
            for part in content.split_whitespace() {
                let at = content[offset..].find(part).map_or(offset, |p| p + offset);
                offset = at + part.len();
                tokens.push(Token {
                    text: part,
                    line: i as u64 + 1,
                    column: content[..at].chars().count() as u64 + 1,
                });
            }
            tokens
        })
        .collect()
}

/// Reads a text file, naming it on failure.
pub fn read(path: &Path, what: &str) -> Result<String, SceneError> {
    std::fs::read_to_string(path)
        .map_err(|e| SceneError::file(path, format!("cannot read the {what}: {e}")))
}

/// A finite f32 from a token, or an error at its position.
pub fn number(path: &Path, source: &str, token: &Token<'_>) -> Result<f32, SceneError> {
    match token.text.parse::<f32>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(SceneError::at(
            path,
            source,
            token.line,
            token.column,
            format!("expected a finite number, found `{}`", token.text),
        )),
    }
}
