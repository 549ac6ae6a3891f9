//! The task API: every task function's signature, listed once, and the [`Tasks`] trait and
//! [`TaskFns`] table generated from that list. The task ids, points and hints are the
//! course's ([`pbrlab_course::task`], re-exported here), which the list below is checked
//! against at compile time.
//!
//! # Conventions (every task, every file)
//! - **Directions point away from the surface**: both `wo` (towards the viewer) and `wi`
//!   (towards the light) start at the shading point. A ray's propagation direction is the
//!   negative of such a direction.
//! - **Local shading frame**: the normal is +z, so `cos θ = w.z`; for anisotropic materials
//!   +x is the tangent along which `alpha_x` applies. Framework code converts with
//!   [`crate::math::Frame`]; task functions that take a `tangent` or `n` say so.
//! - **Float type**: the renderer's f32 (glam `Vec3`). The layer-stack calculator works in
//!   f64 because its worksheet answers are checked to seven digits.
//! - **Radiance** is linear RGB. Angles in the API are radians unless a name says `_deg`.
//!
//! # How an implementation is put together
//! The `tasks!` invocation at the bottom of this file lists every task function once. It
//! generates the [`Tasks`] trait and the function table [`TaskFns`] that implements it.
//! The student's crate (`exercises/`) and the reference's crate (`solutions/`) each export
//! a `TaskFns` built by [`task_table!`](crate::task_table); the grader's `implementation`
//! module holds the ones a binary links. Task functions that build on other tasks take `t: &impl Tasks`
//! as their first argument and call the other tasks through it, so the grader can grade one
//! task with the reference standing in for the others, and `--impl mixed` can combine the
//! two ([`TaskFns::with_task`]).

use crate::bsdf::{KajiyaKayParams, PhongParams, PlausibilityReport};
use crate::geometry::{Hit, Ray};
use crate::integrator::{DirectLight, Heuristic, Segment};
use crate::medium::{FreeFlight, Medium};
use crate::optics::{LayerStack, StackReport};
use crate::sampling::Sampler;
use crate::scene::Scene;
use glam::{Vec2, Vec3};
pub use pbrlab_course::task::{TASKS, TaskId, TaskInfo};

