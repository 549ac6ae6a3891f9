// The variants of `brdf_check` the tests grade the grader with (see `src/grader/tasks/mod.rs`).
// `tests/instructor/support/variants.rs` includes this file into a module of the tests,
// so it has no inner attributes or doc; the student handout leaves it out.

use crate::support::patch::{Patch, Variant, variant};
use crate::support::variants::Naive;
use glam::{Vec2, Vec3};
use pbrlab::bsdf::PlausibilityReport;
use pbrlab::sampling::{Sampler, uniform_hemisphere, uniform_hemisphere_pdf};
use pbrlab::worksheet::{TaskId, Tasks};
use pbrlab_solutions as sol;
use std::f32::consts::FRAC_1_PI;

/// Known-wrong implementations of `brdf_check`: each must fail this task and no other.
pub fn wrong() -> Vec<Variant> {
    use TaskId::*;
    vec![
        variant("energy tested at normal incidence only", BrdfCheck, |p| {
            p.brdf_check =
                Some(|t, brdf, sampler, samples| albedo_check(t, brdf, sampler, samples, &[0.0]))
        }),
        variant("albedo without 1/pdf", BrdfCheck, |p| {
            p.brdf_check = Some(|t, brdf, sampler, samples| {
                let mut r = sol::brdf_check::brdf_check(t, brdf, sampler, samples);
                r.max_albedo *= uniform_hemisphere_pdf();
                r
            })
        }),
        variant("f32::min and max that skip NaN", BrdfCheck, |p| {
            p.brdf_check = Some(|t, brdf, sampler, samples| {
                let mut r = sol::brdf_check::brdf_check(t, brdf, sampler, samples);
                if r.min_value.is_nan() {
                    r.min_value = 0.5 * FRAC_1_PI;
                }
                if r.max_albedo.is_nan() {
                    r.max_albedo = 0.5;
                }
                r
            })
        }),
        variant("energy tested up to 85° only", BrdfCheck, |p| {
            p.brdf_check = Some(|t, brdf, sampler, samples| {
                albedo_check(t, brdf, sampler, samples, &[0.0, 30.0, 60.0, 75.0, 85.0])
            })
        }),
        variant("worst_wi pointing into the surface", BrdfCheck, |p| {
            p.brdf_check = Some(|t, brdf, sampler, samples| {
                let mut r = sol::brdf_check::brdf_check(t, brdf, sampler, samples);
                r.worst_wi = -r.worst_wi;
                r
            })
        }),
        variant(
            "worst_wi the last direction tried, not the worst",
            BrdfCheck,
            |p| {
                p.brdf_check = Some(|t, brdf, sampler, samples| {
                    let mut r = sol::brdf_check::brdf_check(t, brdf, sampler, samples);
                    r.worst_wi =
                        Vec3::new(89.9f32.to_radians().sin(), 0.0, 89.9f32.to_radians().cos());
                    r
                })
            },
        ),
        variant("positivity of |f|", BrdfCheck, |p| {
            p.brdf_check = Some(|t, brdf, sampler, samples| {
                let mut r = sol::brdf_check::brdf_check(t, brdf, sampler, samples);
                r.min_value = r.min_value.abs();
                r
            })
        }),
    ]
}

/// Correct implementations of `brdf_check` that differ from the reference: each gets full marks.
pub fn different() -> Vec<Variant> {
    use TaskId::*;
    vec![variant(
        "plausibility with stratified uniform albedo samples at its own angles",
        BrdfCheck,
        |p| p.brdf_check = Some(stratified_check),
    )]
}

/// Naive implementations of `brdf_check` (the textbook formula without its guards), each with
/// exactly the stability cases it must fail and the verdict of each.
pub fn naive() -> Vec<Naive> {
    Vec::new()
}

/// A plausibility check whose albedo only looks at the incident angles `theta_deg`.
fn albedo_check(
    t: &impl Tasks,
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut Sampler,
    samples: usize,
    theta_deg: &[f32],
) -> PlausibilityReport {
    let mut report = PlausibilityReport {
        min_value: f32::INFINITY,
        max_reciprocity_error: t.reciprocity_gap(brdf, sampler, samples),
        max_albedo: 0.0,
        worst_wi: Vec3::Z,
    };
    for &deg in theta_deg {
        let (s, c) = deg.to_radians().sin_cos();
        let wi = Vec3::new(s, 0.0, c);
        let mut sum = 0.0;
        for _ in 0..samples {
            let wo = uniform_hemisphere(sampler.next_2d());
            let f = brdf(wi, wo);
            report.min_value = report.min_value.min(f);
            sum += f * wo.z / uniform_hemisphere_pdf();
        }
        let albedo = sum / samples.max(1) as f32;
        if albedo > report.max_albedo {
            report.max_albedo = albedo;
            report.worst_wi = wi;
        }
    }
    report
}

fn stratified_check(
    t: &Patch,
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut Sampler,
    samples: usize,
) -> PlausibilityReport {
    let mut report = PlausibilityReport {
        min_value: f32::INFINITY,
        max_reciprocity_error: t.reciprocity_gap(brdf, sampler, samples),
        max_albedo: 0.0,
        worst_wi: Vec3::Z,
    };
    // A jittered √n × √n grid of uniform hemisphere samples, as the text suggests.
    let side = (samples as f64).sqrt().floor().max(1.0) as usize;
    for deg in [0.0f32, 20.0, 40.0, 60.0, 80.0, 88.0, 89.5, 89.95] {
        let (s, c) = deg.to_radians().sin_cos();
        let wi = Vec3::new(0.0, s, c);
        let mut sum = 0.0f64;
        for k in 0..side * side {
            let u = sampler.next_2d();
            let u = Vec2::new(
                ((k % side) as f32 + u.x) / side as f32,
                ((k / side) as f32 + u.y) / side as f32,
            )
            .min(Vec2::splat(1.0 - f32::EPSILON));
            let wo = uniform_hemisphere(u);
            let f = brdf(wi, wo);
            // A NaN reaches the report (f32::min would skip it).
            if f.is_nan() || f < report.min_value {
                report.min_value = f;
            }
            sum += (f * wo.z / uniform_hemisphere_pdf()) as f64;
        }
        let albedo = (sum / (side * side) as f64) as f32;
        if albedo.is_nan() || albedo > report.max_albedo {
            report.max_albedo = albedo;
            report.worst_wi = wi;
        }
    }
    report
}
