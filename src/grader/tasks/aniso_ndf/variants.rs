// The variants of `aniso_ndf` the tests grade the grader with (see `src/grader/tasks/mod.rs`).
// `tests/instructor/support/variants.rs` includes this file into a module of the tests,
// so it has no inner attributes or doc; the student handout leaves it out.

use crate::support::patch::{Variant, variant};
use crate::support::variants::Naive;
use glam::Vec3;
use pbrlab::bsdf::MIN_ALPHA;
use pbrlab::stability::Verdict;
use pbrlab::worksheet::TaskId;
use pbrlab_solutions as sol;
use std::f32::consts::PI;

/// Known-wrong implementations of `aniso_ndf`: each must fail this task and no other.
pub fn wrong() -> Vec<Variant> {
    use TaskId::*;
    vec![
        variant(
            "polar form through tan²θ, NaN where cos²θ underflows",
            AnisoNdf,
            |p| {
                p.aniso_ndf = Some(|h, ax, ay| {
                    if h.z <= 0.0 {
                        return 0.0;
                    }
                    let (ax, ay) = (ax.max(1e-4), ay.max(1e-4));
                    let c2 = h.z * h.z;
                    let s2 = (1.0 - c2).max(0.0);
                    let tan2 = s2 / c2;
                    let (cos2_phi, sin2_phi) = if s2 == 0.0 {
                        (1.0, 0.0)
                    } else {
                        (h.x * h.x / s2, h.y * h.y / s2)
                    };
                    let e = tan2 * (cos2_phi / (ax * ax) + sin2_phi / (ay * ay));
                    1.0 / (PI * ax * ay * c2 * c2 * (1.0 + e) * (1.0 + e))
                })
            },
        ),
        variant("swapped anisotropic roughnesses", AnisoNdf, |p| {
            p.aniso_ndf = Some(|h, ax, ay| ggx(h, ay, ax))
        }),
        variant("missing 1/π", AnisoNdf, |p| {
            p.aniso_ndf = Some(|h, ax, ay| ggx(h, ax, ay) * PI)
        }),
        variant("isotropic: αx for both directions", AnisoNdf, |p| {
            p.aniso_ndf = Some(|h, ax, _| ggx(h, ax, ax))
        }),
        variant("no zero below the horizon", AnisoNdf, |p| {
            p.aniso_ndf = Some(|h, ax, ay| ggx(Vec3::new(h.x, h.y, h.z.abs()), ax, ay))
        }),
        variant(
            "`h.z < 0` for the horizon: h in the surface is not 0",
            AnisoNdf,
            |p| {
                p.aniso_ndf = Some(|h, ax, ay| {
                    if h.z == 0.0 {
                        // The formula itself at hz = 0.
                        let (x, y) = (h.x / ax, h.y / ay);
                        1.0 / (PI * ax * ay * (x * x + y * y).powi(2))
                    } else {
                        ggx(h, ax, ay)
                    }
                })
            },
        ),
    ]
}

/// Correct implementations of `aniso_ndf` that differ from the reference: each gets full marks.
pub fn different() -> Vec<Variant> {
    use TaskId::*;
    vec![variant(
        "anisotropic GGX in the polar form",
        AnisoNdf,
        |p| {
            p.aniso_ndf = Some(|h, ax, ay| {
                if h.z <= 0.0 {
                    return 0.0;
                }
                // α = 0 is a mirror, which no density represents: keep a tall finite peak.
                let (ax, ay) = (ax.max(1e-4), ay.max(1e-4));
                let c2 = h.z * h.z;
                let s2 = (1.0 - c2).max(0.0);
                let (cos2_phi, sin2_phi) = if s2 == 0.0 {
                    (1.0, 0.0)
                } else {
                    (h.x * h.x / s2, h.y * h.y / s2)
                };
                // cos²θ (1 + tan²θ (…)) without tan θ, which overflows at grazing.
                let q = c2 + s2 * (cos2_phi / (ax * ax) + sin2_phi / (ay * ay));
                1.0 / (PI * ax * ay * q * q)
            })
        },
    )]
    .into_iter()
    .chain(other_arithmetic())
    .collect()
}

/// Correct implementations of `aniso_ndf` in other arithmetic (f64, other algebraic forms):
/// each gets full marks, whatever its rounding.
fn other_arithmetic() -> Vec<Variant> {
    use TaskId::*;
    vec![variant("anisotropic GGX in f64 throughout", AnisoNdf, |p| {
        p.aniso_ndf = Some(|h, ax, ay| {
            if h.z <= 0.0 {
                return 0.0;
            }
            let h = h.as_dvec3();
            let ax = f64::from(ax.abs().max(MIN_ALPHA));
            let ay = f64::from(ay.abs().max(MIN_ALPHA));
            let s = (h.x / ax).powi(2) + (h.y / ay).powi(2) + h.z * h.z;
            (1.0 / (std::f64::consts::PI * ax * ay * s * s)) as f32
        })
    })]

}

/// Naive implementations of `aniso_ndf` (the textbook formula without its guards), each with
/// exactly the stability cases it must fail and the verdict of each.
pub fn naive() -> Vec<Naive> {
    use TaskId::*;
    use Verdict::*;
    vec![Naive::new(
        "`aniso_ndf` is the cancelling isotropic form, with no χ⁺",
        AnisoNdf,
        |p| {
            p.aniso_ndf = Some(textbook::aniso_ndf);
        },
        vec![
            ("aniso_ndf/alpha_1e-3_peak", WrongValue),
            ("aniso_ndf/alpha_1e-4_peak", Inf),
            ("aniso_ndf/below_horizon", WrongValue),
            ("aniso_ndf/alpha_zero_peak", NaN),
            ("cook_torrance/alpha_zero_specular", NaN),
            ("ndf_pdf/alpha_1e-4_mirror", Inf),
        ],
    )]
}

/// GGX D in Cartesian form with free roughnesses (for slips in other tasks).
fn ggx(h: Vec3, ax: f32, ay: f32) -> f32 {
    sol::aniso_ndf::aniso_ndf(h, ax, ay)
}

/// The naive functions of [`naive`].
mod textbook {
    use super::*;

    /// The common isotropic GGX form α²/(π((α² − 1)cos²θ + 1)²), which cancels in f32, with no
    /// test for h below the surface.
    pub fn aniso_ndf(h: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
        let a2 = alpha_x * alpha_y;
        let c2 = h.z * h.z;
        a2 / (PI * ((a2 - 1.0) * c2 + 1.0).powi(2))
    }
}
