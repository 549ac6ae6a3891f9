//! Stability cases of the `fresnel_schlick` task: equal indices, dense to less dense, total
//! internal reflection at and past the critical angle, grazing incidence and a cosine
//! that rounds above one.

use crate::stability::case::{Case, UNIT_INTERVAL};
use crate::grade::tolerance::Tolerance;
use crate::stability::expect::Expect;
use crate::stability::inputs::{critical_angle_f32, errata_unit_vector, ulps_above_f32};
use crate::worksheet::{TaskId, Tasks};

const EQUAL: &str = "with equal indices R0 = 0 and nothing reflects: return 0, not (1 − cos θ)^5";
const TIR: &str = "going from dense to less dense use cos θt; when sin²θt ≥ 1 return 1, and \
                   clamp 1 − sin²θt at 0 before the square root";

/// The cases.
pub fn cases<T: Tasks>() -> Vec<Case<T>> {
    vec![
        Case {
            task: TaskId::FresnelSchlick,
            name: "fresnel_schlick/equal_indices_60deg",
            input: "cos θ = cos 60°, eta_i = eta_t = 1.33",
            eval: |t| {
                t.fresnel_schlick(60f32.to_radians().cos(), 1.33, 1.33)
                    .into()
            },
            range: UNIT_INTERVAL,
            expect: Expect::scalar(0.0, Tolerance::abs(1e-7)),
            guard: EQUAL,
        },
        Case {
            task: TaskId::FresnelSchlick,
            name: "fresnel_schlick/equal_indices_80deg",
            input: "cos θ = cos 80°, eta_i = eta_t = 1.33",
            eval: |t| {
                t.fresnel_schlick(80f32.to_radians().cos(), 1.33, 1.33)
                    .into()
            },
            range: UNIT_INTERVAL,
            expect: Expect::scalar(0.0, Tolerance::abs(1e-7)),
            guard: EQUAL,
        },
        Case {
            task: TaskId::FresnelSchlick,
            name: "fresnel_schlick/equal_indices_89deg",
            input: "cos θ = cos 89°, eta_i = eta_t = 1.0",
            eval: |t| t.fresnel_schlick(89f32.to_radians().cos(), 1.0, 1.0).into(),
            range: UNIT_INTERVAL,
            expect: Expect::scalar(0.0, Tolerance::abs(1e-7)),
            guard: EQUAL,
        },
        Case {
            task: TaskId::FresnelSchlick,
            name: "fresnel_schlick/dense_to_less_40deg",
            input: "cos θ = cos 40°, glass → air (1.5 → 1.0)",
            eval: |t| t.fresnel_schlick(40f32.to_radians().cos(), 1.5, 1.0).into(),
            range: UNIT_INTERVAL,
            expect: Expect::scalar(0.245_583_350_6, Tolerance::rel(1e-4)),
            guard: "from dense to less dense Schlick needs cos θt (0.245583; exact Fresnel \
                    0.245291); cos θi gives 0.040673",
        },
        Case {
            task: TaskId::FresnelSchlick,
            name: "fresnel_schlick/tir_45deg",
            input: "cos θ = cos 45°, glass → air (past θc = 41.81°)",
            eval: |t| t.fresnel_schlick(45f32.to_radians().cos(), 1.5, 1.0).into(),
            range: UNIT_INTERVAL,
            expect: Expect::scalar(1.0, Tolerance::abs(1e-6)),
            guard: TIR,
        },
        Case {
            task: TaskId::FresnelSchlick,
            name: "fresnel_schlick/at_critical_f32",
            input: "cos θ = cos(fl32(asin(1/1.5))), glass → air",
            eval: |t| {
                let cos = critical_angle_f32(1.5, 1.0).cos();
                t.fresnel_schlick(cos, 1.5, 1.0).into()
            },
            range: UNIT_INTERVAL,
            expect: Expect::scalar(1.0, Tolerance::abs(2e-3)),
            guard: TIR,
        },
        Case {
            task: TaskId::FresnelSchlick,
            name: "fresnel_schlick/past_critical_2ulp_f32",
            input: "cos θ = cos(fl32(asin(1/1.5)) + 2 ulp), glass → air",
            eval: |t| {
                let cos = ulps_above_f32(critical_angle_f32(1.5, 1.0), 2).cos();
                t.fresnel_schlick(cos, 1.5, 1.0).into()
            },
            range: UNIT_INTERVAL,
            expect: Expect::scalar(1.0, Tolerance::abs(1e-6)),
            guard: TIR,
        },
        Case {
            task: TaskId::FresnelSchlick,
            name: "fresnel_schlick/grazing",
            input: "cos θ = 0, air → glass",
            eval: |t| t.fresnel_schlick(0.0, 1.0, 1.5).into(),
            range: UNIT_INTERVAL,
            expect: Expect::scalar(1.0, Tolerance::abs(1e-6)),
            guard: "everything reflects at grazing incidence",
        },
        Case {
            task: TaskId::FresnelSchlick,
            name: "fresnel_schlick/cos_above_one_dense_to_less",
            input: "cos θ = w·w = 1.0000001 (the errata's f32 vector), glass → air",
            eval: |t| {
                let w = errata_unit_vector();
                t.fresnel_schlick(w.dot(w), 1.5, 1.0).into()
            },
            range: UNIT_INTERVAL,
            expect: Expect::scalar(0.04, Tolerance::abs(1e-6)),
            guard: "clamp cos θ to [0, 1] before sin θ = sqrt(1 − cos²θ)",
        },
        Case {
            task: TaskId::FresnelSchlick,
            name: "fresnel_schlick/cos_above_one_into_denser",
            input: "cos θ = w·w = 1.0000001 (the errata's f32 vector), air → glass",
            eval: |t| {
                let w = errata_unit_vector();
                t.fresnel_schlick(w.dot(w), 1.0, 1.5).into()
            },
            range: UNIT_INTERVAL,
            expect: Expect::scalar(0.04, Tolerance::abs(1e-6)),
            guard: "clamp cos θ to [0, 1]: (1 − cos θ)^5 must not go negative",
        },
    ]
}
