//! Figures as SVG and PNG (plotters): line charts of means across seeds with 95% CI error bars.
//!
//! Log axes are drawn by plotting log10 of the values on a linear axis and labelling ticks with the
//! original values, so one code path serves both. Text needs a TrueType font found through
//! fontconfig (plotters' `ttf` feature); if none can be loaded the figure is drawn again without any
//! text (axes, lines and error bars only) and [`Rendered::with_text`] says so.

use std::path::{Path, PathBuf};

use plotters::coord::Shift;
use plotters::prelude::*;

use crate::error::BenchError;
use crate::stats::MeanCi;

/// One line: points (x, mean ± CI).
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend entry.
    pub name: String,
    /// Points in x order.
    pub points: Vec<(f64, MeanCi)>,
}

/// One chart.
#[derive(Debug, Clone, PartialEq)]
pub struct Panel {
    /// Chart title.
    pub title: String,
    /// X axis description.
    pub x_label: String,
    /// Y axis description.
    pub y_label: String,
    /// Logarithmic x.
    pub log_x: bool,
    /// Logarithmic y.
    pub log_y: bool,
    /// Lines.
    pub series: Vec<Series>,
}

/// Panels side by side.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// Panels, left to right.
    pub panels: Vec<Panel>,
}

/// Files written for a figure.
#[derive(Debug, Clone, PartialEq)]
pub struct Rendered {
    /// The SVG.
    pub svg: PathBuf,
    /// The PNG.
    pub png: PathBuf,
    /// Whether text (titles, labels, legend) could be drawn.
    pub with_text: bool,
}

const PANEL_W: u32 = 640;
const PANEL_H: u32 = 480;

const COLORS: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
];

fn tx(v: f64, log: bool) -> Option<f64> {
    if !v.is_finite() {
        None
    } else if log {
        (v > 0.0).then(|| v.log10())
    } else {
        Some(v)
    }
}

fn tick(v: f64, log: bool) -> String {
    let x = if log { 10f64.powf(v) } else { v };
    let a = x.abs();
    if a == 0.0 {
        "0".into()
    } else if !(1e-3..1e5).contains(&a) {
        format!("{x:.0e}")
    } else if a >= 10.0 {
        format!("{x:.0}")
    } else if a >= 1.0 {
        format!("{x:.1}")
    } else {
        let d = (-a.log10().floor()) as usize + 1;
        format!("{x:.d$}")
    }
}

/// Transformed points of a series: (x, y, y_lo, y_hi).
fn points(s: &Series, p: &Panel) -> Vec<(f64, f64, f64, f64)> {
    s.points
        .iter()
        .filter_map(|(x, c)| {
            let x = tx(*x, p.log_x)?;
            let y = tx(c.mean, p.log_y)?;
            let (lo, hi) = if c.half.is_finite() {
                let lo = tx(c.lo(), p.log_y).unwrap_or(y);
                let hi = tx(c.hi(), p.log_y).unwrap_or(y);
                (lo, hi)
            } else {
                (y, y)
            };
            Some((x, y, lo, hi))
        })
        .collect()
}

fn range(vals: impl Iterator<Item = f64>, log: bool) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in vals {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let span = (hi - lo).max(if log { 0.2 } else { 1e-9 * (1.0 + hi.abs()) });
    let pad = 0.06 * span;
    let lo = if !log && lo >= 0.0 {
        (lo - pad).max(0.0)
    } else {
        lo - pad
    };
    (lo, hi + pad)
}

