//! The estimators of `path_trace`: closed furnaces whose radiance is known in closed form
//! (also around lossless glass and mirror objects, which a correct tracer renders
//! invisible), in the configurations where Russian roulette can go wrong (a survival probability that
//! is exactly 1/2 hides an inverted test; a bounce weight above 1 needs the probability
//! capped), and a floor under a sky, where a path that escapes after a bounce must not add
//! the sky that `mis` already counted.
//!
//! They cover the contract's whole range of depths (below 1, 1, 2, small caps, unbounded),
//! coloured albedos (each channel its own estimate, weighted apart by
//! [`crate::grade::estimator::CHANNEL_WEIGHTS`]), and a glossy Phong floor under emitters that reflect
//! nothing, whose BSDF sampling fails at every wall (`bounce` is `None`) and whose bounce
//! weights vary around and above 1.

use crate::grade::catalogue::phong_floor::PhongSurface;
use crate::grade::catalogue::rough_conductor::{self, RoughConductor, StoredQuadrature};
use crate::grade::estimator::{CHANNEL_WEIGHTS, EstimatorSpec, yaml_rgb};
use crate::geometry::Ray;
use crate::grade::declared::Declared;
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
pub(crate) const EMISSION: f64 = 1.0;

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
pub(crate) fn furnace_around(albedo: DVec3, render: &str, inside: Option<&str>) -> Scene {
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

/// The Phong floor of [`floor_box`] seen along its normal.
pub(crate) const PHONG: PhongSurface = PhongSurface {
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

/// The furnace box with a floor of `material` (YAML) that emits nothing, under five walls
/// that emit [`EMISSION`] and reflect nothing (their BSDF samples fail: `mis` returns no
/// bounce). The floor's hemisphere sees radiance `Le` everywhere, so it reflects `Le` times
/// its albedo: `Le (kd + ks)` along the normal of a Phong floor.
pub(crate) fn floor_box(material: &str, render: &str) -> Scene {
    let mut text = format!(
        "camera: {{eye: [0, 0, 0], target: [0, 0, -1], up: [0, 1, 0], fov: 60, width: 4, height: 4}}
render: {render}
materials:
  floor: {material}
shapes:
"
    );
    let (floor, emitters) = FURNACE_WALLS.split_first().expect("six walls");
    text += &format!("  - quad: {{origin: {floor}, material: floor}}\n");
    for wall in emitters {
        text += &format!("  - quad: {{origin: {wall}, emission: {EMISSION}}}\n");
    }
    load(&text, "<grader floor box>")
}

/// The rough conductor of [`floor_box`] seen along its normal: copper-coloured, α = 0.3.
const ROUGH: RoughConductor = RoughConductor {
    alpha_x: 0.3,
    alpha_y: 0.3,
    f0: DVec3::new(0.95, 0.64, 0.54),
};

/// `∫ f cos θi dωi` per channel of [`ROUGH`] along its normal, by quadrature of the
/// reference ([`stored_quadratures`]).
const ROUGH_ALBEDO: DVec3 = DVec3::new(0.833_492_152, 0.561_521_454, 0.473_789_002);

/// An anisotropic rough conductor seen at 70° from its normal ([`GRAZING`]): a large
/// share of its half-vector samples reflect below the horizon and fail.
const ANISOTROPIC: RoughConductor = RoughConductor {
    alpha_x: 0.15,
    alpha_y: 0.6,
    f0: DVec3::new(0.9, 0.8, 0.5),
};

/// `∫ f cos θi dωi` per channel of [`ANISOTROPIC`] seen from [`GRAZING`], by quadrature
/// of the reference ([`stored_quadratures`]).
const ANISOTROPIC_ALBEDO: DVec3 = DVec3::new(0.702_240_285, 0.625_875_187, 0.396_779_802);

/// A diffuse floor of `albedo`, 20 × 20 around the origin, lit by `light` (a light in the
/// scene format) and nothing else: under a sky of radiance [`EMISSION`] a flat floor sees
/// only the sky, so its radiance is `ρ Le` exactly however many bounces are allowed; under
/// [`POINT`] a path's continuation escapes into the dark, and the radiance at the origin is
/// `ρ/π · I cos θ / d²` ([`under_point_light`]).
fn floor_under(albedo: f64, light: &str, render: &str) -> Scene {
    let text = format!(
        "camera: {{eye: [0, 0, 1], target: [0, 0, 0], up: [0, 1, 0], fov: 60, width: 4, height: 4}}
render: {render}
materials:
  floor: {{diffuse: {{albedo: {albedo}}}}}
shapes:
  - quad: {{origin: [-10, -10, 0], edge1: [20, 0, 0], edge2: [0, 20, 0], material: floor}}
lights:
  - {light}
"
    );
    load(&text, "<grader floor under a light>")
}

/// The sky of [`floor_under`], of radiance [`EMISSION`], in the scene format.
fn sky() -> String {
    format!("environment: {{radiance: {EMISSION}}}")
}

/// How much darker than a mirror the dark mirror of [`dark_mirror_spec`] is, and how much
/// brighter than [`sky`] its sky.
const DARKNESS: f64 = 1e4;

/// A floor that is a mirror of reflectance `1 / DARKNESS`, and above it a perfect mirror
/// tilted 45° about y that turns light from the floor sideways, to a sky `DARKNESS` times
/// brighter than [`sky`]. Seen straight down, a path's first bounce has the weight 1e-4 and
/// all the light comes through it and the second mirror (a mirror gets no light sample), so
/// the radiance is `R Le` = [`EMISSION`] exactly. Code that ends a path because its weight
/// is small, rather than by depth or roulette, returns 0.
fn dark_mirror_spec<'a, T: Tasks>(t: &'a T, render: &str) -> EstimatorSpec<'a> {
    let text = format!(
        "camera: {{eye: [0, 0, 1], target: [0, 0, 0], up: [0, 1, 0], fov: 60, width: 4, height: 4}}
render: {render}
materials:
  dark: {{mirror: {{reflectance: {reflectance}}}}}
  bright: {{mirror: {{reflectance: 1}}}}
shapes:
  - quad: {{origin: [-10, -10, 0], edge1: [20, 0, 0], edge2: [0, 20, 0], material: dark}}
  - quad: {{origin: [-0.5, -1, 1.5], edge1: [0, 2, 0], edge2: [1, 0, 1], material: bright}}
lights:
  - environment: {{radiance: {sky}}}
",
        reflectance = 1.0 / DARKNESS,
        sky = EMISSION * DARKNESS
    );
    EstimatorSpec {
        name: "a mirror of reflectance 1e-4 seeing a sky 1e4 times brighter through a second \
               mirror, depth 4: R Le (a bounce of tiny weight still carries light)"
            .into(),
        analytic: EMISSION,
        samples: 2_000,
        estimate: path_estimator(
            t,
            load(&text, "<grader dark mirror>"),
            Vec3::Z,
            |_| -Vec3::Z,
        ),
    }
}

