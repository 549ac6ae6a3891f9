//! The same seed gives the same image bit for bit, whatever the number of threads: every
//! pixel has its own random stream.

use pbrlab::render::{RenderOptions, render};
use pbrlab::scene::{LoadOptions, Scene};
use pbrlab_solutions::TASKS as Reference;
use std::path::Path;

fn render_with_threads(threads: usize, seed: u64) -> Vec<glam::Vec3> {
    let path = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/cornell.yaml"));
    let options = LoadOptions {
        width: Some(40),
        height: Some(30),
        spp: Some(5),
        ..Default::default()
    };
    let scene = Scene::load(path, &options).expect("cornell loads");
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("thread pool");
    let mut opts = RenderOptions::from_scene(&scene);
    opts.seed = seed;
    pool.install(|| render(&scene, &Reference, &opts))
        .mean
        .pixels
}

#[test]
fn one_and_two_threads_give_identical_images() {
    let one = render_with_threads(1, 3);
    let two = render_with_threads(2, 3);
    assert!(
        one.iter()
            .zip(&two)
            .all(|(a, b)| a.to_array().map(f32::to_bits) == b.to_array().map(f32::to_bits))
    );
}

#[test]
fn another_seed_gives_another_image() {
    assert_ne!(render_with_threads(2, 3), render_with_threads(2, 4));
}

/// The 40×30 Cornell box at `spp`, seed 3.
fn small_cornell(spp: u32) -> Scene {
    let path = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/cornell.yaml"));
    let options = LoadOptions {
        width: Some(40),
        height: Some(30),
        spp: Some(spp),
        seed: Some(3),
        ..Default::default()
    };
    Scene::load(path, &options).expect("cornell loads")
}

fn bits(pixels: &[glam::Vec3]) -> Vec<[u32; 3]> {
    pixels
        .iter()
        .map(|p| p.to_array().map(f32::to_bits))
        .collect()
}

/// A render stopped after any pass, saved to a checkpoint file, loaded and continued, is
/// the uninterrupted render bit for bit.
#[test]
fn a_render_continued_from_a_checkpoint_is_the_uninterrupted_render() {
    use pbrlab::render::checkpoint::{self, Origin};
    use pbrlab::render::{RenderState, render_from};
    use std::sync::Mutex;
    let whole = render(
        &small_cornell(13),
        &Reference,
        &RenderOptions::from_scene(&small_cornell(13)),
    );
    let dir = tempfile::tempdir().unwrap();
    let origin = Origin {
        scene: "cornell".into(),
        seed: 3,
        settings: "test".into(),
        implementation: "reference".into(),
        width: 40,
        height: 30,
    };
    // Stopped after 1, 2, 4 and 8 samples per pixel (the passes' ends).
    for stop in [1, 2, 4, 8] {
        let first = small_cornell(stop);
        let saved = Mutex::new(None::<RenderState>);
        let keep = |state: &RenderState| *saved.lock().unwrap() = Some(state.clone());
        let options = RenderOptions {
            on_pass: Some(&keep),
            ..RenderOptions::from_scene(&first)
        };
        render(&first, &Reference, &options);
        let state = saved.into_inner().unwrap().expect("a pass ended");
        assert_eq!(state.spp_done, stop);
        let file = dir.path().join(format!("stop{stop}.checkpoint"));
        checkpoint::save(&file, &origin, &state).unwrap();
        let loaded = checkpoint::load(&file, &origin).unwrap();
        assert_eq!(loaded.film.pixels, state.film.pixels);
        let rest = small_cornell(13);
        let continued = render_from(&rest, &Reference, &RenderOptions::from_scene(&rest), loaded);
        assert_eq!(continued.stats.spp, 13);
        assert_eq!(continued.stats.paths, 40 * 30 * (13 - stop) as u64);
        assert_eq!(
            bits(&continued.mean.pixels),
            bits(&whole.mean.pixels),
            "stopped at {stop} spp"
        );
    }
    // A checkpoint of another render is refused, saying what differs.
    let other = Origin {
        seed: 4,
        ..origin.clone()
    };
    let err = checkpoint::load(&dir.path().join("stop1.checkpoint"), &other).unwrap_err();
    assert!(err.to_string().contains("the seed differs"), "{err}");
}

