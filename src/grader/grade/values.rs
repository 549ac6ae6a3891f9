//! The values check: a task's functions on fixed worksheet inputs and random inputs,
//! against the reference's outputs.
//!
//! In two halves, so the process that runs student code never sees an expected value: a
//! worker evaluates the calls (inputs only, [`super::measure::evaluate_values`]) and sends
//! back what each returned; the grader [`judge`]s those outputs against the expected ones.

use super::call::Call;
use super::case::{Rule, ValueCase};
use super::measure::evaluate_values;
use super::output::{Output, fmt_num};
use super::tolerance::Error;
use super::verdict::{CheckKind, CheckResult, RegionTally, Visibility, Worst};
use super::wire::{Evaluated, ValueOutputs};
use crate::panics::Panic;
use crate::worksheet::Tasks;

/// The label of the simplest failing case, the first of a values check's list.
pub const SIMPLEST: &str = "simplest failing input: ";

/// Calls `t` on every case and judges each output, in this process.
pub fn run(name: &str, cases: &[ValueCase], visibility: Visibility, t: &impl Tasks) -> CheckResult {
    let calls: Vec<Call> = cases.iter().map(|c| c.call.clone()).collect();
    judge(cases, &evaluate_values(name, &calls, t), visibility)
}

/// Judges a worker's `outputs` of `cases` (the grader's half); every failure message names
/// the call, its input, what came back, what was expected and the case's note. Missing
/// outputs (a worker that sent fewer than it was asked for) fail their cases.
pub fn judge(cases: &[ValueCase], outputs: &ValueOutputs, visibility: Visibility) -> CheckResult {
    let mut result = CheckResult::new(&outputs.check, CheckKind::Values);
    result.visibility = visibility;
    result.total = cases.len();
    let mut worst: Option<Worst> = None;
    let mut ratios = Vec::new();
    let mut failing = Vec::new();
    let mut failed_at = vec![false; cases.len()];
    let missing = Err(Panic {
        message: "the worker sent no output for this case".into(),
        location: None,
        todo_in: None,
    });
    for (i, case) in cases.iter().enumerate() {
        let outcome = outputs.outputs.get(i).unwrap_or(&missing);
        let (error, failure) = match outcome {
            Ok(got) => match case.judge(got) {
                Ok(error) => (error, None),
                Err(problem) => {
                    if matches!(case.rule, Rule::Close(_)) {
                        ratios.extend(ratios_of(got, &case.expected));
                    }
                    (super::tolerance::error(got, &case.expected), Some(problem))
                }
            },
            Err(p) => {
                result.fail_panic(&format!("{} [{}]", case.call, case.name), p);
                failed_at[i] = true;
                (Error::UNBOUNDED, None)
            }
        };
        // The worst case by its share of the tolerance where one decides, else by the
        // absolute error.
        let share = match case.rule {
            Rule::Close(tol) => Some(error.abs / (tol.abs + tol.rel * case.expected.magnitude())),
            _ => None,
        };
        let key = |share: Option<f64>, error: &Error| share.unwrap_or(error.abs);
        if worst
            .as_ref()
            .is_none_or(|w| key(share, &error) > key(w.share, &w.error))
        {
            worst = Some(Worst {
                case: format!("{} [{}]", case.call, case.name),
                error,
                share,
            });
        }
        if let Some(problem) = failure {
            failed_at[i] = true;
            failing.push((simplicity(case), case, problem, got_of(outcome)));
        }
    }
    result.regions = regions(cases, &failed_at);
    // The simplest failing input first: a worksheet case, then the shortest inputs (exact
    // boundary and special values print short), which is where a student starts debugging.
    // The summary says how many and where; each failing case is printed once, in this list,
    // the simplest labelled as such with where it lies in the domain.
    failing.sort_by_key(|(key, ..)| *key);
    for (i, (_, case, problem, got)) in failing.iter().enumerate() {
        let note = case
            .note
            .as_deref()
            .map(|n| format!(" ({n})"))
            .unwrap_or_default();
        let (label, position) = match (i, visibility) {
            (0, Visibility::Visible) => (
                SIMPLEST,
                super::value_cases::position(&case.call)
                    .map(|p| format!(" ({p})"))
                    .unwrap_or_default(),
            ),
            _ => ("", String::new()),
        };
        result.fail(
            format!(
                "{label}{}: {problem}{note}{position} [{}]",
                case.call, case.name
            ),
            format!("{label}{}: got {got}{position} [{}]", case.call, case.name),
        );
    }
    result.finish();
    result.worst = worst;
    result.summary = format!(
        "{}/{} cases agree with the expected answers",
        result.total - result.failed,
        result.total
    );
    let failing_regions: Vec<String> = result
        .regions
        .iter()
        .filter(|r| r.failed > 0)
        .map(|r| format!("{} ({} of {} cases)", r.name, r.failed, r.total))
        .collect();
    if !failing_regions.is_empty() {
        result.summary += &format!(
            "; {} of {} regions of the domain pass, each worth an equal share: failing in {}",
            result.regions.len() - failing_regions.len(),
            result.regions.len(),
            failing_regions.join(", ")
        );
    }
    if let Some((factor, shared)) = common_factor(&ratios) {
        let which = if shared == ratios.len() {
            "every failing value is".to_string()
        } else {
            format!("{shared} of {} failing values are", ratios.len())
        };
        result.summary += &format!(
            "; {which} {} × the expected one — a constant factor is missing or extra",
            fmt_num(factor)
        );
    }
    result.seconds = outputs.seconds;
    result
}

