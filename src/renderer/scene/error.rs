use std::fmt;
use std::path::{Path, PathBuf};

/// Where in a file a problem is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Position {
    /// A 1-based line and column of a text file (YAML scenes, grid and hair files).
    LineColumn {
        /// Line, from 1.
        line: u64,
        /// Column, from 1.
        column: u64,
    },
    /// A 1-based face number of an OBJ model (in the order of the file's `f` lines).
    Face {
        /// The OBJ object or group name, when it has one.
        object: String,
        /// Face, from 1.
        face: usize,
    },
    /// The file as a whole (it is missing, empty or unreadable).
    File,
}

/// A problem with a scene or a file it refers to: names the file and where in it, says
/// what is wrong, and quotes the offending line when it can.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SceneError {
    /// The file at fault.
    pub file: PathBuf,
    /// Where in the file.
    pub position: Position,
    /// What is wrong.
    pub message: String,
    /// The source line with a caret under the column, when known.
    pub excerpt: Option<String>,
}

/// A problem that does not stop loading (an albedo above 1, skipped degenerate triangles);
/// shaped like an error.
pub type SceneWarning = SceneError;

impl SceneError {
    /// An error at a line and column of `file`, quoting the line from `source`.
    pub fn at(
        file: &Path,
        source: &str,
        line: u64,
        column: u64,
        message: impl Into<String>,
    ) -> Self {
        Self {
            file: file.to_path_buf(),
            position: Position::LineColumn { line, column },
            message: message.into(),
            excerpt: excerpt(source, line, column),
        }
    }

    /// An error about a whole file.
    pub fn file(file: &Path, message: impl Into<String>) -> Self {
        Self {
            file: file.to_path_buf(),
            position: Position::File,
            message: message.into(),
            excerpt: None,
        }
    }

    /// An error about one face of an OBJ model.
    pub fn face(file: &Path, object: &str, face: usize, message: impl Into<String>) -> Self {
        Self {
            file: file.to_path_buf(),
            position: Position::Face {
                object: object.to_string(),
                face,
            },
            message: message.into(),
            excerpt: None,
        }
    }
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let file = self.file.display();
        match &self.position {
            Position::LineColumn { line, column } => {
                write!(f, "{file}:{line}:{column}: {}", self.message)?
            }
            Position::Face { object, face } if object.is_empty() => {
                write!(f, "{file}: face {face}: {}", self.message)?
            }
            Position::Face { object, face } => write!(
                f,
                "{file}: object `{object}`, face {face}: {}",
                self.message
            )?,
            Position::File => write!(f, "{file}: {}", self.message)?,
        }
        if let Some(excerpt) = &self.excerpt {
            write!(f, "\n{excerpt}")?;
        }
        Ok(())
    }
}

impl std::error::Error for SceneError {}

/// The line `line` of `source` with a caret under `column` (both 1-based).
fn excerpt(source: &str, line: u64, column: u64) -> Option<String> {
    let text = source
        .lines()
        .nth(usize::try_from(line).ok()?.checked_sub(1)?)?;
    let number = line.to_string();
    let pad = " ".repeat(number.len());
    let column = usize::try_from(column.saturating_sub(1)).ok()?;
    // A long line is shown as a window around the column (a 1 MB key printed whole buries
    // the message).
    let length = text.chars().count();
    let start = if length > MAX_EXCERPT {
        column.saturating_sub(MAX_EXCERPT / 2)
    } else {
        0
    };
    let mut shown: String = text.chars().skip(start).take(MAX_EXCERPT).collect();
    let mut caret_pad: String = text
        .chars()
        .skip(start)
        .take(column - start)
        .map(|c| if c == '\t' { '\t' } else { ' ' })
        .collect();
    if start > 0 {
        shown.insert(0, '…');
        caret_pad.insert(0, ' ');
    }
    if start + MAX_EXCERPT < length {
        shown.push('…');
    }
    Some(format!("{pad} |\n{number} | {shown}\n{pad} | {caret_pad}^"))
}

/// The most characters of a line an excerpt shows.
const MAX_EXCERPT: usize = 100;
