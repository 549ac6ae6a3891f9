//! Task `path_trace`: reference solution.

use crate::prelude::*;

/// The radiance arriving along `segment`, by one random path.
pub fn path_trace(
    t: &impl Tasks,
    scene: &Scene,
    segment: &Segment,
    depth: i32,
    sampler: &mut Sampler,
) -> Vec3 {
    if depth <= 0 {
        return Vec3::ZERO;
    }
    let Some(hit) = &segment.hit else {
        return if segment.emission_counted {
            Vec3::ZERO
        } else {
            scene.environment(segment.ray.dir)
        };
    };
    let wo = -segment.ray.dir;
    let mut radiance = if segment.emission_counted {
        Vec3::ZERO
    } else {
        scene.emitted(hit, wo)
    };
    if depth == 1 {
        return radiance;
    }
    let direct = t.mis(scene, hit, wo, scene.heuristic(), sampler);
    radiance += direct.radiance;
    let Some(bounce) = direct.bounce else {
        return radiance;
    };
    // A continuation with one segment left could only add light that mis counted already.
    if depth == 2 {
        return radiance;
    }
    let mut weight = bounce.weight;
    if scene.settings().roulette_applies(depth) {
        let q = weight.max_element().min(0.95);
        if (q.is_nan() || q <= 0.0) || sampler.next_1d() >= q {
            return radiance;
        }
        weight /= q;
    }
    radiance + weight * t.path_trace(scene, &bounce.segment, depth - 1, sampler)
}
