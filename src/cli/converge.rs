//! `pbrlab converge`: error against run time for every strategy a study supports.

use crate::converge::builtin::builtin;
use crate::converge::csv::write_csv;
use crate::converge::plot::plot_error_vs_time;
use crate::converge::{Strategy, StudyConfig, Summary, run_study, summarise};
use crate::implementation::{ImplChoice, Student};
use crate::stability::value::format_number;
use crate::worksheet::Tasks;
use anyhow::{Context, bail};
use indicatif::{ProgressBar, ProgressStyle};
use std::path::PathBuf;

/// Arguments of `pbrlab converge`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// What to estimate: a built-in study (`irradiance`, `microfacet_albedo`).
    pub scene: String,
    /// Whose code the strategies run.
    #[arg(long = "impl", value_enum, default_value = "student")]
    pub implementation: ImplChoice,
    /// Folder for converge.csv, converge.png and converge.svg (created if missing).
    #[arg(long, default_value = "converge-out")]
    pub out: PathBuf,
    /// Largest samples per pixel; the levels double from --min-spp up to it.
    #[arg(long, default_value_t = 1024)]
    pub max_spp: u32,
    /// Samples per pixel of the first level.
    #[arg(long, default_value_t = 1)]
    pub min_spp: u32,
    /// Seed of the first level.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
}

/// Runs the study, writes the CSV and the plot, and prints the slope table.
pub fn run(args: Args) -> anyhow::Result<()> {
    match args.implementation {
        ImplChoice::Student => run_with(Student, &args),
        #[cfg(feature = "solutions")]
        ImplChoice::Reference => run_with(crate::implementation::Reference, &args),
        #[cfg(feature = "solutions")]
        ImplChoice::Mixed => {
            let imp = crate::implementation::Mixed::new(crate::implementation::student_attempted());
            run_with(imp, &args)
        }
        #[cfg(not(feature = "solutions"))]
        ImplChoice::Reference | ImplChoice::Mixed => {
            bail!("this build has no reference solutions; use --impl student")
        }
    }
}

fn run_with<T: Tasks + Clone + Send + 'static>(tasks: T, args: &Args) -> anyhow::Result<()> {
    if args.min_spp == 0 || args.max_spp < args.min_spp {
        bail!(
            "need 1 ≤ --min-spp ≤ --max-spp (got {} and {})",
            args.min_spp,
            args.max_spp
        );
    }
    let study = builtin(&args.scene, tasks)?;
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("creating {}", args.out.display()))?;
    let config = StudyConfig {
        min_spp: args.min_spp,
        max_spp: args.max_spp,
        seed: args.seed,
    };
    let progress = ProgressBar::new(0).with_style(
        ProgressStyle::with_template("{elapsed_precise} [{bar:32}] {pos}/{len} {msg}")?
            .progress_chars("=> "),
    );
    let strategies: Vec<&dyn Strategy> = study.strategies.iter().map(|s| s.as_ref()).collect();
    let result = run_study(&strategies, &study.reference, &config, &progress)?;
    progress.finish_and_clear();

    let csv = args.out.join("converge.csv");
    write_csv(&csv, &result.points)?;
    println!("{} (reference: {})", study.title, study.reference_note);
    println!("wrote {}", csv.display());
    let (png, svg) = (args.out.join("converge.png"), args.out.join("converge.svg"));
    match plot_error_vs_time(&result.points, &study.title, &png, &svg) {
        Ok(()) => println!("wrote {} and {}", png.display(), svg.display()),
        Err(e) => eprintln!("warning: no plot: {e:#}"),
    }

    print_table(&summarise(&result.points));
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

/// One row per strategy: final error, the two slopes, efficiency (absolute and relative
/// to the most efficient strategy) and what the slope suggests.
fn print_table(summaries: &[Summary]) {
    let best = summaries
        .iter()
        .map(|s| s.efficiency)
        .filter(|e| e.is_finite())
        .fold(0.0, f64::max);
    println!(
        "\n{:<22} {:>12} {:>16} {:>15} {:>12} {:>9}  note",
        "strategy", "final relMSE", "slope vs time", "slope vs spp", "efficiency", "relative"
    );
    for s in summaries {
        let slope = |f: Option<crate::converge::fit::Fit>| {
            f.map_or("—".into(), |f| format!("{:.2} (r²={:.2})", f.slope, f.r2))
        };
        let note = if s.non_finite > 0 {
            format!("{} NaN/inf values", s.non_finite)
        } else if s.flattening() {
            "flattening: biased?".into()
        } else {
            "≈ −1: unbiased".into()
        };
        println!(
            "{:<22} {:>12} {:>16} {:>15} {:>12} {:>9}  {note}",
            s.strategy,
            format_number(s.final_rel_mse),
            slope(s.slope_time),
            slope(s.slope_spp).split(' ').next().unwrap_or("—"),
            format_number(s.efficiency),
            if best > 0.0 {
                format!("{:.3}", s.efficiency / best)
            } else {
                "—".into()
            },
        );
    }
}
