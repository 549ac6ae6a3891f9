//! The estimators of `path_trace`: closed furnaces whose radiance is known in closed form
//! (also around lossless glass and mirror objects, which a correct tracer renders
//! invisible), in the configurations where Russian roulette can go wrong (a survival probability that
//! is exactly 1/2 hides an inverted test; a bounce weight above 1 needs the probability
//! capped), and a floor under a sky, where a path that escapes after a bounce must not add
//! the sky that `mis` already counted.

use super::EstimatorSpec;
use crate::geometry::Ray;
use crate::grade::power::Declared;
use crate::integrator::Segment;
use crate::sampling::{Sampler, uniform_sphere};
use crate::scene::{LoadOptions, Scene};
use crate::worksheet::Tasks;
use glam::Vec3;
use std::path::Path;

/// What the estimator and sampling checks of this task catch in at least 90 % of
/// gradings, as measured by `pbrlab power` (asserted by tests/instructor/power.rs).
pub const POWER: Declared = Declared {
    estimator_bias: Some(0.005),
    sampler_distortion: None,
};

/// Radiance the furnace walls emit, and the sky's radiance.
const EMISSION: f64 = 1.0;

/// A closed box whose six walls face inwards, each diffuse with `albedo` and emitting
/// radiance [`EMISSION`]: every point inside sees `Le Σ_{k<D} ρ^k` for paths of at most
/// `D` segments, `Le / (1 − ρ)` unbounded.
fn furnace(albedo: f64, render: &str) -> Scene {
    furnace_around(albedo, render, None)
}

/// [`furnace`] with a sphere of the lossless material `material` (YAML) inside, off the
/// centre: a lossless object in a uniform radiance field reflects and transmits that same
/// radiance, so the field stays `Le / (1 − ρ)` everywhere outside it, whatever its BSDF
/// (the furnace test of delta and refractive lobes).
fn furnace_around(albedo: f64, render: &str, inside: Option<&str>) -> Scene {
    let walls = [
        "[-1, -1, -1], edge1: [0, 0, 2], edge2: [2, 0, 0]",
        "[-1, 1, -1], edge1: [2, 0, 0], edge2: [0, 0, 2]",
        "[-1, -1, -1], edge1: [0, 2, 0], edge2: [0, 0, 2]",
        "[1, -1, -1], edge1: [0, 0, 2], edge2: [0, 2, 0]",
        "[-1, -1, -1], edge1: [2, 0, 0], edge2: [0, 2, 0]",
        "[-1, -1, 1], edge1: [0, 2, 0], edge2: [2, 0, 0]",
    ];
    let mut text = format!(
        "camera: {{eye: [0, 0, 0], target: [0, 0, -1], up: [0, 1, 0], fov: 60, width: 4, height: 4}}
render: {render}
materials:
  wall: {{diffuse: {{albedo: {albedo}}}}}
{object}shapes:
{sphere}",
        object = inside.map_or(String::new(), |m| format!("  object: {m}\n")),
        sphere = if inside.is_some() {
            "  - sphere: {center: [0, 0, -0.5], radius: 0.4, material: object}\n"
        } else {
            ""
        },
    );
    for wall in walls {
        text += &format!("  - quad: {{origin: {wall}, material: wall, emission: {EMISSION}}}\n");
    }
    load(&text, "<grader furnace>")
}

/// A diffuse floor of `albedo`, 20 × 20 around the origin, under a sky of radiance
/// [`EMISSION`]: a flat floor sees only the sky, so the floor's radiance is `ρ Le` exactly,
/// however many bounces are allowed.
fn floor_under_sky(albedo: f64, render: &str) -> Scene {
    let text = format!(
        "camera: {{eye: [0, 0, 1], target: [0, 0, 0], up: [0, 1, 0], fov: 60, width: 4, height: 4}}
render: {render}
materials:
  floor: {{diffuse: {{albedo: {albedo}}}}}
shapes:
  - quad: {{origin: [-10, -10, 0], edge1: [20, 0, 0], edge2: [0, 20, 0], material: floor}}
lights:
  - environment: {{radiance: {EMISSION}}}
"
    );
    load(&text, "<grader floor under a sky>")
}

fn load(text: &str, name: &str) -> Scene {
    Scene::from_yaml(Path::new(name), text, &LoadOptions::default())
        .unwrap_or_else(|e| panic!("the grader's scene {name} is valid: {e}"))
}

