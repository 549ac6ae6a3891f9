//! Reference for task `brdf_check`.

use crate::math::spherical_direction;
use crate::prelude::*;
use crate::sampling::{uniform_hemisphere, uniform_hemisphere_pdf};
use std::f32::consts::PI;

/// Polar angles (degrees) of the incident directions whose albedo is estimated. They run up
/// to 89.9° on purpose: a BRDF with `1/cos θi` in it, like the worksheet's custom one, looks
/// harmless at normal incidence and breaks energy conservation only near grazing.
const INCIDENT_THETA_DEG: [f32; 8] = [0.0, 30.0, 45.0, 60.0, 75.0, 85.0, 89.0, 89.9];

/// Positivity, reciprocity and energy conservation of `brdf(wi, wo)`, measured.
///
/// - Reciprocity: [`Tasks::reciprocity_gap`] over `samples` random pairs.
/// - Energy: for each polar angle in `INCIDENT_THETA_DEG` (at a random azimuth, for
///   anisotropic BRDFs), the albedo `∫ f(wi, wo) cos θo dωo` is estimated with `samples`
///   uniform-hemisphere directions `wo`, stratified in `cos θo` (the first coordinate of
///   [`uniform_hemisphere`]) to keep the estimate of a smooth BRDF within a fraction of a
///   percent: a Lambertian BRDF with albedo 1 must not look like it creates energy.
/// - Positivity: the smallest value among all those evaluations.
///
/// A NaN anywhere makes `min_value` (and the albedo it belongs to) NaN, so the report cannot
/// be plausible; `max` and `min` on floats would otherwise skip it.
pub fn brdf_check(
    t: &impl Tasks,
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut Sampler,
    samples: usize,
) -> PlausibilityReport {
    let mut report = PlausibilityReport {
        min_value: f32::INFINITY,
        max_reciprocity_error: t.reciprocity_gap(brdf, sampler, samples),
        max_albedo: f32::NEG_INFINITY,
        worst_wi: Vec3::Z,
    };
    let n = samples.max(1);
    for theta_deg in INCIDENT_THETA_DEG {
        let (sin_theta, cos_theta) = theta_deg.to_radians().sin_cos();
        let wi = spherical_direction(sin_theta, cos_theta, 2.0 * PI * sampler.next_1d());
        let mut sum = 0.0f64;
        for k in 0..n {
            let u = Vec2::new((k as f32 + sampler.next_1d()) / n as f32, sampler.next_1d());
            let wo = uniform_hemisphere(u);
            let f = brdf(wi, wo);
            if f.is_nan() || f < report.min_value {
                report.min_value = f;
            }
            sum += (f * wo.z / uniform_hemisphere_pdf()) as f64;
        }
        let albedo = (sum / n as f64) as f32;
        if albedo.is_nan() || albedo > report.max_albedo {
            report.max_albedo = albedo;
            report.worst_wi = wi;
        }
    }
    report
}
