//! The render check's grader half: a student's render, made in a worker
//! ([`super::renders::render_raw`]), judged pixel by pixel against the stored reference
//! render ([`super::image_check`]). The reference renders are stored as EXR files (mean, and
//! variance of the mean) in `src/grader/renders/`, embedded at build time like the
//! expected data, so the handout grades renders without solutions; the instructor test
//! `tests/instructor/renders.rs` writes them and checks them against fresh reference
//! renders. Nothing here is reachable from a worker.

use super::image_check::{self, ImageStats};
use super::renders::{STUDENT_SPP, render_raw};
use super::verdict::CheckResult;
use super::wire::{ImageOutputs, Rendered};
use crate::worksheet::Tasks;
use anyhow::Context;
use std::path::Path;

include!(concat!(env!("OUT_DIR"), "/render_files.rs"));

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
        .with_context(|| format!("src/grader/renders/{scene}.*.exr"))
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
    let mut result = image_result(scene, stats, &reference, report_dir);
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

/// The image check of one render: compares `student` with `reference` and, given a report
/// directory, writes its pictures and values there for the HTML page ([`super::report::images`]).
pub(super) fn image_result(
    name: &str,
    student: &ImageStats,
    reference: &ImageStats,
    report_dir: Option<&Path>,
) -> CheckResult {
    let start = std::time::Instant::now();
    let mut result = CheckResult::new(format!("image: {name}"), super::verdict::CheckKind::Image);
    result.total = 1;
    result.alpha = image_check::ALPHA;
    match image_check::compare(name, student, reference) {
        // The sizes, which the scene file gives.
        Err(message) => result.fail_own(message),
        Ok((mut detail, z)) => {
            if let Some(dir) = report_dir {
                match super::report::images::write_pictures(dir, name, student, reference, &z) {
                    Ok(files) => detail.files = files,
                    Err(e) => result.summary = format!("(images not written: {e:#}) "),
                }
            }
            result.summary += &detail.describe();
            for violation in detail.violations() {
                result.fail(
                    violation,
                    format!("{name}: the render does not match the reference within noise"),
                );
            }
            result.detail = Some(super::verdict::Detail::Image(detail));
        }
    }
    result.finish();
    result.seconds = start.elapsed().as_secs_f64();
    result
}
