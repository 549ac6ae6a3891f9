//! The value cases of a task: its fixed cases and cases drawn from its declared domain
//! (public ones with a fixed seed, hidden ones with the course's), evaluated by the task's
//! contract in f64 (or, where it has none, the reference) into expected outputs, with
//! tolerances from the contract's conditioning and f32's arithmetic, and the region of the
//! domain each lies in. The grader's side: the expected outputs are made
//! here.

use super::call::Call;
use super::case::{Rule, ValueCase};
use super::case_input::{CaseInput, PUBLIC_SEED};
use super::catalogue::{contract, domain, drawn, fixed};
use super::domain::Param;
use super::output::{Output, fmt_num};
use super::tolerance::Tolerance;
use crate::panics;
use crate::sampling::Sampler;
use crate::worksheet::{TaskId, Tasks};
use anyhow::bail;

/// Random cases per task in the public data (stored, so the handout grades without the
/// reference).
pub const PUBLIC_RANDOM: usize = 256;

/// Random cases per task added by `--hidden-seed` (computed live by the reference; each
/// costs microseconds).
pub const HIDDEN_RANDOM: usize = 2048;

/// Where `call` lies in its task's declared domain, for a student reading a failure: on
/// or near each boundary it is close to (`2.4e-4 from the horizon: cos θ of w = 2.4e-4`),
/// nearest first, then the values the exercise names that it takes. `None` when it is far
/// from all of them.
pub fn position(call: &Call) -> Option<String> {
    /// Relative distance under which a value is "near" a boundary.
    const NEAR: f64 = 1e-2;
    let mut near: Vec<(f64, String)> = Vec::new();
    let mut named = Vec::new();
    for p in domain(call.task()) {
        let Some(v) = (p.value)(call) else { continue };
        if let Some((b, distance)) = p.nearest_boundary(v).filter(|(_, d)| *d <= NEAR) {
            let text = if distance == 0.0 {
                format!("on {}: {} = {}", b.what, p.name, fmt_num(v))
            } else {
                format!(
                    "{} from {}: {} = {}",
                    fmt_num(distance),
                    b.what,
                    p.name,
                    fmt_num(v)
                )
            };
            near.push((distance, text));
        } else if p.special_at(v).is_some() {
            named.push(format!(
                "{} = {}, a value the exercise names",
                p.name,
                fmt_num(v)
            ));
        }
    }
    near.sort_by(|a, b| a.0.total_cmp(&b.0));
    let all: Vec<String> = near.into_iter().map(|(_, t)| t).chain(named).collect();
    (!all.is_empty()).then(|| all.join("; "))
}

/// The region of the fixed cases (worksheet, errata and exercise-text cases).
pub const WORKED_CASES: &str = "the worked cases (worksheet, errata, text)";

/// The region of a drawn case near no boundary and on no special value.
pub const INTERIOR: &str = "the interior";

/// The declared region of its task's domain that the drawn `call` lies in: on a special
/// value (`alpha = 0`, `cos θ of w = 1e-45`), else on a boundary (`cos θ of w: on the
/// horizon`), else in the band next to a boundary (`cos θ of w: near the horizon`, within
/// 1e-2 relative), else [`INTERIOR`]; the first declared parameter decides among equals. A values check's
/// credit is split over the regions its cases lie in, so that a bug confined to one region
/// costs that region's share, however few draws land there.
pub fn region(call: &Call) -> String {
    /// Relative distance under which a value is in a boundary's band.
    const BAND: f64 = 1e-2;
    let mut on = None;
    let mut near = None;
    for p in domain(call.task()) {
        let Some(v) = (p.value)(call) else { continue };
        // A special value first: a cosine of 1e-45 lies within rounding of the horizon
        // but is a point of its own.
        if let Some(s) = p.special_at(v).filter(|s| (p.lo..=p.hi).contains(s)) {
            return format!("{} = {}", p.name, fmt_num(s));
        }
        if let Some((b, distance)) = p.nearest_boundary(v) {
            if distance <= crate::grade::domain::ON_BOUNDARY && on.is_none() {
                on = Some(format!("{}: on {}", p.name, b.what));
            } else if distance <= BAND && near.is_none() {
                near = Some(format!("{}: near {}", p.name, b.what));
            }
        }
    }
    on.or(near).unwrap_or_else(|| INTERIOR.to_string())
}

fn random(task: TaskId, s: &mut Sampler, count: usize, label: &str) -> Vec<CaseInput> {
    let cases = drawn(task, s, count);
    // A draw aimed just inside a limit can land just outside it once its inputs are rounded
    // to f32 (a direction meant 1e-7 above the horizon ends 5e-8 below): such a case tests
    // a contract the text does not state, so it goes. So does a draw where a quantity
    // derived from independently drawn inputs (`r·wo` of Phong's lobe from `wo` and `wi`)
    // falls nearer a boundary than correct code resolves: rounding decides its side.
    let inside = |call: &Call| {
        domain(task)
            .iter()
            .all(|p| (p.value)(call).is_none_or(|v| p.admits(v)))
    };
    cases
        .into_iter()
        .filter(|c| inside(&c.call))
        .enumerate()
        .map(|(i, mut c)| {
            c.drawn = true;
            c.name = if c.name.is_empty() {
                format!("{label} {}", i + 1)
            } else {
                format!("{label} {}: {}", i + 1, c.name)
            };
            c
        })
        .collect()
}

