//! The estimators of `delta_tracking`: media of slabs where the probability of each outcome
//! of a free flight is known in closed form (the errata's M1, M3 and M4 along a unit
//! segment), and the rest of what the contract allows: segments of other lengths, rays
//! that start elsewhere and cross the slabs obliquely or in the other order, a majorant
//! far above σt, and a step bound of 1 where no tentative collision is null.

use crate::grade::estimator::EstimatorSpec;
use crate::geometry::Ray;
use crate::grade::declared::Declared;
use crate::medium::{Coefficients, FreeFlight, Medium};
use crate::sampling::Sampler;
use crate::worksheet::Tasks;
use glam::Vec3;

/// What the estimator and sampling checks of this task catch in at least 90 % of
/// gradings, as measured by `pbrlab power` (asserted by tests/instructor/power.rs).
pub const POWER: Declared = Declared {
    estimator_bias: Some(0.01),
    sampler_distortion: None,
};

/// A medium of slabs stacked along z, with its own majorant (which may exceed σt, so
/// tracking meets null collisions).
#[derive(Clone, Debug)]
pub struct Slabs {
    /// `(z where the slab ends, its coefficients)`, in increasing z; beyond the last, the
    /// last slab continues.
    pub slabs: Vec<(f32, Coefficients)>,
    /// The majorant.
    pub majorant: f32,
}

impl Medium for Slabs {
    fn coefficients(&self, p: Vec3) -> Coefficients {
        self.slabs
            .iter()
            .find(|(end, _)| p.z < *end)
            .or(self.slabs.last())
            .map_or_else(Coefficients::default, |(_, c)| *c)
    }

    fn majorant(&self) -> f32 {
        self.majorant
    }
}

impl Slabs {
    /// The largest ratio of the majorant to σt over the slabs.
    fn majorant_ratio(&self) -> f32 {
        self.slabs
            .iter()
            .map(|(_, c)| self.majorant / c.sigma_t())
            .fold(1.0, f32::max)
    }

    /// The slabs `segment` crosses, in the order it crosses them: `(length, σa, σs)` of each
    /// piece, in f64.
    fn pieces(&self, segment: &Segment) -> Vec<(f64, f64, f64)> {
        let (z0, dz) = (segment.origin.z as f64, segment.dir.z as f64);
        let t_max = segment.t_max as f64;
        // Where the ray crosses each slab boundary, inside the segment, in order.
        let mut cuts: Vec<f64> = self
            .slabs
            .iter()
            .filter(|(end, _)| end.is_finite() && dz != 0.0)
            .map(|(end, _)| (*end as f64 - z0) / dz)
            .filter(|t| *t > 0.0 && *t < t_max)
            .collect();
        cuts.push(0.0);
        cuts.push(t_max);
        cuts.sort_by(f64::total_cmp);
        cuts.windows(2)
            .map(|w| {
                let mid = segment.origin + segment.dir * (0.5 * (w[0] + w[1])) as f32;
                let c = self.coefficients(mid);
                (w[1] - w[0], c.sigma_a as f64, c.sigma_s as f64)
            })
            .collect()
    }

    /// The exact mean of `event`'s estimate along `segment`: the probability of the
    /// outcome, or the expected distance of a real collision, from `σ(t) e^{−τ(t)}`
    /// integrated over each piece.
    fn analytic(&self, segment: &Segment, event: Event) -> f64 {
        let (mut tau, mut start, mut mean) = (0.0f64, 0.0f64, 0.0f64);
        for (length, sigma_a, sigma_s) in self.pieces(segment) {
            let sigma_t = sigma_a + sigma_s;
            let reach = (-tau).exp();
            let collide = 1.0 - (-sigma_t * length).exp();
            mean += reach
                * match event {
                    Event::Escape => 0.0,
                    Event::Scatter if sigma_t > 0.0 => sigma_s / sigma_t * collide,
                    Event::Absorb if sigma_t > 0.0 => sigma_a / sigma_t * collide,
                    Event::Scatter | Event::Absorb => 0.0,
                    Event::CollisionDistance if sigma_t > 0.0 => {
                        // ∫_0^ℓ (start + s) σt e^{−σt s} ds
                        start * collide
                            + (1.0 - (-sigma_t * length).exp() * (1.0 + sigma_t * length))
                                / sigma_t
                    }
                    Event::CollisionDistance => 0.0,
                };
            tau += sigma_t * length;
            start += length;
        }
        if event == Event::Escape {
            (-tau).exp()
        } else {
            mean
        }
    }
}

