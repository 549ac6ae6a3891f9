//! The reference of `cook_torrance` and of no other task (see `../Cargo.toml`).

pbrlab::reference_library!(pbrlab::worksheet::TaskFns::ABSENT.with_task(
    &pbrlab_solutions::TASKS,
    pbrlab::worksheet::TaskId::CookTorrance
));
