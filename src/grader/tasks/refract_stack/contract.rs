//! The contract of `refract` in f64 (see [`crate::grade::contract`]). `critical_angle` and
//! `refract_stack` take and return f64 already: their reference is their contract.

use crate::grade::call::Call;
use crate::grade::contract::vector;
use crate::grade::output::Output;
use glam::DVec3;

/// The direction Snell's law transmits `wi` (pointing away from the surface, on either
/// side of the normal `n`, both of any non-zero length) into, from index `eta_i` (`wi`'s
/// side) to `eta_t`: a unit vector on the other side, `None` under total internal
/// reflection.
pub fn refract(wi: DVec3, n: DVec3, eta_i: f64, eta_t: f64) -> Option<DVec3> {
    let wi = wi.normalize();
    let mut n = n.normalize();
    let mut cos_i = wi.dot(n);
    if cos_i < 0.0 {
        n = -n;
        cos_i = -cos_i;
    }
    let cos_i = cos_i.min(1.0);
    let eta = eta_i / eta_t;
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i).max(0.0);
    if sin2_t >= 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    Some((-eta * wi + (eta * cos_i - cos_t) * n).normalize())
}

/// The contract's answer to a call of this task's functions; `None` for any other call
/// and for the functions computed in f64 already.
pub fn expected(call: &Call) -> Option<Output> {
    match call {
        Call::refract { wi, n, eta_i, eta_t } => Some(
            refract(wi.as_dvec3(), n.as_dvec3(), *eta_i as f64, *eta_t as f64)
                .map_or(Output::Nothing, vector),
        ),
        _ => None,
    }
}
