//! One call of a task function with concrete inputs: what a value case stores, evaluates
//! and prints in messages.

use super::output::{IntoOutput, Output, fmt_num};
use super::test_brdf::TestBrdf;
use crate::bsdf::{KajiyaKayParams, PhongParams};
use crate::optics::{LayerStack, Slab};
use crate::sampling::Sampler;
use crate::worksheet::{TaskId, Tasks};
use glam::{DVec3, Vec3};
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

/// How many f32 ulps [`Call::jitters`] moves an input at most: the rounding a correct
/// implementation may introduce in the quantities it derives from its inputs.
pub const JITTER_ULPS: f64 = 4.0;

/// The smallest positive (subnormal) f32, 2^-149.
const SMALLEST_SUBNORMAL: f64 = 1.401_298_464_324_817e-45;

/// The inputs that are directions: [`Call::jitters`] also turns them a little.
const DIRECTIONS: [&str; 6] = ["w", "wo", "wi", "h", "n", "tangent"];

/// The largest angle (radians) by which [`Call::jitters`] turns a direction: what an
/// angle computed from a cosine or sine within `JITTER_ULPS` ulps of 1 may be off,
/// `sqrt(2 · 4 ε)`.
const MAX_TURN: f64 = 9.8e-4;

/// A uniform number in [0, 1) from `seed` and `salt`: the same pair, the same number.
fn hash_unit(seed: u64, salt: u64) -> f64 {
    let mut h = seed ^ salt.wrapping_mul(0x9e37_79b9_7f4a_7c15);
    h ^= h >> 29;
    h = h.wrapping_mul(0xbf58_476d_1ce4_e5b9);
    h ^= h >> 32;
    h = h.wrapping_mul(0x94d0_49bb_1331_11eb);
    h ^= h >> 31;
    (h >> 11) as f64 / (1u64 << 53) as f64
}

impl Call {
    /// Copies of the call with its inputs moved within what a correct f32 implementation may
    /// lose to rounding, to measure how far correct answers can lie from the reference's:
    /// - every real input by up to [`JITTER_ULPS`] ulps, by a factor that depends only on
    ///   `seed` and the value, so equal inputs stay equal (equal indices, `αx = αy`) and
    ///   zeros stay zero; a subnormal one (a cosine of 1e-45) by up to as many of the
    ///   smallest subnormal, away from 0;
    /// - every direction turned by `JITTER_ULPS · ε / sin θ` near a pole of the local
    ///   normal or of another direction, or by `JITTER_ULPS · ε / cos θ` near the horizon
    ///   of another direction (at most `MAX_TURN`), toward that axis (landing on a pole
    ///   that close), away from it, or sideways: an implementation that goes through
    ///   `sqrt(1 − cos²)`, `acos` or `asin` (the polar form of an NDF, Snell's law by
    ///   angles) loses that much there, and a direction stored in f32 is not quite unit, so
    ///   `z` and `(x, y)` disagree near the normal; and its length stretched by up to
    ///   [`JITTER_ULPS`] ulps.
    ///
    /// Integers (seeds, counts) are kept. Returns `count` such calls, one per seed
    /// `1..=count`.
    pub fn jitters(&self, count: u64) -> Vec<Call> {
        fn walk(v: &mut serde_json::Value, seed: u64) {
            match v {
                serde_json::Value::Number(n) if n.is_f64() => {
                    let x = n.as_f64().unwrap_or(0.0);
                    let u = hash_unit(seed, x.to_bits());
                    let factor = 1.0 + (2.0 * u - 1.0) * JITTER_ULPS * f32::EPSILON as f64;
                    // A subnormal f32 has fewer digits than ulps can move: move it by up
                    // to `JITTER_ULPS` of the smallest subnormal instead, keeping its sign.
                    let moved = if x != 0.0 && x.abs() < f32::MIN_POSITIVE as f64 {
                        let step = JITTER_ULPS * SMALLEST_SUBNORMAL * u;
                        x.signum() * (x.abs() + step)
                    } else {
                        x * factor
                    };
                    if let Some(m) = serde_json::Number::from_f64(moved) {
                        *n = m;
                    }
                }
                serde_json::Value::Array(items) => items.iter_mut().for_each(|i| walk(i, seed)),
                serde_json::Value::Object(fields) => {
                    fields.values_mut().for_each(|f| walk(f, seed))
                }
                _ => {}
            }
        }
        let Ok(value) = serde_json::to_value(self) else {
            return vec![self.clone(); count as usize];
        };
        let directions: Vec<(String, DVec3)> = DIRECTIONS
            .iter()
            .filter_map(|name| {
                let v: Vec3 = serde_json::from_value(value.get(*name)?.clone()).ok()?;
                Some((name.to_string(), v.as_dvec3()))
            })
            .collect();
        let turns: Vec<Turn> = directions
            .iter()
            .enumerate()
            .filter_map(|(i, (name, v))| Turn::of(name, *v, &directions, i))
            .collect();
        (1..=count)
            .map(|seed| {
                let mut value = value.clone();
                walk(&mut value, seed);
                for (i, turn) in turns.iter().enumerate() {
                    if let Ok(turned) = serde_json::to_value(turn.sample(seed, i).as_vec3()) {
                        value[turn.name.as_str()] = turned;
                    }
                }
                serde_json::from_value(value).unwrap_or_else(|_| self.clone())
            })
            .collect()
    }
}

