//! Inputs moved within rounding ([`Call::jitters`]): how far a correct f32 implementation's
//! answer may lie from the reference's, the spread a value case's tolerance adds.

use super::call::{Call, SampleCall, StackInput};
use super::test_brdf::TestBrdf;
use crate::bsdf::{KajiyaKayParams, PhongParams};
use glam::{DVec3, Vec2, Vec3};

/// How many f32 ulps [`Call::jitters`] moves an input at most: the rounding a correct
/// implementation may introduce in the quantities it derives from its inputs.
pub const JITTER_ULPS: f64 = 4.0;

/// The smallest positive (subnormal) f32, 2^-149.
const SMALLEST_SUBNORMAL: f64 = 1.401_298_464_324_817e-45;

/// The largest angle (radians) by which [`Call::jitters`] turns a direction: what an
/// angle computed from a cosine or sine within `JITTER_ULPS` ulps of 1 may be off,
/// `sqrt(2 · 4 ε)`.
const MAX_TURN: f64 = 9.8e-4;

/// A uniform number in [0, 1) from `seed` and `salt`: the same pair, the same number.
fn hash_unit(seed: u64, salt: u64) -> f64 {
    let mut h = seed ^ salt.wrapping_mul(0x9e37_79b9_7f4a_7c15);
    h ^= h >> 29;
    h = h.wrapping_mul(0xbf58_476d_1ce4_e5b9);
    h ^= h >> 32;
    h = h.wrapping_mul(0x94d0_49bb_1331_11eb);
    h ^= h >> 31;
    (h >> 11) as f64 / (1u64 << 53) as f64
}

impl Call {
    /// Copies of the call with its inputs moved within what a correct f32 implementation may
    /// lose to rounding, to measure how far correct answers can lie from the reference's:
    /// - every real input by up to [`JITTER_ULPS`] ulps, by a factor that depends only on
    ///   `seed` and the value, so equal inputs stay equal (equal indices, `αx = αy`) and
    ///   zeros stay zero; a subnormal one (a cosine of 1e-45) by up to as many of the
    ///   smallest subnormal, away from 0;
    /// - every direction turned by `JITTER_ULPS · ε / sin θ` near a pole of the local
    ///   normal or of another direction, or by `JITTER_ULPS · ε / cos θ` near the horizon
    ///   of another direction (at most `MAX_TURN`), toward that axis (landing on a pole
    ///   that close), away from it, or sideways: an implementation that goes through
    ///   `sqrt(1 − cos²)`, `acos` or `asin` (the polar form of an NDF, Snell's law by
    ///   angles) loses that much there, and a direction stored in f32 is not quite unit, so
    ///   `z` and `(x, y)` disagree near the normal; and its length stretched by up to
    ///   [`JITTER_ULPS`] ulps.
    ///
    /// Integers (seeds, counts) are kept. Returns `count` such calls, one per seed
    /// `1..=count`.
    pub fn jitters(&self, count: u64) -> Vec<Call> {
        let directions: Vec<DVec3> = self.directions().iter().map(|v| v.as_dvec3()).collect();
        let turns: Vec<Option<Turn>> = directions
            .iter()
            .enumerate()
            .map(|(i, v)| Turn::of(*v, &directions, i))
            .collect();
        (1..=count)
            .map(|seed| {
                let mut call = self.clone();
                call.jitter(seed);
                // The turned directions replace the ones moved component by component; the
                // salt of a turn is its place among the turned ones.
                let turned = turns.iter().filter_map(|t| t.as_ref()).enumerate();
                let turned: Vec<Vec3> = turned.map(|(i, t)| t.sample(seed, i).as_vec3()).collect();
                let mut turned = turned.into_iter();
                for (d, turn) in call.directions_mut().into_iter().zip(&turns) {
                    if turn.is_some() {
                        *d = turned.next().unwrap_or(*d);
                    }
                }
                call
            })
            .collect()
    }