/// The point light of [`floor_under`] in the scene format.
fn point_light() -> String {
    let ([x, y, z], intensity) = POINT;
    format!("point: {{position: [{x}, {y}, {z}], intensity: {intensity}}}")
}

/// Position and intensity of the point light of [`floor_under`].
const POINT: ([f64; 3], f64) = ([0.6, -0.2, 0.8], 2.0);

/// The radiance at the origin of [`floor_under`]'s floor under [`point_light`].
fn under_point_light(albedo: f64) -> f64 {
    let ([x, y, z], intensity) = POINT;
    let d2 = x * x + y * y + z * z;
    albedo / std::f64::consts::PI * intensity * (z / d2.sqrt()) / d2
}

fn load(text: &str, name: &str) -> Scene {
    Scene::from_yaml(Path::new(name), text, &LoadOptions::default())
        .unwrap_or_else(|e| panic!("the grader's scene {name} is valid: {e}"))
}

/// The radiance along one ray from `origin` in a direction drawn by `direction`, with the
/// scene's depth; the estimate weighs the channels by [`CHANNEL_WEIGHTS`].
pub(crate) fn path_estimator<'a, T: Tasks>(
    t: &'a T,
    scene: Scene,
    origin: Vec3,
    direction: impl Fn(&mut Sampler) -> Vec3 + 'a,
) -> Box<crate::grade::estimator::Estimator<'a>> {
    let depth = scene.settings().max_depth;
    path_estimator_at(t, scene, depth, origin, direction)
}

/// [`path_estimator`] with `depth` passed to the first call instead of the scene's.
fn path_estimator_at<'a, T: Tasks>(
    t: &'a T,
    scene: Scene,
    depth: i32,
    origin: Vec3,
    direction: impl Fn(&mut Sampler) -> Vec3 + 'a,
) -> Box<crate::grade::estimator::Estimator<'a>> {
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
        name: format!("white furnace, ρ = 0.5, called with depth {depth}"),
        analytic,
        samples: if depth < 1 { 2_000 } else { 20_000 },
        estimate: path_estimator_at(t, furnace(0.5, render), depth, Vec3::ZERO, |s| {
            uniform_sphere(s.next_2d())
        }),
    }
}

