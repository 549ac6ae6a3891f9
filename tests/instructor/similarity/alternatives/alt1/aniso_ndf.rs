use crate::bsdf::MIN_ALPHA;
use crate::prelude::*;
use std::f32::consts::PI;

pub fn aniso_ndf(h: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
    let cos_t = h.z;
    if cos_t <= 0.0 {
        return 0.0;
    }
    let ax = if alpha_x.abs() < MIN_ALPHA { MIN_ALPHA } else { alpha_x.abs() };
    let ay = if alpha_y.abs() < MIN_ALPHA { MIN_ALPHA } else { alpha_y.abs() };
    let term = (h.x * h.x) / (ax * ax) + (h.y * h.y) / (ay * ay) + cos_t * cos_t;
    1.0 / (PI * ax * ay * term * term)
}
