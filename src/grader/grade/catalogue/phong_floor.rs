//! A Phong surface for the integrator estimators: the energy-normalised Phong BRDF
//! `kd/π + ks (n + 2)/(2π) max(0, r·wo)^n` (r the mirror direction of wi) with coloured
//! coefficients, and the exact light it reflects from a uniformly bright hemisphere or an
//! emitting parallelogram, by quadrature. Seen along the normal its albedo is exactly
//! `kd + ks`; seen at a grazing angle with a low exponent, much of its lobe lies below the
//! horizon, where its BSDF sampling fails.

use super::polygon::{projected_hemisphere_integral, projected_integral, projected_solid_angle};
use crate::grade::estimator::yaml_rgb;
use glam::{DVec3, Vec3};
use std::f64::consts::PI;
use std::sync::{Mutex, PoisonError};

/// The coefficients and exponent of a Phong surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhongSurface {
    /// Diffuse coefficient per channel.
    pub kd: DVec3,
    /// Specular coefficient per channel.
    pub ks: DVec3,
    /// The lobe's exponent.
    pub exponent: f64,
}

impl PhongSurface {
    /// The material in the scene format.
    pub fn yaml(&self) -> String {
        format!(
            "{{phong: {{kd: {}, ks: {}, exponent: {}}}}}",
            yaml_rgb(self.kd),
            yaml_rgb(self.ks),
            self.exponent
        )
    }

    /// The specular lobe without `ks` at the incident direction `wi` for the outgoing `wo`
    /// (local frame, z = normal): the mirror image of `wi` about the normal is
    /// `(−wi.x, −wi.y, wi.z)`.
    fn lobe(&self, wo: DVec3, wi: DVec3) -> f64 {
        let cos_alpha = wi.z * wo.z - wi.x * wo.x - wi.y * wo.y;
        (self.exponent + 2.0) / (2.0 * PI) * cos_alpha.max(0.0).powf(self.exponent)
    }

    /// `∫_{H+} f(wo, wi) cos θi dωi`: the radiance reflected towards `wo` (local frame,
    /// above the surface) under unit radiance from every direction, per channel.
    pub fn albedo(&self, wo: DVec3) -> DVec3 {
        let lobe = memoised(self.key(wo, None), || {
            projected_hemisphere_integral(|wi| self.lobe(wo, wi))
        });
        self.kd + self.ks * lobe
    }

    /// `∫_P f(wo, wi) cos θi dωi` over the parallelogram `corners` (local frame, seen from
    /// the origin): the radiance reflected towards `wo` from a light of unit radiance
    /// there, per channel.
    pub fn over(&self, wo: DVec3, corners: &[Vec3; 4]) -> DVec3 {
        let lobe = memoised(self.key(wo, Some(corners)), || {
            projected_integral(corners, |wi| self.lobe(wo, wi))
        });
        self.kd * (projected_solid_angle(corners) / PI) + self.ks * lobe
    }

    /// What a quadrature of the lobe depends on, as bits: the exponent, `wo` and the
    /// parallelogram, if any.
    fn key(&self, wo: DVec3, corners: Option<&[Vec3; 4]>) -> Vec<u64> {
        let mut key = vec![self.exponent.to_bits()];
        key.extend(wo.to_array().map(f64::to_bits));
        for corner in corners.into_iter().flatten() {
            key.extend(corner.to_array().map(|x| u64::from(x.to_bits())));
        }
        key
    }
}

/// The lobe quadratures this process has computed, by [`PhongSurface::key`]: the grader
/// builds a task's estimators several times per grading (to count, run and judge them),
/// and each quadrature takes up to half a million evaluations.
fn memoised(key: Vec<u64>, quadrature: impl FnOnce() -> f64) -> f64 {
    static DONE: Mutex<Vec<(Vec<u64>, f64)>> = Mutex::new(Vec::new());
    let found = DONE
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
        .iter()
        .find(|(k, _)| *k == key)
        .map(|(_, v)| *v);
    found.unwrap_or_else(|| {
        let value = quadrature();
        DONE.lock()
            .unwrap_or_else(PoisonError::into_inner)
            .push((key, value));
        value
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn along_the_normal_the_albedo_is_kd_plus_ks() {
        let surface = PhongSurface {
            kd: DVec3::new(0.1, 0.3, 0.5),
            ks: DVec3::new(0.5, 0.4, 0.2),
            exponent: 20.0,
        };
        let albedo = surface.albedo(DVec3::Z);
        assert!((albedo - (surface.kd + surface.ks)).abs().max_element() < 1e-8);
        // At a grazing angle with a broad lobe, part of the lobe is below the horizon.
        let broad = PhongSurface {
            exponent: 2.0,
            ..surface
        };
        let grazing = DVec3::new(-0.9396926, 0.0, 0.34202014);
        let specular = (broad.albedo(grazing) - broad.kd) / broad.ks;
        assert!(specular.x > 0.3 && specular.x < 0.9, "{specular}");
    }
}
