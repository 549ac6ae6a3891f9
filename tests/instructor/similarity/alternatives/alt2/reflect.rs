use crate::prelude::*;

pub fn reflect(wo: Vec3, n: Vec3) -> Vec3 {
    let len2 = n.dot(n);
    if len2 == 0.0 {
        return -wo;
    }
    let k = 2.0 * wo.dot(n) / len2;
    Vec3::new(k * n.x - wo.x, k * n.y - wo.y, k * n.z - wo.z)
}
