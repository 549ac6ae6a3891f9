use crate::math::{cos_phi, sin_phi};
use glam::Vec3;

/// The smallest roughness the microfacet distributions evaluate (GGX, Beckmann, NDF
/// sampling). Roughness 0 is a perfect mirror: its NDF is a delta distribution, which a
/// density cannot represent (the formulas give 0/0 = NaN), so smaller values are raised to
/// this one. At `1e-4` the GGX peak `1/(π α²)` is 3.2e7, still far from f32 overflow.
pub const MIN_ALPHA: f32 = 1e-4;

/// The roughness an anisotropic GGX surface presents to the local direction `w`:
/// `sqrt(cos²φ αx² + sin²φ αy²)` (Heitz 2014, §5.3). Smith's G1 of an anisotropic surface is
/// the isotropic G1 evaluated with this roughness.
pub fn projected_alpha(w: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
    let (c, s) = (cos_phi(w), sin_phi(w));
    (c * c * alpha_x * alpha_x + s * s * alpha_y * alpha_y).sqrt()
}
