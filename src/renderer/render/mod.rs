//! Rendering a scene: samples per pixel in passes, runs of pixels over rayon threads, a
//! progress bar, and the film's mean and variance images.
//!
//! Every pixel draws from its own random stream (`Sampler::new(seed, pixel index)`), kept
//! from one pass to the next and consumed in the same order whatever thread renders it, so
//! the same seed gives the same image bit for bit on any number of threads.

pub mod checkpoint;
mod film;
mod image;
pub mod output;
pub mod raycast;
mod usage;

pub use film::{Film, PixelSums};
pub use image::Image;
pub use usage::{peak_resident_kib, process_cpu_seconds};

use crate::integrator;
use crate::sampling::Sampler;
use crate::scene::{Scene, take_ray_count};
use crate::worksheet::Tasks;
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use serde::Serialize;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

/// Paths per unit of parallel work, about: a pass is cut into runs of pixels of this many
/// paths (at most [`UNIT_ROWS`] rows), each a rayon job of its own. A pass waits for its
/// last unit while the other threads have nothing left, so units stay short late in a
/// render, when passes are long: with units of four rows, two threads sat idle for up to
/// 100 ms at the end of each pass of glass (4 % of the CPU time of a 4-second render).
const UNIT_PATHS: usize = 4096;

/// Rows per unit of parallel work at most (the first passes, of one sample per pixel).
const UNIT_ROWS: usize = 4;

/// How to render.
pub struct RenderOptions<'a> {
    /// Samples per pixel.
    pub spp: u32,
    /// Seed of every pixel's random stream.
    pub seed: u64,
    /// Show a progress bar (with an ETA) on the terminal.
    pub progress: bool,
    /// Wall time after which no new pass starts (passes are cut to fit what is left): the
    /// render then ends with fewer samples per pixel than `spp`.
    pub time_limit: Option<Duration>,
    /// Called after every pass with the state so far (to save the current estimate, or a
    /// checkpoint to continue from).
    pub on_pass: Option<&'a (dyn Fn(&RenderState) + Sync)>,
}

impl RenderOptions<'_> {
    /// The scene's own spp and seed, no progress bar, no time limit, no callback.
    pub fn from_scene(scene: &Scene) -> Self {
        Self {
            spp: scene.settings().spp,
            seed: scene.settings().seed,
            progress: false,
            time_limit: None,
            on_pass: None,
        }
    }
}

/// A render's estimate so far: the film, every pixel's random stream where it stopped,
/// the samples per pixel done and the samples dropped. Continuing it gives the image an
/// uninterrupted render gives, bit for bit (each pixel's samples are drawn and summed in
/// the same order however the passes are cut).
#[derive(Clone, Debug)]
pub struct RenderState {
    /// Every pixel's sums.
    pub film: Film,
    /// Every pixel's random stream (stream = pixel index).
    pub samplers: Vec<Sampler>,
    /// Samples per pixel done.
    pub spp_done: u32,
    /// Samples dropped so far because they were NaN, infinite or negative.
    pub rejected: u64,
}

