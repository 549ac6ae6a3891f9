//! The packages every cargo build of the framework selects ([`FRAMEWORK_SELECTION`]), so
//! that all of them resolve features alike and share one compilation of it: the `pbrlab`
//! binary's build of `pbrlab-commands`, the student builds of the worker, the builds of the
//! reference's libraries. Cargo resolves features per selection. Without the worker's
//! package, whose student crate has the exercise check as a build dependency, the
//! compiler-side `proc-macro2` lacks its `span-locations` feature, and every derive macro
//! and everything above them compiles a second time (measured: about 150 CPU-s in CI).

/// `cargo build` arguments selecting `pbrlab-commands` and `pbrlab-worker`; add `--bin`,
/// `--lib` or `--examples` (and more packages) for what to build of them.
pub const FRAMEWORK_SELECTION: [&str; 4] = ["-p", "pbrlab-commands", "-p", "pbrlab-worker"];
