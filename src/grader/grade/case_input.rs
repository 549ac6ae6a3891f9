//! A value case before its expected output is known ([`CaseInput`]), as each task's
//! `cases.rs` declares it, and the Jacobian case every sampler task shares.

use super::call::{Call, SampleCall};
use super::case::Rule;
use super::domain::Param;
use super::tolerance::Tolerance;
use crate::sampling::Sampler;

/// A value case before its expected output is known.
#[derive(Clone, Debug, PartialEq)]
pub struct CaseInput {
    /// Where the case comes from.
    pub name: String,
    /// The call.
    pub call: Call,
    /// How outputs are compared.
    pub rule: Rule,
    /// The usual cause of a failure of this case.
    pub note: Option<String>,
    /// Drawn from the declared domain rather than named by the worksheet or the errata:
    /// dropped when it is ill-posed in f32 (see [`super::value_cases::evaluate`]).
    pub drawn: bool,
}

impl CaseInput {
    /// A case compared within the f32 tolerance.
    pub fn new(name: impl Into<String>, call: Call) -> Self {
        Self {
            name: name.into(),
            call,
            rule: Rule::Close(Tolerance::F32),
            note: None,
            drawn: false,
        }
    }

    /// The same case with a note shown when it fails.
    pub fn note(mut self, note: impl Into<String>) -> Self {
        self.note = Some(note.into());
        self
    }

    /// The same case with another comparison rule.
    pub fn rule(mut self, rule: Rule) -> Self {
        self.rule = rule;
        self
    }
}

/// Seed of the public random cases (fixed: they are stored).
pub const PUBLIC_SEED: u64 = 0x5eed_2024;

/// The declaration of a sampler's Jacobian case: points of the unit square (its one input,
/// `u`, is any point of the square).
pub const JACOBIAN: Param = Param::new(
    "sample_jacobian",
    "u",
    &["sampler", "points", "h"],
    |c| match c {
        Call::sample_jacobian { points, .. } => Some(points.len() as f64),
        _ => None,
    },
    1.0,
    1e4,
);

/// The Jacobian cases of a sampler (see [`Call::sample_jacobian`]): 400 points spread over
/// the square away from its edges, a finite-difference step of 1e-3 (its truncation and
/// rounding stay near 1e-4), judged to 2e-3 at 90 % of the points, so that a warp 1 % off
/// its pdf fails while a correct warp with seams (a concentric map) passes.
pub fn jacobian_case(name: &str, sampler: SampleCall) -> CaseInput {
    /// Points per case.
    const POINTS: usize = 400;
    let mut s = Sampler::new(PUBLIC_SEED, 0x6a61_636f_6269);
    let points = (0..POINTS)
        .map(|_| glam::Vec2::new(0.02, 0.02) + 0.96 * s.next_2d())
        .collect();
    CaseInput::new(
        name,
        Call::sample_jacobian {
            sampler,
            points,
            h: 1e-3,
        },
    )
    .rule(Rule::Unity {
        tolerance: 2e-3,
        share: 0.9,
    })
    .note(
        "the solid angle a warp sweeps per unit area of the square is 1/pdf: sample the \
         density your pdf returns",
    )
}
