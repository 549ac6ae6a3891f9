//! # Task `smith_g1` — the GGX masking function (worksheet §3.2)
//!
//! A rough surface hides some of its microfacets from any direction behind other
//! microfacets. Smith's model gives the fraction still visible, `G1(w) = 1 / (1 + Λ(w))`, where
//! `Λ` is the projected area of the back-facing (hidden) microfacets relative to the
//! visible ones. For GGX, `Λ = (sqrt(1 + α² tan²θ) − 1) / 2`. The Cook-Torrance task
//! multiplies `G1(wo) G1(wi)`.
//!
//! ## Convention
//! `w` is a unit direction in the local frame, so `cos θ = w.z`; `alpha` is the GGX
//! roughness (0 is a mirror, 1 is very rough).
//!
//! ## Edge cases (each one breaks the formula as printed)
//! - **Below the horizon** (`cos θ ≤ 0`): nothing is visible, return 0. The worksheet's
//!   cosine form has no such factor and returns −6.19 for `cos θ = −0.5`, `α = 0.5`.
//! - **At the horizon** with `α = 0`: `tan θ` is infinite and `α tan θ` is `0 · ∞ = NaN`.
//! - **Tiny `α² tan²θ`** (smooth surfaces, near-normal directions): `sqrt(1 + a) − 1`
//!   cancels to exactly 0 in f32 for `a = 1e-8`. Rewrite it so nothing is subtracted, or use
//!   the cosine form that §3.2.3 asks you to derive.
//! - The graded directions include cosines down to the smallest positive f32 (`1e-45`, a
//!   subnormal), where `cos²θ` and `cos⁴θ` underflow to 0 and `tan θ` overflows, and
//!   directions exactly along the frame's axes: `G1 ≈ 2 cos θ / (α sin θ)` there, never
//!   NaN.
//!
//! ## What the worksheet gets wrong
//! It never derives `Λ`, and describes it as "the average slope of visible microfacets",
//! which is not what it is (see above). Its cosine form is right once the "above the
//! horizon" condition is added.
//!
//! ## Check yourself
//! `α = 1, cos θ = 0.5` → 2/3; `α = 0` → 1 above the horizon; `α = 0.5, cos θ = 1e-8` →
//! `≈ 4e-8` (≈ `2 cos θ / α`); `α = 0.5, θ = 85°` → 0.294037.

use crate::prelude::*;

/// Smith's masking `G1` of the unit local direction `w` for an isotropic GGX surface of
/// roughness `alpha`: in [0, 1], exactly 0 at or below the horizon, finite for `alpha = 0`.
pub fn smith_g1(w: Vec3, alpha: f32) -> f32 {
    todo!()
}
