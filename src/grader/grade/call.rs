//! One call of a task function with concrete inputs: what a value case stores, evaluates
//! and prints in messages.

use super::argument::{Argument, Probe, n};
use super::output::{IntoOutput, Output, fmt_vec};
use super::rounding::Jitter;
use crate::optics::LayerStack;
use crate::worksheet::{TaskId, Tasks};
// The parameter types of the task signatures, as the generated `Call` spells them.
use crate::bsdf::{KajiyaKayParams, PhongParams};
use crate::sampling::Sampler;
use glam::{Vec2, Vec3};
use serde::{Deserialize, Serialize};
use std::fmt;

/// Generates [`Call`] from the list of task functions (`for_each_task_function!`): a
/// variant per function of a task judged by value, named as the function, with a field per
/// parameter, named and ordered as in its signature and stored as [`Argument`] says.
macro_rules! calls {
    ($($module:ident: $variant:ident {
        $(fn $name:ident($(@ $ctx:ident,)? $($arg:ident: $ty:ty),*) -> $ret:ty;)+
    })*) => {
        /// A task function and its arguments. Serialised into the stored expected data
        /// (tagged by `fn`, the function's name), so the grader can call the student's
        /// function on exactly the inputs the reference saw.
        ///
        /// Generated from the task signatures: a variant per function of every task judged
        /// by value, named as the function (hence snake case), its fields the function's
        /// parameters. A new value task adds nothing here.
        #[allow(non_camel_case_types)]
        #[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
        #[serde(tag = "fn")]
        pub enum Call {
            $($(
                #[doc = concat!("[`Tasks::", stringify!($name), "`].")]
                $name {
                    $(
                        #[doc = concat!("The parameter `", stringify!($arg), "`.")]
                        $arg: <fn($ty) as Argument>::Stored,
                    )*
                },
            )+)*
            /// A sampler's warp against its own pdf at each of `points`: the solid angle
            /// its directions sweep per unit area of the square (central differences of
            /// step `h`) times the pdf at the direction, which is 1 for a sampler that
            /// follows its pdf; NaN where the sampler rejects.
            sample_jacobian {
                /// The sampler and its pdf.
                sampler: SampleCall,
                /// Points of the unit square.
                points: Vec<Vec2>,
                /// The finite-difference step.
                h: f32,
            },
        }

        impl Call {
            /// The task the called function belongs to.
            pub fn task(&self) -> TaskId {
                match self {
                    $($(Call::$name { .. } => TaskId::$variant,)+)*
                    Call::sample_jacobian { sampler, .. } => sampler.task(),
                }
            }

            /// The call with its random numbers drawn from another stream, the `k`-th:
            /// `None` for a call that draws none.
            pub fn reseeded(&self, k: u64) -> Option<Call> {
                let mut call = self.clone();
                let draws = match &mut call {
                    $($(Call::$name { $($arg),* } => {
                        false $(| <fn($ty) as Argument>::reseed($arg, k))*
                    })+)*
                    Call::sample_jacobian { .. } => false,
                };
                draws.then_some(call)
            }

            /// Calls the function on `t` and converts its result.
            pub fn eval(&self, t: &impl Tasks) -> Output {
                match self {
                    $($(Call::$name { $($arg),* } => {
                        $(let mut $arg = <fn($ty) as Argument>::owned($arg);)*
                        t.$name($(<fn($ty) as Probe>::lend(&mut $arg)),*).into_output()
                    })+)*
                    Call::sample_jacobian { sampler, points, h } => {
                        let ratios = points
                            .iter()
                            .map(|&u| sampler.jacobian_times_pdf(t, u, *h).unwrap_or(f64::NAN))
                            .collect();
                        Output::Numbers(ratios)
                    }
                }
            }

            /// Moves every real input by [`Argument::jitter`] (see [`Call::jitters`]).
            pub(super) fn jitter_inputs(&mut self, seed: u64) {
                match self {
                    $($(Call::$name { $($arg),* } => {
                        $(<fn($ty) as Argument>::jitter($arg, seed);)*
                    })+)*
                    Call::sample_jacobian { sampler, points, h } => {
                        sampler.jitter(seed);
                        points.iter_mut().for_each(|p| p.jitter(seed));
                        h.jitter(seed);
                    }
                }
            }

            /// The direction inputs, in the order of the signature: the parameters named
            /// as the worksheet names unit directions ([`is_direction!`]), which
            /// [`Call::jitters`] turns.
            pub(super) fn directions_mut(&mut self) -> Vec<&mut Vec3> {
                let mut out = Vec::new();
                match self {
                    $($(Call::$name { $($arg),* } => {
                        $(if is_direction!($arg) {
                            out.extend(<fn($ty) as Argument>::vector($arg));
                        })*
                    })+)*
                    Call::sample_jacobian { .. } => {}
                }
                out
            }
        }

        impl fmt::Display for Call {
            /// `smith_g1(w=(0.6, 0.0, 0.8), alpha=0.3)`: each input exactly as the function
            /// received it, so a student can paste a failing case into a test.
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                match self {
                    $($(Call::$name { $($arg),* } => {
                        let inputs: Vec<String> = vec![$(format!(
                            "{}={}",
                            stringify!($arg),
                            <fn($ty) as Argument>::show($arg)
                        )),*];
                        write!(f, "{}({})", stringify!($name), inputs.join(", "))
                    })+)*
                    Call::sample_jacobian { sampler, points, h } => write!(
                        f,
                        "{sampler}: solid angle per unit area × pdf at {} points (step {})",
                        points.len(),
                        n(*h)
                    ),
                }
            }
        }
    };
}

