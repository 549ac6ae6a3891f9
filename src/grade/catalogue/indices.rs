//! Declarations and draws shared by the tasks with refractive indices (`refract_stack`,
//! `fresnel_schlick`).

use crate::grade::domain::{Boundary, Draw, Param};

/// The boundary of a ratio of indices at 1: equal indices, no interface.
pub const EQUAL_INDICES: &[Boundary] = &[Boundary {
    at: 1.0,
    what: "equal indices",
}];

/// The boundary of `sin²θt` at 1: the critical angle, past which all light reflects.
pub const CRITICAL_ANGLE: &[Boundary] = &[Boundary {
    at: 1.0,
    what: "the critical angle (total internal reflection past it)",
}];

/// `sin²θt` by Snell's law for incident cosine `cos_i` and index ratio `η_i/η_t`.
pub fn sin2_t(cos_i: f64, ratio: f64) -> f64 {
    ratio * ratio * (1.0 - cos_i * cos_i).max(0.0)
}

/// Two indices in `range` whose ratio `η_i/η_t` is drawn from `ratio` (equal indices
/// exactly equal).
pub fn eta_pair(d: &mut Draw, ratio: &Param, range: (f64, f64)) -> (f32, f32) {
    let r = d.value(ratio);
    let (lo, hi) = range;
    if r >= 1.0 {
        let eta_t = lo + (hi / r - lo).max(0.0) * d.unit();
        ((eta_t * r) as f32, eta_t as f32)
    } else {
        let eta_i = lo + (hi * r - lo).max(0.0) * d.unit();
        (eta_i as f32, (eta_i / r) as f32)
    }
}
