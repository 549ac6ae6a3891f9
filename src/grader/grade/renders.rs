//! The graded scenes and how they are rendered: which scenes, at what size and sample
//! count, and the worker's half of a render check ([`render_raw`]); the grader's half, the
//! stored reference renders and the judge, is [`super::render_check`].
//!
//! A scene's points are awarded once every task it needs has passed on its own
//! ([`super::scene_gate`]), and the render uses the student's code for all of those tasks
//! together.

use super::image_check::ImageStats;
use super::wire::{ImageOutputs, Rendered};
use crate::render::{RenderOptions, render};
use crate::scene::{LoadOptions, Scene};
use crate::task_set::TaskSet;
use crate::worksheet::Tasks;
use anyhow::{Context, anyhow};
use std::path::PathBuf;

pub use pbrlab_course::scenes::{RENDER_CHECKS, RenderCheck};

/// Image size of graded renders (small: the z-test needs samples, not pixels).
pub const WIDTH: u32 = 48;
/// Image height of graded renders.
pub const HEIGHT: u32 = 48;
/// Samples per pixel of the student's render.
pub const STUDENT_SPP: u32 = 256;
/// Samples per pixel of the stored reference render (its variance is then small next to
/// the student's).
pub const REFERENCE_SPP: u32 = 4096;
/// Seed of the stored reference render (the student's render uses other seeds).
pub const REFERENCE_SEED: u64 = 0x7265_6e64;

/// Where the scene files are.
pub fn scene_path(scene: &str) -> PathBuf {
    crate::repository_root()
        .join("scenes")
        .join(format!("{scene}.yaml"))
}

/// Loads `scene` at the graded size.
pub fn load(scene: &str) -> anyhow::Result<Scene> {
    let options = LoadOptions {
        width: Some(WIDTH),
        height: Some(HEIGHT),
        ..LoadOptions::default()
    };
    let path = scene_path(scene);
    Scene::load(&path, &options)
        .map_err(|e| anyhow!("{e}"))
        .with_context(|| format!("loading {}", path.display()))
}

/// The tasks `scene` needs (those it calls and those they call).
pub fn needs(scene: &str) -> anyhow::Result<TaskSet> {
    Ok(load(scene)?.needs().all_tasks())
}

/// Renders `scene` with `t` and returns its mean, the variance of that mean, and how many
/// samples the renderer had to drop (NaN, infinite or negative radiance).
pub fn render_stats<T: Tasks>(scene: &Scene, t: &T, spp: u32, seed: u64) -> (ImageStats, u64) {
    let out = render(
        scene,
        t,
        &RenderOptions {
            spp,
            seed,
            progress: false,
            time_limit: None,
            on_pass: None,
        },
    );
    let flat = |img: &crate::render::Image, scale: f32| -> Vec<f32> {
        img.pixels
            .iter()
            .flat_map(|p| (*p * scale).to_array())
            .collect()
    };
    let stats = ImageStats {
        width: out.mean.width as usize,
        height: out.mean.height as usize,
        mean: flat(&out.mean, 1.0),
        variance: flat(&out.variance, 1.0 / spp as f32),
    };
    (stats, out.stats.rejected_samples)
}

/// The worker's half of a render check: renders `scene` with `t` and seed `seed`, and
/// returns the statistics for the grader to compare (the stored reference never enters the
/// worker).
pub fn render_raw<T: Tasks>(t: &T, scene: &str, seed: u64) -> ImageOutputs {
    let start = std::time::Instant::now();
    let outcome = match load(scene) {
        Ok(loaded) => crate::panics::catch(|| {
            let (stats, rejected) = render_stats(&loaded, t, STUDENT_SPP, seed);
            Ok(Rendered { stats, rejected })
        }),
        Err(e) => Ok(Err(format!("{e:#}"))),
    };
    ImageOutputs {
        scene: scene.into(),
        outcome,
        seconds: start.elapsed().as_secs_f64(),
    }
}
