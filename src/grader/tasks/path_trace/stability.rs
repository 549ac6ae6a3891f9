//! Stability cases of the `path_trace` task: depth 0 and depth 1.

use crate::integrator::Segment;
use crate::sampling::Sampler;
use crate::stability::case::{Case, NON_NEGATIVE};
use crate::grade::tolerance::Tolerance;
use crate::stability::expect::Expect;
use crate::stability::scenes::{self, FURNACE};
use crate::worksheet::{TaskId, Tasks};
use glam::Vec3;

/// The camera segment from (0, 0, 5) along `dir` in the furnace, traced.
fn camera_segment(scene: &crate::scene::Scene, dir: Vec3) -> Segment {
    let ray = crate::geometry::Ray::new(Vec3::new(0.0, 0.0, 5.0), dir.normalize());
    Segment {
        ray,
        hit: scene.intersect(&ray),
        emission_counted: false,
    }
}

/// The cases.
pub fn cases<T: Tasks>() -> Vec<Case<T>> {
    vec![
        Case {
            task: TaskId::PathTrace,
            name: "path_trace/depth_zero",
            input: "furnace, a camera ray hitting the sphere, depth 0",
            eval: |t| {
                let scene = scenes::load(FURNACE);
                let segment = camera_segment(&scene, -Vec3::Z);
                t.path_trace(&scene, &segment, 0, &mut Sampler::new(1, 0))
                    .into()
            },
            range: NON_NEGATIVE,
            expect: Expect::vector([0.0; 3], Tolerance::abs(0.0)),
            guard: "return 0 when depth ≤ 0 before anything else: a path started at depth 0 \
                    must not recurse without end",
        },
        Case {
            task: TaskId::PathTrace,
            name: "path_trace/depth_one_environment",
            input: "furnace, a camera ray missing the sphere, depth 1",
            eval: |t| {
                let scene = scenes::load(FURNACE);
                let segment = camera_segment(&scene, Vec3::new(0.5, 0.0, -1.0));
                t.path_trace(&scene, &segment, 1, &mut Sampler::new(1, 0))
                    .into()
            },
            range: NON_NEGATIVE,
            expect: Expect::vector([1.0; 3], Tolerance::abs(1e-6)),
            guard: "depth 1 is the light seen directly: here the environment, radiance 1",
        },
        Case {
            task: TaskId::PathTrace,
            name: "path_trace/depth_one_surface",
            input: "furnace, a camera ray hitting the (non-emitting) sphere, depth 1",
            eval: |t| {
                let scene = scenes::load(FURNACE);
                let segment = camera_segment(&scene, -Vec3::Z);
                t.path_trace(&scene, &segment, 1, &mut Sampler::new(1, 0))
                    .into()
            },
            range: NON_NEGATIVE,
            expect: Expect::vector([0.0; 3], Tolerance::abs(0.0)),
            guard: "depth 1 adds no direct light and no bounce: only emission, and the sphere \
                    emits nothing",
        },
    ]
}
