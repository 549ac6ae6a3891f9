//! # Task `ndf_sample` — sampling a microfacet BRDF through its NDF (worksheet §5.2)
//!
//! To importance-sample the Cook-Torrance BRDF, draw a microfacet normal `h` where facets
//! are common and reflect `wo` about it. The renderer then needs the density of the
//! resulting `wi` **per steradian of `wi`**, which is not the density of `h`: the
//! reflection stretches solid angle, and the change of variables contributes the Jacobian
//! `|dωh/dωi| = 1 / (4 |wo·h|)`.
//!
//! ## What to compute
//! - [`ndf_sample`]: draw `h` in the local frame with density `D(h) cos θh` for the
//!   anisotropic GGX distribution of your `aniso_ndf` task, using the two numbers in `u`.
//!   (`D cos θh` integrates to 1, so it is a probability density.) Derive the mapping for the
//!   isotropic case from the CDF of `θh` first; the anisotropic one follows by stretching the
//!   slopes by `alpha_x` and `alpha_y`. Reflect `wo` about `h` with `t.reflect`.
//!   This task asks for **NDF sampling**, not the more recent visible-normal sampling; the
//!   grader checks the density `D cos θh`.
//! - [`ndf_pdf`]: the density of `wi` under your sampler, `D(h) cos θh / (4 |wo·h|)` with
//!   `h = normalize(wo + wi)`, and 0 for every `wi` your sampler can never return. The two
//!   functions must agree: the grader compares a histogram of your samples with your pdf.
//!
//! ## Edge cases
//! - A sampled `h` with `wo·h ≤ 0` faces away from the viewer and reflects `wo` into the
//!   surface: return `None`. (The pdf formula would give ∞ at `wo·h = 0` and a negative
//!   density below.)
//! - A reflected `wi` at or below the horizon is not a valid sample either: `None`.
//! - Roughness 0 must not give NaN: raise it to [`crate::bsdf::MIN_ALPHA`].
//! - In `ndf_pdf`, `wo ≈ −wi` has no usable half vector: density 0.
//! - The graded directions include cosines down to the smallest positive f32 (`1e-45`, a
//!   subnormal), where `cos²θ` and `cos⁴θ` underflow to 0 and `tan θ` overflows, and
//!   directions exactly along the frame's axes: the answer must stay finite there.
//!
//! ## What the worksheet gets wrong
//! Nothing in the formula; it writes `4 (wo·h)` where `4 |wo·h|` is safer, and never says
//! which samples to reject.

use crate::prelude::*;

/// Samples an incident direction for the unit local outgoing direction `wo` (z = normal) by
/// drawing a microfacet normal with density `D(h) cos θh` (anisotropic GGX, `alpha_x` along
/// local x) from the uniform sample `u ∈ [0, 1)²` and reflecting `wo` about it.
/// `None` when `wo·h ≤ 0` or the reflected direction is at or below the surface.
pub fn ndf_sample(t: &impl Tasks, wo: Vec3, alpha_x: f32, alpha_y: f32, u: Vec2) -> Option<Vec3> {
    todo!()
}

/// The density per steradian with which [`ndf_sample`] returns the unit local direction `wi`
/// for `wo`: `D(h) cos θh / (4 |wo·h|)` with `h` the half vector, and 0 wherever the sampler
/// cannot produce `wi`. Finite and non-negative for every input.
pub fn ndf_pdf(t: &impl Tasks, wo: Vec3, wi: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
    todo!()
}
