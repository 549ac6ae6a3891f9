//! The estimators of `mis`: the errata's direct-light scene, where the answer is an exact
//! integral, with and without an occluder, for every weighting.

use super::EstimatorSpec;
use crate::geometry::Ray;
use crate::integrator::Heuristic;
use crate::sampling::Sampler;
use crate::scene::{LoadOptions, Scene};
use crate::worksheet::Tasks;
use glam::Vec3;
use std::path::Path;

/// The errata's exact direct light without the occluder (scene A).
pub const OPEN: f64 = 0.067_482_93;
/// The errata's exact direct light with the occluder (scene B).
pub const OCCLUDED: f64 = 0.009_195_30;

/// A Lambertian floor (albedo 0.8) at z = 0 lit by a one-sided unit square of radiance 1 at
/// z = 1 (x ∈ [0.5, 1.5], y ∈ [−0.5, 0.5], facing down); with `occluder`, a black strip at
/// z = 0.5 (x ∈ [0.2, 0.6], y ∈ [−1, 1]) shades most of it. Every length is multiplied by
/// `scale`, which must not change any radiance.
fn scene(occluder: bool, scale: f32) -> Scene {
    let s = |x: f32| x * scale;
    let mut text = format!(
        "camera: {{eye: [0, 0, {e}], target: [0, 0, 0], up: [0, 1, 0], fov: 60, width: 4, height: 4}}
render: {{spp: 1, max_depth: 2, strategy: mis, heuristic: power, seed: 0}}
materials:
  floor: {{diffuse: {{albedo: 0.8}}}}
  black: {{diffuse: {{albedo: 0}}}}
shapes:
  - quad: {{origin: [{a}, {a}, 0], edge1: [{b}, 0, 0], edge2: [0, {b}, 0], material: floor}}
  - quad: {{origin: [{lx}, {ly}, {lz}], edge1: [0, {l}, 0], edge2: [{l}, 0, 0], emission: 1}}
",
        e = s(3.0),
        a = s(-3.0),
        b = s(6.0),
        lx = s(0.5),
        ly = s(-0.5),
        lz = s(1.0),
        l = s(1.0),
    );
    if occluder {
        text += &format!(
            "  - quad: {{origin: [{ox}, {oy}, {oz}], edge1: [{w}, 0, 0], edge2: [0, {h}, 0], material: black}}\n",
            ox = s(0.2),
            oy = s(-1.0),
            oz = s(0.5),
            w = s(0.4),
            h = s(2.0),
        );
    }
    Scene::from_yaml(
        Path::new("<grader mis scene>"),
        &text,
        &LoadOptions::default(),
    )
    .expect("the grader's MIS scene is valid")
}

/// One call of `mis` at the origin, looking straight up; the mean of the three channels.
fn direct_light<'a, T: Tasks>(
    t: &'a T,
    scene: Scene,
    heuristic: Heuristic,
) -> Box<super::super::estimator::Estimator<'a>> {
    let down = Ray::new(Vec3::new(0.0, 0.0, 0.3) * scene_scale(&scene), -Vec3::Z);
    let hit = scene
        .intersect(&down)
        .expect("the probe ray hits the floor at the origin");
    Box::new(move |s: &mut Sampler| {
        let direct = t.mis(&scene, &hit, Vec3::Z, heuristic, s);
        Ok(direct.radiance.element_sum() as f64 / 3.0)
    })
}

/// The scale of a scene built by [`scene`], read back from its camera height.
fn scene_scale(scene: &Scene) -> f32 {
    scene.camera().eye.z / 3.0
}

fn spec<'a, T: Tasks>(
    t: &'a T,
    occluder: bool,
    scale: f32,
    heuristic: Heuristic,
) -> EstimatorSpec<'a> {
    let (analytic, which) = if occluder {
        (OCCLUDED, "occluded")
    } else {
        (OPEN, "open")
    };
    let units = if scale == 1.0 {
        String::new()
    } else {
        format!(", lengths × {scale}")
    };
    EstimatorSpec {
        name: format!("direct light from a square light, {which}, {heuristic:?} weights{units}")
            .to_lowercase(),
        analytic,
        samples: 100_000,
        estimate: direct_light(t, scene(occluder, scale), heuristic),
    }
}

pub fn estimators<T: Tasks>(t: &T) -> Vec<EstimatorSpec<'_>> {
    vec![
        spec(t, false, 1.0, Heuristic::Power),
        spec(t, false, 1.0, Heuristic::Balance),
        spec(t, true, 1.0, Heuristic::Power),
        spec(t, true, 1.0, Heuristic::Light),
        spec(t, true, 1.0, Heuristic::Bsdf),
    ]
}

/// The same estimator in the same scene in two units of length: its variance must not
/// change (MIS weights that mix a pdf per unit area with one per solid angle do).
pub fn unit_pairs<T: Tasks>(t: &T) -> Vec<(EstimatorSpec<'_>, EstimatorSpec<'_>)> {
    vec![(
        spec(t, false, 1.0, Heuristic::Balance),
        spec(t, false, 1000.0, Heuristic::Balance),
    )]
}
