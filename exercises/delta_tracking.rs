//! Task `delta_tracking`: free-flight sampling in a heterogeneous medium (worksheet §6.3).
//!
//! # The idea
//! In a medium whose extinction `σt(x)` varies, the distance to the first real collision
//! cannot be drawn directly. Delta tracking (Woodcock et al. 1965) adds fictitious "null"
//! particles so that the total density is a constant majorant `σ̄ ≥ σt(x)`: distances to
//! *tentative* collisions are then exponential with rate `σ̄`, and each tentative collision
//! is real with probability `σt(x)/σ̄`.
//!
//! # What to do
//! Starting at `t = 0` on the ray (`ray.at(t)` is the point at distance `t`):
//! 1. Step: `t += −ln(1 − u) / σ̄` with a **fresh** uniform `u` (`sampler.next_1d()`).
//!    `1 − u` is never 0 because `u < 1`.
//! 2. If `t >= t_max` the path crossed the segment: return [`FreeFlight::Escape`].
//! 3. Otherwise look up `let c = medium.coefficients(ray.at(t));`, draw a **fresh** `ξ`, and
//!    - if `ξ σ̄ < c.sigma_a`: return `FreeFlight::Absorb { t }`;
//!    - else if `ξ σ̄ < c.sigma_a + c.sigma_s`: return `FreeFlight::Scatter { t }`;
//!    - else it was a null collision: go back to 1.
//!
//! # Edge cases
//! - `σ̄ = medium.majorant()` may be 0 (an empty medium) or even NaN: nothing can collide,
//!   so return `Escape` before dividing by it.
//! - Count the tentative collisions; after `max_steps` of them return
//!   [`FreeFlight::Exhausted`] instead of looping on (a huge majorant makes the steps so
//!   small that `t + dt == t` in f32).
//! - Returned distances lie in `[0, t_max)`.
//! - The ray may start anywhere and point in any direction, `t_max` is any positive length,
//!   and `max_steps` may be as small as 1.
//!
//! The result is checked statistically: in a homogeneous medium the escape probability
//! must be `e^{−σt t_max}`, and collisions must split into scatterings and absorptions in
//! the ratio `σs : σa`, whatever the majorant.
//!
//! # What the worksheet gets wrong
//! - It draws two random numbers once and reuses them at every iteration. The tentative
//!   collisions then land at multiples of one step and the same acceptance test repeats:
//!   with `σ̄ = 2σt` a homogeneous medium lets 57 % of paths through instead of
//!   `e^{−1} = 37 %`, and its scatter/absorb choice is biased too.
//! - It reports an escape as an absorption (`{max_distance, false}`), so a renderer that
//!   ends paths on absorption loses all light transmitted through the medium.
//! - With `u = 0` its step is 0 and with `σ̄ = 0` it is NaN: both loop forever.

use crate::prelude::*;

/// The first real collision along `ray` within `(0, t_max)` in `medium`, by delta
/// tracking; see the module documentation.
pub fn delta_tracking(
    medium: &dyn Medium,
    ray: &Ray,
    t_max: f32,
    max_steps: u32,
    sampler: &mut Sampler,
) -> FreeFlight {
    todo!()
}
