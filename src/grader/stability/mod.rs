//! Numerical stability: every task on stiff and extreme inputs.
//!
//! A [`Case`] is one input for one task (a grazing direction, α = 0, the critical angle
//! and 2 ulp past it in f32 and f64, a cosine that rounds above one, …) with the range the
//! result must lie in and the value or limit it must take. [`cases`] lists them all, one
//! file per task (`src/grader/tasks/<task>/stability.rs`), built from the errata's "Stiff / extreme-case
//! catalogue". Stability is a check kind of the grader: a case runs in a worker process
//! ([`Case::run`]), which sends back what the task returned, and the parent judges it
//! ([`outcome::judge_output`]) into a [`Verdict`]: pass, wrong value, NaN, inf, out of
//! range, panic, not attempted (`todo!()`), hang or crash (a stack overflow, an abort).
//! The grader's check ([`crate::grade::stability`]) runs a task's cases in its grading
//! job; `pbrlab stability` ([`run_isolated`]) each in a worker of its own, and prints the
//! table.
//!
//! The catalogue is generic over the implementation (`cases::<Student>()`, `cases::<Mixed>()`),
//! so a case calls the task functions directly, and it places no requirement on the
//! [`Tasks`](crate::worksheet::Tasks) trait beyond the functions it calls.
//!
//! Adding a case: append it to the task's `src/grader/tasks/<task>/stability.rs`, with the input in words,
//! an evaluation that returns a [`Value`], a range, an [`Expect`], and the guard a robust
//! implementation needs (the text a student sees when the case fails).

pub mod case;
pub mod catalogue;
pub mod expect;
pub mod inputs;
pub mod isolated;
pub mod outcome;
pub mod scenes;
pub mod summary;
pub mod value;
pub mod verdict;

pub use case::Case;
pub use catalogue::{cases, cases_for};
pub use expect::{Bound, Expect};
pub use isolated::run_isolated;
pub use outcome::{DEFAULT_TIMEOUT, Outcome};
pub use value::Value;
pub use verdict::Verdict;
