use glam::Vec3;

/// A direction drawn from a BSDF, with everything an estimator needs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BsdfSample {
    /// The sampled direction, world space, pointing away from the surface.
    pub wi: Vec3,
    /// The estimator weight `f(wo, wi) |cos θi| / pdf` per RGB channel. For a delta lobe
    /// (mirror, glass) it is the lobe's reflectance or transmittance, already divided by
    /// the probability of choosing that lobe.
    pub weight: Vec3,
    /// Density of `wi` per unit solid angle. 0 for a delta lobe, which has no density: use
    /// `delta` to tell, and never put a delta sample into a MIS weight.
    pub pdf: f32,
    /// True when `wi` came from a delta lobe (mirror reflection or refraction).
    pub delta: bool,
}
