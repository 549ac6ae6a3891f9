//! A value task's contract in f64: the answer its exercise text defines, evaluated in f64
//! at exactly the inputs the student's function receives (each f32 input widened). This,
//! not the f32 reference, is a value case's expected output, and its tolerance comes from
//! how far this answer moves when the inputs move within rounding
//! ([`super::value_cases::evaluate`]): where the answer is ill-conditioned (a direction
//! along a fibre, a cosine at ±1, a grazing angle), the reference's own rounding decides
//! nothing.
//!
//! Each value task writes its contract in its folder, `src/grader/tasks/<task>/contract.rs`
//! (an `expected(&Call) -> Option<Output>`, listed as `contract` in
//! [`crate::for_each_task!`]), in the same conventions as its exercise: directions point
//! away from the surface, the local frame's z is the normal. A call no contract covers (a
//! Monte Carlo estimate with a seeded sampler, a function whose reference already computes
//! in f64) is judged against the reference. The tests check that the reference agrees
//! with every contract within the cases' tolerances (it gets full marks).

use glam::DVec3;

/// The roughness floor of the GGX and Beckmann NDFs, as the exercise texts state it
/// ([`crate::bsdf::MIN_ALPHA`]).
pub const MIN_ALPHA: f64 = crate::bsdf::MIN_ALPHA as f64;

/// A vector answer as an output (as a `Vec3` converts).
pub fn vector(v: DVec3) -> super::output::Output {
    super::output::Output::Numbers(v.to_array().to_vec())
}
