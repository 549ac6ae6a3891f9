//! A value case: a call, the reference's output, and the rule that decides whether the
//! student's output agrees.

use super::call::Call;
use super::output::{Output, fmt_num};
use super::tolerance::{Error, Tolerance, error};
use serde::{Deserialize, Serialize};

/// One graded input of a task function with its expected output.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ValueCase {
    /// Where the case comes from: `worksheet §1.3 glass→air 40°`, `random 7`, …
    pub name: String,
    /// The function and its inputs.
    pub call: Call,
    /// What decides agreement.
    pub rule: Rule,
    /// Shown with a failure of this case: the usual cause.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
    /// The reference's output: finite, except where the rule judges a verdict (a
    /// reciprocity gap of ∞, a plausibility report with NaN, for a BRDF that returns NaN).
    pub expected: Output,
    /// The region of the task's declared domain the case lies in (`cos θ of w: on the
    /// horizon`, `alpha = 0`, `the interior`, `the worked cases`,
    /// [`crate::grade::value_cases::region`]): a values check's credit is split over its
    /// regions ([`crate::grade::credit::Credit::PerRegion`]). Empty where not declared.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub region: String,
}

/// How a student's output is compared with the expected one.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "rule", rename_all = "snake_case")]
pub enum Rule {
    /// Every number within the tolerance, same shape (`None` only where expected).
    Close(Tolerance),
    /// A measured quantity only judged on which side of `threshold` it falls (for Monte
    /// Carlo answers whose exact value depends on the random numbers a student draws; one
    /// the contract fixes whatever is drawn is judged by value instead, see
    /// [`crate::grade::value_cases::evaluate`]).
    SameSide {
        /// The dividing value.
        threshold: f64,
    },
    /// A [`crate::bsdf::PlausibilityReport`] judged by its three verdicts (positivity,
    /// reciprocity, energy conservation), and by its albedo within `albedo` when the
    /// BRDF's albedo is known.
    Plausibility {
        /// Relative tolerance on `max_albedo`, for BRDFs whose albedo is a constant.
        albedo: Option<f64>,
        /// Whether `max_reciprocity_error` is judged by value ([`Tolerance::F32`]) as well
        /// as by verdict: where the contract fixes it whatever pairs are drawn (0 for a
        /// reciprocal BRDF, 1/2 for one twice as bright one way round).
        #[serde(default, skip_serializing_if = "std::ops::Not::not")]
        gap_by_value: bool,
    },
    /// A list of ratios that should be 1 (a sampler's Jacobian times its pdf): at least
    /// `share` of the finite ones within `tolerance` of 1, and at least half finite (seams
    /// of a warp and its singular points spoil a few finite differences; a distorted warp
    /// spoils most).
    Unity {
        /// Largest accepted |ratio − 1|.
        tolerance: f64,
        /// Smallest share of finite ratios within the tolerance.
        share: f64,
    },
}

impl Rule {
    /// Whether a non-finite expected output is meaningful under this rule: the verdict
    /// rules judge which side of a threshold a value falls, and NaN or ∞ is a side.
    pub fn judges_verdicts(&self) -> bool {
        !matches!(self, Rule::Close(_))
    }
}

/// Below this a report's `min_value` counts as negative.
const NEGATIVE: f64 = -1e-6;
/// Above this a report's reciprocity error counts as a violation.
const ASYMMETRIC: f64 = 1e-3;
/// Above this a report's albedo counts as gaining energy (Monte Carlo noise stays below).
const GAINS_ENERGY: f64 = 1.05;

impl ValueCase {
    /// Judges `got`: `Ok` with the error when it agrees, `Err` with what is wrong.
    pub fn judge(&self, got: &Output) -> Result<Error, String> {
        match self.rule {
            Rule::Close(tol) => match tol.compare(got, &self.expected) {
                Ok(()) => Ok(error(got, &self.expected)),
                Err(m) if m.path.is_empty() => {
                    Err(format!("got {}, expected {}", m.got, m.expected))
                }
                Err(m) => Err(format!(
                    "{}: got {}, expected {}",
                    m.path, m.got, m.expected
                )),
            },
            Rule::SameSide { threshold } => {
                let (Some(g), Some(e)) = (got.as_number(), self.expected.as_number()) else {
                    return Err(format!("got {got}, expected a number"));
                };
                // NaN is never at most the threshold: a gap that is NaN says "not
                // reciprocal", as a non-finite BRDF value must.
                let side = |x: f64| if x <= threshold { "≤" } else { ">" };
                if side(g) == side(e) {
                    Ok(Error::default())
                } else {
                    Err(format!(
                        "got {} ({} {}), expected a value {} {} (reference: {})",
                        fmt_num(g),
                        side(g),
                        fmt_num(threshold),
                        side(e),
                        fmt_num(threshold),
                        fmt_num(e)
                    ))
                }
            }
            Rule::Plausibility {
                albedo,
                gap_by_value,
            } => judge_plausibility(got, &self.expected, albedo, gap_by_value).and_then(|error| {
                judge_worst_wi(got, &self.call)?;
                Ok(error)
            }),
            Rule::Unity { tolerance, share } => judge_unity(got, tolerance, share),
        }
    }
}

