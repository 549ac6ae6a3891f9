//! The reference of `path_trace` and of no other task (see `../Cargo.toml`).

pbrlab_renderer::reference_library!(pbrlab_renderer::worksheet::TaskFns::ABSENT.with_task(
    &pbrlab_solutions::TASKS,
    pbrlab_renderer::worksheet::TaskId::PathTrace
));
