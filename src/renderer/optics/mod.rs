//! Geometric optics that the framework provides: the exact dielectric and conductor Fresnel
//! equations and
//! the plane-parallel layer stack that the `refract_stack` task describes.

mod fresnel;
mod layer_stack;

pub use fresnel::{fresnel_conductor, fresnel_dielectric, fresnel_dielectric_f64, schlick_weight};
pub use layer_stack::{LayerStack, Slab, StackReport};
