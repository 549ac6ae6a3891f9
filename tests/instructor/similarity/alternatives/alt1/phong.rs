use crate::prelude::*;
use crate::sampling::uniform_hemisphere;
use std::f32::consts::PI;

pub fn phong(t: &impl Tasks, wo: Vec3, wi: Vec3, params: &PhongParams) -> Vec3 {
    if wi.z <= 0.0 || wo.z <= 0.0 {
        return Vec3::ZERO;
    }
    let mirror = t.reflect(wo, Vec3::Z);
    let c = mirror.dot(wi);
    let spec = if c > 0.0 {
        (params.exponent + 2.0) / (2.0 * PI) * c.powf(params.exponent)
    } else {
        0.0
    };
    params.kd / PI + params.ks * spec
}

pub fn reciprocity_gap(
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut Sampler,
    pairs: usize,
) -> f32 {
    let mut worst = 0.0f32;
    for _ in 0..pairs {
        let x = uniform_hemisphere(sampler.next_2d());
        let y = uniform_hemisphere(sampler.next_2d());
        let forward = brdf(x, y);
        let backward = brdf(y, x);
        if forward.is_nan() || backward.is_nan() || forward.is_infinite() || backward.is_infinite()
        {
            return f32::INFINITY;
        }
        let scale = forward.abs().max(backward.abs());
        if scale > 0.0 {
            let rel = (forward - backward).abs() / scale;
            if rel > worst {
                worst = rel;
            }
        }
    }
    worst
}
