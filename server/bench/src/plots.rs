//! Figures as SVG and PNG (plotters): line charts of estimates across seeds with their 95%
//! intervals as error bars, a caption under the panels that says what is plotted, n and what the
//! bars are, and the commit and engine that drew it ([`crate::stamp`]).
//!
//! On a log axis an interval end at or below zero is drawn to the axis' floor (the bar stays
//! two-sided and says it reaches zero), a value of zero as an open triangle on the floor, and a
//! line is broken where a point cannot be drawn, never bridged across it. Each scheduler has one
//! colour in every figure ([`SCHEDULER_COLOURS`]).
//!
//! Log axes are drawn by plotting log10 of the values on a linear axis and labelling ticks with the
//! original values, so one code path serves both; the ticks are where a reader needs them, not
//! where an even spacing of the logarithm falls: on x at the values actually tested (the N or
//! budgets of the protocol), on a logarithmic y at 1, 2 and 5 times each power of ten, with the
//! minor grid at every integer multiple of a power of ten. Legends sit beside the chart, never
//! over the data; a series may be dashed (estimates are dashed, audited values solid), and a
//! panel may carry reference lines (the paper's "16x", a halving). Text needs a TrueType font found through
//! fontconfig (plotters' `ttf` feature); if none can be loaded the figure is drawn again without any
//! text (axes, lines and error bars only) and [`Rendered::with_text`] says so.

use std::path::{Path, PathBuf};

use plotters::coord::Shift;
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::prelude::*;

use crate::error::BenchError;
use crate::stats::Interval;

/// One line: points (x, estimate with its interval).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Series {
    /// Legend entry.
    pub name: String,
    /// Points in x order.
    pub points: Vec<(f64, Interval)>,
    /// Drawn dashed (an estimate beside its audited value).
    pub dashed: bool,
}

/// One chart.
#[derive(Debug, Clone, PartialEq, Default)]
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
    /// Horizontal reference lines: (y, label).
    pub references: Vec<(f64, String)>,
}

/// Panels side by side.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// Panels, left to right.
    pub panels: Vec<Panel>,
    /// What is plotted, over how many replicates, and what the bars are: drawn under the panels
    /// (wrapped), with the stamp of what drew it after it.
    pub caption: String,
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

const PANEL_W: u32 = 820;
const PANEL_H: u32 = 480;
/// Width of the legend column to the right of each chart.
const LEGEND_W: u32 = 200;

/// Height of the caption's area under the panels.
const CAPTION_H: u32 = 96;

/// Enough colours that the fixed names and a figure's others never share one (the grid's four
/// priority-queue thresholds beside the fixed ten).
const COLORS: [RGBColor; 16] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
    RGBColor(174, 199, 232),
    RGBColor(255, 187, 120),
    RGBColor(152, 223, 138),
    RGBColor(255, 152, 150),
    RGBColor(197, 176, 213),
    RGBColor(196, 156, 148),
];

/// Series names that keep one colour (an index into the palette) in every figure: the
/// schedulers, the bound and the exact frame. Any other name takes the next colour after these.
pub const SCHEDULER_COLOURS: [&str; 10] = [
    "round-robin",
    "priority-only",
    "priority-sorted",
    "expected-gain",
    "priced",
    "sequential",
    "sorted-sequential",
    "exact",
    "clairvoyant bound",
    "priced-no-gaze",
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

/// A linear axis over transformed values whose ticks (and minor grid lines) are given, not
/// chosen by plotters: see [`ticks`].
#[derive(Debug, Clone)]
struct TickedAxis {
    lo: f64,
    hi: f64,
    bold: Vec<f64>,
    light: Vec<f64>,
}

impl Ranged for TickedAxis {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, v: &f64, limit: (i32, i32)) -> i32 {
        if self.hi == self.lo {
            return (limit.1 - limit.0) / 2;
        }
        let t = (v - self.lo) / (self.hi - self.lo);
        limit.0 + (t * f64::from(limit.1 - limit.0)).round() as i32
    }

    fn key_points<H: KeyPointHint>(&self, hint: H) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.light.clone()
        } else {
            self.bold.clone()
        }
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.lo..self.hi
    }
}

