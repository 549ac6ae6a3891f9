//! Cases of `beckmann_ndf`, and its normalisation as an estimator.

use crate::grade::case_input::CaseInput;
use crate::grade::estimator::EstimatorSpec;
use crate::grade::call::Call;
use crate::grade::case::Rule;
use crate::grade::domain::{Draw, Param, cos_z, cosine, floored_roughness};
use crate::grade::declared::Declared;
use crate::grade::tolerance::Tolerance;
use crate::sampling::{Sampler, uniform_hemisphere, uniform_hemisphere_pdf};
use crate::worksheet::Tasks;
use glam::Vec3;

/// What the estimator and sampling checks of this task catch in at least 90 % of
/// gradings, as measured by `pbrlab power` (asserted by tests/instructor/power.rs).
pub const POWER: Declared = Declared {
    estimator_bias: Some(0.05),
    sampler_distortion: None,
};

const D: &str = "D = exp(−tan²θh / α²) / (π α² cos⁴θh)";

fn at_degrees(deg: f32) -> Vec3 {
    let r = deg.to_radians();
    Vec3::new(r.sin(), 0.0, r.cos())
}

fn ndf(name: &str, h: Vec3, alpha: f32) -> CaseInput {
    CaseInput::new(name, Call::beckmann_ndf { h, alpha })
        .rule(Rule::Close(TAIL))
        .note(D)
}

/// The tolerance of a Beckmann density: its tail falls through thirty orders of magnitude
/// before it underflows (3.7e-35 at the text's own θh = 42.5°, α = 0.1), so the absolute
/// part is the smallest normal f32, not [`Tolerance::F32`]'s 1e-5, which would take any
/// tail for 0.
const TAIL: Tolerance = Tolerance::new(1.2e-38, 2e-4);

pub fn fixed() -> Vec<CaseInput> {
    vec![
        ndf("worksheet §3.4.3: h = n, α = 0.1", Vec3::Z, 0.1),
        ndf("errata §3.4.3: θh = 30°, α = 0.1", at_degrees(30.0), 0.1),
        ndf("errata §3.4.3: θh = 42.5°, α = 0.1", at_degrees(42.5), 0.1)
            .note("far in the tail the density is tiny, not 0"),
        ndf("θh = 30°, α = 0.5", at_degrees(30.0), 0.5),
        ndf("errata: grazing h", Vec3::X, 0.1).note("at cos θh = 0 return 0, not 0 · ∞"),
        ndf("below the surface", at_degrees(120.0), 0.3).note("h below the surface has density 0"),
    ]
}

fn of(c: &Call) -> Option<(Vec3, f32)> {
    match c {
        Call::beckmann_ndf { h, alpha } => Some((*h, *alpha)),
        _ => None,
    }
}

/// The declared domain of `beckmann_ndf(h, alpha)`: a unit local `h` anywhere (0 at or
/// below the horizon, and where `cos⁴θh` underflows near `cos θh = 1e-12`), a roughness from
/// 0 (raised to `MIN_ALPHA`) to 1.
pub const DOMAIN: &[Param] = &[
    cosine("beckmann_ndf", "cos θh", &["h"], |c| {
        of(c).map(|x| cos_z(x.0))
    }),
    floored_roughness("beckmann_ndf", "alpha", &["alpha"], |c| {
        of(c).map(|x| x.1 as f64)
    }),
];

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    let mut d = Draw::new(s);
    (0..count)
        .map(|_| {
            let cos = d.value(&DOMAIN[0]);
            let h = d.direction_at(Vec3::Z, cos);
            let alpha = d.value(&DOMAIN[1]) as f32;
            ndf("", h, alpha)
        })
        .collect()
}

pub fn estimators<T: Tasks>(t: &T) -> Vec<EstimatorSpec<'_>> {
    vec![EstimatorSpec {
        name: "∫ D(h) cos θh dωh for α = 0.4, uniform hemisphere sampling".into(),
        analytic: 1.0,
        samples: 200_000,
        estimate: Box::new(move |s: &mut Sampler| {
            Ok({
                let h = uniform_hemisphere(s.next_2d());
                (t.beckmann_ndf(h, 0.4) * h.z / uniform_hemisphere_pdf()) as f64
            })
        }),
    }]
}