/// Whether a parameter of this name is a unit direction: the worksheet's names `w`, `wo`,
/// `wi`, `h` (a half vector), `n` (a normal) and `tangent`.
macro_rules! is_direction {
    (w) => {
        true
    };
    (wo) => {
        true
    };
    (wi) => {
        true
    };
    (h) => {
        true
    };
    (n) => {
        true
    };
    (tangent) => {
        true
    };
    ($other:ident) => {
        false
    };
}

/// Passes the functions of the tasks judged by value to [`calls!`]: every task but the
/// estimator tasks, whose inputs (a scene, a hit, a medium) no case stores. A new
/// estimator task adds its line here.
macro_rules! value_tasks {
    (@keep [$($kept:tt)*] path_trace: $v:ident { $($f:tt)* } $($rest:tt)*) => {
        value_tasks!(@keep [$($kept)*] $($rest)*);
    };
    (@keep [$($kept:tt)*] mis: $v:ident { $($f:tt)* } $($rest:tt)*) => {
        value_tasks!(@keep [$($kept)*] $($rest)*);
    };
    (@keep [$($kept:tt)*] delta_tracking: $v:ident { $($f:tt)* } $($rest:tt)*) => {
        value_tasks!(@keep [$($kept)*] $($rest)*);
    };
    (@keep [$($kept:tt)*] $m:ident: $v:ident { $($f:tt)* } $($rest:tt)*) => {
        value_tasks!(@keep [$($kept)* $m: $v { $($f)* }] $($rest)*);
    };
    (@keep [$($kept:tt)*]) => {
        calls! { $($kept)* }
    };
    ($($all:tt)*) => {
        value_tasks!(@keep [] $($all)*);
    };
}

crate::for_each_task_function!(value_tasks);

/// A task's direction sampler with its parameters: what a sampling check draws from.
// The fields are the sampler's parameters, named as in its signature.
#[allow(missing_docs)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "fn", rename_all = "snake_case")]
pub enum SampleCall {
    /// [`Tasks::cosine_sample`] with its pdf [`Tasks::cosine_pdf`].
    CosineSample,
    /// [`Tasks::ndf_sample`] with its pdf [`Tasks::ndf_pdf`].
    NdfSample {
        wo: Vec3,
        alpha_x: f32,
        alpha_y: f32,
    },
}

