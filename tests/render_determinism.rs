//! The same seed gives the same image bit for bit, whatever the number of threads: every
//! pixel has its own random stream.

#![cfg(feature = "solutions")]

use pbrlab::render::{RenderOptions, render};
use pbrlab::scene::{LoadOptions, Scene};
use pbrlab_solutions::TASKS as Reference;
use std::path::Path;

fn render_with_threads(threads: usize, seed: u64) -> Vec<glam::Vec3> {
    let path = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/cornell.yaml"));
    let options = LoadOptions {
        width: Some(40),
        height: Some(30),
        spp: Some(5),
        ..Default::default()
    };
    let scene = Scene::load(path, &options).expect("cornell loads");
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("thread pool");
    let mut opts = RenderOptions::from_scene(&scene);
    opts.seed = seed;
    pool.install(|| render(&scene, &Reference, &opts))
        .mean
        .pixels
}

#[test]
fn one_and_two_threads_give_identical_images() {
    let one = render_with_threads(1, 3);
    let two = render_with_threads(2, 3);
    assert!(
        one.iter()
            .zip(&two)
            .all(|(a, b)| a.to_array().map(f32::to_bits) == b.to_array().map(f32::to_bits))
    );
}

#[test]
fn another_seed_gives_another_image() {
    assert_ne!(render_with_threads(2, 3), render_with_threads(2, 4));
}
