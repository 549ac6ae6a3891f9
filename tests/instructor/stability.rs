//! The stability catalogue on known implementations: the reference passes every case, the
//! stubs are "not attempted" everywhere, each deliberately naive function fails exactly
//! the cases it should with the verdict it should, and hangs and panics are reported.

use pbrlab::stability::{Case, Outcome, Verdict, cases, run_cases};
use pbrlab::worksheet::Tasks;
use pbrlab_exercises::TASKS as Student;
use std::time::Duration;
#[cfg(feature = "solutions")]
use {
    crate::stability_support::{Flaw, flawed},
    pbrlab::stability::cases_for,
    pbrlab::worksheet::TaskId,
    std::collections::BTreeMap,
};

/// Far longer than any case takes; only the hang test uses a short limit.
const TIMEOUT: Duration = Duration::from_secs(20);

fn run_all<T: Tasks + Clone + Send + 'static>(
    imp: T,
    cases: &[Case<T>],
    timeout: Duration,
) -> Vec<Outcome> {
    run_cases(cases, &imp, timeout, |_| {})
}

/// The cases that did not pass, with their verdicts.
#[cfg(feature = "solutions")]
fn failures(flaw: Flaw) -> BTreeMap<&'static str, Verdict> {
    run_all(flawed(flaw), &cases(), TIMEOUT)
        .into_iter()
        .filter(|o| o.verdict != Verdict::Pass)
        .map(|o| (o.case, o.verdict))
        .collect()
}

