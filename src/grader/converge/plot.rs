//! The error-against-time plot of a study, as PNG and SVG.

use super::study::Point;
use anyhow::{Context, Result, anyhow};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;
use std::sync::OnceLock;

/// Font files tried, in order, for the plot's text (after `$PBRLAB_FONT`). plotters is
/// built without a system font loader, so the text needs a TrueType file.
const FONT_CANDIDATES: &[&str] = &[
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/TTF/DejaVuSans.ttf",
    "/usr/share/fonts/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf",
    "/usr/share/fonts/liberation/LiberationSans-Regular.ttf",
    "/usr/share/fonts/truetype/noto/NotoSans-Regular.ttf",
    "/usr/share/fonts/noto/NotoSans-Regular.ttf",
    "/System/Library/Fonts/Supplemental/Arial.ttf",
    "/Library/Fonts/Arial.ttf",
    "C:\\Windows\\Fonts\\arial.ttf",
];

/// The font family name the plot asks plotters for.
const FAMILY: &str = "sans-serif";

/// Registers a TrueType font with plotters once per process: `$PBRLAB_FONT` if set, else
/// the first of a list of common font files that loads. Returns the file used.
pub fn ensure_font() -> Result<&'static str> {
    static FONT: OnceLock<Option<String>> = OnceLock::new();
    FONT.get_or_init(|| {
        let from_env = std::env::var("PBRLAB_FONT").ok();
        from_env
            .iter()
            .map(String::as_str)
            .chain(FONT_CANDIDATES.iter().copied())
            .find_map(|path| {
                let bytes = std::fs::read(path).ok()?;
                // plotters keeps fonts for the life of the process.
                let bytes: &'static [u8] = Box::leak(bytes.into_boxed_slice());
                plotters::style::register_font(FAMILY, FontStyle::Normal, bytes).ok()?;
                Some(path.to_owned())
            })
    })
    .as_deref()
    .ok_or_else(|| {
        anyhow!("no TrueType font found for the plot's text; set PBRLAB_FONT to a .ttf file")
    })
}

/// Line colours, one per strategy (cycled).
const PALETTE: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
];

