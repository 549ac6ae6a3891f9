//! Inline SVG pictures of a sampling check: observed and expected counts over the
//! hemisphere cells, and their difference in standard deviations.

use crate::grade::sampling::Histogram;
use std::fmt::Write;

const CELL: usize = 8;

/// A grey ramp for counts (black = 0, white = the largest count of either map).
fn grey(value: f64, max: f64) -> String {
    let g = if max > 0.0 {
        (255.0 * (value / max).clamp(0.0, 1.0)) as u8
    } else {
        0
    };
    format!("rgb({g},{g},{g})")
}

/// Blue (too few samples) – white – red (too many), saturating at 4 standard deviations.
fn diverging(z: f64) -> String {
    let t = (z.abs() / 4.0).min(1.0);
    let fade = (255.0 * (1.0 - t)) as u8;
    if z > 0.0 {
        format!("rgb(255,{fade},{fade})")
    } else {
        format!("rgb({fade},{fade},255)")
    }
}

/// Room left of the cells for the cos θ axis, and below them for the φ axis.
const LEFT: usize = 34;
const BOTTOM: usize = 26;

fn map(title: &str, h: &Histogram, colour: impl Fn(usize) -> String) -> String {
    let (cw, ch) = (h.bins.n_phi * CELL, h.bins.n_cos * CELL);
    let (w, ht) = (LEFT + cw, ch + BOTTOM);
    let mut s = format!(
        "<figure><svg width=\"{w}\" height=\"{ht}\" viewBox=\"0 0 {w} {ht}\" role=\"img\" \
         aria-label=\"{title}\" font-size=\"9\" font-family=\"sans-serif\">"
    );
    for band in 0..h.bins.n_cos {
        for sector in 0..h.bins.n_phi {
            // cos θ = 1 (the normal) at the top.
            let y = (h.bins.n_cos - 1 - band) * CELL;
            let _ = write!(
                s,
                "<rect x=\"{}\" y=\"{y}\" width=\"{CELL}\" height=\"{CELL}\" fill=\"{}\"/>",
                LEFT + sector * CELL,
                colour(band * h.bins.n_phi + sector)
            );
        }
    }
    // The axes: cos θ from 1 (the normal, top) to 0 (the horizon), φ from 0 to 2π.
    let _ = write!(
        s,
        "<text x=\"{x}\" y=\"8\" text-anchor=\"end\">1</text>\
         <text x=\"{x}\" y=\"{ch}\" text-anchor=\"end\">0</text>\
         <text x=\"{x}\" y=\"{mid}\" text-anchor=\"end\">cos θ</text>\
         <text x=\"{LEFT}\" y=\"{ty}\">0</text>\
         <text x=\"{w}\" y=\"{ty}\" text-anchor=\"end\">2π</text>\
         <text x=\"{cx}\" y=\"{ty}\" text-anchor=\"middle\">φ</text>",
        x = LEFT - 3,
        mid = ch / 2 + 3,
        ty = ch + 11,
        cx = LEFT + cw / 2,
    );
    let _ = write!(s, "</svg><figcaption>{title}</figcaption></figure>");
    s
}

/// Three maps side by side: observed, expected, (observed − expected)/√expected. Rows are
/// bands of cos θ (normal at the top), columns sectors of φ.
pub fn histogram(h: &Histogram) -> String {
    let max = h
        .observed
        .iter()
        .map(|&o| o as f64)
        .chain(h.expected.iter().copied())
        .fold(0.0, f64::max);
    let observed = map("student samples", h, |i| grey(h.observed[i] as f64, max));
    let expected = map("expected (reference)", h, |i| grey(h.expected[i], max));
    let difference = map("difference in standard deviations", h, |i| {
        let e = h.expected[i].max(1.0);
        diverging((h.observed[i] as f64 - h.expected[i]) / e.sqrt())
    });
    format!("<div class=\"maps\">{observed}{expected}{difference}</div>")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grade::sampling::HemisphereBins;

    #[test]
    fn a_histogram_draws_one_rect_per_cell_and_map() {
        let bins = HemisphereBins { n_cos: 2, n_phi: 3 };
        let h = Histogram {
            name: "x".into(),
            bins,
            observed: vec![1, 2, 3, 4, 5, 6],
            expected: vec![3.5; 6],
            rejected: (0, 0.0),
            chi2: 1.0,
            dof: 5,
            p_value: 0.9,
        };
        let svg = histogram(&h);
        assert_eq!(svg.matches("<rect").count(), 18);
        assert_eq!(
            svg.matches(">cos θ</text>").count(),
            3,
            "each map's axes are labelled"
        );
        assert_eq!(svg.matches(">φ</text>").count(), 3);
        assert!(
            svg.contains("rgb(255,255,255)"),
            "the largest count is white"
        );
    }
}
