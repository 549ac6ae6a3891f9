use super::{Coefficients, Medium};
use glam::Vec3;

/// A medium with the same coefficients everywhere. Its majorant is σt itself, so delta
/// tracking never meets a null collision in it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Homogeneous {
    /// The coefficients, per unit length.
    pub coefficients: Coefficients,
}

impl Medium for Homogeneous {
    fn coefficients(&self, _p: Vec3) -> Coefficients {
        self.coefficients
    }

    fn majorant(&self) -> f32 {
        self.coefficients.sigma_t()
    }
}
