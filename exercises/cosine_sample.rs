//! # Task `cosine_sample` — cosine-weighted hemisphere sampling (worksheet §2.7)
//!
//! A diffuse surface reflects `ρ/π · L cos θ`. If directions are drawn with density
//! proportional to `cos θ`, the cosine and the π cancel in the Monte Carlo estimate and each
//! sample contributes just `ρ L`. The diffuse material in the renderer samples with your
//! function, and divides by your pdf, so the two must agree exactly.
//!
//! ## What to compute
//! Map a uniform point `u ∈ [0, 1)²` to a unit direction in the local frame (z = normal)
//! whose density per steradian is `cos θ / π` on the upper hemisphere. Derive it by inverting
//! CDFs: the density in (θ, φ) includes the solid-angle factor `sin θ`; integrate out φ to get
//! the marginal of θ, invert its CDF, and take φ uniform. A correct derivation ends at a
//! closed form for `cos θ` (or `sin θ`) in terms of one coordinate of `u`. Another valid
//! route: pick a uniform point on the unit disk and project it up onto the hemisphere
//! (Malley's method). Any correct mapping passes; the grader tests the distribution.
//!
//! ## What the worksheet gets wrong
//! Its derivation loses the `2π` from integrating over φ, mis-evaluates an integral, ends
//! with a "CDF" that only reaches `1/π`, and then removes the π by "scaling", which is not a
//! valid step; its intermediate `arcsin sqrt(π ξ)` is NaN for 68 % of samples. The final
//! mapping it states happens to be right, but do the derivation yourself.
//!
//! ## Edge cases
//! - `u` is in [0, 1), so `1 − u` never reaches 0; make sure your mapping never produces a
//!   direction on or below the horizon, where the pdf is 0 and `f cos / pdf` would be 0/0.
//! - Clamp arguments of square roots that rounding could push below 0.
//! - `cosine_pdf` is 0 below (and on) the horizon.
//! - `cosine_pdf` is graded at cosines down to the smallest positive f32 (`1e-45`).

use crate::prelude::*;

/// A unit direction in the local frame (z = normal) with density `cos θ / π` per steradian
/// over the upper hemisphere, from a uniform sample `u ∈ [0, 1)²`.
pub fn cosine_sample(u: Vec2) -> Vec3 {
    todo!()
}

/// The density per steradian with which [`cosine_sample`] produces the unit local direction
/// `w`: `cos θ / π` above the surface, 0 at or below it.
pub fn cosine_pdf(w: Vec3) -> f32 {
    todo!()
}
