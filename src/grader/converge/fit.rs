//! Least-squares lines through log-log points: the convergence rate of a strategy.

use serde::Serialize;

/// A least-squares line `y = slope · x + intercept`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Fit {
    /// The slope.
    pub slope: f64,
    /// The intercept.
    pub intercept: f64,
    /// Coefficient of determination (1 for points exactly on a line).
    pub r2: f64,
    /// Number of points fitted.
    pub points: usize,
}

/// Ordinary least squares of `ys` on `xs`; `None` with fewer than two points or when every
/// `x` is the same.
pub fn least_squares(xs: &[f64], ys: &[f64]) -> Option<Fit> {
    let n = xs.len().min(ys.len());
    if n < 2 {
        return None;
    }
    let (xs, ys) = (&xs[..n], &ys[..n]);
    let mean = |v: &[f64]| v.iter().sum::<f64>() / n as f64;
    let (mx, my) = (mean(xs), mean(ys));
    let sxx: f64 = xs.iter().map(|x| (x - mx) * (x - mx)).sum();
    let sxy: f64 = xs.iter().zip(ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let syy: f64 = ys.iter().map(|y| (y - my) * (y - my)).sum();
    if sxx <= 0.0 {
        return None;
    }
    let slope = sxy / sxx;
    let r2 = if syy > 0.0 {
        sxy * sxy / (sxx * syy)
    } else {
        1.0
    };
    Some(Fit {
        slope,
        intercept: my - slope * mx,
        r2,
        points: n,
    })
}

/// Least squares of `ln y` on `ln x`, over the pairs where both are positive and finite:
/// the exponent of a power law `y ∝ x^slope`.
pub fn log_log(xs: &[f64], ys: &[f64]) -> Option<Fit> {
    let (lx, ly): (Vec<f64>, Vec<f64>) = xs
        .iter()
        .zip(ys)
        .filter(|(x, y)| x.is_finite() && y.is_finite() && **x > 0.0 && **y > 0.0)
        .map(|(x, y)| (x.ln(), y.ln()))
        .unzip();
    least_squares(&lx, &ly)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_exact_power_law_has_its_exponent_as_slope() {
        let xs: Vec<f64> = (0..8).map(|k| 2f64.powi(k)).collect();
        let ys: Vec<f64> = xs.iter().map(|x| 3.0 / x).collect();
        let fit = log_log(&xs, &ys).unwrap();
        assert!((fit.slope + 1.0).abs() < 1e-12);
        assert!((fit.intercept - 3f64.ln()).abs() < 1e-12);
        assert!((fit.r2 - 1.0).abs() < 1e-12);
    }

    #[test]
    fn degenerate_inputs_have_no_fit() {
        assert!(least_squares(&[1.0], &[2.0]).is_none());
        assert!(least_squares(&[1.0, 1.0], &[2.0, 3.0]).is_none());
        assert_eq!(
            log_log(&[1.0, 2.0, 0.0], &[1.0, 0.5, 7.0]).unwrap().points,
            2
        );
    }
}
