//! The student's exercises: one file per task, each a stub to fill in.
//!
//! This crate is yours to edit file by file (`exercises/<task>.rs`); this file, the
//! manifest and the build script belong to the framework, and the grader uses its own copy
//! of them. The crate depends on the framework's task API only: it cannot name the
//! reference solutions or the grader's expected data, and it may not use `unsafe`.
#![forbid(unsafe_code)]
#![allow(unused_variables)]
// A student's own helper functions need no doc comments.
#![allow(missing_docs)]

/// What a task file needs in scope: vectors, the task trait, the parameter types.
pub mod prelude {
    pub use pbrlab_renderer::prelude::*;
}

/// The framework helpers a task may use, under the paths the exercise texts give
/// (`crate::bsdf::projected_alpha`, `crate::optics::schlick_weight`, …).
pub use pbrlab_renderer::{
    bsdf, geometry, light, math, medium, optics, sampling, scene, worksheet,
};

/// The integrator types the tasks exchange. Not the framework's integrators themselves:
/// its volumetric path tracer would compute `path_trace`'s answer for a student who
/// forwarded to it.
pub mod integrator {
    pub use pbrlab_renderer::integrator::{Bounce, DirectLight, Heuristic, Segment};
}

/// The crate's task modules under the name they had when `exercises/` was a module of the
/// framework (`crate::exercises::reflect::reflect`).
pub use crate as exercises;

// The task modules, `pub mod reflect;` and so on, one per file: written by the build script,
// which compiles them from this folder (or, for the grader, from a submission's copy, with
// the shipped stub standing in for a file that does not compile).
include!(concat!(env!("OUT_DIR"), "/tasks.rs"));

/// The student's code as the framework calls it.
pub static TASKS: worksheet::TaskFns = pbrlab_renderer::task_table!();
