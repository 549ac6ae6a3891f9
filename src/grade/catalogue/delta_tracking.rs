//! The estimators of `delta_tracking`: media along a unit segment where the probability of
//! each outcome of a free flight is known in closed form (the errata's M1, M3 and M4).

use super::EstimatorSpec;
use crate::geometry::Ray;
use crate::grade::power::Declared;
use crate::medium::{Coefficients, FreeFlight, Medium};
use crate::sampling::Sampler;
use crate::worksheet::Tasks;
use glam::Vec3;

/// What the estimator and sampling checks of this task catch in at least 90 % of
/// gradings, as measured by `pbrlab power` (asserted by tests/instructor/power.rs).
pub const POWER: Declared = Declared {
    estimator_bias: Some(0.02),
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

/// Length of the segment every flight crosses.
const T_MAX: f32 = 1.0;
/// The iteration bound the estimators pass: far more than any correct walk needs here.
const MAX_STEPS: u32 = 100_000;

/// One flight along +z from the origin; 1 when `event` happened, else 0 (or the collision
/// distance). A collision outside [0, T_MAX) or a bound that ran out is an error. (A
/// collision exactly at 0 is what a uniform number of exactly 0 gives: allowed.)
fn flight<'a, T: Tasks>(
    t: &'a T,
    medium: Slabs,
    event: Event,
) -> Box<super::super::estimator::Estimator<'a>> {
    Box::new(move |s: &mut Sampler| {
        let ray = Ray::new(Vec3::ZERO, Vec3::Z);
        let outcome = t.delta_tracking(&medium, &ray, T_MAX, MAX_STEPS, s);
        let at = match outcome {
            FreeFlight::Scatter { t } | FreeFlight::Absorb { t } => Some(t),
            FreeFlight::Escape => None,
            FreeFlight::Exhausted => {
                return Err(format!(
                    "ran out of its {MAX_STEPS} steps (the majorant here is {}, at most twice σt: a correct walk needs a few steps)",
                    medium.majorant
                ));
            }
        };
        if let Some(at) = at
            && !(0.0..T_MAX).contains(&at)
        {
            return Err(format!("{outcome:?} at a distance outside [0, {T_MAX})"));
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

pub fn estimators<T: Tasks>(t: &T) -> Vec<EstimatorSpec<'_>> {
    // M1: homogeneous σa = σs = 0.5 under a majorant of 2 (null collisions).
    let m1 = Slabs {
        slabs: vec![(f32::INFINITY, coefficients(0.5, 0.5))],
        majorant: 2.0,
    };
    // M3: σ = (0.1, 0.9) on [0, 0.5), (1.5, 0.5) on [0.5, 1), majorant 2.
    let m3 = Slabs {
        slabs: vec![
            (0.5, coefficients(0.1, 0.9)),
            (f32::INFINITY, coefficients(1.5, 0.5)),
        ],
        majorant: 2.0,
    };
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
        estimate: flight(t, medium.clone(), event),
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
