//! Reference for task `smith_g1`.

use crate::prelude::*;

/// GGX Smith G1 in its cosine form `2c / (c + sqrt(α² (1 − c²) + c²))`, `c = cos θ`.
///
/// This is `1 / (1 + Λ)` with `Λ = (sqrt(1 + α² tan²θ) − 1) / 2` multiplied through by `c`,
/// and unlike the tangent form it has no cancellation for small `α tan θ`, no infinity at
/// grazing, and gives the right limits: 1 at `α = 0`, `≈ 2c/α` as `c → 0`. Directions at or
/// below the horizon are fully masked (the bare formula goes negative there). The root is
/// a `hypot`, so that `c²` underflowing (c below about 1e-19 in f32) cannot make it 0: with
/// `α = 0` it is `c` however small.
pub fn smith_g1(w: Vec3, alpha: f32) -> f32 {
    let c = w.z.min(1.0);
    if c <= 0.0 {
        return 0.0;
    }
    let root = c.hypot(alpha * (1.0 - c * c).max(0.0).sqrt());
    2.0 * c / (c + root)
}
