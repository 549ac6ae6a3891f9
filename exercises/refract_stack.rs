//! # Task `refract_stack` — Snell's law, total internal reflection, a layer stack
//! (worksheet §1.2, §1.4)
//!
//! Three functions: refraction of a direction through one interface (used by the glass
//! material), the critical angle, and a small optics calculator that follows a ray through
//! plane-parallel layers and reports angles, shifts, reflectances and the transmitted
//! intensity.
//!
//! ## Convention
//! `wi` points **away** from the interface on the side the light comes from, and the normal
//! you are given lies on that side too (it need not be unit length). The refracted direction
//! you return is a unit vector that points away from the interface on the **other** side.
//! Snell's law ties the sines together: `eta_i sin θi = eta_t sin θt`; it is easiest to work
//! with `cos θi = wi·n̂` and get `cos θt` from `sin²θt = (eta_i/eta_t)² sin²θi`.
//!
//! ## Edge cases
//! - Total internal reflection happens when `sin²θt ≥ 1`. Decide it on that test (with `≥`):
//!   exactly at the critical angle no light is transmitted and the reflectance is 1.
//! - In floating point, `1 − sin²θt` can come out as `−2.4e-7` one rounding past the
//!   critical angle; its square root is NaN. Clamp before `sqrt`.
//! - The critical angle `asin(eta_t/eta_i)` exists only when light goes from dense to less
//!   dense (`eta_i > eta_t`). Otherwise the formula gives NaN (`asin(1.5)`) or 90° (equal
//!   indices), and neither is a critical angle: return `None`.
//! - `n` may have any non-zero length, also within 1e-3 of 1: normalise it always.
//! - Incident cosines go down to the smallest positive f32 (`1e-45`, a subnormal).
//! - Indices run from 1 (vacuum) to 4 (germanium), either way round: a ratio `eta_i/eta_t`
//!   from 1/4 to 4.
//!
//! ## The layer stack
//! In a stack of parallel layers the product `eta sin θ` is the same in every medium, so every
//! angle follows from the first one. [`StackReport`] lists what to fill in, field by field;
//! read its documentation. For each slab of thickness `d`:
//! - the **shift of the ray**, measured perpendicular to it, between where it leaves the slab
//!   and where it would have been without the slab: `d sin(θ_in − θ_slab) / cos θ_slab`;
//! - the **offset along the interface** between entry and exit points: `d tan θ_slab`.
//!
//! For each interface, the reflectance by Schlick's approximation (call `t.fresnel_schlick`,
//! your other task, with the incidence cosine at that interface) and by the exact Fresnel
//! equations ([`crate::optics::fresnel_dielectric_f64`]). The transmitted intensity is the
//! incident one times `(1 − R)` for every interface crossed (no absorption, no multiple
//! reflections), and 0 once total internal reflection has stopped the ray.
//!
//! ## What the worksheet gets wrong (§1.4)
//! - It calls `d tan θ2 = 3.55 mm` the lateral displacement. That is how far the exit point
//!   is from the entry point along the glass. The ray itself is shifted by
//!   **1.93813782 mm**, and `d tan θ2` is 3.53553391 mm anyway, not 3.55.
//! - Its glass/water `R0 = 0.0041` is an arithmetic slip: it is 0.0036085. Two fifth powers
//!   are wrong as well, so its final intensity 95.6 is off in the third digit.
//!
//! ## Check yourself (air 1.0 → 10 mm glass 1.5 → water 1.33, 30°, intensity 100)
//! θ = 30°, 19.4712206°, 22.0824132°; critical angles glass→air 41.8103149°, water→air
//! 48.7534666°, glass→water 62.4573249°; transmitted 95.649254 (Schlick) and 95.494809
//! (exact Fresnel).

use crate::prelude::*;

/// The refracted direction of `wi` through an interface from index `eta_i` into `eta_t`.
///
/// `wi` points away from the interface on the incident side, `n` is the normal on that side
/// (not necessarily unit length). Returns the unit transmitted direction, pointing away from
/// the interface into the second medium, or `None` under total internal reflection
/// (including exactly at the critical angle). Never returns NaN components.
pub fn refract(wi: Vec3, n: Vec3, eta_i: f32, eta_t: f32) -> Option<Vec3> {
    todo!()
}

/// The critical angle in radians for light going from index `eta_i` into `eta_t`, or `None`
/// when no angle of incidence gives total internal reflection (`eta_i <= eta_t`).
pub fn critical_angle(eta_i: f64, eta_t: f64) -> Option<f64> {
    todo!()
}

/// Follows a ray that enters `stack` at `theta_deg` degrees from the normal through every
/// interface, and reports what happens in a [`StackReport`] (see its documentation for the
/// exact content of every field, including after total internal reflection).
///
/// `t` gives access to your other tasks: use `t.fresnel_schlick(..)` for the Schlick column.
pub fn refract_stack(t: &impl Tasks, theta_deg: f64, stack: &LayerStack) -> StackReport {
    todo!()
}
