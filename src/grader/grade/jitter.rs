//! Inputs moved within rounding ([`Call::jitters`]): how far a correct f32 implementation's
//! answer may lie from the reference's, the spread a value case's tolerance adds.

use super::call::Call;
use super::rounding::{JITTER_ULPS, hash_unit};
use glam::{DVec3, Vec3};

/// The largest angle (radians) by which [`Call::jitters`] turns a direction: what an
/// angle computed from a cosine or sine within `JITTER_ULPS` ulps of 1 may be off,
/// `sqrt(2 · 4 ε)`.
const MAX_TURN: f64 = 9.8e-4;

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
                call.jitter_inputs(seed);
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

    /// The direction inputs, in the order of the signature.
    fn directions(&self) -> Vec<Vec3> {
        let mut call = self.clone();
        call.directions_mut().into_iter().map(|d| *d).collect()
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
