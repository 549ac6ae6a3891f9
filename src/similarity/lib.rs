//! # Similarity of student submissions, per task, on normalised Rust tokens
//!
//! `pbrlab similarity` looks for copied code in a class's exercise files without sending
//! them anywhere (it replaces MOSS). Each task is compared on its own, because every file of
//! a task answers the same question; then the pairs are ranked over all tasks, because
//! copying is usually of many files.
//!
//! ## The pipeline
//! 1. **Tokens** (`tokens.rs`): `proc-macro2` lexes each file (the fallback lexer,
//!    `lexer.rs`, reads what does not lex). Comments, doc comments and whitespace are gone.
//! 2. **Normalisation** (`normalise.rs`): literals become their kind, names a student chooses
//!    become placeholders numbered within each k-gram (renaming does not change the
//!    stream), keywords and punctuation stay. By default the names a renaming cannot change
//!    (methods and fields after `.`, `::` paths, macros, CamelCase types, primitive types)
//!    stay too.
//! 3. **Fingerprints** (`winnow.rs`): robust winnowing of the k-gram hashes, each kept hash
//!    with the lines it covers.
//! 4. **Exclusions** (`compare.rs`): every k-gram of the `exclude` texts (the task's stub, and
//!    the reference if the caller passes it), and every fingerprint found in more files of
//!    the task than [`Options::common_share`] of the class allows (MOSS's `-m`).
//! 5. **Scores**: per pair, `shared / min(|A|, |B|)` of the fingerprints left, with the
//!    matched regions (`regions.rs`); over all tasks, [`rank()`] sums both parts.
//! 6. **Report** ([`html()`]): one self-contained page.
//!
//! ## Conventions
//! Lines are 1-based and inclusive, as an editor shows them. A pair is always ordered by
//! student name (`a < b`). Scores are fractions in `[0, 1]`. Fingerprint counts are of
//! *distinct* fingerprints (a line repeated ten times is one piece of evidence).
//!
//! ## The defaults, and how they were chosen
//! Measured on a generated class (`tests/instructor/similarity/`): the reference solutions
//! and two or three independent implementations per task in other styles, and planted
//! copies of each, renamed, reformatted, reordered, recommented, all of these at once, and
//! all at once with a brace deleted (read by the fallback lexer), over a sweep of k 8 to
//! 20, window 2 to 8 and each normalisation.
//! - **k = 12 tokens.** Shorter k-grams match between independent solutions (k = 8: an
//!   independent pair of one task reaches 0.52 without the common-code filter); longer ones
//!   are broken by reordering and swapped branches (k = 20: 88–95 % of copied long tasks
//!   found, against 100 % at k = 12).
//! - **Window 4.** Scores hardly depend on it (2 to 8); 4 keeps at least 19 shared
//!   fingerprints on the smallest copied long task, so the count threshold has room, and
//!   guarantees every shared run of 15 tokens (about two lines) is seen.
//! - **Names kept, locals numbered.** Keeping the names a renaming cannot change lowers
//!   independent scores (mean 0.21 against 0.22–0.23, highest 0.41 against 0.45, without
//!   the common-code filter) and leaves copies' scores as they were; numbering locals within
//!   a k-gram instead of one placeholder changes little either way and is kept because it
//!   can only separate more.
//! - **Thresholds.** A task is flagged at a score of 0.45 with at least 10 shared
//!   fingerprints: copies of long tasks score at least 0.48 (0.59 without the common-code
//!   filter), independent pairs at most 0.28 (0.41). Ten fingerprints are about three lines
//!   of code: the one-line `reflect` is counted but not judged. Over all tasks a pair is
//!   flagged at 0.4 with at least 40: whole copied submissions score at least 0.65 (0.71),
//!   independent ones at most 0.15 (0.27).
//! - **Common code**: a fingerprint in more than half of a task's files is dropped. The
//!   measured class is small (five files per task), so this share could not be calibrated;
//!   the results above hold with the filter off as well.

mod compare;
mod html;
pub mod lexer;
mod normalise;
mod rank;
mod regions;
mod tokens;
mod winnow;

#[cfg(test)]
mod tests;

pub use compare::compare_task;
pub use html::html;
pub use normalise::Normalisation;
pub use rank::rank;

use serde::Serialize;
use std::collections::BTreeMap;

