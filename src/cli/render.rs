use crate::grade::isolation::Launcher;
use crate::grade::sandbox::{self, Policy, Protections};
use crate::implementation::{Attempt, ImplChoice, PROBE_TIMEOUT, probe_student, student};
use crate::panics::QuietPanics;
use crate::render::{self, Film, RenderOptions, RenderOutput, output, raycast};
use crate::scene::schema::Strategy;
use crate::scene::{LoadOptions, Scene};
use crate::worksheet::Tasks;
use anyhow::{Context, Result, anyhow, bail};
use std::path::{Path, PathBuf};

/// The scene `pbrlab render` renders when none is given.
pub const DEFAULT_SCENE: &str = "scenes/cornell.yaml";

/// Arguments of `pbrlab render`.
#[derive(clap::Args, Debug, Default)]
pub struct Args {
    /// The scene file (default: scenes/cornell.yaml).
    pub scene: Option<PathBuf>,
    /// Whose task code renders (one of the possible values below; by default the
    /// reference where this build has it, otherwise yours).
    #[arg(long = "impl", value_enum)]
    pub implementation: Option<ImplChoice>,
    /// Samples per pixel (overrides the scene's).
    #[arg(long)]
    pub spp: Option<u32>,
    /// Seed (overrides the scene's).
    #[arg(long)]
    pub seed: Option<u64>,
    /// Direct-light strategy (overrides the scene's).
    #[arg(long, value_enum)]
    pub strategy: Option<Strategy>,
    /// Output image: an EXR and a PNG preview beside it (default: renders/SCENE.exr).
    #[arg(short, long)]
    pub output: Option<PathBuf>,
    /// Write render statistics (paths per CPU-second, …) as JSON to this file.
    #[arg(long)]
    pub stats: Option<PathBuf>,
    /// Rendering threads (default: all cores).
    #[arg(long)]
    pub threads: Option<usize>,
    /// No progress bar.
    #[arg(long)]
    pub quiet: bool,
}

/// Finds the scene file: as given, or the default scene (also looked for beside the
/// crate's sources, so `cargo run` works from any directory).
fn scene_path(given: Option<&Path>) -> PathBuf {
    match given {
        Some(p) => p.to_path_buf(),
        None => {
            let local = PathBuf::from(DEFAULT_SCENE);
            if local.is_file() {
                local
            } else {
                crate::repository_root().join(DEFAULT_SCENE)
            }
        }
    }
}

/// Refuses, naming each task and why (not implemented, panicking, or not returning), when
/// the scene at `path` needs student code that cannot run yet.
pub fn require_student_tasks(scene: &Scene, path: &Path) -> Result<()> {
    let unusable: Vec<String> = probe_student(&Launcher::current_exe()?, scene.needs().all_tasks())
        .into_iter()
        .filter_map(|(t, attempt)| {
            let why = match attempt {
                Attempt::Written => return None,
                Attempt::NotAttempted => "not implemented yet".to_string(),
                Attempt::Panics(m) => format!("panics: {m}"),
                Attempt::Hangs => format!(
                    "did not return within {} s (an infinite loop?)",
                    PROBE_TIMEOUT.as_secs()
                ),
            };
            Some(format!("{t} (exercises/{t}.rs): {why}"))
        })
        .collect();
    if !unusable.is_empty() {
        let what_to_do = if crate::implementation::try_reference().is_some() {
            "Use `--impl reference` for the reference alone, or `--impl mixed` to take the \
             reference for those tasks only."
        } else {
            "Write those first: `pbrlab tasks` shows what is left, `pbrlab hint TASK` helps."
        };
        bail!(
            "{} needs tasks your code cannot run yet:\n  {}\n{what_to_do}",
            path.display(),
            unusable.join("\n  ")
        );
    }
    Ok(())
}

/// Enters the sandbox for a render of student code: nothing readable, the folders of the
/// image and of the statistics file writable (created first), no processes, no network.
fn sandbox_render(output: &Path, stats: Option<&Path>) -> Result<Protections> {
    let mut writable = Vec::new();
    for file in std::iter::once(output).chain(stats) {
        let dir = match file.parent() {
            Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
            _ => PathBuf::from("."),
        };
        std::fs::create_dir_all(&dir).with_context(|| format!("creating {}", dir.display()))?;
        writable.push(dir);
    }
    Ok(sandbox::enter(&Policy {
        memory_limit: 0,
        cpu_seconds: 0,
        readable: Vec::new(),
        writable,
    }))
}

