//! The contract of `kajiya_kay` in f64 (see [`crate::grade::contract`]).

use crate::bsdf::KajiyaKayParams;
use crate::grade::call::Call;
use crate::grade::contract::vector;
use crate::grade::output::Output;
use glam::DVec3;

/// Kajiya-Kay hair shading for `wo` and `wi` around the fibre `tangent`: diffuse
/// `kd sin(t, wi)` plus specular `ks max(0, cos of the angle to the reflection cone)^p`,
/// the cone's cosine `sin θi sin θo − cos θi cos θo` with `cos θ = t·w` (clamped to
/// [−1, 1]).
pub fn kajiya_kay(wo: DVec3, wi: DVec3, tangent: DVec3, params: &KajiyaKayParams) -> DVec3 {
    let cos_i = tangent.dot(wi).clamp(-1.0, 1.0);
    let cos_o = tangent.dot(wo).clamp(-1.0, 1.0);
    let sin_i = (1.0 - cos_i * cos_i).max(0.0).sqrt();
    let sin_o = (1.0 - cos_o * cos_o).max(0.0).sqrt();
    let cone = (sin_i * sin_o - cos_i * cos_o).max(0.0);
    params.kd.as_dvec3() * sin_i + params.ks.as_dvec3() * cone.powf(params.exponent as f64)
}

/// The contract's answer to a call of this task's functions; `None` for any other call.
pub fn expected(call: &Call) -> Option<Output> {
    match call {
        Call::kajiya_kay {
            wo,
            wi,
            tangent,
            params,
        } => Some(vector(kajiya_kay(
            wo.as_dvec3(),
            wi.as_dvec3(),
            tangent.as_dvec3(),
            params,
        ))),
        _ => None,
    }
}
