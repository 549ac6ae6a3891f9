use crate::geometry::{Hit, Ray};
use glam::Vec3;

/// One straight piece of a path: a ray that was traced and what it found.
#[derive(Clone, Copy, Debug)]
pub struct Segment {
    /// The ray: origin at the previous vertex (or the camera), direction of travel.
    pub ray: Ray,
    /// The first surface the ray hit; `None` when it left the scene (then it sees the
    /// environment, [`crate::scene::Scene::environment`]).
    pub hit: Option<Hit>,
    /// True when the light this segment reaches (the emission of `hit`, or the environment
    /// when it escaped) has already been added to the estimate, with its MIS weight, by the
    /// `mis` task that sampled it. False for camera rays.
    pub emission_counted: bool,
}

/// The continuation of a path that the `mis` task sampled from the BSDF.
#[derive(Clone, Copy, Debug)]
pub struct Bounce {
    /// The estimator weight `f |cos θi| / pdf` of the sampled direction: the radiance the
    /// path brings back along `segment` is multiplied by it.
    pub weight: Vec3,
    /// The traced continuation (its `emission_counted` is true).
    pub segment: Segment,
}

/// The result of the `mis` task at one surface point.
#[derive(Clone, Copy, Debug)]
pub struct DirectLight {
    /// The estimate of the radiance reflected towards `wo` that arrives straight from the
    /// lights (one light sample and one BSDF sample, each with its MIS weight).
    pub radiance: Vec3,
    /// The BSDF sample, traced, for the path to continue with; `None` when the BSDF
    /// absorbed the path.
    pub bounce: Option<Bounce>,
}
