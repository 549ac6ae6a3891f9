// The variants of `phong` the tests grade the grader with (see `src/grader/tasks/mod.rs`).
// `tests/instructor/support/variants.rs` includes this file into a module of the tests,
// so it has no inner attributes or doc; the student handout leaves it out.

use crate::support::patch::{Variant, variant};
use crate::support::variants::Naive;
use crate::support::warps::cosine_direction;
use glam::Vec3;
use pbrlab::bsdf::PhongParams;
use pbrlab::sampling::{Sampler, uniform_hemisphere};
use pbrlab::stability::Verdict;
use pbrlab::worksheet::{TaskId, Tasks};
use pbrlab_solutions as sol;
use std::f32::consts::{FRAC_1_PI, PI, TAU};

/// Known-wrong implementations of `phong`: each must fail this task and no other.
pub fn wrong() -> Vec<Variant> {
    use TaskId::*;
    vec![
        variant("NaN-prone pow of a negative cosine", Phong, |p| {
            p.phong = Some(|t, wo, wi, params| {
                if wo.z <= 0.0 || wi.z <= 0.0 {
                    return Vec3::ZERO;
                }
                let r = t.reflect(wi, Vec3::Z);
                let lobe = r.dot(wo).powf(params.exponent);
                params.kd * FRAC_1_PI
                    + params.ks * ((params.exponent + 2.0) * 0.5 * FRAC_1_PI * lobe)
            })
        }),
        variant("normalisation (n+1)/(2π)", Phong, |p| {
            p.phong = Some(|t, wo, wi, params| {
                let mut q = *params;
                q.ks *= (params.exponent + 1.0) / (params.exponent + 2.0);
                sol::phong::phong(t, wo, wi, &q)
            })
        }),
        variant("Phong shading model (divides by cos θi)", Phong, |p| {
            p.phong = Some(|t, wo, wi, params| {
                let mut q = *params;
                q.kd = Vec3::ZERO;
                let lobe = sol::phong::phong(t, wo, wi, &q) / wi.z.max(1e-6);
                params.kd * FRAC_1_PI + lobe
            })
        }),
        variant(
            "reciprocity gap without the relative scale, averaged",
            Phong,
            |p| {
                p.reciprocity_gap = Some(|brdf, sampler, pairs| {
                    let mut sum = 0.0;
                    for _ in 0..pairs {
                        let a = uniform_hemisphere(sampler.next_2d());
                        let b = uniform_hemisphere(sampler.next_2d());
                        sum += (brdf(a, b) - brdf(b, a)).abs() * 1e-3;
                    }
                    sum / pairs.max(1) as f32
                })
            },
        ),
        variant("reciprocity gap whose f32::max skips NaN", Phong, |p| {
            p.reciprocity_gap = Some(|brdf, sampler, pairs| {
                largest_pair_gap(brdf, sampler, pairs, |f_ab, f_ba| {
                    if f_ab == f_ba {
                        0.0
                    } else {
                        (f_ab - f_ba).abs() / f_ab.abs().max(f_ba.abs())
                    }
                })
            })
        }),
        variant(
            "reciprocity gap that skips a pair NaN in one order only",
            Phong,
            |p| {
                p.reciprocity_gap = Some(|brdf, sampler, pairs| {
                    largest_pair_gap(brdf, sampler, pairs, |f_ab, f_ba| {
                        if f_ab.is_nan() && f_ba.is_nan() {
                            f32::INFINITY
                        } else if f_ab == f_ba {
                            0.0
                        } else {
                            (f_ab - f_ba).abs() / f_ab.abs().max(f_ba.abs())
                        }
                    })
                })
            },
        ),
        variant(
            "reciprocity gap that calls two equal infinities reciprocal",
            Phong,
            |p| {
                p.reciprocity_gap = Some(|brdf, sampler, pairs| {
                    largest_pair_gap(brdf, sampler, pairs, |f_ab, f_ba| {
                        if f_ab == f_ba {
                            0.0
                        } else if !(f_ab.is_finite() && f_ba.is_finite()) {
                            f32::INFINITY
                        } else {
                            (f_ab - f_ba).abs() / f_ab.abs().max(f_ba.abs())
                        }
                    })
                })
            },
        ),
        variant(
            "reciprocity gap relative to the smaller value",
            Phong,
            |p| {
                p.reciprocity_gap = Some(|brdf, sampler, pairs| {
                    largest_pair_gap(brdf, sampler, pairs, |f_ab, f_ba| {
                        if !(f_ab.is_finite() && f_ba.is_finite()) {
                            f32::INFINITY
                        } else if f_ab == f_ba {
                            0.0
                        } else {
                            (f_ab - f_ba).abs() / f_ab.abs().min(f_ba.abs())
                        }
                    })
                })
            },
        ),
        variant("absolute reciprocity gap", Phong, |p| {
            p.reciprocity_gap = Some(|brdf, sampler, pairs| {
                let mut gap = 0.0f32;
                for _ in 0..pairs {
                    let a = uniform_hemisphere(sampler.next_2d());
                    let b = uniform_hemisphere(sampler.next_2d());
                    let d = (brdf(a, b) - brdf(b, a)).abs();
                    gap = if d.is_nan() { d } else { gap.max(d) };
                }
                gap
            })
        }),
    ]
}

