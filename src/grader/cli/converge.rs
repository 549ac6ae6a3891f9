//! `pbrlab converge`: error against run time for every strategy a study supports.

use crate::converge::builtin::{BUILTIN, builtin};
use crate::converge::csv::write_csv;
use crate::converge::plot::plot_error_vs_time;
use crate::converge::scene_study::{ReferenceSource, scene_study};
use crate::converge::study::FLOOR_MARGIN;
use crate::converge::{Strategy, Study, StudyConfig, Summary, run_study_reporting, summarise};
use crate::implementation::ImplChoice;
use crate::scene::{LoadOptions, Scene};
use crate::stability::value::format_number;
use crate::worksheet::Tasks;
use anyhow::{Context, anyhow, bail};
use indicatif::{ProgressBar, ProgressStyle};
use std::path::{Path, PathBuf};

/// Arguments of `pbrlab converge`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// A scene file, or a built-in study (`irradiance`, `microfacet_albedo`).
    pub scene: String,
    /// Whose code the strategies run.
    #[arg(long = "impl", value_enum, default_value = "student")]
    pub implementation: ImplChoice,
    /// Folder for converge.csv, converge.png and converge.svg (created if missing).
    #[arg(long, default_value = "converge-out")]
    pub out: PathBuf,
    /// Largest samples per pixel; the levels double from --min-spp up to it (default: 32
    /// for a scene, 1024 for a built-in study).
    #[arg(long)]
    pub max_spp: Option<u32>,
    /// Samples per pixel of the first level.
    #[arg(long, default_value_t = 1)]
    pub min_spp: u32,
    /// Seed of the first run.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Independent runs per level: their mean relMSE gets a 95 % interval, and their spread
    /// splits the error into variance and bias (2 or more; 1 measures each level once).
    #[arg(long, default_value_t = 16, value_parser = clap::value_parser!(u32).range(1..))]
    pub runs: u32,
    /// Scene only: image width (overrides the scene's; smaller is faster).
    #[arg(long)]
    pub width: Option<u32>,
    /// Scene only: image height (overrides the scene's).
    #[arg(long)]
    pub height: Option<u32>,
    /// Scene only: the reference image (linear EXR of the scene's size) instead of
    /// rendering one.
    #[arg(long)]
    pub reference: Option<PathBuf>,
    /// Scene only: samples per pixel of the rendered reference (default: 16 × --max-spp).
    #[arg(long)]
    pub reference_spp: Option<u32>,
}

/// True when `scene` names a built-in study rather than a file.
fn is_builtin(scene: &str) -> bool {
    BUILTIN.iter().any(|(name, _)| *name == scene)
}

/// Builds the study: a built-in one, or the scene file's with its reference.
fn load_study<T: Tasks + Clone + Send + 'static>(
    tasks: T,
    args: &Args,
    max_spp: u32,
) -> anyhow::Result<Study> {
    if is_builtin(&args.scene) {
        return builtin(&args.scene, tasks);
    }
    let path = Path::new(&args.scene);
    if !path.is_file() {
        return builtin(&args.scene, tasks).with_context(|| {
            format!(
                "`{}` is neither a scene file nor a built-in study",
                args.scene
            )
        });
    }
    let base = LoadOptions {
        width: args.width,
        height: args.height,
        ..LoadOptions::default()
    };
    let spp = args.reference_spp.unwrap_or(max_spp.saturating_mul(16));
    if let Some(file) = &args.reference {
        return scene_study::<T, T>(path, tasks, &base, ReferenceSource::File(file), &args.out);
    }
    if let Some(reference) = crate::implementation::try_reference() {
        let source = ReferenceSource::Render {
            tasks: *reference,
            label: "reference",
            spp,
        };
        return scene_study(path, tasks, &base, source, &args.out);
    }
    eprintln!(
        "warning: {}: the reference is rendered with your own code, so a bias in it cannot \
         show (pass --reference FILE.exr)",
        crate::implementation::no_reference()
    );
    let source = ReferenceSource::Render {
        tasks: tasks.clone(),
        label: "student",
        spp,
    };
    scene_study(path, tasks, &base, source, &args.out)
}

