//! The reference's whole task table behind two C functions, for the handout's binaries to
//! load (`pbrlab_renderer::compiled_reference`): the library's ABI signature, which the loader
//! compares with its own before anything else crosses, and the table.
//!
//! The package's examples (each task's `src/grader/tasks/<task>/library.rs`) are the grader's
//! libraries of one task each.

pbrlab_renderer::reference_library!(pbrlab_solutions::TASKS);
