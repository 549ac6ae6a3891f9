//! The estimators of `path_trace`: closed furnaces whose radiance is known in closed form
//! (also around lossless glass and mirror objects, which a correct tracer renders
//! invisible), in the configurations where Russian roulette can go wrong (a survival probability that
//! is exactly 1/2 hides an inverted test; a bounce weight above 1 needs the probability
//! capped), and a floor under a sky, where a path that escapes after a bounce must not add
//! the sky that `mis` already counted.
//!
//! They cover the contract's whole range of depths (below 1, 1, 2, small caps, unbounded),
//! coloured albedos (each channel its own estimate, weighted apart by
//! [`super::CHANNEL_WEIGHTS`]), and a glossy Phong floor under emitters that reflect
//! nothing, whose BSDF sampling fails at every wall (`bounce` is `None`) and whose bounce
//! weights vary around and above 1.

use super::phong_floor::PhongSurface;
use super::{CHANNEL_WEIGHTS, EstimatorSpec, yaml_rgb};
use crate::geometry::Ray;
use crate::grade::power::Declared;
use crate::integrator::Segment;
use crate::sampling::{Sampler, uniform_sphere};
use crate::scene::{LoadOptions, Scene};
use crate::worksheet::Tasks;
use glam::{DVec3, Vec3};
use std::path::Path;

/// What the estimator and sampling checks of this task catch in at least 90 % of
/// gradings, as measured by `pbrlab power` (asserted by tests/instructor/power.rs).
pub const POWER: Declared = Declared {
    estimator_bias: Some(0.005),
    sampler_distortion: None,
};

/// Radiance the furnace walls emit, and the sky's radiance.
pub(super) const EMISSION: f64 = 1.0;

/// A closed box whose six walls face inwards, each diffuse with `albedo` and emitting
/// radiance [`EMISSION`]: every point inside sees `Le Σ_{k<D} ρ^k` for paths of at most
/// `D` segments, `Le / (1 − ρ)` unbounded.
fn furnace(albedo: f64, render: &str) -> Scene {
    furnace_around(DVec3::splat(albedo), render, None)
}

/// [`furnace`] with a sphere of the lossless material `material` (YAML) inside, off the
/// centre: a lossless object in a uniform radiance field reflects and transmits that same
/// radiance, so the field stays `Le / (1 − ρ)` everywhere outside it, whatever its BSDF
/// (the furnace test of delta and refractive lobes).
pub(super) fn furnace_around(albedo: DVec3, render: &str, inside: Option<&str>) -> Scene {
    let mut text = format!(
        "camera: {{eye: [0, 0, 0], target: [0, 0, -1], up: [0, 1, 0], fov: 60, width: 4, height: 4}}
render: {render}
materials:
  wall: {{diffuse: {{albedo: {albedo}}}}}
{object}shapes:
{sphere}",
        albedo = yaml_rgb(albedo),
        object = inside.map_or(String::new(), |m| format!("  object: {m}\n")),
        sphere = if inside.is_some() {
            "  - sphere: {center: [0, 0, -0.5], radius: 0.4, material: object}\n"
        } else {
            ""
        },
    );
    for wall in FURNACE_WALLS {
        text += &format!("  - quad: {{origin: {wall}, material: wall, emission: {EMISSION}}}\n");
    }
    load(&text, "<grader furnace>")
}

/// The six walls of the furnaces, facing inwards: origin and edges of each quad of the box
/// [−1, 1]³; the first is the floor y = −1.
const FURNACE_WALLS: [&str; 6] = [
    "[-1, -1, -1], edge1: [0, 0, 2], edge2: [2, 0, 0]",
    "[-1, 1, -1], edge1: [2, 0, 0], edge2: [0, 0, 2]",
    "[-1, -1, -1], edge1: [0, 2, 0], edge2: [0, 0, 2]",
    "[1, -1, -1], edge1: [0, 0, 2], edge2: [0, 2, 0]",
    "[-1, -1, -1], edge1: [2, 0, 0], edge2: [0, 2, 0]",
    "[-1, -1, 1], edge1: [0, 2, 0], edge2: [2, 0, 0]",
];

