//! The variance image is calibrated: two renders of the same scene with different seeds
//! agree pixel by pixel within the standard errors it gives (what the grader's image z-test
//! relies on), and a 10 % brighter image does not.

use pbrlab::render::{RenderOptions, RenderOutput, render};
use pbrlab::scene::{LoadOptions, Scene};
use pbrlab_solutions::TASKS as Reference;
use std::path::Path;

fn cornell(seed: u64) -> RenderOutput {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/cornell.yaml");
    let options = LoadOptions {
        width: Some(48),
        height: Some(48),
        spp: Some(128),
        seed: Some(seed),
        ..Default::default()
    };
    let scene = Scene::load(&path, &options).expect("cornell");
    render(&scene, &Reference, &RenderOptions::from_scene(&scene))
}

/// The fraction of pixel channels where `a · scale` and `b` differ by less than 3.29
/// standard errors (two-sided 99.9 %), among channels with some variance.
fn agreement(a: &RenderOutput, b: &RenderOutput, scale: f32) -> f64 {
    let n = a.stats.spp as f32;
    let (mut ok, mut total) = (0usize, 0usize);
    for i in 0..a.mean.pixels.len() {
        for c in 0..3 {
            let (ma, mb) = (a.mean.pixels[i][c] * scale, b.mean.pixels[i][c]);
            let var = (a.variance.pixels[i][c] * scale * scale + b.variance.pixels[i][c]) / n;
            if var > 0.0 {
                total += 1;
                ok += (((ma - mb) / var.sqrt()).abs() < 3.29) as usize;
            }
        }
    }
    ok as f64 / total as f64
}

#[test]
fn two_seeds_agree_within_the_variance_image() {
    let (a, b) = (cornell(1), cornell(2));
    let same = agreement(&a, &b, 1.0);
    assert!(
        same > 0.99,
        "only {:.2} % of pixel channels agree",
        same * 100.0
    );
    // Measured when written: 99.93 % agree (99.9 % expected); 94.6 % for a 10 % brighter one.
    let brighter = agreement(&a, &b, 1.1);
    assert!(
        brighter < same - 0.03,
        "a 10 % brighter image still agrees on {:.2} %",
        brighter * 100.0
    );
}
