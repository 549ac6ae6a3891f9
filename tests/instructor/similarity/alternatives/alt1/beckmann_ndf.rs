use crate::bsdf::MIN_ALPHA;
use crate::prelude::*;
use std::f32::consts::PI;

pub fn beckmann_ndf(h: Vec3, alpha: f32) -> f32 {
    let cos_h = h.z;
    if cos_h <= 0.0 {
        return 0.0;
    }
    let a = alpha.abs().max(MIN_ALPHA);
    let c2 = (cos_h * cos_h).min(1.0);
    let t2 = (1.0 - c2) / c2;
    let val = (-t2 / (a * a)).exp() / (PI * a * a * c2 * c2);
    if val.is_finite() { val } else { 0.0 }
}
