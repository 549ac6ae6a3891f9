//! Tiny scenes for the integrator cases, written inline so the catalogue needs no files.
//! Every scene renders a 4 × 4 image; only the geometry and the lights matter.

use crate::geometry::{Hit, Ray};
use crate::scene::{LoadOptions, Scene};
use glam::Vec3;
use std::path::Path;

const HEADER: &str = "
camera: {eye: [0, 0, 5], target: [0, 0, 0], up: [0, 1, 0], fov: 30, width: 4, height: 4}
render: {spp: 1, max_depth: ~, rr_depth: 3, strategy: mis, heuristic: power, seed: 0}
";

/// A mirror (reflectance 0.9) in the plane z = 0, facing +z, under a 1 × 1 quad light of
/// radiance 5 at z = 2 facing down: the mirror direction of wo = +z at the origin hits it.
pub const MIRROR_UNDER_LIGHT: &str = "
materials:
  mirror: {mirror: {reflectance: 0.9}}
shapes:
  - quad: {origin: [-1, -1, 0], edge1: [2, 0, 0], edge2: [0, 2, 0], material: mirror}
  - quad: {origin: [-0.5, -0.5, 2], edge1: [0, 1, 0], edge2: [1, 0, 0], emission: 5}
";

/// A diffuse floor in z = 0 and, beside it in the same plane, a quad light facing up:
/// from any floor point every light sample arrives edge-on (cos θ at the light = 0).
pub const LIGHT_IN_THE_FLOOR_PLANE: &str = "
materials:
  floor: {diffuse: {albedo: 0.5}}
shapes:
  - quad: {origin: [-1, -1, 0], edge1: [2, 0, 0], edge2: [0, 2, 0], material: floor}
  - quad: {origin: [2, -0.5, 0], edge1: [1, 0, 0], edge2: [0, 1, 0], emission: 5}
";

/// A diffuse quad light (albedo 0.5, radiance 5) in z = 0 facing +z and nothing else:
/// shading a point of the light itself, every light sample lies in its plane.
pub const ON_THE_LIGHT: &str = "
materials:
  panel: {diffuse: {albedo: 0.5}}
shapes:
  - quad: {origin: [-1, -1, 0], edge1: [2, 0, 0], edge2: [0, 2, 0], material: panel, emission: 5}
";

/// A diffuse sphere (albedo 0.8, radius 0.8) under a constant environment of radiance 1.
pub const FURNACE: &str = "
materials:
  grey: {diffuse: {albedo: 0.8}}
shapes:
  - sphere: {center: [0, 0, 0], radius: 0.8, material: grey}
lights:
  - environment: {radiance: 1}
";

/// Loads one of the scenes above. They are fixed text, so failing to load one is a bug in
/// the catalogue, reported as a panic of the case.
pub fn load(body: &str) -> Scene {
    let text = format!("{HEADER}{body}");
    Scene::from_yaml(
        Path::new("<stability scene>"),
        &text,
        &LoadOptions::default(),
    )
    .unwrap_or_else(|e| panic!("stability scene does not load: {e}"))
}

/// The first hit of the ray from `origin` along the unit `dir`.
pub fn hit(scene: &Scene, origin: Vec3, dir: Vec3) -> (Ray, Hit) {
    let ray = Ray::new(origin, dir);
    let hit = scene.intersect(&ray).unwrap_or_else(|| {
        panic!("stability scene: the ray from {origin} along {dir} hits nothing")
    });
    (ray, hit)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_scene_loads_and_is_hit_where_the_cases_aim() {
        for body in [
            MIRROR_UNDER_LIGHT,
            LIGHT_IN_THE_FLOOR_PLANE,
            ON_THE_LIGHT,
            FURNACE,
        ] {
            let scene = load(body);
            let (_, h) = hit(&scene, Vec3::new(0.0, 0.0, 1.0), -Vec3::Z);
            assert!(
                h.p.length() < 1e-3 || (h.p.z - 0.8).abs() < 1e-3,
                "{:?}",
                h.p
            );
        }
    }
}
