//! Error metrics of an estimate against the reference: relMSE, with its interval, and bias.

use serde::Serialize;

/// The ε in relMSE's denominator (Rousselle et al. 2011): keeps near-black pixels from
/// dominating the mean.
pub const REL_MSE_EPSILON: f64 = 1e-2;

/// How far an estimate is from the reference, over all pixel channels.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ImageError {
    /// Mean of `(x − r)² / (r² + ε)` over the finite channels.
    pub rel_mse: f64,
    /// Root of the mean of `(x − r)²` over the finite channels.
    pub rmse: f64,
    /// Channels of the estimate that were NaN or infinite (left out of both means; any
    /// at all is a bug in the estimator).
    pub non_finite: usize,
}

/// Compares an estimate with a reference of the same length, channel by channel.
pub fn image_error(estimate: &[f32], reference: &[f32]) -> anyhow::Result<ImageError> {
    anyhow::ensure!(
        estimate.len() == reference.len(),
        "the estimate has {} values but the reference has {}",
        estimate.len(),
        reference.len()
    );
    anyhow::ensure!(!reference.is_empty(), "the reference is empty");
    let (mut rel, mut sq, mut finite) = (0.0, 0.0, 0usize);
    for (&x, &r) in estimate.iter().zip(reference) {
        if !x.is_finite() {
            continue;
        }
        let (x, r) = (x as f64, r as f64);
        let d2 = (x - r) * (x - r);
        rel += d2 / (r * r + REL_MSE_EPSILON);
        sq += d2;
        finite += 1;
    }
    let n = finite.max(1) as f64;
    Ok(ImageError {
        rel_mse: rel / n,
        rmse: (sq / n).sqrt(),
        non_finite: estimate.len() - finite,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_of_a_known_difference() {
        let e = image_error(&[1.1, 2.0, 0.0], &[1.0, 2.0, 0.0]).unwrap();
        let rel = (0.1f64 * 0.1 / (1.0 + REL_MSE_EPSILON)) / 3.0;
        assert!((e.rel_mse / rel - 1.0).abs() < 1e-6, "{}", e.rel_mse);
        assert!((e.rmse - (0.01f64 / 3.0).sqrt()).abs() < 1e-7);
        assert_eq!(e.non_finite, 0);
    }

    #[test]
    fn non_finite_channels_are_counted_not_averaged() {
        let e = image_error(&[f32::NAN, 1.0], &[1.0, 1.0]).unwrap();
        assert_eq!(e.non_finite, 1);
        assert_eq!(e.rel_mse, 0.0);
        assert!(image_error(&[1.0], &[1.0, 2.0]).is_err());
    }
}
