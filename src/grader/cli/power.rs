//! `pbrlab power`: the power table of the statistical checks (see [`crate::grade::power`]),
//! measured on the reference.

use crate::grade::power::{PowerRow, render_power, table, task_power};
use crate::worksheet::TaskId;
use anyhow::{anyhow, bail};

/// Arguments of `pbrlab power`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Tasks to measure (ids or unique prefixes); every task when none are given.
    pub tasks: Vec<String>,
    /// Seeds per error level.
    #[arg(long, default_value_t = 200)]
    pub seeds: usize,
    /// Also measure the render checks: one render of each graded scene per seed (minutes).
    #[arg(long)]
    pub renders: bool,
    /// Print the rows as JSON instead of a table.
    #[arg(long)]
    pub json: bool,
}

/// Measures and prints the power table.
pub fn run(args: Args) -> anyhow::Result<()> {
    let Some(reference) = crate::implementation::try_reference() else {
        bail!("{}", crate::implementation::no_reference())
    };
    if args.seeds == 0 {
        bail!("--seeds must be at least 1");
    }
    let tasks: Vec<TaskId> = if args.tasks.is_empty() {
        TaskId::ALL.to_vec()
    } else {
        args.tasks
            .iter()
            .map(|n| TaskId::parse(n).map_err(|e| anyhow!(e)))
            .collect::<anyhow::Result<_>>()?
    };
    let mut rows: Vec<PowerRow> = task_power(&tasks, reference, args.seeds);
    if args.renders {
        rows.extend(render_power(reference, args.seeds)?);
    }
    if args.json {
        println!("{}", serde_json::to_string_pretty(&rows)?);
    } else {
        print!("{}", table(&rows));
    }
    Ok(())
}
