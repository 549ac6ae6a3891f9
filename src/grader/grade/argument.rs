//! How each parameter type of the task functions is stored in a case, handed to the
//! function, shown in a message, moved within rounding and probed: what lets [`Call`] and
//! the probe be generated from the task signatures alone
//! ([`for_each_task_function!`](crate::for_each_task_function)).
//!
//! [`Argument`] is implemented on the function-pointer type `fn(T)` of each parameter type
//! `T` that a signature uses: a pointer type spells a borrowed parameter (`&LayerStack`)
//! without a lifetime, which a stored field could not. A new task whose parameters have
//! types listed here needs nothing in this file; a new parameter type needs its impl.
//!
//! [`Call`]: super::call::Call

use super::rounding::Jitter;
use super::test_brdf::TestBrdf;
use crate::bsdf::{KajiyaKayParams, PhongParams};
use crate::geometry::{Hit, Ray};
use crate::integrator::{Heuristic, Segment};
use crate::medium::{Coefficients, Homogeneous, Medium};
use crate::optics::{LayerStack, Slab};
use crate::sampling::Sampler;
use crate::scene::{LoadOptions, Scene};
use glam::{Vec2, Vec3};
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use std::fmt::Debug;
use std::path::Path;

/// A parameter type `T` of a task function, implemented on `fn(T)`: how a call owns the
/// value and lends it to the function, and its ordinary value for the probe. Every
/// parameter type of every task has one.
pub trait Probe {
    /// What the call owns while the function borrows it.
    type Owned;
    /// The parameter as the function takes it, borrowed from [`Probe::Owned`].
    type Lent<'a>;
    /// The argument, lent from `owned`.
    fn lend(owned: &mut Self::Owned) -> Self::Lent<'_>;
    /// An ordinary value for the probe ([`super::probe::probe_task`]): every task
    /// function called on these returns, calling no other task's function.
    fn probe() -> Self::Owned;
}

/// A parameter type that a value case stores ([`super::call::Call`]): every parameter type
/// of the tasks judged by value. (A scene, a hit or a medium is a [`Probe`] only: their
/// tasks are judged by estimators.)
pub trait Argument: Probe {
    /// The parameter as a case stores it.
    type Stored: Clone + Debug + PartialEq + Serialize + DeserializeOwned;
    /// The owned value of a stored one.
    fn owned(stored: &Self::Stored) -> Self::Owned;
    /// The stored value as a student can paste it into a test (`0.99999994`).
    fn show(stored: &Self::Stored) -> String;
    /// Moves every real number of `stored` within rounding ([`super::jitter`]).
    fn jitter(_stored: &mut Self::Stored, _seed: u64) {}
    /// Draws the value's random numbers from the `k`-th other stream; false when it draws
    /// none.
    fn reseed(_stored: &mut Self::Stored, _k: u64) -> bool {
        false
    }
    /// The value as a direction that [`super::call::Call::jitters`] may turn, when it is
    /// a vector.
    fn vector(_stored: &mut Self::Stored) -> Option<&mut Vec3> {
        None
    }
}

/// An argument passed by value: stored as it is.
macro_rules! by_value {
    ($($ty:ty => probe $probe:expr, show $show:expr, jitter $jitter:expr;)+) => {$(
        impl Probe for fn($ty) {
            type Owned = $ty;
            type Lent<'a> = $ty;
            fn lend(owned: &mut $ty) -> $ty {
                *owned
            }
            fn probe() -> $ty {
                $probe
            }
        }
        impl Argument for fn($ty) {
            type Stored = $ty;
            fn owned(stored: &$ty) -> $ty {
                *stored
            }
            fn show(stored: &$ty) -> String {
                ($show)(*stored)
            }
            fn jitter(stored: &mut $ty, seed: u64) {
                ($jitter)(stored, seed)
            }
            fn vector(stored: &mut $ty) -> Option<&mut Vec3> {
                (stored as &mut dyn std::any::Any).downcast_mut()
            }
        }
    )+};
}

/// An argument passed by reference to a plain value: stored as the value it refers to.
macro_rules! by_reference {
    ($($ty:ty => probe $probe:expr, show $show:expr;)+) => {$(
        impl Probe for fn(&$ty) {
            type Owned = $ty;
            type Lent<'a> = &'a $ty;
            fn lend(owned: &mut $ty) -> &$ty {
                owned
            }
            fn probe() -> $ty {
                $probe
            }
        }
        impl Argument for fn(&$ty) {
            type Stored = $ty;
            fn owned(stored: &$ty) -> $ty {
                *stored
            }
            fn show(stored: &$ty) -> String {
                ($show)(stored)
            }
            fn jitter(stored: &mut $ty, seed: u64) {
                stored.jitter(seed);
            }
        }
    )+};
}

