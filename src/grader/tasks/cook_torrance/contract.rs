//! The contract of `cook_torrance` in f64 (see [`crate::grade::contract`]).

use crate::grade::call::Call;
use crate::grade::contract::vector;
use crate::grade::output::Output;
use crate::tasks::aniso_ndf::contract::aniso_ndf;
use crate::tasks::fresnel_schlick::contract::schlick_weight;
use crate::tasks::smith_g1::contract::smith_g1;
use glam::DVec3;

/// The roughness an anisotropic GGX surface presents to the direction `w`:
/// `√(cos²φ αx² + sin²φ αy²)`, with `φ = 0` along the normal.
pub fn projected_alpha(w: DVec3, alpha_x: f64, alpha_y: f64) -> f64 {
    let sin_theta = (1.0 - w.z * w.z).max(0.0).sqrt();
    let (c, s) = if sin_theta == 0.0 {
        (1.0, 0.0)
    } else {
        (
            (w.x / sin_theta).clamp(-1.0, 1.0),
            (w.y / sin_theta).clamp(-1.0, 1.0),
        )
    };
    (c * c * alpha_x * alpha_x + s * s * alpha_y * alpha_y).sqrt()
}

/// The Cook-Torrance microfacet BRDF of an anisotropic GGX conductor with Schlick's Fresnel
/// from `f0`, for `wo` and `wi` (local frame, pointing away from the surface):
/// `F(wo·h) D(h) G1(wo) G1(wi) / (4 cos θo cos θi)`, each G1 divided by its own cosine so
/// that a tiny cosine does not underflow the product; 0 when either direction is at or
/// below the surface, or `wo + wi` vanishes.
pub fn cook_torrance(wo: DVec3, wi: DVec3, alpha_x: f64, alpha_y: f64, f0: DVec3) -> DVec3 {
    let (cos_o, cos_i) = (wo.z, wi.z);
    if cos_o <= 0.0 || cos_i <= 0.0 {
        return DVec3::ZERO;
    }
    let sum = wo + wi;
    let len2 = sum.length_squared();
    if len2 <= 1e-12 {
        return DVec3::ZERO;
    }
    let h = sum / len2.sqrt();
    let d = aniso_ndf(h, alpha_x, alpha_y);
    let g_o = smith_g1(wo, projected_alpha(wo, alpha_x, alpha_y)) / cos_o;
    let g_i = smith_g1(wi, projected_alpha(wi, alpha_x, alpha_y)) / cos_i;
    let fresnel = f0 + (DVec3::ONE - f0) * schlick_weight(wo.dot(h));
    fresnel * (d * g_o * g_i / 4.0)
}

/// The contract's answer to a call of this task's functions; `None` for any other call.
pub fn expected(call: &Call) -> Option<Output> {
    match call {
        Call::cook_torrance {
            wo,
            wi,
            alpha_x,
            alpha_y,
            f0,
        } => Some(vector(cook_torrance(
            wo.as_dvec3(),
            wi.as_dvec3(),
            *alpha_x as f64,
            *alpha_y as f64,
            f0.as_dvec3(),
        ))),
        _ => None,
    }
}
