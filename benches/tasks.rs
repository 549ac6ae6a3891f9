//! Per-function micro-benchmarks of the closed-form and sampling tasks, run on the
//! reference. Each benchmark evaluates one function over the same batch of random inputs,
//! so criterion's throughput is calls per second. `baseline/normalize` (one `Vec3`
//! normalisation per input) is measured in the same run: quote the other figures as
//! multiples of it, which survives a noisy, shared machine better than absolute times.
//!
//! `cargo bench -p pbrlab-benches --bench tasks` (add `-- reflect` to run the benchmarks whose name matches).

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::{Vec2, Vec3};
use pbrlab::bsdf::{KajiyaKayParams, PhongParams};
use pbrlab::optics::{LayerStack, Slab};
use pbrlab::sampling::{Sampler, uniform_hemisphere, uniform_sphere};
use pbrlab::worksheet::Tasks;
use pbrlab_solutions::TASKS as Reference;
use std::hint::black_box;
use std::time::Duration;

/// Inputs per benchmark iteration.
const BATCH: usize = 1024;

/// A fixed batch of inputs: directions above the surface, unit normals and points of
/// [0, 1)², all from one seeded sampler.
struct Inputs {
    wo: Vec<Vec3>,
    wi: Vec<Vec3>,
    normals: Vec<Vec3>,
    u: Vec<Vec2>,
    cos: Vec<f32>,
}

impl Inputs {
    fn new() -> Self {
        let mut s = Sampler::new(42, 0);
        let mut hemi = || {
            (0..BATCH)
                .map(|_| uniform_hemisphere(s.next_2d()))
                .collect::<Vec<_>>()
        };
        let (wo, wi) = (hemi(), hemi());
        let mut s = Sampler::new(43, 0);
        let normals = (0..BATCH).map(|_| uniform_sphere(s.next_2d())).collect();
        let u = (0..BATCH).map(|_| s.next_2d()).collect();
        let cos = (0..BATCH).map(|_| s.next_1d()).collect();
        Self {
            wo,
            wi,
            normals,
            u,
            cos,
        }
    }
}

