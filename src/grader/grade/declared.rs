//! What a task's statistical checks are declared to catch (each task's `POWER`), which
//! `pbrlab power` ([`super::power`]) measures.

/// What a task's statistical checks are declared to catch, each in at least [`super::power::CAUGHT`] of
/// gradings: an error of this relative size (one of [`super::power::LEVELS`]) or larger.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Declared {
    /// The smallest relative bias of every estimate that the estimator checks catch.
    pub estimator_bias: Option<f64>,
    /// The smallest distortion of the sampler that the sampling checks catch.
    pub sampler_distortion: Option<f64>,
}
