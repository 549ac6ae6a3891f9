//! Task `path_trace`: one recursive step of a path tracer (worksheet §5.3).
//!
//! # What the renderer expects
//! The renderer traces a camera ray, wraps it in a [`Segment`] (with
//! `emission_counted: false`) and calls `t.path_trace(scene, &segment, max_depth, sampler)`
//! once per sample. The value you return is that sample's radiance; a pixel is the average
//! over its samples. Your function calls itself (through `t.path_trace`) for the rest of
//! the path.
//!
//! # Depth
//! `depth` counts the segments the path may still have, **including this one**. So
//! `depth <= 0` returns black; `depth == 1` may only add the light the segment itself
//! reaches (emitters seen directly); from `depth == 2` on, direct lighting at the hit is
//! allowed (it adds a second segment), and so on. "Unbounded" scenes pass a large depth and
//! rely on Russian roulette.
//!
//! # One step
//! 1. **Emission.** If the segment hit nothing, the light it reaches is
//!    `scene.environment(segment.ray.dir)`; otherwise it is `scene.emitted(hit, wo)` with
//!    `wo = -segment.ray.dir`. Add it **only when `segment.emission_counted` is false**
//!    (camera rays). A segment that `mis` sampled already had that light added by `mis`,
//!    with its MIS weight; adding it again would count it twice.
//! 2. **Direct light (next-event estimation)** at the hit: call
//!    `t.mis(scene, hit, wo, scene.heuristic(), sampler)`. Add its `radiance`.
//! 3. **Continuation.** `mis` also returns the BSDF sample it drew, already traced, as
//!    `bounce` (`None` when the surface absorbed the path). Its `weight` is
//!    `f · |cos θi| / pdf`. The path continues along `bounce.segment` with `depth - 1`:
//!    add `bounce.weight * t.path_trace(scene, &bounce.segment, depth - 1, sampler)`.
//! 4. **Russian roulette.** When `scene.settings().roulette_applies(depth)`, keep going
//!    only with some probability `q` (for example the largest component of
//!    `bounce.weight`, at most 0.95) and **divide** the continuation by `q`. Choosing `q`
//!    well only changes the noise; forgetting the division darkens the image.
//!
//! # Edge cases
//! - Return finite, non-negative values; a NaN ruins the pixel (the renderer drops it).
//! - `q` can be 0 (a black continuation): stop without dividing.
//! - A path ends only by `depth` and by roulette, never because its weight is small: a
//!   bounce off a dark surface (weight 1e-4) may still carry all the light there is (a dark
//!   mirror under a bright sky).
//! - `bounce` is `None` whenever the BSDF absorbs the path: an emitter without a material
//!   (it reflects nothing) and surfaces whose sampling failed (a glossy lobe below the
//!   horizon). The emission and direct light of that step still count.
//! - Radiance and weights are colours: keep the three channels apart (a surface may reflect
//!   one channel and not another).
//! - The checks call you with every depth from −1 up, in closed boxes whose answer is
//!   known exactly, with diffuse, coloured, glossy, mirror and glass surfaces.
//!
//! # What the worksheet gets wrong
//! Its recursion never adds emission or direct light at any level, so every value it
//! returns is 0: only the caller's zero-bounce emission ever reaches the image. It also has
//! no Russian roulette (a fixed depth is a biased truncation), and it tests `depth == 0`,
//! which never fires when the depth starts at 0 or below.

use crate::prelude::*;

/// The radiance arriving along `segment` (towards its ray's origin), estimated by one
/// random path; see the module documentation.
pub fn path_trace(
    t: &impl Tasks,
    scene: &Scene,
    segment: &Segment,
    depth: i32,
    sampler: &mut Sampler,
) -> Vec3 {
    todo!()
}
