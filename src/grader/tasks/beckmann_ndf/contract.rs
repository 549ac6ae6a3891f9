//! The contract of `beckmann_ndf` in f64 (see [`crate::grade::contract`]).

use crate::grade::call::Call;
use crate::grade::contract::MIN_ALPHA;
use crate::grade::output::Output;
use glam::DVec3;
use std::f64::consts::FRAC_1_PI;

/// The Beckmann density of half vectors `h` (its cosine `h.z`, at most 1) with roughness
/// `alpha` floored at [`MIN_ALPHA`]: `exp(−tan²θ / α²) / (π α² cos⁴θ)`, 0 at or below the
/// surface (and where the exponential underflows, its limit).
pub fn beckmann_ndf(h: DVec3, alpha: f64) -> f64 {
    let c = h.z.min(1.0);
    if c <= 0.0 {
        return 0.0;
    }
    let cos2 = c * c;
    let a2 = alpha.abs().max(MIN_ALPHA).powi(2);
    let tan2 = (1.0 - cos2).max(0.0) / cos2;
    let falloff = (-tan2 / a2).exp();
    if falloff == 0.0 {
        return 0.0;
    }
    falloff * FRAC_1_PI / (a2 * cos2 * cos2)
}

/// The contract's answer to a call of this task's functions; `None` for any other call.
pub fn expected(call: &Call) -> Option<Output> {
    match call {
        Call::beckmann_ndf { h, alpha } => {
            Some(Output::Number(beckmann_ndf(h.as_dvec3(), *alpha as f64)))
        }
        _ => None,
    }
}
