use crate::optics::fresnel_dielectric_f64;
use crate::prelude::*;

pub fn refract(wi: Vec3, n: Vec3, eta_i: f32, eta_t: f32) -> Option<Vec3> {
    let d = wi.normalize();
    let mut normal = n.normalize();
    let mut c1 = normal.dot(d);
    // the normal has to be on the side of wi
    if c1 < 0.0 {
        normal = -normal;
        c1 = -c1;
    }
    let c1 = c1.clamp(0.0, 1.0);
    let ratio = eta_i / eta_t;
    let k = 1.0 - ratio * ratio * (1.0 - c1 * c1);
    if k <= 0.0 {
        // total internal reflection (also exactly at the critical angle)
        return None;
    }
    let c2 = k.sqrt();
    let out = (ratio * c1 - c2) * normal - ratio * d;
    Some(out.normalize())
}

pub fn critical_angle(eta_i: f64, eta_t: f64) -> Option<f64> {
    if eta_i <= eta_t || eta_t <= 0.0 {
        return None;
    }
    let s = eta_t / eta_i;
    Some(s.asin())
}

pub fn refract_stack(t: &impl Tasks, theta_deg: f64, stack: &LayerStack) -> StackReport {
    let etas = stack.etas();
    let mut out = StackReport::default();
    out.theta.push(theta_deg);
    let mut sin_in = theta_deg.to_radians().sin();
    let mut i_schlick = stack.intensity;
    let mut i_exact = stack.intensity;
    let mut hit_tir = false;
    for idx in 0..stack.interfaces() {
        let n1 = etas[idx];
        let n2 = etas[idx + 1];
        let sin_out = n1 * sin_in / n2;
        if sin_out >= 1.0 {
            out.tir_at = Some(idx);
            out.reflectance_schlick.push(1.0);
            out.reflectance_exact.push(1.0);
            hit_tir = true;
            break;
        }
        let theta_in = sin_in.asin();
        let cos_in = theta_in.cos();
        let rs = t.fresnel_schlick(cos_in as f32, n1 as f32, n2 as f32) as f64;
        let re = fresnel_dielectric_f64(cos_in, n1, n2);
        out.reflectance_schlick.push(rs);
        out.reflectance_exact.push(re);
        i_schlick *= 1.0 - rs;
        i_exact *= 1.0 - re;
        let theta_out = sin_out.asin();
        out.theta.push(theta_out.to_degrees());
        if idx < stack.slabs.len() {
            let thickness = stack.slabs[idx].thickness;
            let shift = thickness * (theta_in - theta_out).sin() / theta_out.cos();
            out.perpendicular_shift.push(shift);
            out.interface_offset.push(thickness * theta_out.tan());
        }
        sin_in = sin_out;
    }
    if hit_tir {
        i_schlick = 0.0;
        i_exact = 0.0;
    }
    out.transmitted_schlick = i_schlick;
    out.transmitted_exact = i_exact;
    out
}