/// The radiance along one ray from `origin` in a direction drawn by `direction`; the
/// estimate is the mean of the three (equal) channels.
fn path_estimator<'a, T: Tasks>(
    t: &'a T,
    scene: Scene,
    origin: Vec3,
    direction: fn(&mut Sampler) -> Vec3,
) -> Box<super::super::estimator::Estimator<'a>> {
    let depth = scene.settings().max_depth;
    Box::new(move |s: &mut Sampler| {
        let ray = Ray::new(origin, direction(s));
        let segment = Segment {
            ray,
            hit: scene.intersect(&ray),
            emission_counted: false,
        };
        let l = t.path_trace(&scene, &segment, depth, s);
        Ok(l.element_sum() as f64 / 3.0)
    })
}

/// A path from the furnace's centre in a uniformly random direction.
fn furnace_spec<'a, T: Tasks>(
    t: &'a T,
    name: &str,
    albedo: f64,
    render: &str,
    analytic: f64,
) -> EstimatorSpec<'a> {
    EstimatorSpec {
        name: name.into(),
        analytic,
        samples: 40_000,
        estimate: path_estimator(t, furnace(albedo, render), Vec3::ZERO, |s| {
            uniform_sphere(s.next_2d())
        }),
    }
}

/// A path from the centre of a furnace with a lossless sphere of `material` inside.
fn lossless_spec<'a, T: Tasks>(t: &'a T, name: &str, material: &str) -> EstimatorSpec<'a> {
    let render = "{spp: 1, max_depth: ~, rr_depth: 1, strategy: mis, heuristic: power, seed: 0}";
    EstimatorSpec {
        name: name.into(),
        analytic: EMISSION / (1.0 - 0.5),
        samples: 40_000,
        estimate: path_estimator(
            t,
            furnace_around(0.5, render, Some(material)),
            Vec3::ZERO,
            |s| uniform_sphere(s.next_2d()),
        ),
    }
}

/// `Le Σ_{k<segments} ρ^k`.
fn bounded(albedo: f64, segments: i32) -> f64 {
    (0..segments).map(|k| EMISSION * albedo.powi(k)).sum()
}

pub fn estimators<T: Tasks>(t: &T) -> Vec<EstimatorSpec<'_>> {
    let roulette = |depth: &str| {
        format!(
            "{{spp: 1, max_depth: {depth}, rr_depth: 1, strategy: mis, heuristic: power, seed: 0}}"
        )
    };
    let without_roulette = |depth: i32| {
        format!(
            "{{spp: 1, max_depth: {depth}, rr_depth: 100, strategy: mis, heuristic: power, seed: 0}}"
        )
    };
    vec![
        furnace_spec(
            t,
            "white furnace Le/(1 − ρ), ρ = 0.5, unbounded depth with Russian roulette",
            0.5,
            &roulette("~"),
            EMISSION / (1.0 - 0.5),
        ),
        furnace_spec(
            t,
            "white furnace Le/(1 − ρ), ρ = 0.8, unbounded depth, roulette at every bounce",
            0.8,
            &roulette("~"),
            EMISSION / (1.0 - 0.8),
        ),
        furnace_spec(
            t,
            "white furnace Le (1 + ρ + ρ²), depth 3 without roulette",
            0.5,
            &without_roulette(3),
            bounded(0.5, 3),
        ),
        furnace_spec(
            t,
            "furnace with ρ = 1.25 (bounce weights above 1), depth 4 with roulette",
            1.25,
            &roulette("4"),
            bounded(1.25, 4),
        ),
        lossless_spec(
            t,
            "white furnace Le/(1 − ρ), ρ = 0.5, around a glass sphere (lossless: invisible)",
            "{dielectric: {ior: 1.5}}",
        ),
        lossless_spec(
            t,
            "white furnace Le/(1 − ρ), ρ = 0.5, around a perfect mirror sphere (invisible)",
            "{mirror: {reflectance: 1}}",
        ),
        EstimatorSpec {
            // Four segments: the camera ray, the bounce off the floor, and two that escape.
            name: "a floor (ρ = 0.5) under a sky, depth 4: ρ Le, the sky counted once".into(),
            analytic: 0.5 * EMISSION,
            samples: 40_000,
            estimate: path_estimator(
                t,
                floor_under_sky(0.5, &without_roulette(4)),
                Vec3::Z,
                |_| -Vec3::Z,
            ),
        },
    ]
}
