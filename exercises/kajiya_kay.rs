//! # Task `kajiya_kay` — the Kajiya-Kay hair fibre model (worksheet §4.3)
//!
//! A hair is a thin cylinder with tangent `t`. Light reflected by a mirror cylinder leaves on
//! a **cone** around the fibre: every outgoing direction that makes the same angle with `t`
//! as the incident light, on the other side (`t·wo = −t·wi`). Kajiya and Kay (1989) shade a
//! fibre with a diffuse term proportional to the sine of the light's angle to the fibre, and
//! a specular term that peaks on that cone.
//!
//! ## What to compute
//! With `cos θ = t·w` and `sin θ ≥ 0` for each of `wi` and `wo` (both pointing away from the
//! fibre; all three vectors in one frame, `t` of unit length):
//! - diffuse: `kd sin θi`;
//! - specular: `ks max(0, c)^p`, where `c` is the cosine of the angle between `wo` and the
//!   reflection cone. Work out `c` from `θi`, `θo` with the cone condition above (a
//!   trigonometric identity turns it into products of the sines and cosines).
//!
//! The model ignores azimuth around the fibre, so any `wo` at the right angle to `t` is on
//! the highlight. The specular term is symmetric in `wi` and `wo`; the diffuse term is not,
//! so the model as a whole is not reciprocal.
//!
//! ## Edge cases
//! - `t·w` from f32 vectors can be 1.0000001: `sqrt(1 − c²)` is then NaN. Clamp.
//! - Clamp the cone cosine at 0 before the power (a negative base with `p = 80.5` is NaN).
//! - `p = 0` is allowed. Where `c > 0` the specular term is then `ks`; where `c ≤ 0` the
//!   formula as written gives `max(0, c)^0 = 1` (what `powf` gives) and the limit `p → 0⁺`
//!   gives 0: either is accepted, but it must be one of the two.
//! - `wi` along the fibre (`sin θi = 0`) must give a finite value.
//!
//! ## What the worksheet gets wrong
//! - Its formula is not Kajiya-Kay's: the bracket it divides by `sin θi sin θo` is just
//!   `wi·wo`, so the "prefactor" is `wi·wo / (sin θi sin θo)` times a half-vector power.
//!   At the true mirror direction it gives **f = −1.7**, a negative BRDF; with `wi` along the
//!   fibre it divides by 0.
//! - Its "perfect specular" direction `wo = wi` is retro-reflection. The mirror cone for
//!   `wi = (0.5, 0, 0.866)` and `t = z` contains `(0.5, 0, −0.866)`.
//!
//! ## Check yourself (`kd = 0.1`, `ks = 0.9`, `p = 80`, `t = z`, `wi = (0.5, 0, √3/2)`)
//! `wo = (0, 0.5, √3/2)` → 0.05; `wo = wi` → 0.05; `wo = (0.5, 0, −√3/2)` → 0.95.

use crate::prelude::*;

/// The Kajiya-Kay shading value for directions `wo`, `wi` (pointing away from the fibre) and
/// the unit fibre `tangent`, all in one frame: `kd sin θi` plus `ks` times the `p`-th power of
/// the (clamped) cosine to the reflection cone. Non-negative and finite for every input.
pub fn kajiya_kay(wo: Vec3, wi: Vec3, tangent: Vec3, params: &KajiyaKayParams) -> Vec3 {
    todo!()
}
