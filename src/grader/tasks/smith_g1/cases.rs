//! Cases of `smith_g1`.

use crate::grade::case_input::CaseInput;
use crate::grade::call::Call;
use crate::grade::domain::{Draw, Param, cos_z, cosine, roughness};
use crate::sampling::Sampler;
use glam::Vec3;

const G1: &str = "G1 = 1 / (1 + Λ) with the GGX Λ: a value in [0, 1]";
const BACK: &str = "back-facing: a direction below the surface is fully masked, G1 = 0";

fn at_degrees(deg: f32) -> Vec3 {
    let r = deg.to_radians();
    Vec3::new(r.sin(), 0.0, r.cos())
}

pub fn fixed() -> Vec<CaseInput> {
    let g1 = |name: &str, w: Vec3, alpha: f32| CaseInput::new(name, Call::smith_g1 { w, alpha });
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

/// The declared domain of `smith_g1(w, alpha)`: `w` any unit direction (below the horizon
/// returns 0), `alpha` from 0 (a mirror, still finite) to 1 and beyond (very rough).
pub const DOMAIN: &[Param] = &[
    cosine("smith_g1", "cos θ of w", &["w"], |c| match c {
        Call::smith_g1 { w, .. } => Some(cos_z(*w)),
        _ => None,
    }),
    roughness("smith_g1", "alpha", &["alpha"], |c| match c {
        Call::smith_g1 { alpha, .. } => Some(*alpha as f64),
        _ => None,
    }),
];

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    let mut d = Draw::new(s);
    (0..count)
        .map(|_| {
            let cos = d.value(&DOMAIN[0]);
            let w = d.direction_at(Vec3::Z, cos);
            let alpha = d.value(&DOMAIN[1]) as f32;
            let case = CaseInput::new("", Call::smith_g1 { w, alpha });
            if w.z <= 0.0 {
                case.note(BACK)
            } else {
                case.note(G1)
            }
        })
        .collect()
}
