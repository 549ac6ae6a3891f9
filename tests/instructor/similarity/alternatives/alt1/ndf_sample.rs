use crate::bsdf::MIN_ALPHA;
use crate::prelude::*;
use std::f32::consts::PI;

pub fn ndf_sample(t: &impl Tasks, wo: Vec3, alpha_x: f32, alpha_y: f32, u: Vec2) -> Option<Vec3> {
    let ax = alpha_x.abs().max(MIN_ALPHA);
    let ay = alpha_y.abs().max(MIN_ALPHA);
    // GGX: tan^2(theta) = alpha^2 u / (1 - u), stretched per axis
    let phi = 2.0 * PI * u.y;
    let r = (u.x / (1.0 - u.x).max(1e-12)).sqrt();
    let m = Vec3::new(r * ax * phi.cos(), r * ay * phi.sin(), 1.0).normalize();
    let c = wo.dot(m);
    if c <= 0.0 {
        return None;
    }
    let wi = t.reflect(wo, m);
    if wi.z <= 0.0 { None } else { Some(wi) }
}

pub fn ndf_pdf(t: &impl Tasks, wo: Vec3, wi: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
    if wi.z <= 0.0 {
        return 0.0;
    }
    let h = wo + wi;
    let l = h.length();
    if l < 1e-6 {
        return 0.0;
    }
    let h = h / l;
    let woh = wo.dot(h);
    if woh <= 0.0 || h.z <= 0.0 {
        return 0.0;
    }
    let pdf = t.aniso_ndf(h, alpha_x, alpha_y) * h.z / (4.0 * woh);
    if pdf.is_finite() { pdf } else { 0.0 }
}
