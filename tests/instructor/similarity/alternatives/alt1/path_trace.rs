use crate::prelude::*;

pub fn path_trace(
    t: &impl Tasks,
    scene: &Scene,
    segment: &Segment,
    depth: i32,
    sampler: &mut Sampler,
) -> Vec3 {
    if depth < 1 {
        return Vec3::ZERO;
    }
    let hit = match &segment.hit {
        Some(h) => h,
        None => {
            // escaped: only camera rays pick up the environment here
            if !segment.emission_counted {
                return scene.environment(segment.ray.dir);
            }
            return Vec3::ZERO;
        }
    };
    let wo = -segment.ray.dir;
    let mut l = Vec3::ZERO;
    if !segment.emission_counted {
        l += scene.emitted(hit, wo);
    }
    if depth == 1 {
        return l;
    }
    let nee = t.mis(scene, hit, wo, scene.heuristic(), sampler);
    l += nee.radiance;
    match nee.bounce {
        None => l,
        Some(b) => {
            let mut throughput = b.weight;
            if scene.settings().roulette_applies(depth) {
                let p = throughput.max_element().min(0.95);
                if !(p > 0.0) {
                    return l;
                }
                if sampler.next_1d() >= p {
                    return l;
                }
                throughput = throughput / p;
            }
            l + throughput * t.path_trace(scene, &b.segment, depth - 1, sampler)
        }
    }
}
