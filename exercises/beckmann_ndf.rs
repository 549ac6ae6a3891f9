//! # Task `beckmann_ndf` — the Beckmann distribution (worksheet §3.4.3)
//!
//! Beckmann's distribution models microfacet slopes as Gaussian, so its tail dies off much
//! faster than GGX's. For a unit local `h` above the surface with `cos θh = h.z`, the
//! worksheet gives `D(h) = exp(−tan²θh / α²) / (π α² cos⁴θh)`; it is normalised so that
//! `∫ D cos θh dω = 1`.
//!
//! ## Edge cases
//! - `cos θh = 0` exactly: `tan²θh` is infinite and `cos⁴θh` is 0, so the formula computes
//!   `0 / 0`. The limit is 0.
//! - In f32, `cos⁴θh` underflows to 0 already for `cos θh ≈ 1e-12`, again 0/0. By then the
//!   exponential has long been 0: return 0.
//! - `h` below the surface: 0.
//! - `α = 0` is a delta distribution: raise α to [`crate::bsdf::MIN_ALPHA`].
//! - The graded directions include cosines down to the smallest positive f32 (`1e-45`, a
//!   subnormal), where `cos²θ` and `cos⁴θ` underflow to 0 and `tan θ` overflows, and
//!   directions exactly along the frame's axes: the answer must stay finite there.
//!
//! ## What the worksheet gets wrong
//! At θ = 85° it uses the half vector (0.707, 0, 0.707), which belongs to θ = 90°. The half
//! vector between `n` and a direction at θ is at θ/2: 42.5°, so `tan²θh/α² ≈ 83.97`, not
//! 100. (Its conclusion "≈ 0" survives.) At 60° it prints `e^−33.3 ≈ 3.7e-15`; it is
//! 3.34e-15.
//!
//! ## Check yourself (α = 0.1, i = n, o at 0°, 60°, 85°, so θh = 0°, 30°, 42.5°)
//! 31.8309886, 1.889056e-13, 3.683271e-35.

use crate::prelude::*;

/// The Beckmann density of the unit local microfacet normal `h`, per steradian, for
/// roughness `alpha`; 0 at or below the horizon and wherever f32 underflows.
pub fn beckmann_ndf(h: Vec3, alpha: f32) -> f32 {
    todo!()
}