    /// The direction inputs, in the order `w, wo, wi, h, n, tangent`.
    fn directions(&self) -> Vec<Vec3> {
        let mut call = self.clone();
        call.directions_mut().into_iter().map(|d| *d).collect()
    }

    /// The direction inputs, in the order `w, wo, wi, h, n, tangent`: the ones
    /// [`Call::jitters`] turns.
    fn directions_mut(&mut self) -> Vec<&mut Vec3> {
        match self {
            Call::Reflect { wo, n } => vec![wo, n],
            Call::Refract { wi, n, .. } => vec![wi, n],
            Call::CosinePdf { w } | Call::SmithG1 { w, .. } => vec![w],
            Call::CookTorrance { wo, wi, .. }
            | Call::Phong { wo, wi, .. }
            | Call::NdfPdf { wo, wi, .. } => vec![wo, wi],
            Call::KajiyaKay {
                wo, wi, tangent, ..
            } => vec![wo, wi, tangent],
            Call::AnisoNdf { h, .. } | Call::BeckmannNdf { h, .. } => vec![h],
            Call::CriticalAngle { .. }
            | Call::RefractStack { .. }
            | Call::SchlickR0 { .. }
            | Call::FresnelSchlick { .. }
            | Call::ReciprocityGap { .. }
            | Call::BrdfCheck { .. }
            | Call::SampleJacobian { .. } => Vec::new(),
        }
    }
}

/// A value whose real numbers [`Call::jitters`] moves, each by [`jitter_real`]; integers
/// (seeds, counts, exponents of a test BRDF) are kept.
trait Jitter {
    /// Moves every real number in `self` for `seed`.
    fn jitter(&mut self, seed: u64);
}

/// `x` moved by up to [`JITTER_ULPS`] f32 ulps, by a factor that depends only on `seed` and
/// `x`; a subnormal f32 by up to as many of the smallest subnormal, away from 0. A move
/// that leaves the finite numbers keeps `x`.
fn jitter_real(x: f64, seed: u64) -> f64 {
    let u = hash_unit(seed, x.to_bits());
    // A subnormal f32 has fewer digits than ulps can move: move it by up to `JITTER_ULPS`
    // of the smallest subnormal instead, keeping its sign.
    let moved = if x != 0.0 && x.abs() < f32::MIN_POSITIVE as f64 {
        x.signum() * (x.abs() + JITTER_ULPS * SMALLEST_SUBNORMAL * u)
    } else {
        x * (1.0 + (2.0 * u - 1.0) * JITTER_ULPS * f32::EPSILON as f64)
    };
    if moved.is_finite() { moved } else { x }
}

impl Jitter for f64 {
    fn jitter(&mut self, seed: u64) {
        *self = jitter_real(*self, seed);
    }
}

impl Jitter for f32 {
    fn jitter(&mut self, seed: u64) {
        *self = jitter_real(*self as f64, seed) as f32;
    }
}

impl Jitter for Vec3 {
    fn jitter(&mut self, seed: u64) {
        for x in self.as_mut() {
            x.jitter(seed);
        }
    }
}

impl Jitter for Vec2 {
    fn jitter(&mut self, seed: u64) {
        for x in self.as_mut() {
            x.jitter(seed);
        }
    }
}

impl Jitter for PhongParams {
    fn jitter(&mut self, seed: u64) {
        self.kd.jitter(seed);
        self.ks.jitter(seed);
        self.exponent.jitter(seed);
    }
}

impl Jitter for KajiyaKayParams {
    fn jitter(&mut self, seed: u64) {
        self.kd.jitter(seed);
        self.ks.jitter(seed);
        self.exponent.jitter(seed);
    }
}

impl Jitter for TestBrdf {
    fn jitter(&mut self, seed: u64) {
        match self {
            TestBrdf::Lambert { albedo: x }
            | TestBrdf::CosinePower { k: x, .. }
            | TestBrdf::ScaledIncidentOnly { scale: x } => x.jitter(seed),
            TestBrdf::IncidentOnly
            | TestBrdf::NanNearGrazing
            | TestBrdf::NanOneWayRound
            | TestBrdf::Lopsided
            | TestBrdf::NegativeLopsided
            | TestBrdf::InfiniteNearGrazing => {}
        }
    }
}

