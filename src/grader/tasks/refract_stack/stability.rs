//! Stability cases of the `refract_stack` task: refraction, the critical angle and the
//! layer stack, exactly at and just past the critical angle in f32 and f64.

use crate::optics::{LayerStack, Slab, StackReport};
use crate::stability::case::{ANY, Case, DIRECTION};
use crate::grade::tolerance::Tolerance;
use crate::stability::expect::{Bound, Expect};
use crate::stability::inputs::{
    critical_angle_deg_f64, critical_angle_f32, direction_xz, errata_unit_vector, ulps_above_f32,
    ulps_above_f64,
};
use crate::stability::value::Value;
use crate::worksheet::{TaskId, Tasks};
use glam::Vec3;

/// A glass → air interface with no slab between, and unit incident intensity.
fn glass_to_air() -> LayerStack {
    LayerStack {
        eta_incident: 1.5,
        slabs: Vec::new(),
        eta_exit: 1.0,
        intensity: 1.0,
    }
}

/// Every number of a [`StackReport`], named by field and index; `tir_at` is −1 for `None`.
pub fn stack_report_value(r: &StackReport) -> Value {
    let mut fields = Vec::new();
    let mut push_all = |name: &str, xs: &[f64]| {
        for (i, x) in xs.iter().enumerate() {
            fields.push((format!("{name}[{i}]"), *x));
        }
    };
    push_all("theta", &r.theta);
    push_all("shift", &r.perpendicular_shift);
    push_all("offset", &r.interface_offset);
    push_all("R_schlick", &r.reflectance_schlick);
    push_all("R_exact", &r.reflectance_exact);
    fields.push(("tir_at".into(), r.tir_at.map_or(-1.0, |k| k as f64)));
    fields.push(("T_schlick".into(), r.transmitted_schlick));
    fields.push(("T_exact".into(), r.transmitted_exact));
    Value::Record(fields)
}

/// True for a unit vector within 0.1° of grazing exit along −x (the continuation of a ray
/// arriving in the x-z plane from +x, refracted to 90°).
fn is_grazing_exit(v: &Value) -> bool {
    match v {
        Value::Vector([x, y, z]) => {
            (x * x + y * y + z * z - 1.0).abs() < 1e-5 && (x + 1.0).abs() < 2e-6 && z.abs() < 2e-3
        }
        _ => false,
    }
}

/// No refraction (total internal reflection) or a grazing exit: both are right exactly at
/// the critical angle, where cos θt = 0.
fn tir_or_grazing() -> Expect {
    Expect::AnyOf(vec![
        Expect::Absent,
        Expect::Rule {
            text: "grazing unit vector ≈ (−1, 0, 0)",
            holds: is_grazing_exit,
        },
    ])
}

const CLAMP: &str = "decide TIR with sin²θt ≥ 1 and take sqrt(max(0, 1 − sin²θt)): rounding \
                     makes 1 − sin²θt slightly negative at the critical angle";