/// Runs the study, writes the CSV and the plot, and prints the slope table.
pub fn run(args: Args) -> anyhow::Result<()> {
    if args.implementation != ImplChoice::Reference && !crate::implementation::links_student() {
        return super::delegate::delegate();
    }
    match args.implementation {
        ImplChoice::Student => {
            let path = Path::new(&args.scene);
            if path.is_file() {
                // Fail before the (long) reference render rather than at the first estimate.
                let scene =
                    Scene::load(path, &LoadOptions::default()).map_err(|e| anyhow!("{e}"))?;
                super::render::require_student_tasks(&scene, path)?;
            }
            sandbox(&args)?;
            run_with(*crate::implementation::student(), &args)
        }
        ImplChoice::Reference | ImplChoice::Mixed => {
            let Some(reference) = crate::implementation::try_reference() else {
                bail!(
                    "{}; use --impl student",
                    crate::implementation::no_reference()
                )
            };
            if args.implementation == ImplChoice::Reference {
                return run_with(*reference, &args);
            }
            let imp = crate::implementation::mixed(crate::implementation::student_written(
                &crate::grade::isolation::Launcher::current_exe()?,
            ));
            sandbox(&args)?;
            run_with(imp, &args)
        }
    }
}

/// Enters the sandbox before a study runs student code: the scene's folder, the scenes and a
/// given reference image readable, the output folder writable, no processes, no network.
fn sandbox(args: &Args) -> anyhow::Result<()> {
    use crate::grade::sandbox::{Policy, enter};
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("creating {}", args.out.display()))?;
    let folder = |p: &Path| match p.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let mut readable = vec![crate::repository_root().join("scenes")];
    let scene = Path::new(&args.scene);
    if scene.is_file() {
        readable.push(folder(scene));
    }
    readable.extend(args.reference.as_deref().map(folder));
    // The plot's font is read now: the sandbox closes the system's font folders.
    let _ = crate::converge::plot::ensure_font();
    let protections = enter(&Policy {
        memory_limit: 0,
        cpu_seconds: 0,
        // Its own process, as its user: a per-user thread limit would count the user's
        // every process.
        threads: 0,
        readable,
        writable: vec![args.out.clone()],
    });
    if !protections.complete() {
        eprintln!("warning: the study's sandbox is incomplete: {protections}");
    }
    Ok(())
}

fn run_with<T: Tasks + Clone + Send + 'static>(tasks: T, args: &Args) -> anyhow::Result<()> {
    let max_spp = args
        .max_spp
        .unwrap_or(if is_builtin(&args.scene) { 1024 } else { 32 });
    if args.min_spp == 0 || max_spp < args.min_spp {
        bail!(
            "need 1 ≤ --min-spp ≤ --max-spp (got {} and {max_spp})",
            args.min_spp
        );
    }
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("creating {}", args.out.display()))?;
    // Path tracing recurses once per bounce: give the threads the renderer's deep stacks.
    let pool = rayon::ThreadPoolBuilder::new()
        .stack_size(64 << 20)
        .build()
        .context("cannot start the worker threads")?;
    pool.install(|| study_with(tasks, args, max_spp))
}

