use crate::bsdf::MIN_ALPHA;
use crate::prelude::*;
use std::f32::consts::TAU;

fn half_vector(a: Vec3, b: Vec3) -> Option<Vec3> {
    let s = a + b;
    let n2 = s.length_squared();
    (n2 > 1e-12).then(|| s / n2.sqrt())
}

pub fn ndf_sample(t: &impl Tasks, wo: Vec3, alpha_x: f32, alpha_y: f32, u: Vec2) -> Option<Vec3> {
    let (ax, ay) = (alpha_x.abs().max(MIN_ALPHA), alpha_y.abs().max(MIN_ALPHA));
    let cos2 = 1.0 - u.x;
    let sin_t = (1.0 - cos2).max(0.0).sqrt();
    let cos_t = cos2.max(0.0).sqrt();
    let phi = TAU * u.y;
    let h = Vec3::new(ax * sin_t * phi.cos(), ay * sin_t * phi.sin(), cos_t).normalize();
    match wo.dot(h) > 0.0 {
        false => None,
        true => {
            let wi = t.reflect(wo, h);
            if wi.z > 0.0 { Some(wi) } else { None }
        }
    }
}

pub fn ndf_pdf(t: &impl Tasks, wo: Vec3, wi: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
    if wi.z <= 0.0 {
        return 0.0;
    }
    let Some(h) = half_vector(wo, wi) else {
        return 0.0;
    };
    let cos_oh = wo.dot(h);
    if cos_oh > 0.0 && h.z > 0.0 {
        t.aniso_ndf(h, alpha_x, alpha_y) * h.z / (4.0 * cos_oh)
    } else {
        0.0
    }
}
