//! Shrinking a failing value case: from the simplest graded input that fails, simpler
//! inputs of the same contract are tried on the student's code, round by round, and the
//! simplest that still fails is what the report names (`shrunk to smith_g1(w=(1.0, 0.0, 0.0),
//! alpha=0.5)`), as property-based testing tools do with a failing example.
//!
//! A step changes one input: a number to one with fewer significant digits (0, ±1, the
//! number rounded), or a unit direction to one at a rounder azimuth φ with its polar angle
//! θ kept (so a bug in a band next to the horizon still shows), or at a rounder θ or an
//! axis. A candidate must be admitted by the task's declared domain ([`super::domain`]:
//! inside the range, not on an open boundary, not nearer a boundary than correct code can
//! resolve), and its expected output is the reference's, with the tolerance of
//! the case it came from widened by the candidate's own rounding spread, as every drawn case
//! is ([`super::value_cases::evaluate`]): a shrunk case fails by a clear margin or is not
//! taken. Only public cases are shrunk (the inputs shown are derived from an input the
//! student saw), and only where the grader holds the reference (instructor grading and the
//! packages; the handout names the simplest graded input instead).

use super::call::Call;
use super::case::{Rule, ValueCase};
use super::case_input::CaseInput;
use super::catalogue;
use super::values::{got_of, simplicity};
use super::verdict::CheckResult;
use super::wire::{Evaluated, ValueOutputs};
use crate::worksheet::Tasks;
use serde_json::Value;
use std::time::{Duration, Instant};

/// At most this many rounds of candidates.
const ROUNDS: usize = 6;
/// At most this many candidates a round (the simplest first).
const PER_ROUND: usize = 48;

/// A shrunk failing case: the case, what the student's code returned, and what is wrong.
#[derive(Clone, Debug)]
pub struct Shrunk {
    /// The case (its expected output the reference's).
    pub case: ValueCase,
    /// What the student's code returned.
    pub got: Evaluated,
    /// What is wrong, as the values check words it (`got 0.5, expected 0.71`).
    pub problem: String,
}

/// Significant digits of `x` as it prints shortest (as f32 where it is one): 0 for 0, 1 for
/// 0.5 or 2, 7 for 0.8660254. The measure of how simple an input is.
fn digits(x: f64) -> usize {
    let text = if (x as f32) as f64 == x {
        format!("{}", x as f32)
    } else {
        format!("{x}")
    };
    let mantissa = text.split(['e', 'E']).next().unwrap_or("");
    let significant = mantissa
        .chars()
        .filter(char::is_ascii_digit)
        .skip_while(|c| *c == '0')
        .collect::<String>();
    significant.trim_end_matches('0').len() + usize::from(significant.is_empty() && x != 0.0)
}

/// How complex a call's inputs are: the significant digits of all its numbers.
fn complexity(call: &Call) -> usize {
    fn walk(v: &Value) -> usize {
        match v {
            Value::Number(n) => n.as_f64().map_or(0, digits),
            Value::Array(items) => items.iter().map(walk).sum(),
            Value::Object(map) => map.values().map(walk).sum(),
            _ => 0,
        }
    }
    serde_json::to_value(call).map_or(usize::MAX, |v| walk(&v))
}

/// `x` rounded to `n` significant digits.
fn round_to(x: f64, n: i32) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let scale = 10f64.powi(n - 1 - x.abs().log10().floor() as i32);
    (x * scale).round() / scale
}

/// Simpler numbers than `x`.
fn simpler_numbers(x: f64) -> Vec<f64> {
    let mut out = vec![0.0, 1.0, -1.0, x.round(), x.trunc()];
    out.extend((1..=3).map(|n| round_to(x, n)));
    out.retain(|c| *c != x && c.is_finite() && digits(*c) < digits(x));
    out
}

/// `(θ, φ)` in degrees rounded more or less, and the axes' angles.
fn rounder_angles(degrees: f64, axes: &[f64]) -> Vec<f64> {
    let mut out: Vec<f64> = axes.to_vec();
    for step in [45.0, 10.0, 5.0, 1.0, 0.1] {
        out.push((degrees / step).round() * step);
    }
    out
}

