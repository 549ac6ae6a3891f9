//! Reference for task `phong`.

use crate::prelude::*;
use crate::sampling::uniform_hemisphere;
use std::f32::consts::FRAC_1_PI;

/// `kd/π + ks (n+2)/(2π) max(0, r·wo)^n` with `r` the mirror of `wi` about the normal.
///
/// The cosine is clamped before the power: a negative base with a fractional exponent is
/// NaN, and with an even exponent it would light a spurious lobe behind the mirror
/// direction. Both directions must be above the surface.
pub fn phong(t: &impl Tasks, wo: Vec3, wi: Vec3, params: &PhongParams) -> Vec3 {
    if wo.z <= 0.0 || wi.z <= 0.0 {
        return Vec3::ZERO;
    }
    let r = t.reflect(wi, Vec3::Z);
    let lobe = r.dot(wo).max(0.0).powf(params.exponent);
    let norm = (params.exponent + 2.0) * 0.5 * FRAC_1_PI;
    params.kd * FRAC_1_PI + params.ks * (norm * lobe)
}

/// The largest relative asymmetry `|f(a,b) − f(b,a)| / max(|f(a,b)|, |f(b,a)|)` over `pairs`
/// pairs of directions drawn uniformly on the upper hemisphere.
///
/// Pairs where both values are 0 count 0. A pair where either value is not finite
/// counts as infinitely asymmetric: a BRDF that returns NaN or ∞ cannot be checked, and
/// saying so is better than letting `max` skip the NaN silently.
pub fn reciprocity_gap(
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut Sampler,
    pairs: usize,
) -> f32 {
    let mut gap = 0.0f32;
    for _ in 0..pairs {
        let a = uniform_hemisphere(sampler.next_2d());
        let b = uniform_hemisphere(sampler.next_2d());
        let (f_ab, f_ba) = (brdf(a, b), brdf(b, a));
        let pair_gap = if !(f_ab.is_finite() && f_ba.is_finite()) {
            f32::INFINITY
        } else if f_ab == f_ba {
            0.0
        } else {
            (f_ab - f_ba).abs() / f_ab.abs().max(f_ba.abs())
        };
        gap = gap.max(pair_gap);
    }
    gap
}