/// Tick positions (transformed) for an axis over [lo, hi] (transformed): on x the tested values,
/// on a log y 1, 2 and 5 times the powers of ten, on a linear y about eight round steps.
fn ticks(lo: f64, hi: f64, log: bool, tested: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let inside = |v: &f64| *v >= lo - 1e-9 && *v <= hi + 1e-9;
    if !tested.is_empty() {
        let mut t: Vec<f64> = tested
            .iter()
            .filter_map(|&v| tx(v, log))
            .filter(inside)
            .collect();
        t.sort_by(f64::total_cmp);
        t.dedup();
        return (t, minor(lo, hi, log));
    }
    if log {
        let mut t = Vec::new();
        // Over more than three decades, label the powers of ten alone.
        let mults: &[f64] = if hi - lo > 3.0 {
            &[1.0]
        } else {
            &[1.0, 2.0, 5.0]
        };
        for e in (lo.floor() as i32 - 1)..=(hi.ceil() as i32 + 1) {
            for &m in mults {
                t.push(f64::from(e) + m.log10());
            }
        }
        t.retain(inside);
        // A narrow range may hold fewer than two of them: fall back to every integer multiple.
        if t.len() < 2 {
            t = minor(lo, hi, true);
        }
        return (t, minor(lo, hi, true));
    }
    let span = (hi - lo).max(1e-12);
    let raw = span / 8.0;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|k| k * mag)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * mag);
    let t: Vec<f64> = ((lo / step).ceil() as i64..=(hi / step).floor() as i64)
        .map(|k| k as f64 * step)
        .collect();
    (t, Vec::new())
}

/// Minor grid of a log axis: every integer multiple of each power of ten inside [lo, hi].
fn minor(lo: f64, hi: f64, log: bool) -> Vec<f64> {
    if !log {
        return Vec::new();
    }
    let mut t = Vec::new();
    for e in (lo.floor() as i32 - 1)..=(hi.ceil() as i32) {
        for m in 1..10 {
            let v = f64::from(e) + f64::from(m).log10();
            if v >= lo && v <= hi {
                t.push(v);
            }
        }
    }
    t
}

/// A point as drawn: (x, y, y_lo, y_hi) in the axes' coordinates.
type Drawn = (f64, f64, f64, f64);

/// Transformed points of a series: (x, y, y_lo, y_hi) where the point can be drawn, `None` where
/// it cannot (its value is not finite, or not positive on a log axis), so that a line breaks
/// there. On a log axis an interval end at or below zero becomes `floor` (the axis' bottom).
fn points(s: &Series, p: &Panel, floor: f64) -> Vec<Option<Drawn>> {
    s.points
        .iter()
        .map(|(x, c)| {
            let x = tx(*x, p.log_x)?;
            let y = tx(c.value, p.log_y)?;
            let end = |v: f64| {
                if v.is_nan() {
                    y
                } else {
                    tx(v, p.log_y).unwrap_or(floor)
                }
            };
            // An unbounded upper end (a resample with no finite ratio) reaches the axis' top,
            // set once the range is known.
            let hi = if c.hi == f64::INFINITY {
                f64::INFINITY
            } else {
                end(c.hi).max(y)
            };
            Some((x, y, end(c.lo).min(y), hi))
        })
        .collect()
}

