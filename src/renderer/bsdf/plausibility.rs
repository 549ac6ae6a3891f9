use glam::Vec3;
use serde::Serialize;

/// The verdict of the `brdf_check` task on one BRDF: the three plausibility conditions,
/// each measured numerically over random direction pairs in the upper hemisphere.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct PlausibilityReport {
    /// Smallest BRDF value seen (positivity holds when ≥ 0).
    pub min_value: f32,
    /// Largest `|f(wi, wo) − f(wo, wi)|` seen, relative to `max(|f(wi, wo)|, |f(wo, wi)|)`
    /// (reciprocity holds when ≈ 0).
    pub max_reciprocity_error: f32,
    /// Largest directional albedo `∫ f(wi, wo) cos θo dωo` seen over the tested `wi`
    /// (energy conservation holds when ≤ 1).
    pub max_albedo: f32,
    /// The incident direction (local frame) at which `max_albedo` was found.
    pub worst_wi: Vec3,
}

impl PlausibilityReport {
    /// True when all three conditions hold within `tolerance` (relative for reciprocity,
    /// absolute for positivity and albedo).
    pub fn is_plausible(&self, tolerance: f32) -> bool {
        self.min_value >= -tolerance
            && self.max_reciprocity_error <= tolerance
            && self.max_albedo <= 1.0 + tolerance
    }
}
