//! The contract of `cosine_pdf` in f64 (see [`crate::grade::contract`]). The sampler itself
//! is judged by its distribution and its Jacobian, not by value.

use crate::grade::call::Call;
use crate::grade::output::Output;
use glam::DVec3;
use std::f64::consts::FRAC_1_PI;

/// The cosine-weighted density per steradian of the direction `w`: `cos θ / π` above the
/// surface, 0 at or below it.
pub fn cosine_pdf(w: DVec3) -> f64 {
    if w.z > 0.0 { w.z * FRAC_1_PI } else { 0.0 }
}

/// The contract's answer to a call of this task's functions; `None` for any other call.
pub fn expected(call: &Call) -> Option<Output> {
    match call {
        Call::cosine_pdf { w } => Some(Output::Number(cosine_pdf(w.as_dvec3()))),
        _ => None,
    }
}
