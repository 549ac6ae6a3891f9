//! The instructor's tests: everything that uses the reference solutions, so none of it is
//! in the student handout. One test binary (one link of the framework) with a module per
//! subject; run one subject with `cargo test --release --test instructor <module>::`.
//!
//! - the grader grading itself: `grader`, `domain`, `power`, `calibration`, `expected`,
//!   `renders`, `stability`;
//! - the trust boundary: `trust` (compile time), `hostile` and `isolation` (run time);
//! - the map of the code: `architecture` (every file in `src/ARCHITECTURE.md`);
//! - the commands and packages end to end: `cli`, `autograder`, `handout`, `report`,
//!   `converge`;
//! - the reference renderer against closed forms: `reference_values`, `render_*`.
//!
//! Support code shared by the modules: `support` (the reference with functions replaced,
//! and each task's variants from `src/grader/tasks/<task>/variants.rs`), `shipped_stubs`.
#![cfg(feature = "solutions")]

#[path = "../junit_schema.rs"]
mod junit_schema;
mod shipped_stubs;
mod support;

mod architecture;
mod autograder;
mod calibration;
mod cli;
mod converge;
mod domain;
mod expected;
mod feedback;
mod grader;
mod handout;
mod hostile;
mod isolation;
mod power;
mod reference_values;
mod render_determinism;
mod render_furnace;
mod render_materials;
mod render_media;
mod render_mis;
mod render_scenes;
mod render_variance;
mod renders;
mod report;
mod similarity;
mod stability;
mod trust;
mod variants;
