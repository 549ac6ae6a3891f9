//! Stability cases of the `delta_tracking` task: a zero and a NaN majorant, a random number
//! of exactly 0, σt = 1e6, a majorant 10⁶ and 10⁹ times σt, a walk that runs out of steps,
//! a medium with σt = 0 under a positive majorant, and an empty segment.

use crate::geometry::Ray;
use crate::medium::{Coefficients, FreeFlight, Homogeneous, Medium};
use crate::sampling::Sampler;
use crate::stability::case::{ANY, Case};
use crate::stability::expect::Expect;
use crate::stability::value::Value;
use crate::worksheet::{TaskId, Tasks};
use glam::Vec3;

/// A homogeneous medium with a majorant of our choosing (a loose or a zero bound).
struct Loose {
    coefficients: Coefficients,
    majorant: f32,
}

impl Medium for Loose {
    fn coefficients(&self, _p: Vec3) -> Coefficients {
        self.coefficients
    }

    fn majorant(&self) -> f32 {
        self.majorant
    }
}

/// The stream of [`Sampler::new`]`(0, ·)` whose first number is exactly 0.
pub const STREAM_STARTING_AT_ZERO: u64 = 7_098_157;

/// σa = σs = `half` each.
fn coefficients(half: f32) -> Coefficients {
    Coefficients {
        sigma_a: half,
        sigma_s: half,
    }
}

/// A free flight as a record with one field named after the event: `scatter_t`,
/// `absorb_t` (the distance), `escape` or `exhausted` (1).
fn flight_value(f: FreeFlight) -> Value {
    match f {
        FreeFlight::Scatter { t } => Value::record([("scatter_t", t as f64)]),
        FreeFlight::Absorb { t } => Value::record([("absorb_t", t as f64)]),
        FreeFlight::Escape => Value::record([("escape", 1.0)]),
        FreeFlight::Exhausted => Value::record([("exhausted", 1.0)]),
    }
}

/// Runs delta tracking along +x from the origin.
fn fly<T: Tasks>(
    t: &T,
    medium: &dyn Medium,
    t_max: f32,
    max_steps: u32,
    sampler: &mut Sampler,
) -> Value {
    flight_value(t.delta_tracking(
        medium,
        &Ray::new(Vec3::ZERO, Vec3::X),
        t_max,
        max_steps,
        sampler,
    ))
}

/// The flight escaped.
fn escaped(v: &Value) -> bool {
    v.field("escape").is_some()
}

/// A real collision at a distance in `[lo, hi]`.
fn collided_within(v: &Value, lo: f64, hi: f64) -> bool {
    v.field("scatter_t")
        .or(v.field("absorb_t"))
        .is_some_and(|t| lo <= t && t <= hi)
}

