use crate::prelude::*;

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
    let wo = -segment.ray.dir;
    let Some(hit) = segment.hit.as_ref() else {
        let env = scene.environment(segment.ray.dir);
        return if segment.emission_counted { Vec3::ZERO } else { env };
    };
    let emitted = if segment.emission_counted { Vec3::ZERO } else { scene.emitted(hit, wo) };
    if depth == 1 {
        return emitted;
    }
    let direct = t.mis(scene, hit, wo, scene.heuristic(), sampler);
    let mut total = emitted + direct.radiance;
    if let Some(next) = direct.bounce {
        let mut beta = next.weight;
        let mut alive = true;
        // russian roulette on the largest channel
        if scene.settings().roulette_applies(depth) {
            let survive = beta.x.max(beta.y).max(beta.z).min(0.95);
            if survive > 0.0 && sampler.next_1d() < survive {
                beta /= survive;
            } else {
                alive = false;
            }
        }
        if alive {
            total += beta * t.path_trace(scene, &next.segment, depth - 1, sampler);
        }
    }
    total
}
