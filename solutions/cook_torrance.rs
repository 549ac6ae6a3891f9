//! Reference for task `cook_torrance`.

use crate::bsdf::projected_alpha;
use crate::optics::schlick_weight;
use crate::prelude::*;

/// `F(wo·h) D(h) G1(wo) G1(wi) / (4 cos θo cos θi)` with `h = normalize(wo + wi)`.
///
/// Both cosines must be positive: that is where the BRDF is defined, and it keeps the
/// division finite. `|wo + wi|²` is then at least `(cos θo + cos θi)²`, which is tiny only
/// when both directions graze the surface from opposite sides; below `1e-12` the half
/// vector is too inaccurate in f32 to mean anything and the pair counts as invalid. With
/// Smith's G1 the value stays bounded at grazing (`G1(w) ≈ 2 cos θ / α` cancels the
/// `1/cos θ`, so each G1 is divided by its own cosine first), where `G = 1` would blow up
/// like `1/cos θo`. The anisotropic masking uses the
/// roughness projected onto each direction's azimuth.
pub fn cook_torrance(
    t: &impl Tasks,
    wo: Vec3,
    wi: Vec3,
    alpha_x: f32,
    alpha_y: f32,
    f0: Vec3,
) -> Vec3 {
    let (cos_o, cos_i) = (wo.z, wi.z);
    if cos_o <= 0.0 || cos_i <= 0.0 {
        return Vec3::ZERO;
    }
    let sum = wo + wi;
    let len2 = sum.length_squared();
    if len2 <= 1e-12 {
        return Vec3::ZERO;
    }
    let h = sum / len2.sqrt();
    let d = t.aniso_ndf(h, alpha_x, alpha_y);
    // Each G1 divided by its own cosine: bounded however small the cosine (down to a
    // subnormal one, where `4 cos θo cos θi` underflows to 0).
    let g_o = t.smith_g1(wo, projected_alpha(wo, alpha_x, alpha_y)) / cos_o;
    let g_i = t.smith_g1(wi, projected_alpha(wi, alpha_x, alpha_y)) / cos_i;
    let fresnel = f0 + (Vec3::ONE - f0) * schlick_weight(wo.dot(h));
    fresnel * (d * g_o * g_i / 4.0)
}