/// A parameter no value case stores (a scene, a hit, a medium): a probe value only.
macro_rules! probe_only {
    ($($ty:ty => $owned:ty, lent $lent:ty, probe $probe:expr, lend |$o:ident| $lend:expr;)+) => {$(
        impl Probe for fn($ty) {
            type Owned = $owned;
            type Lent<'a> = $lent;
            fn lend($o: &mut $owned) -> Self::Lent<'_> {
                $lend
            }
            fn probe() -> $owned {
                $probe
            }
        }
    )+};
}

/// An ordinary unit direction, above the surface, off every axis.
const PROBE_DIRECTION: Vec3 = Vec3::new(0.36, 0.48, 0.8);

by_value! {
    Vec3 => probe PROBE_DIRECTION, show exact_vec, jitter |v: &mut Vec3, s| v.jitter(s);
    Vec2 => probe Vec2::new(0.3, 0.7),
        show |v: Vec2| format!("({}, {})", n(v.x), n(v.y)),
        jitter |v: &mut Vec2, s| v.jitter(s);
    f32 => probe 0.5, show n, jitter |x: &mut f32, s| x.jitter(s);
    f64 => probe 0.5, show n, jitter |x: &mut f64, s| x.jitter(s);
    usize => probe 4, show |k: usize| k.to_string(), jitter |_: &mut usize, _| ();
    u32 => probe 4, show |k: u32| k.to_string(), jitter |_: &mut u32, _| ();
    i32 => probe 1, show |k: i32| k.to_string(), jitter |_: &mut i32, _| ();
}

by_reference! {
    PhongParams =>
        probe PhongParams { kd: Vec3::splat(0.5), ks: Vec3::splat(0.4), exponent: 20.0 },
        show |p: &PhongParams| format!(
            "{{kd: {}, ks: {}, exponent: {}}}", exact_vec(p.kd), exact_vec(p.ks), n(p.exponent)
        );
    KajiyaKayParams =>
        probe KajiyaKayParams { kd: Vec3::splat(0.1), ks: Vec3::splat(0.9), exponent: 80.0 },
        show |p: &KajiyaKayParams| format!(
            "{{kd: {}, ks: {}, exponent: {}}}", exact_vec(p.kd), exact_vec(p.ks), n(p.exponent)
        );
}

impl Probe for fn(&LayerStack) {
    type Owned = LayerStack;
    type Lent<'a> = &'a LayerStack;
    fn lend(owned: &mut LayerStack) -> &LayerStack {
        owned
    }
    fn probe() -> LayerStack {
        LayerStack {
            eta_incident: 1.0,
            slabs: vec![Slab {
                eta: 1.5,
                thickness: 10.0,
            }],
            eta_exit: 1.33,
            intensity: 100.0,
        }
    }
}

impl Argument for fn(&LayerStack) {
    type Stored = StackInput;
    fn owned(stored: &StackInput) -> LayerStack {
        stored.to_stack()
    }
    fn show(stack: &StackInput) -> String {
        let slabs: Vec<String> = stack
            .slabs
            .iter()
            .map(|(eta, d)| format!("{} [d={}]", n(*eta), n(*d)))
            .collect();
        format!(
            "{}→{}→{}, I={}",
            n(stack.eta_incident),
            slabs.join("→"),
            n(stack.eta_exit),
            n(stack.intensity)
        )
    }
    fn jitter(stored: &mut StackInput, seed: u64) {
        stored.jitter(seed);
    }
}

impl Probe for fn(&mut Sampler) {
    type Owned = Sampler;
    type Lent<'a> = &'a mut Sampler;
    fn lend(owned: &mut Sampler) -> &mut Sampler {
        owned
    }
    fn probe() -> Sampler {
        Sampler::new(0, 0)
    }
}

/// A sampler is stored as its seed: the case draws the same numbers each time.
impl Argument for fn(&mut Sampler) {
    type Stored = u64;
    fn owned(seed: &u64) -> Sampler {
        Sampler::new(*seed, 0)
    }
    fn show(seed: &u64) -> String {
        format!("seed {seed}")
    }
    fn reseed(seed: &mut u64, k: u64) -> bool {
        *seed = seed.wrapping_add(k.wrapping_mul(0x9e37_79b9_7f4a_7c15));
        true
    }
}

impl Probe for fn(&dyn Fn(Vec3, Vec3) -> f32) {
    type Owned = Box<dyn Fn(Vec3, Vec3) -> f32>;
    type Lent<'a> = &'a dyn Fn(Vec3, Vec3) -> f32;
    fn lend(owned: &mut Self::Owned) -> Self::Lent<'_> {
        &**owned
    }
    fn probe() -> Self::Owned {
        Box::new(|_, _| std::f32::consts::FRAC_1_PI)
    }
}

