//! # Task `brdf_check` — a numerical plausibility checker (worksheet §2.2, §2.6)
//!
//! A physically plausible BRDF is never negative, is symmetric under swapping its two
//! directions (Helmholtz reciprocity), and never reflects more energy than arrives: for
//! every incident `wi`, the directional albedo `∫ f(wi, wo) cos θo dωo` is at most 1. Here
//! you measure all three for any BRDF handed to you as a closure `brdf(wi, wo)` of local
//! directions (z = normal), and fill in a [`PlausibilityReport`].
//!
//! ## What to compute
//! - `max_reciprocity_error`: your `t.reciprocity_gap(brdf, sampler, samples)` (Phong task).
//! - `max_albedo` and `worst_wi`: pick a set of incident directions, estimate each one's
//!   albedo by Monte Carlo over `wo` with `samples` uniform hemisphere directions
//!   ([`crate::sampling::uniform_hemisphere`], pdf
//!   [`crate::sampling::uniform_hemisphere_pdf`]), and keep the largest. Reducing the
//!   variance is worth it (stratify the samples): a Lambertian BRDF with albedo exactly 1
//!   should not look like it creates energy because of noise. `worst_wi` is that incident
//!   direction as `brdf` takes it: unit, above the surface, pointing away from it.
//! - `min_value`: the smallest BRDF value among everything you evaluated.
//!
//! ## Where to look
//! Include incident directions close to grazing (89°, 89.9°). The worksheet's own example
//! `k (wi·wo)^n / ((wi·n)(wo·n))` has an albedo of `2πk / ((n + 1) cos θi)`: it looks fine at
//! normal incidence and grows without bound towards grazing. A checker that only tries
//! `wi = n` declares it plausible.
//!
//! ## What the worksheet gets wrong (§2.6.3)
//! It argues that normal incidence is the worst case and concludes `k ≤ (n + 1)/(2π)`. For
//! even `n` the integral `∫ (wi·wo)^n dωo` does not depend on `wi` at all, so the `1/cos θi`
//! in front makes normal incidence the **best** case: with `k = (n + 1)/(2π)` the albedo is
//! 1 at 0°, 2 at 60° and 573 at 89.9°. No `k > 0` conserves energy. Also,
//! `∫ cos^n θ dω = 2π/(n + 1)` holds for every real `n > −1`, not just even `n`.
//!
//! ## Edge cases
//! A BRDF may return NaN or ∞ (the custom one does at `cos θ = 0`). `f32::min` and `max`
//! silently skip NaN; a NaN must reach the report instead: `min_value`, and the albedo the
//! NaN enters, are then NaN (a BRDF that returns NaN is known to be neither non-negative nor
//! energy-conserving), whatever the reciprocity test says.

use crate::prelude::*;

/// Measures positivity, reciprocity and energy conservation of `brdf(wi, wo)` (local
/// directions, z = normal) with `samples` random directions per measurement, drawn from
/// `sampler`; see [`PlausibilityReport`] for the fields.
pub fn brdf_check(
    t: &impl Tasks,
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut Sampler,
    samples: usize,
) -> PlausibilityReport {
    todo!()
}
