//! The study's figures (the paper's figures 4, 5 and 6, and the budget sweep), built from the
//! grouped runs; [`crate::plots`] draws them.
//!
//! The paper's claims are ratios ("up to 16 times lower", "roughly halves"), so beside every
//! panel of absolute values there is a panel of the ratio itself, paired by seed with its 95% CI
//! and the claim as a reference line. Estimates are dashed and the audited (true) values solid,
//! in the same colour. Every axis names its unit: T in milliseconds, Δ in scene units (the
//! shape radius is 1), P in the perceptual model's unit of gap (degrees of visual angle for F2
//! in degrees, a ratio for F1).

use foveal_engine::{EccentricityUnit, PerceptualFunction, PerceptualModel, SchedulerKind};

use crate::plots::{Figure, PAPER_P_RATIO, Panel, Series, panel};
use crate::protocol::{Mode, Part, StudyConfig};
use crate::ratio::RatioCi;
use crate::report::{Group, Metric, find, paired_ratio};

/// The paper's claim for interruption: T "up to 16 times lower" (section 4).
const PAPER_T_RATIO: f64 = 16.0;

/// The paper's claim for inaccuracy against N: "up to 200 times worse" (section 4, figure 5).
const PAPER_GROWTH: f64 = 200.0;

/// Unit of P (and of the gap g') under `model`.
pub fn p_unit(model: &PerceptualModel) -> &'static str {
    match (model.function, model.unit) {
        (PerceptualFunction::F1, _) => "gap / eccentricity",
        (_, EccentricityUnit::Degrees) => "deg",
        (_, EccentricityUnit::Pixels) => "px",
    }
}

