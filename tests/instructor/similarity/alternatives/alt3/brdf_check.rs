use crate::prelude::*;
use crate::sampling::{uniform_hemisphere, uniform_hemisphere_pdf};

pub fn brdf_check(
    t: &impl Tasks,
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut Sampler,
    samples: usize,
) -> PlausibilityReport {
    let thetas = [0.0f32, 15.0, 30.0, 45.0, 60.0, 75.0, 80.0, 85.0, 88.0, 89.0, 89.9];
    let n = if samples == 0 { 1 } else { samples };
    let recip = t.reciprocity_gap(brdf, sampler, samples);
    let mut min_f = f32::INFINITY;
    let mut best = (f32::NEG_INFINITY, Vec3::Z);
    let mut j = 0;
    while j < thetas.len() {
        let th = thetas[j].to_radians();
        let az = sampler.next_1d() * std::f32::consts::TAU;
        let (st, ct) = th.sin_cos();
        let (sa, ca) = az.sin_cos();
        let dir_in = Vec3::new(st * ca, st * sa, ct).normalize();
        let mut sum = 0.0;
        let mut s = 0;
        while s < n {
            let jitter = sampler.next_1d();
            let u = Vec2::new((s as f32 + jitter) / n as f32, sampler.next_1d());
            let dir_out = uniform_hemisphere(u);
            let v = brdf(dir_in, dir_out);
            if v.is_nan() {
                min_f = f32::NAN;
            } else if !min_f.is_nan() && v < min_f {
                min_f = v;
            }
            sum += v as f64 * dir_out.z as f64 / uniform_hemisphere_pdf() as f64;
            s += 1;
        }
        let alb = (sum / n as f64) as f32;
        if alb.is_nan() || (!best.0.is_nan() && alb > best.0) {
            best = (alb, dir_in);
        }
        j += 1;
    }
    PlausibilityReport {
        min_value: min_f,
        max_reciprocity_error: recip,
        max_albedo: best.0,
        worst_wi: best.1,
    }
}
