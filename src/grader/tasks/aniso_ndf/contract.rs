//! The contract of `aniso_ndf` in f64 (see [`crate::grade::contract`]).

use crate::grade::call::Call;
use crate::grade::contract::MIN_ALPHA;
use crate::grade::output::Output;
use glam::DVec3;
use std::f64::consts::FRAC_1_PI;

/// The anisotropic GGX density of half vectors `h` (local frame, z the normal) with
/// roughness `alpha_x` along x and `alpha_y` along y, each floored at [`MIN_ALPHA`]:
/// `1 / (π αx αy ((hx/αx)² + (hy/αy)² + hz²)²)`, 0 at or below the surface.
pub fn aniso_ndf(h: DVec3, alpha_x: f64, alpha_y: f64) -> f64 {
    if h.z <= 0.0 {
        return 0.0;
    }
    let ax = alpha_x.abs().max(MIN_ALPHA);
    let ay = alpha_y.abs().max(MIN_ALPHA);
    let (x, y) = (h.x / ax, h.y / ay);
    let s = x * x + y * y + h.z * h.z;
    FRAC_1_PI / (ax * ay * s * s)
}

/// The contract's answer to a call of this task's functions; `None` for any other call.
pub fn expected(call: &Call) -> Option<Output> {
    match call {
        Call::aniso_ndf {
            h,
            alpha_x,
            alpha_y,
        } => Some(Output::Number(aniso_ndf(
            h.as_dvec3(),
            *alpha_x as f64,
            *alpha_y as f64,
        ))),
        _ => None,
    }
}