/// Draws relMSE against wall time on log-log axes, one line per strategy, into a PNG
/// and an SVG (`stem.png`, `stem.svg`). Points with a non-positive time or error are
/// left out.
pub fn plot_error_vs_time(points: &[Point], title: &str, png: &Path, svg: &Path) -> Result<()> {
    ensure_font()?;
    let size = (900, 640);
    // plotters draws into a buffer, and the framework's `image` writes the PNG: plotters'
    // own encoder would compile a second, older `image`.
    let mut rgb = vec![0u8; size.0 as usize * size.1 as usize * 3];
    draw(
        BitMapBackend::with_buffer(&mut rgb, size).into_drawing_area(),
        points,
        title,
    )
    .map_err(|e| anyhow!("drawing {}: {e}", png.display()))?;
    image::save_buffer(png, &rgb, size.0, size.1, image::ExtendedColorType::Rgb8)
        .with_context(|| format!("writing {}", png.display()))?;
    draw(
        SVGBackend::new(svg, size).into_drawing_area(),
        points,
        title,
    )
    .map_err(|e| anyhow!("drawing {}: {e}", svg.display()))?;
    Ok(())
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    points: &[Point],
    title: &str,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let usable: Vec<&Point> = points
        .iter()
        .filter(|p| p.wall_s > 0.0 && p.rel_mse > 0.0)
        .collect();
    let range = |f: fn(&Point) -> f64| {
        let (lo, hi) = usable
            .iter()
            .map(|p| f(p))
            .fold((f64::MAX, f64::MIN), |(lo, hi), v| (lo.min(v), hi.max(v)));
        if lo > hi {
            (0.1, 10.0)
        } else {
            (lo / 1.5, hi * 1.5)
        }
    };
    let (t0, t1) = range(|p| p.wall_s);
    // The error bars fit too (a lower end at or below 0 is cut at the axis).
    let (e0, e1) = range(|p| p.rel_mse);
    let e0 = usable
        .iter()
        .map(|p| p.rel_mse_interval.0)
        .filter(|lo| *lo > 0.0)
        .fold(e0, |a, lo| a.min(lo / 1.2));
    let e1 = usable
        .iter()
        .map(|p| p.rel_mse_interval.1)
        .fold(e1, |a, hi| a.max(hi * 1.2));

    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, (FAMILY, 22))
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(72)
        .build_cartesian_2d((t0..t1).log_scale(), (e0..e1).log_scale())?;
    chart
        .configure_mesh()
        .x_desc("wall time [s]")
        .y_desc("relMSE")
        .label_style((FAMILY, 14))
        // A few labels: a log axis over decades labelled at every tick overlaps.
        .x_labels(6)
        .y_labels(8)
        .x_label_formatter(&|x| format!("{x:.0e}"))
        .y_label_formatter(&|y| format!("{y:.0e}"))
        .draw()?;

    let names = super::study::strategy_names(usable.iter().copied());
    for (k, name) in names.iter().enumerate() {
        let color = PALETTE[k % PALETTE.len()];
        // In sample-count order: at low spp the time is noisy and need not increase.
        let mut mine: Vec<&&Point> = usable.iter().filter(|p| p.strategy == *name).collect();
        mine.sort_by_key(|p| p.spp);
        let line: Vec<(f64, f64)> = mine.iter().map(|p| (p.wall_s, p.rel_mse)).collect();
        chart
            .draw_series(LineSeries::new(line.clone(), color.stroke_width(2)))?
            .label(*name)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(2))
            });
        chart.draw_series(
            line.into_iter()
                .map(|xy| Circle::new(xy, 3, color.filled())),
        )?;
        // The 95 % interval of each mean relMSE, over the runs.
        chart.draw_series(
            mine.iter()
                .filter(|p| p.rel_mse_interval.1 > p.rel_mse_interval.0)
                .map(|p| {
                    let (lo, hi) = p.rel_mse_interval;
                    PathElement::new(vec![(p.wall_s, lo.max(e0)), (p.wall_s, hi)], color)
                }),
        )?;
    }
    chart
        .configure_series_labels()
        .label_font((FAMILY, 14))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperRight)
        .draw()?;
    root.present()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_a_png_and_an_svg_with_one_line_per_strategy() {
        if ensure_font().is_err() {
            eprintln!("no font on this machine: plot test skipped");
            return;
        }
        let dir = tempfile::tempdir().unwrap();
        let (png, svg) = (dir.path().join("c.png"), dir.path().join("c.svg"));
        let points: Vec<Point> = ["uniform", "cosine"]
            .iter()
            .enumerate()
            .flat_map(|(k, name)| {
                (0..6).map(move |level| {
                    let spp = 1u32 << level;
                    let rel_mse = (k + 1) as f64 / spp as f64;
                    Point {
                        strategy: (*name).into(),
                        spp,
                        runs: 16,
                        wall_s: 1e-3 * spp as f64,
                        cpu_s: None,
                        rel_mse,
                        rel_mse_interval: (0.8 * rel_mse, 1.2 * rel_mse),
                        rel_var: rel_mse,
                        rel_bias2: 0.0,
                        rel_bias2_se: 0.0,
                        rmse: 0.0,
                        efficiency: 0.0,
                        non_finite: 0,
                    }
                })
            })
            .collect();
        plot_error_vs_time(&points, "test", &png, &svg).unwrap();
        let svg_text = std::fs::read_to_string(&svg).unwrap();
        assert!(svg_text.contains("cosine") && svg_text.contains("uniform"));
        // Each strategy's colour draws its line and its legend swatch at width 2, and an
        // error bar per point at width 1.
        for color in &PALETTE[..2] {
            let stroke = format!(
                "stroke=\"#{:02X}{:02X}{:02X}\" stroke-width=\"2\"",
                color.0, color.1, color.2
            );
            assert_eq!(svg_text.matches(&stroke).count(), 2, "{stroke}");
        }
        assert!(!svg_text.contains(&format!(
            "#{:02X}{:02X}{:02X}",
            PALETTE[2].0, PALETTE[2].1, PALETTE[2].2
        )));
        let img = image::open(&png).unwrap();
        assert_eq!((img.width(), img.height()), (900, 640));
    }
}
