//! The statistics behind the checks: Šidák correction, Pearson's χ² with pooling, Student's
//! t-test. Distributions come from statrs.

use statrs::distribution::{ChiSquared, ContinuousCDF, StudentsT};

/// The per-test significance that gives a family of `tests` independent tests the overall
/// false-failure rate `alpha` (Šidák 1967): `1 − (1 − α)^(1/m)`.
pub fn sidak(alpha: f64, tests: usize) -> f64 {
    if tests <= 1 {
        return alpha;
    }
    -f64::exp_m1(f64::ln_1p(-alpha) / tests as f64)
}

/// Cells with a smaller expected count are pooled before the χ² test.
pub const MIN_EXPECTED: f64 = 5.0;

/// The outcome of a Pearson χ² goodness-of-fit test.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChiSquare {
    /// The statistic Σ (O − E)² / E over the (pooled) cells.
    pub statistic: f64,
    /// Degrees of freedom: cells after pooling − 1.
    pub dof: usize,
    /// P(χ²_dof ≥ statistic).
    pub p_value: f64,
}

/// Pearson's χ² test of `observed` counts against `expected` counts (same total), pooling
/// every cell whose expected count is below [`MIN_EXPECTED`] into one cell; if the pool is
/// still too small it absorbs the next smallest cells. `None` when fewer than two cells
/// remain (nothing to test).
pub fn chi_square(observed: &[u64], expected: &[f64]) -> Option<ChiSquare> {
    let mut cells: Vec<(f64, f64)> = expected
        .iter()
        .zip(observed)
        .map(|(&e, &o)| (e, o as f64))
        .collect();
    cells.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (mut pool_e, mut pool_o, mut first) = (0.0, 0.0, 0);
    while first < cells.len()
        && (cells[first].0 < MIN_EXPECTED || pool_e > 0.0 && pool_e < MIN_EXPECTED)
    {
        pool_e += cells[first].0;
        pool_o += cells[first].1;
        first += 1;
    }
    let mut kept = cells.split_off(first);
    if pool_e > 0.0 {
        kept.push((pool_e, pool_o));
    } else if pool_o > 0.0 {
        // Samples where the reference says nothing can land: no finite statistic.
        return Some(ChiSquare {
            statistic: f64::INFINITY,
            dof: kept.len().max(1),
            p_value: 0.0,
        });
    }
    if kept.len() < 2 {
        return None;
    }
    let statistic: f64 = kept.iter().map(|(e, o)| (o - e) * (o - e) / e).sum();
    let dof = kept.len() - 1;
    let p_value = ChiSquared::new(dof as f64).map_or(0.0, |d| d.sf(statistic));
    Some(ChiSquare {
        statistic,
        dof,
        p_value,
    })
}

/// Mean, sample variance and count of a stream of values (Welford's update).
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Moments {
    /// Number of values.
    pub n: u64,
    /// Their mean.
    pub mean: f64,
    m2: f64,
}

impl Moments {
    /// Adds one value.
    pub fn push(&mut self, x: f64) {
        self.n += 1;
        let d = x - self.mean;
        self.mean += d / self.n as f64;
        self.m2 += d * (x - self.mean);
    }

    /// The moments of the same values, each times `factor`.
    pub fn scaled(&self, factor: f64) -> Moments {
        Moments {
            n: self.n,
            mean: self.mean * factor,
            m2: self.m2 * factor * factor,
        }
    }

    /// The unbiased sample variance (0 with fewer than two values).
    pub fn variance(&self) -> f64 {
        if self.n < 2 {
            0.0
        } else {
            self.m2 / (self.n - 1) as f64
        }
    }

    /// The standard error of the mean.
    pub fn std_error(&self) -> f64 {
        (self.variance() / self.n.max(1) as f64).sqrt()
    }
}

/// Two-sided p-value of Student's one-sample t-test of `moments` against the mean `mu`.
/// A sample without variance gives 1 when its mean equals `mu` to the rounding of the f32
/// values it was computed from (a few ulps, 1e-6 relative) and 0 otherwise.
pub fn t_test(moments: &Moments, mu: f64) -> f64 {
    let se = moments.std_error();
    if se == 0.0 || !se.is_finite() {
        let scale = mu.abs().max(1e-12);
        return if (moments.mean - mu).abs() <= 1e-6 * scale {
            1.0
        } else {
            0.0
        };
    }
    let t = (moments.mean - mu) / se;
    let dof = (moments.n - 1) as f64;
    StudentsT::new(0.0, 1.0, dof).map_or(0.0, |d| 2.0 * d.sf(t.abs()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sidak_inverts_the_family_rate() {
        let a = sidak(0.01, 5);
        assert!((1.0 - (1.0 - a).powi(5) - 0.01).abs() < 1e-12);
        assert_eq!(sidak(0.01, 1), 0.01);
    }

    #[test]
    fn chi_square_pools_small_cells_and_detects_misfit() {
        let expected = [1000.0, 1000.0, 1.0, 2.0, 3.0];
        let fit = chi_square(&[1010, 990, 1, 3, 2], &expected).unwrap();
        assert_eq!(fit.dof, 2);
        assert!(fit.p_value > 0.5, "{fit:?}");
        let misfit = chi_square(&[1300, 700, 2, 2, 2], &expected).unwrap();
        assert!(misfit.p_value < 1e-10);
        let impossible = chi_square(&[5, 5], &[10.0, 0.0]).unwrap();
        assert_eq!(impossible.p_value, 0.0);
    }

    #[test]
    fn t_test_of_a_known_mean() {
        let mut m = Moments::default();
        for i in 0..1000 {
            m.push(if i % 2 == 0 { 1.0 } else { 3.0 });
        }
        assert!((m.mean - 2.0).abs() < 1e-12);
        assert!((m.variance() - 1.001).abs() < 1e-3);
        assert!(t_test(&m, 2.0) > 0.99);
        assert!(t_test(&m, 2.2) < 1e-6);
        let mut constant = Moments::default();
        constant.push(0.5);
        constant.push(0.5);
        assert_eq!(t_test(&constant, 0.5), 1.0);
        assert_eq!(t_test(&constant, 0.6), 0.0);
    }
}
