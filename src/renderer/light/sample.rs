use glam::Vec3;

/// One sample drawn from the scene's lights by [`crate::scene::Scene::sample_light`].
///
/// Each kind comes with its density in its *own* measure. Before a MIS weight or a
/// division, bring an area density to solid angle at the shading point `x`:
/// `pdf_ω = pdf_area · |p − x|² / cos θl`, with `cos θl = n · (x − p)/|x − p|` the cosine
/// at the light. A point light is a delta distribution: it has no density to weight with.
///
/// Every density and probability here is positive and finite: a scene has at least one
/// light when it returns a sample, and the loader refuses shapes without area and keeps every
/// coordinate within [`crate::scene::MAX_REACH`], so no area is 0 or overflows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightSample {
    /// A point `p` on an area light.
    Area {
        /// The point on the light.
        p: Vec3,
        /// The light's unit normal at `p`: it emits only towards the side `n` points to.
        n: Vec3,
        /// The radiance it emits on its front side, per RGB channel.
        radiance: Vec3,
        /// Density of `p` per unit area, including the probability of having picked this
        /// light among all of them.
        pdf_area: f32,
    },
    /// A point light at `p`: irradiance at distance `d`, normal incidence, is `intensity / d²`.
    Point {
        /// Position of the light.
        p: Vec3,
        /// Radiant intensity per RGB channel (W/sr).
        intensity: Vec3,
        /// Probability of having picked this light among all of them.
        prob: f32,
    },
    /// A direction towards the environment (a light infinitely far away).
    Environment {
        /// Unit direction from the shading point towards the environment.
        wi: Vec3,
        /// Radiance arriving from that direction, per RGB channel.
        radiance: Vec3,
        /// Density of `wi` per unit solid angle, including the probability of having picked
        /// the environment among all lights.
        pdf: f32,
    },
}
