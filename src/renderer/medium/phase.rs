use crate::math::Frame;
use glam::{Vec2, Vec3};
use std::f32::consts::PI;

/// The Henyey-Greenstein phase function with asymmetry `g ∈ (−1, 1)` (0 is isotropic,
/// positive scatters forwards). Directions point away from the scattering point, so
/// `cos θ = −wo · wi` is the cosine of the deflection angle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HenyeyGreenstein {
    /// Mean cosine of the deflection angle.
    pub g: f32,
}

impl HenyeyGreenstein {
    /// The phase function value (per steradian) for the pair `wo`, `wi`; it integrates to 1
    /// over `wi`.
    pub fn eval(&self, wo: Vec3, wi: Vec3) -> f32 {
        let cos = -wo.dot(wi);
        let g = self.g;
        let denom = 1.0 + g * g - 2.0 * g * cos;
        (1.0 - g * g) / (4.0 * PI * denom * denom.max(1e-12).sqrt())
    }

    /// Samples `wi` exactly proportionally to the phase function; the weight is 1.
    pub fn sample(&self, wo: Vec3, u: Vec2) -> Vec3 {
        let g = self.g;
        // Inverse of the cumulative distribution of cos θ (θ the deflection angle).
        let cos = if g.abs() < 1e-3 {
            1.0 - 2.0 * u.x
        } else {
            let s = (1.0 - g * g) / (1.0 - g + 2.0 * g * u.x);
            (1.0 + g * g - s * s) / (2.0 * g)
        }
        .clamp(-1.0, 1.0);
        let sin = (1.0 - cos * cos).max(0.0).sqrt();
        let phi = 2.0 * PI * u.y;
        // cos is measured from the propagation direction −wo.
        Frame::from_normal(-wo).to_world(Vec3::new(sin * phi.cos(), sin * phi.sin(), cos))
    }
}
