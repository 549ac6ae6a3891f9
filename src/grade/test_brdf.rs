//! BRDFs with known plausibility, fed to the `phong` reciprocity test and the `brdf_check`
//! task. None of them is a task's answer: they are the cases a checker must tell apart.

use glam::Vec3;
use serde::{Deserialize, Serialize};
use std::f32::consts::FRAC_1_PI;

/// A BRDF `f(wi, wo)` on local directions, named so a stored case can refer to it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "brdf", rename_all = "snake_case")]
pub enum TestBrdf {
    /// Lambertian `albedo / π`: positive, reciprocal, directional albedo `albedo`.
    Lambert {
        /// Directional albedo in [0, 1].
        albedo: f32,
    },
    /// The worksheet's §2.6 BRDF `k (wi·wo)^n / (cos θi cos θo)`: reciprocal; negative
    /// somewhere for odd `n`; its albedo `2πk / ((n+1) cos θi)` exceeds 1 near grazing.
    CosinePower {
        /// Scale `k`.
        k: f32,
        /// Integer exponent `n`.
        n: i32,
    },
    /// `cos θi / (2π)`, a function of the incident direction only: positive and
    /// energy-conserving (albedo `cos θi / 2`), but not reciprocal.
    IncidentOnly,
    /// [`TestBrdf::IncidentOnly`] scaled by `scale` (say 1e-6): as far from reciprocal, in
    /// relative terms, but every absolute difference is tiny.
    ScaledIncidentOnly {
        /// The factor.
        scale: f32,
    },
    /// Lambert with albedo 1/2, but NaN where `cos θi cos θo < 0.05` (a formula that divides
    /// by zero near grazing): symmetric, yet no test can call it reciprocal or plausible.
    NanNearGrazing,
    /// Lambert with albedo 1/2, but NaN where `cos θi > cos θo`: of every pair with distinct
    /// cosines, exactly one order is NaN.
    NanOneWayRound,
    /// `2/π` where `cos θi > cos θo`, else `1/π`: every pair with distinct cosines has the
    /// relative reciprocity gap exactly 1/2, however the pairs are drawn.
    Lopsided,
}

impl TestBrdf {
    /// Evaluates `f(wi, wo)`; 0 when either direction is below the surface.
    pub fn eval(&self, wi: Vec3, wo: Vec3) -> f32 {
        if wi.z <= 0.0 || wo.z <= 0.0 {
            return 0.0;
        }
        match *self {
            TestBrdf::Lambert { albedo } => albedo * FRAC_1_PI,
            TestBrdf::CosinePower { k, n } => k * wi.dot(wo).powi(n) / (wi.z * wo.z),
            TestBrdf::IncidentOnly => 0.5 * wi.z * FRAC_1_PI,
            TestBrdf::ScaledIncidentOnly { scale } => scale * 0.5 * wi.z * FRAC_1_PI,
            TestBrdf::NanNearGrazing if wi.z * wo.z < 0.05 => f32::NAN,
            TestBrdf::NanNearGrazing => 0.5 * FRAC_1_PI,
            TestBrdf::NanOneWayRound if wi.z > wo.z => f32::NAN,
            TestBrdf::NanOneWayRound => 0.5 * FRAC_1_PI,
            TestBrdf::Lopsided if wi.z > wo.z => 2.0 * FRAC_1_PI,
            TestBrdf::Lopsided => FRAC_1_PI,
        }
    }

    /// A short description for messages.
    pub fn describe(&self) -> String {
        match *self {
            TestBrdf::Lambert { albedo } => format!("Lambert albedo {albedo}"),
            TestBrdf::CosinePower { k, n } => {
                format!("k (wi·wo)^{n} / (cos θi cos θo) with k = {k:.4}")
            }
            TestBrdf::IncidentOnly => "cos θi / (2π) (depends on wi only)".into(),
            TestBrdf::ScaledIncidentOnly { scale } => {
                format!("{scale:e} cos θi / (2π) (depends on wi only, and tiny)")
            }
            TestBrdf::NanNearGrazing => "Lambert 1/2, NaN where cos θi cos θo < 0.05".into(),
            TestBrdf::NanOneWayRound => "Lambert 1/2, NaN where cos θi > cos θo".into(),
            TestBrdf::Lopsided => "2/π where cos θi > cos θo, else 1/π".into(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn incident_only_is_not_reciprocal() {
        let (a, b) = (Vec3::new(0.6, 0.0, 0.8), Vec3::Z);
        let f = TestBrdf::IncidentOnly;
        assert!((f.eval(a, b) - f.eval(b, a)).abs() > 0.01);
        let g = TestBrdf::CosinePower { k: 0.5, n: 3 };
        assert_eq!(g.eval(a, b), g.eval(b, a));
        let l = TestBrdf::Lopsided;
        let (ab, ba) = (l.eval(a, b), l.eval(b, a));
        assert_eq!((ab - ba).abs() / ab.max(ba), 0.5);
        let n = TestBrdf::NanOneWayRound;
        assert!(n.eval(b, a).is_nan() && n.eval(a, b).is_finite());
    }
}