/// One file of one student: the text of `exercises/<task>.rs` in their submission.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Source {
    /// The student's name or id, as it appears in the report (unique within a task).
    pub student: String,
    /// The file's text, as submitted (it need not compile, or even lex).
    pub text: String,
}

/// The comparison's parameters. [`Options::default`] holds the measured defaults.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Options {
    /// Tokens per k-gram: no match shorter than this counts.
    pub k: usize,
    /// The winnowing window, in k-grams: every shared run of at least `k + window − 1`
    /// tokens is found.
    pub window: usize,
    /// How identifiers are abstracted.
    pub normalisation: Normalisation,
    /// A fingerprint found in more than this share of the task's files is common code and
    /// not evidence (at least 2 files may always share one, so a pair of copies survives in
    /// any class size).
    pub common_share: f64,
    /// Optionally also an absolute limit, as MOSS's `-m`: a fingerprint in more than this
    /// many of the task's files is common code. The smaller of the two limits applies.
    pub common_max_files: Option<usize>,
    /// A task's pair is flagged when its score reaches this …
    pub min_score: f64,
    /// … and it shares at least this many fingerprints (short tasks cannot be judged
    /// alone: they are counted in the aggregate but not flagged).
    pub min_shared: usize,
    /// A pair is flagged over all tasks when its aggregate score reaches this …
    pub aggregate_min_score: f64,
    /// … and it shares at least this many fingerprints over all tasks.
    pub aggregate_min_shared: usize,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            k: 12,
            window: 4,
            normalisation: Normalisation {
                keep_names: true,
                number_locals: true,
            },
            common_share: 0.5,
            common_max_files: None,
            min_score: 0.45,
            min_shared: 10,
            aggregate_min_score: 0.4,
            aggregate_min_shared: 40,
        }
    }
}

/// The comparison of every pair of files of one task.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TaskComparison {
    /// The task, as the caller named it.
    pub task: String,
    /// Every pair that shares at least one fingerprint, by score (highest first).
    pub pairs: Vec<PairScore>,
    /// Distinct fingerprints per student after the exclusions: the denominators of the
    /// scores. Every student with a file for the task is here, with 0 for a file that is
    /// (still) the stub.
    pub fingerprints: BTreeMap<String, usize>,
    /// A fingerprint in more files than this was dropped as common code.
    pub common_limit: usize,
    /// How many distinct fingerprints were dropped as common code.
    pub common_fingerprints: usize,
    /// Students whose file `proc-macro2` could not lex (read by the fallback lexer instead;
    /// the file does not compile).
    pub fallback_lexed: Vec<String>,
}

/// Two students' files of one task.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PairScore {
    /// The first student (by name).
    pub a: String,
    /// The second student.
    pub b: String,
    /// Distinct fingerprints both files have, after the exclusions.
    pub shared: usize,
    /// `shared / min(|A|, |B|)`, in `[0, 1]`.
    pub score: f64,
    /// Whether the score and the shared count both reach the task thresholds.
    pub flagged: bool,
    /// The matched regions, sorted by A's lines.
    pub regions: Vec<Region>,
}

/// A region of A that matches a region of B.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize)]
pub struct Region {
    /// First and last line in A's file, 1-based, inclusive.
    pub a_lines: (usize, usize),
    /// First and last line in B's file, 1-based, inclusive.
    pub b_lines: (usize, usize),
}

/// One pair of students over all tasks.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PairSummary {
    /// The first student (by name).
    pub a: String,
    /// The second student.
    pub b: String,
    /// Shared fingerprints, summed over the tasks.
    pub shared: usize,
    /// `min(|A|, |B|)` summed over the tasks both have a file for: the denominator.
    pub compared: usize,
    /// `shared / compared`, in `[0, 1]`.
    pub score: f64,
    /// Whether the aggregate score and shared count both reach the aggregate thresholds.
    pub flagged: bool,
    /// How many of the pair's tasks are flagged on their own.
    pub flagged_tasks: usize,
    /// The tasks in which the pair shares fingerprints, in the order the tasks were given.
    pub tasks: Vec<TaskScore>,
}

/// One task's part of a [`PairSummary`].
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TaskScore {
    /// The task.
    pub task: String,
    /// As [`PairScore::shared`].
    pub shared: usize,
    /// As [`PairScore::score`].
    pub score: f64,
    /// As [`PairScore::flagged`].
    pub flagged: bool,
}