impl SampleCall {
    /// The task the sampler belongs to.
    pub fn task(&self) -> TaskId {
        match self {
            SampleCall::CosineSample => TaskId::CosineSample,
            SampleCall::NdfSample { .. } => TaskId::NdfSample,
        }
    }

    /// One direction from the uniform point `u`, or `None` when the sampler rejects.
    pub fn sample(&self, t: &impl Tasks, u: Vec2) -> Option<Vec3> {
        match self {
            SampleCall::CosineSample => Some(t.cosine_sample(u)),
            SampleCall::NdfSample {
                wo,
                alpha_x,
                alpha_y,
            } => t.ndf_sample(*wo, *alpha_x, *alpha_y, u),
        }
    }

    /// The density per steradian with which [`SampleCall::sample`] produces `w`.
    pub fn pdf(&self, t: &impl Tasks, w: Vec3) -> f32 {
        match self {
            SampleCall::CosineSample => t.cosine_pdf(w),
            SampleCall::NdfSample {
                wo,
                alpha_x,
                alpha_y,
            } => t.ndf_pdf(*wo, w, *alpha_x, *alpha_y),
        }
    }

    /// The solid angle the sampler's directions sweep per unit area of the square at `u`
    /// (central differences of step `h`), times its pdf at the direction: 1 where the warp
    /// follows the pdf. `None` where the sampler rejects at `u` or a neighbour.
    pub fn jacobian_times_pdf(&self, t: &impl Tasks, u: Vec2, h: f32) -> Option<f64> {
        let at = |du: f32, dv: f32| self.sample(t, u + Vec2::new(du, dv)).map(|w| w.as_dvec3());
        let (xp, xm, yp, ym) = (at(h, 0.0)?, at(-h, 0.0)?, at(0.0, h)?, at(0.0, -h)?);
        let w = self.sample(t, u)?;
        let step = 2.0 * h as f64;
        let swept = ((xp - xm) / step).cross((yp - ym) / step).length();
        Some(swept * self.pdf(t, w) as f64)
    }

    /// True when the sampler may return `None`.
    pub fn rejects(&self) -> bool {
        matches!(self, SampleCall::NdfSample { .. })
    }

    /// The cells its histogram uses.
    pub fn bins(&self) -> super::sampling::HemisphereBins {
        super::sampling::HemisphereBins {
            n_cos: 16,
            n_phi: 32,
        }
    }

    /// The reference's distribution over [`SampleCall::bins`], integrated from the reference
    /// pdf (16 × 16 midpoints per cell).
    #[cfg(feature = "solutions")]
    pub fn reference_target(&self) -> super::sampling::SamplingTarget {
        self.target(crate::implementation::reference())
    }

    /// The distribution over [`SampleCall::bins`] that `t`'s pdf says its sampler follows
    /// (16 × 16 midpoints per cell).
    pub fn target(&self, t: &impl Tasks) -> super::sampling::SamplingTarget {
        let bins = self.bins();
        let cells = bins.integrate(|w| self.pdf(t, w) as f64, 16);
        super::sampling::SamplingTarget::from_cells(self.to_string(), bins, cells, self.rejects())
    }
}

impl fmt::Display for SampleCall {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SampleCall::CosineSample => f.write_str("cosine_sample"),
            SampleCall::NdfSample {
                wo,
                alpha_x,
                alpha_y,
            } => write!(
                f,
                "ndf_sample(wo={}, alpha_x={}, alpha_y={})",
                fmt_vec(*wo),
                n(*alpha_x),
                n(*alpha_y)
            ),
        }
    }
}

impl Jitter for SampleCall {
    fn jitter(&mut self, seed: u64) {
        match self {
            SampleCall::CosineSample => {}
            SampleCall::NdfSample {
                wo,
                alpha_x,
                alpha_y,
            } => {
                wo.jitter(seed);
                alpha_x.jitter(seed);
                alpha_y.jitter(seed);
            }
        }
    }
}
