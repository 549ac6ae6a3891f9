//! Reference for task `reflect`.

use crate::prelude::*;

/// Mirror reflection of `wo` about `n`: `2 (wo·n̂) n̂ − wo` with `n̂ = n / |n|`.
///
/// Written as `2 (wo·n) n / (n·n) − wo`, which is the same vector without a square root and
/// stays right when `n` is not of unit length (the worksheet's formula, fed `n = (0, 2, 0)`,
/// scales the normal component by `|n|²`).
pub fn reflect(wo: Vec3, n: Vec3) -> Vec3 {
    n * (2.0 * wo.dot(n) / n.length_squared()) - wo
}
