//! The grader: checks that score a [`crate::worksheet::Tasks`] implementation task by task.
//!
//! # Check kinds (one file each)
//! - [`values`]: fixed and random cases against the reference's stored outputs, compared
//!   with an absolute + relative [`tolerance`]; NaN never passes.
//! - [`sampling`]: Pearson χ² of a student's direction sampler against the reference
//!   density over cells of equal solid angle ([`stats`] holds the tests).
//! - [`estimator`]: Student's t-test of an estimator against an analytic value;
//!   [`variance_pair`] and [`variance_check`]: two estimators' variances against a bound.
//! - [`image_check`]: per-pixel z-test of a render ([`renders`]) against the stored
//!   reference render ([`render_check`]).
//! - [`stability`]: extreme inputs must give finite values in range.
//!
//! [`power`] measures how large an error the statistical kinds catch, and
//! [`calibration`] how often they fail correct code.
//!
//! # Data
//! [`catalogue`] holds what each task's folder declares (its [`domain`], cases, samplers,
//! estimators); [`value_cases`] draws the value cases from the domains, with a bias toward
//! their boundaries and special points, and evaluates them on the reference; [`expected`]
//! stores the reference's answers (insta snapshots embedded at build time), so the handout
//! grades without solutions. [`checks`] judges and scores a task's checks.
//!
//! # Two sides
//! Student code runs only in a worker process: [`worker`] (the child side, in [`sandbox`])
//! runs a task's checks through [`measure`] and sends back raw outputs, never a verdict;
//! what crosses is [`wire`]. [`runner`] grades each task in its own worker ([`isolation`]
//! is the parent side) and judges the outputs against the expected data, which no
//! worker-side file can import (`src/ARCHITECTURE.md` tags each file with its side, and a
//! test holds it): a panic, an endless loop, a stack overflow, an abort, a runaway
//! allocation or an early `exit` in student code costs that task and nothing else.

pub mod argument;
pub mod build_view;
pub mod calibration;
pub mod call;
pub mod case;
pub mod case_input;
pub mod catalogue;
pub mod checks;
pub mod contract;
pub mod credit;
pub mod declared;
pub mod domain;
pub mod estimator;
pub mod expected;
pub mod feedback;
pub mod history;
pub mod image_check;
pub mod isolation;
pub mod jitter;
pub mod lenient_f64;
pub mod measure;
pub mod output;
pub mod power;
pub mod probe;
pub mod references;
pub mod render_check;
pub mod renders;
pub mod report;
pub mod rounding;
pub mod runner;
pub mod sampling;
pub mod sandbox;
pub mod scene_gate;
pub mod shrink;
pub mod stability;
pub mod stats;
pub mod student_build;
pub mod test_brdf;
pub mod tolerance;
pub mod value_cases;
pub mod values;
pub mod variance_check;
pub mod variance_pair;
pub mod variant;
pub mod verdict;
pub mod wire;
pub mod worker;
