//! What each scene needs (tasks and subsystems), and what the renderer does with that:
//! builds only those parts, and refuses to render student code that is not written yet.

use pbrlab::scene::{LoadOptions, Scene};
use pbrlab::task_set::TaskSet;
use pbrlab::worksheet::TaskId;
use std::path::Path;
use std::process::Command;

fn load(name: &str) -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("scenes/{name}.yaml"));
    Scene::load(&path, &LoadOptions::default()).unwrap_or_else(|e| panic!("{e}"))
}

fn set(ids: &[TaskId]) -> TaskSet {
    ids.iter().copied().collect()
}

use TaskId::*;

#[test]
fn cornell() {
    let s = load("cornell");
    let n = s.needs();
    assert_eq!(n.tasks, set(&[PathTrace, CosineSample, Reflect]));
    assert_eq!(n.all_tasks(), set(&[PathTrace, Mis, CosineSample, Reflect]));
    assert_eq!(
        (n.triangles, n.fibre_segments, n.media, n.lights),
        (0, 0, 0, 1)
    );
    assert!(s.surfaces().triangles().is_none() && s.surfaces().fibres().is_none());
}

#[test]
fn furnace() {
    let n = *load("furnace").needs();
    assert_eq!(n.tasks, set(&[PathTrace, CosineSample]));
    assert_eq!(n.lights, 1);
}

#[test]
fn materials() {
    let n = *load("materials").needs();
    assert_eq!(
        n.tasks,
        set(&[
            PathTrace,
            CosineSample,
            CookTorrance,
            NdfSample,
            Phong,
            Reflect
        ])
    );
    assert!(n.all_tasks().contains(SmithG1) && n.all_tasks().contains(AnisoNdf));
}

#[test]
fn glass() {
    let n = *load("glass").needs();
    assert_eq!(
        n.tasks,
        set(&[PathTrace, CosineSample, Reflect, RefractStack])
    );
    // refract_stack's own dependency comes in through the task table.
    assert!(n.all_tasks().contains(FresnelSchlick));
}

#[test]
fn hair() {
    let s = load("hair");
    let n = s.needs();
    assert_eq!(n.tasks, set(&[PathTrace, CosineSample, KajiyaKay]));
    assert_eq!(n.fibre_segments, 4000 * 8);
    assert!(s.surfaces().fibres().is_some() && s.surfaces().triangles().is_none());
}

#[test]
fn smoke() {
    let n = *load("smoke").needs();
    assert_eq!(n.tasks, set(&[DeltaTracking, CosineSample]));
    assert!(!n.all_tasks().contains(PathTrace));
    assert_eq!(n.media, 3);
}

#[test]
fn veach_mis() {
    let n = *load("veach_mis").needs();
    assert_eq!(
        n.tasks,
        set(&[PathTrace, CosineSample, CookTorrance, NdfSample])
    );
    assert_eq!(n.lights, 5);
}

#[test]
fn knot() {
    let s = load("knot");
    let n = s.needs();
    assert_eq!(n.triangles, 96 * 12 * 2);
    assert!(s.surfaces().triangles().is_some());
    assert_eq!(
        n.tasks,
        set(&[PathTrace, CosineSample, CookTorrance, NdfSample])
    );
}

#[test]
fn a_scene_without_lights_builds_no_light_sampler() {
    let text = "camera: {eye: [0, 0, 5], target: [0, 0, 0], fov: 40, width: 8, height: 8}\nmaterials: {m: {diffuse: {albedo: 0.5, sampling: uniform}}}\nshapes:\n  - sphere: {center: [0, 0, 0], radius: 1, material: m}\n";
    let s = Scene::from_yaml(Path::new("dark.yaml"), text, &LoadOptions::default()).unwrap();
    assert_eq!(s.needs().lights, 0);
    assert_eq!(s.needs().tasks, set(&[PathTrace]));
    assert!(
        s.warnings()[0]
            .message
            .contains("nothing in the scene emits light")
    );
    let mut sampler = pbrlab::sampling::Sampler::new(0, 0);
    assert!(s.sample_light(glam::Vec3::ZERO, &mut sampler).is_none());
}

#[test]
fn the_needs_command_prints_tasks_and_subsystems() {
    let out = Command::new(env!("CARGO_BIN_EXE_pbrlab"))
        .args([
            "needs",
            concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/knot.yaml"),
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    for words in [
        "cook_torrance",
        "smith_g1",
        "triangle BVH:        yes (2304 triangles)",
        "fibre BVH:           no",
        "media:               no",
    ] {
        assert!(text.contains(words), "`{words}` missing from:\n{text}");
    }
}

#[test]
fn student_renders_stop_on_unwritten_tasks() {
    let launcher = pbrlab::grade::isolation::Launcher {
        program: crate::worker(),
        args: Vec::new(),
        env: Vec::new(),
    };
    let dir = tempfile::tempdir().unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_pbrlab"))
        .args([
            "render",
            concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/furnace.yaml"),
        ])
        .args(["--impl", "student", "--spp", "1", "--quiet", "-o"])
        .arg(dir.path().join("f.exr"))
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    let missing: Vec<TaskId> = load("furnace")
        .needs()
        .all_tasks()
        .iter()
        .filter(|t| !pbrlab::implementation::student_has_attempted(&launcher, *t))
        .collect();
    if missing.is_empty() {
        assert!(out.status.success(), "{stderr}");
    } else {
        assert!(!out.status.success());
        for t in missing {
            assert!(
                stderr.contains(&format!("{t} (exercises/{t}.rs)")),
                "{stderr}"
            );
        }
        assert!(
            !dir.path().join("f.exr").exists(),
            "nothing may be rendered"
        );
        // What to do next: the reference alone where the build has it, else the tasks left.
        assert!(
            stderr.contains("`--impl reference`") || stderr.contains(" tasks` shows what is left"),
            "{stderr}"
        );
    }
}
