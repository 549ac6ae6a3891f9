//! Reference for task `ndf_sample`.

use crate::bsdf::MIN_ALPHA;
use crate::prelude::*;
use std::f32::consts::PI;

/// Draws `h` with density `D(h) cos θh` and reflects `wo` about it.
///
/// GGX with α = 1 has `D cos θh = cos θh / π`, the cosine distribution, whose inverse CDF is
/// `sin²θ = u.x`. Anisotropic GGX is that distribution with its slopes scaled by `αx` and
/// `αy`, so scaling the x and y components of the α = 1 normal and renormalising gives
/// exactly `D(h) cos θh` for any `(αx, αy)`; no `atan` and no special case for the
/// isotropic surface. This is not visible-normal sampling: the density ignores `wo`.
pub fn ndf_sample(t: &impl Tasks, wo: Vec3, alpha_x: f32, alpha_y: f32, u: Vec2) -> Option<Vec3> {
    let ax = alpha_x.abs().max(MIN_ALPHA);
    let ay = alpha_y.abs().max(MIN_ALPHA);
    let sin_theta = u.x.max(0.0).sqrt();
    let cos_theta = (1.0 - u.x).max(0.0).sqrt();
    let (sin_phi, cos_phi) = (2.0 * PI * u.y).sin_cos();
    let h = Vec3::new(
        ax * sin_theta * cos_phi,
        ay * sin_theta * sin_phi,
        cos_theta,
    )
    .normalize();
    if wo.dot(h) <= 0.0 {
        return None;
    }
    let wi = t.reflect(wo, h);
    (wi.z > 0.0).then_some(wi)
}

/// `D(h) cos θh / (4 wo·h)` with `h = normalize(wo + wi)`, the density of `wi` under
/// [`ndf_sample`].
///
/// The sampler only ever produces `h` above the surface with `wo·h > 0` and `wi` above the
/// surface, so everything else has density 0; a nearly opposite pair (`|wo + wi|²` below
/// 1e-12) has no usable half vector and also gets 0.
pub fn ndf_pdf(t: &impl Tasks, wo: Vec3, wi: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
    if wi.z <= 0.0 {
        return 0.0;
    }
    let sum = wo + wi;
    let len2 = sum.length_squared();
    if len2 <= 1e-12 {
        return 0.0;
    }
    let h = sum / len2.sqrt();
    let wo_dot_h = wo.dot(h);
    if h.z <= 0.0 || wo_dot_h <= 0.0 {
        return 0.0;
    }
    t.aniso_ndf(h, alpha_x, alpha_y) * h.z / (4.0 * wo_dot_h)
}
