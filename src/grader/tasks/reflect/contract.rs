//! The contract of `reflect` in f64 (see [`crate::grade::contract`]).

use crate::grade::call::Call;
use crate::grade::contract::vector;
use crate::grade::output::Output;
use glam::DVec3;

/// The mirror of `wo` about the normal `n` (any non-zero length): the part of `wo` along
/// `n` kept, its part in the surface plane reversed, `2 (wo·n) n / |n|² − wo`.
pub fn reflect(wo: DVec3, n: DVec3) -> DVec3 {
    n * (2.0 * wo.dot(n) / n.length_squared()) - wo
}

/// The contract's answer to a call of this task's functions; `None` for any other call.
pub fn expected(call: &Call) -> Option<Output> {
    match call {
        Call::reflect { wo, n } => Some(vector(reflect(wo.as_dvec3(), n.as_dvec3()))),
        _ => None,
    }
}