fn draw_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    p: &Panel,
    text: bool,
) -> Result<(), String> {
    let pts: Vec<Vec<(f64, f64, f64, f64)>> = p.series.iter().map(|s| points(s, p)).collect();
    let (x0, x1) = range(pts.iter().flatten().map(|q| q.0), p.log_x);
    let (y0, y1) = range(pts.iter().flatten().flat_map(|q| [q.1, q.2, q.3]), p.log_y);
    let mut b = ChartBuilder::on(area);
    b.margin(12);
    if text {
        b.caption(&p.title, ("sans-serif", 18))
            .x_label_area_size(42)
            .y_label_area_size(64);
    }
    let mut chart = b
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(|e| e.to_string())?;
    let (lx, ly) = (p.log_x, p.log_y);
    let fx = move |v: &f64| tick(*v, lx);
    let fy = move |v: &f64| tick(*v, ly);
    let mut mesh = chart.configure_mesh();
    mesh.light_line_style(RGBColor(235, 235, 235));
    if text {
        mesh.x_desc(p.x_label.as_str())
            .y_desc(p.y_label.as_str())
            .x_label_formatter(&fx)
            .y_label_formatter(&fy)
            .x_labels(8)
            .y_labels(8);
    } else {
        mesh.x_labels(0).y_labels(0);
    }
    mesh.draw().map_err(|e| e.to_string())?;
    for (i, (s, q)) in p.series.iter().zip(&pts).enumerate() {
        let color = COLORS[i % COLORS.len()];
        let style = ShapeStyle::from(&color).stroke_width(2);
        let line = chart
            .draw_series(LineSeries::new(q.iter().map(|q| (q.0, q.1)), style))
            .map_err(|e| e.to_string())?;
        if text {
            line.label(s.name.as_str()).legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 18, y)], color.stroke_width(2))
            });
        }
        chart
            .draw_series(q.iter().map(|q| Circle::new((q.0, q.1), 3, color.filled())))
            .map_err(|e| e.to_string())?;
        chart
            .draw_series(
                q.iter()
                    .filter(|q| q.3 > q.2)
                    .map(|q| PathElement::new(vec![(q.0, q.2), (q.0, q.3)], color)),
            )
            .map_err(|e| e.to_string())?;
    }
    if text && !p.series.is_empty() {
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperLeft)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 13))
            .draw()
            .map_err(|e| e.to_string())?;
    }
    Ok(())
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    fig: &Figure,
    text: bool,
) -> Result<(), String> {
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    let areas = root.split_evenly((1, fig.panels.len().max(1)));
    for (a, p) in areas.iter().zip(&fig.panels) {
        draw_panel(a, p, text)?;
    }
    root.present().map_err(|e| e.to_string())
}

fn render_svg(fig: &Figure, path: &Path, size: (u32, u32), text: bool) -> Result<(), String> {
    draw(SVGBackend::new(path, size).into_drawing_area(), fig, text)
}

fn render_png(fig: &Figure, path: &Path, size: (u32, u32), text: bool) -> Result<(), String> {
    draw(
        BitMapBackend::new(path, size).into_drawing_area(),
        fig,
        text,
    )
}

/// Write `stem.svg` and `stem.png`.
pub fn render(fig: &Figure, stem: &Path) -> Result<Rendered, BenchError> {
    let size = (PANEL_W * fig.panels.len().max(1) as u32, PANEL_H);
    // Not `with_extension`: stems such as `fig6_schedulers_f0.1` contain dots.
    let with_ext = |ext: &str| {
        let mut s = stem.as_os_str().to_owned();
        s.push(".");
        s.push(ext);
        PathBuf::from(s)
    };
    let svg = with_ext("svg");
    let png = with_ext("png");
    let plot_err = |path: &Path, msg: String| BenchError::Plot {
        path: path.to_owned(),
        msg,
    };
    let mut with_text = true;
    if render_svg(fig, &svg, size, true).is_err() {
        with_text = false;
        render_svg(fig, &svg, size, false).map_err(|m| plot_err(&svg, m))?;
    }
    if !with_text || render_png(fig, &png, size, true).is_err() {
        with_text = false;
        // Redo the SVG too, so both files agree.
        render_svg(fig, &svg, size, false).map_err(|m| plot_err(&svg, m))?;
        render_png(fig, &png, size, false).map_err(|m| plot_err(&png, m))?;
    }
    Ok(Rendered {
        svg,
        png,
        with_text,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_read_back_the_original_values() {
        assert_eq!(tick(2.0, true), "100");
        assert_eq!(tick(0.5, false), "0.50");
        assert_eq!(tick(-2.0, true), "0.010");
        assert_eq!(tx(-1.0, true), None);
        assert_eq!(tx(100.0, true), Some(2.0));
    }
}
