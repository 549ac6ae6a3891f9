//! NaN-propagating reductions for cases that summarise many calls in one record.
//! `f64::min` and `f64::max` drop a NaN operand, which would hide the very failure a
//! stability case is looking for.

/// The smaller of `a` and `b`, or NaN when either is NaN.
pub fn min_nan(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.min(b)
    }
}

/// The larger of `a` and `b`, or NaN when either is NaN.
pub fn max_nan(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.max(b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nan_survives_the_reduction() {
        assert!(min_nan(1.0, f64::NAN).is_nan());
        assert!(max_nan(f64::NAN, 1.0).is_nan());
        assert_eq!(min_nan(1.0, -2.0), -2.0);
        assert_eq!(max_nan(1.0, -2.0), 1.0);
    }
}
