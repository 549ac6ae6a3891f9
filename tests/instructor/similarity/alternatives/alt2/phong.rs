use crate::prelude::*;
use crate::sampling::uniform_hemisphere;
use std::f32::consts::FRAC_1_PI;

pub fn phong(t: &impl Tasks, wo: Vec3, wi: Vec3, params: &PhongParams) -> Vec3 {
    let above = wo.z > 0.0 && wi.z > 0.0;
    if !above {
        return Vec3::ZERO;
    }
    let diffuse = params.kd * FRAC_1_PI;
    let r = t.reflect(wi, Vec3::Z);
    let cos_alpha = r.dot(wo).clamp(0.0, 1.0);
    let n = params.exponent;
    let specular = params.ks * ((n + 2.0) * FRAC_1_PI * 0.5) * cos_alpha.powf(n);
    diffuse + specular
}

fn relative_gap(p: f32, q: f32) -> f32 {
    if !p.is_finite() || !q.is_finite() {
        return f32::INFINITY;
    }
    if p == q {
        return 0.0;
    }
    (p - q).abs() / p.abs().max(q.abs())
}

pub fn reciprocity_gap(
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut Sampler,
    pairs: usize,
) -> f32 {
    (0..pairs)
        .map(|_| {
            let a = uniform_hemisphere(sampler.next_2d());
            let b = uniform_hemisphere(sampler.next_2d());
            relative_gap(brdf(a, b), brdf(b, a))
        })
        .fold(0.0, f32::max)
}
