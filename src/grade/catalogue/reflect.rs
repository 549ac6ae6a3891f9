//! Cases of `reflect`.

use super::CaseInput;
use crate::grade::call::Call;
use crate::grade::domain::{Draw, Param, Spread, UPPER_COS_BOUNDARIES, cos_between};
use crate::sampling::Sampler;
use glam::Vec3;

const AWAY: &str = "both wo and the result point away from the surface: keep the part of wo \
                    along n, reverse its part in the surface plane";

pub fn fixed() -> Vec<CaseInput> {
    vec![
        CaseInput::new(
            "worksheet §1.5",
            Call::Reflect {
                wo: Vec3::new(0.6, 0.8, 0.0),
                n: Vec3::Y,
            },
        )
        .note(AWAY),
        CaseInput::new(
            "errata: normal of length 2",
            Call::Reflect {
                wo: Vec3::new(-0.6, 0.8, 0.0),
                n: Vec3::new(0.0, 2.0, 0.0),
            },
        )
        .note("n need not have unit length: normalise it"),
        CaseInput::new(
            "grazing",
            Call::Reflect {
                wo: Vec3::X,
                n: Vec3::Z,
            },
        )
        .note(AWAY),
        CaseInput::new(
            "normal incidence",
            Call::Reflect {
                wo: Vec3::Z,
                n: Vec3::Z,
            },
        )
        .note(AWAY),
    ]
}

/// Lengths of a vector the text allows without requiring unit length (`n`; and `wo`,
/// whose length the result keeps).
const LENGTH: (f64, f64) = (1e-2, 1e2);

/// The declared domain of `reflect(wo, n)`: `wo` on the side `n` points to, from grazing to
/// the normal; `n` any non-zero vector along the normal, and `wo` of any length (the
/// result keeps it).
pub const DOMAIN: &[Param] = &[
    Param {
        function: "reflect",
        name: "cos(wo, n)",
        covers: &["wo", "n"],
        value: |c| match c {
            Call::Reflect { wo, n } => Some(cos_between(*wo, *n)),
            _ => None,
        },
        lo: 0.0,
        hi: 1.0,
        spread: Spread::Linear,
        boundaries: UPPER_COS_BOUNDARIES,
        special: &[],
        resolution: 1e-7,
        on_boundaries: true,
    },
    Param {
        function: "reflect",
        name: "|n|",
        covers: &["n"],
        value: |c| match c {
            Call::Reflect { n, .. } => Some(n.length() as f64),
            _ => None,
        },
        lo: LENGTH.0,
        hi: LENGTH.1,
        spread: Spread::Log {
            from: LENGTH.0,
            to: LENGTH.1,
        },
        boundaries: &[],
        special: &[1.0, 2.0],
        resolution: 1e-6,
        on_boundaries: true,
    },
    Param {
        function: "reflect",
        name: "|wo|",
        covers: &["wo"],
        value: |c| match c {
            Call::Reflect { wo, .. } => Some(wo.length() as f64),
            _ => None,
        },
        lo: LENGTH.0,
        hi: LENGTH.1,
        spread: Spread::Log {
            from: LENGTH.0,
            to: LENGTH.1,
        },
        boundaries: &[],
        special: &[1.0],
        resolution: 1e-6,
        on_boundaries: true,
    },
];

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    let mut d = Draw::new(s);
    (0..count)
        .map(|_| {
            let n = d.sphere();
            let cos = d.value(&DOMAIN[0]);
            let wo = d.direction_at(n, cos);
            let n = n * d.value(&DOMAIN[1]) as f32;
            let wo = wo * d.value(&DOMAIN[2]) as f32;
            CaseInput::new("", Call::Reflect { wo, n })
                .note("n need not have unit length; keep the length of wo and its angle to n")
        })
        .collect()
}
