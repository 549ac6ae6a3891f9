//! # Task `fresnel_schlick` — reflectance by Schlick's approximation
//! (worksheet §1.3, §1.4.4, §3.4.2)
//!
//! The exact Fresnel equations for a smooth dielectric cost two square roots and a few
//! divisions; Schlick replaced them by a curve that starts at the normal-incidence
//! reflectance `R0` and rises to 1 at grazing: `R0 + (1 − R0)(1 − cos θ)^5`, with
//! `R0 = ((eta_i − eta_t)/(eta_i + eta_t))²`. The renderer's glass and the layer-stack task
//! use your version. ([`crate::optics::schlick_weight`] computes the `(1 − cos θ)^5` factor
//! with its clamping, if you want it.)
//!
//! ## Which angle?
//! The curve fits the exact reflectance as a function of the angle on the **optically
//! thinner** side of the interface. Going from less dense to dense (air → glass) that is the
//! incident angle. Going from dense to less dense (glass → air) it is the **transmitted**
//! angle: get `cos θt` from Snell's law. Evaluated with the incident angle instead, glass →
//! air at 40° gives 0.0407, while the exact value is 0.2453 (Schlick with `cos θt`: 0.2456).
//!
//! ## Edge cases
//! - Past the critical angle there is no transmitted angle and all light is reflected:
//!   return 1. (With the incident cosine, glass → air at 45° would give 0.042.)
//! - Equal indices: there is no interface and nothing reflects, but `R0 = 0` still leaves
//!   `(1 − cos θ)^5` (0.385 at 80°). Return 0.
//! - A cosine that rounding pushed to `1 + 1e-7` is normal incidence; `1 − cos θ` must not
//!   go negative.
//! - Indices run from 1 (vacuum) to 4 (germanium), either way round: a ratio `eta_i/eta_t`
//!   from 1/4 to 4, and equal.
//!
//! ## What the worksheet gets wrong
//! Its glass/water `R0` is printed as 0.0041; `(0.17/2.83)² = 0.0036085`. Its Schlick value
//! at 30° is 0.0400414365, not 0.04005 (`(1 − cos 30°)^5 = 4.3163e-5`). In §3.4.2 it uses the
//! half vector of the 90° configuration for θ = 85°; with the right one F = 0.0412016.
//! For glass → water it evaluates Schlick with the incident cosine; our convention (cosine
//! on the less dense side) gives 0.0036106020 instead of 0.0036090952.
//!
//! ## Check yourself
//! `schlick_r0(1.0, 1.5) = 0.04`, `schlick_r0(1.5, 1.33) = 0.00360849`;
//! `fresnel_schlick(cos 30°, 1.0, 1.5) = 0.0400414`.

use crate::prelude::*;

/// The reflectance at normal incidence of the interface between indices `eta_i` and
/// `eta_t` (the same either way round).
pub fn schlick_r0(eta_i: f32, eta_t: f32) -> f32 {
    todo!()
}

/// Schlick's approximation of the unpolarised reflectance for light arriving at an
/// interface from index `eta_i` into `eta_t` with cosine `cos_theta_i` (≥ 0) to the normal.
///
/// Uses the transmitted cosine when `eta_i > eta_t`, returns 1 under total internal
/// reflection and 0 when the two indices are equal. Get `R0` through `t.schlick_r0(..)`.
pub fn fresnel_schlick(t: &impl Tasks, cos_theta_i: f32, eta_i: f32, eta_t: f32) -> f32 {
    todo!()
}
