//! Cases of `cosine_pdf`, and the irradiance estimator built on `cosine_sample`.

use crate::grade::catalogue::polygon::{hits_rectangle, projected_solid_angle};
use crate::grade::case_input::CaseInput;
use crate::grade::estimator::EstimatorSpec;
use crate::grade::call::{Call, SampleCall};
use crate::grade::domain::{Draw, Param, cos_z, cosine};
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

const PDF: &str = "the density is cos θ / π above the surface and 0 below";

/// The sampling check's one setup: `cosine_sample` has no parameters.
pub fn setups() -> Vec<SampleCall> {
    vec![SampleCall::CosineSample]
}

pub fn fixed() -> Vec<CaseInput> {
    let pdf = |name: &str, w: Vec3| CaseInput::new(name, Call::cosine_pdf { w }).note(PDF);
    vec![
        pdf("normal", Vec3::Z),
        pdf("45°", Vec3::new(0.0, 1.0, 1.0).normalize()),
        pdf("grazing", Vec3::X),
        pdf("below the surface", Vec3::new(0.6, 0.0, -0.8)),
        crate::grade::case_input::jacobian_case("the warp follows cosine_pdf", SampleCall::CosineSample),
    ]
}

/// The declared domain of `cosine_pdf(w)`: any unit direction, 0 below the horizon; and of
/// `cosine_sample(u)`: any point of the unit square.
pub const DOMAIN: &[Param] = &[
    cosine("cosine_pdf", "cos θ of w", &["w"], |c| match c {
        Call::cosine_pdf { w } => Some(cos_z(*w)),
        _ => None,
    }),
    crate::grade::case_input::JACOBIAN,
];

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    let mut d = Draw::new(s);
    (0..count)
        .map(|_| {
            let cos = d.value(&DOMAIN[0]);
            let w = d.direction_at(Vec3::Z, cos);
            CaseInput::new("", Call::cosine_pdf { w }).note(PDF)
        })
        .collect()
}

/// The errata's MIS light, a unit square at height 1 off to one side of the normal.
pub const QUAD_Z: f32 = 1.0;
/// Its extent along x.
pub const QUAD_X: (f32, f32) = (0.5, 1.5);
/// Its extent along y.
pub const QUAD_Y: (f32, f32) = (-0.5, 0.5);

/// The square's corners.
pub fn quad() -> [Vec3; 4] {
    [
        Vec3::new(QUAD_X.0, QUAD_Y.0, QUAD_Z),
        Vec3::new(QUAD_X.1, QUAD_Y.0, QUAD_Z),
        Vec3::new(QUAD_X.1, QUAD_Y.1, QUAD_Z),
        Vec3::new(QUAD_X.0, QUAD_Y.1, QUAD_Z),
    ]
}

pub fn estimators<T: Tasks>(t: &T) -> Vec<EstimatorSpec<'_>> {
    vec![EstimatorSpec {
        name: "irradiance from a unit-radiance square light, cosine sampling".into(),
        analytic: projected_solid_angle(&quad()),
        samples: 200_000,
        estimate: Box::new(move |s: &mut Sampler| {
            Ok({
                let w = t.cosine_sample(s.next_2d());
                if hits_rectangle(w, QUAD_Z, QUAD_X, QUAD_Y) {
                    (w.z / t.cosine_pdf(w)) as f64
                } else {
                    0.0
                }
            })
        }),
    }]
}
