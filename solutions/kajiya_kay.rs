//! Reference for task `kajiya_kay`.

use crate::prelude::*;

/// Kajiya-Kay (1989) with both directions pointing away from the fibre:
/// `kd sin θi + ks max(0, sin θi sin θo − cos θi cos θo)^p`, `cos θ = t·w`.
///
/// Mirror reflection off a cylinder sends light onto the cone `t·wo = −t·wi`; the bracket is
/// the cosine of the angle between `wo` and that cone, `cos(π − θi − θo)`. The cosines are
/// clamped to [−1, 1] so an f32 dot product of 1.0000001 gives `sin = 0` instead of NaN,
/// and the cone cosine is clamped before the power. The specular term is symmetric in `wi`
/// and `wo`; the diffuse term `kd sin θi` is not, so the model as a whole is not reciprocal.
pub fn kajiya_kay(wo: Vec3, wi: Vec3, tangent: Vec3, params: &KajiyaKayParams) -> Vec3 {
    let cos_i = tangent.dot(wi).clamp(-1.0, 1.0);
    let cos_o = tangent.dot(wo).clamp(-1.0, 1.0);
    let sin_i = (1.0 - cos_i * cos_i).max(0.0).sqrt();
    let sin_o = (1.0 - cos_o * cos_o).max(0.0).sqrt();
    let cone = (sin_i * sin_o - cos_i * cos_o).max(0.0);
    params.kd * sin_i + params.ks * cone.powf(params.exponent)
}
