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
//! - [`shard`]: a protocol's cells split over a cluster's workers, their partial results, and
//!   the merge that writes what one machine would have.
//! - [`shard_error`]: what can stop a sharded run or a merge, and a partial file's names.
//! - [`gaze`]: the seeded fixation/saccade script and the recorded-trace reader.
//! - [`runner`]: one run, the plan, per-frame CSV records; [`clock`]: the `Instant` clock.
//! - [`frames`]: exact frames of the paper scene and nothing else, the run a profiler wraps.
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
pub mod capacity;
pub mod claims;
pub mod clock;
pub mod contact;
pub mod endpoint;
pub mod error;
pub mod figures;
pub mod frames;
pub mod gaze;
pub mod open_loop;
pub mod plots;
pub mod protocol;
pub mod ratio;
pub mod report;
pub mod runner;
pub mod scale;
pub mod session;
pub mod shape_check;
pub mod shape_oracle;
pub mod shard;
pub mod shard_error;
pub mod staleness;
pub mod stamp;
pub mod stats;
pub mod stress;
pub mod trees;

use std::fmt::Write as _;
use std::path::PathBuf;

pub use clock::InstantClock;
pub use error::BenchError;
pub use gaze::{GazeError, RecordedGaze, ScriptedGaze};
pub use protocol::{CurvesConfig, GazeSpec, Mode, Part, RunSpec, StudyConfig};
pub use runner::RunSummary;
pub use shard::{CellSpec, Partial, Shard, ShardError};

use shard::{CellKind, ClosedRecord, Num, OpenRecord};

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
        Part::F1 => figures::f1_figures(cfg, &gs),
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
    if part != Part::F1 {
        let _ = writeln!(md, "## Headlines\n\n{}", report::headlines(&part_cfg, &gs));
    }
    md.push_str(&match part {
        Part::Table => report::table_markdown(cfg, &gs),
        Part::F1 => report::f1_markdown(cfg, &gs),
        Part::Curves => report::curves_markdown(cfg, &gs),
    });
    let _ = writeln!(
        md,
        "\n## Figures\n\n{fig_md}\nGenerated by {}.",
        stamp::current().line()
    );
    let md_path = cfg.out.join(format!("{name}_report.md"));
    std::fs::write(&md_path, md).map_err(|e| BenchError::io(&md_path, e))?;
    out.files.extend([runs_csv, summary_csv, md_path]);
    Ok(())
}

/// Run the study of `cfg` and write its CSVs, reports and figures under `cfg.out`: every cell on
/// this machine, through the same partial result and merge a sharded run takes, so one machine
/// and many write the same files.
pub fn run_study(cfg: &StudyConfig) -> Result<StudyOutput, BenchError> {
    let started = std::time::Instant::now();
    let partial = run_study_shard(cfg, Shard::WHOLE, serde_json::Value::Null)?;
    let mut out = merge_study(cfg, &[(cfg.out.join(Shard::WHOLE.file_name()), partial)])?;
    out.wall_s = started.elapsed().as_secs_f64();
    Ok(out)
}

impl StudyConfig {
    /// The open-loop parts as the study runs them, on one set of frames: the comparison, then the
    /// sensitivity grid (written under `out/grid`) with the comparison's N, seeds and frames.
    pub fn open_loop_parts(&self) -> Vec<open_loop::OpenLoopConfig> {
        let Some(ol) = &self.open_loop else {
            return Vec::new();
        };
        let ol = open_loop::OpenLoopConfig {
            out: self.out.clone(),
            jobs: self.jobs.max(1),
            truth: self.truth,
            ..ol.clone()
        };
        // The grid at its own N where the comparison runs them too (on the same frames).
        let grid = self.grid.as_ref().map(|g| open_loop::OpenLoopConfig {
            ns: ol.ns.iter().copied().filter(|n| g.ns.contains(n)).collect(),
            seeds: ol.seeds.clone(),
            frames: ol.frames.clone(),
            warmup: ol.warmup,
            timing_frames: ol.timing_frames,
            jobs: ol.jobs,
            truth: ol.truth,
            out: self.out.join("grid"),
            ..g.clone()
        });
        let mut parts = vec![ol];
        parts.extend(grid);
        parts
    }

