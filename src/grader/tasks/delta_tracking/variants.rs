// The variants of `delta_tracking` the tests grade the grader with (see `src/grader/tasks/mod.rs`).
// `tests/instructor/support/variants.rs` includes this file into a module of the tests,
// so it has no inner attributes or doc; the student handout leaves it out.

use crate::support::patch::{Variant, variant};
use crate::support::variants::Naive;
use pbrlab::geometry::Ray;
use pbrlab::medium::{FreeFlight, Medium};
use pbrlab::sampling::Sampler;
use pbrlab::stability::Verdict;
use pbrlab::worksheet::TaskId;

/// A wrong `delta_tracking`: the reference's algorithm with one flaw (a task function is a plain
/// `fn`, which cannot capture the flaw, hence a macro).
macro_rules! flawed {
    ($name:expr, $flaw:ident) => {
        variant($name, TaskId::DeltaTracking, |p| {
            p.delta_tracking =
                Some(|m, r, tm, n, s| tracking_variant(m, r, tm, n, s, TrackingFlaw::$flaw))
        })
    };
}

/// Known-wrong implementations of `delta_tracking`: each must fail this task and no other.
pub fn wrong() -> Vec<Variant> {
    vec![
        flawed!(
            "the medium looked up as if the ray started at the origin",
            RayFromOrigin
        ),
        flawed!("one tentative collision fewer than allowed", OneStepShort),
        flawed!("one tentative collision more than allowed", OneStepTooMany),
        flawed!(
            "a walk out of steps reported as an absorption",
            ExhaustedAsAbsorption
        ),
        flawed!("the sheet's reused random numbers", ReusedRandomNumbers),
        flawed!(
            "the sheet's escape reported as absorption",
            EscapeAsAbsorption
        ),
        flawed!("every tentative collision is real", NoNullCollisions),
        flawed!("a NaN majorant is not guarded", UnguardedNanMajorant),
        flawed!(
            "a walk out of steps reported as an escape",
            ExhaustedAsEscape
        ),
    ]
}

/// Correct implementations of `delta_tracking` that differ from the reference: each gets full marks.
pub fn different() -> Vec<Variant> {
    use TaskId::*;
    vec![variant(
        "delta tracking that counts a step only once it is inside the segment",
        DeltaTracking,
        |p| p.delta_tracking = Some(count_after_escape_test),
    )]
}

/// Naive implementations of `delta_tracking` (the textbook formula without its guards), each with
/// exactly the stability cases it must fail and the verdict of each.
pub fn naive() -> Vec<Naive> {
    use TaskId::*;
    use Verdict::*;
    vec![Naive::new(
        "`delta_tracking` as on the worksheet (reused random numbers, escape as absorption)",
        DeltaTracking,
        |p| {
            p.delta_tracking = Some(textbook::delta_tracking_sheet);
        },
        vec![
            ("delta_tracking/zero_majorant", WrongValue),
            ("delta_tracking/nan_majorant", WrongValue),
            ("delta_tracking/empty_medium", WrongValue),
            ("delta_tracking/empty_segment", WrongValue),
        ],
    )]
}

/// How a `delta_tracking` variant goes wrong.
#[derive(Clone, Copy, PartialEq)]
enum TrackingFlaw {
    /// The sheet: two random numbers drawn once and reused at every step.
    ReusedRandomNumbers,
    /// An escape returned as an absorption at the end of the segment.
    EscapeAsAbsorption,
    /// Every tentative collision taken as real (no null collisions).
    NoNullCollisions,
    /// `majorant <= 0` as the only guard: a NaN majorant walks on with NaN distances.
    UnguardedNanMajorant,
    /// A walk that ran out of steps reported as an escape.
    ExhaustedAsEscape,
    /// The medium looked up at `t · dir`, as if every ray started at the origin.
    RayFromOrigin,
    /// One tentative collision fewer than `max_steps`.
    OneStepShort,
    /// One tentative collision more than `max_steps`.
    OneStepTooMany,
    /// A walk that ran out of steps reported as an absorption where it stopped.
    ExhaustedAsAbsorption,
}

