//! Rendering a scene: samples per pixel in passes, bands of rows over rayon threads, a
//! progress bar, and the film's mean and variance images.
//!
//! Every pixel draws from its own random stream (`Sampler::new(seed, pixel index)`), kept
//! from one pass to the next and consumed in the same order whatever thread renders it, so
//! the same seed gives the same image bit for bit on any number of threads.

mod cpu_time;
mod film;
mod image;
pub mod output;
pub mod raycast;

pub use cpu_time::process_cpu_seconds;
pub use film::{Film, PixelSums};
pub use image::Image;

use crate::integrator;
use crate::sampling::Sampler;
use crate::scene::{Scene, take_ray_count};
use crate::worksheet::Tasks;
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use serde::Serialize;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Instant;

/// Rows per unit of parallel work.
const BAND_ROWS: usize = 4;

/// How to render.
pub struct RenderOptions<'a> {
    /// Samples per pixel.
    pub spp: u32,
    /// Seed of every pixel's random stream.
    pub seed: u64,
    /// Show a progress bar (with an ETA) on the terminal.
    pub progress: bool,
    /// Called after every pass with the film so far (to save the current estimate).
    pub on_pass: Option<&'a (dyn Fn(&Film) + Sync)>,
}

impl RenderOptions<'_> {
    /// The scene's own spp and seed, no progress bar, no callback.
    pub fn from_scene(scene: &Scene) -> Self {
        Self {
            spp: scene.settings().spp,
            seed: scene.settings().seed,
            progress: false,
            on_pass: None,
        }
    }
}

/// Counts and times of one render.
#[derive(Clone, Copy, Debug, Default, Serialize)]
pub struct RenderStats {
    /// Image width.
    pub width: u32,
    /// Image height.
    pub height: u32,
    /// Samples per pixel.
    pub spp: u32,
    /// Camera paths traced (pixels × spp).
    pub paths: u64,
    /// Rays cast (closest-hit and shadow rays).
    pub rays: u64,
    /// Samples dropped because they were NaN, infinite or negative.
    pub rejected_samples: u64,
    /// Wall-clock time, seconds.
    pub wall_seconds: f64,
    /// CPU time of the process during the render, seconds (all threads).
    pub cpu_seconds: f64,
    /// Threads of the rayon pool that rendered.
    pub threads: usize,
    /// Paths per wall-clock second.
    pub paths_per_second: f64,
    /// Paths per CPU-second: the throughput of one core.
    pub paths_per_cpu_second: f64,
    /// Rays per CPU-second.
    pub rays_per_cpu_second: f64,
}

/// The result of a render.
#[derive(Clone, Debug)]
pub struct RenderOutput {
    /// Every pixel's estimate (the mean of its samples).
    pub mean: Image,
    /// Every pixel's sample variance: the variance of *one* sample, per channel. The
    /// variance of a pixel's mean is this divided by `spp`.
    pub variance: Image,
    /// The film itself (per-pixel sums and counts).
    pub film: Film,
    /// Counts and times.
    pub stats: RenderStats,
}

/// The passes a render of `spp` samples is split into: 1, 1, 2, 4, 8, … (the last one
/// cut to what is left), so a picture appears early and is refined at a doubling pace.
pub fn pass_sizes(spp: u32) -> Vec<u32> {
    let mut sizes = Vec::new();
    let mut done = 0u32;
    let mut next = 1u32;
    while done < spp {
        let n = next.min(spp - done);
        sizes.push(n);
        done += n;
        if sizes.len() > 1 {
            next = next.saturating_mul(2);
        }
    }
    sizes
}

/// Renders `scene` with the task implementation `t` on the current rayon pool.
pub fn render<T: Tasks>(scene: &Scene, t: &T, options: &RenderOptions<'_>) -> RenderOutput {
    let camera = scene.camera();
    let (width, height) = (camera.width, camera.height);
    let mut film = Film::new(width, height);
    let mut samplers: Vec<Sampler> = (0..width as u64 * height as u64)
        .map(|i| Sampler::new(options.seed, i))
        .collect();
    let band = BAND_ROWS * width as usize;
    let total = width as u64 * height as u64 * options.spp as u64;
    let bar = if options.progress {
        let bar = ProgressBar::new(total);
        bar.set_style(
            ProgressStyle::with_template(
                "{elapsed_precise} [{bar:40}] {percent:>3}% {msg} ETA {eta_precise}",
            )
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> "),
        );
        bar
    } else {
        ProgressBar::hidden()
    };
    let rays = AtomicU64::new(0);
    let rejected = AtomicU64::new(0);
    let cpu_start = process_cpu_seconds();
    let start = Instant::now();
    let mut done_spp = 0;
    for pass in pass_sizes(options.spp) {
        // Samples per pixel finished so far (passes double, so the last pass is half the
        // work: naming the pass's target here read "1024/1024 spp" at 50 %).
        bar.set_message(format!("{done_spp}/{} spp done", options.spp));
        film.pixels
            .par_chunks_mut(band)
            .zip(samplers.par_chunks_mut(band))
            .enumerate()
            .for_each(|(b, (sums, band_samplers))| {
                take_ray_count();
                let mut local_rejected = 0;
                let first = b * band;
                for (i, (sum, sampler)) in sums.iter_mut().zip(band_samplers).enumerate() {
                    let index = first + i;
                    let (x, y) = (
                        (index % width as usize) as f32,
                        (index / width as usize) as f32,
                    );
                    for _ in 0..pass {
                        let offset = sampler.next_2d();
                        let ray = camera.ray(x + offset.x, y + offset.y);
                        let l = integrator::radiance(t, scene, ray, sampler);
                        if !sum.add(l) {
                            local_rejected += 1;
                        }
                    }
                }
                rays.fetch_add(take_ray_count(), Ordering::Relaxed);
                rejected.fetch_add(local_rejected, Ordering::Relaxed);
                bar.inc(sums.len() as u64 * pass as u64);
            });
        done_spp += pass;
        if let Some(callback) = options.on_pass {
            callback(&film);
        }
    }
    bar.finish_and_clear();
    let wall_seconds = start.elapsed().as_secs_f64();
    let threads = rayon::current_num_threads();
    let cpu_seconds = match (cpu_start, process_cpu_seconds()) {
        (Some(a), Some(b)) => b - a,
        _ => wall_seconds * threads as f64,
    };
    let paths = width as u64 * height as u64 * options.spp as u64;
    let rays = rays.into_inner();
    let per = |n: u64, s: f64| if s > 0.0 { n as f64 / s } else { 0.0 };
    let stats = RenderStats {
        width,
        height,
        spp: options.spp,
        paths,
        rays,
        rejected_samples: rejected.into_inner(),
        wall_seconds,
        cpu_seconds,
        threads,
        paths_per_second: per(paths, wall_seconds),
        paths_per_cpu_second: per(paths, cpu_seconds),
        rays_per_cpu_second: per(rays, cpu_seconds),
    };
    RenderOutput {
        mean: film.mean(),
        variance: film.variance(),
        film,
        stats,
    }
}