/// Judges a list of ratios that should be 1 (see [`Rule::Unity`]).
fn judge_unity(got: &Output, tolerance: f64, share: f64) -> Result<Error, String> {
    let Output::Numbers(ratios) = got else {
        return Err(format!("got {got}, expected a list of ratios"));
    };
    let finite: Vec<f64> = ratios.iter().copied().filter(|r| r.is_finite()).collect();
    // A worker's outputs are untrusted data: an empty list is a failure, not a panic here.
    if finite.is_empty() || finite.len() * 2 < ratios.len() {
        return Err(format!(
            "the sampler rejected or failed at {} of {} points",
            ratios.len() - finite.len(),
            ratios.len()
        ));
    }
    let mut sorted = finite.clone();
    sorted.sort_by(f64::total_cmp);
    let median = sorted[sorted.len() / 2];
    let within = finite
        .iter()
        .filter(|r| (*r - 1.0).abs() <= tolerance)
        .count();
    if (within as f64) < share * finite.len() as f64 {
        return Err(format!(
            "the solid angle the warp sweeps times the pdf is 1 at only {within} of {} points \
             (median {}): the directions do not follow the pdf",
            finite.len(),
            fmt_num(median)
        ));
    }
    Ok(Error {
        abs: (median - 1.0).abs(),
        rel: (median - 1.0).abs(),
    })
}

/// One plausibility condition of a report field: which values satisfy it, and its name
/// when it holds or fails.
struct Condition {
    field: &'static str,
    holds: fn(f64) -> bool,
    yes: &'static str,
    no: &'static str,
}

const CONDITIONS: [Condition; 3] = [
    Condition {
        field: "min_value",
        holds: |x| x >= NEGATIVE,
        yes: "non-negative",
        no: "negative somewhere",
    },
    Condition {
        field: "max_reciprocity_error",
        holds: |x| x <= ASYMMETRIC,
        yes: "reciprocal",
        no: "not reciprocal",
    },
    Condition {
        field: "max_albedo",
        holds: |x| x <= GAINS_ENERGY,
        yes: "energy-conserving",
        no: "not energy-conserving",
    },
];

fn judge_plausibility(
    got: &Output,
    expected: &Output,
    albedo: Option<f64>,
    gap_by_value: bool,
) -> Result<Error, String> {
    let field = |o: &Output, name: &str| o.field(name).and_then(Output::as_number);
    let mut problems = Vec::new();
    for c in &CONDITIONS {
        let (Some(g), Some(e)) = (field(got, c.field), field(expected, c.field)) else {
            return Err(format!("got {got}, expected a report like {expected}"));
        };
        let verdict = |ok: bool| if ok { c.yes } else { c.no };
        if e.is_nan() {
            // The BRDF returns NaN somewhere: the report must not pass the condition (a NaN
            // that reached it, or a value that fails it).
            if (c.holds)(g) {
                problems.push(format!(
                    "{} = {} means {}, but the BRDF returns NaN for some directions \
                     (reference {} = NaN): a NaN was skipped",
                    c.field,
                    fmt_num(g),
                    c.yes,
                    c.field
                ));
            }
        } else if g.is_nan() {
            problems.push(format!("{} is NaN", c.field));
        } else if (c.holds)(g) != (c.holds)(e) {
            problems.push(format!(
                "{} = {} means {}, but the BRDF is {} (reference {} = {})",
                c.field,
                fmt_num(g),
                verdict((c.holds)(g)),
                verdict((c.holds)(e)),
                c.field,
                fmt_num(e)
            ));
        }
    }
    let (g, e) = (
        field(got, "max_reciprocity_error"),
        field(expected, "max_reciprocity_error"),
    );
    if let (true, Some(g), Some(e)) = (gap_by_value, g, e)
        && !Tolerance::F32.close(g, e)
    {
        problems.push(format!(
            "max_reciprocity_error = {}, expected {}: this BRDF's gap is the same for every \
             pair of directions",
            fmt_num(g),
            fmt_num(e)
        ));
    }
    let (g, e) = (field(got, "max_albedo"), field(expected, "max_albedo"));
    if let (Some(rel), Some(g), Some(e)) = (albedo, g, e)
        && !Tolerance::new(0.0, rel).close(g, e)
    {
        problems.push(format!(
            "max_albedo = {}, expected {} within {:.0} %",
            fmt_num(g),
            fmt_num(e),
            rel * 100.0
        ));
    }
    if problems.is_empty() {
        Ok(Error::default())
    } else {
        Err(problems.join("; "))
    }
}

