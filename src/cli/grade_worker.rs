use crate::grade::worker;

/// Arguments of the hidden `pbrlab grade-worker` (the job arrives on stdin).
#[derive(clap::Args, Debug, Default)]
pub struct Args {}

/// Serves one grading job; see [`crate::grade::worker`].
pub fn run(_args: Args) -> anyhow::Result<()> {
    worker::serve(worker::production_impl)
}