/// Correct implementations of `phong` that differ from the reference: each gets full marks.
pub fn different() -> Vec<Variant> {
    use TaskId::*;
    vec![variant(
        "Phong with the mirror computed inline and a cosine-sampled reciprocity test",
        Phong,
        |p| {
            p.phong = Some(|_, wo, wi, params| {
                if wo.z <= 0.0 || wi.z <= 0.0 {
                    return Vec3::ZERO;
                }
                let r = Vec3::new(-wi.x, -wi.y, wi.z);
                let c = r.dot(wo);
                let lobe = if c > 0.0 {
                    c.powf(params.exponent)
                } else {
                    0.0
                };
                params.kd / PI + params.ks * (params.exponent + 2.0) / TAU * lobe
            });
            p.reciprocity_gap = Some(|brdf, sampler, pairs| {
                let mut gap = 0.0f32;
                for _ in 0..pairs {
                    let a = cosine_direction(sampler.next_2d());
                    let b = cosine_direction(sampler.next_2d());
                    let (x, y) = (brdf(a, b), brdf(b, a));
                    let scale = x.abs().max(y.abs());
                    if !(x.is_finite() && y.is_finite()) {
                        return f32::INFINITY;
                    }
                    if scale > 0.0 {
                        gap = gap.max((x - y).abs() / scale);
                    }
                }
                gap
            });
        },
    )]
    .into_iter()
    .chain(other_arithmetic())
    .collect()
}

/// Correct implementations of `phong` in other arithmetic (f64, other algebraic forms):
/// each gets full marks, whatever its rounding.
fn other_arithmetic() -> Vec<Variant> {
    use TaskId::*;
    vec![variant("Phong in f64 throughout", Phong, |p| {
        p.phong = Some(|_, wo, wi, params| {
            if wo.z <= 0.0 || wi.z <= 0.0 {
                return Vec3::ZERO;
            }
            let (wo, wi) = (wo.as_dvec3(), wi.as_dvec3());
            let mirror = glam::DVec3::new(-wi.x, -wi.y, wi.z);
            let e = f64::from(params.exponent);
            let lobe = mirror.dot(wo).max(0.0).powf(e);
            let pi = std::f64::consts::PI;
            (params.kd.as_dvec3() / pi + params.ks.as_dvec3() * ((e + 2.0) / (2.0 * pi) * lobe))
                .as_vec3()
        })
    })]

}

