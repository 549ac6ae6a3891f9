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
    /// `seed`. Returns one value per pixel channel, in the same order as the reference.
    fn estimate(&self, spp: u32, seed: u64) -> Result<Vec<f32>>;
}
