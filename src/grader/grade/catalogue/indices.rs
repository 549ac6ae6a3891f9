//! Declarations and draws shared by the tasks with refractive indices (`refract_stack`,
//! `fresnel_schlick`).

use crate::grade::call::Call;
use crate::grade::domain::{Boundary, Draw, Param, Spread};

/// Indices of refraction the grader draws, as the exercise texts state them: vacuum to
/// germanium (its index in the infrared, the highest of common optical materials), so
/// ratios far from 1 (1/4 and 4) are drawn as well as near 1.
pub const ETA: (f64, f64) = (1.0, 4.0);

/// A ratio of two indices drawn from [`ETA`], `η_i/η_t` (or of neighbours), with equal
/// indices (no interface) as its boundary.
pub const fn index_ratio(
    function: &'static str,
    name: &'static str,
    covers: &'static [&'static str],
    value: fn(&Call) -> Option<f64>,
) -> Param {
    Param::new(function, name, covers, value, ETA.0 / ETA.1, ETA.1 / ETA.0)
        .spread(Spread::Log {
            from: ETA.0 / ETA.1,
            to: ETA.1 / ETA.0,
        })
        .boundaries(EQUAL_INDICES)
        .resolution(1e-6)
}

/// `sin²θt` (or its largest over a stack's media) for indices from [`ETA`], with the
/// critical angle as its boundary. Left open: on the critical angle itself, `≥` and `>`
/// are both right in f32, and `cos θt` is 0 or a few 1e-4 as rounding falls.
pub const fn critical(
    function: &'static str,
    name: &'static str,
    covers: &'static [&'static str],
    value: fn(&Call) -> Option<f64>,
) -> Param {
    Param::new(
        function,
        name,
        covers,
        value,
        0.0,
        (ETA.1 / ETA.0) * (ETA.1 / ETA.0),
    )
    .boundaries(CRITICAL_ANGLE)
    .resolution(1e-5)
    .open()
}

/// The boundary of a ratio of indices at 1: equal indices, no interface.
pub const EQUAL_INDICES: &[Boundary] = &[Boundary {
    at: 1.0,
    what: "equal indices",
    continuous: false,
}];

/// The boundary of `sin²θt` at 1: the critical angle, past which all light reflects.
pub const CRITICAL_ANGLE: &[Boundary] = &[Boundary {
    at: 1.0,
    what: "the critical angle (total internal reflection past it)",
    continuous: false,
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
