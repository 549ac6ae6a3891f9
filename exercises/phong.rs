//! # Task `phong` — the Phong BRDF and a reciprocity test (worksheet §4.2)
//!
//! The energy-normalised Phong BRDF puts a diffuse part and a lobe around the mirror
//! direction: `f = kd/π + ks (n + 2)/(2π) max(0, r·wo)^n`, where `r` is the mirror image of
//! `wi` about the normal and `n` the exponent ([`PhongParams`]). The factor `(n + 2)/(2π)`
//! makes the lobe's albedo exactly 1 at normal incidence (less elsewhere, where the horizon
//! cuts the lobe).
//!
//! ## What to compute
//! - [`phong`]: the BRDF for local directions (z = normal, both away from the surface). Use
//!   your `t.reflect(..)` for `r`. Return 0 when either direction is below the surface.
//! - [`reciprocity_gap`]: a numerical test of Helmholtz reciprocity for **any** BRDF given as
//!   a closure `brdf(wi, wo)`. Draw `pairs` random pairs of directions on the upper
//!   hemisphere ([`crate::sampling::uniform_hemisphere`] with `sampler.next_2d()`), evaluate
//!   both orders, and return the largest relative difference
//!   `|f(a,b) − f(b,a)| / max(|f(a,b)|, |f(b,a)|)`. A pair where both values are 0 counts 0.
//!   Think about what a NaN or infinite value should do to the answer: a test that
//!   silently skips them would call a broken BRDF reciprocal.
//!
//! ## Edge cases
//! - Clamp `r·wo` at 0 **before** the power: a negative base with a fractional exponent
//!   (10.5) is NaN, and with an even one it lights a lobe that should not exist.
//! - An exponent of 0 is allowed. Where `r·wo > 0` the lobe is then `ks/π`; where
//!   `r·wo ≤ 0` the formula as written gives `max(0, r·wo)^0 = 1` (what `powf` gives) and
//!   the limit `n → 0⁺` gives 0: either is accepted, but it must be one of the two (a
//!   power computed as `exp(n ln x)` gives NaN there).
//! - The graded directions include cosines down to the smallest positive f32 (`1e-45`, a
//!   subnormal), where `cos²θ` and `cos⁴θ` underflow to 0 and `tan θ` overflows, and
//!   directions exactly along the frame's axes: the answer must stay finite there.
//!
//! ## What the worksheet gets wrong
//! It asks you to show that this BRDF violates reciprocity. It does not: write `r(wi)·wo`
//! out with the reflection formula and you will find an expression symmetric in `wi` and
//! `wo`, so swapping them changes nothing (your `reciprocity_gap` should find a gap at the
//! level of float rounding). The model that is *not* reciprocal is the original Phong
//! *shading* formula, whose implied BRDF divides the lobe by `cos θi`. The sheet's remark
//! that Blinn-Phong was introduced to fix this rests on the same mistake.

use crate::prelude::*;

/// The Phong BRDF of `params` for unit local directions `wo` and `wi` (z = normal, both
/// pointing away from the surface); 0 when either is at or below the surface.
pub fn phong(t: &impl Tasks, wo: Vec3, wi: Vec3, params: &PhongParams) -> Vec3 {
    todo!()
}

/// The largest relative reciprocity error of `brdf(wi, wo)` over `pairs` random pairs of
/// directions on the upper hemisphere, drawn with `sampler`. 0 means "reciprocal as far as
/// the test can tell"; a non-finite BRDF value must not go unnoticed.
pub fn reciprocity_gap(
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut Sampler,
    pairs: usize,
) -> f32 {
    todo!()
}