/// How [`Call::jitters`] turns one direction input.
struct Turn {
    /// The input's name.
    name: String,
    /// Its length, kept.
    len: f64,
    /// Its unit direction.
    d: DVec3,
    /// The axis of the worst loss (a pole, or the normal of a horizon it lies near).
    axis: DVec3,
    /// Whether that axis is a pole (toward it, a turn may land on it).
    is_pole: bool,
    /// The angle to turn by.
    angle: f64,
}

impl Turn {
    /// The turn of the direction `v` named `name`, the `i`-th of `directions`.
    fn of(name: &str, v: DVec3, directions: &[(String, DVec3)], i: usize) -> Option<Turn> {
        let len = v.length();
        if len == 0.0 {
            return None;
        }
        let d = v / len;
        let others: Vec<DVec3> = directions
            .iter()
            .enumerate()
            .filter(|(j, (_, u))| *j != i && u.length() > 0.0)
            .map(|(_, (_, u))| u.normalize())
            .collect();
        // Near a pole (of the local normal or another direction), `sqrt(1 − cos²)` and
        // `acos` lose `ε / sin θ`; near the horizon of another direction, `asin` (Snell's
        // law by angles) loses `ε / cos θ`. Neither more than `sqrt(2ε)`.
        let pole = others
            .iter()
            .copied()
            .chain([DVec3::Z])
            .map(|u| if d.dot(u) < 0.0 { -u } else { u })
            .max_by(|a, b| d.dot(*a).total_cmp(&d.dot(*b)))
            .unwrap_or(DVec3::Z);
        let to_pole = d.dot(pole).clamp(-1.0, 1.0).acos();
        let horizon = others
            .iter()
            .copied()
            .min_by(|a, b| d.dot(*a).abs().total_cmp(&d.dot(*b).abs()));
        let ulps = JITTER_ULPS * f32::EPSILON as f64;
        let pole_turn = (ulps / to_pole.sin().max(1e-300)).min(MAX_TURN);
        let horizon_turn =
            horizon.map_or(0.0, |u| (ulps / d.dot(u).abs().max(1e-300)).min(MAX_TURN));
        let (axis, is_pole) = match horizon {
            Some(u) if horizon_turn > pole_turn && d.dot(u) >= 0.0 => (u, false),
            Some(u) if horizon_turn > pole_turn => (-u, false),
            _ => (pole, true),
        };
        Some(Turn {
            name: name.to_string(),
            len,
            d,
            axis,
            is_pole,
            angle: pole_turn.max(horizon_turn),
        })
    }

    /// The turned vector for `seed`: toward the axis (landing on a pole that close), away
    /// from it, or sideways at an azimuth from `seed` and `salt`; its length stretched by
    /// up to [`JITTER_ULPS`] ulps.
    fn sample(&self, seed: u64, salt: usize) -> DVec3 {
        let (d, axis, turn) = (self.d, self.axis, self.angle);
        let at = d.dot(axis).clamp(-1.0, 1.0).acos();
        // On the axis itself (`wi` exactly along the fibre), away is every way: pick one
        // per direction, so that directions on one line move apart. (What is left of `d`
        // off the axis there is rounding, the same for every direction on that line.)
        let off = if d.cross(axis).length() < 1e-12 {
            sideways(d, seed, salt)
        } else {
            (d - axis * d.dot(axis)).normalize()
        };
        let turned = match seed % 3 {
            1 if self.is_pole && at <= turn => axis,
            1 => axis * (at - turn).cos() + off * (at - turn).sin(),
            2 => axis * (at + turn).cos() + off * (at + turn).sin(),
            _ => d * turn.cos() + sideways(d, seed, salt) * turn.sin(),
        };
        // And stretched within rounding: an f32 direction is unit only to a few ulps, and
        // code that normalises it and code that does not differ by that much (`sin θ`
        // from a dot product near ±1 by much more).
        let stretch = 1.0
            + (2.0 * hash_unit(seed, salt as u64 + 7) - 1.0) * JITTER_ULPS * f32::EPSILON as f64;
        turned * self.len * stretch
    }
}

/// A unit vector perpendicular to `d`, at an azimuth from `seed` and `salt`.
fn sideways(d: DVec3, seed: u64, salt: usize) -> DVec3 {
    let phi = std::f64::consts::TAU * hash_unit(seed, salt as u64 + 1);
    let (a, b) = d.any_orthonormal_pair();
    a * phi.cos() + b * phi.sin()
}

/// A vector for messages: `(0.6, -0.8, 0)`.
pub fn fmt_vec(v: Vec3) -> String {
    format!(
        "({}, {}, {})",
        fmt_num(v.x as f64),
        fmt_num(v.y as f64),
        fmt_num(v.z as f64)
    )
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
