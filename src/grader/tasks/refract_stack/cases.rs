//! Cases of `refract`, `critical_angle` and `refract_stack`.

use crate::grade::case_input::CaseInput;
use crate::grade::catalogue::indices::{ETA, critical, eta_pair, index_ratio, sin2_t};
use crate::grade::argument::StackInput;
use crate::grade::call::Call;
use crate::grade::case::Rule;
use crate::grade::domain::{Boundary, Draw, Param, Spread, cos_between, length, upper_cosine};
use crate::grade::tolerance::Tolerance;
use crate::sampling::Sampler;
use glam::Vec3;

const TIR: &str = "sin θt would exceed 1: total internal reflection, return None";
const STACK: &str = "η sin θ is the same in every medium; perpendicular_shift is \
                     d sin(θin − θslab)/cos θslab, interface_offset is d tan θslab; \
                     intensities multiply (1 − R) over the interfaces";
const CRITICAL: &str = "θc = asin(η_t/η_i), only when η_i > η_t";

/// The stack calculator's answers are compared a little looser than pure f64, because its
/// Schlick column goes through the f32 `fresnel_schlick`.
const STACK_TOLERANCE: Tolerance = Tolerance::new(1e-6, 1e-5);

fn stack(eta_incident: f64, slabs: &[(f64, f64)], eta_exit: f64) -> StackInput {
    StackInput {
        eta_incident,
        slabs: slabs.to_vec(),
        eta_exit,
        intensity: 100.0,
    }
}

fn at_degrees(deg: f32) -> Vec3 {
    let r = deg.to_radians();
    Vec3::new(r.sin(), 0.0, r.cos())
}

pub fn fixed() -> Vec<CaseInput> {
    let refract = |name: &str, wi: Vec3, eta_i: f32, eta_t: f32| {
        CaseInput::new(
            name,
            Call::refract {
                wi,
                n: Vec3::Z,
                eta_i,
                eta_t,
            },
        )
    };
    let critical = |name: &str, eta_i: f64, eta_t: f64| {
        CaseInput::new(name, Call::critical_angle { eta_i, eta_t })
            .rule(Rule::Close(Tolerance::F64))
            .note(CRITICAL)
    };
    let layers = |name: &str, theta_deg: f64, stack: StackInput| {
        CaseInput::new(name, Call::refract_stack { theta_deg, stack })
            .rule(Rule::Close(STACK_TOLERANCE))
            .note(STACK)
    };
    vec![
        refract("worksheet §1.4 air→glass 30°", at_degrees(30.0), 1.0, 1.5)
            .note("the result points away from the surface on the far side (z < 0 here)"),
        refract("normal incidence", Vec3::Z, 1.0, 1.5),
        refract(
            "equal indices pass straight through",
            at_degrees(60.0),
            1.33,
            1.33,
        ),
        refract("errata: glass→air 45°", at_degrees(45.0), 1.5, 1.0).note(TIR),
        refract("glass→air 40°", at_degrees(40.0), 1.5, 1.0),
        CaseInput::new(
            "errata: normal of length 2",
            Call::refract {
                wi: at_degrees(30.0),
                n: Vec3::new(0.0, 0.0, 2.0),
                eta_i: 1.0,
                eta_t: 1.5,
            },
        )
        .note("n need not have unit length: normalise it"),
        critical("errata §1.2 glass→air", 1.5, 1.0),
        critical("errata §1.2 water→air", 1.33, 1.0),
        critical("errata §1.2 glass→water", 1.5, 1.33),
        critical("errata: air→glass has none", 1.0, 1.5),
        critical("errata: equal indices have none", 1.33, 1.33),
        layers(
            "worksheet §1.4 air|glass 10 mm|water at 30°",
            30.0,
            stack(1.0, &[(1.5, 10.0)], 1.33),
        ),
        layers(
            "errata: normal incidence",
            0.0,
            stack(1.0, &[(1.5, 10.0)], 1.33),
        ),
        layers(
            "errata: 89° incidence",
            89.0,
            stack(1.0, &[(1.5, 10.0)], 1.33),
        ),
        layers(
            "TIR at the first interface",
            50.0,
            stack(1.5, &[(1.0, 2.0)], 1.5),
        )
        .note(TIR),
        layers(
            "TIR at the second interface",
            45.0,
            stack(1.5, &[(1.4, 3.0)], 1.0),
        )
        .note(TIR),
        layers(
            "three slabs",
            35.0,
            stack(1.0, &[(1.5, 2.0), (1.33, 4.0), (2.4, 1.0)], 1.2),
        ),
    ]
}

