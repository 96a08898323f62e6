//! # foveal-bench
//!
//! Re-runs the performance study of O'Sullivan, "A Model of Collision Perception for Real-Time
//! Animation", section 4, headless on the engine alone, and extends it: true error beside the
//! estimates (audit mode), budgets that transfer across machines (fractions of the exact cost), every
//! scheduler including our expected-gain one, several seeds with confidence intervals, and a budget
//! sweep. One call of [`run_study`] writes every table and figure of a study.
//!
//! # Layout
//! - [`protocol`]: the study's runs ([`StudyConfig`], [`Mode`], [`RunSpec`]); the paper's N and
//!   target times.
//! - [`open_loop`]: schedulers compared on identical frames against the clairvoyant bound.
//! - [`calibrate`]: regenerates the priced scheduler's table and reports its reliability.
//! - [`gaze`]: the seeded fixation/saccade script and the recorded-trace reader.
//! - [`runner`]: the `Instant` clock, one run, the plan, per-frame CSV records.
//! - [`stats`]: per-run mean/sd, mean and 95% CI across seeds.
//! - [`report`]: grouping, paired ratios, summary CSVs and markdown tables.
//! - [`plots`]: SVG and PNG figures.
//!
//! # Output directory
//! ```text
//! {table,curves}_runs.csv     one row per run (per-run means over frames)
//! {table,curves}_summary.csv  one row per condition: mean and 95% CI half-width across seeds
//! {table,curves}_report.md    tables and headline ratios
//! figures/*.svg|png           fig4_time, fig5_inaccuracy, fig6_schedulers_f<fraction>,
//!                             fig6_schedulers_ms, curves_n<N>
//! frames/*.csv                per-frame records of every run (unless disabled)
//! ```
//! The two parts write separate files, so they can be run separately into one directory.

pub mod calibrate;
pub mod gaze;
pub mod open_loop;
pub mod plots;
pub mod protocol;
pub mod report;
pub mod runner;
pub mod scale;
pub mod stats;
pub mod stress;

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use foveal_engine::{ConfigError, SchedulerKind};

pub use gaze::{GazeError, RecordedGaze, ScriptedGaze};
pub use protocol::{CurvesConfig, GazeSpec, Mode, Part, RunSpec, StudyConfig};
pub use runner::{InstantClock, RunSummary};

use plots::{Figure, Panel, Series};
use report::{Group, Metric, find, groups};

