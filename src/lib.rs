//! # pbrlab
//!
//! A course-grading harness for physically based rendering. The worksheet's tasks are
//! functions a student writes (`exercises/`), with a reference (`solutions/`); a renderer
//! calls them, so a student's code renders real pictures; and a grader scores them.
//!
//! ## Architecture
//! - [`worksheet`]: the task table: every task's id, points, hints, and the [`Tasks`]
//!   trait that lists every task function once. Conventions are stated there.
//! - [`implementation`]: `Student` (exercises/), `Reference` (solutions/) and `Mixed`.
//! - [`math`], [`sampling`], [`optics`], [`bsdf`]: framework pieces that are not tasks.
//! - The renderer: [`scene`] (YAML scenes, validation, what a scene needs, and the
//!   framework API integrators call), [`geometry`] (shapes, BVHs), [`light`], [`medium`],
//!   [`integrator`] (the path tracer built on the `path_trace` and `mis` tasks, and the
//!   volumetric path tracer built on `delta_tracking`) and [`render`] (tiles, threads,
//!   film, image files).
//! - [`grade`]: the grader.
//! - [`handout`]: the student repository without the solutions.
//!
//! [`Tasks`]: worksheet::Tasks

pub mod bsdf;
pub mod cli;
pub mod converge;
pub mod geometry;
pub mod grade;
pub mod handout;
pub mod implementation;
pub mod integrator;
pub mod light;
pub mod math;
pub mod medium;
pub mod optics;
pub mod panics;
pub mod render;
pub mod sampling;
pub mod scene;
pub mod stability;
pub mod task_set;
pub mod worksheet;

/// The student's exercises: one file per task, each a stub to fill in.
#[allow(unused_variables)]
#[path = "../exercises/mod.rs"]
pub mod exercises;

/// The reference solutions: one file per task, mirroring `exercises/`.
#[cfg(feature = "solutions")]
#[path = "../solutions/mod.rs"]
pub mod solutions;

/// What a task file needs in scope: vectors, the task trait, the parameter types.
pub mod prelude {
    pub use crate::bsdf::{Bsdf, BsdfSample, KajiyaKayParams, PhongParams, PlausibilityReport};
    pub use crate::geometry::{Hit, Ray};
    pub use crate::integrator::{Bounce, DirectLight, Heuristic, Segment};
    pub use crate::light::LightSample;
    pub use crate::medium::{Coefficients, FreeFlight, Medium};
    pub use crate::optics::{LayerStack, Slab, StackReport};
    pub use crate::sampling::Sampler;
    pub use crate::scene::Scene;
    pub use crate::worksheet::Tasks;
    pub use glam::{Vec2, Vec3};
}