fn refract_of(c: &Call) -> Option<(Vec3, Vec3, f32, f32)> {
    match c {
        Call::refract {
            wi,
            n,
            eta_i,
            eta_t,
        } => Some((*wi, *n, *eta_i, *eta_t)),
        _ => None,
    }
}

fn stack_of(c: &Call) -> Option<(f64, &StackInput)> {
    match c {
        Call::refract_stack { theta_deg, stack } => Some((*theta_deg, stack)),
        _ => None,
    }
}

/// The largest `sin²θ` over the media after the first: past 1 the ray reflects totally.
fn largest_sin2(theta_deg: f64, stack: &StackInput) -> f64 {
    let invariant = stack.eta_incident * theta_deg.to_radians().sin();
    stack
        .slabs
        .iter()
        .map(|s| s.0)
        .chain([stack.eta_exit])
        .map(|eta| (invariant / eta).powi(2))
        .fold(0.0, f64::max)
}

/// The ratio of neighbouring indices nearest to 1 (equal neighbours: no interface).
fn nearest_equal(stack: &StackInput) -> f64 {
    let etas: Vec<f64> = std::iter::once(stack.eta_incident)
        .chain(stack.slabs.iter().map(|s| s.0))
        .chain([stack.eta_exit])
        .collect();
    etas.windows(2)
        .map(|w| w[0] / w[1])
        .min_by(|a, b| (a.ln().abs()).total_cmp(&b.ln().abs()))
        .unwrap_or(1.0)
}

/// The declared domain of `refract(wi, n, eta_i, eta_t)`, `critical_angle(eta_i, eta_t)`
/// and `refract_stack(theta_deg, stack)`: `wi` on the side `n` points to, `n` of any
/// non-zero length, indices from vacuum to germanium (1 to 4) either way round and equal;
/// total internal reflection from the critical angle on (`sin²θt ≥ 1`); stacks of zero or more slabs of
/// any finite thickness, at incidence from the normal to grazing, of any intensity.
pub const DOMAIN: &[Param] = &[
    upper_cosine("refract", "cos(wi, n)", &["wi", "n"], |c| {
        refract_of(c).map(|x| cos_between(x.0, x.1))
    }),
    length("refract", "|n|", &["n"], |c| {
        refract_of(c).map(|x| x.1.length() as f64)
    }),
    index_ratio("refract", "η_i/η_t", &["eta_i", "eta_t"], |c| {
        refract_of(c).map(|x| x.2 as f64 / x.3 as f64)
    }),
    critical("refract", "sin²θt", &[], |c| {
        refract_of(c).map(|x| sin2_t(cos_between(x.0, x.1), x.2 as f64 / x.3 as f64))
    }),
    index_ratio(
        "critical_angle",
        "η_i/η_t",
        &["eta_i", "eta_t"],
        |c| match c {
            Call::critical_angle { eta_i, eta_t } => Some(eta_i / eta_t),
            _ => None,
        },
    ),
    Param::new(
        "refract_stack",
        "θ (degrees)",
        &["theta_deg"],
        |c| stack_of(c).map(|x| x.0),
        0.0,
        89.9,
    )
    .boundaries(&[Boundary {
        at: 0.0,
        what: "normal incidence",
        continuous: false,
    }]),
    critical(
        "refract_stack",
        "largest sin²θ",
        &["stack.eta_incident", "stack.slabs", "stack.eta_exit"],
        |c| stack_of(c).map(|x| largest_sin2(x.0, x.1)),
    ),
    index_ratio(
        "refract_stack",
        "neighbouring indices",
        &["stack.eta_incident", "stack.slabs", "stack.eta_exit"],
        |c| stack_of(c).map(|x| nearest_equal(x.1)),
    ),
    Param::new(
        "refract_stack",
        "slabs",
        &["stack.slabs"],
        |c| stack_of(c).map(|x| x.1.slabs.len() as f64),
        0.0,
        4.0,
    )
    .special(&[0.0, 1.0]),
    length("refract_stack", "thickness", &["stack.slabs"], |c| {
        stack_of(c).and_then(|x| x.1.slabs.iter().map(|s| s.1).min_by(|a, b| a.total_cmp(b)))
    })
    .special(&[]),
    Param::new(
        "refract_stack",
        "intensity",
        &["stack.intensity"],
        |c| stack_of(c).map(|x| x.1.intensity),
        1e-2,
        1e3,
    )
    .spread(Spread::Log {
        from: 1e-2,
        to: 1e2,
    })
    .special(&[1.0, 100.0]),
];