/// The probability that a walk allowed `steps` tentative collisions in a homogeneous
/// medium ends in a real collision of the kind with coefficient `sigma_x`, along a segment
/// of length `t_max`: the k-th tentative collision exists (a Poisson process of rate
/// `majorant`), the ones before it were null, and it is of that kind. Both readings of
/// "after `max_steps` tentative collisions return Exhausted" (stop at once, or only when
/// the next step lands inside the segment) give this; one step more or less does not.
fn capped_collision(sigma_x: f64, sigma_t: f64, majorant: f64, t_max: f64, steps: u32) -> f64 {
    let lambda = majorant * t_max;
    let null = 1.0 - sigma_t / majorant;
    let (mut poisson, mut below) = ((-lambda).exp(), 0.0);
    let mut total = 0.0;
    for k in 1..=steps {
        // P(N ≥ k) = 1 − Σ_{j<k} P(N = j).
        below += poisson;
        poisson *= lambda / k as f64;
        total += (1.0 - below) * null.powi(k as i32 - 1) * sigma_x / majorant;
    }
    total
}

/// The errata's M3: σ = (0.1, 0.9) on z < 0.5, (1.5, 0.5) beyond, majorant 2.
fn m3() -> Slabs {
    Slabs {
        slabs: vec![
            (0.5, coefficients(0.1, 0.9)),
            (f32::INFINITY, coefficients(1.5, 0.5)),
        ],
        majorant: 2.0,
    }
}

fn coefficients(sigma_a: f32, sigma_s: f32) -> Coefficients {
    Coefficients { sigma_a, sigma_s }
}

/// Which outcome an estimator counts.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Event {
    Escape,
    Scatter,
    Absorb,
    /// The distance of a real collision (0 for an escape).
    CollisionDistance,
}

/// The iteration bound the estimators pass, unless they say otherwise: far more than any
/// correct walk needs here.
const MAX_STEPS: u32 = 100_000;

/// The segment a flight crosses, and the step bound it is given.
#[derive(Clone, Copy, Debug)]
struct Segment {
    /// Where the ray starts.
    origin: Vec3,
    /// Its direction (unit).
    dir: Vec3,
    /// The segment's length.
    t_max: f32,
    /// The bound on tentative collisions.
    max_steps: u32,
}

/// The errata's segment: along +z from the origin, length 1.
const UNIT: Segment = Segment {
    origin: Vec3::ZERO,
    dir: Vec3::Z,
    t_max: 1.0,
    max_steps: MAX_STEPS,
};

