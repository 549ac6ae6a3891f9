//! Render checks: a scene rendered with the student's code against the reference render,
//! pixel by pixel ([`super::image_check`]).
//!
//! A scene's points are awarded once every task it needs has passed on its own
//! ([`super::scene_gate`]), and the render uses the student's code for all of those tasks
//! together. The reference renders are stored as EXR files (mean, and variance of the mean)
//! in `tests/snapshots/renders/`, embedded at build time like the expected data, so the
//! handout grades renders without solutions; the instructor test
//! `tests/instructor/renders.rs` writes them and checks them against fresh reference renders.

use super::checks::{ImageOutputs, Rendered};
use super::image_check::{self, ImageStats};
use super::verdict::CheckResult;
use crate::render::{RenderOptions, render};
use crate::scene::{LoadOptions, Scene};
use crate::task_set::TaskSet;
use crate::worksheet::Tasks;
use anyhow::{Context, anyhow};
use std::path::{Path, PathBuf};

include!(concat!(env!("OUT_DIR"), "/render_files.rs"));

/// A scene graded by rendering it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderCheck {
    /// The scene's file name in `scenes/`, without `.yaml`.
    pub scene: &'static str,
    /// Points the render is worth.
    pub points: f64,
}

/// The graded scenes: one per family of materials, so each needs a different set of tasks.
/// The hair scene is not among them: its fibres are thinner than a pixel at the graded size,
/// so a pixel's samples are hit-or-miss and far from normal at any affordable count (the
/// reference itself failed 0.6 % of its pixel-channels at 256 samples per pixel); the
/// `kajiya_kay` task is graded by its values.
pub const RENDER_CHECKS: [RenderCheck; 4] = [
    RenderCheck {
        scene: "cornell",
        points: 4.0,
    },
    RenderCheck {
        scene: "materials",
        points: 4.0,
    },
    RenderCheck {
        scene: "glass",
        points: 4.0,
    },
    RenderCheck {
        scene: "smoke",
        points: 4.0,
    },
];

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

fn decode(bytes: &[u8]) -> anyhow::Result<(usize, usize, Vec<f32>)> {
    let img =
        image::load_from_memory_with_format(bytes, image::ImageFormat::OpenExr)?.into_rgb32f();
    Ok((img.width() as usize, img.height() as usize, img.into_raw()))
}

/// A render from its two EXR files: the mean and the variance of the mean.
pub fn from_exr(mean: &[u8], variance: &[u8]) -> anyhow::Result<ImageStats> {
    let (width, height, mean) = decode(mean).context("the mean image")?;
    let (w2, h2, variance) = decode(variance).context("the variance image")?;
    anyhow::ensure!(
        (w2, h2) == (width, height),
        "mean and variance differ in size"
    );
    Ok(ImageStats {
        width,
        height,
        mean,
        variance,
    })
}

/// The stored reference render of `scene`, if there is one.
pub fn stored_reference(scene: &str) -> anyhow::Result<Option<ImageStats>> {
    let find = |kind: &str| {
        RENDER_FILES
            .iter()
            .find(|(name, _)| *name == format!("{scene}.{kind}"))
            .map(|(_, b)| *b)
    };
    let (Some(mean), Some(variance)) = (find("mean"), find("variance")) else {
        return Ok(None);
    };
    from_exr(mean, variance)
        .map(Some)
        .with_context(|| format!("tests/snapshots/renders/{scene}.*.exr"))
}

/// Writes `stats` as `<scene>.mean.exr` and `<scene>.variance.exr` into `dir`.
pub fn write_reference(dir: &Path, scene: &str, stats: &ImageStats) -> anyhow::Result<()> {
    std::fs::create_dir_all(dir)?;
    for (kind, data) in [("mean", &stats.mean), ("variance", &stats.variance)] {
        let img =
            image::Rgb32FImage::from_raw(stats.width as u32, stats.height as u32, data.clone())
                .context("image size does not match its pixels")?;
        let path = dir.join(format!("{scene}.{kind}.exr"));
        img.save(&path)
            .with_context(|| format!("writing {}", path.display()))?;
    }
    Ok(())
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

/// The grader's half: compares the worker's render of `scene` (`None` when none came back)
/// with the stored reference, and writes the pictures into `report_dir` when given.
pub fn judge(
    scene: &str,
    rendered: Option<&ImageOutputs>,
    report_dir: Option<&Path>,
) -> CheckResult {
    // One case, the render; it failed with `failure`.
    let failed = |failure: &dyn Fn(&mut CheckResult)| {
        let mut r = CheckResult::new(format!("image: {scene}"), super::verdict::CheckKind::Image);
        r.total = 1;
        failure(&mut r);
        r.finish();
        r
    };
    // Each of these says what went wrong with the render, nothing of the reference's.
    let fail = |message: String| failed(&|r: &mut CheckResult| r.fail_own(message.clone()));
    let reference = match stored_reference(scene) {
        Ok(Some(r)) => r,
        Ok(None) => return fail(format!("no stored reference render of {scene}")),
        Err(e) => return fail(format!("{e:#}")),
    };
    let Some(rendered) = rendered.filter(|r| r.scene == scene) else {
        return fail(format!(
            "{scene}: no render came back from the worker (it stopped before the render ended)"
        ));
    };
    let Rendered { stats, rejected } = match &rendered.outcome {
        Ok(Ok(r)) => r,
        Ok(Err(message)) => return fail(message.clone()),
        Err(p) => {
            return failed(&|r: &mut CheckResult| r.fail_panic(&format!("rendering {scene}"), p));
        }
    };
    let mut result = image_check::run(scene, stats, &reference, report_dir);
    if *rejected > 0 {
        let message = format!(
            "{scene}: {rejected} of {} samples were NaN, infinite or negative and had to be dropped",
            stats.width * stats.height * STUDENT_SPP as usize
        );
        result.fail_own(message);
        result.finish();
    }
    result.seconds = rendered.seconds;
    result
}

/// The render check of `scene` on `t` in this process: [`render_raw`] then [`judge`].
pub fn check<T: Tasks>(t: &T, scene: &str, seed: u64, report_dir: Option<&Path>) -> CheckResult {
    judge(scene, Some(&render_raw(t, scene, seed)), report_dir)
}
