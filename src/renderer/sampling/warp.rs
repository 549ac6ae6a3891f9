//! Uniform warps from [0,1)² to directions. Directions are in the local frame (z = normal).

use glam::{Vec2, Vec3};
use std::f32::consts::{FRAC_1_PI, PI};

/// A direction uniform on the upper hemisphere (z ≥ 0); pdf 1/(2π) per steradian.
pub fn uniform_hemisphere(u: Vec2) -> Vec3 {
    let z = u.x;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = 2.0 * PI * u.y;
    Vec3::new(r * phi.cos(), r * phi.sin(), z)
}

/// The pdf of [`uniform_hemisphere`] per steradian.
pub fn uniform_hemisphere_pdf() -> f32 {
    0.5 * FRAC_1_PI
}

/// A direction uniform on the whole sphere; pdf 1/(4π) per steradian.
pub fn uniform_sphere(u: Vec2) -> Vec3 {
    let z = 1.0 - 2.0 * u.x;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = 2.0 * PI * u.y;
    Vec3::new(r * phi.cos(), r * phi.sin(), z)
}

/// The pdf of [`uniform_sphere`] per steradian.
pub fn uniform_sphere_pdf() -> f32 {
    0.25 * FRAC_1_PI
}
