//! Cases of `brdf_check`: BRDFs whose plausibility is known, judged by the three verdicts.

use crate::grade::case_input::CaseInput;
use crate::grade::call::Call;
use crate::grade::case::Rule;
use crate::grade::domain::{Draw, Param};
use crate::grade::test_brdf::TestBrdf;
use crate::sampling::Sampler;
use std::f32::consts::TAU;

const SAMPLES: usize = 20_000;

/// Scale of the odd-power BRDFs: small, so their albedo (about 0.1 k/0.05 at grazing, where
/// the Monte Carlo estimate is noisiest) stays far below 1 and only positivity is in doubt.
const ODD_K: f32 = 0.005;

fn check(name: &str, brdf: TestBrdf, seed: u64, albedo: Option<f64>) -> CaseInput {
    CaseInput::new(
        name,
        Call::brdf_check {
            brdf,
            sampler: seed,
            samples: SAMPLES,
        },
    )
    .rule(Rule::Plausibility {
        albedo,
        gap_by_value: false,
    })
}

/// Share by which a Lambertian's reported albedo may miss its true albedo (Monte Carlo noise
/// and the maximum over incident directions).
const LAMBERT_ALBEDO: Option<f64> = Some(0.25);

pub fn fixed() -> Vec<CaseInput> {
    vec![
        check(
            "Lambert is plausible",
            TestBrdf::Lambert { albedo: 0.5 },
            11,
            LAMBERT_ALBEDO,
        )
        .note("max_albedo must match the Lambertian's albedo, within Monte Carlo noise"),
        check(
            "errata §2.6.3: the worksheet's k = (n+1)/(2π) gains energy",
            TestBrdf::CosinePower { k: 3.0 / TAU, n: 2 },
            12,
            None,
        )
        .note("its albedo is 2πk/((n+1) cos θi): test incident directions near grazing"),
        check(
            "errata §2.6.1: odd n is negative",
            TestBrdf::CosinePower { k: ODD_K, n: 3 },
            13,
            None,
        )
        .note("(wi·wo)³ < 0 when wi and wo are more than 90° apart"),
        check(
            "a BRDF of wi alone is not reciprocal",
            TestBrdf::IncidentOnly,
            14,
            None,
        )
        .note("compare f(wi, wo) with f(wo, wi)"),
        check(
            "a BRDF that is NaN near grazing is not plausible",
            TestBrdf::NanNearGrazing,
            15,
            None,
        )
        .note("a NaN must reach the report: f32::min and max skip it"),
        check(
            "a BRDF that gains energy only beyond 88°",
            TestBrdf::CosinePower {
                k: grazing_only_k(0.03, 2),
                n: 2,
            },
            16,
            None,
        )
        .note("its albedo 0.03/cos θi is below 1 up to 88.3°: test 89° and 89.9° as the text says"),
        check(
            "a BRDF that is +∞ near grazing is not plausible",
            TestBrdf::InfiniteNearGrazing,
            17,
            None,
        )
        .note("an infinite value is neither a finite albedo nor a measured reciprocity"),
    ]
}

/// The `k` that gives the even-`n` cosine-power BRDF the albedo `c / cos θi`: above 1 only
/// beyond `acos(c)`, near grazing.
fn grazing_only_k(c: f64, n: i32) -> f32 {
    (c * (n + 1) as f64 / std::f64::consts::TAU) as f32
}

/// The declared domain of `brdf_check(brdf, sampler, samples)`: any BRDF closure over
/// local directions (one that returns NaN, ∞ or negative values included), among them a
/// Lambertian with albedo up to exactly 1, which must not look like it creates energy.
/// Judged by verdicts, so no output field is compared to the last digit.
pub const DOMAIN: &[Param] = &[
    Param::new(
        "brdf_check",
        "Lambertian albedo",
        &["brdf", "sampler"],
        |c| match c {
            Call::brdf_check {
                brdf: TestBrdf::Lambert { albedo },
                ..
            } => Some(*albedo as f64),
            _ => None,
        },
        0.05,
        1.0,
    )
    .special(&[1.0]),
    Param::new(
        "brdf_check",
        "samples",
        &["samples"],
        |c| match c {
            Call::brdf_check { samples, .. } => Some(*samples as f64),
            _ => None,
        },
        1.0,
        1e6,
    ),
];

/// Random checks per grading at most: each draws 20 000 samples per measurement.
const RANDOM_CHECKS: usize = 5;

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    let mut d = Draw::new(s);
    (0..count.min(RANDOM_CHECKS))
        .map(|i| {
            let seed = (d.unit() * 1e9) as u64;
            match i {
                0 => check(
                    "Lambert",
                    TestBrdf::Lambert {
                        albedo: d.value(&DOMAIN[0]) as f32,
                    },
                    seed,
                    LAMBERT_ALBEDO,
                ),
                1 => {
                    let n = if d.unit() < 0.5 { 2 } else { 4 };
                    check(
                        "k (wi·wo)^n / (cos θi cos θo), k = (n+1)/(2π)",
                        TestBrdf::CosinePower {
                            k: (n + 1) as f32 / TAU,
                            n,
                        },
                        seed,
                        None,
                    )
                }
                2 => check(
                    "odd power",
                    TestBrdf::CosinePower { k: ODD_K, n: 5 },
                    seed,
                    None,
                ),
                3 => {
                    // Albedo c / cos θi, above 1 only beyond acos(c) ∈ [85.4°, 88.9°].
                    let c = 0.02 + 0.06 * d.unit();
                    check(
                        "k (wi·wo)² / (cos θi cos θo), gaining energy only near grazing",
                        TestBrdf::CosinePower {
                            k: grazing_only_k(c, 2),
                            n: 2,
                        },
                        seed,
                        None,
                    )
                }
                _ => check("wi alone", TestBrdf::IncidentOnly, seed, None),
            }
        })
        .collect()
}
