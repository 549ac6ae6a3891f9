//! # Task `reflect` — mirror reflection (worksheet §1.1, §1.5)
//!
//! A perfect mirror sends light out at the same angle from the normal as it came in, in the
//! plane spanned by the incoming direction and the normal. You write that mapping once here;
//! the renderer uses it for mirrors, for the reflected part of glass, and (through
//! `t.reflect`) in the Phong and NDF-sampling tasks.
//!
//! ## Convention
//! Both the direction you receive and the one you return point **away** from the surface
//! (towards the viewer, towards the light). Think of the result as "the direction light must
//! come from to leave along `wo`", or equally "where light arriving from `wo` goes".
//! Split `wo` into a part along the normal and a part in the surface plane: a mirror keeps
//! the first and reverses the second.
//!
//! ## What the worksheet gets wrong
//! The sheet writes two formulas that differ by a sign and calls them "different geometric
//! constructions". They are the same construction in two conventions: one for a direction
//! that travels *towards* the surface (pointing into it) and one for a direction that points
//! away from it. Feed the first formula a direction in our convention and you get a vector
//! pointing into the surface. Use the formula that matches our convention.
//!
//! ## Edge cases
//! - The normal may not have unit length (a mesh normal after a non-uniform scale, say):
//!   with `n = (0, 2, 0)` the textbook formula scales the normal part by `|n|² = 4`.
//! - At grazing incidence (`wo·n = 0`) the answer is `−wo`: the ray goes on unchanged.
//! - `n` may also have a length within 1e-3 of 1: divide by `n·n` (or normalise) always;
//!   skipping it "because `n` is nearly unit" is off by that much, and the grader checks.
//!
//! ## Check yourself
//! `wo = (0.6, 0.8, 0)`, `n = (0, 1, 0)` or `(0, 2, 0)` → `(−0.6, 0.8, 0)`.
//! The result has the length of `wo` and the same cosine with the normal.

use crate::prelude::*;

/// The mirror image of `wo` about the normal `n`.
///
/// `wo` points away from the surface; so does the result. `n` is any non-zero vector along
/// the normal (world or local frame, unit length not guaranteed). The result must have the
/// length of `wo` and make the same angle with `n`.
pub fn reflect(wo: Vec3, n: Vec3) -> Vec3 {
    todo!()
}