/// Judges the `worst_wi` of a plausibility report: a unit incident direction above the
/// surface where, for a test BRDF with a closed-form albedo, that albedo is the reported
/// `max_albedo` (within 25 %, Monte Carlo noise and the maximum over directions).
fn judge_worst_wi(got: &Output, call: &Call) -> Result<(), String> {
    let Call::brdf_check { brdf, .. } = call else {
        return Ok(());
    };
    let (Some(Output::Numbers(w)), Some(reported)) = (
        got.field("worst_wi"),
        got.field("max_albedo").and_then(Output::as_number),
    ) else {
        return Err(format!(
            "got {got}, expected a report with worst_wi and max_albedo"
        ));
    };
    let &[x, y, z] = w.as_slice() else {
        return Err(format!("worst_wi has {} components, expected 3", w.len()));
    };
    if !reported.is_finite() {
        return Ok(());
    }
    let w = glam::DVec3::new(x, y, z);
    if !((w.length() - 1.0).abs() <= 1e-3 && w.z > 0.0) {
        return Err(format!(
            "worst_wi = ({}, {}, {}) is not a unit incident direction above the surface \
             (local frame, pointing away from it)",
            fmt_num(x),
            fmt_num(y),
            fmt_num(z)
        ));
    }
    if let Some(exact) = brdf.albedo(w.as_vec3())
        && (exact - reported).abs() > 0.25 * exact.max(reported) + 1e-6
    {
        return Err(format!(
            "max_albedo = {} was reported at worst_wi = ({}, {}, {}), where the albedo is {}: \
             the direction is not the one the largest albedo was measured at",
            fmt_num(reported),
            fmt_num(x),
            fmt_num(y),
            fmt_num(z),
            fmt_num(exact)
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grade::output::IntoOutput;
    use crate::grade::test_brdf::TestBrdf;

    fn case(rule: Rule, expected: Output) -> ValueCase {
        ValueCase {
            name: "t".into(),
            call: Call::reciprocity_gap {
                brdf: TestBrdf::IncidentOnly,
                sampler: 0,
                pairs: 1,
            },
            rule,
            note: None,
            expected,
            region: String::new(),
        }
    }

    #[test]
    fn same_side_compares_verdicts_only() {
        let c = case(Rule::SameSide { threshold: 1e-3 }, 0.4f32.into_output());
        assert!(c.judge(&0.9f32.into_output()).is_ok());
        assert!(c.judge(&0.0f32.into_output()).is_err());
        // NaN is never at most the threshold: "not reciprocal", as a NaN BRDF value demands.
        assert!(c.judge(&f32::NAN.into_output()).is_ok());
        let reciprocal = case(Rule::SameSide { threshold: 1e-3 }, 0.0f32.into_output());
        assert!(reciprocal.judge(&f32::NAN.into_output()).is_err());
        assert!(reciprocal.judge(&0.0f32.into_output()).is_ok());
    }

    #[test]
    fn plausibility_names_the_wrong_verdict() {
        let report = |min, recip, albedo| crate::bsdf::PlausibilityReport {
            min_value: min,
            max_reciprocity_error: recip,
            max_albedo: albedo,
            worst_wi: glam::Vec3::Z,
        };
        let c = case(
            Rule::Plausibility {
                albedo: Some(0.1),
                gap_by_value: false,
            },
            report(0.16, 0.0, 0.5).into_output(),
        );
        assert!(c.judge(&report(0.16, 0.0, 0.52).into_output()).is_ok());
        let e = c.judge(&report(0.16, 0.3, 0.5).into_output()).unwrap_err();
        assert!(
            e.contains("means not reciprocal, but the BRDF is reciprocal"),
            "{e}"
        );
        let e = c.judge(&report(0.16, 0.0, 0.8).into_output()).unwrap_err();
        assert!(e.contains("max_albedo = 0.8"), "{e}");
        // A gap the contract fixes is judged by value too: 5e-4 is "reciprocal" by verdict
        // but not the 0 every pair gives.
        let lenient = c.judge(&report(0.16, 5e-4, 0.5).into_output());
        assert!(lenient.is_ok(), "{lenient:?}");
        let by_value = case(
            Rule::Plausibility {
                albedo: Some(0.1),
                gap_by_value: true,
            },
            report(0.16, 0.0, 0.5).into_output(),
        );
        assert!(
            by_value
                .judge(&report(0.16, 0.0, 0.5).into_output())
                .is_ok()
        );
        let e = by_value
            .judge(&report(0.16, 5e-4, 0.5).into_output())
            .unwrap_err();
        assert!(
            e.contains("max_reciprocity_error = 5e-4, expected 0"),
            "{e}"
        );
    }

    #[test]
    fn unity_judges_ratios_and_refuses_an_empty_or_rejected_list() {
        let c = ValueCase {
            name: "jacobian".into(),
            call: Call::cosine_pdf { w: glam::Vec3::Z },
            rule: Rule::Unity {
                tolerance: 2e-3,
                share: 0.9,
            },
            note: None,
            expected: Output::Numbers(vec![1.0; 4]),
            region: String::new(),
        };
        assert!(
            c.judge(&Output::Numbers(vec![1.0, 1.001, 0.999, 1.0]))
                .is_ok()
        );
        assert!(c.judge(&Output::Numbers(vec![1.01; 4])).is_err());
        assert!(c.judge(&Output::Numbers(vec![])).is_err());
        assert!(c.judge(&Output::Numbers(vec![f64::NAN; 4])).is_err());
        assert!(c.judge(&Output::Number(1.0)).is_err());
    }
}
