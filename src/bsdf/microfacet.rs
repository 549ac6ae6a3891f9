use crate::math::{cos_phi, sin_phi};
use glam::Vec3;

/// The roughness an anisotropic GGX surface presents to the local direction `w`:
/// `sqrt(cos²φ αx² + sin²φ αy²)` (Heitz 2014, §5.3). Smith's G1 of an anisotropic surface is
/// the isotropic G1 evaluated with this roughness.
pub fn projected_alpha(w: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
    let (c, s) = (cos_phi(w), sin_phi(w));
    (c * c * alpha_x * alpha_x + s * s * alpha_y * alpha_y).sqrt()
}
