//! # Task `aniso_ndf` — the anisotropic GGX distribution (worksheet §4.1)
//!
//! Brushed metal is smooth along the brushing and rough across it. The GGX
//! (Trowbridge-Reitz) distribution of microfacet normals handles that with two roughnesses:
//! `alpha_x` along the local x axis (the tangent) and `alpha_y` along local y. With equal
//! roughnesses it is the ordinary isotropic GGX. The Cook-Torrance task calls your function
//! for its `D`, and the NDF-sampling task for its pdf.
//!
//! ## What to compute
//! The density of microfacet normals per steradian at the unit local vector `h`, normalised
//! so that the projected area adds up to one: `∫ D(h) cos θh dωh = 1`. The worksheet's
//! formula, written with the components of `h`, is the one to use:
//! `D(h) = 1 / (π αx αy ((h·t/αx)² + (h·b/αy)² + (h·n)²)²)`, and in the local frame
//! `h·t = h.x`, `h·b = h.y`, `h·n = h.z`.
//!
//! ## Edge cases
//! - `h` at or below the surface (`h.z ≤ 0`): no microfacet faces that way, return 0 (the
//!   formula alone gives the same value as for the mirrored `h`).
//! - `alpha → 0` is a perfect mirror, whose distribution is a delta: at 0 the formula is
//!   0/0. Raise the roughnesses to [`crate::bsdf::MIN_ALPHA`] first, as the reference does.
//! - The isotropic textbook form `α² / (π ((n·h)²(α² − 1) + 1)²)` cancels badly in f32 for
//!   small α (2.6 % wrong at α = 1e-3, infinite at α = 1e-4). The component form above does
//!   not; prefer it.
//! - The graded directions include cosines down to the smallest positive f32 (`1e-45`, a
//!   subnormal), where `cos²θ` and `cos⁴θ` underflow to 0 and `tan θ` overflows, and
//!   directions exactly along the frame's axes: the answer must stay finite there.
//!
//! ## What the worksheet gets wrong
//! Its values are essentially right (0.204, and 0.0048 truncated to 0.004). Its explanation
//! is muddled: `h` leans towards `t`, which is exactly the smooth `alpha_x = 0.1`
//! direction, and a smooth direction has few strongly tilted facets, hence the small D.
//!
//! ## Check yourself
//! `h = (0.5, 0.5, √2/2)`: `α = (0.5, 0.5)` → 0.2037183; `α = (0.1, 1.0)` → 0.0048006.
//! With `α = (1, 1)`, `D = 1/π` for every `h` above the surface.

use crate::prelude::*;

/// The anisotropic GGX density of the unit local microfacet normal `h`, per steradian, with
/// roughness `alpha_x` along local x and `alpha_y` along local y; 0 for `h.z ≤ 0`, finite for
/// zero roughness.
pub fn aniso_ndf(h: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
    todo!()
}
