//! Materials and their BSDFs: the reflection models a scene can use, the framework's
//! sampling and evaluation of them (which calls the worksheet's tasks), and the parameter
//! types shared by the task signatures.

mod material;
mod microfacet;
mod params;
mod phong_lobe;
mod plausibility;
mod sample;
mod surface;

pub use material::{ConductorFresnel, FresnelModel, HemisphereSampling, Material};
pub use microfacet::{MIN_ALPHA, projected_alpha};
pub use params::{KajiyaKayParams, PhongParams};
pub use plausibility::PlausibilityReport;
pub use sample::BsdfSample;
pub use surface::Bsdf;
