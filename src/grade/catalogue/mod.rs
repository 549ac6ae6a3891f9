//! The graded inputs of every task: fixed cases (the worksheet's examples, the errata's
//! traps) and random cases, the sampler setups of the sampling checks, and the estimators
//! of the estimator checks. Each task's own are in its folder, `src/tasks/<task>/cases.rs`;
//! this module holds what they share and dispatches to them by [`TaskId`].
//!
//! Inputs only: outputs come from the reference, either stored ([`super::expected`]) or,
//! for hidden cases, computed live.

pub(crate) mod indices;
pub(crate) mod phong_floor;
pub(crate) mod polygon;
pub(crate) mod rough_conductor;

pub use rough_conductor::StoredQuadrature;

use super::call::{Call, SampleCall};
use super::case::{Rule, ValueCase};
use super::domain::Param;
use super::output::{Output, fmt_num};
use super::tolerance::Tolerance;
use super::variance_pair::VariancePair;
use crate::panics;
use crate::sampling::Sampler;
use crate::worksheet::{TaskId, Tasks};
use anyhow::bail;

pub use polygon::projected_solid_angle;

/// What a task's `cases.rs` declares. Every item defaults to "none", so a task has
/// only what its line in [`crate::for_each_task!`] lists.
trait TaskCatalogue {
    /// The declared domain (see [`domain`]).
    const DOMAIN: &'static [Param] = &[];
    /// What the estimator and sampling checks are declared to catch.
    const POWER: Option<crate::grade::power::Declared> = None;
    /// The fixed cases: the worksheet's examples and the errata's traps.
    fn fixed() -> Vec<CaseInput> {
        Vec::new()
    }
    /// `count` random cases drawn from the domain.
    fn random(_s: &mut Sampler, _count: usize) -> Vec<CaseInput> {
        Vec::new()
    }
    /// The sampler setups of the sampling check.
    fn setups() -> Vec<SampleCall> {
        Vec::new()
    }
    /// The estimators of the estimator check, on implementation `t`.
    fn estimators<T: Tasks>(_t: &T) -> Vec<EstimatorSpec<'_>> {
        Vec::new()
    }
    /// Estimator pairs whose variances must relate as each pair's bound says.
    fn variance_pairs<T: Tasks>(_t: &T) -> Vec<VariancePair<'_>> {
        Vec::new()
    }
}

/// One item of a task's [`TaskCatalogue`], taken from its file `$m.rs`.
macro_rules! catalogue_item {
    ($m:ident, DOMAIN) => {
        const DOMAIN: &'static [Param] = $m::DOMAIN;
    };
    ($m:ident, POWER) => {
        const POWER: Option<crate::grade::power::Declared> = Some($m::POWER);
    };
    ($m:ident, fixed) => {
        fn fixed() -> Vec<CaseInput> {
            $m::fixed()
        }
    };
    ($m:ident, random) => {
        fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
            $m::random(s, count)
        }
    };
    ($m:ident, setups) => {
        fn setups() -> Vec<SampleCall> {
            $m::setups()
        }
    };
    ($m:ident, estimators) => {
        fn estimators<T: Tasks>(t: &T) -> Vec<EstimatorSpec<'_>> {
            $m::estimators(t)
        }
    };
    ($m:ident, variance_pairs) => {
        fn variance_pairs<T: Tasks>(t: &T) -> Vec<VariancePair<'_>> {
            $m::variance_pairs(t)
        }
    };
}

/// The registry, generated from the list of tasks ([`crate::for_each_task!`]), one line per
/// task: `Variant => folder { what its cases.rs declares }`. It dispatches every per-task
/// item by [`TaskId`]; the matches are exhaustive, so a task left out does not compile.
macro_rules! registry {
    ($($variant:ident => $module:ident { $($item:ident),* }),* $(,)?) => {
        /// One unit type per task, carrying its [`TaskCatalogue`].
        mod entries {
            use super::*;
            $(
                use crate::tasks::$module::cases as $module;
                pub(super) struct $variant;
                impl TaskCatalogue for $variant {
                    $(catalogue_item!($module, $item);)*
                }
            )*
        }

        fn domain_of(task: TaskId) -> &'static [Param] {
            match task { $(TaskId::$variant => <entries::$variant as TaskCatalogue>::DOMAIN,)* }
        }
        fn power_of(task: TaskId) -> Option<crate::grade::power::Declared> {
            match task { $(TaskId::$variant => <entries::$variant as TaskCatalogue>::POWER,)* }
        }
        fn fixed_of(task: TaskId) -> Vec<CaseInput> {
            match task { $(TaskId::$variant => <entries::$variant as TaskCatalogue>::fixed(),)* }
        }
        fn random_of(task: TaskId, s: &mut Sampler, count: usize) -> Vec<CaseInput> {
            match task {
                $(TaskId::$variant => <entries::$variant as TaskCatalogue>::random(s, count),)*
            }
        }
        fn setups_of(task: TaskId) -> Vec<SampleCall> {
            match task { $(TaskId::$variant => <entries::$variant as TaskCatalogue>::setups(),)* }
        }
        fn estimators_of<T: Tasks>(task: TaskId, t: &T) -> Vec<EstimatorSpec<'_>> {
            match task {
                $(TaskId::$variant => <entries::$variant as TaskCatalogue>::estimators(t),)*
            }
        }
        fn variance_pairs_of<T: Tasks>(task: TaskId, t: &T) -> Vec<VariancePair<'_>> {
            match task {
                $(TaskId::$variant => <entries::$variant as TaskCatalogue>::variance_pairs(t),)*
            }
        }
    };
}

