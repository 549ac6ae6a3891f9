use crate::optics::fresnel_dielectric_f64;
use crate::prelude::*;

pub fn refract(wi: Vec3, n: Vec3, eta_i: f32, eta_t: f32) -> Option<Vec3> {
    let w = wi.normalize();
    let nn = if w.dot(n) < 0.0 { -n.normalize() } else { n.normalize() };
    let cos_theta_i = w.dot(nn).min(1.0);
    let sin2_theta_i = (1.0 - cos_theta_i * cos_theta_i).max(0.0);
    let eta = eta_i / eta_t;
    let sin2_theta_t = eta * eta * sin2_theta_i;
    if sin2_theta_t >= 1.0 {
        None
    } else {
        let cos_theta_t = (1.0 - sin2_theta_t).max(0.0).sqrt();
        let dir = -w * eta + nn * (eta * cos_theta_i - cos_theta_t);
        Some(dir.normalize())
    }
}

pub fn critical_angle(eta_i: f64, eta_t: f64) -> Option<f64> {
    match eta_t / eta_i {
        r if r > 0.0 && r < 1.0 => Some(r.asin()),
        _ => None,
    }
}

/// Geometry of one slab crossed at angle `inside`, entered from `outside` (radians).
fn slab_geometry(d: f64, outside: f64, inside: f64) -> (f64, f64) {
    let shift = d * (outside - inside).sin() / inside.cos();
    let along = d * inside.tan();
    (shift, along)
}

pub fn refract_stack(t: &impl Tasks, theta_deg: f64, stack: &LayerStack) -> StackReport {
    let etas = stack.etas();
    let snell = etas[0] * theta_deg.to_radians().sin();
    let mut angles = vec![theta_deg.to_radians()];
    let mut r_schlick = Vec::new();
    let mut r_exact = Vec::new();
    let mut tir_at = None;
    let mut k = 0;
    while k < stack.interfaces() {
        let sin_next = snell / etas[k + 1];
        if sin_next * sin_next >= 1.0 {
            tir_at = Some(k);
            r_schlick.push(1.0);
            r_exact.push(1.0);
            break;
        }
        let cos_here = angles[k].cos();
        let schlick = t.fresnel_schlick(cos_here as f32, etas[k] as f32, etas[k + 1] as f32);
        r_schlick.push(f64::from(schlick));
        r_exact.push(fresnel_dielectric_f64(cos_here, etas[k], etas[k + 1]));
        angles.push(sin_next.asin());
        k += 1;
    }
    let mut shifts = Vec::new();
    let mut offsets = Vec::new();
    for (j, slab) in stack.slabs.iter().enumerate() {
        if j + 1 >= angles.len() {
            break;
        }
        let (s, o) = slab_geometry(slab.thickness, angles[j], angles[j + 1]);
        shifts.push(s);
        offsets.push(o);
    }
    let through = |rs: &[f64]| -> f64 {
        if tir_at.is_some() {
            0.0
        } else {
            rs.iter().fold(stack.intensity, |acc, r| acc * (1.0 - r))
        }
    };
    StackReport {
        theta: angles.iter().map(|a| a.to_degrees()).collect(),
        tir_at,
        transmitted_schlick: through(&r_schlick),
        transmitted_exact: through(&r_exact),
        reflectance_schlick: r_schlick,
        reflectance_exact: r_exact,
        perpendicular_shift: shifts,
        interface_offset: offsets,
        ..StackReport::default()
    }
}
