//! Cases of `phong` and `reciprocity_gap`.

use crate::grade::case_input::CaseInput;
use crate::bsdf::PhongParams;
use crate::grade::call::Call;
use crate::grade::case::Rule;
use crate::grade::domain::{Boundary, Draw, Param, channel, cos_between, cos_z, cosine, exponent};
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
    CaseInput::new(name, Call::phong { wo, wi, params })
}

fn gap(name: &str, brdf: TestBrdf, seed: u64) -> CaseInput {
    CaseInput::new(
        name,
        Call::reciprocity_gap {
            brdf,
            sampler: seed,
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
            "a BRDF that is +∞ both ways round near grazing cannot be called reciprocal",
            TestBrdf::InfiniteNearGrazing,
            8,
        )
        .note("two infinite values are not a measured agreement: the gap must be NaN or ∞"),
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
        gap(
            "the gap of a negative BRDF twice as large one way round is exactly 1/2",
            TestBrdf::NegativeLopsided,
            9,
        )
        .rule(Rule::Close(Tolerance::F32))
        .note("the gap compares magnitudes: |f(a,b) − f(b,a)| / max(|f(a,b)|, |f(b,a)|)"),
    ]
}

fn of(c: &Call) -> Option<(Vec3, Vec3, &PhongParams)> {
    match c {
        Call::phong { wo, wi, params } => Some((*wo, *wi, params)),
        _ => None,
    }
}

/// The mirror of the unit local `wi` about the normal `z`.
fn mirror(wi: Vec3) -> Vec3 {
    Vec3::new(-wi.x, -wi.y, wi.z)
}

/// The declared domain of `phong(wo, wi, params)` and `reciprocity_gap(brdf, sampler,
/// pairs)`: unit local directions anywhere (0 at or below the horizon), `r·wo` from −1
/// (clamped: a negative base to a fractional power is NaN) to 1 (the peak), channels of
/// `kd` and `ks` in [0, 1], an exponent ≥ 0 that need not be an integer (0 gives the
/// clamped `0^0 = 1`); any BRDF closure, seed and number of pairs.
pub const DOMAIN: &[Param] = &[
    cosine("phong", "cos θo", &["wo"], |c| of(c).map(|x| cos_z(x.0))),
    cosine("phong", "cos θi", &["wi"], |c| of(c).map(|x| cos_z(x.1))),
    Param::new(
        "phong",
        "r·wo",
        &["wo", "wi"],
        |c| of(c).map(|x| cos_between(mirror(x.1), x.0)),
        -1.0,
        1.0,
    )
    .boundaries(&[
        Boundary {
            at: 0.0,
            what: "the edge of the lobe (clamp r·wo before powf)",
            continuous: false,
        },
        Boundary {
            at: 1.0,
            what: "the peak of the lobe",
            continuous: false,
        },
    ]),
    channel("phong", "largest channel of kd", &["params.kd"], |c| {
        of(c).map(|x| x.2.kd.max_element() as f64)
    }),
    channel("phong", "largest channel of ks", &["params.ks"], |c| {
        of(c).map(|x| x.2.ks.max_element() as f64)
    }),
    exponent(
        "phong",
        &["params.exponent"],
        |c| of(c).map(|x| x.2.exponent as f64),
        0.5,
    )
    .special(&[1.0, 2.0, 10.5]),
    Param::new(
        "reciprocity_gap",
        "pairs",
        &["brdf", "sampler", "pairs"],
        |c| match c {
            Call::reciprocity_gap { pairs, .. } => Some(*pairs as f64),
            _ => None,
        },
        1.0,
        1e5,
    ),
];

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    let mut d = Draw::new(s);
    (0..count)
        .map(|i| {
            let cos_i = d.value(&DOMAIN[1]);
            let wi = d.direction_at(Vec3::Z, cos_i);
            // One case in four aims wo at the lobe's peak or its edge.
            let wo = if i % 4 == 1 {
                let c = d.value(&DOMAIN[2]);
                d.direction_at(mirror(wi), c)
            } else {
                let cos_o = d.value(&DOMAIN[0]);
                d.direction_at(Vec3::Z, cos_o)
            };
            let params = PhongParams {
                kd: d.colour(&DOMAIN[3]),
                ks: d.colour(&DOMAIN[4]),
                exponent: d.value(&DOMAIN[5]) as f32,
            };
            CaseInput::new("", Call::phong { wo, wi, params }).note(PHONG)
        })
        .collect()
}
