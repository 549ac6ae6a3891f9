//! Everything the framework knows about each task, one folder per task, `src/grader/tasks/<task>/`:
//! - `cases.rs`: what the grader judges: the declared domain (`DOMAIN`), the fixed cases
//!   (the worksheet's examples, the errata's traps) and random cases drawn from the domain;
//!   for a sampler its setups, for an estimator task its estimators, their `POWER` and
//!   variance pairs;
//! - `contract.rs` (a task judged by value): its contract in f64, the expected output of
//!   its value cases (see [`crate::grade::contract`]); left out of the handout;
//! - `stability.rs`: its stiff and extreme inputs, with the value or limit each must take
//!   (the grader's stability check, and `pbrlab stability`);
//! - `variants.rs`: the implementations the tests grade the grader with: known-wrong ones
//!   (each must fail this task and no other), correct-but-different ones (full marks), and
//!   naive ones with exactly the stability cases each must fail. Compiled into the tests
//!   only (`tests/instructor/support/variants.rs`), never into this crate, and left out of
//!   the student handout.
//!
//! - `expected.snap`: the public cases' expected outputs, generated from the reference
//!   (`tests/instructor/expected.rs`) and embedded in the grader (`src/grader/build.rs`);
//! - `library.rs`: the task's reference as a shared library, for the grader's workers (an
//!   example of `tools/reference-library/`; left out of the handout too).
//!
//! Beside the folder, a task has its API (its `TaskId` and signatures, with metadata and
//! hints, in `src/renderer/worksheet.rs`), the student's file `exercises/<task>.rs` and the
//! reference `solutions/<task>.rs`. `src/ARCHITECTURE.md`, "Adding a task", lists every
//! step.
//!
//! [`for_each_task!`](crate::for_each_task) is the one list of tasks: every registry (the
//! grader's catalogue, the stability cases, the tests' variants) is generated from it.

/// Calls the macro `$callback` with the list of every task, in worksheet order, one line
/// per task: `Variant => module { what its cases.rs declares }`, where `Variant` is the
/// task's [`TaskId`](crate::worksheet::TaskId) and `module` its folder under `src/grader/tasks/`.
/// The items are those of the grader's catalogue (`DOMAIN`, `POWER`, `fixed`, `random`,
/// `setups`, `estimators`, `variance_pairs` from `cases.rs`, and `contract` from
/// `contract.rs`); what a task does not declare is empty.
///
/// Adding a task adds its line here (and its `TaskId`); the registries' matches over
/// `TaskId` are exhaustive, so a task left out does not compile.
#[macro_export]
macro_rules! for_each_task {
    ($callback:ident) => {
        $callback! {
            Reflect => reflect { DOMAIN, fixed, random, contract },
            RefractStack => refract_stack { DOMAIN, fixed, random, contract },
            FresnelSchlick => fresnel_schlick { DOMAIN, fixed, random, contract },
            CosineSample => cosine_sample { DOMAIN, POWER, fixed, random, setups, estimators, contract },
            SmithG1 => smith_g1 { DOMAIN, fixed, random, contract },
            CookTorrance => cook_torrance { DOMAIN, fixed, random, contract },
            AnisoNdf => aniso_ndf { DOMAIN, POWER, fixed, random, estimators, contract },
            Phong => phong { DOMAIN, fixed, random, contract },
            KajiyaKay => kajiya_kay { DOMAIN, fixed, random, contract },
            BeckmannNdf => beckmann_ndf { DOMAIN, POWER, fixed, random, estimators, contract },
            NdfSample => ndf_sample { DOMAIN, POWER, fixed, random, setups, estimators, contract },
            BrdfCheck => brdf_check { DOMAIN, fixed, random },
            PathTrace => path_trace { POWER, estimators },
            Mis => mis { POWER, estimators, variance_pairs },
            DeltaTracking => delta_tracking { POWER, estimators },
        }
    };
}

/// The file of an item a task's line lists beyond its `cases.rs`: `contract` is
/// `contract.rs`, which writes the answer out and so exists in the instructor's build only
/// (the handout leaves it out, like the reference).
macro_rules! task_file {
    (contract) => {
        #[cfg(feature = "solutions")]
        pub(crate) mod contract;
    };
    ($item:ident) => {};
}

/// Declares each task's folder as a module with its `cases` and `stability`, and checks at
/// compile time that the list holds every task in the order of [`TaskId::ALL`].
macro_rules! task_modules {
    ($($variant:ident => $module:ident { $($item:ident),* }),* $(,)?) => {
        const _: () = {
            let listed = [$(TaskId::$variant),*];
            assert!(listed.len() == TaskId::ALL.len(), "for_each_task! misses a task");
            let mut i = 0;
            while i < listed.len() {
                assert!(listed[i] as usize == i, "for_each_task! is out of worksheet order");
                i += 1;
            }
        };

        $(
            #[doc = concat!(
                "The task `", stringify!($module), "`: its graded cases (`src/grader/tasks/",
                stringify!($module), "/cases.rs`) and stability cases (`stability.rs`). The ",
                "student's file is `exercises/", stringify!($module), ".rs`."
            )]
            pub mod $module {
                pub(crate) mod cases;
                pub(crate) mod stability;
                $(task_file!($item);)*
            }
        )*
    };
}

use crate::worksheet::TaskId;

for_each_task!(task_modules);
