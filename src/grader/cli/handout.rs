use crate::handout;
use crate::worksheet::task_functions;
use anyhow::bail;
use std::path::{Path, PathBuf};

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
    let files = write_student_repository(&args.dir, args.without_reference, handout::write)?;
    println!(
        "Wrote {files} files to {}. Check it builds: cd {} && cargo test --release",
        args.dir.display(),
        args.dir.display()
    );
    Ok(())
}

/// Writes a student repository into `dir` with `write` (the handout's files, or a template
/// repository's, which are the handout's and more), after checking that the exercises are
/// still the committed stubs; adds the compiled reference unless `without_reference`, and
/// makes the first commit. Returns how many files `write` wrote.
pub fn write_student_repository(
    dir: &Path,
    without_reference: bool,
    write: fn(&Path, &Path) -> anyhow::Result<Vec<PathBuf>>,
) -> anyhow::Result<usize> {
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
    let files = write(root, dir)?;
    if !without_reference {
        eprintln!(
            "Compiling the reference into a shared library for mixed renders (on this \
             repository's build of the framework; cargo shows its progress)…"
        );
        let library = handout::compiled_reference::build(root, dir)?;
        eprintln!("Wrote {}", library.display());
    }
    // Without git the handout still works; only `pbrlab reset` needs the first commit.
    if let Err(e) = handout::stubs::commit(dir) {
        eprintln!("warning: the handout is not a git repository ({e:#}); `pbrlab reset` needs one");
    }
    Ok(files.len())
}
