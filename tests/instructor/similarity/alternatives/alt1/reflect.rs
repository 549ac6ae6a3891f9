use crate::prelude::*;

pub fn reflect(wo: Vec3, n: Vec3) -> Vec3 {
    // project wo onto the normal direction (n may be non-unit)
    let n_hat = n.normalize();
    let along = n_hat * wo.dot(n_hat);
    2.0 * along - wo
}