/// Everything that can stop a study.
#[derive(Debug, thiserror::Error)]
pub enum BenchError {
    /// The engine refused a configuration.
    #[error(transparent)]
    Config(#[from] ConfigError),
    /// The gaze trace could not be used.
    #[error(transparent)]
    Gaze(#[from] GazeError),
    /// A file could not be written.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// A figure could not be drawn.
    #[error("figure {path}: {msg}")]
    Plot {
        /// The file.
        path: PathBuf,
        /// What plotters said.
        msg: String,
    },
    /// The study configuration is unusable.
    #[error("invalid study: {0}")]
    Invalid(String),
}

impl BenchError {
    pub(crate) fn io(path: &Path, source: std::io::Error) -> Self {
        Self::Io {
            path: path.to_owned(),
            source,
        }
    }
}

/// What a study wrote.
#[derive(Debug, Clone, Default)]
pub struct StudyOutput {
    /// Every run's summary.
    pub runs: Vec<RunSummary>,
    /// Files written (CSV, markdown, figures; not the per-frame CSVs).
    pub files: Vec<PathBuf>,
    /// Whether figures carry text (a font was available).
    pub figures_with_text: bool,
    /// Wall time of the whole study (s).
    pub wall_s: f64,
}

impl StudyConfig {
    /// Refuse configurations that cannot produce a study.
    pub fn validate(&self) -> Result<(), BenchError> {
        let bad = |m: &str| Err(BenchError::Invalid(m.into()));
        if self.seeds.is_empty() {
            return bad("at least one seed is needed");
        }
        if self.schedulers.is_empty() {
            return bad("at least one scheduler is needed");
        }
        if self.table && (self.ns.is_empty() || self.frames == 0) {
            return bad("the table part needs at least one N and one frame");
        }
        if let Some(c) = &self.curves
            && (c.ns.is_empty() || c.frames == 0 || c.fractions.is_empty())
        {
            return bad("the curves part needs at least one N, one frame and one fraction");
        }
        if !self.table && self.curves.is_none() {
            return bad("nothing to run: neither the table nor the curves part");
        }
        let fractions = self
            .fractions
            .iter()
            .chain(self.curves.iter().flat_map(|c| c.fractions.iter()));
        for &f in fractions {
            if !(0.0..=1.0).contains(&f) {
                return Err(BenchError::Invalid(format!(
                    "fraction {f} is outside [0, 1]"
                )));
            }
        }
        if let Some(k) = self.paper_ms_scale
            && !(k.is_finite() && k > 0.0)
        {
            return bad("the paper-ms scale must be finite and > 0");
        }
        Ok(())
    }
}

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

fn write_part(
    cfg: &StudyConfig,
    part: Part,
    runs: &[RunSummary],
    out: &mut StudyOutput,
) -> Result<(), BenchError> {
    let runs: Vec<RunSummary> = runs
        .iter()
        .filter(|r| r.spec.part == part)
        .cloned()
        .collect();
    if runs.is_empty() {
        return Ok(());
    }
    let gs = groups(&runs);
    let name = part.name();
    let runs_csv = cfg.out.join(format!("{name}_runs.csv"));
    report::write_runs_csv(&runs_csv, &runs)?;
    let summary_csv = cfg.out.join(format!("{name}_summary.csv"));
    report::write_summary_csv(&summary_csv, &gs)?;
    let figs_dir = cfg.out.join("figures");
    std::fs::create_dir_all(&figs_dir).map_err(|e| BenchError::io(&figs_dir, e))?;
    let figures: Vec<(String, Figure)> = match part {
        Part::Table => table_figures(cfg, &gs),
        Part::Curves => curve_figures(cfg, &gs),
    };
    let mut fig_md = String::new();
    for (stem, fig) in &figures {
        let r = plots::render(fig, &figs_dir.join(stem))?;
        out.figures_with_text &= r.with_text;
        let _ = writeln!(fig_md, "![{stem}](figures/{stem}.svg)");
        out.files.push(r.svg);
        out.files.push(r.png);
    }
    let wall: f64 = runs.iter().map(|r| r.wall_s).sum();
    let mut md = format!(
        "# foveal-bench study: {name} part\n\nProtocol:\n\n{}- runs: {}; wall time of the runs {:.1} s\n\n",
        report::describe(cfg),
        runs.len(),
        wall
    );
    let mut part_cfg = cfg.clone();
    if part == Part::Table {
        part_cfg.curves = None;
    } else {
        part_cfg.table = false;
    }
    let _ = writeln!(md, "## Headlines\n\n{}", report::headlines(&part_cfg, &gs));
    md.push_str(&match part {
        Part::Table => report::table_markdown(cfg, &gs),
        Part::Curves => report::curves_markdown(cfg, &gs),
    });
    let _ = writeln!(md, "\n## Figures\n\n{fig_md}");
    let md_path = cfg.out.join(format!("{name}_report.md"));
    std::fs::write(&md_path, md).map_err(|e| BenchError::io(&md_path, e))?;
    out.files.extend([runs_csv, summary_csv, md_path]);
    Ok(())
}

/// Run the study of `cfg` and write its CSVs, reports and figures under `cfg.out`.
pub fn run_study(cfg: &StudyConfig) -> Result<StudyOutput, BenchError> {
    cfg.validate()?;
    let started = std::time::Instant::now();
    std::fs::create_dir_all(&cfg.out).map_err(|e| BenchError::io(&cfg.out, e))?;
    let plan = cfg.plan();
    let runs = runner::run_plan(cfg, &plan)?;
    let mut out = StudyOutput {
        figures_with_text: true,
        ..StudyOutput::default()
    };
    write_part(cfg, Part::Table, &runs, &mut out)?;
    write_part(cfg, Part::Curves, &runs, &mut out)?;
    out.runs = runs;
    out.wall_s = started.elapsed().as_secs_f64();
    Ok(out)
}
