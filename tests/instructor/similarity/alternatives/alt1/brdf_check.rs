use crate::prelude::*;
use crate::sampling::{uniform_hemisphere, uniform_hemisphere_pdf};
use std::f32::consts::PI;

const ANGLES: [f32; 9] = [0.0, 20.0, 40.0, 60.0, 70.0, 80.0, 85.0, 89.0, 89.9];

pub fn brdf_check(
    t: &impl Tasks,
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut Sampler,
    samples: usize,
) -> PlausibilityReport {
    let gap = t.reciprocity_gap(brdf, sampler, samples);
    let mut lowest = f32::INFINITY;
    let mut highest = f32::NEG_INFINITY;
    let mut worst = Vec3::Z;
    let count = samples.max(1);
    let pdf = uniform_hemisphere_pdf();
    for deg in ANGLES {
        let theta = deg.to_radians();
        let phi = sampler.next_1d() * 2.0 * PI;
        let wi = Vec3::new(theta.sin() * phi.cos(), theta.sin() * phi.sin(), theta.cos());
        let mut total = 0.0f64;
        let mut has_nan = false;
        for i in 0..count {
            // stratified in the first coordinate
            let u0 = (i as f32 + sampler.next_1d()) / count as f32;
            let wo = uniform_hemisphere(Vec2::new(u0, sampler.next_1d()));
            let value = brdf(wi, wo);
            if value.is_nan() {
                has_nan = true;
            } else if value < lowest {
                lowest = value;
            }
            total += f64::from(value * wo.z / pdf);
        }
        let estimate = if has_nan {
            f32::NAN
        } else {
            (total / count as f64) as f32
        };
        if has_nan {
            lowest = f32::NAN;
        }
        if estimate.is_nan() || estimate > highest {
            highest = estimate;
            worst = wi;
        }
    }
    PlausibilityReport {
        min_value: lowest,
        max_reciprocity_error: gap,
        max_albedo: highest,
        worst_wi: worst,
    }
}
