//! Cases of `aniso_ndf`, and its normalisation as an estimator.

use crate::grade::case_input::CaseInput;
use crate::grade::estimator::EstimatorSpec;
use crate::grade::call::Call;
use crate::grade::domain::{Draw, Param, anisotropy, cos_z, cosine, ratio, floored_roughness};
use crate::grade::declared::Declared;
use crate::sampling::{Sampler, uniform_hemisphere, uniform_hemisphere_pdf};
use crate::worksheet::Tasks;
use glam::Vec3;

/// What the estimator and sampling checks of this task catch in at least 90 % of
/// gradings, as measured by `pbrlab power` (asserted by tests/instructor/power.rs).
pub const POWER: Declared = Declared {
    estimator_bias: Some(0.05),
    sampler_distortion: None,
};

const D: &str = "D = 1 / (π αx αy (hx²/αx² + hy²/αy² + hz²)²), αx along local x";

fn ndf(name: &str, h: Vec3, alpha_x: f32, alpha_y: f32) -> CaseInput {
    CaseInput::new(
        name,
        Call::aniso_ndf {
            h,
            alpha_x,
            alpha_y,
        },
    )
    .note(D)
}

pub fn fixed() -> Vec<CaseInput> {
    let h = Vec3::new(0.5, 0.5, std::f32::consts::FRAC_1_SQRT_2);
    let along_x = Vec3::new(0.6, 0.0, 0.8);
    vec![
        ndf("worksheet §4.1a", h, 0.5, 0.5),
        ndf("worksheet §4.1b", h, 0.1, 1.0),
        ndf("tilted along x, αx < αy", along_x, 0.2, 0.8),
        ndf("tilted along x, αx > αy", along_x, 0.8, 0.2),
        ndf(
            "errata: α = 1 is 1/π everywhere",
            Vec3::new(0.36, 0.48, 0.8),
            1.0,
            1.0,
        ),
        ndf("smooth, h = n", Vec3::Z, 0.05, 0.05),
        CaseInput::new(
            "errata: below the horizon",
            Call::aniso_ndf {
                h: Vec3::new(0.5, 0.5, -std::f32::consts::FRAC_1_SQRT_2),
                alpha_x: 0.5,
                alpha_y: 0.5,
            },
        )
        .note("h below the surface has density 0"),
    ]
}

fn of(c: &Call) -> Option<(Vec3, f32, f32)> {
    match c {
        Call::aniso_ndf {
            h,
            alpha_x,
            alpha_y,
        } => Some((*h, *alpha_x, *alpha_y)),
        _ => None,
    }
}

/// The declared domain of `aniso_ndf(h, alpha_x, alpha_y)`: a unit local `h` anywhere (0 at
/// or below the horizon), roughnesses from 0 (raised to `MIN_ALPHA`, finite) to 1, the
/// text's traps `1e-3` and `1e-4` among them.
pub const DOMAIN: &[Param] = &[
    cosine("aniso_ndf", "cos θh", &["h"], |c| {
        of(c).map(|x| cos_z(x.0))
    }),
    floored_roughness("aniso_ndf", "alpha_x", &["alpha_x"], |c| {
        of(c).map(|x| x.1 as f64)
    })
    .special(ALPHA_TRAPS),
    floored_roughness("aniso_ndf", "alpha_y", &["alpha_y"], |c| {
        of(c).map(|x| x.2 as f64)
    })
    .special(ALPHA_TRAPS),
    anisotropy("aniso_ndf", &["alpha_x", "alpha_y"], |c| {
        of(c).and_then(|x| ratio(x.1, x.2))
    }),
];

/// Roughnesses the text names: 0, the f32 traps of the textbook form, and 1 (`D = 1/π`).
const ALPHA_TRAPS: &[f64] = &[0.0, 1e-4, 1e-3, 1.0];

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    let mut d = Draw::new(s);
    (0..count)
        .map(|_| {
            let cos = d.value(&DOMAIN[0]);
            let h = d.direction_at(Vec3::Z, cos);
            let (ax, ay) = d.alpha_pair(&DOMAIN[1], &DOMAIN[3]);
            ndf("", h, ax, ay)
        })
        .collect()
}

pub fn estimators<T: Tasks>(t: &T) -> Vec<EstimatorSpec<'_>> {
    vec![EstimatorSpec {
        name: "∫ D(h) cos θh dωh for αx = 0.25, αy = 0.5, uniform hemisphere sampling".into(),
        analytic: 1.0,
        samples: 200_000,
        estimate: Box::new(move |s: &mut Sampler| {
            Ok({
                let h = uniform_hemisphere(s.next_2d());
                (t.aniso_ndf(h, 0.25, 0.5) * h.z / uniform_hemisphere_pdf()) as f64
            })
        }),
    }]
}
