//! Cases of `cook_torrance`.

use super::CaseInput;
use super::random::{colour, roughness, upper};
use crate::grade::call::Call;
use crate::sampling::Sampler;
use glam::Vec3;

const CT: &str =
    "f = F(wo·h) D(h) G1(wo) G1(wi) / (4 cos θo cos θi), G1 with the projected roughness";
const BELOW: &str = "a direction at or below the horizon: f = 0";

fn at_degrees(deg: f32) -> Vec3 {
    let r = deg.to_radians();
    Vec3::new(r.sin(), 0.0, r.cos())
}

fn ct(name: &str, wo: Vec3, wi: Vec3, alpha_x: f32, alpha_y: f32, f0: Vec3) -> CaseInput {
    CaseInput::new(
        name,
        Call::CookTorrance {
            wo,
            wi,
            alpha_x,
            alpha_y,
            f0,
        },
    )
}

pub fn fixed() -> Vec<CaseInput> {
    let f0 = Vec3::splat(0.04);
    vec![
        ct(
            "worksheet §3.3: α = 1, h = n",
            at_degrees(60.0),
            at_degrees(-60.0),
            1.0,
            1.0,
            f0,
        )
        .note(CT),
        ct(
            "errata: wi = n, θo = 89.9°",
            at_degrees(89.9),
            Vec3::Z,
            0.5,
            0.5,
            f0,
        )
        .note("with G1·G1 the value stays finite at grazing (→ 0.00857)"),
        ct(
            "coloured f0",
            at_degrees(20.0),
            at_degrees(-50.0),
            0.3,
            0.3,
            Vec3::new(0.95, 0.64, 0.54),
        )
        .note(CT),
        ct(
            "anisotropic, h tilted along x",
            at_degrees(40.0),
            at_degrees(-10.0),
            0.1,
            0.6,
            f0,
        )
        .note("αx applies along local x, αy along local y"),
        ct(
            "anisotropic, h tilted along y",
            Vec3::new(0.0, 0.643, 0.766),
            Vec3::new(0.0, 0.174, 0.985),
            0.1,
            0.6,
            f0,
        )
        .note("αx applies along local x, αy along local y"),
        ct(
            "wi below the surface",
            at_degrees(30.0),
            Vec3::new(0.6, 0.0, -0.8),
            0.3,
            0.3,
            f0,
        )
        .note(BELOW),
        ct(
            "wo below the surface",
            Vec3::new(0.6, 0.0, -0.8),
            at_degrees(30.0),
            0.3,
            0.3,
            f0,
        )
        .note(BELOW),
    ]
}

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    (0..count)
        .map(|i| {
            let wo = upper(s, 0.02);
            let wi = upper(s, 0.02);
            let (ax, ay) = (roughness(s, 0.05, 1.0), roughness(s, 0.05, 1.0));
            let f0 = colour(s, 0.02, 1.0);
            if i % 8 == 7 {
                ct("", wo, -wi, ax, ay, f0).note(BELOW)
            } else {
                ct("", wo, wi, ax, ay, f0).note(CT)
            }
        })
        .collect()
}
