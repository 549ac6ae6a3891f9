//! The estimators of `path_trace`: a closed furnace whose radiance is known in closed form.

use super::EstimatorSpec;
use crate::geometry::Ray;
use crate::integrator::Segment;
use crate::sampling::{Sampler, uniform_sphere};
use crate::scene::{LoadOptions, Scene};
use crate::worksheet::Tasks;
use glam::Vec3;
use std::path::Path;

/// Albedo of the furnace walls.
const ALBEDO: f64 = 0.5;
/// Radiance the walls emit.
const EMISSION: f64 = 1.0;

/// A closed box whose six walls face inwards, each diffuse with albedo 1/2 and emitting
/// radiance 1: every point inside sees `Le Σ ρ^k`, `Le / (1 − ρ) = 2` for unbounded paths.
fn furnace(render: &str) -> Scene {
    let text = format!(
        "camera: {{eye: [0, 0, 0], target: [0, 0, -1], up: [0, 1, 0], fov: 60, width: 4, height: 4}}
render: {render}
materials:
  wall: {{diffuse: {{albedo: {ALBEDO}}}}}
shapes:
  - quad: {{origin: [-1, -1, -1], edge1: [0, 0, 2], edge2: [2, 0, 0], material: wall, emission: {EMISSION}}}
  - quad: {{origin: [-1, 1, -1], edge1: [2, 0, 0], edge2: [0, 0, 2], material: wall, emission: {EMISSION}}}
  - quad: {{origin: [-1, -1, -1], edge1: [0, 2, 0], edge2: [0, 0, 2], material: wall, emission: {EMISSION}}}
  - quad: {{origin: [1, -1, -1], edge1: [0, 0, 2], edge2: [0, 2, 0], material: wall, emission: {EMISSION}}}
  - quad: {{origin: [-1, -1, -1], edge1: [2, 0, 0], edge2: [0, 2, 0], material: wall, emission: {EMISSION}}}
  - quad: {{origin: [-1, -1, 1], edge1: [0, 2, 0], edge2: [2, 0, 0], material: wall, emission: {EMISSION}}}
"
    );
    Scene::from_yaml(
        Path::new("<grader furnace>"),
        &text,
        &LoadOptions::default(),
    )
    .expect("the grader's furnace scene is valid")
}

/// One path from the centre of `scene` in a uniformly random direction; the estimate is the
/// mean of the three (equal) channels.
fn furnace_estimator<'a, T: Tasks>(
    t: &'a T,
    scene: Scene,
) -> Box<super::super::estimator::Estimator<'a>> {
    let depth = scene.settings().max_depth;
    Box::new(move |s: &mut Sampler| {
        let ray = Ray::new(Vec3::ZERO, uniform_sphere(s.next_2d()));
        let segment = Segment {
            ray,
            hit: scene.intersect(&ray),
            emission_counted: false,
        };
        let l = t.path_trace(&scene, &segment, depth, s);
        Ok(l.element_sum() as f64 / 3.0)
    })
}

pub fn estimators<T: Tasks>(t: &T) -> Vec<EstimatorSpec<'_>> {
    let unbounded = "{spp: 1, max_depth: ~, rr_depth: 1, strategy: mis, heuristic: power, seed: 0}";
    let three = "{spp: 1, max_depth: 3, rr_depth: 100, strategy: mis, heuristic: power, seed: 0}";
    vec![
        EstimatorSpec {
            name: "white furnace Le/(1 − ρ), unbounded depth with Russian roulette".into(),
            analytic: EMISSION / (1.0 - ALBEDO),
            samples: 40_000,
            estimate: furnace_estimator(t, furnace(unbounded)),
        },
        EstimatorSpec {
            name: "white furnace Le (1 + ρ + ρ²), depth 3 without roulette".into(),
            analytic: EMISSION * (1.0 + ALBEDO + ALBEDO * ALBEDO),
            samples: 40_000,
            estimate: furnace_estimator(t, furnace(three)),
        },
    ]
}