/// The public cases of `task`: its fixed cases and [`PUBLIC_RANDOM`] random ones.
pub fn public_inputs(task: TaskId) -> Vec<CaseInput> {
    let mut s = Sampler::new(PUBLIC_SEED, task as u64);
    let mut cases = fixed(task);
    cases.extend(random(task, &mut s, PUBLIC_RANDOM, "random"));
    cases
}

/// The hidden cases of `task` for `seed`: up to [`HIDDEN_RANDOM`] random ones from the same
/// declared domain as the public random cases, none of them a public input.
pub fn hidden_inputs(task: TaskId, seed: u64) -> Vec<CaseInput> {
    let mut s = Sampler::new(seed ^ 0x68_69_64_64_65_6e, task as u64);
    let public: Vec<Call> = public_inputs(task).into_iter().map(|c| c.call).collect();
    // Boundary values drawn exactly may repeat a public input; a hidden case is a new one.
    random(task, &mut s, HIDDEN_RANDOM, "hidden")
        .into_iter()
        .filter(|c| !public.contains(&c.call))
        .collect()
}

/// Magnitudes within 2^40 of f32's largest finite value: where an f32 product of a few
/// factors, two of them as large as 2^20, overflows or not depending on their order.
pub const OVERFLOW_RANGE: f64 = f32::MAX as f64 / 1_099_511_627_776.0;

/// Jittered evaluations per case that measure how the answer (the contract's and the
/// reference's) moves when its inputs move within rounding ([`Call::jitters`]).
const CONDITIONING_SAMPLES: u64 = 6;

/// How far a correct f32 implementation's answer to `call` may lie from `expected`, the
/// contract's: `None` when correct implementations may disagree on the answer's shape
/// (a `None` that becomes a value at a critical angle, a value that becomes non-finite).
/// The largest of
/// - the contract's **conditioning**: the spread of its answer over the inputs moved within
///   rounding ([`spread`]): how far the answer moves when each input moves by what f32
///   loses there;
/// - the **f32 arithmetic** at the input, witnessed by `t` (the reference, one correct f32
///   implementation): its own spread over the same moves, plus how far its answer lies
///   from the contract's. Where f32 cannot hold an intermediate (a G1 of a subnormal
///   cosine has a few significant bits) every f32 implementation is that far off, however
///   exact its inputs.
///
/// For a call no contract covers (`contracted` false), `expected` is the reference's and
/// this is its spread.
fn allowance(call: &Call, expected: &Output, contracted: bool, t: &impl Tasks) -> Option<f64> {
    let by_reference = |c: &Call| panics::catch(|| c.eval(t)).ok();
    let jittered = call.jitters(CONDITIONING_SAMPLES);
    if !contracted {
        return spread(call, &jittered, expected, by_reference);
    }
    let reference = by_reference(call)?;
    let deviation = reference.max_difference(expected)?;
    let arithmetic = spread(call, &jittered, &reference, by_reference)?;
    let conditioning = spread(call, &jittered, expected, contract)?;
    Some(conditioning.max(arithmetic) + deviation / 2.0)
}

/// The spread of `answer` over `jittered` (the inputs of `call` moved within rounding,
/// [`Call::jitters`]), around `centre`; `None` when a move changes the output's shape or
/// `answer` gives none (a panic).
///
/// Where the contract's answer on a boundary of its declared domain is exactly 0 (`h.z = 0`
/// is "at or below the surface", so `D = 0`) and jumps there, an input that lies exactly
/// on that boundary stays there: a move off it measures the other side of the boundary,
/// not rounding, so such moves are left out, and with them the tolerance they would add,
/// which would hide code that gets the boundary itself wrong. A boundary the answer is
/// continuous across (`wi` along a fibre: `sin θi → 0`) keeps every move: there it is the
/// contract's own steepness. (An input that only rounds onto a boundary,
/// like a unit vector near the normal whose z is 1 in f32, has a non-zero answer there and
/// keeps every move.)
fn spread(
    call: &Call,
    jittered: &[Call],
    centre: &Output,
    answer: impl Fn(&Call) -> Option<Output>,
) -> Option<f64> {
    let on: Vec<(&Param, f64)> = if is_zero(centre) {
        domain(call.task())
            .iter()
            .filter_map(|p| {
                let v = (p.value)(call)?;
                p.jump_values().any(|e| e == v).then_some((p, v))
            })
            .collect()
    } else {
        Vec::new()
    };
    jittered
        .iter()
        .filter(|moved| on.iter().all(|(p, v)| (p.value)(moved) == Some(*v)))
        .try_fold(0f64, |spread, moved| {
            Some(spread.max(answer(moved)?.max_difference(centre)?))
        })
}