/// The Phong floor of [`phong_floor_box`] seen along its normal.
pub(super) const PHONG: PhongSurface = PhongSurface {
    kd: DVec3::new(0.1, 0.3, 0.5),
    ks: DVec3::new(0.5, 0.4, 0.2),
    exponent: 20.0,
};

/// A broad Phong lobe, seen at 70° from the normal: about half of it lies below the
/// horizon, where its samples fail.
const BROAD_PHONG: PhongSurface = PhongSurface {
    kd: DVec3::new(0.2, 0.05, 0.1),
    ks: DVec3::new(0.5, 0.7, 0.6),
    exponent: 2.0,
};

/// The direction towards the floor's centre from which [`BROAD_PHONG`] is seen: 70° from
/// its normal (+y).
const GRAZING: Vec3 = Vec3::new(0.939_692_6, -0.342_020_14, 0.0);

/// The furnace box with a floor of `surface` that emits nothing, under five walls that emit
/// [`EMISSION`] and reflect nothing (their BSDF samples fail: `mis` returns no bounce). The
/// floor's hemisphere sees radiance `Le` everywhere, so it reflects `Le` times its albedo:
/// `Le (kd + ks)` along its normal.
pub(super) fn phong_floor_box(surface: &PhongSurface, render: &str) -> Scene {
    let mut text = format!(
        "camera: {{eye: [0, 0, 0], target: [0, 0, -1], up: [0, 1, 0], fov: 60, width: 4, height: 4}}
render: {render}
materials:
  floor: {}
shapes:
",
        surface.yaml()
    );
    let (floor, emitters) = FURNACE_WALLS.split_first().expect("six walls");
    text += &format!("  - quad: {{origin: {floor}, material: floor}}\n");
    for wall in emitters {
        text += &format!("  - quad: {{origin: {wall}, emission: {EMISSION}}}\n");
    }
    load(&text, "<grader Phong floor>")
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

/// The radiance along one ray from `origin` in a direction drawn by `direction`, with the
/// scene's depth; the estimate weighs the channels by [`CHANNEL_WEIGHTS`].
pub(super) fn path_estimator<'a, T: Tasks>(
    t: &'a T,
    scene: Scene,
    origin: Vec3,
    direction: fn(&mut Sampler) -> Vec3,
) -> Box<super::super::estimator::Estimator<'a>> {
    let depth = scene.settings().max_depth;
    path_estimator_at(t, scene, depth, origin, direction)
}

/// [`path_estimator`] with `depth` passed to the first call instead of the scene's.
fn path_estimator_at<'a, T: Tasks>(
    t: &'a T,
    scene: Scene,
    depth: i32,
    origin: Vec3,
    direction: fn(&mut Sampler) -> Vec3,
) -> Box<super::super::estimator::Estimator<'a>> {
    Box::new(move |s: &mut Sampler| {
        let ray = Ray::new(origin, direction(s));
        let segment = Segment {
            ray,
            hit: scene.intersect(&ray),
            emission_counted: false,
        };
        let l = t.path_trace(&scene, &segment, depth, s);
        Ok(l.as_dvec3().dot(CHANNEL_WEIGHTS))
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
            furnace_around(DVec3::splat(0.5), render, Some(material)),
            Vec3::ZERO,
            |s| uniform_sphere(s.next_2d()),
        ),
    }
}

/// A path from the centre of a furnace whose walls have a different albedo per channel,
/// unbounded with roulette: each channel is `Le / (1 − ρ_c)`, weighted by
/// [`CHANNEL_WEIGHTS`]. One channel reflects nothing, so a survival probability taken
/// from the smallest channel ends every path and darkens the others.
fn coloured_furnace_spec<'a, T: Tasks>(t: &'a T, render: &str) -> EstimatorSpec<'a> {
    let albedo = DVec3::new(0.8, 0.4, 0.0);
    EstimatorSpec {
        name: "white furnace Le/(1 − ρ) per channel, ρ = (0.8, 0.4, 0), unbounded depth with roulette"
            .into(),
        analytic: CHANNEL_WEIGHTS.dot(EMISSION / (DVec3::ONE - albedo)),
        samples: 40_000,
        estimate: path_estimator(
            t,
            furnace_around(albedo, render, None),
            Vec3::ZERO,
            |s| uniform_sphere(s.next_2d()),
        ),
    }
}

