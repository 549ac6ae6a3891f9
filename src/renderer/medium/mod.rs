//! Participating media: the [`Medium`] interface the `delta_tracking` task samples, the
//! homogeneous and grid media, the Henyey-Greenstein phase function, and the framework's
//! transmittance estimators (ratio tracking and the closed form of a homogeneous medium).
//!
//! Media are grey: one σa and one σs for all three colour channels, so a free-flight
//! distance serves every channel at once.

mod coefficients;
mod free_flight;
mod grid;
mod homogeneous;
mod phase;
mod transmittance;

pub use coefficients::Coefficients;
pub use free_flight::FreeFlight;
pub use grid::{DensityGrid, GridMedium};
pub use homogeneous::Homogeneous;
pub use phase::HenyeyGreenstein;
pub use transmittance::{homogeneous_transmittance, ratio_tracking};

use glam::Vec3;

/// A participating medium as free-flight sampling sees it: coefficients that vary in space
/// and a bound on their sum.
pub trait Medium: Sync {
    /// The absorption and scattering coefficients at the world-space point `p`, per unit
    /// length. Zero outside the medium's support.
    fn coefficients(&self, p: Vec3) -> Coefficients;

    /// A majorant σ̄: an upper bound of `σt(p) = σa(p) + σs(p)` over every point of the
    /// medium, per unit length. The tighter it is, the fewer null collisions tracking needs.
    fn majorant(&self) -> f32;
}
