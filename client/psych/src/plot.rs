//! The fit drawn as a psychophysicist checks it (SVG): left, the proportion reported "apart"
//! against the gap at each eccentricity, with Wilson intervals and the fitted F2 observer's
//! curves; right, the same proportion against eccentricity at each gap, with the fitted F2 over
//! it (the paper's figure 7 is this panel for its experiment 4).

use plotters::prelude::*;

use crate::fit::Cell;
use crate::model::Observer;
use crate::report::wilson;

/// One colour per series, the same in both panels, distinguishable in colour-blind vision
/// (Okabe and Ito's palette).
const COLORS: [RGBColor; 7] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(86, 180, 233),
    RGBColor(230, 159, 0),
    RGBColor(0, 0, 0),
];

/// The two panels for `cells` and the fitted `observer`, as an SVG document titled `title`.
pub fn svg(cells: &[Cell], observer: &Observer, title: &str) -> Result<String, String> {
    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, (1100, 460)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let root = root
            .titled(title, ("sans-serif", 18))
            .map_err(|e| e.to_string())?;
        let (left, right) = root.split_horizontally(550);
        let mut eccs: Vec<f64> = cells.iter().map(|c| c.eccentricity_deg).collect();
        eccs.dedup();
        let mut gaps: Vec<f64> = cells
            .iter()
            .filter(|c| c.gap_deg > 0.0)
            .map(|c| c.gap_deg)
            .collect();
        gaps.sort_by(f64::total_cmp);
        gaps.dedup();
        let (gmin, gmax) = match (gaps.first(), gaps.last()) {
            (Some(&a), Some(&b)) => (a / 2.0, b * 2.0),
            _ => return Err("no trial with a gap to draw".into()),
        };
        let emax = eccs.iter().copied().fold(1.0, f64::max) * 1.05;

        let mut chart = ChartBuilder::on(&left)
            .margin(12)
            .caption(
                "reported apart against gap, by eccentricity",
                ("sans-serif", 14),
            )
            .x_label_area_size(40)
            .y_label_area_size(50)
            .build_cartesian_2d((gmin..gmax).log_scale(), 0.0..1.0)
            .map_err(|e| e.to_string())?;
        chart
            .configure_mesh()
            .light_line_style(WHITE)
            .x_labels(6)
            .x_label_formatter(&|x| format!("{}", (x * 1000.0).round() / 1000.0))
            .x_desc("gap (degrees, log scale)")
            .y_desc("P(reported apart)")
            .draw()
            .map_err(|e| e.to_string())?;
        for (i, &e) in eccs.iter().enumerate() {
            let color = COLORS[i % COLORS.len()];
            let curve = (0..=80).map(|k| {
                let g = gmin * (gmax / gmin).powf(f64::from(k) / 80.0);
                (g, observer.p_apart(g, e))
            });
            chart
                .draw_series(LineSeries::new(curve, color.stroke_width(2)))
                .map_err(|e| e.to_string())?
                .label(format!("{e} deg"))
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 18, y)], color.stroke_width(2))
                });
            for c in cells
                .iter()
                .filter(|c| c.eccentricity_deg == e && c.gap_deg > 0.0)
            {
                let p = f64::from(c.apart) / f64::from(c.n);
                let (lo, hi) = wilson(c.apart, c.n);
                chart
                    .draw_series([
                        PathElement::new(vec![(c.gap_deg, lo), (c.gap_deg, hi)], color),
                        PathElement::new(vec![(c.gap_deg, p), (c.gap_deg, p)], color),
                    ])
                    .map_err(|e| e.to_string())?;
                chart
                    .draw_series([Circle::new((c.gap_deg, p), 4, color.filled())])
                    .map_err(|e| e.to_string())?;
            }
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .position(SeriesLabelPosition::LowerRight)
            .draw()
            .map_err(|e| e.to_string())?;

        let mut chart = ChartBuilder::on(&right)
            .margin(12)
            .caption(
                "reported apart against eccentricity, by gap (triangles: touching); lines: fitted F2",
                ("sans-serif", 14),
            )
            .x_label_area_size(40)
            .y_label_area_size(50)
            .build_cartesian_2d(0.0..emax, 0.0..1.0)
            .map_err(|e| e.to_string())?;
        chart
            .configure_mesh()
            .light_line_style(WHITE)
            .x_desc("eccentricity (degrees)")
            .y_desc("P(reported apart)")
            .draw()
            .map_err(|e| e.to_string())?;
        for (i, &g) in gaps.iter().enumerate() {
            let color = COLORS[i % COLORS.len()];
            let curve = (0..=80).map(|k| {
                let e = emax * f64::from(k) / 80.0;
                (e, observer.p_apart(g, e))
            });
            chart
                .draw_series(LineSeries::new(curve, color.stroke_width(2)))
                .map_err(|e| e.to_string())?
                .label(format!("gap {g} deg"))
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 18, y)], color.stroke_width(2))
                });
            for c in cells.iter().filter(|c| c.gap_deg == g) {
                let p = f64::from(c.apart) / f64::from(c.n);
                let (lo, hi) = wilson(c.apart, c.n);
                let x = c.eccentricity_deg;
                chart
                    .draw_series([PathElement::new(vec![(x, lo), (x, hi)], color)])
                    .map_err(|e| e.to_string())?;
                chart
                    .draw_series([Circle::new((x, p), 4, color.filled())])
                    .map_err(|e| e.to_string())?;
            }
        }
        let false_alarms: Vec<&Cell> = cells.iter().filter(|c| c.gap_deg <= 0.0).collect();
        for c in false_alarms {
            let p = f64::from(c.apart) / f64::from(c.n);
            chart
                .draw_series([TriangleMarker::new(
                    (c.eccentricity_deg, p),
                    5,
                    BLACK.filled(),
                )])
                .map_err(|e| e.to_string())?;
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .position(SeriesLabelPosition::UpperRight)
            .draw()
            .map_err(|e| e.to_string())?;
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::cells;
    use crate::model::Function;
    use crate::simulate::{Design, simulate};

    #[test]
    fn the_plot_draws_every_cell_and_curve() {
        let o = Observer {
            function: Function::F2 { c: 4.0 },
            alpha: 0.05,
            beta: 2.5,
            guess: 0.05,
            lapse: 0.02,
        };
        let cells = cells(&simulate(&o, &Design::default(), 1));
        let doc = svg(&cells, &o, "simulated").expect("draws");
        assert!(doc.starts_with("<svg"), "{}", &doc[..40.min(doc.len())]);
        // A marker per cell with a gap in each panel, one per touching cell in the right one.
        let with_gap = cells.iter().filter(|c| c.gap_deg > 0.0).count();
        let touching = cells.len() - with_gap;
        assert_eq!(doc.matches("<circle").count(), 2 * with_gap);
        assert!(doc.matches("<polygon").count() >= touching);
        assert!(doc.contains("20 deg") && doc.contains("gap 0.2 deg"));
        assert!(svg(&[], &o, "none").is_err());
    }
}