/// Other random streams on which [`by_value_where_fixed`] measures the reference again.
const RESEEDS: u64 = 3;

/// `rule`, a verdict rule for a quantity measured from random draws, judged by value as well
/// where the contract fixes that quantity whatever is drawn: the reciprocity gap of a
/// reciprocal BRDF is 0 and of one twice as bright one way round 1/2, over any pairs. Such
/// a quantity is found by measuring the reference on [`RESEEDS`] other random streams: the
/// same finite answer to the last bit every time is the contract's. A gap that depends on
/// the draws, however little (a BRDF of `wi` alone, whose largest gap over 20,000 pairs is
/// 1 − 1e-4 or so), keeps its verdict rule.
fn by_value_where_fixed(rule: Rule, call: &Call, expected: &Output, t: &impl Tasks) -> Rule {
    let fixed = |field: Option<&str>| {
        let number = |o: &Output| match field {
            Some(name) => o.field(name).and_then(Output::as_number),
            None => o.as_number(),
        };
        let Some(e) = number(expected).filter(|e| e.is_finite()) else {
            return false;
        };
        (1..=RESEEDS).all(|k| {
            call.reseeded(k)
                .and_then(|c| panics::catch(|| c.eval(t)).ok())
                .and_then(|o| number(&o))
                .is_some_and(|o| o == e)
        })
    };
    match rule {
        Rule::SameSide { .. } if fixed(None) => Rule::Close(Tolerance::F32),
        Rule::Plausibility { albedo, .. } => Rule::Plausibility {
            albedo,
            gap_by_value: fixed(Some("max_reciprocity_error")),
        },
        rule => rule,
    }
}

/// True when every number in `output` is 0 as the student's f32 holds it: exactly 0, or
/// an f64 answer of the contract that rounds to 0 in f32 (a density of 1e-65).
fn is_zero(output: &Output) -> bool {
    let zero = |x: f64| x as f32 == 0.0;
    match output {
        Output::Nothing => false,
        Output::Number(x) => zero(*x),
        Output::Numbers(v) => v.iter().all(|x| zero(*x)),
        Output::Record(fields) => fields.values().all(is_zero),
    }
}

/// Evaluates `inputs` into cases with expected outputs: the answer of the task's contract
/// in f64 at exactly the case's inputs, or, for a call no contract covers, of `t` (the
/// reference). Fails when an output is NaN, or infinite in a fixed case (under a rule that
/// compares numbers), or the reference panics: expected data must be well defined. A drawn
/// case whose answer comes within [`OVERFLOW_RANGE`] of overflowing f32 is left out.
///
/// A case compared by a tolerance gets that tolerance (the task's allowance for the last
/// digits) widened by twice how far a correct f32 answer may lie from the expected one
/// (`allowance`): near a singularity (a tiny roughness with `h` near the normal, the
/// grazing limit of `cos θt`, a direction along a fibre) a correct f32 implementation that
/// rounds differently is as far off as that, and a wrong one much further. A drawn case
/// whose shape changes within rounding (`refract` on the critical angle) is dropped.
pub fn evaluate(inputs: &[CaseInput], t: &impl Tasks) -> anyhow::Result<Vec<ValueCase>> {
    let mut cases = Vec::with_capacity(inputs.len());
    for input in inputs {
        // The contract's answer in f64, or the reference's where the task has none.
        let contracted = contract(&input.call);
        let has_contract = contracted.is_some();
        let answer = contracted.map_or_else(
            || panics::catch(|| input.call.eval(t)).map_err(|p| p.describe()),
            Ok,
        );
        let expected = match answer {
            // A drawn combination of special values where the answer lies at the edge of
            // f32's range or beyond (a mirror, which no masking bounds, at a subnormal
            // grazing cosine: 1/cos θ alone is 8.5e37) is a singularity of the contract,
            // not a test: correct code overflows there or not by the order of its products.
            Ok(out)
                if input.drawn
                    && !input.rule.judges_verdicts()
                    && !out.has_nan()
                    && out.magnitude() >= OVERFLOW_RANGE =>
            {
                continue;
            }
            Ok(out) if out.is_finite() || input.rule.judges_verdicts() => out,
            Ok(out) => bail!(
                "{} [{}]: the reference returned {out}",
                input.call,
                input.name
            ),
            Err(panic) => bail!("{} [{}]: the reference {panic}", input.call, input.name),
        };
        let rule = match input.rule {
            Rule::Close(tol) => match allowance(&input.call, &expected, has_contract, t) {
                Some(spread) => Rule::Close(Tolerance::new(tol.abs + 2.0 * spread, tol.rel)),
                None if input.drawn => continue,
                None => input.rule,
            },
            rule => by_value_where_fixed(rule, &input.call, &expected, t),
        };
        cases.push(ValueCase {
            name: input.name.clone(),
            call: input.call.clone(),
            rule,
            note: input.note.clone(),
            expected,
            region: if input.drawn {
                region(&input.call)
            } else {
                WORKED_CASES.to_string()
            },
        });
    }
    Ok(cases)
}
