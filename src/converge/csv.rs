use super::study::Point;
use anyhow::Result;
use std::io::Write;
use std::path::Path;

/// The CSV header, in column order.
pub const HEADER: &str = "strategy,spp,wall_s,cpu_s,rel_mse,rmse,efficiency,non_finite";

/// Writes one row per point to `path` (atomically, see [`crate::atomic_file`]). An unknown
/// CPU time is an empty cell.
pub fn write_csv(path: &Path, points: &[Point]) -> Result<()> {
    crate::atomic_file::write_with(path, |w| {
        writeln!(w, "{HEADER}")?;
        for p in points {
            writeln!(
                w,
                "{},{},{:e},{},{:e},{:e},{:e},{}",
                quoted(&p.strategy),
                p.spp,
                p.wall_s,
                p.cpu_s.map_or(String::new(), |c| format!("{c:e}")),
                p.rel_mse,
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
            wall_s: 0.25,
            cpu_s,
            rel_mse: 1e-3,
            rmse: 0.5,
            efficiency: 4000.0,
            non_finite: 0,
        };
        write_csv(&path, &[point("cosine", Some(0.5)), point("a,b", None)]).unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], HEADER);
        assert_eq!(lines[1], "cosine,8,2.5e-1,5e-1,1e-3,5e-1,4e3,0");
        assert_eq!(lines[2], "\"a,b\",8,2.5e-1,,1e-3,5e-1,4e3,0");
    }
}
