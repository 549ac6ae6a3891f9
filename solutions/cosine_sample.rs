//! Reference for task `cosine_sample`.

use crate::prelude::*;
use std::f32::consts::{FRAC_1_PI, PI};

/// Inverts the marginal CDF `sin²θ` of the density `cos θ / π`: `sin²θ = u.y`, so
/// `cos θ = sqrt(1 − u.y)`, and `φ = 2π u.x` uniformly. With `u.y < 1` the direction is
/// strictly above the surface, so its pdf is never 0.
pub fn cosine_sample(u: Vec2) -> Vec3 {
    let sin2_theta = u.y;
    let cos_theta = (1.0 - sin2_theta).max(0.0).sqrt();
    let sin_theta = sin2_theta.max(0.0).sqrt();
    let (sin_phi, cos_phi) = (2.0 * PI * u.x).sin_cos();
    Vec3::new(sin_theta * cos_phi, sin_theta * sin_phi, cos_theta)
}

/// `cos θ / π` above the surface, 0 at or below it.
pub fn cosine_pdf(w: Vec3) -> f32 {
    if w.z > 0.0 { w.z * FRAC_1_PI } else { 0.0 }
}
