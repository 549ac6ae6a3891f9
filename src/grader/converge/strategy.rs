//! A strategy of the convergence study: one way of estimating a fixed set of quantities.

use anyhow::Result;

/// One way of estimating a fixed set of quantities (the pixels of a render, the entries
/// of an integral table): a rendering strategy in the convergence study.
///
/// `estimate` must be deterministic for a given `(spp, seed)` and should do all its work
/// inside the call, so that timing the call times the estimator.
pub trait Strategy: Sync {
    /// A short name for tables, the CSV and the plot legend (`cosine`, `mis_power`, …).
    fn name(&self) -> &str;

    /// Estimates every quantity with `spp` samples each, from random numbers chosen by
    /// `seed`.
    fn estimate(&self, spp: u32, seed: u64) -> Result<Estimate>;
}

/// What a strategy produced at one sample count.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Estimate {
    /// One value per pixel channel, in the same order as the reference.
    pub values: Vec<f32>,
    /// Samples the estimator dropped because they were NaN, infinite or negative (the
    /// renderer's film refuses them); each is a bug upstream, and a source of bias.
    pub dropped_samples: u64,
}

impl From<Vec<f32>> for Estimate {
    fn from(values: Vec<f32>) -> Self {
        Self {
            values,
            dropped_samples: 0,
        }
    }
}
