use crate::prelude::*;

fn lambda(cos_theta: f32, alpha: f32) -> f32 {
    let cos2 = cos_theta * cos_theta;
    let tan2 = (1.0 - cos2).max(0.0) / cos2;
    0.5 * ((1.0 + alpha * alpha * tan2).sqrt() - 1.0)
}

pub fn smith_g1(w: Vec3, alpha: f32) -> f32 {
    if w.z <= 0.0 {
        return 0.0;
    }
    let cos_theta = w.z.min(1.0);
    1.0 / (1.0 + lambda(cos_theta, alpha))
}
