use crate::bsdf::MIN_ALPHA;
use crate::prelude::*;
use std::f32::consts::PI;

pub fn aniso_ndf(h: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
    if !(h.z > 0.0) {
        return 0.0;
    }
    let ax = alpha_x.abs().max(MIN_ALPHA);
    let ay = alpha_y.abs().max(MIN_ALPHA);
    let cos2 = h.z * h.z;
    let sin2 = (1.0 - cos2).max(0.0);
    // tan^2 theta (cos^2 phi / ax^2 + sin^2 phi / ay^2)
    let e = if sin2 > 0.0 {
        (h.x * h.x / (ax * ax) + h.y * h.y / (ay * ay)) / cos2
    } else {
        0.0
    };
    let cos4 = cos2 * cos2;
    let d = PI * ax * ay * cos4 * (1.0 + e) * (1.0 + e);
    if d > 0.0 { 1.0 / d } else { 0.0 }
}
