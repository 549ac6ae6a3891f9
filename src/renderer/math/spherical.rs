//! Trigonometry of a direction in the local shading frame (z = normal), pbrt style.
//! Every function clamps where rounding could leave the valid range, so a unit vector whose
//! f32 length squared is 1.0000001 never produces a NaN.

use glam::Vec3;

/// cos θ of a local direction: its z component.
#[inline]
pub fn cos_theta(w: Vec3) -> f32 {
    w.z
}

/// |cos θ| of a local direction.
#[inline]
pub fn abs_cos_theta(w: Vec3) -> f32 {
    w.z.abs()
}

/// cos² θ of a local direction.
#[inline]
pub fn cos2_theta(w: Vec3) -> f32 {
    w.z * w.z
}

/// sin² θ, clamped at zero against rounding.
#[inline]
pub fn sin2_theta(w: Vec3) -> f32 {
    (1.0 - cos2_theta(w)).max(0.0)
}

/// sin θ, never NaN.
#[inline]
pub fn sin_theta(w: Vec3) -> f32 {
    sin2_theta(w).sqrt()
}

/// tan² θ (infinite at grazing).
#[inline]
pub fn tan2_theta(w: Vec3) -> f32 {
    sin2_theta(w) / cos2_theta(w)
}

/// cos φ of a local direction (1 when θ = 0, where φ is undefined).
#[inline]
pub fn cos_phi(w: Vec3) -> f32 {
    let s = sin_theta(w);
    if s == 0.0 {
        1.0
    } else {
        (w.x / s).clamp(-1.0, 1.0)
    }
}

/// sin φ of a local direction (0 when θ = 0, where φ is undefined).
#[inline]
pub fn sin_phi(w: Vec3) -> f32 {
    let s = sin_theta(w);
    if s == 0.0 {
        0.0
    } else {
        (w.y / s).clamp(-1.0, 1.0)
    }
}

/// True when two local directions lie on the same side of the surface.
#[inline]
pub fn same_hemisphere(a: Vec3, b: Vec3) -> bool {
    a.z * b.z > 0.0
}

/// The local direction with polar angle θ (from +z) and azimuth φ (from +x), from their
/// sine and cosine.
#[inline]
pub fn spherical_direction(sin_theta: f32, cos_theta: f32, phi: f32) -> Vec3 {
    let (sin_phi, cos_phi) = phi.sin_cos();
    Vec3::new(sin_theta * cos_phi, sin_theta * sin_phi, cos_theta)
}
