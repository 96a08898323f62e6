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
//! - [`session`]: a recorded server session replayed bit for bit, then open loop under every
//!   scheduler.
//! - [`calibrate`]: regenerates the priced scheduler's table and reports its reliability.
//! - [`contact`]: first contacts under each truth, the gap between the drawn stars measured.
//! - [`shape_check`]: every candidate pair of whole exact scenes, the engine's shape answer and
//!   gap against the independent judge.
//! - [`shape_oracle`]: an independent judge of whether two stars touch, and of their distance, by
//!   branch and bound over patches of their surfaces (shared with the engine's tests by path).
//! - [`gaze`]: the seeded fixation/saccade script and the recorded-trace reader.
//! - [`runner`]: the `Instant` clock, one run, the plan, per-frame CSV records.
//! - [`stats`]: per-run mean/sd, mean and 95% CI across seeds.
//! - [`error`]: [`BenchError`], what can stop a bench command.
//! - [`report`]: grouping, paired ratios, summary CSVs and markdown tables.
//! - [`figures`]: the study's figures from the grouped runs.
//! - [`plots`]: SVG and PNG rendering.
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
pub mod contact;
pub mod error;
pub mod figures;
pub mod gaze;
pub mod open_loop;
pub mod plots;
pub mod protocol;
pub mod report;
pub mod runner;
pub mod scale;
pub mod session;
pub mod shape_check;
pub mod shape_oracle;
pub mod stats;
pub mod stress;

use std::fmt::Write as _;
use std::path::PathBuf;

pub use error::BenchError;
pub use gaze::{GazeError, RecordedGaze, ScriptedGaze};
pub use protocol::{CurvesConfig, GazeSpec, Mode, Part, RunSpec, StudyConfig};
pub use runner::{InstantClock, RunSummary};

use figures::{curve_figures, table_figures};
use plots::Figure;
use report::groups;

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
    /// The open-loop report (markdown, with the `clairvoyant` rows), if that part ran.
    pub open_loop_report: Option<String>,
    /// The sensitivity grid's report (markdown), if that part ran.
    pub grid_report: Option<String>,
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
        if !self.table && self.curves.is_none() && self.open_loop.is_none() {
            return bad("nothing to run: neither the table, the curves nor the open-loop part");
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
        "# foveal-bench study: {name} part (closed loop)\n\nEach scheduler runs its own \
         simulation, whose deemed pairs respond as if they collided, so the runs show what a \
         viewer sees over time and differ in their physics: compare schedulers in \
         `open_loop_report.md` (identical frames, with the clairvoyant bound).\n\nProtocol:\n\n\
         - truth: `{}` (what \"colliding\" means)\n{}- runs: {}; wall time of the runs {:.1} s\n\n",
        cfg.truth,
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
    if let Some(ol) = &cfg.open_loop {
        let ol = open_loop::OpenLoopConfig {
            out: cfg.out.clone(),
            jobs: cfg.jobs.max(1),
            truth: cfg.truth,
            ..ol.clone()
        };
        // The grid runs on the open-loop part's frames: one exact run, one set of truths.
        let grid = cfg.grid.as_ref().map(|g| open_loop::OpenLoopConfig {
            ns: ol.ns.clone(),
            seeds: ol.seeds.clone(),
            frames: ol.frames.clone(),
            warmup: ol.warmup,
            timing_frames: ol.timing_frames,
            jobs: ol.jobs,
            truth: ol.truth,
            out: cfg.out.join("grid"),
            ..g.clone()
        });
        let mut parts = vec![&ol];
        parts.extend(grid.as_ref());
        let written = open_loop::run_and_write_parts(&parts)?;
        for w in &written {
            out.files.extend(w.files.iter().cloned());
        }
        let mut reports = written.into_iter().map(|w| w.report);
        out.open_loop_report = reports.next();
        out.grid_report = reports.next();
    }
    out.runs = runs;
    out.wall_s = started.elapsed().as_secs_f64();
    Ok(out)
}
