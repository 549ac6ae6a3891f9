use crate::prelude::*;

pub fn smith_g1(w: Vec3, alpha: f32) -> f32 {
    let n_dot_v = w.z.clamp(-1.0, 1.0);
    if !(n_dot_v > 0.0) {
        return 0.0;
    }
    let a2 = alpha * alpha;
    let denom = n_dot_v + (a2 + (1.0 - a2) * n_dot_v * n_dot_v).sqrt();
    (2.0 * n_dot_v / denom).min(1.0)
}