impl Jitter for StackInput {
    fn jitter(&mut self, seed: u64) {
        self.eta_incident.jitter(seed);
        for (eta, thickness) in &mut self.slabs {
            eta.jitter(seed);
            thickness.jitter(seed);
        }
        self.eta_exit.jitter(seed);
        self.intensity.jitter(seed);
    }
}

impl Jitter for SampleCall {
    fn jitter(&mut self, seed: u64) {
        match self {
            SampleCall::CosineSample => {}
            SampleCall::NdfSample {
                wo,
                alpha_x,
                alpha_y,
            } => {
                wo.jitter(seed);
                alpha_x.jitter(seed);
                alpha_y.jitter(seed);
            }
        }
    }
}

impl Jitter for Call {
    fn jitter(&mut self, seed: u64) {
        match self {
            Call::Reflect { wo, n } => {
                wo.jitter(seed);
                n.jitter(seed);
            }
            Call::Refract {
                wi,
                n,
                eta_i,
                eta_t,
            } => {
                wi.jitter(seed);
                n.jitter(seed);
                eta_i.jitter(seed);
                eta_t.jitter(seed);
            }
            Call::CriticalAngle { eta_i, eta_t } => {
                eta_i.jitter(seed);
                eta_t.jitter(seed);
            }
            Call::RefractStack { theta_deg, stack } => {
                theta_deg.jitter(seed);
                stack.jitter(seed);
            }
            Call::SchlickR0 { eta_i, eta_t } => {
                eta_i.jitter(seed);
                eta_t.jitter(seed);
            }
            Call::FresnelSchlick {
                cos_theta_i,
                eta_i,
                eta_t,
            } => {
                cos_theta_i.jitter(seed);
                eta_i.jitter(seed);
                eta_t.jitter(seed);
            }
            Call::CosinePdf { w } => w.jitter(seed),
            Call::SmithG1 { w, alpha } => {
                w.jitter(seed);
                alpha.jitter(seed);
            }
            Call::CookTorrance {
                wo,
                wi,
                alpha_x,
                alpha_y,
                f0,
            } => {
                wo.jitter(seed);
                wi.jitter(seed);
                alpha_x.jitter(seed);
                alpha_y.jitter(seed);
                f0.jitter(seed);
            }
            Call::AnisoNdf {
                h,
                alpha_x,
                alpha_y,
            } => {
                h.jitter(seed);
                alpha_x.jitter(seed);
                alpha_y.jitter(seed);
            }
            Call::Phong { wo, wi, params } => {
                wo.jitter(seed);
                wi.jitter(seed);
                params.jitter(seed);
            }
            Call::ReciprocityGap { brdf, .. } | Call::BrdfCheck { brdf, .. } => brdf.jitter(seed),
            Call::KajiyaKay {
                wo,
                wi,
                tangent,
                params,
            } => {
                wo.jitter(seed);
                wi.jitter(seed);
                tangent.jitter(seed);
                params.jitter(seed);
            }
            Call::BeckmannNdf { h, alpha } => {
                h.jitter(seed);
                alpha.jitter(seed);
            }
            Call::NdfPdf {
                wo,
                wi,
                alpha_x,
                alpha_y,
            } => {
                wo.jitter(seed);
                wi.jitter(seed);
                alpha_x.jitter(seed);
                alpha_y.jitter(seed);
            }
            Call::SampleJacobian { sampler, points, h } => {
                sampler.jitter(seed);
                points.iter_mut().for_each(|p| p.jitter(seed));
                h.jitter(seed);
            }
        }
    }
}

/// How [`Call::jitters`] turns one direction input.
struct Turn {
    /// Its length, kept.
    len: f64,
    /// Its unit direction.
    d: DVec3,
    /// The axis of the worst loss (a pole, or the normal of a horizon it lies near).
    axis: DVec3,
    /// Whether that axis is a pole (toward it, a turn may land on it).
    is_pole: bool,
    /// The angle to turn by.
    angle: f64,
}

