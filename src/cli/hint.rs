use crate::worksheet::TaskId;
use anyhow::anyhow;

/// Arguments of `pbrlab hint`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The task (its id, or a unique prefix of it).
    pub task: String,
    /// Show hints up to this level (1 is the gentlest). Default: all levels.
    #[arg(long)]
    pub level: Option<usize>,
}

/// Prints a task's hints up to the requested level.
pub fn run(args: Args) -> anyhow::Result<()> {
    let task = TaskId::parse(&args.task).map_err(|e| anyhow!(e))?;
    let info = task.info();
    let levels = info.hints.len();
    let shown = args.level.unwrap_or(levels).clamp(1, levels);
    println!(
        "{} — {} (worksheet {}, exercises/{}.rs)",
        info.id, info.title, info.section, info.id
    );
    for (i, hint) in info.hints.iter().take(shown).enumerate() {
        println!("\nhint {}/{}: {}", i + 1, levels, hint);
    }
    if shown < levels {
        println!("\nMore: pbrlab hint {} --level {}", info.id, shown + 1);
    }
    Ok(())
}