    /// Every cell of the study, with its estimated cost: each closed-loop run of [`Self::plan`]
    /// (plan order), then each (N, seed) of the open-loop parts.
    pub fn cells(&self) -> Vec<CellSpec> {
        let mut cells: Vec<CellSpec> = self
            .plan()
            .iter()
            .enumerate()
            .map(|(i, spec)| CellSpec {
                id: spec.stem(),
                cost_s: shard::closed_loop_cost_s(self, spec),
                kind: shard::CellKind::ClosedLoop(i),
                group: None,
                serial: spec.part.is_timed() || self.jobs <= 1,
            })
            .collect();
        let parts = self.open_loop_parts();
        let refs: Vec<&open_loop::OpenLoopConfig> = parts.iter().collect();
        cells.extend(shard::open_loop_cells(&refs));
        cells
    }

    /// Hash of every setting that changes a result (not the output directory, threads, progress
    /// or per-frame files): shards of one study must agree on it.
    pub fn protocol_hash(&self) -> String {
        let mut c = self.clone();
        c.out = PathBuf::new();
        c.jobs = 1;
        c.frame_csv = false;
        c.progress = false;
        for p in c.open_loop.iter_mut().chain(c.grid.iter_mut()) {
            p.out = PathBuf::new();
            p.jobs = 1;
        }
        shard::fnv64(format!("{c:?}").as_bytes())
    }
}

/// Hash of every setting of a standalone open-loop run that changes a result (not its output
/// directory or threads).
pub fn open_loop_protocol_hash(cfg: &open_loop::OpenLoopConfig) -> String {
    let mut c = cfg.clone();
    c.out = PathBuf::new();
    c.jobs = 1;
    shard::fnv64(format!("{c:?}").as_bytes())
}

/// The open-loop cells of one (N, seed) in a shard: (cell, part, condition).
type Group<'c> = Vec<(&'c CellSpec, usize, usize)>;

/// Run one (N, seed)'s cells of a shard on one thread: each part cut to the group's conditions
/// (parts without one left out), all on the scene's frames.
fn run_open_group(
    parts: &[&open_loop::OpenLoopConfig],
    n: u32,
    seed: u64,
    group: &Group<'_>,
) -> Result<Vec<OpenRecord>, BenchError> {
    let mut subs: Vec<(open_loop::OpenLoopConfig, Vec<&CellSpec>)> = Vec::new();
    for (pi, p) in parts.iter().enumerate() {
        let picked: Vec<&(&CellSpec, usize, usize)> =
            group.iter().filter(|(_, part, _)| *part == pi).collect();
        if picked.is_empty() {
            continue;
        }
        let sub = open_loop::OpenLoopConfig {
            conditions: picked
                .iter()
                .filter_map(|(_, _, ci)| p.conditions.get(*ci).cloned())
                .collect(),
            jobs: 1,
            ..(*p).clone()
        };
        subs.push((sub, picked.iter().map(|(c, _, _)| *c).collect()));
    }
    let refs: Vec<&open_loop::OpenLoopConfig> = subs.iter().map(|(s, _)| s).collect();
    let (results, walls) = open_loop::run_parts_timed_on(&refs, &[(n, seed)])?;
    let wall_s = walls.first().copied().unwrap_or(f64::NAN);
    let mut out = Vec::new();
    for ((sub, specs), per_part) in subs.iter().zip(&results) {
        let Some(r) = per_part.first() else {
            continue;
        };
        for (ci, (c, cond)) in specs.iter().zip(&sub.conditions).enumerate() {
            let mut rec = OpenRecord::of(&c.id, &cond.name, r, ci);
            rec.wall_s = Num(wall_s);
            rec.run_cells = group.len() as u32;
            out.push(rec);
        }
    }
    Ok(out)
}

/// What a shard ran: its cells' names, and the records of its closed- and open-loop cells.
type ShardRecords = (Vec<String>, Vec<ClosedRecord>, Vec<OpenRecord>);

