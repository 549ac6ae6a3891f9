//! Task `mis`: direct lighting by multiple importance sampling (worksheet §5.4).
//!
//! # The estimate
//! The light reflected at `hit` towards `wo` straight from the light sources,
//! `∫ f(wo, wi) |cos θi| Le(wi) dωi`, estimated with **two** samples, each weighted by a
//! MIS weight so that together they are unbiased (Veach and Guibas 1995):
//!
//! `radiance = w_L · f|cos| Le / p_L(wi_L)  +  w_B · f|cos| Le / p_B(wi_B)`.
//!
//! Use `let bsdf = scene.bsdf(hit);` for `f`: `bsdf.eval(t, wo, wi)` already contains
//! the `|cos θi|` factor, `bsdf.pdf(t, wo, wi)` is a solid-angle density, and
//! `bsdf.sample(t, wo, sampler)` returns a [`BsdfSample`] whose `weight` is
//! `f|cos|/pdf`.
//!
//! # The light sample
//! `scene.sample_light(hit.p, sampler)` returns a [`LightSample`]:
//! - `Area { p, n, radiance, pdf_area }`: with `d = |p − hit.p|` and
//!   `wi = (p − hit.p)/d`, the light faces you only if `cos θl = n · (−wi) > 0`. Its
//!   density **per solid angle** is `pdf_area · d² / cos θl`.
//! - `Point { p, intensity, prob }`: a delta light. It contributes
//!   `f|cos| · intensity / d² / prob` with weight 1 (no BSDF sample can hit a point).
//! - `Environment { wi, radiance, pdf }`: `pdf` is already per solid angle; the shadow ray
//!   goes to infinity.
//!
//! The shadow test: `let (ray, t_max) = hit.spawn_to(p);` then the light is visible when
//! `!scene.occluded(&ray, t_max)`. For the environment use `hit.spawn(wi)` and
//! `f32::INFINITY`. (`spawn` moves the origin off the surface so the ray cannot hit the
//! surface it starts on; `t_max` stops just short of the light's own surface.)
//!
//! # The BSDF sample
//! Draw it, then trace it: `let ray = hit.spawn(s.wi); let next = scene.intersect(&ray);`
//! - If `next` hits a surface, it reaches `scene.emitted(&next_hit, -s.wi)` (zero unless
//!   it is the front of a light). The light sampler would have produced that point with
//!   area density `scene.light_pdf(&next_hit)`; convert it with the hit's distance
//!   (`next_hit.t`) and the cosine at the light, `|next_hit.n · s.wi|`.
//! - If it escapes, it reaches `scene.environment(s.wi)` with solid-angle density
//!   `scene.environment_pdf(s.wi)`.
//!
//! Always return this sample as `DirectLight::bounce` (`Bounce { weight: s.weight,
//! segment: Segment { ray, hit: next, emission_counted: true } }`): `path_trace` continues
//! the path with it instead of tracing a new ray.
//!
//! # The weights
//! For a sample drawn by strategy `a` with density `p_a` while the other strategy would have
//! drawn it with density `p_b` (both per solid angle):
//! - [`Heuristic::Balance`]: `p_a / (p_a + p_b)`;
//! - [`Heuristic::Power`]: `p_a² / (p_a² + p_b²)`;
//! - [`Heuristic::Bsdf`]: 1 for the BSDF sample, 0 for an area or environment light sample
//!   (skip its shadow ray); [`Heuristic::Light`]: 1 for those light samples, 0 for a BSDF
//!   sample that is not delta.
//!
//! A BSDF sample with `s.delta` (mirror, glass) and a point-light sample always have weight
//! 1: the other strategy cannot produce them. If both densities are 0, the contribution is
//! 0, not `0/0`. If the BSDF is entirely delta (`bsdf.is_delta()`), the light sample can
//! only contribute 0: skip it.
//!
//! # Edge cases
//! - The surface need not be Lambertian: use `bsdf.pdf` and `s.weight`, never `cos θ / π`.
//!   The checks shade diffuse, glossy (Phong, also at grazing angles where many BSDF samples
//!   fail and return `None`: the light sample still counts), mirror and glass surfaces.
//! - The bounce you return is what `path_trace` continues with: the checks also trace whole
//!   paths with your `mis` at every bounce.
//! - A point light lying exactly on the shading point (`d = 0`) lights nothing there (every
//!   other point of the surface sees it at 90°): return 0 for it instead of dividing by
//!   `d² = 0`. The graded estimators include such a light, and a NaN fails them.
//! - Every density and probability in a [`LightSample`] is positive and finite.
//!
//! # What the worksheet gets wrong
//! - Its geometry term is `cos θ / d²`: the cosine at the light is missing from the
//!   area-to-solid-angle conversion (33 % too bright in the errata's test scene).
//! - Its visibility test compares squared distances the wrong way round, so an occluder
//!   nearer than the light never blocks it.
//! - It adds a solid-angle pdf to an area pdf inside the weights, which makes them depend on
//!   the scene's units (or biased, depending on how the light pdf is read).
//! - It never offsets shadow-ray origins, accepts light from below the surface through an
//!   absolute value, and does not exclude delta BSDFs or point lights from MIS.

use crate::prelude::*;

/// Direct light at `hit` towards `wo` by one light sample and one BSDF sample weighted by
/// `heuristic`, and that BSDF sample, traced; see the module documentation.
pub fn mis(
    t: &impl Tasks,
    scene: &Scene,
    hit: &Hit,
    wo: Vec3,
    heuristic: Heuristic,
    sampler: &mut Sampler,
) -> DirectLight {
    todo!()
}
