use crate::prelude::*;
use std::f32::consts::PI;

pub fn cosine_sample(u: Vec2) -> Vec3 {
    // Malley's method: uniform point on the unit disk, lifted onto the hemisphere
    let r = u.x.sqrt();
    let phi = 2.0 * PI * u.y;
    let x = r * phi.cos();
    let y = r * phi.sin();
    let z = (1.0 - x * x - y * y).max(0.0).sqrt();
    Vec3::new(x, y, z)
}

pub fn cosine_pdf(w: Vec3) -> f32 {
    if w.z <= 0.0 {
        return 0.0;
    }
    w.z / PI
}
