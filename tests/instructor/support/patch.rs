//! `Patch`: the reference with some task functions replaced, for grading the grader.
//!
//! A patch replaces functions of one or more tasks; which replacements are in force is a
//! [`TaskSet`], exactly like [`pbrlab::implementation::Mixed`]: grading task X uses
//! `patch.only(X)`, so a wrong `smith_g1` is seen by `cook_torrance` only when both are
//! active. Functions that call other tasks take the patch itself as their first argument.

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

/// A BRDF callback as the tasks take it.
pub type Brdf<'a> = &'a dyn Fn(Vec3, Vec3) -> f32;

/// The reference with replaced functions. Build with `Patch::new(task)` and set fields.
// The field types are the task signatures, spelled out once each.
#[allow(clippy::type_complexity)]
#[derive(Clone, Copy)]
pub struct Patch {
    /// Tasks whose replacements are in force.
    pub active: TaskSet,
    pub reflect: Option<fn(Vec3, Vec3) -> Vec3>,
    pub refract: Option<fn(Vec3, Vec3, f32, f32) -> Option<Vec3>>,
    pub critical_angle: Option<fn(f64, f64) -> Option<f64>>,
    pub refract_stack: Option<fn(&Patch, f64, &LayerStack) -> StackReport>,
    pub schlick_r0: Option<fn(f32, f32) -> f32>,
    pub fresnel_schlick: Option<fn(&Patch, f32, f32, f32) -> f32>,
    pub cosine_sample: Option<fn(Vec2) -> Vec3>,
    pub cosine_pdf: Option<fn(Vec3) -> f32>,
    pub smith_g1: Option<fn(Vec3, f32) -> f32>,
    pub cook_torrance: Option<fn(&Patch, Vec3, Vec3, f32, f32, Vec3) -> Vec3>,
    pub aniso_ndf: Option<fn(Vec3, f32, f32) -> f32>,
    pub phong: Option<fn(&Patch, Vec3, Vec3, &PhongParams) -> Vec3>,
    pub reciprocity_gap: Option<fn(Brdf<'_>, &mut Sampler, usize) -> f32>,
    pub kajiya_kay: Option<fn(Vec3, Vec3, Vec3, &KajiyaKayParams) -> Vec3>,
    pub beckmann_ndf: Option<fn(Vec3, f32) -> f32>,
    pub ndf_sample: Option<fn(&Patch, Vec3, f32, f32, Vec2) -> Option<Vec3>>,
    pub ndf_pdf: Option<fn(&Patch, Vec3, Vec3, f32, f32) -> f32>,
    pub brdf_check: Option<fn(&Patch, Brdf<'_>, &mut Sampler, usize) -> PlausibilityReport>,
    pub path_trace: Option<fn(&Patch, &Scene, &Segment, i32, &mut Sampler) -> Vec3>,
    pub mis: Option<fn(&Patch, &Scene, &Hit, Vec3, Heuristic, &mut Sampler) -> DirectLight>,
    pub delta_tracking: Option<fn(&dyn Medium, &Ray, f32, u32, &mut Sampler) -> FreeFlight>,
    /// Panic, loop, abort, … (for isolation tests) in every function of `task` while that
    /// task is active.
    pub misbehave: Option<fn()>,
    /// The task the patch was made for.
    pub task: TaskId,
}

impl Patch {
    /// The plain reference (no replacement in force), with replacements for `task` to be
    /// set on the fields.
    pub fn new(task: TaskId) -> Self {
        Self {
            active: [task].into_iter().collect(),
            reflect: None,
            refract: None,
            critical_angle: None,
            refract_stack: None,
            schlick_r0: None,
            fresnel_schlick: None,
            cosine_sample: None,
            cosine_pdf: None,
            smith_g1: None,
            cook_torrance: None,
            aniso_ndf: None,
            phong: None,
            reciprocity_gap: None,
            kajiya_kay: None,
            beckmann_ndf: None,
            ndf_sample: None,
            ndf_pdf: None,
            brdf_check: None,
            path_trace: None,
            mis: None,
            delta_tracking: None,
            misbehave: None,
            task,
        }
    }

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

macro_rules! pick {
    ($self:ident, $task:ident, $field:ident, |$f:ident| $patched:expr, $reference:expr) => {
        match $self.$field {
            Some($f) if $self.on(TaskId::$task) => $patched,
            _ => {
                // A misbehaving patch also misbehaves in functions it does not replace.
                let _ = $self.on(TaskId::$task);
                $reference
            }
        }
    };
}

impl Tasks for Patch {
    fn reflect(&self, wo: Vec3, n: Vec3) -> Vec3 {
        pick!(
            self,
            Reflect,
            reflect,
            |f| f(wo, n),
            sol::reflect::reflect(wo, n)
        )
    }
    fn refract(&self, wi: Vec3, n: Vec3, eta_i: f32, eta_t: f32) -> Option<Vec3> {
        pick!(
            self,
            RefractStack,
            refract,
            |f| f(wi, n, eta_i, eta_t),
            sol::refract_stack::refract(wi, n, eta_i, eta_t)
        )
    }
    fn critical_angle(&self, eta_i: f64, eta_t: f64) -> Option<f64> {
        pick!(
            self,
            RefractStack,
            critical_angle,
            |f| f(eta_i, eta_t),
            sol::refract_stack::critical_angle(eta_i, eta_t)
        )
    }
    fn refract_stack(&self, theta_deg: f64, stack: &LayerStack) -> StackReport {
        pick!(
            self,
            RefractStack,
            refract_stack,
            |f| f(self, theta_deg, stack),
            sol::refract_stack::refract_stack(self, theta_deg, stack)
        )
    }
    fn schlick_r0(&self, eta_i: f32, eta_t: f32) -> f32 {
        pick!(
            self,
            FresnelSchlick,
            schlick_r0,
            |f| f(eta_i, eta_t),
            sol::fresnel_schlick::schlick_r0(eta_i, eta_t)
        )
    }
    fn fresnel_schlick(&self, cos_theta_i: f32, eta_i: f32, eta_t: f32) -> f32 {
        pick!(
            self,
            FresnelSchlick,
            fresnel_schlick,
            |f| f(self, cos_theta_i, eta_i, eta_t),
            sol::fresnel_schlick::fresnel_schlick(self, cos_theta_i, eta_i, eta_t)
        )
    }
    fn cosine_sample(&self, u: Vec2) -> Vec3 {
        pick!(
            self,
            CosineSample,
            cosine_sample,
            |f| f(u),
            sol::cosine_sample::cosine_sample(u)
        )
    }
    fn cosine_pdf(&self, w: Vec3) -> f32 {
        pick!(
            self,
            CosineSample,
            cosine_pdf,
            |f| f(w),
            sol::cosine_sample::cosine_pdf(w)
        )
    }
    fn smith_g1(&self, w: Vec3, alpha: f32) -> f32 {
        pick!(
            self,
            SmithG1,
            smith_g1,
            |f| f(w, alpha),
            sol::smith_g1::smith_g1(w, alpha)
        )
    }
    fn cook_torrance(&self, wo: Vec3, wi: Vec3, alpha_x: f32, alpha_y: f32, f0: Vec3) -> Vec3 {
        pick!(
            self,
            CookTorrance,
            cook_torrance,
            |f| f(self, wo, wi, alpha_x, alpha_y, f0),
            sol::cook_torrance::cook_torrance(self, wo, wi, alpha_x, alpha_y, f0)
        )
    }
    fn aniso_ndf(&self, h: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
        pick!(
            self,
            AnisoNdf,
            aniso_ndf,
            |f| f(h, alpha_x, alpha_y),
            sol::aniso_ndf::aniso_ndf(h, alpha_x, alpha_y)
        )
    }
    fn phong(&self, wo: Vec3, wi: Vec3, params: &PhongParams) -> Vec3 {
        pick!(
            self,
            Phong,
            phong,
            |f| f(self, wo, wi, params),
            sol::phong::phong(self, wo, wi, params)
        )
    }
    fn reciprocity_gap(
        &self,
        brdf: &dyn Fn(Vec3, Vec3) -> f32,
        sampler: &mut Sampler,
        pairs: usize,
    ) -> f32 {
        pick!(
            self,
            Phong,
            reciprocity_gap,
            |f| f(brdf, sampler, pairs),
            sol::phong::reciprocity_gap(brdf, sampler, pairs)
        )
    }
    fn kajiya_kay(&self, wo: Vec3, wi: Vec3, tangent: Vec3, params: &KajiyaKayParams) -> Vec3 {
        pick!(
            self,
            KajiyaKay,
            kajiya_kay,
            |f| f(wo, wi, tangent, params),
            sol::kajiya_kay::kajiya_kay(wo, wi, tangent, params)
        )
    }
    fn beckmann_ndf(&self, h: Vec3, alpha: f32) -> f32 {
        pick!(
            self,
            BeckmannNdf,
            beckmann_ndf,
            |f| f(h, alpha),
            sol::beckmann_ndf::beckmann_ndf(h, alpha)
        )
    }
    fn ndf_sample(&self, wo: Vec3, alpha_x: f32, alpha_y: f32, u: Vec2) -> Option<Vec3> {
        pick!(
            self,
            NdfSample,
            ndf_sample,
            |f| f(self, wo, alpha_x, alpha_y, u),
            sol::ndf_sample::ndf_sample(self, wo, alpha_x, alpha_y, u)
        )
    }
    fn ndf_pdf(&self, wo: Vec3, wi: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
        pick!(
            self,
            NdfSample,
            ndf_pdf,
            |f| f(self, wo, wi, alpha_x, alpha_y),
            sol::ndf_sample::ndf_pdf(self, wo, wi, alpha_x, alpha_y)
        )
    }
    fn path_trace(
        &self,
        scene: &Scene,
        segment: &Segment,
        depth: i32,
        sampler: &mut Sampler,
    ) -> Vec3 {
        pick!(
            self,
            PathTrace,
            path_trace,
            |f| f(self, scene, segment, depth, sampler),
            sol::path_trace::path_trace(self, scene, segment, depth, sampler)
        )
    }
    fn mis(
        &self,
        scene: &Scene,
        hit: &Hit,
        wo: Vec3,
        heuristic: Heuristic,
        sampler: &mut Sampler,
    ) -> DirectLight {
        pick!(
            self,
            Mis,
            mis,
            |f| f(self, scene, hit, wo, heuristic, sampler),
            sol::mis::mis(self, scene, hit, wo, heuristic, sampler)
        )
    }
    fn delta_tracking(
        &self,
        medium: &dyn Medium,
        ray: &Ray,
        t_max: f32,
        max_steps: u32,
        sampler: &mut Sampler,
    ) -> FreeFlight {
        pick!(
            self,
            DeltaTracking,
            delta_tracking,
            |f| f(medium, ray, t_max, max_steps, sampler),
            sol::delta_tracking::delta_tracking(medium, ray, t_max, max_steps, sampler)
        )
    }
    fn brdf_check(
        &self,
        brdf: &dyn Fn(Vec3, Vec3) -> f32,
        sampler: &mut Sampler,
        samples: usize,
    ) -> PlausibilityReport {
        pick!(
            self,
            BrdfCheck,
            brdf_check,
            |f| f(self, brdf, sampler, samples),
            sol::brdf_check::brdf_check(self, brdf, sampler, samples)
        )
    }
}
