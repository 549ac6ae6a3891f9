//! The contract of `ndf_pdf` in f64 (see [`crate::grade::contract`]). The sampler itself is
//! judged by its distribution and its Jacobian, not by value.

use crate::grade::call::Call;
use crate::grade::output::Output;
use crate::tasks::aniso_ndf::contract::aniso_ndf;
use glam::DVec3;

/// The density per steradian of `wi` when the half vector is drawn from the anisotropic
/// GGX NDF and `wo` reflected about it: `D(h) cos θh / (4 wo·h)`, 0 when `wi` is at or
/// below the surface, `wo + wi` vanishes, or `h` faces away from the normal or from `wo`.
pub fn ndf_pdf(wo: DVec3, wi: DVec3, alpha_x: f64, alpha_y: f64) -> f64 {
    if wi.z <= 0.0 {
        return 0.0;
    }
    let sum = wo + wi;
    let len2 = sum.length_squared();
    if len2 <= 1e-12 {
        return 0.0;
    }
    let h = sum / len2.sqrt();
    let wo_dot_h = wo.dot(h);
    if h.z <= 0.0 || wo_dot_h <= 0.0 {
        return 0.0;
    }
    aniso_ndf(h, alpha_x, alpha_y) * h.z / (4.0 * wo_dot_h)
}

/// The contract's answer to a call of this task's functions; `None` for any other call.
pub fn expected(call: &Call) -> Option<Output> {
    match call {
        Call::ndf_pdf {
            wo,
            wi,
            alpha_x,
            alpha_y,
        } => Some(Output::Number(ndf_pdf(
            wo.as_dvec3(),
            wi.as_dvec3(),
            *alpha_x as f64,
            *alpha_y as f64,
        ))),
        _ => None,
    }
}
