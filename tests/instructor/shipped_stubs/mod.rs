//! Which exercise files are still the shipped stubs. Tests about the stubs check those
//! files only, so that a student's own work never makes the README's test command fail;
//! in CI, which tests a clean clone, every file must be the stub, so nothing is skipped
//! there.

use pbrlab::worksheet::TaskId;
use std::path::Path;

/// The tasks whose `exercises/<task>.rs` is the shipped stub (git tells: the handout's
/// tagged first commit, or HEAD in the instructor repository). A file git cannot compare
/// counts as the student's.
pub fn untouched() -> Vec<TaskId> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let (untouched, edited): (Vec<TaskId>, Vec<TaskId>) = TaskId::ALL
        .into_iter()
        .partition(|t| pbrlab::handout::stubs::unchanged(root, *t) == Some(true));
    if std::env::var_os("CI").is_some() {
        assert!(
            edited.is_empty(),
            "CI tests a clean clone, whose exercises are the shipped stubs; these are not: {edited:?}"
        );
    } else if !edited.is_empty() {
        let names: Vec<&str> = edited.iter().map(|t| t.name()).collect();
        eprintln!(
            "the stub checks skip exercises/{{{}}}.rs: yours, not the shipped stubs",
            names.join(",")
        );
    }
    untouched
}
