//! Integrators: the radiance along a camera ray. Scenes without media use the path tracer
//! the student writes (the `path_trace` task, which calls the `mis` task); scenes with media
//! use the framework's volumetric path tracer ([`volpath`]), which samples free flights
//! with the `delta_tracking` task.
//!
//! Both are generic over the task implementation `T: Tasks` (static dispatch).

mod heuristic;
mod segment;
pub mod volpath;

pub use heuristic::{Heuristic, MisHeuristic};
pub use segment::{Bounce, DirectLight, Segment};

use crate::geometry::Ray;
use crate::sampling::Sampler;
use crate::scene::Scene;
use crate::worksheet::Tasks;
use glam::Vec3;

/// An estimate of the radiance arriving at the camera along `ray` (towards its origin).
#[inline]
pub fn radiance<T: Tasks>(t: &T, scene: &Scene, ray: Ray, sampler: &mut Sampler) -> Vec3 {
    if scene.needs().media > 0 {
        volpath::radiance(t, scene, ray, sampler)
    } else {
        let segment = Segment {
            ray,
            hit: scene.intersect(&ray),
            emission_counted: false,
        };
        t.path_trace(scene, &segment, scene.settings().max_depth, sampler)
    }
}