fn table(outcomes: &[Outcome]) -> String {
    outcomes
        .iter()
        .map(|o| {
            format!(
                "{:<46} {:<14} {} (expected {})",
                o.case,
                o.verdict.label(),
                o.value_text,
                o.expected
            )
        })
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn stubs_are_not_attempted_everywhere() {
    let untouched = crate::shipped_stubs::untouched();
    let stub_cases: Vec<Case<_>> = cases()
        .into_iter()
        .filter(|c| untouched.contains(&c.task))
        .collect();
    let outcomes = run_all(Student, &stub_cases, TIMEOUT);
    let other: Vec<Outcome> = outcomes
        .into_iter()
        .filter(|o| o.verdict != Verdict::NotAttempted)
        .collect();
    assert!(
        other.is_empty(),
        "stubs gave other verdicts:\n{}",
        table(&other)
    );
}

#[cfg(feature = "solutions")]
#[test]
fn the_reference_passes_every_case() {
    use pbrlab_solutions::TASKS as Reference;
    let outcomes = run_all(Reference, &cases(), TIMEOUT);
    assert!(outcomes.len() >= 70, "only {} cases", outcomes.len());
    let failed: Vec<Outcome> = outcomes
        .into_iter()
        .filter(|o| o.verdict != Verdict::Pass)
        .collect();
    assert!(
        failed.is_empty(),
        "the reference fails:\n{}",
        table(&failed)
    );
}

#[cfg(feature = "solutions")]
#[test]
fn the_flawed_wrapper_without_a_flaw_is_the_reference() {
    let failed = failures(Flaw::None);
    assert!(failed.is_empty(), "{failed:?}");
}

/// Each naive implementation and exactly the cases it must fail.
#[cfg(feature = "solutions")]
fn naive_expectations() -> Vec<(Flaw, Vec<(&'static str, Verdict)>)> {
    use Verdict::*;
    vec![
        (
            Flaw::ReflectUnnormalised,
            vec![("reflect/non_unit_normal", OutOfRange)],
        ),
        (
            Flaw::UnguardedSnell,
            vec![
                ("refract/at_critical_f32", NaN),
                ("refract/past_critical_2ulp_f32", NaN),
                ("refract_stack/past_critical_2ulp_f64", NaN),
                // The f32 Schlick inside the stack meets the critical angle too: at θc
                // itself, and where a ray that entered the slab at 90° leaves it.
                ("refract_stack/at_critical_f64", NaN),
                ("refract_stack/grazing_slab", NaN),
                ("fresnel_schlick/tir_45deg", NaN),
                ("fresnel_schlick/at_critical_f32", NaN),
                ("fresnel_schlick/past_critical_2ulp_f32", NaN),
            ],
        ),
        (
            Flaw::CriticalAngleAsin,
            vec![
                ("critical_angle/into_denser", NaN),
                ("critical_angle/equal_indices", WrongValue),
            ],
        ),
        (
            Flaw::SchlickR0Everywhere,
            vec![
                ("fresnel_schlick/equal_indices_60deg", WrongValue),
                ("fresnel_schlick/equal_indices_80deg", WrongValue),
                ("fresnel_schlick/equal_indices_89deg", WrongValue),
                ("fresnel_schlick/dense_to_less_40deg", WrongValue),
                ("fresnel_schlick/tir_45deg", WrongValue),
                ("fresnel_schlick/at_critical_f32", WrongValue),
                ("fresnel_schlick/past_critical_2ulp_f32", WrongValue),
            ],
        ),
        (
            Flaw::CosinePdfSigned,
            vec![("cosine_pdf/below_horizon", OutOfRange)],
        ),
        (
            Flaw::SmithNoChi,
            vec![
                ("smith_g1/back_facing", OutOfRange),
                ("smith_g1/grazing_alpha_zero", NaN),
            ],
        ),
        (
            Flaw::HalfVectorUnguarded,
            vec![
                ("cook_torrance/opposite_normal", NaN),
                ("cook_torrance/opposite_tilted", NaN),
                ("cook_torrance/horizon", NaN),
            ],
        ),
        (
            Flaw::CancellingGgx,
            vec![
                ("aniso_ndf/alpha_1e-3_peak", WrongValue),
                ("aniso_ndf/alpha_1e-4_peak", Inf),
                ("aniso_ndf/below_horizon", WrongValue),
                ("aniso_ndf/alpha_zero_peak", NaN),
                ("cook_torrance/alpha_zero_specular", NaN),
                ("ndf_pdf/alpha_1e-4_mirror", Inf),
            ],
        ),
        (
            Flaw::PhongUnclamped,
            vec![
                ("phong/fractional_exponent_negative_lobe", NaN),
                ("phong/even_exponent_negative_lobe", WrongValue),
            ],
        ),
        (
            Flaw::PhongPowerByLogarithm,
            vec![("phong/exponent_zero_behind_the_mirror", NaN)],
        ),
        (
            Flaw::GapZeroOverZero,
            vec![
                ("reciprocity_gap/zero_brdf", NaN),
                ("reciprocity_gap/no_pairs", Inf),
                ("brdf_check/zero_brdf", NaN),
            ],
        ),
        (
            Flaw::SheetKajiyaKay,
            vec![
                ("kajiya_kay/wi_along_tangent", NaN),
                ("kajiya_kay/mirror_cone", OutOfRange),
                ("kajiya_kay/tangent_dot_above_one", NaN),
                ("kajiya_kay/exponent_zero_off_the_cone", WrongValue),
                ("kajiya_kay/fractional_exponent_negative_cone", WrongValue),
                ("kajiya_kay/highlight_underflow", WrongValue),
            ],
        ),
        (
            Flaw::BeckmannUnguarded,
            vec![
                ("beckmann_ndf/horizon", NaN),
                ("beckmann_ndf/cos_1e-12", NaN),
                ("beckmann_ndf/below_horizon", WrongValue),
                ("beckmann_ndf/alpha_zero_peak", NaN),
                ("beckmann_ndf/alpha_zero_off_peak", NaN),
            ],
        ),
        (
            Flaw::NdfPdfUnguarded,
            vec![("ndf_pdf/opposite", NaN), ("ndf_pdf/wi_below", WrongValue)],
        ),
        (
            Flaw::PathTraceNoDepthGuard,
            vec![("path_trace/depth_zero", WrongValue)],
        ),
        (
            Flaw::MisUnguarded,
            vec![
                ("mis/delta_bsdf", WrongValue),
                ("mis/light_edge_on", NaN),
                ("mis/shading_point_on_the_light", NaN),
            ],
        ),
        (
            Flaw::DeltaTrackingSheet,
            vec![
                ("delta_tracking/zero_majorant", WrongValue),
                ("delta_tracking/nan_majorant", WrongValue),
                ("delta_tracking/empty_medium", WrongValue),
                ("delta_tracking/empty_segment", WrongValue),
            ],
        ),
        (
            Flaw::NdfPdfNoJacobian,
            vec![
                ("ndf_pdf/grazing_pair", WrongValue),
                ("ndf_pdf/alpha_1e-4_mirror", WrongValue),
            ],
        ),
    ]
}

#[cfg(feature = "solutions")]
#[test]
fn each_naive_implementation_fails_exactly_its_cases() {
    let mut report = String::new();
    for (flaw, expected) in naive_expectations() {
        let expected: BTreeMap<&str, Verdict> = expected.into_iter().collect();
        let got = failures(flaw);
        if got != expected {
            report += &format!("{flaw:?}:\n  expected {expected:?}\n  got      {got:?}\n");
        }
    }
    assert!(report.is_empty(), "{report}");
}

#[cfg(feature = "solutions")]
#[test]
fn code_that_never_returns_is_reported_as_a_hang() {
    let start = std::time::Instant::now();
    let outcomes = run_all(
        flawed(Flaw::SmithHangs),
        &cases_for(TaskId::SmithG1),
        Duration::from_millis(150),
    );
    assert!(!outcomes.is_empty());
    assert!(
        outcomes.iter().all(|o| o.verdict == Verdict::Hang),
        "{}",
        table(&outcomes)
    );
    assert!(
        start.elapsed() < Duration::from_secs(10),
        "the run waited for the hung threads"
    );
}

#[cfg(feature = "solutions")]
#[test]
fn a_panic_is_reported_with_its_message() {
    let outcomes = run_all(
        flawed(Flaw::ReflectPanics),
        &cases_for(TaskId::Reflect),
        TIMEOUT,
    );
    for o in &outcomes {
        assert_eq!(o.verdict, Verdict::Panic, "{}", o.case);
        assert!(
            o.message
                .as_deref()
                .is_some_and(|m| m.contains("index out of bounds")),
            "{:?}",
            o.message
        );
    }
}

#[cfg(feature = "solutions")]
#[test]
fn json_output_names_the_task_and_spells_out_nan() {
    let outcomes = run_all(
        flawed(Flaw::PhongUnclamped),
        &cases_for(TaskId::Phong),
        TIMEOUT,
    );
    let json = serde_json::to_value(&outcomes).unwrap();
    let nan_case = json
        .as_array()
        .unwrap()
        .iter()
        .find(|o| o["case"] == "phong/fractional_exponent_negative_lobe")
        .unwrap();
    assert_eq!(nan_case["task"], "phong");
    assert_eq!(nan_case["verdict"], "nan");
    assert_eq!(nan_case["value"][0], "NaN");
}
