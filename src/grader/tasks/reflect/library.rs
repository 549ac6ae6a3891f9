//! The reference of `reflect` and of no other task, as a shared library: an example of the
//! package `tools/reference-library/` (see its `Cargo.toml`), which the grader's workers load.

pbrlab_renderer::reference_library!(pbrlab_renderer::worksheet::TaskFns::ABSENT.with_task(
    &pbrlab_solutions::TASKS,
    pbrlab_renderer::worksheet::TaskId::Reflect
));