/// A path from the centre of the furnace (ρ = 0.5, no roulette) started with `depth`
/// segments: none below 1, the emission seen alone at 1.
fn depth_spec<T: Tasks>(t: &T, depth: i32, analytic: f64) -> EstimatorSpec<'_> {
    let render = "{spp: 1, max_depth: 8, rr_depth: 100, strategy: mis, heuristic: power, seed: 0}";
    EstimatorSpec {
        name: format!("white furnace, ρ = 0.5, called with depth {depth}: {analytic}"),
        analytic,
        samples: if depth < 1 { 2_000 } else { 20_000 },
        estimate: path_estimator_at(t, furnace(0.5, render), depth, Vec3::ZERO, |s| {
            uniform_sphere(s.next_2d())
        }),
    }
}

/// A ray straight down onto the centre of [`phong_floor_box`]'s floor.
fn phong_floor_spec<'a, T: Tasks>(t: &'a T, how: &str, render: &str) -> EstimatorSpec<'a> {
    EstimatorSpec {
        name: format!(
            "a Phong floor under emitters that reflect nothing, seen along its normal, {how}: Le (kd + ks)"
        ),
        analytic: CHANNEL_WEIGHTS.dot(EMISSION * (PHONG.kd + PHONG.ks)),
        samples: 40_000,
        estimate: path_estimator(t, phong_floor_box(&PHONG, render), Vec3::ZERO, |_| -Vec3::Y),
    }
}

/// A ray at 70° from the normal onto the centre of a broad Phong floor in
/// [`phong_floor_box`]: its albedo there (by quadrature), where a large share of the
/// BSDF samples fail and the direct light must still count.
fn grazing_phong_spec<'a, T: Tasks>(t: &'a T, render: &str) -> EstimatorSpec<'a> {
    // In the floor's frame (z = its normal +y), the direction away from the floor.
    let wo = DVec3::new(-GRAZING.x as f64, -GRAZING.y as f64, 0.0);
    let wo_local = DVec3::new(wo.x, 0.0, wo.y);
    EstimatorSpec {
        name: "a broad Phong floor under emitters that reflect nothing, seen at 70° (many BSDF samples fail), roulette at every bounce: Le × its albedo".into(),
        analytic: CHANNEL_WEIGHTS.dot(EMISSION * BROAD_PHONG.albedo(wo_local)),
        samples: 40_000,
        // From 0.8 along `wo` above the floor's centre (0, −1, 0).
        estimate: path_estimator(
            t,
            phong_floor_box(&BROAD_PHONG, render),
            Vec3::new(0.0, -1.0, 0.0) - GRAZING * 0.8,
            |_| GRAZING,
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
        coloured_furnace_spec(t, &roulette("~")),
        depth_spec(t, 1, bounded(0.5, 1)),
        depth_spec(t, 2, bounded(0.5, 2)),
        depth_spec(t, 0, 0.0),
        depth_spec(t, -1, 0.0),
        phong_floor_spec(t, "depth 2 without roulette", &without_roulette(2)),
        grazing_phong_spec(t, &roulette("~")),
        EstimatorSpec {
            name: "an emitter that reflects nothing (no bounce), seen directly: Le".into(),
            analytic: EMISSION,
            samples: 2_000,
            estimate: path_estimator(
                t,
                phong_floor_box(&PHONG, &roulette("~")),
                Vec3::ZERO,
                |_| Vec3::Y,
            ),
        },
        phong_floor_spec(
            t,
            "unbounded depth, roulette at every bounce",
            &roulette("~"),
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
