use crate::handout;
use crate::worksheet::task_functions;
use anyhow::bail;
use std::path::PathBuf;

/// Arguments of `pbrlab handout`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Where to write the student repository (must not exist, or be empty).
    pub dir: PathBuf,
    /// Leave out the compiled reference (tools/reference/), without which the handout
    /// cannot render with `--impl mixed` or `reference`.
    #[arg(long)]
    pub without_reference: bool,
}

/// Writes the student repository.
pub fn run(args: Args) -> anyhow::Result<()> {
    if !cfg!(feature = "solutions") {
        bail!("this is already a handout: run `pbrlab handout` from the instructor repository");
    }
    // The exercises are copied as they are: they must still be the stubs.
    let root = crate::repository_root();
    let written: Vec<_> = handout::stubs::edited(root)
        .iter()
        .filter(|t| !task_functions(*t).is_empty())
        .map(|t| format!("exercises/{t}.rs"))
        .collect();
    if !written.is_empty() {
        bail!(
            "these exercises differ from the committed stubs and would be handed out as they are: {}",
            written.join(", ")
        );
    }
    let files = handout::write(root, &args.dir)?;
    if !args.without_reference {
        eprintln!(
            "Compiling the reference into a shared library for mixed renders (on this \
             repository's build of the framework; cargo shows its progress)…"
        );
        let library = handout::compiled_reference::build(root, &args.dir)?;
        eprintln!("Wrote {}", library.display());
    }
    // Without git the handout still works; only `pbrlab reset` needs the first commit.
    if let Err(e) = handout::stubs::commit(&args.dir) {
        eprintln!("warning: the handout is not a git repository ({e:#}); `pbrlab reset` needs one");
    }
    println!(
        "Wrote {} files to {}. Check it builds: cd {} && cargo test --release",
        files.len(),
        args.dir.display(),
        args.dir.display()
    );
    Ok(())
}