crate::for_each_task!(registry);

/// A value case before its expected output is known.
#[derive(Clone, Debug, PartialEq)]
pub struct CaseInput {
    /// Where the case comes from.
    pub name: String,
    /// The call.
    pub call: Call,
    /// How outputs are compared.
    pub rule: Rule,
    /// The usual cause of a failure of this case.
    pub note: Option<String>,
    /// Drawn from the declared domain rather than named by the worksheet or the errata:
    /// dropped when it is ill-posed in f32 (see [`evaluate`]).
    pub drawn: bool,
}

impl CaseInput {
    /// A case compared within the f32 tolerance.
    pub fn new(name: impl Into<String>, call: Call) -> Self {
        Self {
            name: name.into(),
            call,
            rule: Rule::Close(Tolerance::F32),
            note: None,
            drawn: false,
        }
    }

    /// The same case with a note shown when it fails.
    pub fn note(mut self, note: impl Into<String>) -> Self {
        self.note = Some(note.into());
        self
    }

    /// The same case with another comparison rule.
    pub fn rule(mut self, rule: Rule) -> Self {
        self.rule = rule;
        self
    }
}

/// The declaration of a sampler's Jacobian case: points of the unit square (its one input,
/// `u`, is any point of the square).
pub const JACOBIAN: Param = Param::new(
    "sample_jacobian",
    "u",
    &["sampler", "points", "h"],
    |c| match c {
        Call::SampleJacobian { points, .. } => Some(points.len() as f64),
        _ => None,
    },
    1.0,
    1e4,
);

/// The Jacobian cases of a sampler (see [`Call::SampleJacobian`]): 400 points spread over
/// the square away from its edges, a finite-difference step of 1e-3 (its truncation and
/// rounding stay near 1e-4), judged to 2e-3 at 90 % of the points, so that a warp 1 % off
/// its pdf fails while a correct warp with seams (a concentric map) passes.
pub fn jacobian_case(name: &str, sampler: SampleCall) -> CaseInput {
    /// Points per case.
    const POINTS: usize = 400;
    let mut s = Sampler::new(PUBLIC_SEED, 0x6a61_636f_6269);
    let points = (0..POINTS)
        .map(|_| glam::Vec2::new(0.02, 0.02) + 0.96 * s.next_2d())
        .collect();
    CaseInput::new(
        name,
        Call::SampleJacobian {
            sampler,
            points,
            h: 1e-3,
        },
    )
    .rule(Rule::Unity {
        tolerance: 2e-3,
        share: 0.9,
    })
    .note(
        "the solid angle a warp sweeps per unit area of the square is 1/pdf: sample the \
         density your pdf returns",
    )
}

/// Random cases per task in the public data (stored, so the handout grades without the
/// reference).
pub const PUBLIC_RANDOM: usize = 256;
/// Random cases per task added by `--hidden-seed` (computed live by the reference; each
/// costs microseconds).
pub const HIDDEN_RANDOM: usize = 2048;
/// Seed of the public random cases (fixed: they are stored).
pub const PUBLIC_SEED: u64 = 0x5eed_2024;

