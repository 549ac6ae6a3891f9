use crate::medium::{Coefficients, GridMedium, HenyeyGreenstein, Homogeneous, Medium};
use glam::Vec3;

/// The kinds of medium a scene can hold.
#[derive(Clone, Debug, PartialEq)]
pub enum MediumKind {
    /// Constant coefficients.
    Homogeneous(Homogeneous),
    /// A density grid.
    Grid(GridMedium),
}

/// A medium filling one shape of the scene, with its phase function.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneMedium {
    /// Its coefficients.
    pub kind: MediumKind,
    /// Its phase function.
    pub phase: HenyeyGreenstein,
}

impl Medium for SceneMedium {
    fn coefficients(&self, p: Vec3) -> Coefficients {
        match &self.kind {
            MediumKind::Homogeneous(m) => m.coefficients(p),
            MediumKind::Grid(m) => m.coefficients(p),
        }
    }

    fn majorant(&self) -> f32 {
        match &self.kind {
            MediumKind::Homogeneous(m) => m.majorant(),
            MediumKind::Grid(m) => m.majorant(),
        }
    }
}
