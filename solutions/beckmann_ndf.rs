//! Reference for task `beckmann_ndf`.

use crate::bsdf::MIN_ALPHA;
use crate::prelude::*;
use std::f32::consts::FRAC_1_PI;

/// Beckmann `exp(−tan²θh / α²) / (π α² cos⁴θh)`.
///
/// 0 for `h` at or below the horizon, and 0 as soon as `cos⁴θh` underflows in f32 or the
/// exponential reaches 0: `α² cos⁴θh` may underflow too by then, and dividing would give
/// 0/0 = NaN. Roughness is raised to [`MIN_ALPHA`].
pub fn beckmann_ndf(h: Vec3, alpha: f32) -> f32 {
    let c = h.z.min(1.0);
    if c <= 0.0 {
        return 0.0;
    }
    let cos2 = c * c;
    let cos4 = cos2 * cos2;
    if cos4 == 0.0 {
        return 0.0;
    }
    let a2 = alpha.abs().max(MIN_ALPHA).powi(2);
    let tan2 = (1.0 - cos2).max(0.0) / cos2;
    let falloff = (-tan2 / a2).exp();
    if falloff == 0.0 {
        return 0.0;
    }
    falloff * FRAC_1_PI / (a2 * cos4)
}