/// The cases.
pub fn cases<T: Tasks>() -> Vec<Case<T>> {
    vec![
        Case {
            task: TaskId::DeltaTracking,
            name: "delta_tracking/zero_majorant",
            input: "σt = 0 and majorant 0, t_max = 1",
            eval: |t| {
                let medium = Loose {
                    coefficients: coefficients(0.0),
                    majorant: 0.0,
                };
                fly(
                    t,
                    &medium,
                    1.0,
                    1000,
                    &mut Sampler::new(0, STREAM_STARTING_AT_ZERO),
                )
            },
            range: ANY,
            expect: Expect::Rule {
                text: "escape",
                holds: escaped,
            },
            guard: "with σ̄ = 0 the step −ln(1 − u)/σ̄ is ∞ or 0/0 = NaN: return escape at once",
        },
        Case {
            task: TaskId::DeltaTracking,
            name: "delta_tracking/random_number_zero",
            input: "σa = σs = 0.5, t_max = 10, first random number exactly 0",
            eval: |t| {
                let medium = Homogeneous {
                    coefficients: coefficients(0.5),
                };
                fly(
                    t,
                    &medium,
                    10.0,
                    1000,
                    &mut Sampler::new(0, STREAM_STARTING_AT_ZERO),
                )
            },
            range: ANY,
            expect: Expect::Rule {
                text: "a collision in [0, 10] or escape",
                holds: |v| escaped(v) || collided_within(v, 0.0, 10.0),
            },
            guard: "u = 0 gives a step of 0 (or ∞ with −ln u): draw fresh numbers every step so \
                    one zero costs one step, not an endless loop",
        },
        Case {
            task: TaskId::DeltaTracking,
            name: "delta_tracking/huge_sigma_t",
            input: "σs = 1e6 (σa = 0), t_max = 1",
            eval: |t| {
                let medium = Homogeneous {
                    coefficients: Coefficients {
                        sigma_a: 0.0,
                        sigma_s: 1e6,
                    },
                };
                fly(t, &medium, 1.0, 1000, &mut Sampler::new(3, 0))
            },
            range: ANY,
            expect: Expect::Rule {
                text: "a collision within 1e-3 (mean free path 1e-6)",
                holds: |v| {
                    v.field("scatter_t")
                        .is_some_and(|t| (0.0..=1e-3).contains(&t))
                },
            },
            guard: "steps of 1e-6 are fine in f32; the collision comes at once",
        },
        Case {
            task: TaskId::DeltaTracking,
            name: "delta_tracking/majorant_1e6_sigma_t",
            input: "σa = σs = 0.5, majorant 1e6, t_max = 1, 10⁸ steps allowed",
            eval: |t| {
                let medium = Loose {
                    coefficients: coefficients(0.5),
                    majorant: 1e6,
                };
                fly(t, &medium, 1.0, 100_000_000, &mut Sampler::new(5, 0))
            },
            range: ANY,
            expect: Expect::Rule {
                text: "a collision in [0, 1] or escape (not exhausted)",
                holds: |v| escaped(v) || collided_within(v, 0.0, 1.0),
            },
            guard: "a loose majorant only costs null collisions (about 10⁶ here): keep stepping \
                    with fresh numbers until t ≥ t_max",
        },
        Case {
            task: TaskId::DeltaTracking,
            name: "delta_tracking/majorant_1e9_stalls",
            input: "σt = 1e-3, majorant 1e9, t_max = 1, 10⁶ steps allowed",
            eval: |t| {
                let medium = Loose {
                    coefficients: coefficients(5e-4),
                    majorant: 1e9,
                };
                fly(t, &medium, 1.0, 1_000_000, &mut Sampler::new(5, 0))
            },
            range: ANY,
            expect: Expect::Finite,
            guard: "steps of 1e-9 stop moving t in f32 near t = 0.01: the step bound must end the \
                    loop (exhausted), or it never ends",
        },
        Case {
            task: TaskId::DeltaTracking,
            name: "delta_tracking/nan_majorant",
            input: "σa = σs = 0.5, majorant NaN, t_max = 1, 1000 steps allowed",
            eval: |t| {
                let medium = Loose {
                    coefficients: coefficients(0.5),
                    majorant: f32::NAN,
                };
                fly(t, &medium, 1.0, 1000, &mut Sampler::new(11, 0))
            },
            range: ANY,
            expect: Expect::Rule {
                text: "escape",
                holds: escaped,
            },
            guard: "`σ̄ <= 0` is false for NaN: test `!(σ̄ > 0)` (or is_nan) and escape before \
                    dividing, or every distance is NaN and the walk runs out of steps",
        },
        Case {
            task: TaskId::DeltaTracking,
            name: "delta_tracking/out_of_steps",
            input: "σt = 2e-3, majorant 1e3, t_max = 1, 10 steps allowed",
            eval: |t| {
                let medium = Loose {
                    coefficients: coefficients(1e-3),
                    majorant: 1e3,
                };
                fly(t, &medium, 1.0, 10, &mut Sampler::new(13, 0))
            },
            range: ANY,
            expect: Expect::Rule {
                text: "exhausted (about 1000 steps are needed to cross)",
                holds: |v| v.field("exhausted").is_some(),
            },
            guard: "a walk that runs out of steps has not crossed the segment: return \
                    Exhausted, not Escape (a renderer would pass light that never got through)",
        },
        Case {
            task: TaskId::DeltaTracking,
            name: "delta_tracking/empty_medium",
            input: "σt = 0 under majorant 1, t_max = 2",
            eval: |t| {
                let medium = Loose {
                    coefficients: coefficients(0.0),
                    majorant: 1.0,
                };
                fly(t, &medium, 2.0, 1000, &mut Sampler::new(9, 0))
            },
            range: ANY,
            expect: Expect::Rule {
                text: "escape",
                holds: escaped,
            },
            guard: "every tentative collision is null (σt/σ̄ = 0); an escape is an escape, not \
                    an absorption",
        },
        Case {
            task: TaskId::DeltaTracking,
            name: "delta_tracking/empty_segment",
            input: "σa = σs = 0.5, t_max = 0",
            eval: |t| {
                let medium = Homogeneous {
                    coefficients: coefficients(0.5),
                };
                fly(t, &medium, 0.0, 1000, &mut Sampler::new(9, 0))
            },
            range: ANY,
            expect: Expect::Rule {
                text: "escape",
                holds: escaped,
            },
            guard: "a segment of length 0 holds no collision",
        },
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_zero_stream_starts_at_zero() {
        let mut s = Sampler::new(0, STREAM_STARTING_AT_ZERO);
        assert_eq!(s.next_1d(), 0.0);
    }
}