/// Renders a scene from the command line.
pub fn run(args: Args) -> Result<()> {
    let path = scene_path(args.scene.as_deref());
    let options = LoadOptions {
        spp: args.spp,
        seed: args.seed,
        strategy: args.strategy,
        ..Default::default()
    };
    let scene = Scene::load(&path, &options).map_err(|e| anyhow!("{e}"))?;
    for w in scene.warnings() {
        eprintln!("warning: {w}");
    }
    let choice = args
        .implementation
        .unwrap_or(if cfg!(feature = "solutions") {
            ImplChoice::Reference
        } else {
            ImplChoice::Student
        });
    let output_path = args.output.clone().unwrap_or_else(|| {
        let stem = path
            .file_stem()
            .map_or("render".into(), |s| s.to_string_lossy().into_owned());
        PathBuf::from("renders").join(format!("{stem}.exr"))
    });
    if choice != ImplChoice::Student && crate::implementation::try_reference().is_none() {
        bail!("this build has no reference solutions: use `--impl student`")
    }
    // What renders: the student's code, the reference, or the reference with the tasks the
    // student has written (probed in workers, before the sandbox forbids new processes).
    let table = match choice {
        ImplChoice::Student => {
            require_student_tasks(&scene, &path)?;
            *student()
        }
        ImplChoice::Reference => *crate::implementation::reference(),
        ImplChoice::Mixed => {
            let mine = crate::implementation::student_written(&Launcher::current_exe()?);
            let used: Vec<&str> = scene
                .needs()
                .all_tasks()
                .iter()
                .filter(|t| mine.contains(*t))
                .map(crate::worksheet::TaskId::name)
                .collect();
            eprintln!(
                "your code renders: {}",
                if used.is_empty() {
                    "nothing yet (all reference)".into()
                } else {
                    used.join(", ")
                }
            );
            crate::implementation::mixed(mine)
        }
    };
    if choice != ImplChoice::Reference {
        // From here on this process runs student code: it may write the image and nothing
        // else (the scene is loaded, the probes ran in workers, no thread exists yet).
        let protections = sandbox_render(&output_path, args.stats.as_deref())?;
        if !protections.complete() {
            eprintln!("warning: the render's sandbox is incomplete: {protections}");
        }
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.threads.unwrap_or(0))
        .stack_size(64 << 20)
        .build()
        .context("cannot start the rendering threads")?;
    let job = Job {
        scene: &scene,
        output: &output_path,
        progress: !args.quiet,
    };
    let out = pool.install(|| job.run(&table))?;
    let s = &out.stats;
    if s.rejected_samples > 0 {
        eprintln!(
            "warning: {} samples were NaN, infinite or negative and were dropped",
            s.rejected_samples
        );
    }
    let (exr, png) = (
        output_path.with_extension("exr"),
        output_path.with_extension("png"),
    );
    println!("wrote {} and {}", exr.display(), png.display());
    println!(
        "{}×{} at {} spp in {:.2} s: {:.3} M paths/s, {:.3} M paths per CPU-second ({} threads, {:.1} M rays per CPU-second)",
        s.width,
        s.height,
        s.spp,
        s.wall_seconds,
        s.paths_per_second * 1e-6,
        s.paths_per_cpu_second * 1e-6,
        s.threads,
        s.rays_per_cpu_second * 1e-6
    );
    if let Some(stats_path) = &args.stats {
        // Scenes with meshes also report the ray-casting rate against obvhs alone.
        let rays = raycast::test_rays(&scene, 100_000, 1);
        let raycast = raycast::compare_with_obvhs(&scene, &rays, 5);
        if let Some(r) = &raycast {
            println!(
                "ray casting: {:.2} M rays/s through the scene ({} triangles and {} analytic \
                 shapes), {:.2} M rays/s through obvhs on the triangles alone: {:.1} %",
                r.scene_rays_per_second * 1e-6,
                r.triangles,
                scene.needs().analytic_shapes,
                r.obvhs_rays_per_second * 1e-6,
                r.ratio * 100.0
            );
        }
        let json = serde_json::json!({
            "scene": path.display().to_string(),
            "impl": format!("{choice:?}").to_lowercase(),
            "stats": s,
            "raycast_vs_obvhs": raycast,
        });
        std::fs::write(stats_path, serde_json::to_string_pretty(&json)?)
            .with_context(|| format!("cannot write {}", stats_path.display()))?;
    }
    Ok(())
}

/// One render from the command line: progress, checkpoints after passes, panics reported.
struct Job<'a> {
    scene: &'a Scene,
    output: &'a Path,
    progress: bool,
}

impl Job<'_> {
    fn run<T: Tasks>(&self, t: &T) -> Result<RenderOutput> {
        // Saving costs milliseconds and passes double in length, so every pass is saved:
        // an interrupted render keeps its last complete pass.
        let checkpoint = |film: &Film| {
            if let Err(e) = output::write_both(self.output, &film.mean()) {
                eprintln!("warning: could not save the current estimate: {e:#}");
            }
        };
        let options = RenderOptions {
            spp: self.scene.settings().spp,
            seed: self.scene.settings().seed,
            progress: self.progress,
            on_pass: Some(&checkpoint),
        };
        let out = catch_task_panic(|| render::render(self.scene, t, &options))?;
        output::write_both(self.output, &out.mean)?;
        Ok(out)
    }
}

/// Runs `f`, turning a panic (in task code, most likely) into an error that says where it
/// happened and that the last saved estimate is kept. The panic is re-raised on this thread
/// by rayon; where it happened comes from the panic hook ([`QuietPanics`]), which also keeps
/// a student panic from printing once per render thread.
fn catch_task_panic<R>(f: impl FnOnce() -> R) -> Result<R> {
    let quiet = QuietPanics::new();
    quiet.take_first();
    let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
    result.map_err(|payload| {
        let what = match quiet.take_first() {
            Some(p) => p.describe(),
            None => format!(
                "panicked: {}",
                crate::implementation::panic_message(payload.as_ref()).unwrap_or("(no message)")
            ),
        };
        anyhow!(
            "the render stopped: the code {what}. The image of the last complete pass (if one \
             completed) is kept."
        )
    })
}