/// `refract` with indices whose ratio comes from [`DOMAIN`]`[2]`; every other case aims at
/// the critical angle when the light goes to a less dense medium.
fn random_refract(d: &mut Draw, aim: bool) -> CaseInput {
    let (eta_i, eta_t) = eta_pair(d, &DOMAIN[2], ETA);
    let ratio = eta_i as f64 / eta_t as f64;
    let cos = if aim && ratio > 1.0 {
        let s2 = d.value(&DOMAIN[3]);
        (1.0 - s2 / (ratio * ratio)).max(0.0).sqrt()
    } else {
        d.value(&DOMAIN[0])
    };
    let n = d.normal();
    let wi = d.direction_at(n, cos);
    let n = n * d.value(&DOMAIN[1]) as f32;
    let case = CaseInput::new(
        "",
        Call::refract {
            wi,
            n,
            eta_i,
            eta_t,
        },
    );
    if sin2_t(cos_between(wi, n), ratio) >= 1.0 {
        case.note(TIR)
    } else {
        case
    }
}

/// A stack drawn from [`DOMAIN`]: zero to four slabs, neighbours sometimes equal, and every
/// other case aimed at the critical angle of one medium.
fn random_stack(d: &mut Draw, aim: bool) -> CaseInput {
    let eta = |d: &mut Draw| ETA.0 + (ETA.1 - ETA.0) * d.unit();
    let count = d.value(&DOMAIN[8]).round() as usize;
    let mut etas: Vec<f64> = (0..count + 2).map(|_| eta(d)).collect();
    // Now and then a neighbour at a ratio near 1 (or exactly equal).
    if d.unit() < 0.5 {
        let k = 1 + d.index(etas.len() - 1);
        etas[k] = (etas[k - 1] / d.value(&DOMAIN[7])).clamp(ETA.0, ETA.1);
    }
    let slabs: Vec<(f64, f64)> = etas[1..etas.len() - 1]
        .iter()
        .map(|&e| (e, d.value(&DOMAIN[9])))
        .collect();
    let mut st = stack(etas[0], &slabs, etas[etas.len() - 1]);
    st.intensity = d.value(&DOMAIN[10]);
    let mut theta_deg = d.value(&DOMAIN[5]);
    if aim {
        let k = 1 + d.index(etas.len() - 1);
        let s = d.value(&DOMAIN[6]).sqrt() * etas[k] / etas[0];
        if s < 1.0 {
            theta_deg = s.asin().to_degrees().min(DOMAIN[5].hi);
        }
    }
    CaseInput::new(
        "",
        Call::refract_stack {
            theta_deg,
            stack: st,
        },
    )
    .rule(Rule::Close(STACK_TOLERANCE))
    .note(STACK)
}

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    let mut d = Draw::new(s);
    (0..count)
        .map(|i| match i % 3 {
            0 => random_refract(&mut d, i % 2 == 1),
            1 => {
                let (eta_i, eta_t) = eta_pair(&mut d, &DOMAIN[4], ETA);
                CaseInput::new(
                    "",
                    Call::critical_angle {
                        eta_i: eta_i as f64,
                        eta_t: eta_t as f64,
                    },
                )
                .rule(Rule::Close(Tolerance::F64))
                .note(CRITICAL)
            }
            _ => random_stack(&mut d, i % 2 == 1),
        })
        .collect()
}
