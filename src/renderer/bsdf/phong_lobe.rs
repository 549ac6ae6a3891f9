//! Sampling the specular lobe of the Phong BRDF: directions around the mirror direction `r`
//! with density `(n + 1)/(2π) cos^n α`, α the angle to `r` (Lafortune and Willems 1994).

use crate::math::Frame;
use glam::{Vec2, Vec3};
use std::f32::consts::PI;

/// A direction around the unit vector `r` with density `(n + 1)/(2π) max(0, cos α)^n`.
pub fn sample(r: Vec3, exponent: f32, u: Vec2) -> Vec3 {
    let cos_a = u.x.powf(1.0 / (exponent + 1.0));
    let sin_a = (1.0 - cos_a * cos_a).max(0.0).sqrt();
    let phi = 2.0 * PI * u.y;
    Frame::from_normal(r).to_world(Vec3::new(sin_a * phi.cos(), sin_a * phi.sin(), cos_a))
}

/// The density of [`sample`] per steradian at `w`.
pub fn pdf(r: Vec3, exponent: f32, w: Vec3) -> f32 {
    let c = r.dot(w);
    if c <= 0.0 {
        0.0
    } else {
        (exponent + 1.0) / (2.0 * PI) * c.powf(exponent)
    }
}
