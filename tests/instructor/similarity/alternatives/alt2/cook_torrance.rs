use crate::bsdf::projected_alpha;
use crate::prelude::*;

fn schlick_rgb(f0: Vec3, cos: f32) -> Vec3 {
    let m = (1.0 - cos).clamp(0.0, 1.0);
    let m5 = m * m * m * m * m;
    f0 + (Vec3::splat(1.0) - f0) * m5
}

fn masking(t: &impl Tasks, w: Vec3, ax: f32, ay: f32) -> f32 {
    t.smith_g1(w, projected_alpha(w, ax, ay))
}

pub fn cook_torrance(
    t: &impl Tasks,
    wo: Vec3,
    wi: Vec3,
    alpha_x: f32,
    alpha_y: f32,
    f0: Vec3,
) -> Vec3 {
    let cos_o = wo.z;
    let cos_i = wi.z;
    let valid = cos_o > 0.0 && cos_i > 0.0;
    let h_raw = wo + wi;
    let len = h_raw.length();
    if !valid || len < 1e-6 {
        Vec3::ZERO
    } else {
        let h = h_raw / len;
        let d = t.aniso_ndf(h, alpha_x, alpha_y);
        let g = masking(t, wo, alpha_x, alpha_y) * masking(t, wi, alpha_x, alpha_y);
        let value = schlick_rgb(f0, wo.dot(h)) * d * g / (4.0 * cos_o * cos_i);
        if value.is_finite() { value } else { Vec3::ZERO }
    }
}
