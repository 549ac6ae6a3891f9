//! One stability case: a stiff or extreme input of one task and what the task must return.

use super::expect::{Bound, Expect};
use super::value::Value;
use super::verdict::Verdict;
use crate::grade::wire::StabilityOutput;
use crate::worksheet::TaskId;

/// One stiff or extreme input for one task, with what the task must return there.
///
/// `T` is the implementation the case runs on; a catalogue is built for a concrete
/// implementation type (see [`super::cases`]), so the evaluation is a plain function
/// pointer with no dynamic dispatch and no restriction on the [`crate::worksheet::Tasks`]
/// trait.
pub struct Case<T> {
    /// The task whose function the case calls (other tasks may be called through it).
    pub task: TaskId,
    /// A short identifier, unique in the catalogue: `task/what` (`smith_g1/back_facing`).
    pub name: &'static str,
    /// The input, in words and numbers.
    pub input: &'static str,
    /// Calls the task on the input and returns what it gave.
    pub eval: fn(&T) -> Value,
    /// The interval every number of the result must lie in (for example `[0, 1]` for a
    /// masking function, `[0, ∞)` for a BRDF). Checked before [`Case::expect`], so a value
    /// outside it is reported as out of range rather than merely wrong.
    pub range: Bound,
    /// The right value or limit.
    pub expect: Expect,
    /// What a robust implementation does here (shown to a student whose code fails).
    pub guard: &'static str,
}

/// Any real number: the range of a case that only checks its expectation.
pub const ANY: Bound = Bound::Within(f64::NEG_INFINITY, f64::INFINITY);
/// `[0, ∞)`: densities, BRDF values, reflectances before their own upper bound.
pub const NON_NEGATIVE: Bound = Bound::Within(0.0, f64::INFINITY);
/// `[0, 1]`: masking, reflectance.
pub const UNIT_INTERVAL: Bound = Bound::Within(0.0, 1.0);
/// `[−1, 1]` with a little slack for rounding: the components of a unit vector.
pub const DIRECTION: Bound = Bound::Within(-1.0 - 1e-6, 1.0 + 1e-6);

impl<T> Case<T> {
    /// Calls the case on `t`, catching a panic, timed: what a worker sends back for it
    /// (its parent judges it, [`super::outcome::judge_output`]).
    pub fn run(&self, t: &T) -> StabilityOutput {
        let start = std::time::Instant::now();
        let outcome = crate::panics::catch(|| (self.eval)(t));
        StabilityOutput {
            case: self.name.into(),
            outcome,
            seconds: start.elapsed().as_secs_f64(),
        }
    }

    /// Judges a value the task returned: NaN and infinities first (anywhere in the
    /// result), then the range, then the expectation.
    pub fn judge(&self, value: &Value) -> Verdict {
        let numbers = value.numbers();
        if numbers.iter().any(|x| x.is_nan()) {
            Verdict::NaN
        } else if numbers.iter().any(|x| x.is_infinite()) {
            Verdict::Inf
        } else if !numbers.iter().all(|x| self.range.accepts(*x)) {
            Verdict::OutOfRange
        } else if !self.expect.accepts(value) {
            Verdict::WrongValue
        } else {
            Verdict::Pass
        }
    }

    /// The expectation in words, with the range when it adds something.
    pub fn expected_text(&self) -> String {
        if self.range == ANY || matches!(self.expect, Expect::Near(..) | Expect::Fields(_)) {
            self.expect.to_string()
        } else {
            format!("{}, {}", self.expect, self.range)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grade::tolerance::Tolerance;

    fn case(range: Bound, expect: Expect) -> Case<()> {
        Case {
            task: TaskId::SmithG1,
            name: "test",
            input: "",
            eval: |_| Value::Absent,
            range,
            expect,
            guard: "",
        }
    }

    #[test]
    fn judge_orders_nan_inf_range_value() {
        let c = case(UNIT_INTERVAL, Expect::scalar(0.0, Tolerance::abs(1e-6)));
        assert_eq!(c.judge(&Value::Scalar(f64::NAN)), Verdict::NaN);
        assert_eq!(c.judge(&Value::Scalar(f64::INFINITY)), Verdict::Inf);
        assert_eq!(c.judge(&Value::Scalar(-6.19)), Verdict::OutOfRange);
        assert_eq!(c.judge(&Value::Scalar(0.5)), Verdict::WrongValue);
        assert_eq!(c.judge(&Value::Scalar(0.0)), Verdict::Pass);
        assert_eq!(c.judge(&Value::Absent), Verdict::WrongValue);
        let v = Value::Vector([f64::INFINITY, f64::NAN, 0.0]);
        assert_eq!(c.judge(&v), Verdict::NaN);
    }

    #[test]
    fn absent_passes_when_expected() {
        let c = case(ANY, Expect::Absent);
        assert_eq!(c.judge(&Value::Absent), Verdict::Pass);
        assert_eq!(c.judge(&Value::Scalar(0.1)), Verdict::WrongValue);
        assert_eq!(c.judge(&Value::Scalar(f64::NAN)), Verdict::NaN);
    }
}
