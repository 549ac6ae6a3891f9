//! Cases of `kajiya_kay`.

use crate::grade::case_input::CaseInput;
use crate::bsdf::KajiyaKayParams;
use crate::grade::call::Call;
use crate::grade::domain::{Boundary, Draw, Param, channel, cos_between, exponent};
use crate::sampling::Sampler;
use glam::Vec3;

const KK: &str = "kd sin θi plus ks max(0, c)^p, c the cosine to the reflection cone \
                  t·wo = −t·wi (angles to the tangent)";
const SHEET: &str = "the worksheet's form divides by sin θi sin θo and goes negative or infinite";

fn kk(name: &str, wo: Vec3, wi: Vec3) -> CaseInput {
    let params = KajiyaKayParams {
        kd: Vec3::splat(0.1),
        ks: Vec3::splat(0.9),
        exponent: 80.0,
    };
    CaseInput::new(
        name,
        Call::kajiya_kay {
            wo,
            wi,
            tangent: Vec3::Z,
            params,
        },
    )
}

pub fn fixed() -> Vec<CaseInput> {
    let wi = Vec3::new(0.5, 0.0, 0.866_025_4);
    vec![
        kk(
            "errata §4.3 (a): off the cone",
            Vec3::new(0.0, 0.5, 0.866_025_4),
            wi,
        )
        .note(KK),
        kk("errata §4.3 (b): retro-reflection", wi, wi).note(KK),
        kk(
            "errata §4.3 (c): on the reflection cone",
            Vec3::new(0.5, 0.0, -0.866_025_4),
            wi,
        )
        .note(SHEET),
        kk(
            "errata: wi along the fibre",
            Vec3::new(0.5, 0.0, 0.866_025_4),
            Vec3::Z,
        )
        .note(SHEET),
        CaseInput::new(
            "errata: fractional exponent off the cone",
            Call::kajiya_kay {
                wo: Vec3::new(0.0, 0.5, 0.866_025_4),
                wi,
                tangent: Vec3::Z,
                params: KajiyaKayParams {
                    kd: Vec3::splat(0.1),
                    ks: Vec3::splat(0.9),
                    exponent: 80.5,
                },
            },
        )
        .note("clamp the cone cosine to 0 before powf"),
    ]
}

fn of(c: &Call) -> Option<(Vec3, Vec3, Vec3, &KajiyaKayParams)> {
    match c {
        Call::kajiya_kay {
            wo,
            wi,
            tangent,
            params,
        } => Some((*wo, *wi, *tangent, params)),
        _ => None,
    }
}

/// The boundaries of a cosine to the fibre: along it, either way (`sin θ = 0`, where the
/// worksheet's form divides by 0 and a rounded `t·w` may be 1.0000001). The answer is
/// continuous there but steep: `sin θ = √(1 − c²)` turns a cosine 1e-7 from ±1 into
/// 4.5e-4, below what an f32 dot product of vectors not quite unit resolves, hence
/// [`FIBRE_RESOLUTION`].
const ALONG_THE_FIBRE: &[Boundary] = &[
    Boundary {
        at: 1.0,
        what: "along the fibre",
        continuous: true,
    },
    Boundary {
        at: -1.0,
        what: "along the fibre, backwards",
        continuous: true,
    },
];

/// How near (in cosine) to the fibre a drawn direction may lie without lying along it:
/// 1e-5 in the cosine is 4.5e-3 in `sin θ`, which f32 resolves.
const FIBRE_RESOLUTION: f64 = 1e-5;

/// The declared domain of `kajiya_kay(wo, wi, tangent, params)`: unit directions on the
/// whole sphere, pointing away from the fibre, a unit tangent; non-negative and finite for
/// every input, also along the fibre; channels of `kd` and `ks` in [0, 1] and an exponent
/// ≥ 0 that need not be an integer (0 gives the clamped `0^0 = 1`).
pub const DOMAIN: &[Param] = &[
    Param::new(
        "kajiya_kay",
        "t·wi",
        &["wi", "tangent"],
        |c| of(c).map(|x| cos_between(x.2, x.1)),
        -1.0,
        1.0,
    )
    .boundaries(ALONG_THE_FIBRE)
    .resolution(FIBRE_RESOLUTION),
    Param::new(
        "kajiya_kay",
        "t·wo",
        &["wo", "tangent"],
        |c| of(c).map(|x| cos_between(x.2, x.0)),
        -1.0,
        1.0,
    )
    .boundaries(ALONG_THE_FIBRE)
    .resolution(FIBRE_RESOLUTION),
    Param::new(
        "kajiya_kay",
        "t·wo + t·wi",
        &["wo", "wi"],
        |c| of(c).map(|x| cos_between(x.2, x.0) + cos_between(x.2, x.1)),
        -2.0,
        2.0,
    )
    .boundaries(&[Boundary {
        at: 0.0,
        what: "the reflection cone (t·wo = −t·wi)",
        continuous: true,
    }]),
    channel("kajiya_kay", "largest channel of kd", &["params.kd"], |c| {
        of(c).map(|x| x.3.kd.max_element() as f64)
    }),
    channel("kajiya_kay", "largest channel of ks", &["params.ks"], |c| {
        of(c).map(|x| x.3.ks.max_element() as f64)
    }),
    exponent(
        "kajiya_kay",
        &["params.exponent"],
        |c| of(c).map(|x| x.3.exponent as f64),
        1.0,
    )
    .special(&[1.0, 80.0, 80.5]),
];

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    let mut d = Draw::new(s);
    (0..count)
        .map(|i| {
            let tangent = d.normal();
            let cos_i = d.value(&DOMAIN[0]);
            let wi = d.direction_at(tangent, cos_i);
            // One case in four aims wo at the reflection cone.
            let cos_o = if i % 4 == 1 {
                (d.value(&DOMAIN[2]) - cos_i).clamp(-1.0, 1.0)
            } else {
                d.value(&DOMAIN[1])
            };
            let wo = d.direction_at(tangent, cos_o);
            let params = KajiyaKayParams {
                kd: d.colour(&DOMAIN[3]),
                ks: d.colour(&DOMAIN[4]),
                exponent: d.value(&DOMAIN[5]) as f32,
            };
            let call = Call::kajiya_kay {
                wo,
                wi,
                tangent,
                params,
            };
            CaseInput::new("", call).note(KK)
        })
        .collect()
}
