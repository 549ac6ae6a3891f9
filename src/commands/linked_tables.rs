//! The task tables the `pbrlab-commands` binary links: in the instructor build the reference's, in
//! the handout the compiled reference `pbrlab handout` put in `tools/reference/`, when it
//! fits this build. No student code: that runs in the worker binary (`src/worker/`). A
//! module of this binary, not of the framework.

use pbrlab::implementation::{Implementations, install};

/// Hands the linked tables to the framework; called first thing in `main`.
pub fn install_linked() {
    install(Implementations {
        student: None,
        #[cfg(feature = "solutions")]
        reference: Some(pbrlab_solutions::TASKS),
        #[cfg(not(feature = "solutions"))]
        reference: pbrlab::compiled_reference::load_in(pbrlab::repository_root()),
        #[cfg(feature = "solutions")]
        reference_render: Some(|scene, options, state| {
            pbrlab::render::render_from(scene, &pbrlab_solutions::Direct, options, state)
        }),
        #[cfg(not(feature = "solutions"))]
        reference_render: None,
    });
}