/// Naive implementations of `phong` (the textbook formula without its guards), each with
/// exactly the stability cases it must fail and the verdict of each.
pub fn naive() -> Vec<Naive> {
    use TaskId::*;
    use Verdict::*;
    vec![
        Naive::new(
            "`phong` raises an unclamped lobe cosine to the exponent",
            Phong,
            |p| {
                p.phong = Some(textbook::phong);
            },
            vec![
                ("phong/fractional_exponent_negative_lobe", NaN),
                ("phong/even_exponent_negative_lobe", WrongValue),
            ],
        ),
        Naive::new(
            "`phong` takes the power of the clamped lobe cosine as `exp(n ln x)`",
            Phong,
            |p| {
                p.phong = Some(textbook::phong_power_by_logarithm);
            },
            vec![("phong/exponent_zero_behind_the_mirror", NaN)],
        ),
        Naive::new(
            "`reciprocity_gap` divides 0 by 0 and starts its maximum at −∞",
            Phong,
            |p| {
                p.reciprocity_gap = Some(textbook::reciprocity_gap);
            },
            vec![
                ("reciprocity_gap/zero_brdf", NaN),
                ("reciprocity_gap/no_pairs", Inf),
                ("brdf_check/zero_brdf", NaN),
            ],
        ),
    ]
}

/// The largest `pair_gap(f(a,b), f(b,a))` over `pairs` pairs drawn as the exercise says, by
/// `f32::max` (which skips NaN).
fn largest_pair_gap(
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut Sampler,
    pairs: usize,
    pair_gap: impl Fn(f32, f32) -> f32,
) -> f32 {
    (0..pairs).fold(0.0f32, |gap, _| {
        let a = uniform_hemisphere(sampler.next_2d());
        let b = uniform_hemisphere(sampler.next_2d());
        gap.max(pair_gap(brdf(a, b), brdf(b, a)))
    })
}

/// The naive functions of [`naive`].
mod textbook {
    use super::*;

    /// The lobe cosine raised to the exponent without clamping it at 0.
    pub fn phong(t: &impl Tasks, wo: Vec3, wi: Vec3, params: &PhongParams) -> Vec3 {
        if wo.z <= 0.0 || wi.z <= 0.0 {
            return Vec3::ZERO;
        }
        let lobe = t.reflect(wi, Vec3::Z).dot(wo).powf(params.exponent);
        params.kd * FRAC_1_PI + params.ks * ((params.exponent + 2.0) / (2.0 * PI) * lobe)
    }

    /// The clamped lobe cosine raised to the exponent as `exp(n ln x)`: right for every
    /// exponent above 0, NaN (`0 · −∞`) behind the mirror direction at an exponent of 0.
    pub fn phong_power_by_logarithm(
        t: &impl Tasks,
        wo: Vec3,
        wi: Vec3,
        params: &PhongParams,
    ) -> Vec3 {
        if wo.z <= 0.0 || wi.z <= 0.0 {
            return Vec3::ZERO;
        }
        let cos = t.reflect(wi, Vec3::Z).dot(wo).max(0.0);
        let lobe = (params.exponent * cos.ln()).exp();
        params.kd * FRAC_1_PI + params.ks * ((params.exponent + 2.0) / (2.0 * PI) * lobe)
    }

    /// The relative gap of every pair, 0/0 included.
    pub fn reciprocity_gap(
        brdf: &dyn Fn(Vec3, Vec3) -> f32,
        sampler: &mut Sampler,
        pairs: usize,
    ) -> f32 {
        let mut gap = f32::NEG_INFINITY;
        for _ in 0..pairs {
            let a = uniform_hemisphere(sampler.next_2d());
            let b = uniform_hemisphere(sampler.next_2d());
            let (fab, fba) = (brdf(a, b), brdf(b, a));
            let g = (fab - fba).abs() / fab.abs().max(fba.abs());
            gap = if g > gap || g.is_nan() { g } else { gap };
        }
        gap
    }
}
