use crate::prelude::*;

fn emission(scene: &Scene, segment: &Segment) -> Vec3 {
    if segment.emission_counted {
        return Vec3::ZERO;
    }
    match &segment.hit {
        Some(hit) => scene.emitted(hit, -segment.ray.dir),
        None => scene.environment(segment.ray.dir),
    }
}

fn continue_probability(weight: Vec3) -> f32 {
    let q = weight.max_element();
    if q.is_finite() { q.clamp(0.0, 0.95) } else { 0.0 }
}

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
    let le = emission(scene, segment);
    let hit = match segment.hit.as_ref() {
        Some(hit) if depth > 1 => hit,
        _ => return le,
    };
    let wo = -segment.ray.dir;
    let direct = t.mis(scene, hit, wo, scene.heuristic(), sampler);
    let Some(bounce) = direct.bounce else {
        return le + direct.radiance;
    };
    let mut factor = bounce.weight;
    if scene.settings().roulette_applies(depth) {
        let q = continue_probability(factor);
        if q == 0.0 || sampler.next_1d() >= q {
            return le + direct.radiance;
        }
        factor = factor / q;
    }
    let rest = t.path_trace(scene, &bounce.segment, depth - 1, sampler);
    le + direct.radiance + factor * rest
}
