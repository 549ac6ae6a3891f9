//! `Patch`: the reference with some task functions replaced, for grading the grader.
//!
//! A patch replaces functions of one or more tasks; which replacements are in force is a
//! [`TaskSet`], exactly like [`pbrlab::implementation::Mixed`]: grading task X uses
//! `patch.only(X)`, so a wrong `smith_g1` is seen by `cook_torrance` only when both are
//! active. Functions that call other tasks take the patch itself as their first argument.
//! The type is generated from the task API's list of functions
//! ([`pbrlab::for_each_task_function!`]): a field per function, each `None` (the reference)
//! until a variant sets it.

use glam::{Vec2, Vec3};
use pbrlab::bsdf::{KajiyaKayParams, PhongParams, PlausibilityReport};
use pbrlab::geometry::{Hit, Ray};
use pbrlab::integrator::{DirectLight, Heuristic, Segment};
use pbrlab::medium::{FreeFlight, Medium};
use pbrlab::optics::{LayerStack, StackReport};
use pbrlab::sampling::Sampler;
use pbrlab::scene::Scene;
use pbrlab::task_set::TaskSet;
use pbrlab::worksheet::{TaskId, Tasks};
use pbrlab_solutions as sol;

/// `Patch`, its constructor and its [`Tasks`], from the list of task functions: a
/// function whose replacement is set and in force calls it, every other the reference's.
macro_rules! patch {
    ($($module:ident: $variant:ident {
        $(fn $name:ident($(@ $ctx:ident,)? $($arg:ident: $ty:ty),*) -> $ret:ty;)+
    })+) => {
        /// The reference with replaced functions. Build with `Patch::new(task)` and set
        /// fields: each has the task function's signature, with `&Patch` first where the
        /// function calls other tasks.
        // The field types are the task signatures, spelled out once each.
        #[allow(clippy::type_complexity)]
        #[derive(Clone, Copy)]
        pub struct Patch {
            /// Tasks whose replacements are in force.
            pub active: TaskSet,
            $($(pub $name: Option<fn($(patch!(@patch $ctx),)? $($ty),*) -> $ret>,)+)+
            /// Panic, loop, abort, … (for isolation tests) in every function of `task`
            /// while that task is active.
            pub misbehave: Option<fn()>,
            /// The task the patch was made for.
            pub task: TaskId,
        }

        impl Patch {
            /// The plain reference (no replacement in force), with replacements for `task`
            /// to be set on the fields.
            pub fn new(task: TaskId) -> Self {
                Self {
                    active: [task].into_iter().collect(),
                    $($($name: None,)+)+
                    misbehave: None,
                    task,
                }
            }
        }

        impl Tasks for Patch {
            $($(
                fn $name(&self, $($arg: $ty),*) -> $ret {
                    match self.$name {
                        Some(f) if self.on(TaskId::$variant) => {
                            f($(patch!(@self self $ctx),)? $($arg),*)
                        }
                        _ => {
                            // A misbehaving patch also misbehaves in functions it does not
                            // replace.
                            let _ = self.on(TaskId::$variant);
                            sol::$module::$name($(patch!(@self self $ctx),)? $($arg),*)
                        }
                    }
                }
            )+)+
        }
    };
    (@patch $ctx:ident) => { &Patch };
    (@self $this:ident $ctx:ident) => { $this };
}

pbrlab::for_each_task_function!(patch);

impl Patch {
    /// The same replacements, in force for exactly `tasks`.
    pub fn only(mut self, tasks: TaskSet) -> Self {
        self.active = tasks;
        self
    }

    fn on(&self, task: TaskId) -> bool {
        let on = self.active.contains(task);
        if on
            && task == self.task
            && let Some(misbehave) = self.misbehave
        {
            misbehave();
        }
        on
    }
}

/// One implementation of a test catalogue: the reference with `patch` applied.
pub struct Variant {
    /// How it differs from the reference.
    pub name: &'static str,
    /// The task it is about (the one a wrong variant must fail).
    pub task: TaskId,
    /// The implementation.
    pub patch: Patch,
}

/// A variant of `task` named `name`, whose patch `set` fills in.
pub fn variant(name: &'static str, task: TaskId, set: impl FnOnce(&mut Patch)) -> Variant {
    let mut patch = Patch::new(task);
    set(&mut patch);
    Variant { name, task, patch }
}