/// The declared domain of `task`'s functions: every parameter's range, special values and
/// boundaries (see [`super::domain`]), stated in the task's `cases.rs`. Empty for the
/// integrator tasks, which are graded by estimators and renders, not value cases.
pub fn domain(task: TaskId) -> &'static [Param] {
    domain_of(task)
}

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
        } else if p.special.contains(&v) {
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
        if let Some(s) = p.special_values().find(|s| (v - s).abs() <= 1e-6 * s.abs()) {
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

fn fixed(task: TaskId) -> Vec<CaseInput> {
    fixed_of(task)
}

fn random(task: TaskId, s: &mut Sampler, count: usize, label: &str) -> Vec<CaseInput> {
    let cases = random_of(task, s, count);
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

/// Jittered evaluations per case that measure how the reference's answer moves when its
/// inputs move within rounding ([`Call::jitters`]).
const CONDITIONING_SAMPLES: u64 = 6;

/// The spread of `t`'s output over inputs moved within rounding, or `None` when such a move
/// changes the output's shape (a `None` that becomes a value at a critical angle, a value
/// that becomes non-finite) or panics: then correct f32 implementations may disagree on
/// the shape itself.
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
fn conditioning(call: &Call, expected: &Output, t: &impl Tasks) -> Option<f64> {
    let on: Vec<(&Param, f64)> = if is_zero(expected) {
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
    call.jitters(CONDITIONING_SAMPLES)
        .iter()
        .filter(|jittered| on.iter().all(|(p, v)| (p.value)(jittered) == Some(*v)))
        .try_fold(0f64, |spread, jittered| {
            let out = panics::catch(|| jittered.eval(t)).ok()?;
            Some(spread.max(out.max_difference(expected)?))
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

/// A colour in the scene format, for the grader's own scenes.
pub(crate) fn yaml_rgb(c: glam::DVec3) -> String {
    format!("[{}, {}, {}]", c.x, c.y, c.z)
}

/// True when every number in `output` is exactly 0.
fn is_zero(output: &Output) -> bool {
    match output {
        Output::Nothing => false,
        Output::Number(x) => *x == 0.0,
        Output::Numbers(v) => v.iter().all(|x| *x == 0.0),
        Output::Record(fields) => fields.values().all(is_zero),
    }
}

/// Evaluates `inputs` on `t` (the reference) into cases with expected outputs. Fails when
/// an output is NaN, or infinite in a fixed case (under a rule that compares numbers), or
/// the code panics: expected data must be well defined. A drawn case whose answer comes
/// within [`OVERFLOW_RANGE`] of overflowing f32 is left out.
///
/// A case compared by a tolerance gets that tolerance widened by twice the spread of the
/// reference's answer over inputs moved by a few ulps: near a singularity (a tiny roughness
/// with `h` near the normal, the grazing limit of `cos θt`) a correct implementation that
/// rounds differently is as far off as that, and a wrong one much further. A drawn case
/// whose shape changes within rounding (`refract` on the critical angle) is dropped.
pub fn evaluate(inputs: &[CaseInput], t: &impl Tasks) -> anyhow::Result<Vec<ValueCase>> {
    let mut cases = Vec::with_capacity(inputs.len());
    for input in inputs {
        let expected = match panics::catch(|| input.call.eval(t)) {
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
            Err(p) => bail!(
                "{} [{}]: the reference {}",
                input.call,
                input.name,
                p.describe()
            ),
        };
        let rule = match input.rule {
            Rule::Close(tol) => match conditioning(&input.call, &expected, t) {
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

/// The sampler setups whose distributions the sampling check tests.
pub fn sampling_setups(task: TaskId) -> Vec<SampleCall> {
    setups_of(task)
}

/// How an estimator of radiance (RGB) turns it into one number: a weighted sum whose
/// weights differ per channel and sum to 1. A grey radiance keeps its value, and in a
/// coloured scene code that mixes up channels (uses one channel for all, or a scalar
/// where the contract has a colour) changes the mean.
pub const CHANNEL_WEIGHTS: glam::DVec3 = glam::DVec3::new(1.0 / 7.0, 2.0 / 7.0, 4.0 / 7.0);

/// An estimator with a known mean, built on an implementation's task functions.
pub struct EstimatorSpec<'a> {
    /// What it estimates.
    pub name: String,
    /// The analytic value of its mean.
    pub analytic: f64,
    /// How many estimates the check draws.
    pub samples: usize,
    /// One estimate per call.
    pub estimate: Box<super::estimator::Estimator<'a>>,
}

/// The estimators of the estimator check of `task`, on implementation `t`.
pub fn estimators<T: Tasks>(task: TaskId, t: &T) -> Vec<EstimatorSpec<'_>> {
    estimators_of(task, t)
}

/// Every stored quadrature the estimators' answers are built from (the light rough
/// conductors reflect), beside the same quadrature of `t`'s BSDF: with the reference's
/// table the two agree (`tests/instructor/reference_values.rs`).
pub fn stored_quadratures<T: Tasks>(t: &T) -> Vec<StoredQuadrature> {
    let mut all = crate::tasks::path_trace::cases::stored_quadratures(t);
    all.extend(crate::tasks::mis::cases::stored_quadratures(t));
    all
}

/// What `task`'s estimator and sampling checks are declared to catch (its `cases.rs`'s
/// `POWER`); `None` for a task without either.
pub fn declared_power(task: TaskId) -> Option<crate::grade::power::Declared> {
    power_of(task)
}

/// Pairs of estimators of `task` whose variances must relate as each pair's bound says
/// (see [`super::variance_pair`]).
pub fn variance_pairs<T: Tasks>(task: TaskId, t: &T) -> Vec<VariancePair<'_>> {
    variance_pairs_of(task, t)
}
