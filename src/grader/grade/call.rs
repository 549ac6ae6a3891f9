//! One call of a task function with concrete inputs: what a value case stores, evaluates
//! and prints in messages.

use super::output::{IntoOutput, Output, fmt_vec};
use super::test_brdf::TestBrdf;
use crate::bsdf::{KajiyaKayParams, PhongParams};
use crate::optics::{LayerStack, Slab};
use crate::sampling::Sampler;
use crate::worksheet::{TaskId, Tasks};
use glam::Vec3;
use serde::{Deserialize, Serialize};
use std::fmt;

/// A task function and its arguments. Serialised into the stored expected data, so the
/// grader can call the student's function on exactly the inputs the reference saw.
// The fields are the task function's parameters, named as in its signature (`Tasks`).
#[allow(missing_docs)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "fn", rename_all = "snake_case")]
pub enum Call {
    /// [`Tasks::reflect`].
    Reflect { wo: Vec3, n: Vec3 },
    /// [`Tasks::refract`].
    Refract {
        wi: Vec3,
        n: Vec3,
        eta_i: f32,
        eta_t: f32,
    },
    /// [`Tasks::critical_angle`].
    CriticalAngle { eta_i: f64, eta_t: f64 },
    /// [`Tasks::refract_stack`].
    RefractStack { theta_deg: f64, stack: StackInput },
    /// [`Tasks::schlick_r0`].
    SchlickR0 { eta_i: f32, eta_t: f32 },
    /// [`Tasks::fresnel_schlick`].
    FresnelSchlick {
        cos_theta_i: f32,
        eta_i: f32,
        eta_t: f32,
    },
    /// [`Tasks::cosine_pdf`].
    CosinePdf { w: Vec3 },
    /// [`Tasks::smith_g1`].
    SmithG1 { w: Vec3, alpha: f32 },
    /// [`Tasks::cook_torrance`].
    CookTorrance {
        wo: Vec3,
        wi: Vec3,
        alpha_x: f32,
        alpha_y: f32,
        f0: Vec3,
    },
    /// [`Tasks::aniso_ndf`].
    AnisoNdf { h: Vec3, alpha_x: f32, alpha_y: f32 },
    /// [`Tasks::phong`].
    Phong {
        wo: Vec3,
        wi: Vec3,
        params: PhongParams,
    },
    /// [`Tasks::reciprocity_gap`] of a [`TestBrdf`], with a sampler seeded by `seed`.
    ReciprocityGap {
        brdf: TestBrdf,
        seed: u64,
        pairs: usize,
    },
    /// [`Tasks::kajiya_kay`].
    KajiyaKay {
        wo: Vec3,
        wi: Vec3,
        tangent: Vec3,
        params: KajiyaKayParams,
    },
    /// [`Tasks::beckmann_ndf`].
    BeckmannNdf { h: Vec3, alpha: f32 },
    /// [`Tasks::ndf_pdf`].
    NdfPdf {
        wo: Vec3,
        wi: Vec3,
        alpha_x: f32,
        alpha_y: f32,
    },
    /// [`Tasks::brdf_check`] of a [`TestBrdf`], with a sampler seeded by `seed`.
    BrdfCheck {
        brdf: TestBrdf,
        seed: u64,
        samples: usize,
    },
    /// A sampler's warp against its own pdf at each of `points`: the solid angle its
    /// directions sweep per unit area of the square (central differences of step `h`)
    /// times the pdf at the direction, which is 1 for a sampler that follows its pdf;
    /// NaN where the sampler rejects.
    SampleJacobian {
        sampler: SampleCall,
        points: Vec<glam::Vec2>,
        h: f32,
    },
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

impl Call {
    /// The task the called function belongs to.
    pub fn task(&self) -> TaskId {
        match self {
            Call::Reflect { .. } => TaskId::Reflect,
            Call::Refract { .. } | Call::CriticalAngle { .. } | Call::RefractStack { .. } => {
                TaskId::RefractStack
            }
            Call::SchlickR0 { .. } | Call::FresnelSchlick { .. } => TaskId::FresnelSchlick,
            Call::CosinePdf { .. } => TaskId::CosineSample,
            Call::SmithG1 { .. } => TaskId::SmithG1,
            Call::CookTorrance { .. } => TaskId::CookTorrance,
            Call::AnisoNdf { .. } => TaskId::AnisoNdf,
            Call::Phong { .. } | Call::ReciprocityGap { .. } => TaskId::Phong,
            Call::KajiyaKay { .. } => TaskId::KajiyaKay,
            Call::BeckmannNdf { .. } => TaskId::BeckmannNdf,
            Call::NdfPdf { .. } => TaskId::NdfSample,
            Call::BrdfCheck { .. } => TaskId::BrdfCheck,
            Call::SampleJacobian { sampler, .. } => sampler.task(),
        }
    }

