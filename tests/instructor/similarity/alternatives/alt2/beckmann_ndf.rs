use crate::bsdf::MIN_ALPHA;
use crate::prelude::*;
use std::f32::consts::FRAC_1_PI;

pub fn beckmann_ndf(h: Vec3, alpha: f32) -> f32 {
    if !(h.z > 0.0) {
        return 0.0;
    }
    let alpha = if alpha.abs() < MIN_ALPHA { MIN_ALPHA } else { alpha.abs() };
    let cos_theta = h.z.min(1.0);
    let sin2 = (h.x * h.x + h.y * h.y).min(1.0);
    let cos4 = cos_theta.powi(4);
    if cos4 <= 0.0 {
        return 0.0;
    }
    let exponent = -sin2 / (cos_theta * cos_theta * alpha * alpha);
    exponent.exp() * FRAC_1_PI / (alpha * alpha * cos4)
}
