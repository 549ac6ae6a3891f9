//! Numerical stability: every task on stiff and extreme inputs.
//!
//! A [`Case`] is one input for one task (a grazing direction, α = 0, the critical angle
//! and 2 ulp past it in f32 and f64, a cosine that rounds above one, …) with the range the
//! result must lie in and the value or limit it must take. [`cases`] lists them all, one
//! file per task under `catalogue/`, built from the errata's "Stiff / extreme-case
//! catalogue". [`run_cases`] runs each case on a worker thread with a time limit and
//! gives a [`Verdict`]: pass, wrong value, NaN, inf, out of range, panic, not attempted
//! (`todo!()`) or hang; [`run_isolated`] runs each in a worker process instead, which also
//! survives a case that crashes its process (a stack overflow, an abort).
//!
//! The catalogue is generic over the implementation (`cases::<Student>()`, `cases::<Mixed>()`),
//! so a case calls the task functions directly, and it places no requirement on the
//! [`Tasks`](crate::worksheet::Tasks) trait beyond the functions it calls. `pbrlab
//! stability` prints the table (cases in worker processes); the grader's stability check
//! runs the same cases inside each task's worker.
//!
//! Adding a case: append it to the task's file in `catalogue/`, with the input in words,
//! an evaluation that returns a [`Value`], a range, an [`Expect`], and the guard a robust
//! implementation needs (the text a student sees when the case fails).

pub mod case;
pub mod catalogue;
pub mod expect;
pub mod inputs;
pub mod isolated;
pub mod runner;
pub mod scenes;
pub mod summary;
pub mod value;
pub mod verdict;

pub use case::Case;
pub use catalogue::{cases, cases_for};
pub use expect::{Bound, Expect};
pub use isolated::run_isolated;
pub use runner::{DEFAULT_TIMEOUT, Outcome, run_case, run_cases};
pub use value::Value;
pub use verdict::Verdict;