fn study_with<T: Tasks + Clone + Send + 'static>(
    tasks: T,
    args: &Args,
    max_spp: u32,
) -> anyhow::Result<()> {
    let study = load_study(tasks, args, max_spp)?;
    let config = StudyConfig {
        min_spp: args.min_spp,
        max_spp,
        seed: args.seed,
        runs: args.runs,
    };
    let progress = ProgressBar::new(0).with_style(
        ProgressStyle::with_template("{elapsed_precise} [{bar:32}] {pos}/{len} {msg}")?
            .progress_chars("=> "),
    );
    let strategies: Vec<&dyn Strategy> = study.strategies.iter().map(|s| s.as_ref()).collect();
    let csv = args.out.join("converge.csv");
    // Saved after every level, so an interrupted study keeps the levels it finished.
    let mut save_error = None;
    let result = run_study_reporting(
        &strategies,
        &study.reference,
        &config,
        &progress,
        &mut |so_far| {
            if let Err(e) = write_csv(&csv, &so_far.points, study.reference_floor) {
                save_error.get_or_insert(e);
            }
        },
    )?;
    progress.finish_and_clear();
    if let Some(e) = save_error {
        return Err(e);
    }
    println!("{} (reference: {})", study.title, study.reference_note);
    if study.reference_floor > 0.0 {
        println!(
            "the reference's own noise adds about {} to every relMSE; levels within {FLOOR_MARGIN}× \
             of that are left out of the slopes",
            format_number(study.reference_floor)
        );
    }
    println!("wrote {}", csv.display());
    let (png, svg) = (args.out.join("converge.png"), args.out.join("converge.svg"));
    match plot_error_vs_time(&result.points, &study.title, &png, &svg) {
        Ok(()) => println!("wrote {} and {}", png.display(), svg.display()),
        Err(e) => eprintln!("warning: no plot: {e:#}"),
    }

    print_table(&summarise(&result.points, study.reference_floor));
    print_equal_time(&result.points);
    for f in &result.failures {
        eprintln!(
            "strategy {} failed at {} spp: {}",
            f.strategy, f.spp, f.message
        );
    }
    if result.points.is_empty() {
        bail!("every strategy failed");
    }
    Ok(())
}

/// One row per strategy: final error with its interval, the slope against spp,
/// efficiency (absolute and relative to the most efficient strategy), the time to unit
/// variance, and the verdict on bias.
fn print_table(summaries: &[Summary]) {
    let best = summaries
        .iter()
        .map(|s| s.efficiency)
        .filter(|e| e.is_finite())
        .fold(0.0, f64::max);
    println!(
        "\n{:<26} {:>26} {:>13} {:>12} {:>9} {:>13}  bias",
        "strategy", "final relMSE [95 %]", "slope vs spp", "efficiency", "relative", "t(var = 1)"
    );
    for s in summaries {
        let fitted = s.slope_spp.map_or(0, |f| f.points);
        let note = if s.non_finite > 0 {
            format!("{} NaN/inf values or dropped samples", s.non_finite)
        } else if let Some(b) = s.bias {
            if b.biased() {
                format!("BIASED: about {} (z = {:.1})", format_number(b.bias), b.z)
            } else if b.significant() {
                format!(
                    "possible, below the noise: about {} (z = {:.1}; raise --max-spp)",
                    format_number(b.bias),
                    b.z
                )
            } else {
                format!("none detected (z = {:.1})", b.z)
            }
        } else if fitted < 3 && s.at_floor > 0 {
            "at the reference's noise: raise --reference-spp".into()
        } else if fitted < 3 {
            "too few levels to judge: raise --max-spp".into()
        } else if s.flattening() {
            "flattening: biased? (--runs 16 tests it)".into()
        } else {
            "slope ≈ −1 (--runs 16 tests it)".into()
        };
        let (lo, hi) = s.final_interval;
        println!(
            "{:<26} {:>26} {:>13} {:>12} {:>9} {:>13}  {note}",
            s.strategy,
            format!(
                "{} [{}, {}]",
                format_number(s.final_rel_mse),
                format_number(lo),
                format_number(hi)
            ),
            s.slope_spp
                .map_or("—".into(), |f| format!("{:.2}", f.slope)),
            format_number(s.efficiency),
            if best > 0.0 {
                format!("{:.3}", s.efficiency / best)
            } else {
                "—".into()
            },
            s.time_to_unit_variance
                .map_or("—".into(), |t| format!("{} s", format_number(t))),
        );
    }
}

/// The relMSE of every strategy at the same wall time (the longest time every strategy
/// reached), read off its measured points on log-log axes: which strategy is better for a
/// given budget, which differs from which is better per sample.
fn print_equal_time(points: &[crate::converge::Point]) {
    let Some((time, table)) = crate::converge::study::equal_time(points) else {
        return;
    };
    println!("\nat equal time ({} s per estimate):", format_number(time));
    for (strategy, rel_mse) in &table {
        println!("  {strategy:<26} relMSE {}", format_number(*rel_mse));
    }
}
