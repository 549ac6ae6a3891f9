//! Cases of `smith_g1`.

use super::CaseInput;
use super::random::{roughness, upper};
use crate::grade::call::Call;
use crate::sampling::Sampler;
use glam::Vec3;

const G1: &str = "G1 = 1 / (1 + Λ) with the GGX Λ: a value in [0, 1]";
const BACK: &str = "back-facing: a direction below the surface is fully masked, G1 = 0";

fn at_degrees(deg: f32) -> Vec3 {
    let r = deg.to_radians();
    Vec3::new(r.sin(), 0.0, r.cos())
}

pub fn fixed() -> Vec<CaseInput> {
    let g1 = |name: &str, w: Vec3, alpha: f32| CaseInput::new(name, Call::SmithG1 { w, alpha });
    vec![
        g1("normal incidence", Vec3::Z, 0.5).note(G1),
        g1("errata §3.2.1: α = 0.5, θ = 85°", at_degrees(85.0), 0.5).note(G1),
        g1("errata: α = 1, cos θ = 0.5", at_degrees(60.0), 1.0).note(G1),
        g1("errata: grazing", Vec3::X, 0.5).note("grazing: G1 = 0"),
        g1(
            "errata §3.2.3: back-facing",
            Vec3::new(0.866_025_4, 0.0, -0.5),
            0.5,
        )
        .note(BACK),
        g1("smooth surface", at_degrees(70.0), 0.05).note(G1),
    ]
}

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    (0..count)
        .map(|i| {
            let w = upper(s, 0.0);
            let alpha = roughness(s, 0.05, 1.0);
            if i % 8 == 7 {
                CaseInput::new("", Call::SmithG1 { w: -w, alpha }).note(BACK)
            } else {
                CaseInput::new("", Call::SmithG1 { w, alpha }).note(G1)
            }
        })
        .collect()
}
