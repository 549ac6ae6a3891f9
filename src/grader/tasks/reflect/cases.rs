//! Cases of `reflect`.

use crate::grade::case_input::CaseInput;
use crate::grade::call::Call;
use crate::grade::domain::{Draw, Param, cos_between, cosine, length};
use crate::sampling::Sampler;
use glam::Vec3;

const AWAY: &str = "both wo and the result point away from the surface: keep the part of wo \
                    along n, reverse its part in the surface plane";

pub fn fixed() -> Vec<CaseInput> {
    vec![
        CaseInput::new(
            "worksheet §1.5",
            Call::reflect {
                wo: Vec3::new(0.6, 0.8, 0.0),
                n: Vec3::Y,
            },
        )
        .note(AWAY),
        CaseInput::new(
            "errata: normal of length 2",
            Call::reflect {
                wo: Vec3::new(-0.6, 0.8, 0.0),
                n: Vec3::new(0.0, 2.0, 0.0),
            },
        )
        .note("n need not have unit length: normalise it"),
        CaseInput::new(
            "grazing",
            Call::reflect {
                wo: Vec3::X,
                n: Vec3::Z,
            },
        )
        .note(AWAY),
        CaseInput::new(
            "normal incidence",
            Call::reflect {
                wo: Vec3::Z,
                n: Vec3::Z,
            },
        )
        .note(AWAY),
    ]
}

/// The declared domain of `reflect(wo, n)`: `wo` on the side `n` points to, from grazing to
/// the normal; `n` any non-zero vector along the normal, and `wo` of any length (the
/// result keeps it).
pub const DOMAIN: &[Param] = &[
    cosine("reflect", "cos(wo, n)", &["wo", "n"], |c| match c {
        Call::reflect { wo, n } => Some(cos_between(*wo, *n)),
        _ => None,
    }),
    length("reflect", "|n|", &["n"], |c| match c {
        Call::reflect { n, .. } => Some(n.length() as f64),
        _ => None,
    }),
    length("reflect", "|wo|", &["wo"], |c| match c {
        Call::reflect { wo, .. } => Some(wo.length() as f64),
        _ => None,
    }),
];

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    let mut d = Draw::new(s);
    (0..count)
        .map(|_| {
            let n = d.normal();
            let cos = d.value(&DOMAIN[0]);
            let wo = d.direction_at(n, cos);
            let n = n * d.value(&DOMAIN[1]) as f32;
            let wo = wo * d.value(&DOMAIN[2]) as f32;
            CaseInput::new("", Call::reflect { wo, n })
                .note("n need not have unit length; keep the length of wo and its angle to n")
        })
        .collect()
}
