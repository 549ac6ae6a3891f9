//! The reference of `cosine_sample` and of no other task (see `../Cargo.toml`).

pbrlab::reference_library!(pbrlab::worksheet::TaskFns::ABSENT.with_task(
    &pbrlab_solutions::TASKS,
    pbrlab::worksheet::TaskId::CosineSample
));
