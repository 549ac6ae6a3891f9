use crate::prelude::*;
use std::f32::consts::{FRAC_PI_2, FRAC_PI_4, PI};

fn concentric_disk(u: Vec2) -> (f32, f32) {
    let a = 2.0 * u.x - 1.0;
    let b = 2.0 * u.y - 1.0;
    if a == 0.0 && b == 0.0 {
        return (0.0, 0.0);
    }
    let (r, theta) = if a.abs() > b.abs() {
        (a, FRAC_PI_4 * (b / a))
    } else {
        (b, FRAC_PI_2 - FRAC_PI_4 * (a / b))
    };
    (r * theta.cos(), r * theta.sin())
}

pub fn cosine_sample(u: Vec2) -> Vec3 {
    let (dx, dy) = concentric_disk(u);
    let h = 1.0 - dx * dx - dy * dy;
    Vec3::new(dx, dy, if h > 0.0 { h.sqrt() } else { 0.0 })
}

pub fn cosine_pdf(w: Vec3) -> f32 {
    let c = w.z;
    match c > 0.0 {
        true => c * (1.0 / PI),
        false => 0.0,
    }
}
