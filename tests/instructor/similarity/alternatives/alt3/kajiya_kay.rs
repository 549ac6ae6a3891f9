use crate::prelude::*;

/// Sine and cosine of the angle between the fibre and `w`.
fn sin_cos_to(t: Vec3, w: Vec3) -> (f32, f32) {
    let c = t.dot(w).clamp(-1.0, 1.0);
    let s = t.cross(w).length().min(1.0);
    (s, c)
}

pub fn kajiya_kay(wo: Vec3, wi: Vec3, tangent: Vec3, params: &KajiyaKayParams) -> Vec3 {
    let (sin_i, cos_i) = sin_cos_to(tangent, wi);
    let (sin_o, cos_o) = sin_cos_to(tangent, wo);
    let highlight = f32::max(sin_i * sin_o - cos_i * cos_o, 0.0);
    let mut result = params.kd * sin_i;
    if highlight > 0.0 {
        result += params.ks * highlight.powf(params.exponent);
    }
    result
}
