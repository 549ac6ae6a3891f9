use crate::prelude::*;
use crate::sampling::{uniform_hemisphere, uniform_hemisphere_pdf};
use std::f32::consts::TAU;

/// Cosines of the incident directions I test (includes 89 and 89.9 degrees).
fn test_cosines() -> Vec<f32> {
    let mut v: Vec<f32> = (0..=8).map(|k| 1.0 - k as f32 / 8.0).filter(|c| *c > 0.0).collect();
    v.push(89.0f32.to_radians().cos());
    v.push(89.9f32.to_radians().cos());
    v
}

fn direction_with_cos(c: f32, azimuth: f32) -> Vec3 {
    let s = (1.0 - c * c).max(0.0).sqrt();
    Vec3::new(s * azimuth.cos(), s * azimuth.sin(), c)
}

/// Albedo estimate and the smallest value seen (NaN propagates).
fn albedo(brdf: &dyn Fn(Vec3, Vec3) -> f32, wi: Vec3, sampler: &mut Sampler, n: usize) -> (f32, f32) {
    let strata = ((n as f64).sqrt().ceil() as usize).max(1);
    let total = strata * strata;
    let mut acc = 0.0f64;
    let mut min = f32::INFINITY;
    for a in 0..strata {
        for b in 0..strata {
            let u = Vec2::new(
                (a as f32 + sampler.next_1d()) / strata as f32,
                (b as f32 + sampler.next_1d()) / strata as f32,
            );
            let wo = uniform_hemisphere(u);
            let f = brdf(wi, wo);
            min = if f.is_nan() || min.is_nan() { f32::NAN } else { min.min(f) };
            acc += (f as f64) * (wo.z as f64) / (uniform_hemisphere_pdf() as f64);
        }
    }
    ((acc / total as f64) as f32, min)
}

pub fn brdf_check(
    t: &impl Tasks,
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut Sampler,
    samples: usize,
) -> PlausibilityReport {
    let max_reciprocity_error = t.reciprocity_gap(brdf, sampler, samples);
    let mut report = PlausibilityReport {
        min_value: f32::INFINITY,
        max_reciprocity_error,
        max_albedo: f32::NEG_INFINITY,
        worst_wi: Vec3::Z,
    };
    for c in test_cosines() {
        let wi = direction_with_cos(c, TAU * sampler.next_1d());
        let (a, m) = albedo(brdf, wi, sampler, samples);
        if m.is_nan() || m < report.min_value {
            report.min_value = m;
        }
        if a.is_nan() || a > report.max_albedo {
            report.max_albedo = a;
            report.worst_wi = wi;
        }
    }
    report
}
