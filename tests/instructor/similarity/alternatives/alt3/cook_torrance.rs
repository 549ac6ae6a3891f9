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
    let n_dot_v = wo.z;
    let n_dot_l = wi.z;
    if n_dot_v > 0.0 && n_dot_l > 0.0 {
        let sum = wi + wo;
        let l2 = sum.dot(sum);
        if l2 > 1e-12 {
            let m = sum * l2.sqrt().recip();
            let v_dot_m = wo.dot(m).clamp(0.0, 1.0);
            let spec_d = t.aniso_ndf(m, alpha_x, alpha_y);
            let g_v = t.smith_g1(wo, projected_alpha(wo, alpha_x, alpha_y));
            let g_l = t.smith_g1(wi, projected_alpha(wi, alpha_x, alpha_y));
            let f = f0 + (1.0 - f0) * schlick_weight(v_dot_m);
            return f * spec_d * g_v * g_l * 0.25 / (n_dot_v * n_dot_l);
        }
    }
    Vec3::ZERO
}
