//! Cases of `cook_torrance`.

use super::CaseInput;
use crate::grade::call::Call;
use crate::grade::domain::{
    Boundary, Draw, Param, anisotropy, cos_between, cos_z, cosine, ratio, roughness,
};
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

/// The value of a Cook-Torrance call, for the declarations below.
fn of(c: &Call) -> Option<(Vec3, Vec3, f32, f32, Vec3)> {
    match c {
        Call::CookTorrance {
            wo,
            wi,
            alpha_x,
            alpha_y,
            f0,
        } => Some((*wo, *wi, *alpha_x, *alpha_y, *f0)),
        _ => None,
    }
}

/// The declared domain of `cook_torrance(wo, wi, alpha_x, alpha_y, f0)`: unit local
/// directions anywhere (0 at or below the horizon, never NaN, also for `wo ≈ −wi`),
/// roughnesses from 0 to 1 along local x and y, and an RGB `f0` in [0, 1] (1 for the
/// renderer's metals).
pub const DOMAIN: &[Param] = &[
    cosine("cook_torrance", "cos θo", &["wo"], |c| {
        of(c).map(|x| cos_z(x.0))
    }),
    cosine("cook_torrance", "cos θi", &["wi"], |c| {
        of(c).map(|x| cos_z(x.1))
    }),
    Param::new(
        "cook_torrance",
        "cos(wo, wi)",
        &["wo", "wi"],
        |c| of(c).map(|x| cos_between(x.0, x.1)),
        -1.0,
        1.0,
    )
    .boundaries(&[Boundary {
        at: -1.0,
        what: "wo = −wi (no half vector)",
    }]),
    roughness("cook_torrance", "alpha_x", &["alpha_x"], |c| {
        of(c).map(|x| x.2 as f64)
    }),
    roughness("cook_torrance", "alpha_y", &["alpha_y"], |c| {
        of(c).map(|x| x.3 as f64)
    }),
    anisotropy("cook_torrance", &["alpha_x", "alpha_y"], |c| {
        of(c).and_then(|x| ratio(x.2, x.3))
    }),
    Param::new(
        "cook_torrance",
        "largest channel of f0",
        &["f0"],
        |c| of(c).map(|x| x.4.max_element() as f64),
        0.0,
        1.0,
    )
    .special(&[0.0, 0.04, 1.0]),
];

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    let mut d = Draw::new(s);
    (0..count)
        .map(|i| {
            let cos_o = d.value(&DOMAIN[0]);
            let wo = d.direction_at(Vec3::Z, cos_o);
            // One case in eight aims wi at −wo, the rest draw it on its own.
            let wi = if i % 8 == 3 {
                let c = d.value(&DOMAIN[2]);
                d.direction_at(wo, c)
            } else {
                let cos_i = d.value(&DOMAIN[1]);
                d.direction_at(Vec3::Z, cos_i)
            };
            let (ax, ay) = d.alpha_pair(&DOMAIN[3], &DOMAIN[5]);
            let f0 = d.colour(&DOMAIN[6]);
            let below = wo.z.min(wi.z) <= 0.0;
            ct("", wo, wi, ax, ay, f0).note(if below { BELOW } else { CT })
        })
        .collect()
}
