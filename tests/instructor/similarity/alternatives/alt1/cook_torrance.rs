use crate::bsdf::projected_alpha;
use crate::optics::schlick_weight;
use crate::prelude::*;

pub fn cook_torrance(
    t: &impl Tasks,
    wo: Vec3,
    wi: Vec3,
    alpha_x: f32,
    alpha_y: f32,
    f0: Vec3,
) -> Vec3 {
    if wo.z <= 0.0 || wi.z <= 0.0 {
        return Vec3::ZERO;
    }
    let half = wo + wi;
    if half.length_squared() < 1e-12 {
        return Vec3::ZERO;
    }
    let half = half.normalize();
    let ndf = t.aniso_ndf(half, alpha_x, alpha_y);
    let a_o = projected_alpha(wo, alpha_x, alpha_y);
    let a_i = projected_alpha(wi, alpha_x, alpha_y);
    let shadowing = t.smith_g1(wo, a_o) * t.smith_g1(wi, a_i);
    let w = schlick_weight(wi.dot(half).max(0.0));
    let fresnel = Vec3::new(
        f0.x + (1.0 - f0.x) * w,
        f0.y + (1.0 - f0.y) * w,
        f0.z + (1.0 - f0.z) * w,
    );
    let denom = 4.0 * wo.z * wi.z;
    fresnel * ndf * shadowing / denom
}
