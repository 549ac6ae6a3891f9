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
    /// [`TestBrdf::Lopsided`] negated: `−2/π` where `cos θi > cos θo`, else `−1/π`. No
    /// physical BRDF, but the relative gap is one of magnitudes, exactly 1/2 again.
    NegativeLopsided,
    /// Lambert with albedo 1/2, but +∞ where `cos θi cos θo < 0.05`: symmetric, and equal
    /// both ways round where it is infinite, yet a value no test may call reciprocal or
    /// plausible.
    InfiniteNearGrazing,
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
            TestBrdf::NegativeLopsided if wi.z > wo.z => -2.0 * FRAC_1_PI,
            TestBrdf::NegativeLopsided => -FRAC_1_PI,
            TestBrdf::InfiniteNearGrazing if wi.z * wo.z < 0.05 => f32::INFINITY,
            TestBrdf::InfiniteNearGrazing => 0.5 * FRAC_1_PI,
        }
    }

    /// The exact directional albedo `∫ f(wi, wo) cos θo dωo` at the incident direction `wi`
    /// (local frame), where it has a closed form: `None` for the BRDFs whose albedo is
    /// NaN, infinite or has none, and for `wi` at or below the surface.
    pub fn albedo(&self, wi: Vec3) -> Option<f64> {
        let cos = wi.normalize_or_zero().z as f64;
        if cos <= 0.0 {
            return None;
        }
        match *self {
            TestBrdf::Lambert { albedo } => Some(albedo as f64),
            // `∫ (wi·wo)^n dωo` over the hemisphere is `2π/(n + 1)` for even n, whatever wi.
            TestBrdf::CosinePower { k, n } if n % 2 == 0 => {
                Some(std::f64::consts::TAU * k as f64 / ((n + 1) as f64 * cos))
            }
            TestBrdf::IncidentOnly => Some(0.5 * cos),
            TestBrdf::ScaledIncidentOnly { scale } => Some(scale as f64 * 0.5 * cos),
            // `(2/π) ∫_{cos θo < c} cos θo dω + (1/π) ∫_{cos θo > c} cos θo dω = 2c² + 1 − c²`.
            TestBrdf::Lopsided => Some(1.0 + cos * cos),
            TestBrdf::CosinePower { .. }
            | TestBrdf::NanNearGrazing
            | TestBrdf::NanOneWayRound
            | TestBrdf::NegativeLopsided
            | TestBrdf::InfiniteNearGrazing => None,
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
            TestBrdf::NegativeLopsided => "−2/π where cos θi > cos θo, else −1/π".into(),
            TestBrdf::InfiniteNearGrazing => "Lambert 1/2, +∞ where cos θi cos θo < 0.05".into(),
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
        let grazing = Vec3::new(0.999, 0.0, 0.01).normalize();
        let i = TestBrdf::InfiniteNearGrazing;
        assert_eq!(i.eval(grazing, a), f32::INFINITY);
        assert_eq!(i.eval(a, grazing), f32::INFINITY);
    }

    /// The closed-form albedos agree with Monte Carlo over the hemisphere.
    #[test]
    fn the_closed_form_albedos_match_monte_carlo() {
        use crate::sampling::{Sampler, uniform_hemisphere, uniform_hemisphere_pdf};
        let wi = Vec3::new(0.8, 0.0, 0.6);
        for brdf in [
            TestBrdf::Lambert { albedo: 0.7 },
            TestBrdf::CosinePower { k: 0.2, n: 2 },
            TestBrdf::CosinePower { k: 0.2, n: 4 },
            TestBrdf::IncidentOnly,
            TestBrdf::Lopsided,
        ] {
            let mut s = Sampler::new(4, 0);
            let n = 200_000;
            let mc = (0..n)
                .map(|_| {
                    let wo = uniform_hemisphere(s.next_2d());
                    (brdf.eval(wi, wo) * wo.z / uniform_hemisphere_pdf()) as f64
                })
                .sum::<f64>()
                / n as f64;
            let exact = brdf.albedo(wi).expect("a closed form");
            assert!((mc / exact - 1.0).abs() < 0.01, "{brdf:?}: {mc} vs {exact}");
        }
    }
}