/// The cases of each region (in order of name), with their failing ones; empty when no case
/// names a region.
fn regions(cases: &[ValueCase], failed_at: &[bool]) -> Vec<RegionTally> {
    let mut tally: std::collections::BTreeMap<&str, RegionTally> = Default::default();
    for (case, failed) in cases.iter().zip(failed_at) {
        if case.region.is_empty() {
            continue;
        }
        let r = tally.entry(&case.region).or_insert_with(|| RegionTally {
            name: case.region.clone(),
            total: 0,
            failed: 0,
        });
        r.total += 1;
        r.failed += usize::from(*failed);
    }
    tally.into_values().collect()
}

/// What the student's code returned, as a failure shows it.
pub(crate) fn got_of(outcome: &Evaluated) -> String {
    match outcome {
        Ok(got) => got.to_string(),
        Err(p) => p.describe(),
    }
}

/// How simple a case is to debug (smaller is simpler): a case the worksheet or the errata
/// name before a drawn one, then the shorter its printed inputs.
pub(crate) fn simplicity(case: &ValueCase) -> (bool, usize) {
    let drawn = case.name.starts_with("random") || case.name.starts_with("hidden");
    (drawn, case.call.to_string().len())
}

/// got / expected for every component where both are finite and the expected is not 0.
fn ratios_of(got: &Output, expected: &Output) -> Vec<f64> {
    let pairs: Vec<(f64, f64)> = match (got, expected) {
        (Output::Number(g), Output::Number(e)) => vec![(*g, *e)],
        (Output::Numbers(g), Output::Numbers(e)) if g.len() == e.len() => {
            g.iter().copied().zip(e.iter().copied()).collect()
        }
        _ => return vec![f64::NAN],
    };
    pairs
        .into_iter()
        .filter(|(g, e)| g.is_finite() && *e != 0.0 && e.abs() > 1e-12)
        .map(|(g, e)| g / e)
        .collect()
}

/// The factor that nine in ten of the failing values' ratios to the expected ones share
/// (their median, to 0.1 %), with how many share it: when at least three do and it is not 1.
fn common_factor(ratios: &[f64]) -> Option<(f64, usize)> {
    let mut sorted: Vec<f64> = ratios.iter().copied().filter(|r| r.is_finite()).collect();
    sorted.sort_by(f64::total_cmp);
    let median = *sorted.get(sorted.len() / 2)?;
    let shared = ratios
        .iter()
        .filter(|r| (*r - median).abs() <= 1e-3 * median.abs())
        .count();
    // Nine in ten: an f32 implementation off by a factor is off by a little more where
    // its own rounding is coarse (a subnormal cosine), and the expected value is exact.
    let common = shared >= 3 && shared * 10 >= ratios.len() * 9;
    (common && (median - 1.0).abs() > 1e-2).then_some((median, shared))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_constant_factor_is_diagnosed() {
        assert_eq!(common_factor(&[4.0, 4.0, 4.000_01]), Some((4.0, 3)));
        assert_eq!(common_factor(&[4.0, 4.0]), None);
        assert_eq!(common_factor(&[4.0, 2.0, 4.0]), None);
        assert_eq!(common_factor(&[1.0, 1.0, 1.0]), None);
        let mostly: Vec<f64> = [4.0; 9].into_iter().chain([4.2]).collect();
        assert_eq!(common_factor(&mostly), Some((4.0, 9)));
        let half: Vec<f64> = [4.0; 5].into_iter().chain([2.0; 5]).collect();
        assert_eq!(common_factor(&half), None);
    }
}
