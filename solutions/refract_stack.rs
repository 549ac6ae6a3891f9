//! Reference for task `refract_stack`: Snell's law with total internal reflection, the
//! critical angle, and a ray followed through a stack of plane-parallel layers.

use crate::optics::fresnel_dielectric_f64;
use crate::prelude::*;

/// Refraction of `wi` through the interface with normal `n`, from `eta_i` into `eta_t`.
///
/// Both `wi` and `n` are normalised first. If `n` lies on the far side of the interface it is
/// flipped to `wi`'s side, because `eta_i` names the medium `wi` is in whatever way `n`
/// points. Total internal reflection is decided on `sin²θt ≥ 1` (so exactly at the critical
/// angle there is no transmitted ray, and `R = 1`), and the square root is taken of a
/// clamped value so rounding cannot produce a NaN.
pub fn refract(wi: Vec3, n: Vec3, eta_i: f32, eta_t: f32) -> Option<Vec3> {
    let wi = wi.normalize();
    let mut n = n.normalize();
    let mut cos_i = wi.dot(n);
    if cos_i < 0.0 {
        n = -n;
        cos_i = -cos_i;
    }
    let cos_i = cos_i.min(1.0);
    let eta = eta_i / eta_t;
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i).max(0.0);
    if sin2_t >= 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).max(0.0).sqrt();
    Some((-eta * wi + (eta * cos_i - cos_t) * n).normalize())
}

/// `asin(eta_t / eta_i)` when light can be totally reflected (`eta_i > eta_t > 0`), else
/// `None` (the formula would give NaN for `eta_i < eta_t` and a meaningless 90° for equal
/// indices).
pub fn critical_angle(eta_i: f64, eta_t: f64) -> Option<f64> {
    (eta_t > 0.0 && eta_i > eta_t && eta_i.is_finite()).then(|| (eta_t / eta_i).asin())
}

/// Follows the ray through `stack`, medium by medium.
///
/// `eta sin θ` is the same in every medium the ray reaches, so each angle comes from the
/// first one; this also makes errors in one interface not accumulate into the next. The ray
/// stops at the first interface where `sin θt ≥ 1`. Per slab it reports the shift of the ray
/// perpendicular to its incoming direction, `d sin(θ_in − θ) / cos θ`, and the offset of the
/// exit point along the interface, `d tan θ`, for every slab the ray entered. Reflectances use
/// the cosine of the incidence angle at each interface: Schlick through the `fresnel_schlick`
/// task (which chooses the cosine it needs itself), exact through the f64 Fresnel equations.
pub fn refract_stack(t: &impl Tasks, theta_deg: f64, stack: &LayerStack) -> StackReport {
    let etas = stack.etas();
    let invariant = etas[0] * theta_deg.to_radians().sin();
    let mut report = StackReport {
        theta: vec![theta_deg],
        ..StackReport::default()
    };
    let mut transmitted_schlick = stack.intensity;
    let mut transmitted_exact = stack.intensity;
    for k in 0..stack.interfaces() {
        let (eta_i, eta_t) = (etas[k], etas[k + 1]);
        let theta_i = report.theta[k].to_radians();
        let sin_t = invariant / eta_t;
        if sin_t * sin_t >= 1.0 {
            report.tir_at = Some(k);
            report.reflectance_schlick.push(1.0);
            report.reflectance_exact.push(1.0);
            transmitted_schlick = 0.0;
            transmitted_exact = 0.0;
            break;
        }
        let cos_i = theta_i.cos();
        let r_schlick = t.fresnel_schlick(cos_i as f32, eta_i as f32, eta_t as f32) as f64;
        let r_exact = fresnel_dielectric_f64(cos_i, eta_i, eta_t);
        report.reflectance_schlick.push(r_schlick);
        report.reflectance_exact.push(r_exact);
        transmitted_schlick *= 1.0 - r_schlick;
        transmitted_exact *= 1.0 - r_exact;

        let theta_t = sin_t.asin();
        report.theta.push(theta_t.to_degrees());
        if let Some(slab) = stack.slabs.get(k) {
            let d = slab.thickness;
            report
                .perpendicular_shift
                .push(d * (theta_i - theta_t).sin() / theta_t.cos());
            report.interface_offset.push(d * theta_t.tan());
        }
    }
    report.transmitted_schlick = transmitted_schlick;
    report.transmitted_exact = transmitted_exact;
    report
}
