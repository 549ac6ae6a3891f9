//! Validated scene values. Each type checks its value while it is read, so a bad number is
//! reported at its own line and column of the YAML file (serde-saphyr attaches the
//! position of the value being read to the error).

use glam::Vec3;
use serde::Deserialize;
use serde::de::{self, Deserializer, SeqAccess, Visitor};
use std::fmt;

/// Accepts a YAML number only: a quoted `"0.5"` is text, and reading it as a number anyway
/// would hide a mistake in the file.
struct NumberVisitor;

impl Visitor<'_> for NumberVisitor {
    type Value = f64;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a number")
    }

    fn visit_f64<E: de::Error>(self, v: f64) -> Result<f64, E> {
        Ok(v)
    }

    fn visit_i64<E: de::Error>(self, v: i64) -> Result<f64, E> {
        Ok(v as f64)
    }

    fn visit_u64<E: de::Error>(self, v: u64) -> Result<f64, E> {
        Ok(v as f64)
    }

    fn visit_str<E: de::Error>(self, v: &str) -> Result<f64, E> {
        Err(E::custom(format!(
            "expected a number, found the text `{v}` (numbers are written without quotes)"
        )))
    }
}

/// Reads a number as f32, rejecting text, NaN, infinities and values beyond the f32 range.
fn finite<'de, D: Deserializer<'de>>(d: D) -> Result<f32, D::Error> {
    let v = d.deserialize_any(NumberVisitor)?;
    let v32 = v as f32;
    if !v.is_finite() || !v32.is_finite() {
        return Err(de::Error::custom(format!(
            "expected a finite number, found {v}"
        )));
    }
    Ok(v32)
}

fn check<E: de::Error>(ok: bool, what: &str, v: f32) -> Result<f32, E> {
    if ok {
        Ok(v)
    } else {
        Err(E::custom(format!("{what}, found {v}")))
    }
}

macro_rules! scalar {
    ($(#[$doc:meta])* $name:ident, |$v:ident| $ok:expr, $what:literal) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq)]
        pub struct $name(pub f32);

        impl<'de> Deserialize<'de> for $name {
            fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                let $v = finite(d)?;
                check($ok, $what, $v).map($name)
            }
        }
    };
}

scalar!(
    /// Any finite number.
    Real, |v| true, "expected a finite number"
);
scalar!(
    /// A finite number > 0 (radii, lengths, IORs' relatives).
    Positive, |v| v > 0.0, "expected a number > 0"
);
scalar!(
    /// A finite number ≥ 0 (coefficients, exponents).
    NonNegative, |v| v >= 0.0, "expected a number ≥ 0"
);
scalar!(
    /// An index of refraction: finite and > 0.
    Ior, |v| v > 0.0, "an index of refraction must be > 0"
);
scalar!(
    /// A GGX roughness α: finite, > 0 and at most 2 (a perfectly smooth conductor is a
    /// `mirror`).
    Roughness, |v| v > 0.0 && v <= 2.0, "a roughness must be in (0, 2] (use `mirror` for a perfectly smooth metal)"
);
scalar!(
    /// A full vertical field of view in degrees, in (0, 180).
    FovDegrees, |v| v > 0.0 && v < 180.0, "the field of view must be in (0, 180) degrees"
);
scalar!(
    /// A Henyey-Greenstein asymmetry g in (−1, 1).
    Asymmetry, |v| v > -1.0 && v < 1.0, "the asymmetry g must be in (-1, 1)"
);

struct Vec3Visitor;

impl<'de> Visitor<'de> for Vec3Visitor {
    type Value = Vec3;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a list of three finite numbers [x, y, z]")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Vec3, A::Error> {
        let mut v = [0.0f32; 3];
        for (i, slot) in v.iter_mut().enumerate() {
            let x: Real = seq
                .next_element()?
                .ok_or_else(|| de::Error::invalid_length(i, &self))?;
            *slot = x.0;
        }
        if seq.next_element::<de::IgnoredAny>()?.is_some() {
            return Err(de::Error::invalid_length(4, &self));
        }
        Ok(Vec3::from(v))
    }
}

/// A point or vector with three finite coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Point(pub Vec3);

impl<'de> Deserialize<'de> for Point {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_seq(Vec3Visitor).map(Point)
    }
}

/// A non-zero vector with three finite coordinates (not normalised).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Direction(pub Vec3);

impl<'de> Deserialize<'de> for Direction {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let v = d.deserialize_seq(Vec3Visitor)?;
        if v.length_squared() > 0.0 {
            Ok(Direction(v))
        } else {
            Err(de::Error::custom(
                "expected a non-zero vector, found [0, 0, 0]",
            ))
        }
    }
}

/// An RGB triple of finite values ≥ 0, written `[r, g, b]` or as one number for grey.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rgb(pub Vec3);

struct RgbVisitor;

impl RgbVisitor {
    fn grey<E: de::Error>(v: f64) -> Result<Rgb, E> {
        let v32 = v as f32;
        if !v.is_finite() || !v32.is_finite() {
            return Err(E::custom(format!(
                "expected a finite colour value, found {v}"
            )));
        }
        check(v32 >= 0.0, "a colour value must be ≥ 0", v32).map(|g| Rgb(Vec3::splat(g)))
    }
}

impl<'de> Visitor<'de> for RgbVisitor {
    type Value = Rgb;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a colour: [r, g, b] or one number for grey")
    }

    fn visit_f64<E: de::Error>(self, v: f64) -> Result<Rgb, E> {
        Self::grey(v)
    }

    fn visit_i64<E: de::Error>(self, v: i64) -> Result<Rgb, E> {
        Self::grey(v as f64)
    }

    fn visit_u64<E: de::Error>(self, v: u64) -> Result<Rgb, E> {
        Self::grey(v as f64)
    }

    fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<Rgb, A::Error> {
        let v = Vec3Visitor.visit_seq(seq)?;
        if v.cmpge(Vec3::ZERO).all() {
            Ok(Rgb(v))
        } else {
            Err(de::Error::custom(format!(
                "colour values must be ≥ 0, found [{}, {}, {}]",
                v.x, v.y, v.z
            )))
        }
    }
}

impl<'de> Deserialize<'de> for Rgb {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(RgbVisitor)
    }
}