/// Run the cells of `cells` that [`shard::assign`] gives `shard`: closed-loop runs of `study`'s
/// plan, and open-loop cells of `parts`, those of one (N, seed) together on its frames.
fn run_cells(
    study: Option<&StudyConfig>,
    parts: &[&open_loop::OpenLoopConfig],
    cells: &[CellSpec],
    shard: Shard,
) -> Result<ShardRecords, BenchError> {
    shard::check_unique(cells)?;
    let owner = shard::assign(cells, shard.count);
    let mine: Vec<&CellSpec> = cells
        .iter()
        .zip(&owner)
        .filter(|(_, s)| **s == shard.index)
        .map(|(c, _)| c)
        .collect();
    let mut closed = Vec::new();
    if let Some(cfg) = study {
        let plan = cfg.plan();
        let picked: Vec<(&CellSpec, RunSpec)> = mine
            .iter()
            .filter_map(|c| match c.kind {
                CellKind::ClosedLoop(i) => plan.get(i).map(|s| (*c, s.clone())),
                CellKind::OpenLoop { .. } => None,
            })
            .collect();
        let specs: Vec<RunSpec> = picked.iter().map(|(_, s)| s.clone()).collect();
        if !specs.is_empty() {
            std::fs::create_dir_all(&cfg.out).map_err(|e| BenchError::io(&cfg.out, e))?;
        }
        let runs = runner::run_plan(cfg, &specs)?;
        closed = picked
            .iter()
            .zip(&runs)
            .map(|((c, _), r)| ClosedRecord::of(&c.id, r))
            .collect();
    }
    // The shard's open-loop cells by (N, seed), in order: each group runs its conditions, and
    // only those, on the scene's frames.
    let mut groups: Vec<((u32, u64), Group<'_>)> = Vec::new();
    for c in &mine {
        if let CellKind::OpenLoop {
            n,
            seed,
            part,
            condition,
        } = c.kind
        {
            match groups.iter_mut().find(|(k, _)| *k == (n, seed)) {
                Some((_, v)) => v.push((c, part, condition)),
                None => groups.push(((n, seed), vec![(c, part, condition)])),
            }
        }
    }
    // The groups on the parts' `jobs` threads, the costliest first (as the open loop orders its
    // runs), each group's cells in its records; the records come back in the shard's order.
    let jobs = parts.first().map_or(1, |p| p.jobs.max(1));
    let cost = |g: &Group<'_>| g.iter().map(|(c, _, _)| c.cost_s).sum::<f64>();
    let mut order: Vec<usize> = (0..groups.len()).collect();
    order.sort_by(|&a, &b| cost(&groups[b].1).total_cmp(&cost(&groups[a].1)));
    let next = std::sync::atomic::AtomicUsize::new(0);
    type Done = (usize, Result<Vec<OpenRecord>, BenchError>);
    let done: std::sync::Mutex<Vec<Done>> = std::sync::Mutex::new(Vec::new());
    std::thread::scope(|scope| {
        for _ in 0..jobs.min(groups.len()) {
            scope.spawn(|| {
                while let Some(&g) =
                    order.get(next.fetch_add(1, std::sync::atomic::Ordering::Relaxed))
                {
                    let ((n, seed), group) = &groups[g];
                    let r = run_open_group(parts, *n, *seed, group);
                    if let Ok(mut v) = done.lock() {
                        v.push((g, r));
                    }
                }
            });
        }
    });
    let mut done = done
        .into_inner()
        .map_err(|_| BenchError::Invalid("a worker thread panicked".into()))?;
    done.sort_by_key(|(g, _)| *g);
    let mut open = Vec::new();
    for (_, r) in done {
        open.extend(r?);
    }
    Ok((mine.iter().map(|c| c.id.clone()).collect(), closed, open))
}

/// Run `shard`'s share of the study's cells and return its partial result; `protocol` is what the
/// caller records to rebuild the protocol at merge (the binary's protocol flags).
pub fn run_study_shard(
    cfg: &StudyConfig,
    shard: Shard,
    protocol: serde_json::Value,
) -> Result<Partial, BenchError> {
    cfg.validate()?;
    let parts = cfg.open_loop_parts();
    let refs: Vec<&open_loop::OpenLoopConfig> = parts.iter().collect();
    timed_partial("study", protocol, cfg.protocol_hash(), shard, || {
        run_cells(Some(cfg), &refs, &cfg.cells(), shard)
    })
}

/// Run `shard`'s share of a standalone open-loop comparison (`open-loop --shard`).
pub fn run_open_loop_shard(
    cfg: &open_loop::OpenLoopConfig,
    shard: Shard,
    protocol: serde_json::Value,
) -> Result<Partial, BenchError> {
    let parts = [cfg];
    timed_partial(
        "open-loop",
        protocol,
        open_loop_protocol_hash(cfg),
        shard,
        || run_cells(None, &parts, &shard::open_loop_cells(&parts), shard),
    )
}

/// The partial of `command`'s shard `shard`: `run` timed, with the load average before and
/// after it.
fn timed_partial(
    command: &str,
    protocol: serde_json::Value,
    protocol_hash: String,
    shard: Shard,
    run: impl FnOnce() -> Result<ShardRecords, BenchError>,
) -> Result<Partial, BenchError> {
    let load_start = open_loop::load_average();
    let started = std::time::Instant::now();
    let (cells, closed_loop, open_loop) = run()?;
    Ok(Partial {
        format: shard::PARTIAL_FORMAT.into(),
        command: command.into(),
        protocol,
        protocol_hash,
        engine_hash: shard::ENGINE_SOURCE_HASH.into(),
        shard,
        cells,
        closed_loop,
        open_loop,
        load_start,
        load_end: open_loop::load_average(),
        wall_s: Num(started.elapsed().as_secs_f64()),
    })
}

/// Merge the partials of a study (of one command, protocol and engine: [`shard::check_same_run`])
/// and write every table, CSV, report and figure under `cfg.out`, as one machine's run does.
pub fn merge_study(
    cfg: &StudyConfig,
    partials: &[(PathBuf, Partial)],
) -> Result<StudyOutput, BenchError> {
    cfg.validate()?;
    let parts = cfg.open_loop_parts();
    let refs: Vec<&open_loop::OpenLoopConfig> = parts.iter().collect();
    let cells = cfg.cells();
    shard::check_unique(&cells)?;
    let merged = shard::merge(&cells, &cfg.plan(), &refs, &cfg.protocol_hash(), partials)?;
    std::fs::create_dir_all(&cfg.out).map_err(|e| BenchError::io(&cfg.out, e))?;
    let mut out = StudyOutput {
        figures_with_text: true,
        ..StudyOutput::default()
    };
    write_part(cfg, Part::Table, &merged.closed_loop, &mut out)?;
    write_part(cfg, Part::F1, &merged.closed_loop, &mut out)?;
    write_part(cfg, Part::Curves, &merged.closed_loop, &mut out)?;
    if !refs.is_empty() {
        let written = open_loop::write_parts(&refs, &merged.open_loop, &merged.stamp)?;
        for w in &written {
            out.files.extend(w.files.iter().cloned());
        }
        let mut reports = written.into_iter().map(|w| w.report);
        out.open_loop_report = reports.next();
        out.grid_report = reports.next();
    }
    out.runs = merged.closed_loop;
    out.wall_s = merged.stamp.wall_s;
    Ok(out)
}

/// Merge the partials of a standalone open-loop run and write its files under `cfg.out`.
pub fn merge_open_loop(
    cfg: &open_loop::OpenLoopConfig,
    partials: &[(PathBuf, Partial)],
) -> Result<open_loop::OpenLoopOutput, BenchError> {
    let parts = [cfg];
    let cells = shard::open_loop_cells(&parts);
    shard::check_unique(&cells)?;
    let merged = shard::merge(&cells, &[], &parts, &open_loop_protocol_hash(cfg), partials)?;
    let mut v = open_loop::write_parts(&parts, &merged.open_loop, &merged.stamp)?;
    v.pop()
        .ok_or_else(|| BenchError::Invalid("the open-loop comparison wrote nothing".into()))
}
