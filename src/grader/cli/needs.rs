use crate::scene::{LoadOptions, Scene};
use anyhow::{Result, anyhow};
use std::path::PathBuf;

/// Arguments of `pbrlab needs`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The scene file.
    pub scene: PathBuf,
}

/// Prints what a scene needs: the tasks it runs (and whether you have written them) and
/// the subsystems it builds.
pub fn run(args: Args) -> Result<()> {
    let scene = Scene::load(&args.scene, &LoadOptions::default()).map_err(|e| anyhow!("{e}"))?;
    for w in scene.warnings() {
        eprintln!("warning: {w}");
    }
    let needs = scene.needs();
    println!("{}", args.scene.display());
    println!("{needs}");
    println!("your code:");
    let attempted = crate::handout::stubs::edited(crate::repository_root());
    for task in needs.all_tasks().iter() {
        let status = if attempted.contains(task) {
            "edited"
        } else {
            "still the stub"
        };
        println!("  {:<16} {status}", task.name());
    }
    Ok(())
}
