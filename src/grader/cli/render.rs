use crate::grade::isolation::Launcher;
use crate::grade::sandbox::{self, Policy, Protections};
use crate::implementation::{Attempt, ImplChoice, PROBE_TIMEOUT, probe_student, student};
use crate::panics::QuietPanics;
use crate::render::checkpoint::{self, Origin};
use crate::render::{self, RenderOptions, RenderOutput, RenderState, output, raycast};
use crate::scene::schema::Strategy;
use crate::scene::{LoadOptions, Scene};
use anyhow::{Context, Result, anyhow, bail};
use std::path::{Path, PathBuf};
use std::sync::{Condvar, Mutex, MutexGuard, PoisonError};
use std::time::{Duration, Instant};

/// The scene `pbrlab render` renders when none is given.
pub const DEFAULT_SCENE: &str = "scenes/cornell.yaml";

/// Arguments of `pbrlab render`.
#[derive(clap::Args, Debug, Default)]
pub struct Args {
    /// The scene file (default: scenes/cornell.yaml).
    pub scene: Option<PathBuf>,
    /// Whose task code renders: `student` (yours), `mixed` (yours where written, the
    /// reference elsewhere) or `reference`; by default the reference where this build has
    /// it, otherwise yours. In the handout, `mixed` and `reference` take the compiled
    /// reference (tools/reference/).
    #[arg(long = "impl", value_enum)]
    pub implementation: Option<ImplChoice>,
    /// Samples per pixel (overrides the scene's; with --resume, the new total).
    #[arg(long)]
    pub spp: Option<u32>,
    /// Continue the render that left its checkpoint beside the output
    /// (`renders/SCENE.checkpoint`, saved as the render goes and at its end): killed or
    /// finished with fewer samples, it goes on to --spp and gives the image an
    /// uninterrupted render gives.
    #[arg(long)]
    pub resume: bool,
    /// Start no new pass after this much wall time (`90s`, `10m`, `2h`; a bare number is
    /// seconds): the image then has the samples that fitted, and --resume can add more.
    #[arg(long, value_parser = parse_duration)]
    pub time: Option<Duration>,
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

/// A duration as `--time` takes it: a number of seconds, or one with the unit s, m or h.
fn parse_duration(text: &str) -> Result<Duration, String> {
    let text = text.trim();
    let (number, unit) = match text.char_indices().last() {
        Some((i, c)) if c.is_ascii_alphabetic() => (&text[..i], c),
        _ => (text, 's'),
    };
    let scale = match unit {
        's' => 1.0,
        'm' => 60.0,
        'h' => 3600.0,
        _ => return Err(format!("`{text}`: the units are s, m and h")),
    };
    let value: f64 = number
        .trim()
        .parse()
        .map_err(|_| format!("`{text}` is not a duration such as 90s, 10m or 2h"))?;
    if !(value.is_finite() && value > 0.0) {
        return Err(format!("`{text}`: a duration must be positive"));
    }
    Duration::try_from_secs_f64(value * scale).map_err(|e| format!("`{text}`: {e}"))
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
        // (The worker that runs this for `pbrlab` loads the reference only for a mix.)
        let what_to_do =
            if cfg!(feature = "solutions") || crate::implementation::try_reference().is_some() {
                "Use `--impl reference` for the reference alone, or `--impl mixed` to take the \
             reference for those tasks only."
                    .to_string()
            } else {
                let pbrlab = super::invocation();
                format!(
                    "Write those first: `{pbrlab} tasks` shows what is left, `{pbrlab} hint TASK` \
                 helps."
                )
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
        // Its own process, as its user: a per-user thread limit would count the user's
        // every process.
        threads: 0,
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
    let choice = args
        .implementation
        .unwrap_or(if cfg!(feature = "solutions") {
            ImplChoice::Reference
        } else {
            ImplChoice::Student
        });
    // Student code runs in `pbrlab-student`: the scene is checked here first, so that a
    // mistake in it is reported before any build.
    if choice != ImplChoice::Reference && !crate::implementation::links_student() {
        return super::delegate::delegate();
    }
    for w in scene.warnings() {
        eprintln!("warning: {w}");
    }
    let output_path = args.output.clone().unwrap_or_else(|| {
        let stem = path
            .file_stem()
            .map_or("render".into(), |s| s.to_string_lossy().into_owned());
        PathBuf::from("renders").join(format!("{stem}.exr"))
    });
    if choice != ImplChoice::Student && crate::implementation::try_reference().is_none() {
        bail!(
            "{}: use `--impl student`",
            crate::implementation::no_reference()
        )
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
    // What a checkpoint must match to be continued, and the state it holds (read now:
    // a sandboxed render reads nothing).
    let origin = Origin {
        scene: std::fs::read_to_string(&path)
            .with_context(|| format!("reading {}", path.display()))?,
        seed: scene.settings().seed,
        settings: format!(
            "{:?}",
            // The seed is compared on its own; the target spp may grow.
            crate::scene::RenderSettings {
                spp: 0,
                seed: 0,
                ..*scene.settings()
            }
        ),
        implementation: format!("{choice:?}").to_lowercase(),
        width: scene.camera().width,
        height: scene.camera().height,
    };
    let checkpoint_path = checkpoint::path_for(&output_path);
    let start = if args.resume && checkpoint_path.is_file() {
        let state = checkpoint::load(&checkpoint_path, &origin)?;
        if args.spp.is_none() && state.spp_done >= scene.settings().spp {
            bail!(
                "{} already has {} spp, the scene's {} or more: pass the new total with \
                 --spp, e.g. `--resume --spp {}`",
                checkpoint_path.display(),
                state.spp_done,
                scene.settings().spp,
                state.spp_done.saturating_mul(2)
            );
        }
        eprintln!(
            "resuming {} at {}/{} spp",
            checkpoint_path.display(),
            state.spp_done,
            scene.settings().spp
        );
        state
    } else {
        if args.resume {
            eprintln!(
                "no checkpoint at {}: starting afresh",
                checkpoint_path.display()
            );
        }
        RenderState::new(origin.width, origin.height, origin.seed)
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
        checkpoint: (&checkpoint_path, &origin),
        progress: !args.quiet,
        time_limit: args.time,
    };
    // The reference alone renders with its functions called directly where this binary
    // links it; any student code stays behind the table.
    let direct = match choice {
        ImplChoice::Reference => crate::implementation::reference_render(),
        ImplChoice::Student | ImplChoice::Mixed => None,
    };
    let out = pool.install(|| match direct {
        Some(render) => job.run(|options, state| render(&scene, options, state), start),
        None => job.run(
            |options, state| render::render_from(&scene, &table, options, state),
            start,
        ),
    })?;
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
    if s.spp < scene.settings().spp
        && let Some(limit) = args.time
    {
        println!(
            "stopped by --time {:?} at {} of {} spp; `--resume` continues the render",
            limit,
            s.spp,
            scene.settings().spp
        );
    }
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

/// One render from the command line: progress, the image and a checkpoint saved after
/// passes (see [`SAVE_SPACING`]) and at the end, panics reported.
struct Job<'a> {
    scene: &'a Scene,
    output: &'a Path,
    checkpoint: (&'a Path, &'a Origin),
    progress: bool,
    time_limit: Option<Duration>,
}

/// A pass's estimate is saved when at least this many times the last save's duration has
/// gone by since that save ended, so saving (PNG filtering, EXR compression, the
/// checkpoint) takes at most 1/20 of a render's CPU time (saving every pass took 6–17 % of
/// a short one). The first pass is always saved, and the last one at the end.
const SAVE_SPACING: u32 = 19;

/// The saves of one render. A pass hands its estimate to a saver thread and the render
/// goes on. Saved on the pass's own thread, the other render threads sat idle meanwhile:
/// two threads kept 1.90–1.92 CPUs busy on cornell, and 1.94–1.96 with the saver thread.
#[derive(Default)]
struct Saves {
    /// When the last save ended, and how long it took.
    last: Option<(Instant, Duration)>,
    /// A state handed to the saver and not taken yet.
    pending: Option<RenderState>,
    /// The saver is writing a state.
    writing: bool,
    /// The render has ended: the saver stops when nothing is pending.
    ended: bool,
    /// The state of the newest pass, when it was neither saved nor handed to the saver.
    unsaved: Option<RenderState>,
}

/// [`Saves`] shared by the passes and the saver thread.
#[derive(Default)]
struct Saver {
    saves: Mutex<Saves>,
    wake: Condvar,
}

impl Saver {
    fn lock(&self) -> MutexGuard<'_, Saves> {
        self.saves.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// After a pass: hands `state` to the saver when a save is due and none is under way,
    /// and keeps it as the unsaved state otherwise.
    fn pass(&self, state: &RenderState) {
        let mut saves = self.lock();
        let due = !saves.writing
            && saves.pending.is_none()
            && saves
                .last
                .is_none_or(|(end, took)| end.elapsed() >= took * SAVE_SPACING);
        if due {
            saves.pending = Some(state.clone());
            saves.unsaved = None;
            self.wake.notify_one();
        } else {
            saves.unsaved = Some(state.clone());
        }
    }

    /// The saver thread: writes each state handed to it with `write` until the render
    /// has ended and nothing is pending.
    fn run(&self, write: impl Fn(&RenderState) -> Result<()>) {
        loop {
            let state = {
                let mut saves = self.lock();
                while saves.pending.is_none() && !saves.ended {
                    saves = self
                        .wake
                        .wait(saves)
                        .unwrap_or_else(PoisonError::into_inner);
                }
                let Some(state) = saves.pending.take() else {
                    return;
                };
                saves.writing = true;
                state
            };
            let began = Instant::now();
            if let Err(e) = write(&state) {
                eprintln!("warning: could not save the current estimate: {e:#}");
            }
            let mut saves = self.lock();
            saves.last = Some((Instant::now(), began.elapsed()));
            saves.writing = false;
        }
    }

    /// The render has ended: the saver finishes what it was handed, then stops.
    fn end(&self) {
        self.lock().ended = true;
        self.wake.notify_one();
    }
}

impl Job<'_> {
    /// Renders from `start` with `render` (`render_from` for the chosen implementation).
    fn run(
        &self,
        render: impl FnOnce(&RenderOptions<'_>, RenderState) -> RenderOutput,
        start: RenderState,
    ) -> Result<RenderOutput> {
        let (checkpoint_path, origin) = self.checkpoint;
        let write = |state: &RenderState| {
            output::write_both(self.output, &state.film.mean())
                .and_then(|_| checkpoint::save(checkpoint_path, origin, state))
        };
        let saver = Saver::default();
        let save = |state: &RenderState| saver.pass(state);
        let options = RenderOptions {
            spp: self.scene.settings().spp,
            seed: self.scene.settings().seed,
            progress: self.progress,
            time_limit: self.time_limit,
            on_pass: Some(&save),
        };
        let rendered = std::thread::scope(|scope| {
            scope.spawn(|| saver.run(write));
            let rendered = catch_task_panic(|| render(&options, start));
            saver.end();
            rendered
        });
        // What the passes since the last save computed is kept, whether or not the render
        // finished.
        let unsaved = saver
            .saves
            .into_inner()
            .unwrap_or_else(PoisonError::into_inner)
            .unsaved;
        match rendered {
            Ok(out) => {
                output::write_both(self.output, &out.mean)?;
                if let Some(state) = unsaved {
                    checkpoint::save(checkpoint_path, origin, &state)?;
                }
                Ok(out)
            }
            Err(e) => {
                if let Some(state) = unsaved
                    && let Err(saving) = write(&state)
                {
                    eprintln!("warning: could not save the last estimate: {saving:#}");
                }
                Err(e)
            }
        }
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

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::mpsc;

    /// Waits at most 10 s for a message: a lost handover fails instead of hanging.
    fn receive<T>(from: &mpsc::Receiver<T>) -> T {
        from.recv_timeout(Duration::from_secs(10))
            .expect("the saver did not answer")
    }

    #[test]
    fn passes_go_on_while_the_saver_writes_and_the_last_one_is_kept() {
        let saver = Saver::default();
        let (started, saver_started) = mpsc::channel();
        let (release, released) = mpsc::channel::<()>();
        let written = Mutex::new(Vec::new());
        let (saver_ref, written_ref) = (&saver, &written);
        let mut last = RenderState::new(2, 2, 1);
        std::thread::scope(|scope| {
            scope.spawn(move || {
                saver_ref.run(|state: &RenderState| {
                    started.send(state.spp_done).unwrap();
                    if state.spp_done == 1 {
                        receive(&released);
                    }
                    written_ref.lock().unwrap().push(state.spp_done);
                    Ok(())
                })
            });
            // Ends the saver however this thread leaves the scope, so that a failed
            // assertion fails the test instead of leaving it waiting for the saver.
            struct EndOnDrop<'a>(&'a Saver);
            impl Drop for EndOnDrop<'_> {
                fn drop(&mut self) {
                    self.0.end();
                }
            }
            let _end = EndOnDrop(saver_ref);
            // The first pass is handed over; the passes during its save are kept, the
            // newest only.
            last.spp_done = 1;
            saver.pass(&last);
            assert_eq!(receive(&saver_started), 1);
            for spp in 2..=5 {
                last.spp_done = spp;
                saver.pass(&last);
            }
            let unsaved = saver.lock().unsaved.as_ref().map(|s| s.spp_done);
            assert_eq!(unsaved, Some(5));
            release.send(()).unwrap();
            // Once the spacing after that save has gone by, a pass is saved again.
            let deadline = Instant::now() + Duration::from_secs(10);
            while written.lock().unwrap().len() < 2 {
                assert!(Instant::now() < deadline, "no second save");
                std::thread::sleep(Duration::from_millis(2));
                last.spp_done += 1;
                saver.pass(&last);
            }
        });
        let written = written.into_inner().unwrap();
        assert!(written[0] == 1 && written[1] > 5, "{written:?}");
        // The last pass is written, or left for the end of the render.
        let unsaved = saver.saves.into_inner().unwrap().unsaved;
        assert!(
            written.last() == Some(&last.spp_done)
                || unsaved.map(|s| s.spp_done) == Some(last.spp_done),
            "{written:?}, last pass {}",
            last.spp_done
        );
    }

    #[test]
    fn durations_take_seconds_minutes_and_hours() {
        assert_eq!(parse_duration("90"), Ok(Duration::from_secs(90)));
        assert_eq!(parse_duration("1.5s"), Ok(Duration::from_millis(1500)));
        assert_eq!(parse_duration("10m"), Ok(Duration::from_secs(600)));
        assert_eq!(parse_duration("2h"), Ok(Duration::from_secs(7200)));
        for bad in ["", "5x", "-3s", "0", "nan", "h"] {
            assert!(parse_duration(bad).is_err(), "{bad}");
        }
    }
}