impl Turn {
    /// The turn of the direction `v`, the `i`-th of `directions`; `None` for a zero vector.
    fn of(v: DVec3, directions: &[DVec3], i: usize) -> Option<Turn> {
        let len = v.length();
        if len == 0.0 {
            return None;
        }
        let d = v / len;
        let others: Vec<DVec3> = directions
            .iter()
            .enumerate()
            .filter(|(j, u)| *j != i && u.length() > 0.0)
            .map(|(_, u)| u.normalize())
            .collect();
        // Near a pole (of the local normal or another direction), `sqrt(1 − cos²)` and
        // `acos` lose `ε / sin θ`; near the horizon of another direction, `asin` (Snell's
        // law by angles) loses `ε / cos θ`. Neither more than `sqrt(2ε)`.
        let pole = others
            .iter()
            .copied()
            .chain([DVec3::Z])
            .map(|u| if d.dot(u) < 0.0 { -u } else { u })
            .max_by(|a, b| d.dot(*a).total_cmp(&d.dot(*b)))
            .unwrap_or(DVec3::Z);
        let to_pole = d.dot(pole).clamp(-1.0, 1.0).acos();
        let horizon = others
            .iter()
            .copied()
            .min_by(|a, b| d.dot(*a).abs().total_cmp(&d.dot(*b).abs()));
        let ulps = JITTER_ULPS * f32::EPSILON as f64;
        let pole_turn = (ulps / to_pole.sin().max(1e-300)).min(MAX_TURN);
        let horizon_turn =
            horizon.map_or(0.0, |u| (ulps / d.dot(u).abs().max(1e-300)).min(MAX_TURN));
        let (axis, is_pole) = match horizon {
            Some(u) if horizon_turn > pole_turn && d.dot(u) >= 0.0 => (u, false),
            Some(u) if horizon_turn > pole_turn => (-u, false),
            _ => (pole, true),
        };
        Some(Turn {
            len,
            d,
            axis,
            is_pole,
            angle: pole_turn.max(horizon_turn),
        })
    }

    /// The turned vector for `seed`: toward the axis (landing on a pole that close), away
    /// from it, or sideways at an azimuth from `seed` and `salt`; its length stretched by
    /// up to [`JITTER_ULPS`] ulps.
    fn sample(&self, seed: u64, salt: usize) -> DVec3 {
        let (d, axis, turn) = (self.d, self.axis, self.angle);
        let at = d.dot(axis).clamp(-1.0, 1.0).acos();
        // On the axis itself (`wi` exactly along the fibre), away is every way: pick one
        // per direction, so that directions on one line move apart. (What is left of `d`
        // off the axis there is rounding, the same for every direction on that line.)
        let off = if d.cross(axis).length() < 1e-12 {
            sideways(d, seed, salt)
        } else {
            (d - axis * d.dot(axis)).normalize()
        };
        let turned = match seed % 3 {
            1 if self.is_pole && at <= turn => axis,
            1 => axis * (at - turn).cos() + off * (at - turn).sin(),
            2 => axis * (at + turn).cos() + off * (at + turn).sin(),
            _ => d * turn.cos() + sideways(d, seed, salt) * turn.sin(),
        };
        // And stretched within rounding: an f32 direction is unit only to a few ulps, and
        // code that normalises it and code that does not differ by that much (`sin θ`
        // from a dot product near ±1 by much more).
        let stretch = 1.0
            + (2.0 * hash_unit(seed, salt as u64 + 7) - 1.0) * JITTER_ULPS * f32::EPSILON as f64;
        turned * self.len * stretch
    }
}

/// A unit vector perpendicular to `d`, at an azimuth from `seed` and `salt`.
fn sideways(d: DVec3, seed: u64, salt: usize) -> DVec3 {
    let phi = std::f64::consts::TAU * hash_unit(seed, salt as u64 + 1);
    let (a, b) = d.any_orthonormal_pair();
    a * phi.cos() + b * phi.sin()
}
