//! Ray-casting throughput of the scene layer (its four-wide BVH, the watertight triangle
//! test, hit records) against obvhs' CWBVH over the same triangles, traversed with the same
//! rays directly (its own ray-triangle test, no hit record). Measured in one run,
//! interleaved, best of several rounds each, so that the ratio does not depend on the
//! machine's load.

use crate::geometry::Ray;
use crate::sampling::{Sampler, uniform_sphere};
use crate::scene::Scene;
use serde::Serialize;
use std::time::Instant;

/// The result of [`compare_with_obvhs`].
#[derive(Clone, Copy, Debug, Serialize)]
pub struct RaycastComparison {
    /// Rays cast in each round.
    pub rays: usize,
    /// Triangles in the scene's BVH.
    pub triangles: usize,
    /// Closest-hit rays per second through [`Scene::intersect`] (full hit records).
    pub scene_rays_per_second: f64,
    /// Closest-hit rays per second through obvhs' CWBVH directly.
    pub obvhs_rays_per_second: f64,
    /// `scene_rays_per_second / obvhs_rays_per_second`.
    pub ratio: f64,
    /// Rays that hit something through the scene (watertight test).
    pub scene_hits: usize,
    /// Rays that hit something through obvhs (its own test).
    pub obvhs_hits: usize,
}

/// A mix of camera rays (coherent) and rays from random points of the scene's bounding box
/// in random directions (incoherent), `count` in all.
pub fn test_rays(scene: &Scene, count: usize, seed: u64) -> Vec<Ray> {
    let cam = scene.camera();
    let mut sampler = Sampler::new(seed, 0);
    let (lo, hi) = scene
        .surfaces()
        .triangles()
        .map(|t| {
            t.triangles().flatten().fold(
                (
                    glam::Vec3::splat(f32::INFINITY),
                    glam::Vec3::splat(f32::NEG_INFINITY),
                ),
                |(lo, hi), v| (lo.min(*v), hi.max(*v)),
            )
        })
        .unwrap_or((glam::Vec3::splat(-1.0), glam::Vec3::ONE));
    (0..count)
        .map(|i| {
            if i % 2 == 0 {
                let u = sampler.next_2d();
                cam.ray(u.x * cam.width as f32, u.y * cam.height as f32)
            } else {
                let u = glam::Vec3::new(sampler.next_1d(), sampler.next_1d(), sampler.next_1d());
                Ray::new(lo + u * (hi - lo), uniform_sphere(sampler.next_2d()))
            }
        })
        .collect()
}

/// Casts `rays` through the scene and through an obvhs CWBVH (built here, with its medium
/// settings) directly, `rounds` times each (interleaved), and compares the best times.
/// `None` when the scene has no triangles.
pub fn compare_with_obvhs(scene: &Scene, rays: &[Ray], rounds: usize) -> Option<RaycastComparison> {
    let set = scene.surfaces().triangles()?;
    let tris: Vec<obvhs::triangle::Triangle> = set
        .triangles()
        .map(|v| obvhs::triangle::Triangle {
            v0: v[0].into(),
            v1: v[1].into(),
            v2: v[2].into(),
        })
        .collect();
    let bvh = obvhs::cwbvh::builder::build_cwbvh_from_tris(
        &tris,
        obvhs::BvhBuildParams::medium_build(),
        &mut std::time::Duration::default(),
    );
    let obvhs_rays: Vec<obvhs::ray::Ray> = rays
        .iter()
        .map(|r| obvhs::ray::Ray::new_inf(r.origin.into(), r.dir.into()))
        .collect();
    let (mut best_scene, mut best_obvhs) = (f64::INFINITY, f64::INFINITY);
    let (mut scene_hits, mut obvhs_hits) = (0, 0);
    for _ in 0..rounds.max(1) {
        let start = Instant::now();
        scene_hits = rays.iter().filter(|r| scene.intersect(r).is_some()).count();
        best_scene = best_scene.min(start.elapsed().as_secs_f64());

        let start = Instant::now();
        obvhs_hits = obvhs_rays
            .iter()
            .filter(|r| {
                let mut hit = obvhs::ray::RayHit::none();
                bvh.ray_traverse(**r, &mut hit, |ray, id| {
                    tris[bvh.primitive_indices[id] as usize].intersect(ray)
                })
            })
            .count();
        best_obvhs = best_obvhs.min(start.elapsed().as_secs_f64());
    }
    crate::scene::take_ray_count();
    let n = rays.len() as f64;
    Some(RaycastComparison {
        rays: rays.len(),
        triangles: set.len(),
        scene_rays_per_second: n / best_scene,
        obvhs_rays_per_second: n / best_obvhs,
        ratio: best_obvhs / best_scene,
        scene_hits,
        obvhs_hits,
    })
}
