//! Renderer benchmarks.
//!
//! - `cornell`: the Cornell box at 256×256, 64 spp, unbounded depth with Russian roulette
//!   from depth 5, rendered by the reference on one thread; the throughput is paths per
//!   second of that thread, and the paths per CPU-second (from the process's CPU time) are
//!   printed beside it.
//! - `raycast`: closest-hit rays through the scene layer and through obvhs directly, on the
//!   same BVH and the same rays (a dense trefoil knot mesh); the ratio is printed.
//!
//! Run with `cargo bench -p pbrlab-benches --bench render`.

mod render_benches {
    use criterion::{Criterion, Throughput, criterion_group};
    use pbrlab::render::raycast::{compare_with_obvhs, test_rays};
    use pbrlab::render::{RenderOptions, render};
    use pbrlab::scene::{LoadOptions, Scene};
    use pbrlab_solutions::TASKS as Reference;
    use std::fmt::Write as _;

    fn cornell(c: &mut Criterion) {
        let path = pbrlab::repository_root().join("scenes/cornell.yaml");
        let scene = Scene::load(&path, &LoadOptions::default()).expect("cornell");
        let s = scene.settings();
        assert_eq!(
            (
                scene.camera().width,
                scene.camera().height,
                s.spp,
                s.rr_depth
            ),
            (256, 256, 64, 5)
        );
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .unwrap();
        let options = RenderOptions::from_scene(&scene);
        let paths = 256 * 256 * 64;

        let out = pool.install(|| render(&scene, &Reference, &options));
        eprintln!(
            "cornell 256x256, 64 spp, unbounded depth, roulette from 5: {:.3} M paths per CPU-second \
             ({:.2} CPU-s, {:.2} rays per path)",
            out.stats.paths_per_cpu_second * 1e-6,
            out.stats.cpu_seconds,
            out.stats.rays as f64 / paths as f64
        );

        let mut group = c.benchmark_group("cornell");
        group.sample_size(10);
        group.throughput(Throughput::Elements(paths));
        group.bench_function("256x256_64spp_one_thread", |b| {
            b.iter(|| pool.install(|| render(&scene, &Reference, &options)))
        });
        group.finish();
    }

    /// A trefoil knot tube of `along × around` quads, as OBJ text.
    fn knot_obj(along: usize, around: usize) -> String {
        let curve = |t: f32| {
            glam::Vec3::new(
                t.sin() + 2.0 * (2.0 * t).sin(),
                t.cos() - 2.0 * (2.0 * t).cos(),
                -(3.0 * t).sin(),
            ) / 3.2
        };
        let mut obj = String::new();
        for i in 0..along {
            let t = std::f32::consts::TAU * i as f32 / along as f32;
            let tangent = (curve(t + 1e-3) - curve(t - 1e-3)).normalize();
            let side = tangent.cross(glam::Vec3::Z).normalize();
            let up = side.cross(tangent);
            for j in 0..around {
                let a = std::f32::consts::TAU * j as f32 / around as f32;
                let v = curve(t) + 0.18 * (a.cos() * side + a.sin() * up);
                writeln!(obj, "v {} {} {}", v.x, v.y, v.z).unwrap();
            }
        }
        for i in 0..along {
            for j in 0..around {
                let idx = |i: usize, j: usize| (i % along) * around + (j % around) + 1;
                let (a, b, c, d) = (idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1));
                writeln!(obj, "f {a} {b} {c}\nf {a} {c} {d}").unwrap();
            }
        }
        obj
    }

    fn raycast(c: &mut Criterion) {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("knot.obj"), knot_obj(1200, 48)).unwrap();
        let text = "camera: {eye: [0, 0, 3.2], target: [0, 0, 0], fov: 45, width: 256, height: 256}\n\
                    materials: {m: {diffuse: {albedo: 0.5}}}\n\
                    shapes: [mesh: {file: knot.obj, material: m}]\n\
                    lights: [environment: {radiance: 1}]\n";
        let file = dir.path().join("knot.yaml");
        std::fs::write(&file, text).unwrap();
        let scene = Scene::load(&file, &LoadOptions::default()).expect("knot");
        let rays = test_rays(&scene, 200_000, 1);

        let cmp = compare_with_obvhs(&scene, &rays, 7).expect("the scene has triangles");
        eprintln!(
            "raycast, {} triangles, {} rays: scene layer {:.2} M rays/s, obvhs directly {:.2} M rays/s, \
             ratio {:.1} % (hits {} vs {})",
            cmp.triangles,
            cmp.rays,
            cmp.scene_rays_per_second * 1e-6,
            cmp.obvhs_rays_per_second * 1e-6,
            cmp.ratio * 100.0,
            cmp.scene_hits,
            cmp.obvhs_hits
        );

        let mut group = c.benchmark_group("raycast");
        group.sample_size(20);
        group.throughput(Throughput::Elements(rays.len() as u64));
        group.bench_function("scene_layer", |b| {
            b.iter(|| rays.iter().filter(|r| scene.intersect(r).is_some()).count())
        });
        group.finish();
    }

    criterion_group!(benches, cornell, raycast);
}

criterion::criterion_main!(render_benches::benches);