/// The cases.
pub fn cases<T: Tasks>() -> Vec<Case<T>> {
    vec![
        Case {
            task: TaskId::RefractStack,
            name: "critical_angle/glass_to_air",
            input: "eta_i = 1.5, eta_t = 1.0",
            eval: |t| t.critical_angle(1.5, 1.0).into(),
            range: ANY,
            expect: Expect::scalar((1.0f64 / 1.5).asin(), Tolerance::rel(1e-12)),
            guard: "θc = asin(eta_t / eta_i) = 41.8103149°",
        },
        Case {
            task: TaskId::RefractStack,
            name: "critical_angle/into_denser",
            input: "eta_i = 1.0, eta_t = 1.5",
            eval: |t| t.critical_angle(1.0, 1.5).into(),
            range: ANY,
            expect: Expect::Absent,
            guard: "no TIR into a denser medium: asin(1.5) is NaN, return None when eta_i ≤ eta_t",
        },
        Case {
            task: TaskId::RefractStack,
            name: "critical_angle/equal_indices",
            input: "eta_i = eta_t = 1.33",
            eval: |t| t.critical_angle(1.33, 1.33).into(),
            range: ANY,
            expect: Expect::Absent,
            guard: "equal indices never reflect totally (asin(1) = 90° is not a critical angle)",
        },
        Case {
            task: TaskId::RefractStack,
            name: "refract/at_critical_f32",
            input: "wi at θ = fl32(asin(1/1.5)) = 0.7297277, n = +z, 1.5 → 1.0",
            eval: |t| {
                let wi = direction_xz(critical_angle_f32(1.5, 1.0));
                t.refract(wi, Vec3::Z, 1.5, 1.0).into()
            },
            range: DIRECTION,
            expect: tir_or_grazing(),
            guard: CLAMP,
        },
        Case {
            task: TaskId::RefractStack,
            name: "refract/past_critical_2ulp_f32",
            input: "wi at θ = fl32(asin(1/1.5)) + 2 ulp, n = +z, 1.5 → 1.0",
            eval: |t| {
                let wi = direction_xz(ulps_above_f32(critical_angle_f32(1.5, 1.0), 2));
                t.refract(wi, Vec3::Z, 1.5, 1.0).into()
            },
            range: DIRECTION,
            expect: Expect::Absent,
            guard: CLAMP,
        },
        Case {
            task: TaskId::RefractStack,
            name: "refract/grazing_into_denser",
            input: "wi = (1, 0, 0) (grazing), n = +z, 1.0 → 1.5",
            eval: |t| t.refract(Vec3::X, Vec3::Z, 1.0, 1.5).into(),
            range: DIRECTION,
            expect: Expect::vector(
                [-1.0 / 1.5, 0.0, -(1.0f64 - 1.0 / 2.25).sqrt()],
                Tolerance::abs(1e-6),
            ),
            guard: "cos θi = 0 is valid: the ray leaves at the critical angle on the far side",
        },
        Case {
            task: TaskId::RefractStack,
            name: "refract/cos_above_one",
            input: "wi = n = the errata's f32-normalised vector (wi·n = 1.0000001), 1.0 → 1.5",
            eval: |t| {
                t.refract(errata_unit_vector(), errata_unit_vector(), 1.0, 1.5)
                    .into()
            },
            range: DIRECTION,
            expect: Expect::Near((-errata_unit_vector()).into(), Tolerance::abs(1e-6)),
            guard: "clamp cos θi to [−1, 1] before sqrt(1 − cos²θi)",
        },
        Case {
            task: TaskId::RefractStack,
            name: "refract_stack/at_critical_f64",
            input: "glass → air, θ = asin(1/1.5) in degrees (f64), intensity 1",
            eval: |t| {
                stack_report_value(
                    &t.refract_stack(critical_angle_deg_f64(1.5, 1.0), &glass_to_air()),
                )
            },
            range: ANY,
            expect: Expect::Fields(vec![
                ("T_schlick", Bound::Near(0.0, Tolerance::abs(1e-6))),
                ("T_exact", Bound::Near(0.0, Tolerance::abs(1e-6))),
            ]),
            guard: "at θc, cos θt = 0 and R = 1: nothing is transmitted",
        },
        Case {
            task: TaskId::RefractStack,
            name: "refract_stack/past_critical_2ulp_f64",
            input: "glass → air, θ = asin(1/1.5) in degrees + 2 ulp (f64), intensity 1",
            eval: |t| {
                let theta = ulps_above_f64(critical_angle_deg_f64(1.5, 1.0), 2);
                stack_report_value(&t.refract_stack(theta, &glass_to_air()))
            },
            range: ANY,
            expect: Expect::Fields(vec![
                ("tir_at", Bound::Near(0.0, Tolerance::abs(0.0))),
                ("T_schlick", Bound::Near(0.0, Tolerance::abs(0.0))),
                ("T_exact", Bound::Near(0.0, Tolerance::abs(0.0))),
            ]),
            guard: CLAMP,
        },
        Case {
            task: TaskId::RefractStack,
            name: "refract_stack/grazing_slab",
            input: "air | glass 1.5, 10 mm | air at θ = 90°",
            eval: |t| {
                let stack = LayerStack {
                    eta_incident: 1.0,
                    slabs: vec![Slab {
                        eta: 1.5,
                        thickness: 10.0,
                    }],
                    eta_exit: 1.0,
                    intensity: 1.0,
                };
                stack_report_value(&t.refract_stack(90.0, &stack))
            },
            range: ANY,
            expect: Expect::Fields(vec![
                ("shift[0]", Bound::Near(10.0, Tolerance::rel(1e-9))),
                (
                    "offset[0]",
                    Bound::Near(4.0 * 5.0f64.sqrt(), Tolerance::rel(1e-9)),
                ),
                ("T_exact", Bound::Near(0.0, Tolerance::abs(1e-9))),
            ]),
            guard: "at 90° the perpendicular shift is the whole thickness d; d tan θ2 = 8.944 mm \
                    is the offset along the interface",
        },
    ]
}
