//! Convergence studies of a scene file: the same scene rendered with every strategy it
//! supports, measured against a high-sample reference render.
//!
//! - Surface scenes (the `path_trace` and `mis` tasks): direct light by BSDF sampling,
//!   light sampling, and MIS with the balance and the power heuristic; when the scene
//!   has diffuse materials, also MIS with uniform instead of cosine-weighted hemisphere
//!   sampling on them.
//! - Scenes with media (the volumetric path tracer and the `delta_tracking` task): shadow-ray
//!   transmittance by ratio tracking, delta tracking, and the closed form where every
//!   medium is homogeneous.

use super::reference_cache::{ReferenceKey, cached_reference, rel_mse_floor, text_hash};
use super::{Estimate, Strategy, Study};
use crate::bsdf::HemisphereSampling;
use crate::render::{Image, RenderOptions, render};
use crate::scene::schema::{MisHeuristic, Strategy as DirectLight, TransmittanceEstimator};
use crate::scene::{LoadOptions, Scene};
use crate::worksheet::{TaskId, Tasks};
use anyhow::{Context, Result, anyhow};
use std::path::Path;

/// One way of rendering the scene: a name and the settings that select it.
#[derive(Clone, Debug, PartialEq)]
pub struct Variant {
    /// Name in the table, the CSV and the plot.
    pub name: &'static str,
    /// The settings that differ from the scene file's.
    pub options: LoadOptions,
}

/// The variants a scene supports; the first is the one the reference is rendered with
/// (the lowest-variance estimator available).
pub fn variants(scene: &Scene, base: &LoadOptions) -> Vec<Variant> {
    let with = |name, f: &dyn Fn(&mut LoadOptions)| {
        let mut options = base.clone();
        f(&mut options);
        Variant { name, options }
    };
    if scene.needs().media > 0 {
        let transmittance =
            |e: TransmittanceEstimator| move |o: &mut LoadOptions| o.transmittance = Some(e);
        return vec![
            with(
                "ratio_tracking",
                &transmittance(TransmittanceEstimator::Ratio),
            ),
            with(
                "delta_tracking",
                &transmittance(TransmittanceEstimator::Delta),
            ),
            with("analytic", &transmittance(TransmittanceEstimator::Analytic)),
        ];
    }
    let mis = |h: MisHeuristic| {
        move |o: &mut LoadOptions| {
            o.strategy = Some(DirectLight::Mis);
            o.heuristic = Some(h);
        }
    };
    let mut v = vec![
        with("mis_power", &mis(MisHeuristic::Power)),
        with("mis_balance", &mis(MisHeuristic::Balance)),
        with("bsdf", &|o| o.strategy = Some(DirectLight::Bsdf)),
        with("light", &|o| o.strategy = Some(DirectLight::Light)),
    ];
    if scene.needs().all_tasks().contains(TaskId::CosineSample) {
        v.push(with("mis_power_uniform_diffuse", &|o| {
            mis(MisHeuristic::Power)(o);
            o.diffuse_sampling = Some(HemisphereSampling::Uniform);
        }));
    }
    v
}

/// A scene with one variant's settings, rendered by one implementation.
pub struct SceneStrategy<T> {
    name: &'static str,
    scene: Scene,
    tasks: T,
}

impl<T: Tasks> Strategy for SceneStrategy<T> {
    fn name(&self) -> &str {
        self.name
    }

    fn estimate(&self, spp: u32, seed: u64) -> Result<Estimate> {
        let out = render(
            &self.scene,
            &self.tasks,
            &RenderOptions {
                spp,
                seed,
                progress: false,
                time_limit: None,
                on_pass: None,
            },
        );
        Ok(Estimate {
            values: flatten(&out.mean),
            dropped_samples: out.stats.rejected_samples,
        })
    }
}

/// An image's channels, pixel by pixel.
pub fn flatten(image: &Image) -> Vec<f32> {
    image.pixels.iter().flat_map(|p| p.to_array()).collect()
}

/// Where the reference comes from.
pub enum ReferenceSource<'a, R> {
    /// An EXR file of the right size (for example shipped with a handout).
    File(&'a Path),
    /// Rendered with `tasks` at `spp` samples per pixel, cached in the output folder.
    Render {
        /// The implementation that renders it (the reference solution when available).
        tasks: R,
        /// What to call it in the cache key (`reference`, `student`).
        label: &'static str,
        /// Samples per pixel.
        spp: u32,
    },
}

/// Seed of reference renders: unrelated to the study's seeds, so its noise is independent.
pub const REFERENCE_SEED: u64 = 0x5eed_f00d;

/// Builds the study of the scene at `path`: one strategy per [`variants`] entry, on `tasks`,
/// and the reference from `source` (cached in `out_dir`).
pub fn scene_study<T, R>(
    path: &Path,
    tasks: T,
    base: &LoadOptions,
    source: ReferenceSource<'_, R>,
    out_dir: &Path,
) -> Result<Study>
where
    T: Tasks + Clone + Send + 'static,
    R: Tasks,
{
    let load = |options: &LoadOptions| Scene::load(path, options).map_err(|e| anyhow!("{e}"));
    let scene = load(base)?;
    let all = variants(&scene, base);
    let mut strategies: Vec<Box<dyn Strategy>> = Vec::new();
    let mut reference_scene = None;
    for v in &all {
        // A variant the loader refuses (analytic transmittance through a grid) is skipped.
        let Ok(scene) = load(&v.options) else {
            continue;
        };
        if reference_scene.is_none() {
            reference_scene = Some((v.name, load(&v.options)?));
        }
        strategies.push(Box::new(SceneStrategy {
            name: v.name,
            scene,
            tasks: tasks.clone(),
        }));
    }
    let (reference_variant, reference_scene) =
        reference_scene.context("the scene supports no strategy")?;
    let camera = scene.camera();
    let (reference, floor, note) = match source {
        ReferenceSource::File(file) => {
            let image = super::reference_cache::read_exr(file)?;
            anyhow::ensure!(
                (image.width, image.height) == (camera.width, camera.height),
                "{} is {}×{}, the scene renders {}×{}",
                file.display(),
                image.width,
                image.height,
                camera.width,
                camera.height
            );
            (image, 0.0, format!("{}", file.display()))
        }
        ReferenceSource::Render { tasks, label, spp } => {
            let text = std::fs::read_to_string(path)
                .with_context(|| format!("cannot read {}", path.display()))?;
            let key = ReferenceKey {
                scene_hash: text_hash(&text),
                width: camera.width,
                height: camera.height,
                spp,
                seed: REFERENCE_SEED,
                renderer: format!("{label} {reference_variant}"),
                version: env!("CARGO_PKG_VERSION").into(),
            };
            let r = cached_reference(out_dir, &key, || {
                let options = RenderOptions {
                    spp,
                    seed: REFERENCE_SEED,
                    progress: true,
                    time_limit: None,
                    on_pass: None,
                };
                let out = render(&reference_scene, &tasks, &options);
                let floor = rel_mse_floor(&out.mean, &out.variance, spp);
                Ok((out.mean, floor))
            })?;
            let how = if r.cached { "cached" } else { "rendered" };
            let note = format!("{label} code, {reference_variant}, {spp} spp ({how})");
            (r.image, r.rel_mse_floor, note)
        }
    };
    Ok(Study {
        title: format!("{}: error against time", path.display()),
        strategies,
        reference: flatten(&reference),
        reference_floor: floor,
        reference_note: note,
    })
}