/// A BRDF closure is stored as one of the named [`TestBrdf`]s.
impl Argument for fn(&dyn Fn(Vec3, Vec3) -> f32) {
    type Stored = TestBrdf;
    fn owned(brdf: &TestBrdf) -> Self::Owned {
        let brdf = *brdf;
        Box::new(move |wi, wo| brdf.eval(wi, wo))
    }
    fn show(brdf: &TestBrdf) -> String {
        brdf.describe()
    }
    fn jitter(brdf: &mut TestBrdf, seed: u64) {
        brdf.jitter(seed);
    }
}

/// The floor of the probe scene, hit from above.
fn probe_hit() -> Hit {
    let ray = Ray::new(Vec3::new(0.0, 0.5, 0.3), -Vec3::Y);
    probe_scene()
        .intersect(&ray)
        .expect("the probe ray hits the probe scene's floor")
}

probe_only! {
    &Scene => Scene, lent &'a Scene, probe probe_scene(), lend |s| &*s;
    // A camera ray that leaves the scene: written code returns the environment (black)
    // without calling any other task.
    &Segment => Segment, lent &'a Segment,
        probe Segment {
            ray: Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::Y),
            hit: None,
            emission_counted: false,
        },
        lend |s| &*s;
    &Hit => Hit, lent &'a Hit, probe probe_hit(), lend |h| &*h;
    &dyn Medium => Homogeneous, lent &'a dyn Medium,
        probe Homogeneous { coefficients: Coefficients { sigma_a: 0.5, sigma_s: 0.5 } },
        lend |m| &*m as &dyn Medium;
    &Ray => Ray, lent &'a Ray, probe Ray::new(Vec3::ZERO, Vec3::Z), lend |r| &*r;
    Heuristic => Heuristic, lent Heuristic, probe Heuristic::Power, lend |h| *h;
}

/// A [`LayerStack`] as stored in a case (the framework type is not deserialisable).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StackInput {
    /// Index of the incident half-space.
    pub eta_incident: f64,
    /// `(eta, thickness)` of each slab in ray order.
    pub slabs: Vec<(f64, f64)>,
    /// Index of the exit half-space.
    pub eta_exit: f64,
    /// Incident intensity.
    pub intensity: f64,
}

impl StackInput {
    /// The framework's stack.
    pub fn to_stack(&self) -> LayerStack {
        LayerStack {
            eta_incident: self.eta_incident,
            slabs: self
                .slabs
                .iter()
                .map(|&(eta, thickness)| Slab { eta, thickness })
                .collect(),
            eta_exit: self.eta_exit,
            intensity: self.intensity,
        }
    }
}

impl Jitter for StackInput {
    fn jitter(&mut self, seed: u64) {
        self.eta_incident.jitter(seed);
        for (eta, thickness) in &mut self.slabs {
            eta.jitter(seed);
            thickness.jitter(seed);
        }
        self.eta_exit.jitter(seed);
        self.intensity.jitter(seed);
    }
}

/// An input exactly as the function received it (the shortest text that reads back to the
/// same number), so a student can paste a failing case into a test: `0.99999994`, `1e-7`.
pub(super) fn n(x: impl Into<f64>) -> String {
    let x: f64 = x.into();
    if (x as f32) as f64 == x {
        format!("{:?}", x as f32)
    } else {
        format!("{x:?}")
    }
}

/// A vector input, exactly: `(0.6, -0.8, 0.0)`.
pub(super) fn exact_vec(w: Vec3) -> String {
    format!("({}, {}, {})", n(w.x), n(w.y), n(w.z))
}

/// A tiny scene for probing the integrator tasks: a floor lit by a small area light. Its
/// floor samples directions uniformly (framework code), so probing `mis` calls no other
/// task.
pub const PROBE_SCENE: &str = "\
camera: {eye: [0, 1, 3], target: [0, 0, 0], fov: 40, width: 4, height: 4}
render: {spp: 1}
materials:
  floor: {diffuse: {albedo: 0.5, sampling: uniform}}
shapes:
  - quad: {origin: [-1, 0, 1], edge1: [2, 0, 0], edge2: [0, 0, -2], material: floor}
  - quad: {origin: [-0.25, 1, -0.25], edge1: [0.5, 0, 0], edge2: [0, 0, 0.5], emission: 4}
";

/// The probe scene, built.
pub fn probe_scene() -> Scene {
    Scene::from_yaml(
        Path::new("<probe scene>"),
        PROBE_SCENE,
        &LoadOptions::default(),
    )
    .expect("the built-in probe scene is valid (tests/instructor/render_scenes.rs checks it)")
}
