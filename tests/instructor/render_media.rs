//! Media: the reference `delta_tracking` samples the right distribution whatever the
//! majorant, the framework's transmittance estimators agree with the closed form, and the
//! volumetric path tracer conserves energy (a white scattering ball under a white sky is
//! invisible) and attenuates by Beer-Lambert.

use glam::Vec3;
use pbrlab::geometry::Ray;
use pbrlab::medium::{
    Coefficients, FreeFlight, Homogeneous, Medium, homogeneous_transmittance, ratio_tracking,
};
use pbrlab::render::{RenderOptions, render};
use pbrlab::sampling::Sampler;
use pbrlab::scene::schema::TransmittanceEstimator;
use pbrlab::scene::{LoadOptions, Scene};
use pbrlab::worksheet::Tasks;
use pbrlab_solutions::TASKS as Reference;
use std::path::Path;

/// A medium whose coefficients change halfway along z (the errata's slab medium M3), with
/// a loose majorant.
struct Slabs;

impl Medium for Slabs {
    fn coefficients(&self, p: Vec3) -> Coefficients {
        if p.z < 0.5 {
            Coefficients {
                sigma_a: 0.1,
                sigma_s: 0.9,
            }
        } else {
            Coefficients {
                sigma_a: 1.5,
                sigma_s: 0.5,
            }
        }
    }
    fn majorant(&self) -> f32 {
        2.0
    }
}

/// A homogeneous medium reporting a majorant `factor` times too large (still a bound).
struct Loose(Homogeneous, f32);

impl Medium for Loose {
    fn coefficients(&self, p: Vec3) -> Coefficients {
        self.0.coefficients(p)
    }
    fn majorant(&self) -> f32 {
        self.0.majorant() * self.1
    }
}

/// Frequencies of scatter, absorb and escape over `n` flights along the unit z segment.
fn frequencies(medium: &dyn Medium, n: usize) -> [f64; 3] {
    let mut counts = [0usize; 3];
    let mut sampler = Sampler::new(5, 1);
    let ray = Ray::new(Vec3::ZERO, Vec3::Z);
    for _ in 0..n {
        match Reference.delta_tracking(medium, &ray, 1.0, 10_000, &mut sampler) {
            FreeFlight::Scatter { t } => {
                assert!((0.0..1.0).contains(&t));
                counts[0] += 1
            }
            FreeFlight::Absorb { t } => {
                assert!((0.0..1.0).contains(&t));
                counts[1] += 1
            }
            FreeFlight::Escape => counts[2] += 1,
            FreeFlight::Exhausted => panic!("10 000 steps were not enough"),
        }
    }
    counts.map(|c| c as f64 / n as f64)
}

fn assert_close(got: f64, want: f64, n: usize, what: &str) {
    let se = (want * (1.0 - want) / n as f64).sqrt().max(1e-9);
    assert!(((got - want) / se).abs() < 4.5, "{what}: {got} vs {want}");
}

#[test]
fn delta_tracking_event_probabilities() {
    let n = 200_000;
    let half = Homogeneous {
        coefficients: Coefficients {
            sigma_a: 0.5,
            sigma_s: 0.5,
        },
    };
    for factor in [1.0, 2.0, 7.0] {
        let f = frequencies(&Loose(half, factor), n);
        let escape = (-1.0f64).exp();
        assert_close(f[2], escape, n, "escape");
        assert_close(f[0], (1.0 - escape) / 2.0, n, "scatter");
        assert_close(f[1], (1.0 - escape) / 2.0, n, "absorb");
    }
    // The errata's M3: scatter 0.449973, absorb 0.326897, escape 0.223130.
    let f = frequencies(&Slabs, n);
    assert_close(f[0], 0.449973, n, "M3 scatter");
    assert_close(f[1], 0.326897, n, "M3 absorb");
    assert_close(f[2], 0.223130, n, "M3 escape");
}

#[test]
fn delta_tracking_edge_cases() {
    let mut sampler = Sampler::new(1, 1);
    let ray = Ray::new(Vec3::ZERO, Vec3::Z);
    let empty = Homogeneous {
        coefficients: Coefficients::default(),
    };
    assert_eq!(
        Reference.delta_tracking(&empty, &ray, 1.0, 10, &mut sampler),
        FreeFlight::Escape
    );
    let nan = Loose(empty, f32::NAN);
    assert_eq!(
        Reference.delta_tracking(&nan, &ray, 1.0, 10, &mut sampler),
        FreeFlight::Escape
    );
    // A majorant far above σt: two steps cannot decide.
    let thin = Loose(
        Homogeneous {
            coefficients: Coefficients {
                sigma_a: 1e-3,
                sigma_s: 0.0,
            },
        },
        1e9,
    );
    assert_eq!(
        Reference.delta_tracking(&thin, &ray, 1.0, 2, &mut sampler),
        FreeFlight::Exhausted
    );
}

#[test]
fn ratio_tracking_matches_the_closed_form() {
    let fog = Homogeneous {
        coefficients: Coefficients {
            sigma_a: 0.7,
            sigma_s: 0.6,
        },
    };
    let truth = homogeneous_transmittance(1.3, 1.5) as f64;
    assert!((truth - (-1.95f64).exp()).abs() < 1e-6);
    let mut sampler = Sampler::new(2, 2);
    let ray = Ray::new(Vec3::ZERO, Vec3::X);
    let n = 100_000;
    let (mut sum, mut sum_sq) = (0.0f64, 0.0f64);
    for _ in 0..n {
        let t = ratio_tracking(&Loose(fog, 3.0), &ray, 1.5, 10_000, &mut sampler) as f64;
        sum += t;
        sum_sq += t * t;
    }
    let mean = sum / n as f64;
    let se = ((sum_sq / n as f64 - mean * mean) / n as f64).sqrt();
    assert!(((mean - truth) / se).abs() < 4.5, "{mean} vs {truth}");
}

