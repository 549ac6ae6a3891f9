//! # Task `cook_torrance` — the microfacet BRDF (worksheet §3.1, §3.3, §3.4)
//!
//! A rough conductor is modelled as tiny mirrors (microfacets). Light goes from `wi` to `wo`
//! only via facets whose normal is the half vector `h = normalize(wo + wi)`. The BRDF
//! multiplies how many facets face `h` (the NDF `D`), how much a facet reflects (Fresnel
//! `F`), and how many of them are neither shadowed nor masked (`G`), and converts from
//! facet area and half-vector solid angle to the surface's BRDF:
//! `f = F D G / (4 cos θo cos θi)`.
//!
//! ## What to use
//! - `D`: your `t.aniso_ndf(h, alpha_x, alpha_y)`.
//! - `G`: the separable Smith form `G1(wo) G1(wi)` with your `t.smith_g1`. An anisotropic
//!   surface presents a different roughness to each direction:
//!   [`crate::bsdf::projected_alpha`]`(w, alpha_x, alpha_y)` is the one to pass for `w`.
//! - `F`: Schlick's curve with an RGB normal-incidence reflectance (metals are coloured):
//!   `F = f0 + (1 − f0)(1 − wo·h)^5`, per channel. [`crate::optics::schlick_weight`] gives the
//!   `(1 − cos)^5` factor. The angle is the one between the light and the facet normal `h`,
//!   not the macroscopic normal; `wo·h = wi·h`.
//!
//! Schlick's curve is an approximation: for gold's blue channel it is up to 7 % off the exact
//! conductor Fresnel equations. A scene that gives a metal by its complex index of refraction
//! (`eta` and `k`, as in `scenes/materials.yaml`) is rendered the way pbrt and Mitsuba render
//! it: the renderer calls your function with `f0 = 1` (so `F` is exactly 1) and multiplies by
//! the exact Fresnel reflectance itself. Metals given by an RGB `reflectance` use your Schlick
//! term.
//!
//! ## Convention
//! Local frame (z = normal), both directions away from the surface; `alpha_x` applies along
//! local x. Return RGB.
//!
//! ## Edge cases
//! - Either direction at or below the horizon: the BRDF is 0 (and the cosines in the
//!   denominator would be 0 or negative).
//! - `wo ≈ −wi`: `wo + wi` is (nearly) the zero vector and normalising it gives NaN or a
//!   wildly wrong `h` (10° off in f32 for a pair 1e-7 away from opposite). Both directions
//!   above the horizon rules most of that out; still guard a tiny `|wo + wi|²`.
//! - Grazing `wo` with `G = 1` grows like `1/cos θo` (12 276 at 89.99999° for α = 0.5); with
//!   Smith's `G1` the cosine cancels and the value tends to 0.008570 (F0 = 0.04, wi = n).
//! - Cosines go down to the smallest positive f32 (`1e-45`, a subnormal): there
//!   `4 cos θo cos θi` underflows to 0 while `G1` is tiny, and `D G / (4 cos θo cos θi)` is
//!   `0/0`. Divide each `G1` by its own cosine. A mirror (`α = 0`) at two such cosines is
//!   beyond f32's range in some orders of the product: ∞ is accepted there.
//!
//! ## What the worksheet gets wrong
//! - §3.3 calls the light's contribution a radiance; a point light delivers irradiance
//!   (`I / r²`), not radiance. The arithmetic `f = F0/π` is right for `D = 1/π`, `G = 1`.
//! - §3.4.2 uses the wrong half vector at 85° (that of 90°): F = 0.0412016, not 0.04076.
//! - §3.1's "to normalise the BRDF" for the cosines is vague: the 4 comes from the Jacobian
//!   `dωh/dωo = 1/(4 |wo·h|)`, the cosines from converting facet area to surface area.

use crate::prelude::*;

/// The Cook-Torrance BRDF for unit local directions `wo` and `wi` (z = normal, both pointing
/// away from the surface), anisotropic GGX roughness `alpha_x` (along local x) and `alpha_y`,
/// and Schlick Fresnel with normal-incidence reflectance `f0` (RGB).
///
/// Returns 0 when either direction is at or below the horizon, and never NaN.
pub fn cook_torrance(
    t: &impl Tasks,
    wo: Vec3,
    wi: Vec3,
    alpha_x: f32,
    alpha_y: f32,
    f0: Vec3,
) -> Vec3 {
    todo!()
}