/// A series over the table's N for one mode and scheduler.
fn over_n(
    gs: &[Group<'_>],
    modes: &[(u32, Mode)],
    k: SchedulerKind,
    m: Metric,
    name: String,
    dashed: bool,
) -> Series {
    over_n_in(gs, Part::Table, modes, k, m, name, dashed)
}

/// [`over_n`] in any closed-loop part.
fn over_n_in(
    gs: &[Group<'_>],
    part: Part,
    modes: &[(u32, Mode)],
    k: SchedulerKind,
    m: Metric,
    name: String,
    dashed: bool,
) -> Series {
    Series {
        name,
        points: modes
            .iter()
            .filter_map(|&(n, mode)| {
                find(gs, part, n, mode, k).map(|g| (f64::from(n), g.boot(m).interval()))
            })
            .collect(),
        dashed,
    }
}

/// A metric at each N over the same metric at the smallest N of `modes` (same scheduler, seeds
/// paired by number; the scenes differ by N): how the error grows with N, figure 5's claim.
fn growth_over_n(
    gs: &[Group<'_>],
    modes: &[(u32, Mode)],
    k: SchedulerKind,
    m: Metric,
    name: String,
) -> Series {
    let base = modes
        .iter()
        .min_by_key(|(n, _)| *n)
        .and_then(|&(n, mode)| find(gs, Part::Table, n, mode, k));
    Series {
        name,
        points: modes
            .iter()
            .filter_map(|&(n, mode)| {
                let b = base?;
                let g = find(gs, Part::Table, n, mode, k)?;
                (g.n != b.n).then_some(())?;
                let pairs = g.runs.iter().filter_map(|r| {
                    let rb = b.runs.iter().find(|x| x.spec.seed == r.spec.seed)?;
                    Some((m(r), m(rb)))
                });
                Some((f64::from(n), RatioCi::of(pairs).interval()))
            })
            .collect(),
        dashed: false,
    }
}

/// A paired ratio `m(a) / m(b)` over the table's N.
fn ratio_over_n(
    gs: &[Group<'_>],
    modes: &[(u32, Mode, Mode)],
    ks: (SchedulerKind, SchedulerKind),
    m: Metric,
    name: String,
) -> Series {
    ratio_over_n_in(gs, Part::Table, modes, ks, m, name)
}

/// [`ratio_over_n`] in any closed-loop part.
fn ratio_over_n_in(
    gs: &[Group<'_>],
    part: Part,
    modes: &[(u32, Mode, Mode)],
    (ka, kb): (SchedulerKind, SchedulerKind),
    m: Metric,
    name: String,
) -> Series {
    Series {
        name,
        points: modes
            .iter()
            .filter_map(|&(n, ma, mb)| {
                let a = find(gs, part, n, ma, ka)?;
                let b = find(gs, part, n, mb, kb)?;
                Some((f64::from(n), paired_ratio(a, b, m).interval()))
            })
            .collect(),
        dashed: false,
    }
}

/// The same mode at every N.
fn at_every_n(cfg: &StudyConfig, mode: Mode) -> Vec<(u32, Mode)> {
    cfg.ns.iter().map(|&n| (n, mode)).collect()
}

/// The wall-clock mode of each N that has one (the paper's target time differs by N).
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

/// Figures 4, 5 and 6 of the paper from the table part.
pub fn table_figures(cfg: &StudyConfig, gs: &[Group<'_>]) -> Vec<(String, Figure)> {
    let t_mean: Metric = |r| r.t_ms.mean();
    let t_sd: Metric = |r| r.t_ms.sd();
    let rr = SchedulerKind::RoundRobin;
    let pu = p_unit(&cfg.model);
    // Every interrupted budget as (label, mode per N).
    let mut budgets: Vec<(String, Vec<(u32, Mode)>)> =
        vec![("interrupt at 0".into(), at_every_n(cfg, Mode::Zero))];
    budgets.extend(cfg.fractions.iter().map(|&f| {
        (
            format!("{f} of exact cost"),
            at_every_n(cfg, Mode::Fraction(f)),
        )
    }));
    budgets.extend(
        cfg.tests_budgets
            .iter()
            .map(|&t| (format!("{t} sphere tests"), at_every_n(cfg, Mode::Tests(t)))),
    );
    let ms = ms_modes(cfg);
    if !ms.is_empty() {
        let k = cfg
            .paper_ms_scale
            .map(|k| k.to_string())
            .unwrap_or_default();
        budgets.push((format!("paper target / {k}"), ms.clone()));
    }
    let exact = at_every_n(cfg, Mode::Exact);
    let reps = format!(
        "Points: means over {} seeds x {} frames (closed loop); bars: 95% percentile-bootstrap \
         intervals over seeds, ratios paired by seed (the ratio of the means).",
        cfg.seeds.len(),
        cfg.frames
    );
    let time_panel = |title: &str, y: &str, m: Metric| {
        let mut series = vec![over_n(gs, &exact, rr, m, "exact".into(), false)];
        series.extend(
            budgets
                .iter()
                .map(|(name, modes)| over_n(gs, modes, rr, m, name.clone(), false)),
        );
        panel(title.into(), y.into(), series)
    };
    let mut speedup = panel(
        "T exact / T interrupted (paired by seed)".into(),
        "ratio of mean T".into(),
        budgets
            .iter()
            .map(|(name, modes)| {
                let pairs: Vec<(u32, Mode, Mode)> =
                    modes.iter().map(|&(n, m)| (n, Mode::Exact, m)).collect();
                ratio_over_n(gs, &pairs, (rr, rr), t_mean, name.clone())
            })
            .collect(),
    );
    speedup.references = vec![(PAPER_T_RATIO, "16x (paper)".into())];
    let fig4 = Figure {
        panels: vec![
            time_panel("Mean collision time T (round-robin)", "mean T (ms)", t_mean),
            time_panel("Standard deviation of T", "sd of T (ms)", t_sd),
            speedup,
        ],
        caption: format!(
            "The paper's figure 4: collision-handling time T of round-robin against N, exact and \
             at each interrupted budget; right, exact T over interrupted T (dashed: the paper's \
             16x). {reps}"
        ),
    };
    let inacc_panel = |title: &str, y: String, est: Metric, truth: Metric| {
        let mut series = Vec::new();
        for (name, modes) in budgets.iter().filter(|(n, _)| n != "interrupt at 0") {
            series.push(over_n(
                gs,
                modes,
                rr,
                est,
                format!("{name}, estimate"),
                true,
            ));
            series.push(over_n(gs, modes, rr, truth, format!("{name}, true"), false));
        }
        panel(title.into(), y, series)
    };
    let smallest = cfg.ns.iter().copied().min().unwrap_or(0);
    let mut growth = panel(
        format!("True P over N = {smallest}'s (round-robin, paired by seed)"),
        "ratio of mean true P".into(),
        budgets
            .iter()
            .map(|(name, modes)| growth_over_n(gs, modes, rr, |r| r.true_p.mean(), name.clone()))
            .collect(),
    );
    growth.references = vec![(PAPER_GROWTH, "200x (paper)".into())];
    let fig5 = Figure {
        panels: vec![
            inacc_panel(
                "Geometric inaccuracy Δ (round-robin)",
                "mean Δ per frame (scene units)".into(),
                |r| r.delta.mean(),
                |r| r.true_delta.mean(),
            ),
            inacc_panel(
                "Perceived inaccuracy P (round-robin)",
                format!("mean P per frame ({pu})"),
                |r| r.p.mean(),
                |r| r.true_p.mean(),
            ),
            growth,
        ],
        caption: format!(
            "The paper's figure 5: inaccuracy of round-robin against N at each interrupted \
             budget; dashed the paper's estimate (the bound on each deemed pair's gap), solid the \
             audited truth. Open triangles on the floor: a mean of zero. Right: true P over its \
             value at N = {smallest} for the same seed number (dashed: the paper's 200x; a ratio \
             over a zero is drawn at the top). {reps}"
        ),
    };
    let mut out = vec![
        ("fig4_time".to_string(), fig4),
        ("fig5_inaccuracy".to_string(), fig5),
    ];
    let tp: Metric = |r| r.true_p.mean();
    let scheduler_figure = |title: &str, modes: &[(u32, Mode)]| {
        let absolute = panel(
            format!("True P per scheduler, {title}"),
            format!("mean true P per frame ({pu}, audit)"),
            cfg.schedulers
                .iter()
                .map(|&k| over_n(gs, modes, k, tp, k.name().into(), false))
                .collect(),
        );
        let pairs: Vec<(u32, Mode, Mode)> = modes.iter().map(|&(n, m)| (n, m, m)).collect();
        let mut ratio = panel(
            format!("True P / round-robin's, {title} (paired by seed)"),
            "ratio of mean true P".into(),
            cfg.schedulers
                .iter()
                .filter(|&&k| k != rr)
                .map(|&k| ratio_over_n(gs, &pairs, (k, rr), tp, k.name().into()))
                .collect(),
        );
        ratio.references = vec![
            (PAPER_P_RATIO, "halved (paper)".into()),
            (1.0, "round-robin".into()),
        ];
        Figure {
            panels: vec![absolute, ratio],
            caption: format!(
                "The paper's figure 6, {title}: audited true P per scheduler against N (left) \
                 and over round-robin's on the same seeds (right; dashed: the paper's halving). \
                 Closed loop: each scheduler's own physics. {reps}"
            ),
        }
    };
    for &f in &cfg.fractions {
        out.push((
            format!("fig6_schedulers_f{f}"),
            scheduler_figure(
                &format!("budget {f} of exact"),
                &at_every_n(cfg, Mode::Fraction(f)),
            ),
        ));
    }
    if !ms.is_empty() {
        out.push((
            "fig6_schedulers_ms".to_string(),
            scheduler_figure("the paper's target times (wall clock)", &ms),
        ));
    }
    out
}

/// True P against budget per scheduler, and its ratio to round-robin's, one figure per N.
pub fn curve_figures(cfg: &StudyConfig, gs: &[Group<'_>]) -> Vec<(String, Figure)> {
    let Some(c) = &cfg.curves else {
        return Vec::new();
    };
    let pu = p_unit(&cfg.model);
    let rr = SchedulerKind::RoundRobin;
    let tp: Metric = |r| r.true_p.mean();
    c.ns.iter()
        .map(|&n| {
            let x_label = "budget (fraction of the exact narrow-phase cost)".to_string();
            let series = |ratio: bool| -> Vec<Series> {
                cfg.schedulers
                    .iter()
                    .filter(|&&k| !ratio || k != rr)
                    .map(|&k| Series {
                        name: k.name().into(),
                        points: c
                            .fractions
                            .iter()
                            .filter_map(|&f| {
                                let g = find(gs, Part::Curves, n, Mode::Fraction(f), k)?;
                                let v = if ratio {
                                    let b = find(gs, Part::Curves, n, Mode::Fraction(f), rr)?;
                                    paired_ratio(g, b, tp).interval()
                                } else {
                                    g.boot(tp).interval()
                                };
                                Some((f, v))
                            })
                            .collect(),
                        dashed: false,
                    })
                    .collect()
            };
            let absolute = Panel {
                title: format!("True P against budget, N = {n}"),
                x_label: x_label.clone(),
                y_label: format!("mean true P per frame ({pu}, audit)"),
                log_x: true,
                log_y: true,
                series: series(false),
                references: Vec::new(),
            };
            let ratio = Panel {
                title: format!("True P / round-robin's, N = {n} (paired by seed)"),
                x_label,
                y_label: "ratio of mean true P".into(),
                log_x: true,
                log_y: true,
                series: series(true),
                references: vec![
                    (PAPER_P_RATIO, "halved".into()),
                    (1.0, "round-robin".into()),
                ],
            };
            (
                format!("curves_n{n}"),
                Figure {
                    panels: vec![absolute, ratio],
                    caption: format!(
                        "Budget sweep at N = {n}: audited true P per scheduler against the \
                         budget (left) and over round-robin's (right). Points: means over {} \
                         seeds x {} frames (closed loop); bars: 95% percentile-bootstrap \
                         intervals over seeds, ratios paired by seed.",
                        cfg.seeds.len(),
                        c.frames
                    ),
                },
            )
        })
        .collect()
}

/// The paper's F1 case ([`Part::F1`]): figure 5(b), Δ and P of sorted-sequential and round-robin
/// against N at each N's budget (estimate dashed, truth solid); and figure 6(a), sorted / round-
/// robin for Δ and P, where P below Δ is the paper's "decoupling".
pub fn f1_figures(cfg: &StudyConfig, gs: &[Group<'_>]) -> Vec<(String, Figure)> {
    let rr = SchedulerKind::RoundRobin;
    let sorted = SchedulerKind::SortedSequential;
    let modes: Vec<(u32, Mode)> = cfg
        .ns
        .iter()
        .filter_map(|&n| {
            let ms = cfg.f1_modes(n);
            let tenth = Mode::Fraction(StudyConfig::F1_FRACTION);
            ms.contains(&tenth)
                .then_some(tenth)
                .or_else(|| ms.first().copied())
                .map(|m| (n, m))
        })
        .collect();
    if modes.is_empty() {
        return Vec::new();
    }
    let pu = p_unit(&StudyConfig::f1());
    let both = |title: &str, y: String, est: Metric, truth: Metric| {
        let mut series = Vec::new();
        for k in [rr, sorted] {
            series.push(over_n_in(
                gs,
                Part::F1,
                &modes,
                k,
                est,
                format!("{}, estimate", k.name()),
                true,
            ));
            series.push(over_n_in(
                gs,
                Part::F1,
                &modes,
                k,
                truth,
                format!("{}, true", k.name()),
                false,
            ));
        }
        panel(title.into(), y, series)
    };
    let same: Vec<(u32, Mode, Mode)> = modes.iter().map(|&(n, m)| (n, m, m)).collect();
    let ratio =
        |name: &str, m: Metric| ratio_over_n_in(gs, Part::F1, &same, (sorted, rr), m, name.into());
    let mut ratios = panel(
        "Sorted-sequential / round-robin (paired by seed)".into(),
        "ratio of means".into(),
        vec![
            ratio("Δ, estimate", |r| r.delta.mean()),
            ratio("Δ, true", |r| r.true_delta.mean()),
            ratio("P, estimate", |r| r.p.mean()),
            ratio("P, true", |r| r.true_p.mean()),
        ],
    );
    ratios.references = vec![(1.0, "round-robin".into())];
    let reps = format!(
        "Points: means over {} seeds x {} frames (closed loop) at a budget of {} of the exact \
         cost; bars: 95% percentile-bootstrap intervals over seeds.",
        cfg.seeds.len(),
        cfg.frames,
        StudyConfig::F1_FRACTION
    );
    vec![(
        "fig5b_6a_f1_sorted".to_string(),
        Figure {
            panels: vec![
                both(
                    "Geometric inaccuracy Δ (F1 case)",
                    "mean Δ per frame (scene units)".into(),
                    |r| r.delta.mean(),
                    |r| r.true_delta.mean(),
                ),
                both(
                    "Perceived inaccuracy P, F1",
                    format!("mean P per frame ({pu})"),
                    |r| r.p.mean(),
                    |r| r.true_p.mean(),
                ),
                ratios,
            ],
            caption: format!(
                "The paper's figures 5(b) and 6(a): perceptually sorted sequential scheduling \
                 against round-robin, F1 to schedule and to measure; dashed the paper's estimate, \
                 solid the audited truth. Right: sorted over round-robin; P falling further than \
                 Δ is the paper's decoupling. {reps}"
            ),
        },
    )]
}
