//! The furnace: a diffuse sphere (albedo 0.8) under a constant environment of radiance 1.
//! Every pixel fully inside the sphere's silhouette has the analytic value 0.8 and every
//! pixel fully outside it the value 1. The reference renderer must agree within its own
//! standard error, with every direct-light strategy and both hemisphere samplings.

use pbrlab::bsdf::HemisphereSampling;
use pbrlab::render::{RenderOptions, RenderOutput, render};
use pbrlab::scene::schema::{MisHeuristic, Strategy};
use pbrlab::scene::{LoadOptions, Scene};
use pbrlab_solutions::TASKS as Reference;
use std::path::Path;

const SCENE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/furnace.yaml");

/// Pixels whose square is entirely inside (`Some(true)`) or outside (`Some(false)`) the
/// sphere's silhouette, judged on a 9×9 grid of rays over the square, corners included.
fn coverage(scene: &Scene) -> Vec<Option<bool>> {
    let cam = scene.camera();
    let mut out = Vec::new();
    for y in 0..cam.height {
        for x in 0..cam.width {
            let mut hits = 0;
            for j in 0..9 {
                for i in 0..9 {
                    let ray = cam.ray(x as f32 + i as f32 / 8.0, y as f32 + j as f32 / 8.0);
                    hits += scene.intersect(&ray).is_some() as u32;
                }
            }
            out.push(match hits {
                0 => Some(false),
                81 => Some(true),
                _ => None,
            });
        }
    }
    out
}

/// The t statistic of the mean over the pixels fully inside the sphere against 0.8, with
/// the standard error from the render's own per-pixel variances; and the largest deviation
/// of a pixel fully outside it from 1.
fn furnace_statistics(scene: &Scene, out: &RenderOutput) -> (f64, f64) {
    let cover = coverage(scene);
    let spp = out.stats.spp as f64;
    let (mut sum, mut var, mut n) = (0.0f64, 0.0f64, 0usize);
    let mut background_error = 0.0f64;
    for (i, c) in cover.iter().enumerate() {
        let m = out.mean.pixels[i].as_dvec3();
        let v = out.variance.pixels[i].as_dvec3();
        match c {
            Some(true) => {
                sum += m.element_sum() / 3.0;
                // The three channels are identical (grey scene): use one.
                var += v.x / spp;
                n += 1;
            }
            Some(false) => {
                background_error = background_error.max((m - 1.0).abs().max_element());
            }
            None => {}
        }
    }
    assert!(n > 100, "the sphere covers too few pixels ({n})");
    let mean = sum / n as f64;
    // BSDF sampling of a diffuse surface under a constant environment has no variance at
    // all: allow for the rounding of 0.8 in f32.
    let se = (var.sqrt() / n as f64).max(1e-7);
    ((mean - 0.8f32 as f64) / se, background_error)
}

fn render_furnace(options: LoadOptions) -> (Scene, RenderOutput) {
    let scene = Scene::load(Path::new(SCENE), &options).expect("furnace scene loads");
    let out = render(&scene, &Reference, &RenderOptions::from_scene(&scene));
    (scene, out)
}

fn small(strategy: Strategy) -> LoadOptions {
    LoadOptions {
        width: Some(48),
        height: Some(48),
        spp: Some(16),
        strategy: Some(strategy),
        ..Default::default()
    }
}

fn assert_furnace(options: LoadOptions, what: &str) {
    let (scene, out) = render_furnace(options);
    let (t, background) = furnace_statistics(&scene, &out);
    eprintln!("{what}: t = {t:.3}");
    assert!(
        t.abs() < 4.5,
        "{what}: sphere mean is {t:.2} standard errors from 0.8"
    );
    assert!(
        background < 1e-6,
        "{what}: a background pixel is off by {background}"
    );
    assert_eq!(out.stats.rejected_samples, 0, "{what}: non-finite samples");
}

#[test]
fn furnace_mis_power() {
    assert_furnace(small(Strategy::Mis), "mis (power)");
}

#[test]
fn furnace_mis_balance() {
    let mut o = small(Strategy::Mis);
    o.heuristic = Some(MisHeuristic::Balance);
    assert_furnace(o, "mis (balance)");
}

#[test]
fn furnace_bsdf_sampling() {
    assert_furnace(small(Strategy::Bsdf), "bsdf");
}

#[test]
fn furnace_light_sampling() {
    assert_furnace(small(Strategy::Light), "light");
}

#[test]
fn furnace_uniform_hemisphere_sampling() {
    let mut o = small(Strategy::Mis);
    o.diffuse_sampling = Some(HemisphereSampling::Uniform);
    assert_furnace(o, "uniform hemisphere");
}

#[test]
fn furnace_depth_limit_is_seen() {
    // With one segment the sphere shows no reflected light at all: the same statistic must
    // reject 0.8 by a wide margin (the test has power).
    let mut o = small(Strategy::Mis);
    o.max_depth = Some(1);
    let (scene, out) = render_furnace(o);
    let cover = coverage(&scene);
    for (i, c) in cover.iter().enumerate() {
        if *c == Some(true) {
            assert_eq!(out.mean.pixels[i], glam::Vec3::ZERO);
        }
    }
}
