//! The reference of `phong` and of no other task (see `../Cargo.toml`).

pbrlab_renderer::reference_library!(pbrlab_renderer::worksheet::TaskFns::ABSENT.with_task(
    &pbrlab_solutions::TASKS,
    pbrlab_renderer::worksheet::TaskId::Phong
));
