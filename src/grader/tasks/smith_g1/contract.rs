//! The contract of `smith_g1` in f64 (see [`crate::grade::contract`]).

use crate::grade::call::Call;
use crate::grade::output::Output;
use glam::DVec3;

/// Smith's masking of the GGX NDF of roughness `alpha` for the direction `w` (its cosine
/// `w.z`, at most 1): `2 cos θ / (cos θ + √(cos²θ + α² sin²θ))`, which is `1 / (1 + Λ)`
/// written without `tan θ`; 0 at or below the horizon, 1 for a mirror (`α = 0`).
pub fn smith_g1(w: DVec3, alpha: f64) -> f64 {
    let c = w.z.min(1.0);
    if c <= 0.0 {
        return 0.0;
    }
    let root = c.hypot(alpha * (1.0 - c * c).max(0.0).sqrt());
    2.0 * c / (c + root)
}

/// The contract's answer to a call of this task's functions; `None` for any other call.
pub fn expected(call: &Call) -> Option<Output> {
    match call {
        Call::smith_g1 { w, alpha } => {
            Some(Output::Number(smith_g1(w.as_dvec3(), *alpha as f64)))
        }
        _ => None,
    }
}
