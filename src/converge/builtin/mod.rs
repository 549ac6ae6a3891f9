//! Convergence studies that need no scene: estimators built from the task functions
//! alone, with a reference computed without sampling.

pub mod irradiance;

use super::Strategy;
use crate::worksheet::Tasks;
use std::sync::Arc;

/// A study ready to run: its strategies and the reference they are measured against.
pub struct Study {
    /// What is being estimated, for the plot's title.
    pub title: String,
    /// The competing strategies.
    pub strategies: Vec<Box<dyn Strategy>>,
    /// The exact values, one per pixel channel.
    pub reference: Vec<f32>,
    /// How the reference was obtained, for the report.
    pub reference_note: String,
}

/// The built-in studies, by the name `pbrlab converge` takes in place of a scene file.
pub const BUILTIN: &[(&str, &str)] = &[(
    "irradiance",
    "irradiance under 4096 smooth skies: uniform vs cosine-weighted hemisphere sampling \
     (tasks: cosine_sample)",
)];

/// Builds the built-in study `name` on the implementation `tasks`; `None` for an unknown
/// name.
pub fn builtin<T: Tasks + Clone + Send + 'static>(name: &str, tasks: T) -> Option<Study> {
    match name {
        "irradiance" => {
            let skies = Arc::new(irradiance::skies(irradiance::PIXELS));
            Some(Study {
                title: "Irradiance: uniform vs cosine-weighted hemisphere sampling".into(),
                reference: irradiance::reference(&skies),
                reference_note: "analytic".into(),
                strategies: vec![
                    Box::new(irradiance::Uniform {
                        skies: skies.clone(),
                    }),
                    Box::new(irradiance::Cosine { tasks, skies }),
                ],
            })
        }
        _ => None,
    }
}
