/// What happened to a path flying through a medium, as the `delta_tracking` task reports it.
/// Distances are along the ray, from its origin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FreeFlight {
    /// A real collision that scatters the path at distance `t` (inside the segment).
    Scatter {
        /// Distance of the collision.
        t: f32,
    },
    /// A real collision that absorbs the path at distance `t` (the path ends there).
    Absorb {
        /// Distance of the collision.
        t: f32,
    },
    /// The path crossed the whole segment without a real collision.
    Escape,
    /// The iteration bound ran out before any of the above was decided (a majorant far
    /// above σt, or one so large that the distance stopped growing in f32).
    Exhausted,
}
