//! Random numbers and the framework's own warps (the ones that are not worksheet tasks).

mod sampler;
mod warp;

pub use sampler::Sampler;
pub use warp::{uniform_hemisphere, uniform_hemisphere_pdf, uniform_sphere, uniform_sphere_pdf};
