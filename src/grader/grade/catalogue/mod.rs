//! The graded inputs of every task: fixed cases (the worksheet's examples, the errata's
//! traps) and random cases, the sampler setups of the sampling checks, and the estimators
//! of the estimator checks. Each task's own are in its folder, `src/grader/tasks/<task>/cases.rs`;
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
use super::case_input::CaseInput;
use super::domain::Param;
use super::estimator::EstimatorSpec;
use super::output::Output;
use super::variance_pair::VariancePair;
use crate::sampling::Sampler;
use crate::worksheet::{TaskId, Tasks};

pub use polygon::projected_solid_angle;

/// What a task's `cases.rs` declares. Every item defaults to "none", so a task has
/// only what its line in [`crate::for_each_task!`] lists.
trait TaskCatalogue {
    /// The declared domain (see [`domain`]).
    const DOMAIN: &'static [Param] = &[];
    /// What the estimator and sampling checks are declared to catch.
    const POWER: Option<crate::grade::declared::Declared> = None;
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
    /// The contract's answer to a call in f64 (see [`super::contract`]).
    fn contract(_call: &Call) -> Option<Output> {
        None
    }
}

/// One item of a task's [`TaskCatalogue`], taken from its file `$m.rs`.
macro_rules! catalogue_item {
    ($m:ident, DOMAIN) => {
        const DOMAIN: &'static [Param] = $m::DOMAIN;
    };
    ($m:ident, POWER) => {
        const POWER: Option<crate::grade::declared::Declared> = Some($m::POWER);
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
    ($m:ident, contract) => {
        #[cfg(feature = "solutions")]
        fn contract(call: &Call) -> Option<Output> {
            crate::tasks::$m::contract::expected(call)
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
        fn power_of(task: TaskId) -> Option<crate::grade::declared::Declared> {
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
        fn contract_of(call: &Call) -> Option<Output> {
            match call.task() {
                $(TaskId::$variant => <entries::$variant as TaskCatalogue>::contract(call),)*
            }
        }
    };
}

crate::for_each_task!(registry);

/// The declared domain of `task`'s functions: every parameter's range, special values and
/// boundaries (see [`super::domain`]), stated in the task's `cases.rs`. Empty for the
/// integrator tasks, which are graded by estimators and renders, not value cases.
pub fn domain(task: TaskId) -> &'static [Param] {
    domain_of(task)
}

/// The fixed cases of `task` (the worksheet's examples, the errata's traps, the exercise
/// text's edge cases), as its `cases.rs` declares them.
pub fn fixed(task: TaskId) -> Vec<CaseInput> {
    fixed_of(task)
}

/// `count` cases of `task` drawn from its declared domain with `s`, as its `cases.rs`
/// draws them (before [`super::value_cases`] drops the ill-posed ones).
pub fn drawn(task: TaskId, s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    random_of(task, s, count)
}

/// The sampler setups whose distributions the sampling check tests.
pub fn sampling_setups(task: TaskId) -> Vec<SampleCall> {
    setups_of(task)
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
pub fn declared_power(task: TaskId) -> Option<crate::grade::declared::Declared> {
    power_of(task)
}

/// Pairs of estimators of `task` whose variances must relate as each pair's bound says
/// (see [`super::variance_pair`]).
pub fn variance_pairs<T: Tasks>(task: TaskId, t: &T) -> Vec<VariancePair<'_>> {
    variance_pairs_of(task, t)
}

/// The answer of the contract of `call`'s task in f64, at exactly its inputs (see
/// [`super::contract`]); `None` where the task's `contract.rs` covers no such call, and
/// always in the handout, which has no contracts (nor a reference to evaluate cases with).
pub fn contract(call: &Call) -> Option<Output> {
    contract_of(call)
}
