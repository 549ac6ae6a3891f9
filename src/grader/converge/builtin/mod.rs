//! Convergence studies that need no scene: estimators built from the task functions
//! alone, with a reference computed without sampling.

pub mod irradiance;
pub mod microfacet_albedo;

use super::{Strategy, Study};
use crate::worksheet::Tasks;
use std::sync::Arc;

/// The built-in studies, by the name `pbrlab converge` takes in place of a scene file.
pub const BUILTIN: &[(&str, &str)] = &[
    (
        "irradiance",
        "irradiance under 4096 smooth skies: uniform vs cosine-weighted hemisphere sampling \
         (tasks: cosine_sample)",
    ),
    (
        "microfacet_albedo",
        "directional albedo of Cook-Torrance at 60 (wo, α): uniform, cosine, NDF sampling and \
         MIS of the last two (tasks: cook_torrance, cosine_sample, ndf_sample)",
    ),
];

/// Builds the built-in study `name` on the implementation `tasks`. Fails for an unknown
/// name, and when computing the reference fails (it calls task code too).
pub fn builtin<T: Tasks + Clone + Send + 'static>(name: &str, tasks: T) -> anyhow::Result<Study> {
    match name {
        "irradiance" => {
            let skies = Arc::new(irradiance::skies(irradiance::PIXELS));
            Ok(Study {
                title: "Irradiance: uniform vs cosine-weighted hemisphere sampling".into(),
                reference: irradiance::reference(&skies),
                reference_note: "analytic".into(),
                reference_floor: 0.0,
                strategies: vec![
                    Box::new(irradiance::Uniform {
                        skies: skies.clone(),
                    }),
                    Box::new(irradiance::Cosine { tasks, skies }),
                ],
            })
        }
        "microfacet_albedo" => {
            use crate::integrator::MisHeuristic;
            use microfacet_albedo::{Mis, Sampled, Technique};
            let configs = Arc::new(microfacet_albedo::configs());
            let reference = crate::implementation::catch_quietly(|| {
                microfacet_albedo::reference(&tasks, &configs)
            })
            .map_err(|m| {
                anyhow::anyhow!("the reference quadrature calls cook_torrance, which failed: {m}")
            })?;
            let sampled = |technique| -> Box<dyn Strategy> {
                Box::new(Sampled {
                    tasks: tasks.clone(),
                    configs: configs.clone(),
                    technique,
                })
            };
            let mis = |heuristic| -> Box<dyn Strategy> {
                Box::new(Mis {
                    tasks: tasks.clone(),
                    configs: configs.clone(),
                    heuristic,
                })
            };
            Ok(Study {
                title: "Cook-Torrance albedo: uniform, cosine, NDF sampling and MIS".into(),
                reference,
                reference_floor: 0.0,
                reference_note: format!(
                    "midpoint quadrature, {n} × {n} nodes per pixel",
                    n = microfacet_albedo::QUADRATURE_NODES
                ),
                strategies: vec![
                    sampled(Technique::Uniform),
                    sampled(Technique::Cosine),
                    sampled(Technique::Ndf),
                    mis(MisHeuristic::Balance),
                    mis(MisHeuristic::Power),
                ],
            })
        }
        _ => {
            let names: Vec<String> = BUILTIN
                .iter()
                .map(|(n, what)| format!("  {n}: {what}"))
                .collect();
            anyhow::bail!(
                "`{name}` is not a built-in study; the built-in studies are:\n{}",
                names.join("\n")
            )
        }
    }
}