/// A ray straight down onto the centre of [`floor_box`]'s floor.
fn phong_floor_spec<'a, T: Tasks>(t: &'a T, how: &str, render: &str) -> EstimatorSpec<'a> {
    EstimatorSpec {
        name: format!(
            "a Phong floor under emitters that reflect nothing, seen along its normal, {how}: Le (kd + ks)"
        ),
        analytic: CHANNEL_WEIGHTS.dot(EMISSION * (PHONG.kd + PHONG.ks)),
        samples: 40_000,
        estimate: path_estimator(t, floor_box(&PHONG.yaml(), render), Vec3::ZERO, |_| -Vec3::Y),
    }
}

/// A ray at 70° from the normal onto the centre of a broad Phong floor in
/// [`floor_box`]: its albedo there (by quadrature), where a large share of the
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
            floor_box(&BROAD_PHONG.yaml(), render),
            FLOOR_CENTRE - GRAZING * 0.8,
            |_| GRAZING,
        ),
    }
}

/// A ray onto the centre of [`floor_box`]'s floor of `surface`, from `direction` (towards
/// the floor), whose answer is `Le` times `albedo` (the surface's albedo seen from there).
fn rough_floor_spec<'a, T: Tasks>(
    t: &'a T,
    how: &str,
    surface: &RoughConductor,
    direction: Vec3,
    albedo: DVec3,
    render: &str,
) -> EstimatorSpec<'a> {
    EstimatorSpec {
        name: format!(
            "a rough conductor floor under emitters that reflect nothing, {how}: Le × its albedo"
        ),
        analytic: CHANNEL_WEIGHTS.dot(EMISSION * albedo),
        samples: 40_000,
        estimate: path_estimator(
            t,
            floor_box(&surface.yaml(), render),
            FLOOR_CENTRE - direction * 0.8,
            move |_| direction,
        ),
    }
}

/// The centre of [`floor_box`]'s floor.
const FLOOR_CENTRE: Vec3 = Vec3::new(0.0, -1.0, 0.0);

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
        depth_spec(t, 5, bounded(0.5, 5)),
        depth_spec(t, 8, bounded(0.5, 8)),
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
                floor_box(&PHONG.yaml(), &roulette("~")),
                Vec3::ZERO,
                |_| Vec3::Y,
            ),
        },
        phong_floor_spec(
            t,
            "unbounded depth, roulette at every bounce",
            &roulette("~"),
        ),
        rough_floor_spec(
            t,
            "seen along its normal, depth 2 without roulette",
            &ROUGH,
            -Vec3::Y,
            ROUGH_ALBEDO,
            &without_roulette(2),
        ),
        rough_floor_spec(
            t,
            "anisotropic, seen at 70° (many BSDF samples fail), roulette at every bounce",
            &ANISOTROPIC,
            GRAZING,
            ANISOTROPIC_ALBEDO,
            &roulette("~"),
        ),
        EstimatorSpec {
            name: "a floor (ρ = 0.5) under a point light, unbounded depth with roulette: ρ/π · I cos θ / d²".into(),
            analytic: under_point_light(0.5),
            samples: 20_000,
            estimate: path_estimator(
                t,
                floor_under(0.5, &point_light(), &roulette("~")),
                Vec3::Z,
                |_| -Vec3::Z,
            ),
        },
        dark_mirror_spec(t, &without_roulette(4)),
        EstimatorSpec {
            // Four segments: the camera ray, the bounce off the floor, and two that escape.
            name: "a floor (ρ = 0.5) under a sky, depth 4: ρ Le, the sky counted once".into(),
            analytic: 0.5 * EMISSION,
            samples: 40_000,
            estimate: path_estimator(
                t,
                floor_under(0.5, &sky(), &without_roulette(4)),
                Vec3::Z,
                |_| -Vec3::Z,
            ),
        },
    ]
}

/// The stored albedos of the rough floors beside the same quadratures of `t`'s BSDF, at
/// the hit each estimator's ray makes.
pub(crate) fn stored_quadratures<T: Tasks>(t: &T) -> Vec<StoredQuadrature> {
    let render = "{spp: 1, max_depth: 2, rr_depth: 100, strategy: mis, heuristic: power, seed: 0}";
    [
        ("ROUGH_ALBEDO", ROUGH, -Vec3::Y, ROUGH_ALBEDO),
        ("ANISOTROPIC_ALBEDO", ANISOTROPIC, GRAZING, ANISOTROPIC_ALBEDO),
    ]
    .into_iter()
    .map(|(what, surface, direction, stored)| {
        let scene = floor_box(&surface.yaml(), render);
        let hit = scene
            .intersect(&Ray::new(FLOOR_CENTRE - direction * 0.8, direction))
            .expect("the ray meets the floor");
        StoredQuadrature {
            what: format!("path_trace {what}"),
            stored,
            computed: rough_conductor::albedo(t, &scene, &hit, -direction),
        }
    })
    .collect()
}
