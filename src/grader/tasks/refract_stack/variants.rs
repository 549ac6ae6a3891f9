// The variants of `refract_stack` the tests grade the grader with (see `src/grader/tasks/mod.rs`).
// `tests/instructor/support/variants.rs` includes this file into a module of the tests,
// so it has no inner attributes or doc; the student handout leaves it out.

use crate::support::patch::{Variant, variant};
use crate::support::variants::Naive;
use glam::Vec3;
use pbrlab::optics::{LayerStack, StackReport, fresnel_dielectric_f64};
use pbrlab::stability::Verdict;
use pbrlab::worksheet::{TaskId, Tasks};
use pbrlab_solutions as sol;

/// Known-wrong implementations of `refract_stack`: each must fail this task and no other.
pub fn wrong() -> Vec<Variant> {
    use TaskId::*;
    vec![
        variant("no total internal reflection", RefractStack, |p| {
            p.refract = Some(|wi, n, eta_i, eta_t| {
                let (wi, n) = (wi.normalize(), n.normalize());
                let eta = eta_i / eta_t;
                let c = wi.dot(n);
                let cos_t = (1.0 - eta * eta * (1.0 - c * c)).sqrt();
                Some(-eta * wi + (eta * c - cos_t) * n)
            })
        }),
        variant(
            "critical angle without the eta_i > eta_t guard",
            RefractStack,
            |p| p.critical_angle = Some(|eta_i, eta_t| Some((eta_t / eta_i).asin())),
        ),
        variant(
            "lateral shift taken as d tan θ (the worksheet)",
            RefractStack,
            |p| {
                p.refract_stack = Some(|t, theta, stack| {
                    let mut r = sol::refract_stack::refract_stack(t, theta, stack);
                    r.perpendicular_shift = r.interface_offset.clone();
                    r
                })
            },
        ),
        variant(
            "transmitted intensity ignores the last interface",
            RefractStack,
            |p| {
                p.refract_stack = Some(|t, theta, stack| {
                    let mut r = sol::refract_stack::refract_stack(t, theta, stack);
                    if r.tir_at.is_none() {
                        let last = *r.reflectance_exact.last().unwrap_or(&0.0);
                        r.transmitted_exact /= 1.0 - last;
                    }
                    r
                })
            },
        ),
    ]
}

/// Correct implementations of `refract_stack` that differ from the reference: each gets full marks.
pub fn different() -> Vec<Variant> {
    use TaskId::*;
    vec![
        variant(
            "refraction by angles (asin, then rotate)",
            RefractStack,
            |p| {
                p.refract = Some(|wi, n, eta_i, eta_t| {
                    let (wi, n) = (wi.normalize(), n.normalize());
                    let cos_i = wi.dot(n).clamp(-1.0, 1.0);
                    let sin_t = eta_i / eta_t * (1.0 - cos_i * cos_i).max(0.0).sqrt();
                    if sin_t >= 1.0 {
                        return None;
                    }
                    let tangent = wi - cos_i * n;
                    let tangent = if tangent.length_squared() > 0.0 {
                        tangent.normalize()
                    } else {
                        Vec3::ZERO
                    };
                    let theta_t = sin_t.asin();
                    Some((-tangent * theta_t.sin() - n * theta_t.cos()).normalize())
                })
            },
        ),
        variant(
            "layer stack interface by interface (Snell step by step)",
            RefractStack,
            |p| {
                p.refract_stack = Some(|t, theta_deg, stack| {
                    let etas = stack.etas();
                    let mut r = StackReport {
                        theta: vec![theta_deg],
                        ..StackReport::default()
                    };
                    let (mut i_s, mut i_e) = (stack.intensity, stack.intensity);
                    for k in 0..etas.len() - 1 {
                        let theta_in = r.theta[k].to_radians();
                        let sin_t = etas[k] / etas[k + 1] * theta_in.sin();
                        let cos_in = theta_in.cos();
                        let rs =
                            t.fresnel_schlick(cos_in as f32, etas[k] as f32, etas[k + 1] as f32)
                                as f64;
                        r.reflectance_schlick.push(rs);
                        r.reflectance_exact.push(fresnel_dielectric_f64(
                            cos_in,
                            etas[k],
                            etas[k + 1],
                        ));
                        if sin_t >= 1.0 {
                            r.tir_at = Some(k);
                            i_s = 0.0;
                            i_e = 0.0;
                            break;
                        }
                        i_s *= 1.0 - rs;
                        i_e *= 1.0 - r.reflectance_exact[k];
                        let theta_t = sin_t.asin();
                        r.theta.push(theta_t.to_degrees());
                        if k < stack.slabs.len() {
                            let d = stack.slabs[k].thickness;
                            r.perpendicular_shift
                                .push(d * (theta_in - theta_t).sin() / theta_t.cos());
                            r.interface_offset.push(d * theta_t.tan());
                        }
                    }
                    r.transmitted_schlick = i_s;
                    r.transmitted_exact = i_e;
                    r
                })
            },
        ),
    ]
    .into_iter()
    .chain(other_arithmetic())
    .collect()
}

