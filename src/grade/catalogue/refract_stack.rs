//! Cases of `refract`, `critical_angle` and `refract_stack`.

use super::CaseInput;
use super::random::{eta, range, range64, sphere, upper};
use crate::grade::call::{Call, StackInput};
use crate::grade::case::Rule;
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
            Call::Refract {
                wi,
                n: Vec3::Z,
                eta_i,
                eta_t,
            },
        )
    };
    let critical = |name: &str, eta_i: f64, eta_t: f64| {
        CaseInput::new(name, Call::CriticalAngle { eta_i, eta_t })
            .rule(Rule::Close(Tolerance::F64))
            .note(CRITICAL)
    };
    let layers = |name: &str, theta_deg: f64, stack: StackInput| {
        CaseInput::new(name, Call::RefractStack { theta_deg, stack })
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
            Call::Refract {
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

pub fn random(s: &mut Sampler, count: usize) -> Vec<CaseInput> {
    let mut cases = Vec::with_capacity(count);
    while cases.len() < count {
        match cases.len() % 3 {
            0 => {
                let n = sphere(s);
                let frame = crate::math::Frame::from_normal(n);
                let wi = frame.to_world(upper(s, 0.0));
                let (eta_i, eta_t) = (eta(s), eta(s));
                let sin2_t = (eta_i / eta_t).powi(2) * (1.0 - wi.dot(n).powi(2)).max(0.0);
                // Within rounding of the critical angle both answers are right.
                if (sin2_t - 1.0).abs() < 1e-3 {
                    continue;
                }
                let case = CaseInput::new(
                    "",
                    Call::Refract {
                        wi,
                        n: n * range(s, 0.5, 2.0),
                        eta_i,
                        eta_t,
                    },
                );
                cases.push(if sin2_t > 1.0 { case.note(TIR) } else { case });
            }
            1 => {
                let (eta_i, eta_t) = (eta(s) as f64, eta(s) as f64);
                cases.push(
                    CaseInput::new("", Call::CriticalAngle { eta_i, eta_t })
                        .rule(Rule::Close(Tolerance::F64))
                        .note(CRITICAL),
                );
            }
            _ => {
                let slabs = (0..1 + (s.next_1d() * 3.0) as usize)
                    .map(|_| (eta(s) as f64, range64(s, 0.5, 20.0)))
                    .collect::<Vec<_>>();
                let st = stack(eta(s) as f64, &slabs, eta(s) as f64);
                let theta_deg = range64(s, 0.0, 85.0);
                // Skip stacks that graze an interface within rounding of its critical angle.
                let invariant = st.eta_incident * theta_deg.to_radians().sin();
                let etas = slabs.iter().map(|x| x.0).chain([st.eta_exit]);
                if etas.into_iter().any(|e| (invariant / e - 1.0).abs() < 1e-3) {
                    continue;
                }
                cases.push(
                    CaseInput::new(
                        "",
                        Call::RefractStack {
                            theta_deg,
                            stack: st,
                        },
                    )
                    .rule(Rule::Close(STACK_TOLERANCE))
                    .note(STACK),
                );
            }
        }
    }
    cases
}