/// The x of every point whose value is exactly zero on a log y: drawn on the floor, not dropped.
fn zeros(s: &Series, p: &Panel) -> Vec<f64> {
    if !p.log_y {
        return Vec::new();
    }
    s.points
        .iter()
        .filter(|(_, c)| c.value == 0.0)
        .filter_map(|(x, _)| tx(*x, p.log_x))
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
    palette: &[String],
    text: bool,
) -> Result<(), String> {
    let (plot_area, legend_area) = area.split_horizontally(PANEL_W - LEGEND_W);
    // Interval ends below a log axis are marked -inf first and put on the floor once the range
    // is known.
    let raw: Vec<Vec<Option<Drawn>>> = p
        .series
        .iter()
        .map(|s| points(s, p, f64::NEG_INFINITY))
        .collect();
    let zero_xs: Vec<Vec<f64>> = p.series.iter().map(|s| zeros(s, p)).collect();
    let tested: Vec<f64> = {
        let mut v: Vec<f64> = p
            .series
            .iter()
            .flat_map(|s| s.points.iter().map(|q| q.0))
            .collect();
        v.sort_by(f64::total_cmp);
        v.dedup();
        v
    };
    let refs: Vec<(f64, &str)> = p
        .references
        .iter()
        .filter_map(|(y, l)| tx(*y, p.log_y).map(|t| (t, l.as_str())))
        .collect();
    let drawn = || raw.iter().flatten().flatten();
    let (x0, x1) = range(
        drawn()
            .map(|q| q.0)
            .chain(zero_xs.iter().flatten().copied()),
        p.log_x,
    );
    let (mut y0, y1) = range(
        drawn()
            .flat_map(|q| [q.1, q.2, q.3])
            .filter(|v| v.is_finite())
            .chain(refs.iter().map(|r| r.0)),
        p.log_y,
    );
    let floored = drawn().any(|q| q.2 == f64::NEG_INFINITY);
    if p.log_y && (floored || zero_xs.iter().any(|z| !z.is_empty())) {
        // Room under the lowest value for the floor's marks.
        y0 -= 0.1 * (y1 - y0);
    }
    let pts: Vec<Vec<Option<Drawn>>> = raw
        .iter()
        .map(|v| {
            v.iter()
                .map(|q| q.map(|(x, y, lo, hi)| (x, y, lo.max(y0), hi.min(y1))))
                .collect()
        })
        .collect();
    let (xt, xm) = ticks(x0, x1, p.log_x, &tested);
    let (yt, ym) = ticks(y0, y1, p.log_y, &[]);
    let mut b = ChartBuilder::on(&plot_area);
    b.margin(12);
    if text {
        b.caption(&p.title, ("sans-serif", 18))
            .x_label_area_size(42)
            .y_label_area_size(64);
    }
    let mut chart = b
        .build_cartesian_2d(
            TickedAxis {
                lo: x0,
                hi: x1,
                bold: xt,
                light: xm,
            },
            TickedAxis {
                lo: y0,
                hi: y1,
                bold: yt,
                light: ym,
            },
        )
        .map_err(|e| e.to_string())?;
    let (lx, ly) = (p.log_x, p.log_y);
    let fx = move |v: &f64| tick(*v, lx);
    let fy = move |v: &f64| tick(*v, ly);
    let mut mesh = chart.configure_mesh();
    mesh.light_line_style(RGBColor(235, 235, 235))
        .bold_line_style(RGBColor(205, 205, 205));
    if text {
        mesh.x_desc(p.x_label.as_str())
            .y_desc(p.y_label.as_str())
            .x_label_formatter(&fx)
            .y_label_formatter(&fy);
    } else {
        mesh.x_labels(0).y_labels(0);
    }
    mesh.draw().map_err(|e| e.to_string())?;
    let grey = RGBColor(90, 90, 90);
    for (y, label) in &refs {
        chart
            .draw_series(DashedLineSeries::new(
                [(x0, *y), (x1, *y)],
                8,
                5,
                grey.stroke_width(1),
            ))
            .map_err(|e| e.to_string())?;
        if text {
            chart
                .draw_series(std::iter::once(Text::new(
                    (*label).to_string(),
                    (x0 + 0.01 * (x1 - x0), *y),
                    ("sans-serif", 12).into_font().color(&grey),
                )))
                .map_err(|e| e.to_string())?;
        }
    }
    for (i, q) in pts.iter().enumerate() {
        let s = &p.series[i];
        let color = color_of(palette, s);
        let style = ShapeStyle::from(&color).stroke_width(3);
        // One line per run of drawable points: a gap stays a gap.
        for run in q.split(Option::is_none) {
            let line = run.iter().flatten().map(|q| (q.0, q.1));
            if s.dashed {
                chart
                    .draw_series(DashedLineSeries::new(line, 9, 6, style))
                    .map_err(|e| e.to_string())?;
            } else {
                chart
                    .draw_series(LineSeries::new(line, style))
                    .map_err(|e| e.to_string())?;
            }
        }
        let q: Vec<(f64, f64, f64, f64)> = q.iter().flatten().copied().collect();
        chart
            .draw_series(q.iter().map(|q| Circle::new((q.0, q.1), 4, color.filled())))
            .map_err(|e| e.to_string())?;
        chart
            .draw_series(
                q.iter()
                    .filter(|q| q.3 > q.2)
                    .map(|q| PathElement::new(vec![(q.0, q.2), (q.0, q.3)], color.stroke_width(2))),
            )
            .map_err(|e| e.to_string())?;
        chart
            .draw_series(
                zero_xs[i]
                    .iter()
                    .map(|&x| TriangleMarker::new((x, y0), 7, color.stroke_width(2))),
            )
            .map_err(|e| e.to_string())?;
    }
    if text {
        draw_legend(&legend_area, p, palette)?;
    }
    Ok(())
}

