//! Stability cases of the `aniso_ndf` task: α → 0 in f32, α = 0, α = 1, one α zero, and
//! normals below the horizon or with a cosine above one.

use crate::stability::case::{Case, NON_NEGATIVE};
use crate::grade::tolerance::Tolerance;
use crate::stability::expect::{Bound, Expect};
use crate::stability::inputs::cos_above_one;
use crate::worksheet::{TaskId, Tasks};
use glam::Vec3;
use std::f64::consts::{FRAC_1_PI, PI};

/// The smallest peak value a delta-like lobe may be given (that of α = 1e-2): clamping α
/// keeps the density finite, but it must stay a sharp spike.
pub const DELTA_PEAK_MIN: f64 = 1.0 / (PI * 1e-4);

/// A delta lobe evaluated at its peak: finite, and at least [`DELTA_PEAK_MIN`].
pub const DELTA_PEAK: Bound = Bound::Within(DELTA_PEAK_MIN, f64::INFINITY);

const CANCEL: &str = "α²/(π((α² − 1)cos²θ + 1)²) cancels in f32 (−2.6 % at α = 1e-3, inf at \
                      1e-4); use 1/(π αx αy (hx²/αx² + hy²/αy² + hz²)²)";
const DELTA: &str = "α = 0 is a mirror: clamp α to a small floor (at most 1e-4, so α = 1e-4 stays exact) \
                     or treat it as a specular lobe, so that 0·∞ never happens";

/// The cases.
pub fn cases<T: Tasks>() -> Vec<Case<T>> {
    vec![
        Case {
            task: TaskId::AnisoNdf,
            name: "aniso_ndf/alpha_1e-3_peak",
            input: "h = (0, 0, 1), αx = αy = 1e-3 (f32)",
            eval: |t| t.aniso_ndf(Vec3::Z, 1e-3, 1e-3).into(),
            range: NON_NEGATIVE,
            expect: Expect::scalar(1.0 / (PI * 1e-6), Tolerance::rel(1e-4)),
            guard: CANCEL,
        },
        Case {
            task: TaskId::AnisoNdf,
            name: "aniso_ndf/alpha_1e-4_peak",
            input: "h = (0, 0, 1), αx = αy = 1e-4 (f32)",
            eval: |t| t.aniso_ndf(Vec3::Z, 1e-4, 1e-4).into(),
            range: NON_NEGATIVE,
            expect: Expect::scalar(1.0 / (PI * 1e-8), Tolerance::rel(1e-4)),
            guard: CANCEL,
        },
        Case {
            task: TaskId::AnisoNdf,
            name: "aniso_ndf/alpha_one",
            input: "h = (0.5, 0.5, 0.7071068), αx = αy = 1",
            eval: |t| {
                t.aniso_ndf(Vec3::new(0.5, 0.5, 0.5f32.sqrt()), 1.0, 1.0)
                    .into()
            },
            range: NON_NEGATIVE,
            expect: Expect::scalar(FRAC_1_PI, Tolerance::rel(1e-5)),
            guard: "with α = 1 the density is 1/π for every h above the surface",
        },
        Case {
            task: TaskId::AnisoNdf,
            name: "aniso_ndf/below_horizon",
            input: "h = (0.5, 0.5, −0.7071068), αx = αy = 0.5",
            eval: |t| {
                t.aniso_ndf(Vec3::new(0.5, 0.5, -(0.5f32.sqrt())), 0.5, 0.5)
                    .into()
            },
            range: NON_NEGATIVE,
            expect: Expect::scalar(0.0, Tolerance::abs(0.0)),
            guard: "microfacet normals below the surface have density 0 (χ⁺(h·n))",
        },
        Case {
            task: TaskId::AnisoNdf,
            name: "aniso_ndf/alpha_zero_off_peak",
            input: "h = (0, 0.5, 0.8660254), αx = αy = 0",
            eval: |t| {
                t.aniso_ndf(Vec3::new(0.0, 0.5, 0.75f32.sqrt()), 0.0, 0.0)
                    .into()
            },
            range: NON_NEGATIVE,
            expect: Expect::scalar(0.0, Tolerance::abs(1e-3)),
            guard: DELTA,
        },
        Case {
            task: TaskId::AnisoNdf,
            name: "aniso_ndf/alpha_zero_peak",
            input: "h = (0, 0, 1), αx = αy = 0",
            eval: |t| t.aniso_ndf(Vec3::Z, 0.0, 0.0).into(),
            range: DELTA_PEAK,
            expect: Expect::Finite,
            guard: DELTA,
        },
        Case {
            task: TaskId::AnisoNdf,
            name: "aniso_ndf/alpha_x_zero",
            input: "h = (0, 0.5, 0.8660254), αx = 0, αy = 0.5",
            eval: |t| {
                t.aniso_ndf(Vec3::new(0.0, 0.5, 0.75f32.sqrt()), 0.0, 0.5)
                    .into()
            },
            range: NON_NEGATIVE,
            expect: Expect::Finite,
            guard: DELTA,
        },
        Case {
            task: TaskId::AnisoNdf,
            name: "aniso_ndf/cos_above_one",
            input: "h = (0, 0, 1 + 2⁻²³), αx = αy = 0.5",
            eval: |t| t.aniso_ndf(cos_above_one(), 0.5, 0.5).into(),
            range: NON_NEGATIVE,
            expect: Expect::scalar(1.0 / (PI * 0.25), Tolerance::rel(1e-5)),
            guard: "no square root of 1 − cos²θ is needed in the Cartesian form",
        },
    ]
}
