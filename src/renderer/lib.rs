//! # pbrlab-renderer
//!
//! The bottom layer of pbrlab: the task API and the renderer that calls it.
//!
//! - [`worksheet`]: the task table: every task's id, points and hints, and the [`Tasks`]
//!   trait and [`TaskFns`](worksheet::TaskFns) table that list every task function once.
//!   Conventions are stated there (directions point away from the surface; in the local
//!   frame the normal is +z).
//! - [`math`], [`sampling`], [`optics`], [`bsdf`]: framework pieces that are not tasks.
//! - The renderer: [`scene`] (YAML scenes, validation, what a scene needs, and the
//!   framework API integrators call), [`geometry`] (shapes, BVHs), [`light`], [`medium`],
//!   [`integrator`] (the path tracer built on the `path_trace` and `mis` tasks, and the
//!   volumetric path tracer built on `delta_tracking`) and [`render`] (tiles, threads,
//!   film, image files).
//! - [`compiled_reference`]: the reference as shared libraries, for the student handout's
//!   mixed renders and for the grader's workers.
//!
//! The task API and the renderer are one crate because the tasks' parameters are the
//! renderer's types: `path_trace` and `mis` take a [`Scene`](scene::Scene) and trace rays
//! through it, `delta_tracking` samples a [`Medium`](medium::Medium). The student's crate
//! (`exercises/`) and the reference's (`solutions/`) depend on this crate only; the grader
//! (package `pbrlab`, `src/grader/`) sits above it. The student's crate re-exports the modules a
//! task may use, and not the framework's integrators, so a student cannot forward a task to
//! them. See `src/ARCHITECTURE.md`.
//!
//! [`Tasks`]: worksheet::Tasks

pub mod bsdf;
pub mod compiled_reference;
pub mod geometry;
pub mod integrator;
pub mod light;
pub mod math;
pub mod medium;
pub mod optics;
pub mod render;
pub mod sampling;
pub mod scene;
pub mod worksheet;

pub use pbrlab_course::{atomic_file, task_set};

/// What a task file needs in scope: vectors, π, the task trait, the parameter types.
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
    pub use std::f32::consts::PI;
}