/// `pbrlab render` killed part-way and run again with `--resume` writes the image an
/// uninterrupted render writes.
#[test]
fn render_resume_after_a_kill_gives_the_uninterrupted_image() {
    use std::process::{Command, Stdio};
    use std::time::{Duration, Instant};
    let dir = tempfile::tempdir().unwrap();
    let cornell =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/cornell.yaml"))
            .unwrap();
    let scene = dir.path().join("small.yaml");
    std::fs::write(
        &scene,
        cornell
            .replace("width: 256", "width: 24")
            .replace("height: 256", "height: 18"),
    )
    .unwrap();
    let spp = "6000";
    let render = |out: &str, extra: &[&str]| {
        let mut c = Command::new(env!("CARGO_BIN_EXE_pbrlab"));
        c.arg("render")
            .arg(&scene)
            .args(["--spp", spp, "--threads", "1", "--quiet", "-o"])
            .arg(dir.path().join(out))
            .args(extra)
            .stdout(Stdio::null())
            .stderr(Stdio::piped());
        c
    };
    // Killed once its checkpoint holds a few passes, long before the end.
    let mut killed = render("killed.exr", &[]).spawn().unwrap();
    let checkpoint = dir.path().join("killed.checkpoint");
    let header = |path: &Path| -> Option<serde_json::Value> {
        let text = std::fs::read(path).ok()?;
        let line = text.split(|b| *b == b'\n').next()?;
        serde_json::from_slice(line).ok()
    };
    let start = Instant::now();
    loop {
        if let Some(h) = header(&checkpoint)
            && h["spp_done"].as_u64() >= Some(4)
        {
            break;
        }
        assert!(start.elapsed() < Duration::from_secs(60), "no checkpoint");
        assert!(
            killed.try_wait().unwrap().is_none(),
            "the render ended first"
        );
        std::thread::sleep(Duration::from_millis(2));
    }
    killed.kill().unwrap();
    killed.wait().unwrap();
    let at_kill = header(&checkpoint).unwrap()["spp_done"].as_u64().unwrap();
    assert!(at_kill < 6000, "killed at {at_kill} spp");
    let resumed = render("killed.exr", &["--resume"]).output().unwrap();
    let stderr = String::from_utf8_lossy(&resumed.stderr);
    assert!(resumed.status.success(), "{stderr}");
    assert!(stderr.contains("resuming"), "{stderr}");
    let whole = render("whole.exr", &[]).output().unwrap();
    assert!(whole.status.success());
    let read = |name: &str| {
        image::open(dir.path().join(name))
            .unwrap()
            .into_rgb32f()
            .into_raw()
            .into_iter()
            .map(f32::to_bits)
            .collect::<Vec<_>>()
    };
    assert_eq!(
        read("killed.exr"),
        read("whole.exr"),
        "killed at {at_kill} spp"
    );
}

/// Passes are saved only now and then, but a finished render's checkpoint holds its last
/// pass: `--resume` with the same samples per pixel has nothing left to do.
#[test]
fn a_finished_render_leaves_the_checkpoint_of_its_last_pass() {
    use std::process::Command;
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("furnace.exr");
    let render = |extra: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_pbrlab"))
            .arg("render")
            .arg(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/furnace.yaml"))
            .args(["--spp", "37", "--threads", "1", "--quiet", "-o"])
            .arg(&out)
            .args(extra)
            .output()
            .unwrap()
    };
    assert!(render(&[]).status.success());
    let text = std::fs::read(dir.path().join("furnace.checkpoint")).unwrap();
    let line = text.split(|b| *b == b'\n').next().unwrap();
    let header: serde_json::Value = serde_json::from_slice(line).unwrap();
    assert_eq!(header["spp_done"], 37, "{header}");
    let resumed = render(&["--resume"]);
    assert!(resumed.status.success());
}

#[test]
fn a_render_counts_the_rays_cast_in_a_reference_library() {
    use pbrlab::grade::worker::ImplSpec;
    use pbrlab::worksheet::TaskId;
    let scene = small_cornell(2);
    let options = RenderOptions {
        spp: 2,
        seed: 3,
        progress: false,
        time_limit: None,
        on_pass: None,
    };
    let linked = render(&scene, &Reference, &options).stats.rays;
    assert!(linked > 0);
    // The same render with path_trace from its library, which counts in its own copy of
    // the framework.
    let libraries = pbrlab::grade::references::for_spec(&ImplSpec::Reference).unwrap();
    let library = pbrlab::compiled_reference::load(&libraries["path_trace"])
        .unwrap()
        .expect("the path_trace library");
    let mixed = Reference.with_task(&library, TaskId::PathTrace);
    assert_eq!(render(&scene, &mixed, &options).stats.rays, linked);
}

/// The reference called directly (`pbrlab_solutions::Direct`, what `pbrlab render --impl
/// reference` uses, with every task inlined) renders what its table renders, bit for bit,
/// on scenes that between them use every material, light and medium kind and both BVHs.
#[test]
fn the_direct_reference_renders_what_its_table_renders() {
    for name in [
        "cornell",
        "materials",
        "glass",
        "knot",
        "hair",
        "smoke",
        "veach_mis",
    ] {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("scenes/{name}.yaml"));
        let options = LoadOptions {
            width: Some(24),
            height: Some(18),
            spp: Some(3),
            seed: Some(5),
            ..Default::default()
        };
        let scene = Scene::load(&path, &options).expect("a shipped scene loads");
        let opts = RenderOptions::from_scene(&scene);
        let table = render(&scene, &Reference, &opts);
        let direct = render(&scene, &pbrlab_solutions::Direct, &opts);
        assert_eq!(table.stats.rays, direct.stats.rays, "{name}");
        assert_eq!(
            bits(&table.mean.pixels),
            bits(&direct.mean.pixels),
            "{name}"
        );
    }
}
