use crate::optics::fresnel_dielectric_f64;
use crate::prelude::*;

const NO_LIGHT: f64 = 0.0;

pub fn refract(wi: Vec3, n: Vec3, eta_i: f32, eta_t: f32) -> Option<Vec3> {
    let unit_n = n.normalize();
    let unit_w = wi.normalize();
    let side = unit_w.dot(unit_n).signum();
    let normal = unit_n * side;
    let cosi = unit_w.dot(normal).clamp(0.0, 1.0);
    let rel = eta_i / eta_t;
    let sint2 = rel * rel * (1.0 - cosi * cosi);
    if !(sint2 < 1.0) {
        return None;
    }
    let cost = (1.0 - sint2).max(0.0).sqrt();
    let t = normal * (rel * cosi - cost) - unit_w * rel;
    let len = t.length();
    if len > 0.0 { Some(t / len) } else { None }
}

pub fn critical_angle(eta_i: f64, eta_t: f64) -> Option<f64> {
    if eta_t > 0.0 && eta_t < eta_i {
        let angle = (eta_t / eta_i).asin();
        if angle.is_finite() {
            return Some(angle);
        }
    }
    None
}

fn reflectances(t: &impl Tasks, cos_i: f64, from: f64, to: f64) -> (f64, f64) {
    let approx = t.fresnel_schlick(cos_i as f32, from as f32, to as f32) as f64;
    (approx, fresnel_dielectric_f64(cos_i, from, to))
}

pub fn refract_stack(t: &impl Tasks, theta_deg: f64, stack: &LayerStack) -> StackReport {
    let mut rep = StackReport::default();
    let indices = stack.etas();
    let first = theta_deg.to_radians();
    rep.theta.push(theta_deg);
    let mut energy = (stack.intensity, stack.intensity);
    let mut current = first;
    for (i, pair) in indices.windows(2).enumerate().take(stack.interfaces()) {
        let (from, to) = (pair[0], pair[1]);
        let s = indices[0] * first.sin() / to;
        if s >= 1.0 || s <= -1.0 {
            rep.tir_at = Some(i);
            rep.reflectance_schlick.push(1.0);
            rep.reflectance_exact.push(1.0);
            energy = (NO_LIGHT, NO_LIGHT);
            break;
        }
        let (r_approx, r_true) = reflectances(t, current.cos(), from, to);
        rep.reflectance_schlick.push(r_approx);
        rep.reflectance_exact.push(r_true);
        energy.0 *= 1.0 - r_approx;
        energy.1 *= 1.0 - r_true;
        let next = s.asin();
        rep.theta.push(next.to_degrees());
        if let Some(layer) = stack.slabs.get(i) {
            let d = layer.thickness;
            rep.perpendicular_shift.push(d * (current - next).sin() / next.cos());
            rep.interface_offset.push(d * next.tan());
        }
        current = next;
    }
    rep.transmitted_schlick = energy.0;
    rep.transmitted_exact = energy.1;
    rep
}
