//! Cases of `reflect`.

use super::CaseInput;
use super::random::{range, sphere, upper};
use crate::grade::call::Call;
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

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    (0..count)
        .map(|_| {
            let n = sphere(s);
            let frame = crate::math::Frame::from_normal(n);
            let wo = frame.to_world(upper(s, 0.0));
            let scale = range(s, 0.5, 2.0);
            CaseInput::new("", Call::Reflect { wo, n: n * scale })
                .note("n need not have unit length; keep the length of wo and its angle to n")
        })
        .collect()
}
