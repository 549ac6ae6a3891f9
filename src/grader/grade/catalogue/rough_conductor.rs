//! A rough conductor for the integrator estimators: the Cook-Torrance BRDF with anisotropic
//! GGX and Schlick's Fresnel through a coloured `f0`, the one material class whose BSDF
//! sampling (`ndf_sample`) draws half vectors, fails for every half vector that reflects
//! below the horizon, and whose sample weights are neither constant nor the albedo.
//!
//! The light it reflects has no closed form, so each estimator's exact answer is a stored
//! quadrature of the reference's BSDF (the constants beside the estimators): the grader
//! holds only those numbers, never a second Cook-Torrance that the student handout would
//! ship. [`super::stored_quadratures`] integrates a table's BSDF the same way, at the hit
//! each estimator shades and in that hit's shading frame, for the instructor tests to
//! compare with the reference's.

use super::polygon::{projected_hemisphere_integral, projected_integral};
use crate::geometry::Hit;
use crate::grade::estimator::yaml_rgb;
use crate::scene::Scene;
use crate::worksheet::Tasks;
use glam::{DVec3, Vec3};

/// A rough conductor's roughness and reflectance at normal incidence.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughConductor {
    /// GGX roughness along the shading frame's tangent.
    pub alpha_x: f64,
    /// GGX roughness along its bitangent.
    pub alpha_y: f64,
    /// Reflectance at normal incidence per channel (Schlick's curve through it).
    pub f0: DVec3,
}

impl RoughConductor {
    /// The material in the scene format.
    pub fn yaml(&self) -> String {
        format!(
            "{{conductor: {{alpha_x: {}, alpha_y: {}, reflectance: {}}}}}",
            self.alpha_x,
            self.alpha_y,
            yaml_rgb(self.f0)
        )
    }
}

/// A stored quadrature and the same quadrature computed now: what the instructor tests
/// compare (`tests/instructor/reference_values.rs`) with the reference's table.
#[derive(Clone, Debug, PartialEq)]
pub struct StoredQuadrature {
    /// Which surface, seen from where, integrated over what.
    pub what: String,
    /// The value the estimator's answer is built from.
    pub stored: DVec3,
    /// The same integral of `t`'s BSDF, computed now.
    pub computed: DVec3,
}

/// `f(wo, wi)` per channel of `t`'s BSDF at `hit` (world `wo`; `wi` the direction `local`
/// of the hit's shading frame), without the cosine.
fn brdf(t: &impl Tasks, scene: &Scene, hit: &Hit, wo: Vec3, local: DVec3) -> DVec3 {
    if local.z <= 0.0 {
        return DVec3::ZERO;
    }
    let wi = hit.frame.to_world(local.as_vec3());
    scene.bsdf(hit).eval(t, wo, wi).as_dvec3() / local.z
}

/// `∫_{H+} f(wo, wi) cos θi dωi` per channel of `t`'s BSDF at `hit`: the radiance
/// reflected towards `wo` (world, away from the surface) under unit radiance from the
/// whole hemisphere.
pub fn albedo(t: &impl Tasks, scene: &Scene, hit: &Hit, wo: Vec3) -> DVec3 {
    DVec3::from_array(
        [0, 1, 2].map(|c| projected_hemisphere_integral(|w| brdf(t, scene, hit, wo, w)[c])),
    )
}

/// `∫_P f(wo, wi) cos θi dωi` per channel of `t`'s BSDF at `hit` over the parallelogram
/// `corners` (world positions): the radiance reflected towards `wo` from a light of unit
/// radiance there.
pub fn over(t: &impl Tasks, scene: &Scene, hit: &Hit, wo: Vec3, corners: &[Vec3; 4]) -> DVec3 {
    let local = corners.map(|c| hit.frame.to_local(c - hit.p));
    DVec3::from_array(
        [0, 1, 2].map(|c| projected_integral(&local, |w| brdf(t, scene, hit, wo, w)[c])),
    )
}
