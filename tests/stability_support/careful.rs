//! A careful implementation of the closed-form tasks: the textbook formulas with the guards
//! the errata ask for. It stands in for the reference in these tests, so the catalogue is
//! checked against an independent implementation.

use glam::{Vec2, Vec3};
use pbrlab::bsdf::{KajiyaKayParams, PhongParams, PlausibilityReport, projected_alpha};
use pbrlab::optics::{LayerStack, StackReport, fresnel_dielectric_f64};
use pbrlab::sampling::{Sampler, uniform_hemisphere};
use pbrlab::worksheet::Tasks;
use std::f32::consts::{FRAC_1_PI, PI};

/// The smallest roughness the microfacet functions use: α = 0 is a mirror, and 1e-4 keeps
/// D finite while leaving α = 1e-4 itself exact.
const ALPHA_MIN: f32 = 1e-4;

pub fn reflect(wo: Vec3, n: Vec3) -> Vec3 {
    let n = n.normalize();
    2.0 * wo.dot(n) * n - wo
}

pub fn refract(wi: Vec3, n: Vec3, eta_i: f32, eta_t: f32) -> Option<Vec3> {
    let n = n.normalize();
    let eta = eta_i / eta_t;
    let cos_i = wi.dot(n).clamp(-1.0, 1.0);
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i).max(0.0);
    if sin2_t >= 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).max(0.0).sqrt();
    Some((-eta * wi + (eta * cos_i - cos_t) * n).normalize())
}

pub fn critical_angle(eta_i: f64, eta_t: f64) -> Option<f64> {
    (eta_i > eta_t).then(|| (eta_t / eta_i).asin())
}

pub fn refract_stack(t: &impl Tasks, theta_deg: f64, stack: &LayerStack) -> StackReport {
    let etas = stack.etas();
    let invariant = etas[0] * theta_deg.to_radians().sin();
    let mut r = StackReport {
        theta: vec![theta_deg],
        ..StackReport::default()
    };
    let (mut schlick, mut exact) = (stack.intensity, stack.intensity);
    for k in 0..stack.interfaces() {
        let (eta_i, eta_t) = (etas[k], etas[k + 1]);
        let cos_i = r.theta[k].to_radians().cos();
        let sin_t = invariant / eta_t;
        if sin_t >= 1.0 {
            r.tir_at = Some(k);
            r.reflectance_schlick.push(1.0);
            r.reflectance_exact.push(1.0);
            schlick = 0.0;
            exact = 0.0;
            break;
        }
        let theta_t = sin_t.asin();
        let rs = t.fresnel_schlick(cos_i as f32, eta_i as f32, eta_t as f32) as f64;
        let re = fresnel_dielectric_f64(cos_i, eta_i, eta_t);
        r.reflectance_schlick.push(rs);
        r.reflectance_exact.push(re);
        schlick *= 1.0 - rs;
        exact *= 1.0 - re;
        if let Some(slab) = stack.slabs.get(k) {
            let theta_in = r.theta[k].to_radians();
            r.perpendicular_shift
                .push(slab.thickness * (theta_in - theta_t).sin() / theta_t.cos());
            r.interface_offset.push(slab.thickness * theta_t.tan());
        }
        r.theta.push(theta_t.to_degrees());
    }
    r.transmitted_schlick = schlick;
    r.transmitted_exact = exact;
    r
}

pub fn schlick_r0(eta_i: f32, eta_t: f32) -> f32 {
    ((eta_i - eta_t) / (eta_i + eta_t)).powi(2)
}

pub fn fresnel_schlick(t: &impl Tasks, cos_theta_i: f32, eta_i: f32, eta_t: f32) -> f32 {
    if eta_i == eta_t {
        return 0.0;
    }
    let r0 = t.schlick_r0(eta_i, eta_t);
    let mut cos = cos_theta_i.clamp(0.0, 1.0);
    if eta_i > eta_t {
        let sin2_t = (eta_i / eta_t).powi(2) * (1.0 - cos * cos);
        if sin2_t >= 1.0 {
            return 1.0;
        }
        cos = (1.0 - sin2_t).max(0.0).sqrt();
    }
    r0 + (1.0 - r0) * (1.0 - cos).powi(5)
}

pub fn cosine_sample(u: Vec2) -> Vec3 {
    let r = u.x.sqrt();
    let phi = 2.0 * PI * u.y;
    Vec3::new(r * phi.cos(), r * phi.sin(), (1.0 - u.x).max(0.0).sqrt())
}

pub fn cosine_pdf(w: Vec3) -> f32 {
    w.z.max(0.0) * FRAC_1_PI
}

pub fn smith_g1(w: Vec3, alpha: f32) -> f32 {
    if w.z <= 0.0 {
        return 0.0;
    }
    let c = w.z.min(1.0);
    let a2 = alpha * alpha;
    2.0 * c / (c + (a2 + (1.0 - a2) * c * c).sqrt())
}

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
    let h = (wo + wi).normalize();
    let d = t.aniso_ndf(h, alpha_x, alpha_y);
    let g = t.smith_g1(wo, projected_alpha(wo, alpha_x, alpha_y))
        * t.smith_g1(wi, projected_alpha(wi, alpha_x, alpha_y));
    let f = f0 + (Vec3::ONE - f0) * (1.0 - wo.dot(h).clamp(0.0, 1.0)).powi(5);
    f * (d * g / (4.0 * wo.z.min(1.0) * wi.z.min(1.0)))
}

