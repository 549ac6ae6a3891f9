//! A single harmless call of every function of a task: tells a stub (`todo!()`) from code.

use super::argument::Probe;
use crate::scene::Scene;
use crate::worksheet::{TaskId, Tasks};
// The parameter types of the task signatures, as the generated probe spells them.
use crate::bsdf::{KajiyaKayParams, PhongParams};
use crate::geometry::{Hit, Ray};
use crate::integrator::{Heuristic, Segment};
use crate::medium::Medium;
use crate::optics::LayerStack;
use crate::sampling::Sampler;
use glam::{Vec2, Vec3};

/// Generates [`probe_task`] from the list of task functions: each function called once on
/// its parameters' [`Probe::probe`] values.
macro_rules! probes {
    ($($module:ident: $variant:ident {
        $(fn $name:ident($(@ $ctx:ident,)? $($arg:ident: $ty:ty),*) -> $ret:ty;)+
    })+) => {
        /// Calls every function of `task` once on ordinary inputs ([`Probe::probe`]) and
        /// discards the results. A stub panics with `todo!()`'s message; written code
        /// returns (or panics otherwise).
        pub fn probe_task(t: &impl Tasks, task: TaskId) {
            match task {
                $(TaskId::$variant => {
                    $({
                        $(let mut $arg = <fn($ty) as Probe>::probe();)*
                        let _ = t.$name($(<fn($ty) as Probe>::lend(&mut $arg)),*);
                    })+
                })+
            }
        }
    };
}

crate::for_each_task_function!(probes);