/// The unit vector at polar angle `theta` and azimuth `phi` (degrees), components within
/// 1e-7 of 0 made 0 (so 90° gives z = 0 exactly).
fn direction(theta: f64, phi: f64) -> [f64; 3] {
    let (t, p) = (theta.to_radians(), phi.to_radians());
    let snap = |c: f64| {
        let c = c as f32;
        if c.abs() < 1e-7 { 0.0 } else { c as f64 }
    };
    [
        snap(t.sin() * p.cos()),
        snap(t.sin() * p.sin()),
        snap(t.cos()),
    ]
}

/// The calls one step simpler than `call` in one of its inputs.
fn candidates(call: &Call) -> Vec<Call> {
    let Ok(value) = serde_json::to_value(call) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    let mut path = Vec::new();
    steps(&value, &value, &mut path, &mut out);
    out.into_iter()
        .filter_map(|v| serde_json::from_value(v).ok())
        .filter(|c: &Call| c != call)
        .collect()
}

/// One place of the stored form: a key or an index.
#[derive(Clone)]
enum Step {
    Key(String),
    Index(usize),
}

/// `root` with the value at `path` replaced by `with`.
fn replaced(root: &Value, path: &[Step], with: Value) -> Value {
    let mut copy = root.clone();
    let mut at = &mut copy;
    for step in path {
        at = match (step, at) {
            (Step::Key(k), Value::Object(map)) => match map.get_mut(k) {
                Some(v) => v,
                None => return root.clone(),
            },
            (Step::Index(i), Value::Array(items)) => match items.get_mut(*i) {
                Some(v) => v,
                None => return root.clone(),
            },
            _ => return root.clone(),
        };
    }
    *at = with;
    copy
}

/// Adds to `out` every one-step simplification of the value at `path` (which is `here`).
fn steps(root: &Value, here: &Value, path: &mut Vec<Step>, out: &mut Vec<Value>) {
    let number = |v: &Value| v.as_f64();
    match here {
        Value::Number(n) => {
            for c in n.as_f64().map(simpler_numbers).unwrap_or_default() {
                if let Some(c) = serde_json::Number::from_f64(c) {
                    out.push(replaced(root, path, Value::Number(c)));
                }
            }
        }
        Value::Array(items) if items.len() == 3 && items.iter().all(|v| v.is_number()) => {
            let v: Vec<f64> = items.iter().filter_map(number).collect();
            let length = v.iter().map(|c| c * c).sum::<f64>().sqrt();
            if (length - 1.0).abs() < 1e-4 {
                // A unit direction stays one: rounder angles, θ kept or rounded.
                let theta = v[2].clamp(-1.0, 1.0).acos().to_degrees();
                let phi = v[1].atan2(v[0]).to_degrees();
                for t in [theta]
                    .into_iter()
                    .chain(rounder_angles(theta, &[0.0, 90.0, 180.0]))
                {
                    for p in [phi]
                        .into_iter()
                        .chain(rounder_angles(phi, &[0.0, 90.0, 180.0, -90.0]))
                    {
                        let d = direction(t, p);
                        let d: Vec<Value> = d
                            .iter()
                            .filter_map(|c| serde_json::Number::from_f64(*c).map(Value::Number))
                            .collect();
                        out.push(replaced(root, path, Value::Array(d)));
                    }
                }
            } else {
                for (i, item) in items.iter().enumerate() {
                    path.push(Step::Index(i));
                    steps(root, item, path, out);
                    path.pop();
                }
            }
        }
        Value::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                path.push(Step::Index(i));
                steps(root, item, path, out);
                path.pop();
            }
        }
        Value::Object(map) => {
            for (k, v) in map {
                path.push(Step::Key(k.clone()));
                steps(root, v, path, out);
                path.pop();
            }
        }
        _ => {}
    }
}

/// Whether `call` lies inside its task's declared domain.
fn inside_domain(call: &Call) -> bool {
    catalogue::domain(call.task())
        .iter()
        .all(|p| match (p.value)(call) {
            Some(v) => v.is_finite() && (p.lo..=p.hi).contains(&v),
            None => true,
        })
}

