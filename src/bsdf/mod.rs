//! BSDF parameter types shared by the task signatures and the materials, and microfacet
//! helpers that are framework rather than tasks.

mod microfacet;
mod params;
mod plausibility;

pub use microfacet::{MIN_ALPHA, projected_alpha};
pub use params::{KajiyaKayParams, PhongParams};
pub use plausibility::PlausibilityReport;