fn benchmarks(c: &mut Criterion) {
    let t = Reference;
    let x = Inputs::new();
    let phong = PhongParams {
        kd: Vec3::splat(0.5),
        ks: Vec3::splat(0.4),
        exponent: 20.0,
    };
    let hair = KajiyaKayParams {
        kd: Vec3::splat(0.1),
        ks: Vec3::splat(0.9),
        exponent: 80.0,
    };
    let stack = LayerStack {
        eta_incident: 1.0,
        slabs: vec![Slab {
            eta: 1.5,
            thickness: 10.0,
        }],
        eta_exit: 1.33,
        intensity: 100.0,
    };
    let lambert = |_: Vec3, _: Vec3| std::f32::consts::FRAC_1_PI;
    let (wo, wi, n, u, cos) = (&x.wo, &x.wi, &x.normals, &x.u, &x.cos);

    let mut g = c.benchmark_group("tasks");
    g.throughput(Throughput::Elements(BATCH as u64))
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
        .sample_size(20);

    g.bench_function("baseline/normalize", |b| {
        b.iter(|| {
            n.iter()
                .map(|v| black_box(*v * 1.5).normalize())
                .fold(Vec3::ZERO, |a, v| a + v)
        })
    });
    g.bench_function("reflect", |b| {
        b.iter(|| {
            (0..BATCH)
                .map(|k| t.reflect(black_box(wo[k]), n[k]))
                .fold(Vec3::ZERO, |a, v| a + v)
        })
    });
    g.bench_function("refract", |b| {
        b.iter(|| {
            (0..BATCH)
                .filter_map(|k| t.refract(black_box(wi[k]), Vec3::Z, 1.5, 1.0))
                .count()
        })
    });
    g.bench_function("critical_angle", |b| {
        b.iter(|| {
            (0..BATCH)
                .filter_map(|k| t.critical_angle(black_box(1.0 + cos[k] as f64), 1.0))
                .sum::<f64>()
        })
    });
    g.bench_function("refract_stack", |b| {
        b.iter(|| {
            (0..BATCH)
                .map(|k| {
                    t.refract_stack(black_box(cos[k] as f64 * 89.0), &stack)
                        .transmitted_exact
                })
                .sum::<f64>()
        })
    });
    g.bench_function("schlick_r0", |b| {
        b.iter(|| {
            (0..BATCH)
                .map(|k| t.schlick_r0(black_box(1.0 + cos[k]), 1.5))
                .sum::<f32>()
        })
    });
    g.bench_function("fresnel_schlick", |b| {
        b.iter(|| {
            (0..BATCH)
                .map(|k| t.fresnel_schlick(black_box(cos[k]), 1.5, 1.0))
                .sum::<f32>()
        })
    });
    g.bench_function("cosine_sample", |b| {
        b.iter(|| {
            (0..BATCH)
                .map(|k| t.cosine_sample(black_box(u[k])))
                .fold(Vec3::ZERO, |a, v| a + v)
        })
    });
    g.bench_function("cosine_pdf", |b| {
        b.iter(|| {
            (0..BATCH)
                .map(|k| t.cosine_pdf(black_box(wi[k])))
                .sum::<f32>()
        })
    });
    g.bench_function("smith_g1", |b| {
        b.iter(|| {
            (0..BATCH)
                .map(|k| t.smith_g1(black_box(wi[k]), 0.3))
                .sum::<f32>()
        })
    });
    g.bench_function("cook_torrance", |b| {
        b.iter(|| {
            (0..BATCH)
                .map(|k| t.cook_torrance(black_box(wo[k]), wi[k], 0.2, 0.4, Vec3::splat(0.04)))
                .fold(Vec3::ZERO, |a, v| a + v)
        })
    });
    g.bench_function("aniso_ndf", |b| {
        b.iter(|| {
            (0..BATCH)
                .map(|k| t.aniso_ndf(black_box(wi[k]), 0.2, 0.4))
                .sum::<f32>()
        })
    });
    g.bench_function("phong", |b| {
        b.iter(|| {
            (0..BATCH)
                .map(|k| t.phong(black_box(wo[k]), wi[k], &phong))
                .fold(Vec3::ZERO, |a, v| a + v)
        })
    });
    g.bench_function("kajiya_kay", |b| {
        b.iter(|| {
            (0..BATCH)
                .map(|k| t.kajiya_kay(black_box(wo[k]), wi[k], n[k], &hair))
                .fold(Vec3::ZERO, |a, v| a + v)
        })
    });
    g.bench_function("beckmann_ndf", |b| {
        b.iter(|| {
            (0..BATCH)
                .map(|k| t.beckmann_ndf(black_box(wi[k]), 0.3))
                .sum::<f32>()
        })
    });
    g.bench_function("ndf_sample", |b| {
        b.iter(|| {
            (0..BATCH)
                .filter_map(|k| t.ndf_sample(black_box(wo[k]), 0.2, 0.4, u[k]))
                .count()
        })
    });
    g.bench_function("ndf_pdf", |b| {
        b.iter(|| {
            (0..BATCH)
                .map(|k| t.ndf_pdf(black_box(wo[k]), wi[k], 0.2, 0.4))
                .sum::<f32>()
        })
    });
    g.bench_function("framework/uniform_hemisphere", |b| {
        b.iter(|| {
            (0..BATCH)
                .map(|k| uniform_hemisphere(black_box(u[k])))
                .fold(Vec3::ZERO, |a, v| a + v)
        })
    });
    g.finish();

    // Whole-estimator tasks: one call each, no per-input throughput.
    let mut g = c.benchmark_group("checkers");
    g.warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
        .sample_size(20);
    g.bench_function("reciprocity_gap_64_pairs", |b| {
        b.iter(|| t.reciprocity_gap(&lambert, &mut Sampler::new(black_box(1), 0), 64))
    });
    g.bench_function("brdf_check_64_samples", |b| {
        b.iter(|| {
            t.brdf_check(&lambert, &mut Sampler::new(black_box(1), 0), 64)
                .max_albedo
        })
    });
    g.finish();
}

criterion_group!(benches, benchmarks);
criterion_main!(benches);