/// The simplest case that still fails, reached from `case` (a failing public case judged
/// by value) by rounds of one-step simplifications: `student` returns the student's outputs
/// of a round's calls, in order (fewer when its worker stopped: the rest count as passing).
/// `None` when `case` is not judged by value or no simpler input fails. No round starts
/// after `deadline`.
pub fn shrink(
    case: &ValueCase,
    reference: &impl Tasks,
    mut student: impl FnMut(&[Call]) -> Vec<Evaluated>,
    deadline: Instant,
) -> Option<Shrunk> {
    if !matches!(case.rule, Rule::Close(_)) {
        return None;
    }
    let mut best: Option<Shrunk> = None;
    let mut current = case.clone();
    for _ in 0..ROUNDS {
        if Instant::now() >= deadline {
            break;
        }
        let here = complexity(&current.call);
        let mut calls: Vec<Call> = candidates(&current.call)
            .into_iter()
            .filter(|c| complexity(c) < here && inside_domain(c))
            .collect();
        calls.sort_by_key(complexity);
        calls.dedup();
        calls.truncate(PER_ROUND);
        let cases: Vec<ValueCase> = calls
            .into_iter()
            .filter_map(|call| {
                let input = CaseInput {
                    name: format!("shrunk from {}", case.name),
                    call,
                    rule: case.rule,
                    note: case.note.clone(),
                    drawn: true,
                };
                super::value_cases::evaluate(&[input], reference)
                    .ok()?
                    .pop()
            })
            .collect();
        if cases.is_empty() {
            break;
        }
        let calls: Vec<Call> = cases.iter().map(|c| c.call.clone()).collect();
        let outputs = student(&calls);
        let failing = cases.into_iter().zip(outputs).find_map(|(c, got)| {
            let problem = match &got {
                Ok(out) => c.judge(out).err()?,
                Err(p) => p.describe(),
            };
            Some(Shrunk {
                case: c,
                got,
                problem,
            })
        });
        let Some(step) = failing else { break };
        current = step.case.clone();
        best = Some(step);
    }
    best
}

/// Shrinks the simplest failing case of a values check (`check`, judged from `outputs` of
/// `cases`) with [`shrink`] within `budget`, and names what it found in
/// [`CheckResult::shrunk`]: `shrunk to CALL: got …, expected … (where it lies)`. Nothing changes when
/// no case failed by value (a panic is simple already) or nothing simpler fails. The
/// points and the counts of graded cases stay as graded.
pub fn attach(
    cases: &[ValueCase],
    outputs: &ValueOutputs,
    check: &mut CheckResult,
    reference: &impl Tasks,
    student: impl FnMut(&[Call]) -> Vec<Evaluated>,
    budget: Duration,
) {
    let simplest = cases
        .iter()
        .zip(&outputs.outputs)
        .filter(|(case, got)| matches!(got, Ok(out) if case.judge(out).is_err()))
        .map(|(case, _)| case)
        .min_by_key(|case| simplicity(case));
    let deadline = Instant::now() + budget;
    let Some(shrunk) = simplest.and_then(|case| shrink(case, reference, student, deadline)) else {
        return;
    };
    let Shrunk { case, got, problem } = shrunk;
    let position = super::value_cases::position(&case.call)
        .map(|p| format!(" ({p})"))
        .unwrap_or_default();
    check.shrunk = Some((
        format!(
            "shrunk to {}: {problem}{position} [{}]",
            case.call, case.name
        ),
        format!(
            "shrunk to {}: got {}{position} [{}]",
            case.call,
            got_of(&got),
            case.name
        ),
    ));
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    #[test]
    fn digits_count_what_a_person_reads() {
        assert_eq!(digits(0.0), 0);
        assert_eq!(digits(1.0), 1);
        assert_eq!(digits(0.5), 1);
        assert_eq!(digits(20.0), 1);
        assert_eq!(digits(0.866_025_4_f32 as f64), 7);
        assert_eq!(digits(1.5e-4), 2);
    }

    #[test]
    fn a_unit_direction_shrinks_to_unit_directions_with_rounder_angles() {
        let w = Vec3::new(0.3, 0.4, 0.2).normalize();
        let call = Call::smith_g1 { w, alpha: 0.37 };
        let found = candidates(&call);
        assert!(
            found
                .iter()
                .any(|c| matches!(c, Call::smith_g1 { alpha, .. } if *alpha == 0.4))
        );
        for c in &found {
            let Call::smith_g1 { w, .. } = c else {
                panic!("{c}")
            };
            assert!((w.length() - 1.0).abs() < 1e-5, "{c}");
            assert!(complexity(c) <= complexity(&call) + 21, "{c}");
        }
        // θ kept, φ made 0: y = 0 and the same height.
        assert!(found.iter().any(|c| matches!(
            c,
            Call::smith_g1 { w: v, .. } if v.y == 0.0 && (v.z - w.z).abs() < 1e-6
        )));
    }
}