fn ball_scene(medium: &str, options: LoadOptions) -> Scene {
    let text = format!(
        "camera: {{eye: [0, 0, 4], target: [0, 0, 0], fov: 30, width: 24, height: 24}}\n\
         render: {{spp: 64, rr_depth: 8}}\n\
         media: {{ball: {medium}}}\n\
         shapes: [sphere: {{center: [0, 0, 0], radius: 0.8, medium: ball}}]\n\
         lights: [environment: {{radiance: 1}}]\n"
    );
    Scene::from_yaml(Path::new("ball.yaml"), &text, &options).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn a_white_scattering_ball_under_a_white_sky_is_invisible() {
    for medium in [
        "{homogeneous: {sigma_a: 0, sigma_s: 3, g: 0.5}}",
        "{grid: {density: {cloud: {resolution: 12, seed: 1}}, sigma_a: 0, sigma_s: 6}}",
    ] {
        for estimator in [TransmittanceEstimator::Ratio, TransmittanceEstimator::Delta] {
            let options = LoadOptions {
                transmittance: Some(estimator),
                ..Default::default()
            };
            let scene = ball_scene(medium, options);
            let out = render(&scene, &Reference, &RenderOptions::from_scene(&scene));
            let (mut sum, mut var) = (0.0f64, 0.0f64);
            for (m, v) in out.mean.pixels.iter().zip(&out.variance.pixels) {
                sum += m.x as f64;
                var += v.x as f64 / out.stats.spp as f64;
            }
            let n = out.mean.pixels.len() as f64;
            let z = (sum / n - 1.0) / (var.sqrt() / n).max(1e-9);
            assert!(
                z.abs() < 4.5,
                "{medium} with {estimator:?}: mean {} ({z:.2} s.e.)",
                sum / n
            );
        }
    }
}

#[test]
fn an_absorbing_ball_follows_beer_lambert() {
    let scene = ball_scene(
        "{homogeneous: {sigma_a: 1.2, sigma_s: 0}}",
        LoadOptions::default(),
    );
    let out = render(&scene, &Reference, &RenderOptions::from_scene(&scene));
    let cam = scene.camera();
    // The central pixel: its rays cross the ball along almost a full diameter.
    let (x, y) = (cam.width / 2, cam.height / 2);
    let ray = cam.ray(x as f32 + 0.5, y as f32 + 0.5);
    let b = ray.origin.dot(ray.dir);
    let chord = 2.0 * (b * b - ray.origin.length_squared() + 0.64).sqrt();
    let want = (-1.2 * chord).exp();
    let got = out.mean.get(x, y).x;
    let se = (out.variance.get(x, y).x / out.stats.spp as f32).sqrt();
    // Edge rays of the pixel cross slightly shorter chords: allow for that too.
    assert!((got - want).abs() < 4.5 * se + 0.01, "{got} vs {want}");
}

/// Henyey-Greenstein sampling follows its own density: the mean cosine of the deflection
/// is g, and the sampled deflection cosines fall into bins in proportion to the integral of
/// the phase function over each bin.
#[test]
fn henyey_greenstein_sampling_matches_its_density() {
    use pbrlab::medium::HenyeyGreenstein;
    let wo = Vec3::new(0.3, -0.4, 0.866).normalize();
    for g in [-0.7f32, 0.0, 0.3, 0.9] {
        let phase = HenyeyGreenstein { g };
        let mut sampler = Sampler::new(8, 0);
        let n = 200_000;
        let bins = 20;
        let mut counts = vec![0usize; bins];
        let mut mean_cos = 0.0f64;
        for _ in 0..n {
            let wi = phase.sample(wo, sampler.next_2d());
            let cos = -wo.dot(wi);
            mean_cos += cos as f64 / n as f64;
            counts[(((cos + 1.0) / 2.0 * bins as f32) as usize).min(bins - 1)] += 1;
        }
        assert!(
            (mean_cos - g as f64).abs() < 0.01,
            "g = {g}: mean cosine {mean_cos}"
        );
        for (b, &count) in counts.iter().enumerate() {
            // ∫ p dω over the bin = 2π ∫ p(cos) dcos, by the midpoint rule on 50 points.
            let (lo, hi) = (
                -1.0 + 2.0 * b as f64 / bins as f64,
                -1.0 + 2.0 * (b + 1) as f64 / bins as f64,
            );
            let expected: f64 = (0..50)
                .map(|k| {
                    let c = lo + (hi - lo) * (k as f64 + 0.5) / 50.0;
                    let denom = 1.0 + (g * g) as f64 - 2.0 * g as f64 * c;
                    (1.0 - (g * g) as f64) / (2.0 * denom.powf(1.5)) * (hi - lo) / 50.0
                })
                .sum::<f64>()
                * n as f64;
            let z = (count as f64 - expected) / expected.max(1.0).sqrt();
            assert!(
                z.abs() < 5.0,
                "g = {g}, bin {b}: {count} samples, {expected:.0} expected"
            );
        }
        // The value the renderer evaluates agrees with the density sampled from.
        let wi = phase.sample(wo, glam::Vec2::new(0.37, 0.61));
        let c = -wo.dot(wi) as f64;
        let p = (1.0 - (g * g) as f64)
            / (4.0 * std::f64::consts::PI * (1.0 + (g * g) as f64 - 2.0 * g as f64 * c).powf(1.5));
        assert!((phase.eval(wo, wi) as f64 - p).abs() < 1e-4 * p.max(1.0));
    }
}
