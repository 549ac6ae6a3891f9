use super::schema::{Strategy, TransmittanceEstimator};
use crate::integrator::Heuristic;

/// The depth the renderer uses for "unbounded": Russian roulette ends paths long before
/// (a survival probability of at most 0.95 per segment leaves 0.95^1019 ≈ 1e-23 of paths),
/// and the bound keeps a path tracer without roulette from recursing forever.
pub const UNBOUNDED_DEPTH: i32 = 1024;

/// Render settings, resolved from the scene file and command-line overrides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderSettings {
    /// Samples (paths) per pixel.
    pub spp: u32,
    /// Maximum number of segments of a path (1: emitters seen directly; 2: direct light
    /// only); [`UNBOUNDED_DEPTH`] when the scene sets no bound.
    pub max_depth: i32,
    /// Segments beyond this many face Russian roulette (the continuation from the end of
    /// segment `k` faces it when `k ≥ rr_depth`).
    pub rr_depth: u32,
    /// The direct-light estimator.
    pub strategy: Strategy,
    /// The weighting `mis` uses, derived from the strategy (and the heuristic for `mis`).
    pub heuristic: Heuristic,
    /// Seed of every pixel's random sequence.
    pub seed: u64,
    /// Transmittance estimator for shadow rays through media.
    pub transmittance: TransmittanceEstimator,
}

impl RenderSettings {
    /// True when the path continuing from the end of a segment that had `depth` segments of
    /// budget left (counting itself, as `path_trace` receives it) must face Russian
    /// roulette: the path already has at least `rr_depth` segments.
    #[inline]
    pub fn roulette_applies(&self, depth: i32) -> bool {
        let segments_so_far = self.max_depth - depth + 1;
        segments_so_far >= self.rr_depth as i32
    }
}