pub fn aniso_ndf(h: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
    if h.z <= 0.0 {
        return 0.0;
    }
    let (ax, ay) = (alpha_x.max(ALPHA_MIN), alpha_y.max(ALPHA_MIN));
    let d = h.x * h.x / (ax * ax) + h.y * h.y / (ay * ay) + h.z * h.z;
    1.0 / (PI * ax * ay * d * d)
}

pub fn phong(t: &impl Tasks, wo: Vec3, wi: Vec3, params: &PhongParams) -> Vec3 {
    if wo.z <= 0.0 || wi.z <= 0.0 {
        return Vec3::ZERO;
    }
    let lobe = t
        .reflect(wi, Vec3::Z)
        .dot(wo)
        .max(0.0)
        .powf(params.exponent);
    params.kd * FRAC_1_PI + params.ks * ((params.exponent + 2.0) / (2.0 * PI) * lobe)
}

pub fn reciprocity_gap(
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut Sampler,
    pairs: usize,
) -> f32 {
    let mut gap: f32 = 0.0;
    for _ in 0..pairs {
        let (a, b) = (
            uniform_hemisphere(sampler.next_2d()),
            uniform_hemisphere(sampler.next_2d()),
        );
        let (fab, fba) = (brdf(a, b), brdf(b, a));
        let scale = fab.abs().max(fba.abs());
        if scale > 0.0 {
            gap = gap.max((fab - fba).abs() / scale);
        }
    }
    gap
}

pub fn kajiya_kay(wo: Vec3, wi: Vec3, tangent: Vec3, params: &KajiyaKayParams) -> Vec3 {
    let (cos_i, cos_o) = (
        tangent.dot(wi).clamp(-1.0, 1.0),
        tangent.dot(wo).clamp(-1.0, 1.0),
    );
    let (sin_i, sin_o) = (
        (1.0 - cos_i * cos_i).max(0.0).sqrt(),
        (1.0 - cos_o * cos_o).max(0.0).sqrt(),
    );
    let cone = (sin_i * sin_o - cos_i * cos_o).max(0.0);
    params.kd * sin_i + params.ks * cone.powf(params.exponent)
}

pub fn beckmann_ndf(h: Vec3, alpha: f32) -> f32 {
    if h.z <= 0.0 {
        return 0.0;
    }
    let alpha = alpha.max(ALPHA_MIN);
    let c2 = h.z * h.z;
    let e = (-(1.0 - c2).max(0.0) / c2 / (alpha * alpha)).exp();
    if e == 0.0 {
        return 0.0;
    }
    e / (PI * alpha * alpha * c2 * c2)
}

pub fn ndf_sample(t: &impl Tasks, wo: Vec3, alpha_x: f32, alpha_y: f32, u: Vec2) -> Option<Vec3> {
    if wo.z <= 0.0 {
        return None;
    }
    let r = (u.x / (1.0 - u.x)).sqrt();
    let phi = 2.0 * PI * u.y;
    let h = Vec3::new(alpha_x * r * phi.cos(), alpha_y * r * phi.sin(), 1.0).normalize();
    if wo.dot(h) <= 0.0 {
        return None;
    }
    let wi = t.reflect(wo, h);
    (wi.z > 0.0).then_some(wi)
}

pub fn ndf_pdf(t: &impl Tasks, wo: Vec3, wi: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
    if wo.z <= 0.0 || wi.z <= 0.0 {
        return 0.0;
    }
    let h = (wo + wi).normalize();
    let wo_h = wo.dot(h);
    if wo_h <= 0.0 {
        return 0.0;
    }
    t.aniso_ndf(h, alpha_x, alpha_y) * h.z / (4.0 * wo_h)
}

pub fn brdf_check(
    t: &impl Tasks,
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut Sampler,
    samples: usize,
) -> PlausibilityReport {
    let mut report = PlausibilityReport {
        min_value: f32::INFINITY,
        max_reciprocity_error: t.reciprocity_gap(brdf, sampler, samples),
        ..PlausibilityReport::default()
    };
    for k in 0..8 {
        let cos_i = 1.0 - k as f32 / 8.0;
        let wi = Vec3::new((1.0 - cos_i * cos_i).sqrt(), 0.0, cos_i);
        let mut albedo = 0.0;
        for _ in 0..samples {
            let wo = uniform_hemisphere(sampler.next_2d());
            let f = brdf(wi, wo);
            report.min_value = report.min_value.min(f);
            albedo += f * wo.z * 2.0 * PI;
        }
        albedo /= samples.max(1) as f32;
        if albedo > report.max_albedo || k == 0 {
            report.max_albedo = albedo;
            report.worst_wi = wi;
        }
    }
    report
}
