//! Error against run time: how fast each sampling strategy converges.
//!
//! A study renders (or estimates) the same quantities with several [`Strategy`]s at
//! doubling sample counts, several independent runs at each, times each estimate
//! ([`clock`]), measures it against a reference ([`metrics`]: relMSE, RMSE), and reports
//! per level the expected relMSE with a 95 % interval and its split into variance (the
//! spread over the runs) and squared bias ([`study::Point`]). It fits the slope of log
//! relMSE against log time and log spp ([`fit`], [`study::summarise`]): about −1 for an
//! unbiased estimator. Bias is judged by a test on the squared bias at the largest sample
//! count ([`study::BiasTest`]), not by the slope, which heavy-tailed unbiased estimators
//! flatten too. Efficiency is `1 / (relMSE · time)`; the time to unit variance and an
//! equal-time comparison ([`study::equal_time`]) say which strategy wins for a budget.
//! The points go to a CSV ([`csv`]) and a log-log plot with error bars ([`plot`]).
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