/// One flight along `segment`; 1 when `event` happened, else 0 (or the collision
/// distance). A collision outside [0, t_max) is an error, and so is a bound that ran out
/// when it was [`MAX_STEPS`]; a smaller bound may run out (no collision). (A collision
/// exactly at 0 is what a uniform number of exactly 0 gives: allowed.)
fn flight<'a, T: Tasks>(
    t: &'a T,
    medium: Slabs,
    segment: Segment,
    event: Event,
) -> Box<crate::grade::estimator::Estimator<'a>> {
    let Segment {
        origin,
        dir,
        t_max,
        max_steps,
    } = segment;
    Box::new(move |s: &mut Sampler| {
        let ray = Ray::new(origin, dir);
        let outcome = t.delta_tracking(&medium, &ray, t_max, max_steps, s);
        let at = match outcome {
            FreeFlight::Scatter { t } | FreeFlight::Absorb { t } => Some(t),
            FreeFlight::Escape => None,
            // A small bound may run out: the flight then had no real collision.
            FreeFlight::Exhausted if max_steps < MAX_STEPS => None,
            FreeFlight::Exhausted => {
                return Err(format!(
                    "ran out of its {max_steps} steps (the majorant here is {}, at most {} times σt: a correct walk needs {})",
                    medium.majorant,
                    medium.majorant_ratio(),
                    if medium.majorant_ratio() == 1.0 {
                        "one step: every tentative collision is real"
                    } else {
                        "a few steps"
                    }
                ));
            }
        };
        if let Some(at) = at
            && !(0.0..t_max).contains(&at)
        {
            return Err(format!("{outcome:?} at a distance outside [0, {t_max})"));
        }
        let x = match event {
            Event::Escape => (outcome == FreeFlight::Escape) as u8 as f64,
            Event::Scatter => matches!(outcome, FreeFlight::Scatter { .. }) as u8 as f64,
            Event::Absorb => matches!(outcome, FreeFlight::Absorb { .. }) as u8 as f64,
            Event::CollisionDistance => at.unwrap_or(0.0) as f64,
        };
        Ok(x)
    })
}

/// A walk along the unit segment through σa = σs = 0.5 under a majorant of 4 (three of
/// four tentative collisions null) allowed `steps` tentative collisions: the probability
/// that it ends in `event` (scatter or absorb) moves by 2 to 10 % with each step more or
/// less in the range of small bounds.
fn capped<T: Tasks>(t: &T, event: Event, steps: u32) -> EstimatorSpec<'_> {
    let medium = Slabs {
        slabs: vec![(f32::INFINITY, coefficients(0.5, 0.5))],
        majorant: 4.0,
    };
    let kind = if event == Event::Absorb {
        "absorb"
    } else {
        "scatter"
    };
    EstimatorSpec {
        name: format!(
            "P({kind}), homogeneous σa = σs = 0.5, majorant 4, at most {steps} steps"
        ),
        analytic: capped_collision(0.5, 1.0, 4.0, 1.0, steps),
        samples: 100_000,
        estimate: flight(
            t,
            medium,
            Segment {
                max_steps: steps,
                ..UNIT
            },
            event,
        ),
    }
}

