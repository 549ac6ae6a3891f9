//! Error against run time: how fast each sampling strategy converges.
//!
//! A study renders (or estimates) the same quantities with several [`Strategy`]s at
//! doubling sample counts, times each estimate ([`clock`]), measures it against a
//! reference ([`metrics`]: relMSE, RMSE), and fits the slope of log relMSE against log
//! time and against log spp ([`fit`], [`study::summarise`]). An unbiased estimator has a
//! slope near −1; a slope that flattens at high sample counts reveals bias. Efficiency is
//! `1 / (relMSE · time)`. The points go to a CSV ([`csv`]) and a log-log plot ([`plot`]).
//!
//! `pbrlab converge` runs a study from the command line; the grader can call
//! [`run_study`] on an estimator task to get the same figures. [`scene_study`] studies a
//! scene file (direct-light strategies, hemisphere sampling, transmittance estimators)
//! against a cached high-sample reference ([`reference_cache`]); [`builtin`] holds
//! studies that need no scene, with exact references.

pub mod builtin;
pub mod clock;
pub mod csv;
pub mod fit;
pub mod metrics;
pub mod plot;
pub mod reference_cache;
pub mod scene_study;
pub mod strategy;
pub mod study;

pub use strategy::{Estimate, Strategy};
pub use study::{
    Failure, Point, Study, StudyConfig, StudyResult, Summary, run_study, run_study_reporting,
    summarise,
};