/// Correct implementations of `refract_stack` in other arithmetic (f64, other algebraic forms):
/// each gets full marks, whatever its rounding.
fn other_arithmetic() -> Vec<Variant> {
    use TaskId::*;
    vec![variant("refraction in f64 throughout", RefractStack, |p| {
        p.refract = Some(|wi, n, eta_i, eta_t| {
            let wi = wi.as_dvec3().normalize();
            let mut n = n.as_dvec3().normalize();
            let mut cos_i = wi.dot(n);
            if cos_i < 0.0 {
                n = -n;
                cos_i = -cos_i;
            }
            let cos_i = cos_i.min(1.0);
            let eta = f64::from(eta_i) / f64::from(eta_t);
            let sin2_t = eta * eta * (1.0 - cos_i * cos_i).max(0.0);
            if sin2_t >= 1.0 {
                return None;
            }
            let cos_t = (1.0 - sin2_t).sqrt();
            Some((-eta * wi + (eta * cos_i - cos_t) * n).normalize().as_vec3())
        })
    })]

}

/// Naive implementations of `refract_stack` (the textbook formula without its guards), each with
/// exactly the stability cases it must fail and the verdict of each.
pub fn naive() -> Vec<Naive> {
    use TaskId::*;
    use Verdict::*;
    vec![
        Naive::new(
            "`refract`, `refract_stack` and `fresnel_schlick` by Snell's law with no test for \
             total internal reflection (an unclamped square root at and past θc)",
            RefractStack,
            |p| {
                p.refract = Some(textbook::refract);
                p.refract_stack = Some(textbook::refract_stack);
                p.fresnel_schlick = Some(textbook::fresnel_schlick_unguarded);
            },
            vec![
                ("refract/at_critical_f32", NaN),
                ("refract/past_critical_2ulp_f32", NaN),
                ("refract_stack/past_critical_2ulp_f64", NaN),
                // The f32 Schlick inside the stack meets the critical angle too: at θc
                // itself, and where a ray that entered the slab at 90° leaves it.
                ("refract_stack/at_critical_f64", NaN),
                ("refract_stack/grazing_slab", NaN),
                ("fresnel_schlick/tir_45deg", NaN),
                ("fresnel_schlick/at_critical_f32", NaN),
                ("fresnel_schlick/past_critical_2ulp_f32", NaN),
            ],
        ),
        Naive::new(
            "`critical_angle` returns asin(eta_t/eta_i) for every pair",
            RefractStack,
            |p| {
                p.critical_angle = Some(textbook::critical_angle);
            },
            vec![
                ("critical_angle/into_denser", NaN),
                ("critical_angle/equal_indices", WrongValue),
            ],
        ),
    ]
}

/// The naive functions of [`naive`].
mod textbook {
    use super::*;

    /// Snell's law with no test for total internal reflection: the square root takes whatever
    /// 1 − sin²θt comes out as.
    pub fn refract(wi: Vec3, n: Vec3, eta_i: f32, eta_t: f32) -> Option<Vec3> {
        let n = n.normalize();
        let eta = eta_i / eta_t;
        let cos_i = wi.dot(n);
        let cos_t = (1.0 - eta * eta * (1.0 - cos_i * cos_i)).sqrt();
        Some(-eta * wi + (eta * cos_i - cos_t) * n)
    }

    /// asin of the ratio, whatever the ratio.
    pub fn critical_angle(eta_i: f64, eta_t: f64) -> Option<f64> {
        Some((eta_t / eta_i).asin())
    }

    /// The stack followed with Snell's law and no test for total internal reflection.
    pub fn refract_stack(t: &impl Tasks, theta_deg: f64, stack: &LayerStack) -> StackReport {
        let etas = stack.etas();
        let invariant = etas[0] * theta_deg.to_radians().sin();
        let mut r = StackReport {
            theta: vec![theta_deg],
            ..StackReport::default()
        };
        let (mut schlick, mut exact) = (stack.intensity, stack.intensity);
        for k in 0..stack.interfaces() {
            let sin_t = invariant / etas[k + 1];
            let cos_t = (1.0 - sin_t * sin_t).sqrt();
            let cos_i = r.theta[k].to_radians().cos();
            let rs = t.fresnel_schlick(cos_i as f32, etas[k] as f32, etas[k + 1] as f32) as f64;
            let re = fresnel_dielectric_f64(cos_i, etas[k], etas[k + 1]);
            r.reflectance_schlick.push(rs);
            r.reflectance_exact.push(re);
            schlick *= 1.0 - rs;
            exact *= 1.0 - re;
            let theta_t = cos_t.acos();
            if let Some(slab) = stack.slabs.get(k) {
                let theta_in = r.theta[k].to_radians();
                r.perpendicular_shift
                    .push(slab.thickness * (theta_in - theta_t).sin() / cos_t);
                r.interface_offset.push(slab.thickness * theta_t.tan());
            }
            r.theta.push(theta_t.to_degrees());
        }
        r.transmitted_schlick = schlick;
        r.transmitted_exact = exact;
        r
    }

    /// Schlick's curve on cos θt from dense to less dense, with cos θt from an unclamped
    /// square root and no test for total internal reflection.
    pub fn fresnel_schlick_unguarded(
        t: &impl Tasks,
        cos_theta_i: f32,
        eta_i: f32,
        eta_t: f32,
    ) -> f32 {
        if eta_i == eta_t {
            return 0.0;
        }
        let r0 = t.schlick_r0(eta_i, eta_t);
        let mut cos = cos_theta_i;
        if eta_i > eta_t {
            cos = (1.0 - (eta_i / eta_t).powi(2) * (1.0 - cos * cos)).sqrt();
        }
        r0 + (1.0 - r0) * (1.0 - cos).powi(5)
    }
}
