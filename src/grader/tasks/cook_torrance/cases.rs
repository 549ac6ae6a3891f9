//! Cases of `cook_torrance`.

use crate::grade::case_input::CaseInput;
use crate::grade::call::Call;
use crate::grade::domain::{Draw, Param, channel};
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
        Call::cook_torrance {
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
            "text: subnormal cos θo, grazing wi",
            Vec3::new(1.0, 0.0, 1e-45),
            at_degrees(-87.0),
            0.3,
            0.3,
            f0,
        )
        .note("4 cos θo cos θi underflows to 0: divide each G1 by its own cosine"),
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

/// The microfacet inputs of a Cook-Torrance call.
fn of(c: &Call) -> Option<(Vec3, Vec3, f32, f32)> {
    match c {
        Call::cook_torrance {
            wo,
            wi,
            alpha_x,
            alpha_y,
            ..
        } => Some((*wo, *wi, *alpha_x, *alpha_y)),
        _ => None,
    }
}

/// The declarations of the microfacet pair.
const PAIR: [Param; 6] = crate::microfacet_domain!("cook_torrance", of);

/// The declared domain of `cook_torrance(wo, wi, alpha_x, alpha_y, f0)`: unit local
/// directions anywhere (0 at or below the horizon, never NaN, also for `wo ≈ −wi`),
/// roughnesses from 0 to 1 along local x and y, and an RGB `f0` in [0, 1] (1 for the
/// renderer's metals).
pub const DOMAIN: &[Param] = &[
    PAIR[0],
    PAIR[1],
    // Open: with both directions above the horizon, `wo = −wi` is only approached, and
    // within the guard on `|wo + wi|²` the text accepts 0 as well as the formula's value
    // (h = n in exact arithmetic). The stability cases `cook_torrance/opposite_*` judge the
    // guard; `wo = −wi` with one direction below the horizon is 0 by the horizon rule.
    PAIR[2].open(),
    PAIR[3],
    PAIR[4],
    PAIR[5],
    channel("cook_torrance", "largest channel of f0", &["f0"], |c| {
        f0_of(c).map(|f0| f0.max_element() as f64)
    })
    .special(&[0.0, 0.04, 1.0]),
];

/// The `f0` of a Cook-Torrance call.
fn f0_of(c: &Call) -> Option<Vec3> {
    match c {
        Call::cook_torrance { f0, .. } => Some(*f0),
        _ => None,
    }
}

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    let mut d = Draw::new(s);
    (0..count)
        .map(|i| {
            // One case in eight aims wi at −wo.
            let (wo, wi, ax, ay) = d.microfacet(&PAIR, i % 8 == 3);
            let f0 = d.colour(&DOMAIN[6]);
            let below = wo.z.min(wi.z) <= 0.0;
            ct("", wo, wi, ax, ay, f0).note(if below { BELOW } else { CT })
        })
        .collect()
}