pub fn estimators<T: Tasks>(t: &T) -> Vec<EstimatorSpec<'_>> {
    // M1: homogeneous σa = σs = 0.5 under a majorant of 2 (null collisions).
    let m1 = Slabs {
        slabs: vec![(f32::INFINITY, coefficients(0.5, 0.5))],
        majorant: 2.0,
    };
    let m3 = m3();
    // M4: a pure scatterer, σs = 1, majorant 1: nothing is ever absorbed.
    let m4 = Slabs {
        slabs: vec![(f32::INFINITY, coefficients(0.0, 1.0))],
        majorant: 1.0,
    };
    // M5: σa = 0.2, σs = 0.3 under a majorant of 500: about 500 null collisions a flight,
    // where a walk that loses precision, caps its own steps or skips the null-collision
    // test shows.
    let m5 = Slabs {
        slabs: vec![(f32::INFINITY, coefficients(0.2, 0.3))],
        majorant: 500.0,
    };
    let e1 = (-1.0f64).exp();
    // M3's optical depth is 0.5 · 1 + 0.5 · 2 = 1.5; its outcome probabilities follow from
    // integrating σ(t) e^{−τ(t)} over each slab.
    let e_half = (-0.5f64).exp();
    let m3_escape = (-1.5f64).exp();
    let first = 1.0 - e_half;
    let second = e_half * (1.0 - (-1.0f64).exp());
    let m3_scatter = 0.9 * first + 0.25 * second;
    let m3_absorb = 0.1 * first + 0.75 * second;
    let spec = |name: &str, analytic: f64, medium: &Slabs, event: Event| EstimatorSpec {
        name: name.into(),
        analytic,
        samples: 100_000,
        estimate: flight(t, medium.clone(), UNIT, event),
    };
    // The same media along other segments, their answers from `Slabs::analytic`.
    let along = |name: &str, medium: &Slabs, segment: Segment, event: Event| EstimatorSpec {
        name: name.into(),
        analytic: medium.analytic(&segment, event),
        samples: 100_000,
        estimate: flight(t, medium.clone(), segment, event),
    };
    // M6: σt = 1 in both slabs, absorbing mostly in the second, under a majorant of 1: no
    // tentative collision is null, so one step always decides.
    let m6 = Slabs {
        slabs: vec![
            (0.5, coefficients(0.2, 0.8)),
            (f32::INFINITY, coefficients(0.7, 0.3)),
        ],
        majorant: 1.0,
    };
    // Down through M3 from z = 1.5 off the axis: the slabs in the other order.
    let down = Segment {
        origin: Vec3::new(0.3, -0.2, 1.5),
        dir: -Vec3::Z,
        t_max: 1.5,
        max_steps: MAX_STEPS,
    };
    // Across M3 at 37° from its axis, for 1.25: the boundary at t = 0.625.
    let oblique = Segment {
        origin: Vec3::new(-0.4, 0.7, 0.0),
        dir: Vec3::new(0.6, 0.0, 0.8),
        t_max: 1.25,
        max_steps: MAX_STEPS,
    };
    let short = Segment {
        t_max: 0.3,
        ..UNIT
    };
    let long = Segment {
        t_max: 2.5,
        ..UNIT
    };
    let one_step = Segment {
        max_steps: 1,
        ..UNIT
    };
    vec![
        spec(
            "P(escape) = e^−τ, homogeneous σt = 1, majorant 2",
            e1,
            &m1,
            Event::Escape,
        ),
        spec(
            "P(scatter), homogeneous σa = σs = 0.5, majorant 2",
            0.5 * (1.0 - e1),
            &m1,
            Event::Scatter,
        ),
        spec(
            "E[collision distance], homogeneous σt = 1, majorant 2",
            1.0 - 2.0 * e1,
            &m1,
            Event::CollisionDistance,
        ),
        spec(
            "P(escape) = e^−τ, two slabs, τ = 1.5",
            m3_escape,
            &m3,
            Event::Escape,
        ),
        spec("P(scatter), two slabs", m3_scatter, &m3, Event::Scatter),
        spec("P(absorb), two slabs", m3_absorb, &m3, Event::Absorb),
        spec("P(absorb) = 0 in a pure scatterer", 0.0, &m4, Event::Absorb),
        along(
            "P(escape), homogeneous σt = 1, majorant 2, a segment of length 0.3",
            &m1,
            short,
            Event::Escape,
        ),
        along(
            "E[collision distance], homogeneous σt = 1, majorant 2, a segment of length 2.5",
            &m1,
            long,
            Event::CollisionDistance,
        ),
        along(
            "P(scatter), two slabs crossed downwards from z = 1.5",
            &m3,
            down,
            Event::Scatter,
        ),
        along(
            "E[collision distance], two slabs crossed downwards from z = 1.5",
            &m3,
            down,
            Event::CollisionDistance,
        ),
        along(
            "P(absorb), two slabs crossed obliquely for 1.25",
            &m3,
            oblique,
            Event::Absorb,
        ),
        EstimatorSpec {
            name: "P(scatter), homogeneous σa = σs = 0.5, majorant 2, at most 2 steps".into(),
            analytic: capped_collision(0.5, 1.0, 2.0, 1.0, 2),
            samples: 100_000,
            estimate: flight(
                t,
                m1.clone(),
                Segment {
                    max_steps: 2,
                    ..UNIT
                },
                Event::Scatter,
            ),
        },
        capped(t, Event::Scatter, 3),
        capped(t, Event::Absorb, 5),
        along(
            "P(absorb), two slabs of σt = 1 under a majorant of 1, at most 1 step",
            &m6,
            one_step,
            Event::Absorb,
        ),
        EstimatorSpec {
            samples: 20_000,
            ..spec(
                "P(absorb), σa = 0.2, σs = 0.3 under a majorant of 500",
                0.4 * (1.0 - (-0.5f64).exp()),
                &m5,
                Event::Absorb,
            )
        },
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The piecewise integration gives the errata's closed forms along the unit segment.
    #[test]
    fn the_slab_integral_matches_the_closed_forms() {
        let m3 = m3();
        let e_half = (-0.5f64).exp();
        let first = 1.0 - e_half;
        let second = e_half * (1.0 - (-1.0f64).exp());
        let close = |a: f64, b: f64| assert!((a - b).abs() < 1e-6, "{a} vs {b}");
        close(m3.analytic(&UNIT, Event::Escape), (-1.5f64).exp());
        close(m3.analytic(&UNIT, Event::Scatter), 0.9 * first + 0.25 * second);
        close(m3.analytic(&UNIT, Event::Absorb), 0.1 * first + 0.75 * second);
        let m1 = Slabs {
            slabs: vec![(f32::INFINITY, coefficients(0.5, 0.5))],
            majorant: 2.0,
        };
        let e1 = (-1.0f64).exp();
        close(m1.analytic(&UNIT, Event::CollisionDistance), 1.0 - 2.0 * e1);
        // Every outcome together: probability 1, whatever the segment.
        let down = Segment {
            origin: Vec3::new(0.0, 0.0, 1.5),
            dir: -Vec3::Z,
            t_max: 1.5,
            max_steps: 1,
        };
        let total: f64 = [Event::Escape, Event::Scatter, Event::Absorb]
            .iter()
            .map(|e| m3.analytic(&down, *e))
            .sum();
        close(total, 1.0);
        // Downwards, the denser slab comes first: τ = 2 · 1 + 1 · 0.5.
        close(m3.analytic(&down, Event::Escape), (-2.5f64).exp());
    }

    /// The capped probability: with no bound it is the unbounded one; with one step, the
    /// first tentative collision's.
    #[test]
    fn the_capped_collision_probability_has_its_limits() {
        let close = |a: f64, b: f64| assert!((a - b).abs() < 1e-9, "{a} vs {b}");
        let unbounded = 0.5 * (1.0 - (-1.0f64).exp());
        close(capped_collision(0.5, 1.0, 2.0, 1.0, 200), unbounded);
        close(
            capped_collision(0.5, 1.0, 2.0, 1.0, 1),
            (1.0 - (-2.0f64).exp()) * 0.25,
        );
        // Without null collisions, one step decides.
        close(capped_collision(0.5, 1.0, 1.0, 1.0, 1), unbounded);
    }

    /// The piecewise integral agrees with a fine midpoint quadrature of `σa(t) e^{−τ(t)}`
    /// along a segment that crosses the slabs obliquely.
    #[test]
    fn the_slab_integral_matches_a_quadrature() {
        let m3 = m3();
        let segment = Segment {
            origin: Vec3::new(-0.4, 0.7, 0.0),
            dir: Vec3::new(0.6, 0.0, 0.8),
            t_max: 1.25,
            max_steps: MAX_STEPS,
        };
        let n = 100_000;
        let dt = segment.t_max as f64 / n as f64;
        let (mut tau, mut absorbed) = (0.0f64, 0.0f64);
        for i in 0..n {
            let t = (i as f64 + 0.5) * dt;
            let c = m3.coefficients(segment.origin + segment.dir * t as f32);
            let sigma_t = c.sigma_t() as f64;
            absorbed += c.sigma_a as f64 * (-(tau + 0.5 * sigma_t * dt)).exp() * dt;
            tau += sigma_t * dt;
        }
        let exact = m3.analytic(&segment, Event::Absorb);
        assert!((absorbed - exact).abs() < 1e-5, "{absorbed} vs {exact}");
        assert!((m3.analytic(&segment, Event::Escape) - (-tau).exp()).abs() < 1e-5);
    }
}