fn tracking_variant(
    medium: &dyn Medium,
    ray: &Ray,
    t_max: f32,
    max_steps: u32,
    sampler: &mut Sampler,
    flaw: TrackingFlaw,
) -> FreeFlight {
    let majorant = medium.majorant();
    let nan_guard = flaw != TrackingFlaw::UnguardedNanMajorant;
    if majorant <= 0.0 || (nan_guard && majorant.is_nan()) {
        return FreeFlight::Escape;
    }
    let reused = (sampler.next_1d(), sampler.next_1d());
    let mut t = 0.0f32;
    let steps = match flaw {
        TrackingFlaw::OneStepShort => max_steps.saturating_sub(1),
        TrackingFlaw::OneStepTooMany => max_steps.saturating_add(1),
        _ => max_steps,
    };
    for _ in 0..steps {
        let (u0, u1) = if flaw == TrackingFlaw::ReusedRandomNumbers {
            reused
        } else {
            (sampler.next_1d(), sampler.next_1d())
        };
        t -= (1.0 - u0).ln() / majorant;
        if t >= t_max {
            return if flaw == TrackingFlaw::EscapeAsAbsorption {
                FreeFlight::Absorb { t: t_max }
            } else {
                FreeFlight::Escape
            };
        }
        let c = medium.coefficients(if flaw == TrackingFlaw::RayFromOrigin {
            ray.dir * t
        } else {
            ray.at(t)
        });
        let scale = if flaw == TrackingFlaw::NoNullCollisions {
            c.sigma_t()
        } else {
            majorant
        };
        let xi = u1 * scale;
        if xi < c.sigma_a {
            return FreeFlight::Absorb { t };
        }
        if xi < c.sigma_a + c.sigma_s {
            return FreeFlight::Scatter { t };
        }
    }
    match flaw {
        TrackingFlaw::ExhaustedAsEscape => FreeFlight::Escape,
        TrackingFlaw::ExhaustedAsAbsorption => FreeFlight::Absorb { t },
        _ => FreeFlight::Exhausted,
    }
}

/// Delta tracking that tests for an escape before it counts the step, so that it gives up
/// only when the step after `max_steps` null collisions lands inside the segment (the
/// other reading of "after `max_steps` tentative collisions"), and picks absorption or
/// scattering with a second random number.
fn count_after_escape_test(
    medium: &dyn Medium,
    ray: &Ray,
    t_max: f32,
    max_steps: u32,
    sampler: &mut Sampler,
) -> FreeFlight {
    let majorant = medium.majorant();
    if majorant.is_nan() || majorant <= 0.0 {
        return FreeFlight::Escape;
    }
    let (mut t, mut taken) = (0.0f32, 0u32);
    loop {
        t -= (1.0 - sampler.next_1d()).ln() / majorant;
        if t >= t_max {
            return FreeFlight::Escape;
        }
        if taken >= max_steps {
            return FreeFlight::Exhausted;
        }
        taken += 1;
        let c = medium.coefficients(ray.at(t));
        let sigma_t = c.sigma_a + c.sigma_s;
        if sampler.next_1d() * majorant < sigma_t {
            return if sampler.next_1d() * sigma_t < c.sigma_a {
                FreeFlight::Absorb { t }
            } else {
                FreeFlight::Scatter { t }
            };
        }
    }
}

/// The naive functions of [`naive`].
mod textbook {
    use super::*;

    /// The worksheet's delta tracking: two random numbers drawn once and reused at every step,
    /// an escape reported as an absorption at `t_max`, and (to keep the test finite) the
    /// step bound honoured.
    pub fn delta_tracking_sheet(
        medium: &dyn Medium,
        ray: &Ray,
        t_max: f32,
        max_steps: u32,
        sampler: &mut Sampler,
    ) -> FreeFlight {
        use pbrlab::medium::FreeFlight;
        let (u0, u1) = (sampler.next_1d(), sampler.next_1d());
        let majorant = medium.majorant();
        let dt = -(1.0 - u0).ln() / majorant;
        let mut t = 0.0;
        for _ in 0..max_steps {
            t += dt;
            if t > t_max {
                return FreeFlight::Absorb { t: t_max };
            }
            let c = medium.coefficients(ray.at(t));
            if u1 * majorant < c.sigma_t() {
                return if u1 * majorant < c.sigma_s {
                    FreeFlight::Scatter { t }
                } else {
                    FreeFlight::Absorb { t }
                };
            }
        }
        FreeFlight::Exhausted
    }
}