/// String equality in a constant context (the task list's compile-time checks).
const fn same_str(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// The body of every function of [`TaskFns::ABSENT`].
fn absent(task: &str) -> ! {
    panic!("no implementation of the task `{task}` is in this process")
}

/// Generates the [`Tasks`] trait, the function table [`TaskFns`] and its macro
/// [`task_table!`](crate::task_table) from one list of task functions.
///
/// Each entry is `module: Variant { fn name(args) -> Ret; … }`: the file
/// `exercises/module.rs` (and `solutions/module.rs`) defines each listed function with the
/// same signature, and `Variant` is its [`TaskId`]. A function written `fn name(@t, args)`
/// takes the implementation as its first argument (`t: &impl Tasks`) so it can call other
/// tasks.
macro_rules! tasks {
    ($(
        $module:ident : $variant:ident {
            $(
                $(#[$doc:meta])*
                fn $name:ident ( $(@ $ctx:ident ,)? $($arg:ident : $ty:ty),* $(,)? ) -> $ret:ty;
            )+
        }
    )+) => {
        /// Every task function of the worksheet: the interface the renderer, the grader
        /// and the convergence study are generic over.
        ///
        /// Conventions are those of [`crate::worksheet`]: directions point away from the
        /// surface; in the local frame the normal is +z. The framework itself is compiled
        /// for one implementation, [`TaskFns`]; test implementations may implement the
        /// trait directly.
        pub trait Tasks: Sync + Sized {
            $($(
                $(#[$doc])*
                fn $name(&self, $($arg: $ty),*) -> $ret;
            )+)+
        }

        /// An implementation of the worksheet as a table of function pointers, one per task
        /// function: the boundary between the framework and the crates that implement the
        /// tasks (`exercises/`, `solutions/`). The framework is compiled once against this
        /// type, so changing an exercise recompiles only the exercise crate and a link.
        ///
        /// Functions that call other tasks receive the table itself as `t`, so a table mixed
        /// from two implementations ([`TaskFns::with_task`]) routes every call by task.
        // The field types are the task signatures, spelled out once each.
        #[allow(clippy::type_complexity)]
        #[derive(Clone, Copy)]
        pub struct TaskFns {
            $($(
                $(#[$doc])*
                pub $name: fn($(tasks!(@table $ctx),)? $($ty),*) -> $ret,
            )+)+
        }

        impl Tasks for TaskFns {
            $($(
                #[inline]
                fn $name(&self, $($arg: $ty),*) -> $ret {
                    (self.$name)($({ let _ = stringify!($ctx); self },)? $($arg),*)
                }
            )+)+
        }

        impl TaskFns {
            /// The table in which every function panics, saying that no implementation of
            /// its task is in this process: the start of a table built task by task, such
            /// as a reference library that holds one task ([`crate::compiled_reference`]).
            pub const ABSENT: TaskFns = TaskFns {
                $($(
                    $name: |$(_: tasks!(@table $ctx),)? $($arg: $ty),*| -> $ret {
                        $(let _ = $arg;)*
                        absent(stringify!($module))
                    },
                )+)+
            };

            /// The table that takes `task`'s functions from `from` and every other one from
            /// `self`. A `const fn`, so that a static built with it refers to `task`'s
            /// functions of `from` and to no other.
            pub const fn with_task(mut self, from: &TaskFns, task: TaskId) -> TaskFns {
                match task {
                    $(TaskId::$variant => { $(self.$name = from.$name;)+ })+
                }
                self
            }
        }

        impl std::fmt::Debug for TaskFns {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str("TaskFns")
            }
        }

        /// The [`TaskFns`] of a crate that implements the tasks: `task_table!()` names, for
        /// every task function, `crate::<module>::<function>` (the layout of `exercises/`
        /// and `solutions/`: one module per task).
        // `crate` is meant: the paths are the calling crate's task modules.
        #[allow(clippy::crate_in_macro_def)]
        #[macro_export]
        macro_rules! task_table {
            () => {
                $crate::worksheet::TaskFns {
                    $($($name: crate::$module::$name,)+)+
                }
            };
        }

        /// Defines `pub struct Direct`, the [`Tasks`] of a crate laid out like `exercises/`
        /// and `solutions/` (one module per task) with every call made straight to
        /// `crate::<module>::<function>`: no table, so the compiler can inline one task into
        /// another and into the renderer. Only the `pbrlab` binary's reference-only renders
        /// use it (`solutions/`); a student's code stays behind a [`TaskFns`] table.
        // `crate` is meant, as in `task_table!`.
        #[allow(clippy::crate_in_macro_def)]
        #[macro_export]
        macro_rules! direct_tasks {
            () => {
                /// This crate's task functions as a [`Tasks`](pbrlab_renderer::worksheet::Tasks)
                /// implementation that calls them directly, for renders that may inline them.
                #[derive(Clone, Copy, Debug, Default)]
                pub struct Direct;

                const _: () = {
                    use $crate::prelude::*;
                    impl $crate::worksheet::Tasks for Direct {
                        $($(
                            #[inline]
                            fn $name(&self, $($arg: $ty),*) -> $ret {
                                crate::$module::$name($({ let _ = stringify!($ctx); self },)? $($arg),*)
                            }
                        )+)+
                    }
                };
            };
        }

        /// Calls the macro `$callback` with the list of every task function, task by task, as
        /// `tasks!` takes it (without the docs): `module: Variant { fn name(@t, args) -> Ret;
        /// … }`, for code generated over every function, such as the tests' patched
        /// reference (`tests/instructor/support/patch.rs`).
        #[macro_export]
        macro_rules! for_each_task_function {
            ($callback:ident) => {
                $callback! {
                    $($module: $variant {
                        $(fn $name($(@ $ctx,)? $($arg: $ty),*) -> $ret;)+
                    })+
                }
            };
        }

        /// The trait functions that belong to each task, for messages and coverage checks.
        pub fn task_functions(task: TaskId) -> &'static [&'static str] {
            match task {
                $(TaskId::$variant => &[$(stringify!($name)),+],)+
            }
        }

        // The hand-kept lists agree with this one at compile time: `TaskId::ALL` and
        // `TASKS` hold every task, in the enum's order (which `info` indexes by).
        const _: () = {
            let count = [$(stringify!($variant)),+].len();
            assert!(TaskId::ALL.len() == count, "TaskId::ALL misses a task");
            assert!(TASKS.len() == count, "TASKS misses a task's row");
            let mut i = 0;
            while i < count {
                assert!(TaskId::ALL[i] as usize == i, "TaskId::ALL is out of order");
                i += 1;
            }
            $(assert!(
                same_str(TASKS[TaskId::$variant as usize].id, stringify!($module)),
                concat!("the row of TASKS at TaskId::", stringify!($variant), " is not `",
                    stringify!($module), "`'s"),
            );)+
        };
    };
    (@table $ctx:ident) => { &TaskFns };
}

tasks! {
    reflect: Reflect {
        /// Mirror reflection of `wo` about the normal `n` (world or local; `n` need not have
        /// unit length). Both `wo` and the result point away from the surface.
        fn reflect(wo: Vec3, n: Vec3) -> Vec3;
    }
    refract_stack: RefractStack {
        /// Refraction of `wi` (pointing away from the surface on the incident side) through an
        /// interface with normal `n` on the incident side (need not be unit), from index
        /// `eta_i` into `eta_t`. Returns the unit transmitted direction, pointing away from
        /// the surface on the far side, or `None` under total internal reflection.
        fn refract(wi: Vec3, n: Vec3, eta_i: f32, eta_t: f32) -> Option<Vec3>;
        /// The critical angle in radians for light going from `eta_i` into `eta_t`, or `None`
        /// when total internal reflection cannot happen (`eta_i <= eta_t`).
        fn critical_angle(eta_i: f64, eta_t: f64) -> Option<f64>;
        /// Follows a ray entering `stack` at `theta_deg` degrees from the normal through
        /// every interface; see [`StackReport`] for what to fill in.
        fn refract_stack(@t, theta_deg: f64, stack: &LayerStack) -> StackReport;
    }
    fresnel_schlick: FresnelSchlick {
        /// Reflectance at normal incidence of the interface between `eta_i` and `eta_t`.
        fn schlick_r0(eta_i: f32, eta_t: f32) -> f32;
        /// Schlick's approximation of the unpolarised reflectance for light arriving at
        /// `cos_theta_i` (≥ 0, on the incident side) from `eta_i` into `eta_t`: uses the
        /// transmitted cosine when `eta_i > eta_t`, returns 1 under total internal reflection
        /// and 0 when the indices are equal.
        fn fresnel_schlick(@t, cos_theta_i: f32, eta_i: f32, eta_t: f32) -> f32;
    }
    cosine_sample: CosineSample {
        /// A direction in the local frame (z = normal), distributed with density cos θ / π,
        /// from a uniform point `u` in [0, 1)².
        fn cosine_sample(u: Vec2) -> Vec3;
        /// The density per steradian with which [`Tasks::cosine_sample`] produces the local
        /// direction `w` (0 below the surface).
        fn cosine_pdf(w: Vec3) -> f32;
    }
    smith_g1: SmithG1 {
        /// GGX Smith masking G1 of the local direction `w` for isotropic roughness `alpha`;
        /// in [0, 1], and 0 for `w` at or below the horizon.
        fn smith_g1(w: Vec3, alpha: f32) -> f32;
    }
    cook_torrance: CookTorrance {
        /// The Cook-Torrance BRDF `F D G1(wo) G1(wi) / (4 cos θo cos θi)` for local
        /// directions `wo`, `wi`, anisotropic GGX roughness `alpha_x` (along local x) and
        /// `alpha_y`, and Schlick Fresnel with normal-incidence reflectance `f0` (RGB).
        /// 0 when either direction is at or below the horizon.
        fn cook_torrance(@t, wo: Vec3, wi: Vec3, alpha_x: f32, alpha_y: f32, f0: Vec3) -> Vec3;
    }
    aniso_ndf: AnisoNdf {
        /// The anisotropic GGX (Trowbridge-Reitz) density of microfacet normals `h` (local
        /// frame, unit length) with roughness `alpha_x` along local x and `alpha_y` along
        /// local y, per steradian of `h`; normalised so that ∫ D(h) cos θh dωh = 1.
        fn aniso_ndf(h: Vec3, alpha_x: f32, alpha_y: f32) -> f32;
    }
    phong: Phong {
        /// The energy-normalised Phong BRDF described by [`PhongParams`], for local
        /// directions `wo`, `wi`; 0 when either is below the surface.
        fn phong(@t, wo: Vec3, wi: Vec3, params: &PhongParams) -> Vec3;
        /// A numerical reciprocity test: the largest relative difference
        /// `|f(a, b) − f(b, a)| / max(|f(a, b)|, |f(b, a)|)` over `pairs` random pairs of
        /// local directions in the upper hemisphere (pairs where both values are 0 count 0).
        fn reciprocity_gap(brdf: &dyn Fn(Vec3, Vec3) -> f32, sampler: &mut Sampler, pairs: usize) -> f32;
    }
    kajiya_kay: KajiyaKay {
        /// The Kajiya-Kay fibre shading value for directions `wo`, `wi` (pointing away from
        /// the fibre) and unit fibre `tangent`, all in one frame: diffuse `kd sin(t, wi)` plus
        /// specular `ks max(0, c)^p`, `c` the cosine between `wo` and the reflection cone of
        /// `wi`. Non-negative and finite.
        fn kajiya_kay(wo: Vec3, wi: Vec3, tangent: Vec3, params: &KajiyaKayParams) -> Vec3;
    }
    beckmann_ndf: BeckmannNdf {
        /// The Beckmann density of microfacet normals `h` (local frame) with roughness
        /// `alpha`; 0 for `h` at or below the horizon.
        fn beckmann_ndf(h: Vec3, alpha: f32) -> f32;
    }
    ndf_sample: NdfSample {
        /// Samples an incident direction `wi` for the outgoing direction `wo` (local frame)
        /// by drawing a microfacet normal with density `D(h) cos θh` (anisotropic GGX) from
        /// `u` and reflecting `wo` about it. `None` when `wo·h ≤ 0` or `wi` is below the
        /// surface.
        fn ndf_sample(@t, wo: Vec3, alpha_x: f32, alpha_y: f32, u: Vec2) -> Option<Vec3>;
        /// The density per steradian of `wi` under [`Tasks::ndf_sample`]:
        /// `D(h) cos θh / (4 |wo·h|)`, 0 where sampling cannot produce `wi`.
        fn ndf_pdf(@t, wo: Vec3, wi: Vec3, alpha_x: f32, alpha_y: f32) -> f32;
    }
    brdf_check: BrdfCheck {
        /// Measures positivity, reciprocity and energy conservation of `brdf(wi, wo)`
        /// (local directions) with `samples` random directions; see [`PlausibilityReport`].
        fn brdf_check(@t, brdf: &dyn Fn(Vec3, Vec3) -> f32, sampler: &mut Sampler, samples: usize) -> PlausibilityReport;
    }
    path_trace: PathTrace {
        /// One recursive step of a path tracer: the radiance that arrives along `segment`
        /// (towards its ray's origin). `depth` is the number of segments the path may still
        /// have, counting this one; at `depth <= 0` the answer is 0. Adds the emission
        /// found at the end of the segment unless `segment.emission_counted`, the direct
        /// light there (from `t.mis`), and the light carried back by the continuation
        /// `mis` sampled, with Russian roulette once `scene.settings().roulette_applies(depth)`.
        fn path_trace(@t, scene: &Scene, segment: &Segment, depth: i32, sampler: &mut Sampler) -> Vec3;
    }
    mis: Mis {
        /// Direct light at `hit` towards `wo` by one light sample and one BSDF sample,
        /// weighted by `heuristic`; also returns the BSDF sample, traced, so the path can
        /// continue with it. Every pdf in a weight is per unit solid angle.
        fn mis(@t, scene: &Scene, hit: &Hit, wo: Vec3, heuristic: Heuristic, sampler: &mut Sampler) -> DirectLight;
    }
    delta_tracking: DeltaTracking {
        /// Samples where a path travelling along `ray` through `medium` first really
        /// collides, on the segment `(0, t_max)`, by delta tracking with the medium's
        /// majorant; gives up with `FreeFlight::Exhausted` after `max_steps` tentative
        /// collisions.
        fn delta_tracking(medium: &dyn Medium, ray: &Ray, t_max: f32, max_steps: u32, sampler: &mut Sampler) -> FreeFlight;
    }
}
