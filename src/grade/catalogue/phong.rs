//! Cases of `phong` and `reciprocity_gap`.

use super::CaseInput;
use super::random::{colour, range, upper};
use crate::bsdf::PhongParams;
use crate::grade::call::Call;
use crate::grade::case::Rule;
use crate::grade::test_brdf::TestBrdf;
use crate::grade::tolerance::Tolerance;
use crate::sampling::Sampler;
use glam::Vec3;

const PHONG: &str = "f = kd/π + ks (n+2)/(2π) max(0, r·wo)^n with r the mirror of wi";
const NEGATIVE_LOBE: &str =
    "r·wo < 0: clamp to 0 before powf (a negative base to a fractional power is NaN)";
const GAP: &str =
    "largest |f(a,b) − f(b,a)| / max(|f(a,b)|, |f(b,a)|) over random pairs above the surface";

/// Reciprocity gaps at most this are "reciprocal".
pub const RECIPROCAL: f64 = 1e-3;

fn phong(name: &str, wo: Vec3, wi: Vec3, kd: f32, ks: f32, exponent: f32) -> CaseInput {
    let params = PhongParams {
        kd: Vec3::splat(kd),
        ks: Vec3::splat(ks),
        exponent,
    };
    CaseInput::new(name, Call::Phong { wo, wi, params })
}

fn gap(name: &str, brdf: TestBrdf, seed: u64) -> CaseInput {
    CaseInput::new(
        name,
        Call::ReciprocityGap {
            brdf,
            seed,
            pairs: 2000,
        },
    )
    .rule(Rule::SameSide {
        threshold: RECIPROCAL,
    })
    .note(GAP)
}

pub fn fixed() -> Vec<CaseInput> {
    let wi = Vec3::new(0.6, 0.0, 0.8);
    let mirror = Vec3::new(-0.6, 0.0, 0.8);
    vec![
        phong("peak of the lobe", mirror, wi, 0.3, 0.5, 20.0).note(PHONG),
        phong(
            "errata: r·wo < 0, n = 10.5",
            Vec3::new(0.95, 0.0, 0.3).normalize(),
            wi,
            0.3,
            0.5,
            10.5,
        )
        .note(NEGATIVE_LOBE),
        phong(
            "errata: r·wo < 0, n = 2",
            Vec3::new(0.95, 0.0, 0.3).normalize(),
            wi,
            0.3,
            0.5,
            2.0,
        )
        .note(NEGATIVE_LOBE),
        phong("swapped directions", wi, mirror, 0.3, 0.5, 20.0).note(PHONG),
        phong("wi below the surface", mirror, -wi, 0.3, 0.5, 20.0).note("0 below the surface"),
        gap(
            "Lambert is reciprocal",
            TestBrdf::Lambert { albedo: 0.8 },
            1,
        ),
        gap(
            "the worksheet's §2.6 BRDF is reciprocal",
            TestBrdf::CosinePower {
                k: 3.0 / std::f32::consts::TAU,
                n: 2,
            },
            2,
        ),
        gap(
            "a BRDF of wi alone is not reciprocal",
            TestBrdf::IncidentOnly,
            3,
        ),
        gap(
            "a tiny BRDF of wi alone is not reciprocal either (the gap is relative)",
            TestBrdf::ScaledIncidentOnly { scale: 1e-6 },
            4,
        ),
        gap(
            "a BRDF that is NaN near grazing cannot be called reciprocal",
            TestBrdf::NanNearGrazing,
            5,
        )
        .note("a NaN (or ∞) value must make the gap NaN or ∞: f32::max skips NaN"),
        gap(
            "a BRDF that is NaN in one order of a pair only cannot be called reciprocal",
            TestBrdf::NanOneWayRound,
            6,
        )
        .note("a pair where either f(a,b) or f(b,a) is NaN must make the gap NaN or ∞"),
        gap(
            "the gap of a BRDF twice as bright one way round is exactly 1/2",
            TestBrdf::Lopsided,
            7,
        )
        .rule(Rule::Close(Tolerance::F32))
        .note(GAP),
    ]
}

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    (0..count)
        .map(|i| {
            let (wo, wi) = (upper(s, 0.0), upper(s, 0.0));
            let exponent = match i % 3 {
                0 => (1.0 + range(s, 0.0, 50.0)).floor(),
                1 => range(s, 1.0, 100.0),
                _ => range(s, 0.5, 3.0),
            };
            let params = PhongParams {
                kd: colour(s, 0.0, 0.5),
                ks: colour(s, 0.0, 0.5),
                exponent,
            };
            CaseInput::new("", Call::Phong { wo, wi, params }).note(PHONG)
        })
        .collect()
}
