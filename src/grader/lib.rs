//! # pbrlab
//!
//! A course-grading harness for physically based rendering. The worksheet's tasks are
//! functions a student writes (`exercises/`), with a reference (`solutions/`); a renderer
//! calls them, so a student's code renders real pictures; and a grader scores them.
//!
//! ## Layers
//! This crate (`src/grader/`, package `pbrlab`) is the grader and the commands' library. It builds
//! on the task API and the renderer, the crate `pbrlab-renderer` (`src/renderer/`), whose
//! modules it re-exports under the same paths ([`worksheet`], [`scene`], [`render`], …).
//! Its own modules:
//! - [`implementation`]: the task tables a binary links: the student's (the crate in
//!   `exercises/`) and the reference's (the crate in `solutions/`), and mixes of the two.
//! - [`tasks`]: one folder per task, with everything the framework knows about it: its
//!   graded cases, stability cases and the tests' variants.
//! - [`grade`]: the grader; [`stability`]: stiff and extreme inputs; [`converge`]: error
//!   against run time.
//! - [`autograder`]: packages for Gradescope and PrairieLearn, and a whole class at once.
//! - [`handout`]: the student repository without the solutions.
//! - [`cli`]: the command line, one file per subcommand, run by the `pbrlab` binary (and,
//!   for a render or study of student code, by the worker binary).
//!
//! `src/ARCHITECTURE.md` maps the flows, the crates and every file a task touches.
//!
//! ## Crates, and the boundary around student code
//! The student's code is its own small crate (`exercises/`, `pbrlab-exercises`) and the
//! reference another (`solutions/`, `pbrlab-solutions`); each depends on `pbrlab-renderer`
//! only and exports a
//! [`TaskFns`](worksheet::TaskFns) table built by [`task_table!`]. The root package
//! (`pbrlab-cli`) links the reference into the `pbrlab` binary, and the worker package
//! (`src/worker/`) the student's crate into `pbrlab-worker` and `pbrlab-student`, the
//! only binaries that link it;
//! each [`install`](implementation::install)s its tables. The framework is compiled once,
//! for `TaskFns`, never for a student's type, so an exercise edit recompiles the exercise
//! crate and the worker's link, and a compile error in it never stops `pbrlab` itself.
//!
//! Decision, measured on two cores (same session): the student's code is linked
//! statically and called through function pointers, not loaded at run time. A one-line
//! exercise edit rebuilds in 1.1 s (88 s when exercises/ was a module of this crate), and
//! `pbrlab grade TASK` after an edit takes 1.2–1.3 s including the rebuild
//! (`tools/bench_edit_regrade.sh`); reference throughput on the Cornell box is 1.02× that of
//! the generic build (indirect calls cost nothing measurable beside the ray casting). A
//! `dylib`/`libloading` boundary would save the link (well under a second) at the price of
//! `unsafe` loading, duplicated statics and a second copy of this crate in the library.
//!
//! The student's crate can name only what its `lib.rs` re-exports (the task API) and not
//! the reference (not a dependency); its build script runs the check of
//! `src/exercise-check/` on every task file, which refuses with file:line, and fails
//! closed on, every construct that reaches outside the crate at compile time (`#[path]`,
//! `mod x;`, `include*!`, `env!`, `extern crate`, `pbrlab*` crate names, and their
//! assembly through macros), and `lib.rs` forbids `unsafe`. At run time the student's code runs only in processes that entered
//! [`grade::sandbox`] first: the grader's workers (probes included) and `render`/`converge`
//! of student code.
//!
//! The workers are a binary of their own, `pbrlab-worker` (`src/worker/main.rs`): it links
//! the task tables and the renderer but never calls the grader's judging code, so the linker
//! drops the embedded expected data and reference renders from it (a test searches the file
//! for every stored file's bytes). A worker gets inputs (calls, sampler setups, seeds, a
//! scene name) and sends back raw outputs only ([`grade::wire::Raw`]: values, binned
//! samples, estimates, variances, stability values, a render's mean and variance); the
//! grader, which never runs student code, keeps the list of checks and every expected value
//! and judges them, so an output left out fails its check and nothing a worker prints can
//! pass one.
//!
//! [`Tasks`]: worksheet::Tasks
//! [`task_table!`]: crate::task_table

pub mod autograder;
pub mod cli;
pub mod converge;
pub mod entropy;
pub mod grade;
pub mod handout;
pub mod implementation;
pub mod panics;
pub mod stability;
pub mod tasks;

pub use pbrlab_course::{html_escape, repository_root, timestamp};
pub use pbrlab_renderer::{
    atomic_file, bsdf, compiled_reference, for_each_task_function, geometry, integrator, light,
    math, medium, optics, prelude, reference_library, render, sampling, scene, task_set,
    task_table, worksheet,
};
pub use pbrlab_similarity as similarity;
