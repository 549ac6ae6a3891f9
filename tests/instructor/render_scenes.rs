//! Every scene in scenes/ loads and renders a few samples with the reference; the image
//! files are written and read back; the built-in probe scene is valid.

use pbrlab::grade::argument::probe_scene;
use pbrlab::render::{RenderOptions, output, render};
use pbrlab::scene::{LoadOptions, Scene};
use pbrlab_solutions::TASKS as Reference;
use std::path::{Path, PathBuf};

fn scene_files() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("scenes/ exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "yaml"))
        .collect();
    files.sort();
    files
}

#[test]
fn the_expected_scenes_exist() {
    let names: Vec<String> = scene_files()
        .iter()
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    for wanted in [
        "cornell",
        "furnace",
        "materials",
        "glass",
        "hair",
        "smoke",
        "veach_mis",
        "knot",
    ] {
        assert!(
            names.iter().any(|n| n == wanted),
            "scenes/{wanted}.yaml is missing"
        );
    }
}

#[test]
fn every_scene_renders_a_few_samples() {
    for file in scene_files() {
        let options = LoadOptions {
            width: Some(24),
            height: Some(16),
            spp: Some(2),
            ..Default::default()
        };
        let scene = Scene::load(&file, &options).unwrap_or_else(|e| panic!("{e}"));
        assert!(
            scene.warnings().is_empty(),
            "{}: {:?}",
            file.display(),
            scene.warnings()
        );
        let out = render(&scene, &Reference, &RenderOptions::from_scene(&scene));
        assert_eq!(out.stats.rejected_samples, 0, "{}", file.display());
        let mean = out.mean.mean();
        assert!(
            mean.is_finite() && mean.max_element() > 0.0,
            "{}: mean {mean}",
            file.display()
        );
        assert_eq!(out.stats.paths, 24 * 16 * 2);
    }
}

#[test]
fn images_are_written_and_read_back() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/cornell.yaml");
    let options = LoadOptions {
        width: Some(12),
        height: Some(10),
        spp: Some(2),
        ..Default::default()
    };
    let scene = Scene::load(&path, &options).expect("cornell");
    let out = render(&scene, &Reference, &RenderOptions::from_scene(&scene));
    let dir = tempfile::tempdir().unwrap();
    let (exr, png) = output::write_both(&dir.path().join("sub/img.exr"), &out.mean).unwrap();
    let back = image::open(&exr).unwrap().into_rgb32f();
    assert_eq!((back.width(), back.height()), (12, 10));
    for (y, row) in back.rows().enumerate() {
        for (x, p) in row.enumerate() {
            assert_eq!(p.0, out.mean.get(x as u32, y as u32).to_array());
        }
    }
    let preview = image::open(&png).unwrap().into_rgb8();
    assert_eq!((preview.width(), preview.height()), (12, 10));
    // Only the two images are left in the directory: the temporary files were renamed.
    assert_eq!(
        std::fs::read_dir(dir.path().join("sub")).unwrap().count(),
        2
    );
}

#[test]
fn the_probe_scene_is_valid() {
    let scene = probe_scene();
    assert_eq!(scene.needs().lights, 1);
    let ray = pbrlab::geometry::Ray::new(glam::Vec3::new(0.0, 0.5, 0.3), -glam::Vec3::Y);
    assert!(scene.intersect(&ray).is_some());
    // The probe scene calls no closed-form task (uniform hemisphere sampling).
    let tasks: Vec<_> = scene.needs().tasks.iter().collect();
    assert_eq!(tasks, vec![pbrlab::worksheet::TaskId::PathTrace]);
}

#[test]
fn the_probes_of_the_integrator_tasks_run_the_reference() {
    use pbrlab::grade::probe::probe_task;
    use pbrlab::implementation::catch_quietly;
    use pbrlab::worksheet::TaskId;
    for task in [TaskId::PathTrace, TaskId::Mis, TaskId::DeltaTracking] {
        assert!(
            catch_quietly(|| probe_task(&Reference, task)).is_ok(),
            "{task}"
        );
    }
}

#[test]
fn strands_from_a_file() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("hair.txt"),
        "# two strands\n0 0 0\n0 0.5 0\n0.1 1 0\n\n0.3 0 0\n0.3 1 0.1\n",
    )
    .unwrap();
    let text = "camera: {eye: [0, 0.5, 3], target: [0, 0.5, 0], fov: 40, width: 16, height: 16}\n\
                materials: {hair: {kajiya_kay: {kd: 0.2, ks: 0.3, exponent: 30}}}\n\
                shapes: [fibres: {strands: {file: hair.txt}, radius: 0.02, material: hair}]\n\
                lights: [environment: {radiance: 1}]\n";
    let file = dir.path().join("s.yaml");
    std::fs::write(&file, text).unwrap();
    let scene = Scene::load(&file, &LoadOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(scene.needs().fibre_segments, 3);
    let out = render(&scene, &Reference, &RenderOptions::from_scene(&scene));
    assert!(out.mean.mean().max_element() > 0.0);
}

#[test]
#[ignore = "slow: every scene at its own resolution and sample count (15 s on two cores)"]
fn every_scene_renders_at_full_settings() {
    for file in scene_files() {
        let scene = Scene::load(&file, &LoadOptions::default()).unwrap_or_else(|e| panic!("{e}"));
        let out = render(&scene, &Reference, &RenderOptions::from_scene(&scene));
        assert_eq!(out.stats.rejected_samples, 0, "{}", file.display());
        let mean = out.mean.mean();
        assert!(
            mean.is_finite() && mean.min_element() > 0.0,
            "{}: mean {mean}",
            file.display()
        );
    }
}
