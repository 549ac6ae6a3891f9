//! Stability cases of the `mis` task: a delta BSDF, light samples that arrive edge-on
//! (cos θ at the light = 0, so the solid-angle pdf is infinite) and a shading point on the
//! light itself (distance → 0).

use crate::integrator::Heuristic;
use crate::sampling::Sampler;
use crate::stability::case::{ANY, Case};
use crate::grade::tolerance::Tolerance;
use crate::stability::expect::{Bound, Expect};
use crate::stability::scenes::{self, LIGHT_IN_THE_FLOOR_PLANE, MIRROR_UNDER_LIGHT, ON_THE_LIGHT};
use crate::stability::summary::max_nan;
use crate::stability::value::Value;
use crate::worksheet::{TaskId, Tasks};
use glam::Vec3;

/// Calls of `mis` per case, each with its own random stream.
const RUNS: u64 = 64;

/// Shades the point the ray from (0, 0, 1) along −z hits, towards wo = +z, `RUNS` times
/// with the power heuristic. Reports the mean radiance (NaN if any run gave one) and the
/// largest bounce weight (0 when no run continued).
fn shade_origin<T: Tasks>(t: &T, body: &str) -> Value {
    let scene = scenes::load(body);
    let (_, hit) = scenes::hit(&scene, Vec3::Z, -Vec3::Z);
    let (mut sum, mut bounce) = (Vec3::ZERO, 0.0f64);
    for stream in 0..RUNS {
        let mut sampler = Sampler::new(17, stream);
        let direct = t.mis(&scene, &hit, Vec3::Z, Heuristic::Power, &mut sampler);
        sum += direct.radiance;
        if let Some(b) = direct.bounce {
            bounce = max_nan(bounce, b.weight.max_element() as f64);
            if b.weight.is_nan() {
                bounce = f64::NAN;
            }
        }
    }
    let mean = sum / RUNS as f32;
    Value::record([
        ("L.r", mean.x as f64),
        ("L.g", mean.y as f64),
        ("L.b", mean.z as f64),
        ("max_bounce_weight", bounce),
    ])
}

fn radiance_is(value: f64, tol: Tolerance) -> Expect {
    Expect::Fields(vec![
        ("L.r", Bound::Near(value, tol)),
        ("L.g", Bound::Near(value, tol)),
        ("L.b", Bound::Near(value, tol)),
        ("max_bounce_weight", Bound::Within(0.0, 1.0)),
    ])
}

/// The cases.
pub fn cases<T: Tasks>() -> Vec<Case<T>> {
    vec![
        Case {
            task: TaskId::Mis,
            name: "mis/delta_bsdf",
            input: "mirror (reflectance 0.9) at the origin, wo = +z, its mirror direction hits a \
                    light of radiance 5",
            eval: |t| shade_origin(t, MIRROR_UNDER_LIGHT),
            range: ANY,
            expect: radiance_is(4.5, Tolerance::rel(1e-5)),
            guard: "a delta lobe has no pdf: skip the light sample and give the BSDF sample \
                    weight 1 (pdf_bsdf = ∞ or 0 in a heuristic gives NaN or drops the light)",
        },
        Case {
            task: TaskId::Mis,
            name: "mis/light_edge_on",
            input: "diffuse floor in z = 0, a quad light beside it in the same plane",
            eval: |t| shade_origin(t, LIGHT_IN_THE_FLOOR_PLANE),
            range: ANY,
            expect: radiance_is(0.0, Tolerance::abs(0.0)),
            guard: "cos θ at the light = 0 makes p_ω = p_A d²/cos θ infinite: skip samples with \
                    cos θl ≤ 0 before converting the pdf",
        },
        Case {
            task: TaskId::Mis,
            name: "mis/shading_point_on_the_light",
            input: "a diffuse quad light shaded at one of its own points",
            eval: |t| shade_origin(t, ON_THE_LIGHT),
            range: ANY,
            expect: radiance_is(0.0, Tolerance::abs(0.0)),
            guard: "light samples in the shading point's own plane (distance → 0, both cosines \
                    0) contribute 0: guard d² > 0 and cos θl > 0",
        },
    ]
}
