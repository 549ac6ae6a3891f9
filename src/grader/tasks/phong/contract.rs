//! The contract of `phong` in f64 (see [`crate::grade::contract`]). `reciprocity_gap` is
//! a Monte Carlo estimate: judged against the reference's verdict.

use crate::bsdf::PhongParams;
use crate::grade::call::Call;
use crate::grade::contract::vector;
use crate::grade::output::Output;
use glam::DVec3;
use std::f64::consts::FRAC_1_PI;

/// The normalised modified Phong BRDF for `wo` and `wi` (local frame, pointing away from
/// the surface): `kd/π + ks (n+2)/(2π) max(0, r·wo)^n`, `r` the mirror of `wi` about the
/// normal; 0 when either direction is at or below the surface.
pub fn phong(wo: DVec3, wi: DVec3, params: &PhongParams) -> DVec3 {
    if wo.z <= 0.0 || wi.z <= 0.0 {
        return DVec3::ZERO;
    }
    let r = DVec3::new(-wi.x, -wi.y, wi.z);
    let exponent = params.exponent as f64;
    let lobe = r.dot(wo).max(0.0).powf(exponent);
    let norm = (exponent + 2.0) * 0.5 * FRAC_1_PI;
    params.kd.as_dvec3() * FRAC_1_PI + params.ks.as_dvec3() * (norm * lobe)
}

/// The contract's answer to a call of this task's functions; `None` for any other call.
pub fn expected(call: &Call) -> Option<Output> {
    match call {
        Call::phong { wo, wi, params } => {
            Some(vector(phong(wo.as_dvec3(), wi.as_dvec3(), params)))
        }
        _ => None,
    }
}
