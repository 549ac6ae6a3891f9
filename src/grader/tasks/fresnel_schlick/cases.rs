//! Cases of `schlick_r0` and `fresnel_schlick`.

use crate::grade::case_input::CaseInput;
use crate::grade::catalogue::indices::{ETA, critical, eta_pair, index_ratio, sin2_t};
use crate::grade::call::Call;
use crate::grade::domain::{Draw, Param, UPPER_COS_BOUNDARIES};
use crate::sampling::Sampler;

const R0: &str = "R0 = ((η_i − η_t)/(η_i + η_t))²";
const DENSE: &str = "dense→less dense: use cos θt";
const TIR: &str = "total internal reflection: return 1";
const EQUAL: &str = "equal indices: nothing reflects, return 0";

/// The note that explains the usual mistake for these inputs.
fn note(cos_theta_i: f32, eta_i: f32, eta_t: f32) -> Option<&'static str> {
    let sin2_t = (eta_i / eta_t).powi(2) * (1.0 - cos_theta_i * cos_theta_i).max(0.0);
    if eta_i == eta_t {
        Some(EQUAL)
    } else if sin2_t >= 1.0 {
        Some(TIR)
    } else if eta_i > eta_t {
        Some(DENSE)
    } else {
        None
    }
}

fn schlick(name: &str, cos_theta_i: f32, eta_i: f32, eta_t: f32) -> CaseInput {
    let case = CaseInput::new(
        name,
        Call::fresnel_schlick {
            cos_theta_i,
            eta_i,
            eta_t,
        },
    );
    match note(cos_theta_i, eta_i, eta_t) {
        Some(n) => case.note(n),
        None => case,
    }
}

fn r0(name: &str, eta_i: f32, eta_t: f32) -> CaseInput {
    CaseInput::new(name, Call::schlick_r0 { eta_i, eta_t }).note(R0)
}

fn cos_deg(deg: f32) -> f32 {
    deg.to_radians().cos()
}

pub fn fixed() -> Vec<CaseInput> {
    vec![
        r0("air/glass", 1.0, 1.5),
        r0(
            "errata §1.4: glass/water is 0.0036085, not 0.0041",
            1.5,
            1.33,
        ),
        r0("equal indices", 1.33, 1.33),
        schlick("normal incidence air→glass", 1.0, 1.0, 1.5),
        schlick(
            "errata §3.4.2: θ = 60°, i·h = cos 30°",
            cos_deg(30.0),
            1.0,
            1.5,
        ),
        schlick(
            "errata §3.4.2: θ = 85°, i·h = 0.7372773",
            0.737_277_3,
            1.0,
            1.5,
        ),
        schlick("errata §1.3: glass→air at 40°", cos_deg(40.0), 1.5, 1.0),
        schlick(
            "errata §1.3: glass→air at 45° (TIR)",
            cos_deg(45.0),
            1.5,
            1.0,
        ),
        schlick(
            "errata §1.3: equal indices at 60°",
            cos_deg(60.0),
            1.33,
            1.33,
        ),
        schlick(
            "errata §1.3: equal indices at 89°",
            cos_deg(89.0),
            1.33,
            1.33,
        ),
        schlick("grazing air→glass", 0.0, 1.0, 1.5),
    ]
}

/// The declared domain of `schlick_r0(eta_i, eta_t)` and
/// `fresnel_schlick(cos_theta_i, eta_i, eta_t)`: indices from vacuum to germanium (1 to 4),
/// either way round and equal; a cosine in [0, 1] that rounding may push to `1 + 1e-7`; the critical
/// angle when going to a less dense medium.
pub const DOMAIN: &[Param] = &[
    index_ratio("schlick_r0", "η_i/η_t", &["eta_i", "eta_t"], |c| match c {
        Call::schlick_r0 { eta_i, eta_t } => Some(*eta_i as f64 / *eta_t as f64),
        _ => None,
    }),
    index_ratio(
        "fresnel_schlick",
        "η_i/η_t",
        &["eta_i", "eta_t"],
        |c| match c {
            Call::fresnel_schlick { eta_i, eta_t, .. } => Some(*eta_i as f64 / *eta_t as f64),
            _ => None,
        },
    ),
    Param::new(
        "fresnel_schlick",
        "cos_theta_i",
        &["cos_theta_i"],
        |c| match c {
            Call::fresnel_schlick { cos_theta_i, .. } => Some(*cos_theta_i as f64),
            _ => None,
        },
        0.0,
        1.000_000_2,
    )
    .boundaries(UPPER_COS_BOUNDARIES)
    .special(&[1.000_000_1]),
    critical("fresnel_schlick", "sin²θt", &[], |c| match c {
        Call::fresnel_schlick {
            cos_theta_i,
            eta_i,
            eta_t,
        } => Some(sin2_t(*cos_theta_i as f64, *eta_i as f64 / *eta_t as f64)),
        _ => None,
    }),
];

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    let mut d = Draw::new(s);
    (0..count)
        .map(|i| {
            if i % 4 == 0 {
                let (eta_i, eta_t) = eta_pair(&mut d, &DOMAIN[0], ETA);
                return r0("", eta_i, eta_t);
            }
            let (eta_i, eta_t) = eta_pair(&mut d, &DOMAIN[1], ETA);
            let ratio = eta_i as f64 / eta_t as f64;
            // Every other case aims at the critical angle when there is one.
            let cos = if i % 2 == 1 && ratio > 1.0 {
                let s2 = d.value(&DOMAIN[3]);
                (1.0 - s2 / (ratio * ratio)).max(0.0).sqrt()
            } else {
                d.value(&DOMAIN[2])
            };
            schlick("", cos as f32, eta_i, eta_t)
        })
        .collect()
}
