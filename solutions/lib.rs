//! The reference solutions: one file per task, mirroring `exercises/`.
//!
//! Its own crate, which the student's crate (`exercises/`) does not depend on and so cannot
//! name. The instructor binaries and tests link it; the student handout leaves it out.
#![forbid(unsafe_code)]

/// What a task file needs in scope: vectors, the task trait, the parameter types.
pub mod prelude {
    pub use pbrlab_renderer::prelude::*;
}

pub use pbrlab_renderer::{
    bsdf, geometry, integrator, light, math, medium, optics, sampling, scene, worksheet,
};

pub mod aniso_ndf;
pub mod beckmann_ndf;
pub mod brdf_check;
pub mod cook_torrance;
pub mod cosine_sample;
pub mod delta_tracking;
pub mod fresnel_schlick;
pub mod kajiya_kay;
pub mod mis;
pub mod ndf_sample;
pub mod path_trace;
pub mod phong;
pub mod reflect;
pub mod refract_stack;
pub mod smith_g1;

/// The reference as the framework calls it.
pub static TASKS: worksheet::TaskFns = pbrlab_renderer::task_table!();

pbrlab_renderer::direct_tasks!();