/// A series' name without its ", estimate", ", true" or ", centre-fed" suffix: an estimate and
/// its audited value (or a scheduler and its screen-centre control) share one colour and differ
/// by line style.
fn base_name(s: &Series) -> &str {
    s.name
        .trim_end_matches(", estimate")
        .trim_end_matches(", true")
        .trim_end_matches(", centre-fed")
        .trim_end_matches(", gaze")
        .trim_end_matches(", screen centre")
}

/// Base names with a colour each: the schedulers' fixed ones ([`SCHEDULER_COLOURS`]), then any
/// other of the figure's series in order of first appearance; the same in every panel.
fn palette(fig: &Figure) -> Vec<String> {
    let mut names: Vec<String> = SCHEDULER_COLOURS.iter().map(|s| s.to_string()).collect();
    for s in fig.panels.iter().flat_map(|p| &p.series) {
        let b = base_name(s);
        if !names.iter().any(|n| n == b) {
            names.push(b.to_string());
        }
    }
    names
}

fn color_of(palette: &[String], s: &Series) -> RGBColor {
    let i = palette.iter().position(|n| n == base_name(s)).unwrap_or(0);
    COLORS[i % COLORS.len()]
}

/// The legend in its own column beside the chart: a swatch (solid or dashed) and the name.
fn draw_legend<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    p: &Panel,
    palette: &[String],
) -> Result<(), String> {
    let font = ("sans-serif", 13).into_font();
    for (i, s) in p.series.iter().enumerate() {
        let y = 48 + 20 * i as i32;
        let color = color_of(palette, s);
        if s.dashed {
            for k in 0..3 {
                let x = 4 + 9 * k;
                area.draw(&PathElement::new(
                    vec![(x, y), (x + 5, y)],
                    color.stroke_width(2),
                ))
                .map_err(|e| e.to_string())?;
            }
        } else {
            area.draw(&PathElement::new(
                vec![(4, y), (28, y)],
                color.stroke_width(2),
            ))
            .map_err(|e| e.to_string())?;
        }
        area.draw(&Text::new(s.name.clone(), (34, y - 7), font.clone()))
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
    let (panels, foot) = root.split_vertically(PANEL_H);
    let areas = panels.split_evenly((1, fig.panels.len().max(1)));
    let palette = palette(fig);
    for (a, p) in areas.iter().zip(&fig.panels) {
        draw_panel(a, p, &palette, text)?;
    }
    if text {
        let width = (PANEL_W * fig.panels.len().max(1) as u32) as usize;
        let font = ("sans-serif", 13).into_font();
        for (i, line) in caption_lines(fig, width / 7).iter().enumerate() {
            foot.draw(&Text::new(
                line.clone(),
                (12, 4 + 16 * i as i32),
                font.clone(),
            ))
            .map_err(|e| e.to_string())?;
        }
    }
    root.present().map_err(|e| e.to_string())
}

/// The caption then the stamp, wrapped at `width` characters (at most five lines: the caption
/// is cut with an ellipsis before the stamp is).
fn caption_lines(fig: &Figure, width: usize) -> Vec<String> {
    let mut lines = wrap(&fig.caption, width.max(20));
    lines.truncate(4);
    if lines.len() == 4 {
        lines[3].push_str(" …");
    }
    lines.push(crate::stamp::current().line());
    lines
}

/// Words of `text` in lines of at most `width` characters (a longer word on a line of its own).
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split_whitespace() {
        if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > width {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
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
    let size = (
        PANEL_W * fig.panels.len().max(1) as u32,
        PANEL_H + CAPTION_H,
    );
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

/// The paper's claim for priority scheduling: P "roughly halves" (section 4).
pub(crate) const PAPER_P_RATIO: f64 = 0.5;

/// A panel over the body count N, log-log, without reference lines.
pub(crate) fn panel(title: String, y_label: String, series: Vec<Series>) -> Panel {
    Panel {
        title,
        x_label: "bodies N".into(),
        y_label,
        log_x: true,
        log_y: true,
        series,
        references: Vec::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_ticks_sit_at_the_tested_values_and_round_multiples() {
        let tested = [10.0, 30.0, 100.0, 300.0, 500.0];
        let (x0, x1) = (1.0, 2.8);
        let (t, m) = ticks(x0, x1, true, &tested);
        let back: Vec<String> = t.iter().map(|&v| tick(v, true)).collect();
        assert_eq!(back, ["10", "30", "100", "300", "500"]);
        // Minor grid at 10, 20, ..., 90, 100, 200, ...: log-spaced, not even.
        assert!(m.iter().any(|&v| tick(v, true) == "20"));
        let gaps: Vec<f64> = m.windows(2).map(|w| w[1] - w[0]).collect();
        assert!(gaps.iter().any(|g| (g - 2f64.log10()).abs() < 1e-12));
        assert!(
            gaps.iter()
                .any(|g| (g - (10.0f64 / 9.0).log10()).abs() < 1e-12)
        );
        let (y, _) = ticks(-1.2, 1.4, true, &[]);
        let back: Vec<String> = y.iter().map(|&v| tick(v, true)).collect();
        assert_eq!(
            back,
            ["0.10", "0.20", "0.50", "1.0", "2.0", "5.0", "10", "20"]
        );
        let (lin, none) = ticks(0.0, 1.0, false, &[]);
        assert_eq!(lin.len(), 6);
        assert!(none.is_empty());
    }

    #[test]
    fn a_panel_with_dashed_series_and_references_renders() {
        let dir = std::env::temp_dir().join(format!("foveal-plots-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("dir");
        let c = |m: f64| Interval {
            value: m,
            lo: 0.9 * m,
            hi: 1.1 * m,
        };
        let fig = Figure {
            panels: vec![Panel {
                title: "t".into(),
                x_label: "bodies N".into(),
                y_label: "ratio".into(),
                log_x: true,
                log_y: true,
                series: vec![
                    Series {
                        name: "a, estimate".into(),
                        points: vec![(10.0, c(1.0)), (100.0, c(3.0))],
                        dashed: true,
                    },
                    Series {
                        name: "a, true".into(),
                        points: vec![(10.0, c(2.0)), (100.0, c(4.0))],
                        dashed: false,
                    },
                ],
                references: vec![(16.0, "16x (paper)".into())],
            }],
            caption: "T over the exact frame's, mean of 5 seeds, bars 95% intervals.".into(),
        };
        let r = render(&fig, &dir.join("f")).expect("rendered");
        for f in [&r.svg, &r.png] {
            assert!(std::fs::metadata(f).map(|m| m.len()).unwrap_or(0) > 100);
        }
        let svg = std::fs::read_to_string(&r.svg).unwrap_or_default();
        if r.with_text {
            assert!(svg.contains("mean of 5 seeds"), "the caption is drawn");
            assert!(
                svg.contains(crate::stamp::current().engine),
                "the stamp is drawn"
            );
        }
        let pal = palette(&fig);
        assert_eq!(pal.last().map(String::as_str), Some("a"));
        assert_eq!(
            pal[0], "round-robin",
            "schedulers keep their colours in every figure"
        );
        let p = &fig.panels[0];
        assert_eq!(color_of(&pal, &p.series[0]), color_of(&pal, &p.series[1]));
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// On a log axis a zero is marked on the floor and breaks the line, and an interval reaching
    /// below zero is drawn to the floor, not cut to one side.
    #[test]
    fn zeros_break_the_line_and_low_ends_reach_the_floor() {
        let at = |value: f64, lo: f64, hi: f64| Interval { value, lo, hi };
        let s = Series {
            name: "priced".into(),
            points: vec![
                (1.0, at(0.5, 0.4, 0.6)),
                (10.0, at(0.0, 0.0, 0.1)),
                (100.0, at(0.3, -0.1, 0.7)),
            ],
            dashed: false,
        };
        let p = Panel {
            log_x: true,
            log_y: true,
            series: vec![s.clone()],
            ..Panel::default()
        };
        let drawn = points(&s, &p, -9.0);
        assert!(drawn[0].is_some() && drawn[1].is_none());
        let last = drawn[2].expect("drawn");
        assert_eq!(last.2, -9.0, "the low end goes to the floor");
        assert!((last.3 - 0.7f64.log10()).abs() < 1e-12);
        assert_eq!(zeros(&s, &p), vec![1.0]);
        let lines: Vec<usize> = drawn.split(Option::is_none).map(<[_]>::len).collect();
        assert_eq!(lines, [1, 1], "two runs, not one line across the zero");
    }

    #[test]
    fn ticks_read_back_the_original_values() {
        assert_eq!(tick(2.0, true), "100");
        assert_eq!(tick(0.5, false), "0.50");
        assert_eq!(tick(-2.0, true), "0.010");
        assert_eq!(tx(-1.0, true), None);
        assert_eq!(tx(100.0, true), Some(2.0));
    }
}