    /// The call with its random numbers drawn from another stream, the `k`-th: `None` for a
    /// call that draws none.
    pub fn reseeded(&self, k: u64) -> Option<Call> {
        let mut call = self.clone();
        match &mut call {
            Call::ReciprocityGap { seed, .. } | Call::BrdfCheck { seed, .. } => {
                *seed = seed.wrapping_add(k.wrapping_mul(0x9e37_79b9_7f4a_7c15));
                Some(call)
            }
            _ => None,
        }
    }

    /// Calls the function on `t` and converts its result.
    pub fn eval(&self, t: &impl Tasks) -> Output {
        match self {
            Call::Reflect { wo, n } => t.reflect(*wo, *n).into_output(),
            Call::Refract {
                wi,
                n,
                eta_i,
                eta_t,
            } => t.refract(*wi, *n, *eta_i, *eta_t).into_output(),
            Call::CriticalAngle { eta_i, eta_t } => t.critical_angle(*eta_i, *eta_t).into_output(),
            Call::RefractStack { theta_deg, stack } => {
                t.refract_stack(*theta_deg, &stack.to_stack()).into_output()
            }
            Call::SchlickR0 { eta_i, eta_t } => t.schlick_r0(*eta_i, *eta_t).into_output(),
            Call::FresnelSchlick {
                cos_theta_i,
                eta_i,
                eta_t,
            } => t
                .fresnel_schlick(*cos_theta_i, *eta_i, *eta_t)
                .into_output(),
            Call::CosinePdf { w } => t.cosine_pdf(*w).into_output(),
            Call::SmithG1 { w, alpha } => t.smith_g1(*w, *alpha).into_output(),
            Call::CookTorrance {
                wo,
                wi,
                alpha_x,
                alpha_y,
                f0,
            } => t
                .cook_torrance(*wo, *wi, *alpha_x, *alpha_y, *f0)
                .into_output(),
            Call::AnisoNdf {
                h,
                alpha_x,
                alpha_y,
            } => t.aniso_ndf(*h, *alpha_x, *alpha_y).into_output(),
            Call::Phong { wo, wi, params } => t.phong(*wo, *wi, params).into_output(),
            Call::ReciprocityGap { brdf, seed, pairs } => {
                let f = |wi: Vec3, wo: Vec3| brdf.eval(wi, wo);
                let mut sampler = Sampler::new(*seed, 0);
                t.reciprocity_gap(&f, &mut sampler, *pairs).into_output()
            }
            Call::KajiyaKay {
                wo,
                wi,
                tangent,
                params,
            } => t.kajiya_kay(*wo, *wi, *tangent, params).into_output(),
            Call::BeckmannNdf { h, alpha } => t.beckmann_ndf(*h, *alpha).into_output(),
            Call::NdfPdf {
                wo,
                wi,
                alpha_x,
                alpha_y,
            } => t.ndf_pdf(*wo, *wi, *alpha_x, *alpha_y).into_output(),
            Call::BrdfCheck {
                brdf,
                seed,
                samples,
            } => {
                let f = |wi: Vec3, wo: Vec3| brdf.eval(wi, wo);
                let mut sampler = Sampler::new(*seed, 0);
                t.brdf_check(&f, &mut sampler, *samples).into_output()
            }
            Call::SampleJacobian { sampler, points, h } => {
                let ratios = points
                    .iter()
                    .map(|&u| sampler.jacobian_times_pdf(t, u, *h).unwrap_or(f64::NAN))
                    .collect();
                Output::Numbers(ratios)
            }
        }
    }
}

/// An input exactly as the function received it (the shortest text that reads back to the
/// same number), so a student can paste a failing case into a test: `0.99999994`, `1e-7`.
fn n(x: impl Into<f64>) -> String {
    let x: f64 = x.into();
    if (x as f32) as f64 == x {
        format!("{:?}", x as f32)
    } else {
        format!("{x:?}")
    }
}

/// A vector input, exactly: `(0.6, -0.8, 0.0)`.
fn exact_vec(w: Vec3) -> String {
    format!("({}, {}, {})", n(w.x), n(w.y), n(w.z))
}

impl fmt::Display for Call {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = |w: &Vec3| exact_vec(*w);
        match self {
            Call::Reflect { wo, n } => write!(f, "reflect(wo={}, n={})", v(wo), v(n)),
            Call::Refract {
                wi,
                n: normal,
                eta_i,
                eta_t,
            } => write!(
                f,
                "refract(wi={}, n={}, {}→{})",
                v(wi),
                v(normal),
                n(*eta_i),
                n(*eta_t)
            ),
            Call::CriticalAngle { eta_i, eta_t } => {
                write!(f, "critical_angle({}→{})", n(*eta_i), n(*eta_t))
            }
            Call::RefractStack { theta_deg, stack } => {
                let slabs: Vec<String> = stack
                    .slabs
                    .iter()
                    .map(|(eta, d)| format!("{} [d={}]", n(*eta), n(*d)))
                    .collect();
                write!(
                    f,
                    "refract_stack(θ={}°, {}→{}→{}, I={})",
                    n(*theta_deg),
                    n(stack.eta_incident),
                    slabs.join("→"),
                    n(stack.eta_exit),
                    n(stack.intensity)
                )
            }
            Call::SchlickR0 { eta_i, eta_t } => {
                write!(f, "schlick_r0({}→{})", n(*eta_i), n(*eta_t))
            }
            Call::FresnelSchlick {
                cos_theta_i,
                eta_i,
                eta_t,
            } => write!(
                f,
                "fresnel_schlick(cos={}, {}→{})",
                n(*cos_theta_i),
                n(*eta_i),
                n(*eta_t)
            ),
            Call::CosinePdf { w } => write!(f, "cosine_pdf(w={})", v(w)),
            Call::SmithG1 { w, alpha } => {
                write!(
                    f,
                    "smith_g1(w={} [cos θ={}], α={})",
                    v(w),
                    n(w.z),
                    n(*alpha)
                )
            }
            Call::CookTorrance {
                wo,
                wi,
                alpha_x,
                alpha_y,
                f0,
            } => write!(
                f,
                "cook_torrance(wo={}, wi={}, αx={}, αy={}, f0={})",
                v(wo),
                v(wi),
                n(*alpha_x),
                n(*alpha_y),
                v(f0)
            ),
            Call::AnisoNdf {
                h,
                alpha_x,
                alpha_y,
            } => write!(
                f,
                "aniso_ndf(h={}, αx={}, αy={})",
                v(h),
                n(*alpha_x),
                n(*alpha_y)
            ),
            Call::Phong { wo, wi, params } => write!(
                f,
                "phong(wo={}, wi={}, kd={}, ks={}, n={})",
                v(wo),
                v(wi),
                v(&params.kd),
                v(&params.ks),
                n(params.exponent)
            ),
            Call::ReciprocityGap { brdf, seed, pairs } => write!(
                f,
                "reciprocity_gap({}, pairs={pairs}, seed={seed})",
                brdf.describe()
            ),
            Call::KajiyaKay {
                wo,
                wi,
                tangent,
                params,
            } => write!(
                f,
                "kajiya_kay(wo={}, wi={}, t={}, kd={}, ks={}, p={})",
                v(wo),
                v(wi),
                v(tangent),
                v(&params.kd),
                v(&params.ks),
                n(params.exponent)
            ),
            Call::BeckmannNdf { h, alpha } => {
                write!(f, "beckmann_ndf(h={}, α={})", v(h), n(*alpha))
            }
            Call::NdfPdf {
                wo,
                wi,
                alpha_x,
                alpha_y,
            } => write!(
                f,
                "ndf_pdf(wo={}, wi={}, αx={}, αy={})",
                v(wo),
                v(wi),
                n(*alpha_x),
                n(*alpha_y)
            ),
            Call::BrdfCheck {
                brdf,
                seed,
                samples,
            } => write!(
                f,
                "brdf_check({}, samples={samples}, seed={seed})",
                brdf.describe()
            ),
            Call::SampleJacobian { sampler, points, h } => write!(
                f,
                "{sampler}: solid angle per unit area × pdf at {} points (step {})",
                points.len(),
                n(*h)
            ),
        }
    }
}

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
    pub fn sample(&self, t: &impl Tasks, u: glam::Vec2) -> Option<Vec3> {
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
    pub fn jacobian_times_pdf(&self, t: &impl Tasks, u: glam::Vec2, h: f32) -> Option<f64> {
        let at = |du: f32, dv: f32| {
            self.sample(t, u + glam::Vec2::new(du, dv))
                .map(|w| w.as_dvec3())
        };
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
                "ndf_sample(wo={}, αx={}, αy={})",
                fmt_vec(*wo),
                n(*alpha_x),
                n(*alpha_y)
            ),
        }
    }
}
