//! Cases of `kajiya_kay`.

use super::CaseInput;
use super::random::{colour, range, sphere};
use crate::bsdf::KajiyaKayParams;
use crate::grade::call::Call;
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
        Call::KajiyaKay {
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
            Call::KajiyaKay {
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

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    (0..count)
        .map(|_| {
            let params = KajiyaKayParams {
                kd: colour(s, 0.0, 0.5),
                ks: colour(s, 0.0, 1.0),
                exponent: range(s, 1.0, 100.0),
            };
            let call = Call::KajiyaKay {
                wo: sphere(s),
                wi: sphere(s),
                tangent: sphere(s),
                params,
            };
            CaseInput::new("", call).note(KK)
        })
        .collect()
}
