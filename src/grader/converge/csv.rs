//! The study's points as CSV: one row per strategy and sample count.

use super::study::Point;
use anyhow::Result;
use std::io::Write;
use std::path::Path;

/// The CSV header, in column order.
pub const HEADER: &str = "strategy,spp,runs,wall_s,cpu_s,rel_mse,rel_mse_lo,rel_mse_hi,\
rel_var,rel_bias2,rel_bias2_se,bias,rmse,efficiency,non_finite";

/// Writes one row per point to `path` (atomically, see [`crate::atomic_file`]): the
/// point's fields, the 95 % interval of its relMSE as two columns, and `bias`, the relative
/// RMS bias `√max(0, rel_bias2 − reference_floor)`. An unknown CPU time is an empty cell;
/// what one run cannot tell (variance, bias) is NaN.
pub fn write_csv(path: &Path, points: &[Point], reference_floor: f64) -> Result<()> {
    crate::atomic_file::write_with(path, |w| {
        writeln!(w, "{HEADER}")?;
        for p in points {
            let bias = if p.rel_bias2.is_nan() {
                f64::NAN
            } else {
                (p.rel_bias2 - reference_floor).max(0.0).sqrt()
            };
            writeln!(
                w,
                "{},{},{},{:e},{},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{}",
                quoted(&p.strategy),
                p.spp,
                p.runs,
                p.wall_s,
                p.cpu_s.map_or(String::new(), |c| format!("{c:e}")),
                p.rel_mse,
                p.rel_mse_interval.0,
                p.rel_mse_interval.1,
                p.rel_var,
                p.rel_bias2,
                p.rel_bias2_se,
                bias,
                p.rmse,
                p.efficiency,
                p.non_finite
            )?;
        }
        Ok(())
    })
}

/// A CSV field: quoted when it contains a comma, quote or line break.
fn quoted(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_owned()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_round_trip_through_the_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("converge.csv");
        let point = |strategy: &str, cpu_s| Point {
            strategy: strategy.into(),
            spp: 8,
            runs: 16,
            wall_s: 0.25,
            cpu_s,
            rel_mse: 1e-3,
            rel_mse_interval: (8e-4, 1.2e-3),
            rel_var: 5e-4,
            rel_bias2: 5e-4,
            rel_bias2_se: 1e-5,
            rmse: 0.5,
            efficiency: 4000.0,
            non_finite: 0,
        };
        write_csv(
            &path,
            &[point("cosine", Some(0.5)), point("a,b", None)],
            1e-4,
        )
        .unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], HEADER);
        assert_eq!(
            lines[1],
            "cosine,8,16,2.5e-1,5e-1,1e-3,8e-4,1.2e-3,5e-4,5e-4,1e-5,2e-2,5e-1,4e3,0"
        );
        assert!(
            lines[2].starts_with("\"a,b\",8,16,2.5e-1,,1e-3,"),
            "{}",
            lines[2]
        );
        assert_eq!(HEADER.split(',').count(), lines[1].split(',').count());
    }
}
