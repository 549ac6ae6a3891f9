//! Random inputs for the random cases.

use crate::sampling::{Sampler, uniform_hemisphere, uniform_sphere};
use glam::Vec3;

/// Uniform in [lo, hi).
pub fn range(s: &mut Sampler, lo: f32, hi: f32) -> f32 {
    lo + (hi - lo) * s.next_1d()
}

/// Uniform in [lo, hi), in f64.
pub fn range64(s: &mut Sampler, lo: f64, hi: f64) -> f64 {
    lo + (hi - lo) * s.next_f64()
}

/// A direction uniform on the upper hemisphere with cos θ ≥ `min_cos`.
pub fn upper(s: &mut Sampler, min_cos: f32) -> Vec3 {
    let u = s.next_2d();
    let w = uniform_hemisphere(glam::Vec2::new(min_cos + (1.0 - min_cos) * u.x, u.y));
    w.normalize()
}

/// A direction uniform on the sphere.
pub fn sphere(s: &mut Sampler) -> Vec3 {
    uniform_sphere(s.next_2d()).normalize()
}

/// A roughness, log-uniform in [lo, hi] so small and large values are equally common.
pub fn roughness(s: &mut Sampler, lo: f32, hi: f32) -> f32 {
    (lo.ln() + (hi.ln() - lo.ln()) * s.next_1d()).exp()
}

/// An RGB colour with channels in [lo, hi).
pub fn colour(s: &mut Sampler, lo: f32, hi: f32) -> Vec3 {
    Vec3::new(range(s, lo, hi), range(s, lo, hi), range(s, lo, hi))
}

/// A refractive index between air and diamond.
pub fn eta(s: &mut Sampler) -> f32 {
    range(s, 1.0, 2.42)
}
