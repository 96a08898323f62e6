//! The study's figures (the paper's figures 4, 5 and 6, and the budget sweep), built from the
//! grouped runs; [`crate::plots`] draws them.

use foveal_engine::SchedulerKind;

use crate::plots::{Figure, Panel, Series};
use crate::protocol::{Mode, Part, StudyConfig};
use crate::report::{Group, Metric, find};

fn rr_series(gs: &[Group<'_>], ns: &[u32], mode: Mode, m: Metric, name: String) -> Series {
    scheduler_series(gs, ns, mode, SchedulerKind::RoundRobin, m, name)
}

fn scheduler_series(
    gs: &[Group<'_>],
    ns: &[u32],
    mode: Mode,
    k: SchedulerKind,
    m: Metric,
    name: String,
) -> Series {
    Series {
        name,
        points: ns
            .iter()
            .filter_map(|&n| find(gs, Part::Table, n, mode, k).map(|g| (f64::from(n), g.ci(m))))
            .collect(),
    }
}

/// Mode of the table with the wall-clock budget, if any N has one.
fn ms_modes(cfg: &StudyConfig) -> Vec<(u32, Mode)> {
    cfg.ns
        .iter()
        .filter_map(|&n| {
            cfg.table_modes(n)
                .into_iter()
                .find(Mode::is_wall_clock)
                .map(|m| (n, m))
        })
        .collect()
}

/// Series over N for the paper-ms mode, whose parameter differs by N.
fn ms_series(
    cfg: &StudyConfig,
    gs: &[Group<'_>],
    k: SchedulerKind,
    m: Metric,
    name: &str,
) -> Series {
    Series {
        name: name.into(),
        points: ms_modes(cfg)
            .into_iter()
            .filter_map(|(n, mode)| {
                find(gs, Part::Table, n, mode, k).map(|g| (f64::from(n), g.ci(m)))
            })
            .collect(),
    }
}

/// Figures 4, 5 and 6 of the paper from the table part.
pub fn table_figures(cfg: &StudyConfig, gs: &[Group<'_>]) -> Vec<(String, Figure)> {
    let ns = &cfg.ns;
    let t_mean: Metric = |r| r.t_ms.mean();
    let t_sd: Metric = |r| r.t_ms.sd();
    let rr = SchedulerKind::RoundRobin;
    let mut modes: Vec<(Mode, String)> = vec![
        (Mode::Exact, "exact".into()),
        (Mode::Zero, "interrupt at 0".into()),
    ];
    modes.extend(
        cfg.fractions
            .iter()
            .map(|&f| (Mode::Fraction(f), format!("{f} of exact cost"))),
    );
    modes.extend(
        cfg.tests_budgets
            .iter()
            .map(|&t| (Mode::Tests(t), format!("{t} sphere tests"))),
    );
    let has_ms = !ms_modes(cfg).is_empty();
    let ms_name = format!(
        "paper target / {}",
        cfg.paper_ms_scale
            .map(|k| k.to_string())
            .unwrap_or_default()
    );
    let time_panel = |title: &str, y: &str, m: Metric| {
        let mut series: Vec<Series> = modes
            .iter()
            .map(|(mode, name)| rr_series(gs, ns, *mode, m, name.clone()))
            .collect();
        if has_ms {
            series.push(ms_series(cfg, gs, rr, m, &ms_name));
        }
        Panel {
            title: title.into(),
            x_label: "bodies N".into(),
            y_label: y.into(),
            log_x: true,
            log_y: true,
            series,
        }
    };
    let fig4 = Figure {
        panels: vec![
            time_panel("Mean collision time T (round-robin)", "mean T (ms)", t_mean),
            time_panel("Standard deviation of T", "sd T (ms)", t_sd),
        ],
    };
    let inacc_panel = |title: &str, y: &str, est: Metric, truth: Metric| {
        let mut series = Vec::new();
        for (mode, name) in modes.iter().filter(|(m, _)| *m != Mode::Exact) {
            series.push(rr_series(gs, ns, *mode, est, format!("{name}, estimate")));
            series.push(rr_series(gs, ns, *mode, truth, format!("{name}, true")));
        }
        if has_ms {
            series.push(ms_series(cfg, gs, rr, est, &format!("{ms_name}, estimate")));
            series.push(ms_series(cfg, gs, rr, truth, &format!("{ms_name}, true")));
        }
        Panel {
            title: title.into(),
            x_label: "bodies N".into(),
            y_label: y.into(),
            log_x: true,
            log_y: true,
            series,
        }
    };
    let fig5 = Figure {
        panels: vec![
            inacc_panel(
                "Geometric inaccuracy Δ (round-robin)",
                "mean Δ per frame",
                |r| r.delta.mean(),
                |r| r.true_delta.mean(),
            ),
            inacc_panel(
                "Perceived inaccuracy P (round-robin)",
                "mean P per frame",
                |r| r.p.mean(),
                |r| r.true_p.mean(),
            ),
        ],
    };
    let mut out = vec![
        ("fig4_time".to_string(), fig4),
        ("fig5_inaccuracy".to_string(), fig5),
    ];
    for &f in &cfg.fractions {
        let mode = Mode::Fraction(f);
        let sched_panel = |title: String, y: &str, m: Metric| Panel {
            title,
            x_label: "bodies N".into(),
            y_label: y.into(),
            log_x: true,
            log_y: true,
            series: cfg
                .schedulers
                .iter()
                .map(|&k| scheduler_series(gs, ns, mode, k, m, k.name().into()))
                .collect(),
        };
        out.push((
            format!("fig6_schedulers_f{f}"),
            Figure {
                panels: vec![
                    sched_panel(
                        format!("P per scheduler, budget {f} of exact"),
                        "mean P (estimate)",
                        |r| r.p.mean(),
                    ),
                    sched_panel(
                        format!("True P per scheduler, budget {f} of exact"),
                        "mean true P (audit)",
                        |r| r.true_p.mean(),
                    ),
                ],
            },
        ));
    }
    if has_ms {
        let panel = |title: String, y: &str, m: Metric| Panel {
            title,
            x_label: "bodies N".into(),
            y_label: y.into(),
            log_x: true,
            log_y: true,
            series: cfg
                .schedulers
                .iter()
                .map(|&k| ms_series(cfg, gs, k, m, k.name()))
                .collect(),
        };
        out.push((
            "fig6_schedulers_ms".to_string(),
            Figure {
                panels: vec![
                    panel(
                        format!("P per scheduler, {ms_name} ms"),
                        "mean P (estimate)",
                        |r| r.p.mean(),
                    ),
                    panel(
                        format!("True P per scheduler, {ms_name} ms"),
                        "mean true P (audit)",
                        |r| r.true_p.mean(),
                    ),
                ],
            },
        ));
    }
    out
}

/// True P (and estimated P) against budget per scheduler, one figure per N of the curves.
pub fn curve_figures(cfg: &StudyConfig, gs: &[Group<'_>]) -> Vec<(String, Figure)> {
    let Some(c) = &cfg.curves else {
        return Vec::new();
    };
    c.ns.iter()
        .map(|&n| {
            let panel = |title: String, y: &str, m: Metric| Panel {
                title,
                x_label: "budget (fraction of exact narrow-phase cost)".into(),
                y_label: y.into(),
                log_x: true,
                log_y: true,
                series: cfg
                    .schedulers
                    .iter()
                    .map(|&k| Series {
                        name: k.name().into(),
                        points: c
                            .fractions
                            .iter()
                            .filter_map(|&f| {
                                find(gs, Part::Curves, n, Mode::Fraction(f), k)
                                    .map(|g| (f, g.ci(m)))
                            })
                            .collect(),
                    })
                    .collect(),
            };
            (
                format!("curves_n{n}"),
                Figure {
                    panels: vec![
                        panel(
                            format!("True P against budget, N = {n}"),
                            "mean true P (audit)",
                            |r| r.true_p.mean(),
                        ),
                        panel(
                            format!("Estimated P against budget, N = {n}"),
                            "mean P (estimate)",
                            |r| r.p.mean(),
                        ),
                    ],
                },
            )
        })
        .collect()
}