impl RenderState {
    /// A render not started: an empty film and every stream at its start.
    pub fn new(width: u32, height: u32, seed: u64) -> Self {
        Self {
            film: Film::new(width, height),
            samplers: (0..width as u64 * height as u64)
                .map(|i| Sampler::new(seed, i))
                .collect(),
            spp_done: 0,
            rejected: 0,
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
    /// Samples per pixel of the image (earlier runs of a resumed render included).
    pub spp: u32,
    /// Camera paths traced by this run.
    pub paths: u64,
    /// Rays cast (closest-hit and shadow rays).
    pub rays: u64,
    /// Samples dropped because they were NaN, infinite or negative (earlier runs of a
    /// resumed render included).
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

/// Renders `scene` with the task implementation `t` on the current rayon pool.
pub fn render<T: Tasks>(scene: &Scene, t: &T, options: &RenderOptions<'_>) -> RenderOutput {
    let camera = scene.camera();
    let start = RenderState::new(camera.width, camera.height, options.seed);
    render_from(scene, t, options, start)
}

/// The size of the next pass: the schedule's `next`, cut to the samples left and, under a
/// time limit, to what the time left allows at the rate so far (0: stop).
fn next_pass(next: u32, left: u32, time: Option<(Duration, Duration, u32)>) -> u32 {
    let n = next.min(left);
    match time {
        Some((limit, elapsed, done)) if done > 0 => {
            let Some(remaining) = limit.checked_sub(elapsed) else {
                return 0;
            };
            let per_spp = elapsed.as_secs_f64() / done as f64;
            let fits = (remaining.as_secs_f64() / per_spp.max(1e-9)).floor();
            if fits < 1.0 {
                0
            } else {
                n.min(fits.min(u32::MAX as f64) as u32)
            }
        }
        Some((limit, elapsed, _)) if elapsed >= limit => 0,
        _ => n,
    }
}

/// Continues the render `state` of `scene` up to `options.spp` samples per pixel (or the
/// time limit) with the task implementation `t`, on the current rayon pool.
pub fn render_from<T: Tasks>(
    scene: &Scene,
    t: &T,
    options: &RenderOptions<'_>,
    mut state: RenderState,
) -> RenderOutput {
    let camera = scene.camera();
    let (width, height) = (camera.width, camera.height);
    let pixels = width as u64 * height as u64;
    let resumed_spp = state.spp_done;
    let bar = if options.progress {
        let bar = ProgressBar::new(pixels * options.spp.max(resumed_spp) as u64);
        bar.set_style(
            ProgressStyle::with_template(
                "{elapsed_precise} [{bar:40}] {percent:>3}% {msg} ETA {eta_precise}",
            )
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> "),
        );
        bar.set_position(pixels * resumed_spp as u64);
        bar.reset_eta();
        bar
    } else {
        ProgressBar::hidden()
    };
    let rays = AtomicU64::new(0);
    let mut rejected = AtomicU64::new(0);
    let cpu_start = process_cpu_seconds();
    let start = Instant::now();
    // Passes of 1, 1, 2, 4, 8, … samples (the last one cut to what is left), so a picture
    // appears early and is refined at a doubling pace; after 2^k samples the next pass has
    // 2^k, so a resumed render goes on at the pace it had.
    let mut next = resumed_spp.max(1);
    loop {
        let done_here = state.spp_done - resumed_spp;
        let time = options
            .time_limit
            .map(|limit| (limit, start.elapsed(), done_here));
        let pass = next_pass(next, options.spp.saturating_sub(state.spp_done), time);
        if pass == 0 {
            break;
        }
        // Samples per pixel finished so far (passes double, so the last pass is half the
        // work: naming the pass's target here read "1024/1024 spp" at 50 %).
        bar.set_message(format!("{}/{} spp done", state.spp_done, options.spp));
        let unit = (UNIT_PATHS / pass as usize).clamp(1, UNIT_ROWS * width as usize);
        state
            .film
            .pixels
            .par_chunks_mut(unit)
            .zip(state.samplers.par_chunks_mut(unit))
            .enumerate()
            .with_max_len(1)
            .for_each(|(u, (sums, unit_samplers))| {
                take_ray_count();
                let mut local_rejected = 0;
                let first = u * unit;
                for (i, (sum, sampler)) in sums.iter_mut().zip(unit_samplers).enumerate() {
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
        state.spp_done += pass;
        state.rejected += std::mem::take(rejected.get_mut());
        if state.spp_done > 1 {
            next = next.saturating_mul(2);
        }
        if let Some(callback) = options.on_pass {
            callback(&state);
        }
    }
    bar.finish_and_clear();
    let wall_seconds = start.elapsed().as_secs_f64();
    let threads = rayon::current_num_threads();
    let cpu_seconds = match (cpu_start, process_cpu_seconds()) {
        (Some(a), Some(b)) => b - a,
        _ => wall_seconds * threads as f64,
    };
    let paths = pixels * (state.spp_done - resumed_spp) as u64;
    let rays = rays.into_inner();
    let per = |n: u64, s: f64| if s > 0.0 { n as f64 / s } else { 0.0 };
    let stats = RenderStats {
        width,
        height,
        spp: state.spp_done,
        paths,
        rays,
        rejected_samples: state.rejected,
        wall_seconds,
        cpu_seconds,
        threads,
        paths_per_second: per(paths, wall_seconds),
        paths_per_cpu_second: per(paths, cpu_seconds),
        rays_per_cpu_second: per(rays, cpu_seconds),
    };
    RenderOutput {
        mean: state.film.mean(),
        variance: state.film.variance(),
        film: state.film,
        stats,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn passes_are_cut_to_the_samples_and_the_time_left() {
        let s = Duration::from_secs;
        assert_eq!(next_pass(8, 100, None), 8);
        assert_eq!(next_pass(8, 3, None), 3);
        // The first pass always runs; after 4 spp in 4 s, 6 s left fit 6 more.
        assert_eq!(next_pass(1, 100, Some((s(10), s(0), 0))), 1);
        assert_eq!(next_pass(8, 100, Some((s(10), s(4), 4))), 6);
        assert_eq!(next_pass(8, 100, Some((s(10), s(10), 4))), 0);
        assert_eq!(next_pass(8, 100, Some((s(10), s(9), 4))), 0);
    }
}
