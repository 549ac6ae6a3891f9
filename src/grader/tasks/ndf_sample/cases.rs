//! Cases of `ndf_pdf`, the setups of the `ndf_sample` sampling check, and the irradiance
//! estimator built on both.

use crate::tasks::cosine_sample::cases::{QUAD_X, QUAD_Y, QUAD_Z, quad};
use crate::grade::catalogue::polygon::{hits_rectangle, projected_solid_angle};
use crate::grade::case_input::CaseInput;
use crate::grade::estimator::EstimatorSpec;
use crate::grade::call::{Call, SampleCall};
use crate::grade::domain::{Draw, Param};
use crate::grade::declared::Declared;
use crate::sampling::Sampler;
use crate::worksheet::Tasks;
use glam::Vec3;

/// What the estimator and sampling checks of this task catch in at least 90 % of
/// gradings, as measured by `pbrlab power` (asserted by tests/instructor/power.rs).
pub const POWER: Declared = Declared {
    estimator_bias: Some(0.05),
    sampler_distortion: Some(0.05),
};

const PDF: &str = "pdf(wi) = D(h) cos θh / (4 |wo·h|) with h = normalize(wo + wi)";
const BELOW: &str = "wi below the surface cannot be sampled: pdf 0";

fn at(theta_deg: f32, phi_deg: f32) -> Vec3 {
    let (t, p) = (theta_deg.to_radians(), phi_deg.to_radians());
    Vec3::new(t.sin() * p.cos(), t.sin() * p.sin(), t.cos())
}

fn pdf(name: &str, wo: Vec3, wi: Vec3, alpha_x: f32, alpha_y: f32) -> CaseInput {
    CaseInput::new(
        name,
        Call::ndf_pdf {
            wo,
            wi,
            alpha_x,
            alpha_y,
        },
    )
}

pub fn fixed() -> Vec<CaseInput> {
    vec![
        pdf(
            "mirror direction, h = n",
            at(30.0, 0.0),
            at(30.0, 180.0),
            0.3,
            0.3,
        )
        .note(PDF),
        pdf(
            "errata §5.2: θh = 40°",
            at(10.0, 0.0),
            at(70.0, 0.0),
            0.3,
            0.3,
        )
        .note(PDF),
        pdf("anisotropic", at(50.0, 20.0), at(20.0, 250.0), 0.15, 0.5).note(PDF),
        pdf(
            "wi below the surface",
            at(30.0, 0.0),
            at(120.0, 180.0),
            0.3,
            0.3,
        )
        .note(BELOW),
        crate::grade::case_input::jacobian_case("the warp follows ndf_pdf at setup 1", setups()[0].clone()),
        crate::grade::case_input::jacobian_case("the warp follows ndf_pdf at setup 2", setups()[1].clone()),
        crate::grade::case_input::jacobian_case("the warp follows ndf_pdf at setup 3", setups()[2].clone()),
    ]
}

fn of(c: &Call) -> Option<(Vec3, Vec3, f32, f32)> {
    match c {
        Call::ndf_pdf {
            wo,
            wi,
            alpha_x,
            alpha_y,
        } => Some((*wo, *wi, *alpha_x, *alpha_y)),
        _ => None,
    }
}

/// The declarations of the microfacet pair.
const PAIR: [Param; 6] = crate::microfacet_domain!("ndf_pdf", of);

/// The declared domain of `ndf_pdf(wo, wi, alpha_x, alpha_y)`: finite and non-negative for
/// every input: unit local directions anywhere (0 where the sampler cannot produce `wi`:
/// `wi` at or below the horizon, `wo·h ≤ 0`, `wo ≈ −wi`), roughnesses from 0 (raised to
/// `MIN_ALPHA`) to 1; and of `ndf_sample(wo, alpha_x, alpha_y, u)`: any point of the square.
pub const DOMAIN: &[Param] = &[
    PAIR[0],
    PAIR[1],
    PAIR[2],
    PAIR[3],
    PAIR[4],
    PAIR[5],
    crate::grade::case_input::JACOBIAN,
];

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    let mut d = Draw::new(s);
    (0..count)
        .map(|i| {
            // One case in eight aims wi at −wo.
            let (wo, wi, ax, ay) = d.microfacet(&PAIR, i % 8 == 3);
            let case = pdf("", wo, wi, ax, ay);
            if wi.z <= 0.0 {
                case.note(BELOW)
            } else {
                case.note(PDF)
            }
        })
        .collect()
}

pub fn setups() -> Vec<SampleCall> {
    vec![
        SampleCall::NdfSample {
            wo: at(30.0, 0.0),
            alpha_x: 0.3,
            alpha_y: 0.3,
        },
        SampleCall::NdfSample {
            wo: at(60.0, 40.0),
            alpha_x: 0.15,
            alpha_y: 0.5,
        },
        SampleCall::NdfSample {
            wo: at(80.0, 200.0),
            alpha_x: 0.6,
            alpha_y: 0.6,
        },
    ]
}

pub fn estimators<T: Tasks>(t: &T) -> Vec<EstimatorSpec<'_>> {
    // wo mirrors the light's centre, so the lobe covers the light.
    let wo = Vec3::new(-1.0, 0.0, 1.0).normalize();
    let (ax, ay) = (0.4, 0.3);
    vec![EstimatorSpec {
        name: "irradiance from a unit-radiance square light, NDF sampling".into(),
        analytic: projected_solid_angle(&quad()),
        samples: 200_000,
        estimate: Box::new(move |s: &mut Sampler| {
            Ok(match t.ndf_sample(wo, ax, ay, s.next_2d()) {
                Some(wi) if hits_rectangle(wi, QUAD_Z, QUAD_X, QUAD_Y) => {
                    (wi.z / t.ndf_pdf(wo, wi, ax, ay)) as f64
                }
                _ => 0.0,
            })
        }),
    }]
}
