//! The task tables the `pbrlab` binary links: the student's crate, and in the instructor
//! build the reference's (in the handout, the compiled reference `pbrlab handout` put in
//! `tools/reference/`, when it fits this build). A module of that binary, not of the
//! framework beside it in `src/`. The worker binary links no reference.

use pbrlab::implementation::{Implementations, install};

/// Hands the linked tables to the framework; called first thing in `main`.
pub fn install_linked() {
    install(Implementations {
        student: pbrlab_exercises::TASKS,
        #[cfg(feature = "solutions")]
        reference: Some(pbrlab_solutions::TASKS),
        #[cfg(not(feature = "solutions"))]
        reference: pbrlab::compiled_reference::load_in(std::path::Path::new(env!(
            "CARGO_MANIFEST_DIR"
        ))),
    });
}
