//! The study protocol (paper section 4, extended): which scenes, budgets, schedulers and seeds are
//! run, and for how many frames.
//!
//! Two parts:
//! - **table** (figures 4, 5 and 6 of the paper): for every N and seed, the exact base case, the
//!   interrupt-at-0 case, and every scheduler at the interrupted budgets (a fraction of the exact
//!   narrow-phase cost for that N; the paper's own target times scaled to this machine; optional
//!   fixed sphere-test budgets);
//! - **f1** (figures 5(b) and 6(a)): the paper's F1 case as it specifies it, perceptually sorted
//!   sequential scheduling against round-robin with F1 (in pixels) both to schedule and to
//!   measure, at the paper's target times, with the interrupt-at-0 case for scale;
//! - **curves** (beyond the paper): true perceived inaccuracy against budget, per scheduler, at a few
//!   N, to see whether the expected-gain scheduler beats the paper's best at equal budget.
//!
//! Both parts are *closed loop*: each scheduler simulates its own physics (deemed pairs respond
//! as if they collided), so they show what a viewer sees over time, not a comparison of
//! schedulers. Schedulers are compared **open loop** ([`crate::open_loop`], on by default): every
//! scheduler and budget on the identical frames of one exact run, against the clairvoyant bound.

use std::path::PathBuf;

use crate::open_loop::{Budget, OpenLoopConfig};

use foveal_engine::{
    BudgetSpec, EccentricityUnit, PerceptualFunction, PerceptualModel, SceneConfig, SchedulerKind,
    SimConfig, Truth,
};

/// The paper's body counts (section 4).
pub const PAPER_NS: [u32; 5] = [10, 30, 100, 300, 500];
/// The paper's target times (ms, 233 MHz Pentium) for [`PAPER_NS`]: "5, 20, 44, 30 and 10
/// milliseconds respectively" (section 4).
pub const PAPER_TARGET_MS: [f64; 5] = [5.0, 20.0, 44.0, 30.0, 10.0];

/// The paper's target time for `n` bodies, if the paper ran that N.
pub fn paper_target_ms(n: u32) -> Option<f64> {
    PAPER_NS
        .iter()
        .position(|&m| m == n)
        .map(|i| PAPER_TARGET_MS[i])
}

/// When a run interrupts its narrow phase.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Mode {
    /// No interruption (the paper's base case).
    Exact,
    /// Interrupt before the first sphere test (the paper's "interrupting at 0").
    Zero,
    /// Wall-clock target for collision handling, milliseconds (the paper's X).
    WallMs(f64),
    /// At most this many sphere tests per frame (deterministic).
    Tests(u64),
    /// A fraction of the mean exact narrow-phase cost (sphere tests per frame) measured for this N
    /// and seed; run as the equivalent deterministic sphere-test budget.
    Fraction(f64),
}

impl Mode {
    /// Short kind: `exact`, `zero`, `ms`, `tests`, `fraction`.
    pub fn kind(&self) -> &'static str {
        match self {
            Self::Exact => "exact",
            Self::Zero => "zero",
            Self::WallMs(_) => "ms",
            Self::Tests(_) => "tests",
            Self::Fraction(_) => "fraction",
        }
    }

    /// The mode's parameter (0 for exact and zero).
    pub fn param(&self) -> f64 {
        match *self {
            Self::Exact | Self::Zero => 0.0,
            Self::WallMs(ms) => ms,
            Self::Tests(t) => t as f64,
            Self::Fraction(f) => f,
        }
    }

    /// Label used in file names and tables, e.g. `fraction=0.1`.
    pub fn label(&self) -> String {
        match self {
            Self::Exact | Self::Zero => self.kind().into(),
            _ => format!("{}={}", self.kind(), self.param()),
        }
    }

    /// The engine budget, given the measured exact cost (sphere tests per frame).
    pub fn budget(&self, exact_cost: f64) -> BudgetSpec {
        match *self {
            Self::Exact => BudgetSpec::Exact,
            Self::Zero => BudgetSpec::InterruptAtZero,
            Self::WallMs(ms) => BudgetSpec::WallMs(ms),
            Self::Tests(t) => BudgetSpec::SphereTests(t),
            Self::Fraction(f) => BudgetSpec::SphereTests((f * exact_cost).round() as u64),
        }
    }

    /// Whether the budget is wall-clock (results then depend on the machine and its load).
    pub fn is_wall_clock(&self) -> bool {
        matches!(self, Self::WallMs(_))
    }
}

/// Which part of the study a run belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Part {
    /// Figures 4-6 of the paper.
    Table,
    /// The paper's F1 case: sorted-sequential against round-robin, F1 to schedule and measure
    /// (figures 5(b) and 6(a)).
    F1,
    /// Budget sweep (ours).
    Curves,
}

impl Part {
    /// `table`, `f1` or `curves`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Table => "table",
            Self::F1 => "f1",
            Self::Curves => "curves",
        }
    }

    /// Whether the part's runs are timed closed-loop runs of the paper's table (run one at a
    /// time, so T is not disturbed).
    pub fn is_timed(self) -> bool {
        matches!(self, Self::Table | Self::F1)
    }
}

/// One run: a scene, a budget, a scheduler, a seed, a number of frames.
#[derive(Debug, Clone, PartialEq)]
pub struct RunSpec {
    /// Part of the study.
    pub part: Part,
    /// Bodies.
    pub n: u32,
    /// Scene and gaze seed.
    pub seed: u64,
    /// Budget.
    pub mode: Mode,
    /// Scheduler.
    pub scheduler: SchedulerKind,
    /// Frames.
    pub frames: u32,
}

impl RunSpec {
    /// File-name stem of the run's per-frame CSV.
    pub fn stem(&self) -> String {
        format!(
            "{}_n{}_s{}_{}_{}",
            self.part.name(),
            self.n,
            self.seed,
            self.mode.label().replace('=', "-"),
            self.scheduler.name()
        )
    }
}

/// Where gaze comes from.
#[derive(Debug, Clone, PartialEq)]
pub enum GazeSpec {
    /// The seeded fixation/saccade script (seed = run seed).
    Scripted,
    /// A recorded `t_s,xpos,ypos,ps` CSV (1920x1080 px), replayed in a loop.
    Csv(PathBuf),
}

/// The budget sweep (ours).
#[derive(Debug, Clone, PartialEq)]
pub struct CurvesConfig {
    /// Body counts.
    pub ns: Vec<u32>,
    /// Frames per run.
    pub frames: u32,
    /// Budgets as fractions of the exact narrow-phase cost.
    pub fractions: Vec<f64>,
}

impl Default for CurvesConfig {
    fn default() -> Self {
        Self {
            ns: vec![500, 10_000],
            frames: 500,
            fractions: vec![0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5],
        }
    }
}

/// Everything a study run needs.
#[derive(Debug, Clone, PartialEq)]
pub struct StudyConfig {
    /// Run the table part (figures 4-6).
    pub table: bool,
    /// Body counts of the table part.
    pub ns: Vec<u32>,
    /// Frames per table run (paper: 5,000).
    pub frames: u32,
    /// Seeds (scene and gaze); the CI is across them.
    pub seeds: Vec<u64>,
    /// Schedulers run at every interrupted budget.
    pub schedulers: Vec<SchedulerKind>,
    /// Interrupted budgets of the table as fractions of exact cost.
    pub fractions: Vec<f64>,
    /// Divide the paper's target times by this machine factor for a wall-clock mode (None: skip).
    pub paper_ms_scale: Option<f64>,
    /// Fixed sphere-test budgets of the table.
    pub tests_budgets: Vec<u64>,
    /// Run the paper's F1 case ([`Part::F1`]) at the table's N and seeds.
    pub f1: bool,
    /// The budget sweep, if requested.
    pub curves: Option<CurvesConfig>,
    /// The open-loop comparison of schedulers, if run (written into [`Self::out`]).
    pub open_loop: Option<OpenLoopConfig>,
    /// The sensitivity grid ([`OpenLoopConfig::grid`]), run with the open-loop part on the same
    /// frames (its N, seeds and frames are the open-loop part's) and written under `out/grid`.
    pub grid: Option<OpenLoopConfig>,
    /// Gaze source.
    pub gaze: GazeSpec,
    /// Perceptual model used both to schedule and to measure (paper figure 6(b): F2).
    pub model: PerceptualModel,
    /// Priority-queue eccentricity threshold (degrees).
    pub threshold_deg: f64,
    /// Frames of exact narrow phase used to measure the exact cost per (N, seed), after warm-up.
    pub calibration_frames: u32,
    /// Frames stepped before recording (and before calibrating): the random initial placement
    /// interpenetrates bodies, so the first ~60 frames cost 1.5-3x the steady state.
    pub warmup_frames: u32,
    /// Worker threads for the curves part (its budgets are in sphere tests, so its results do not
    /// depend on timing). The table part always runs on one thread, so T is not disturbed.
    pub jobs: usize,
    /// Output directory.
    pub out: PathBuf,
    /// Write one CSV of per-frame records per run.
    pub frame_csv: bool,
    /// Show a progress bar (only drawn when stderr is a terminal).
    pub progress: bool,
    /// What "colliding" means in every run, the open-loop parts included (`SceneConfig::truth`).
    pub truth: Truth,
}

impl Default for StudyConfig {
    /// The default protocol: paper N, 1,000 frames, the 5 evaluation seeds, every scheduler, budgets at
    /// 1/100 and 1/10 of exact cost and at the paper's times / 100; curves off.
    fn default() -> Self {
        Self {
            table: true,
            ns: PAPER_NS.to_vec(),
            // The paper recorded 5,000 frames a run; 1,000 keep the default study within 40
            // minutes on 2 cores under the shape truth (`--frames 5000` runs the paper's).
            frames: 1_000,
            seeds: crate::open_loop::EVALUATION_SEEDS.to_vec(),
            schedulers: SchedulerKind::ALL.to_vec(),
            fractions: vec![0.01, 0.1],
            paper_ms_scale: Some(100.0),
            tests_budgets: Vec::new(),
            f1: true,
            curves: None,
            open_loop: Some(OpenLoopConfig::standard()),
            grid: Some(OpenLoopConfig::grid()),
            gaze: GazeSpec::Scripted,
            model: PerceptualModel::default(),
            threshold_deg: 5.0,
            calibration_frames: 60,
            warmup_frames: 60,
            jobs: 1,
            out: PathBuf::from("target/foveal-bench/study"),
            frame_csv: true,
            progress: true,
            truth: Truth::default(),
        }
    }
}

impl StudyConfig {
    /// The `--quick` preset: every part of the protocol (all N of the paper, every mode and
    /// scheduler, the budget sweep), small enough to finish in under a minute in release.
    pub fn quick() -> Self {
        Self {
            frames: 50,
            seeds: crate::open_loop::evaluation_seeds(3),
            fractions: vec![0.1],
            tests_budgets: vec![2_000],
            curves: Some(CurvesConfig {
                ns: vec![300],
                frames: 30,
                fractions: vec![0.01, 0.1, 0.5],
            }),
            open_loop: Some(OpenLoopConfig::quick()),
            grid: Some(OpenLoopConfig::grid()),
            calibration_frames: 20,
            warmup_frames: 20,
            jobs: 2,
            out: PathBuf::from("target/foveal-bench/quick"),
            ..Self::default()
        }
    }

    /// The `--tiny` preset: every part and output of the protocol at N = 10 and 30 (curves at 30,
    /// the open loop and its grid at N = 150), 2 seeds of a few frames, every mode and scheduler:
    /// about a second in a test build. CI runs it whole and sharded and compares the two.
    pub fn tiny() -> Self {
        let mut ol = OpenLoopConfig::quick();
        ol.ns = vec![150];
        ol.seeds = vec![1, 2];
        ol.frames = vec![(150, 4)];
        ol.warmup = 5;
        ol.timing_frames = 2;
        ol.budgets = vec![Budget::Tests(0.05), Budget::Tests(0.3)];
        ol.conditions.truncate(1);
        let mut grid = OpenLoopConfig::grid();
        grid.ns = vec![150];
        grid.budgets = vec![Budget::Tests(0.3)];
        grid.conditions.truncate(2);
        Self {
            ns: vec![10, 30],
            frames: 6,
            seeds: vec![1, 2],
            fractions: vec![0.1],
            tests_budgets: vec![200],
            curves: Some(CurvesConfig {
                ns: vec![30],
                frames: 4,
                fractions: vec![0.05, 0.5],
            }),
            open_loop: Some(ol),
            grid: Some(grid),
            calibration_frames: 3,
            warmup_frames: 2,
            jobs: 2,
            out: PathBuf::from("target/foveal-bench/tiny"),
            ..Self::default()
        }
    }

    /// The paper's F1 in pixels, the other model the paper uses (figures 5(b), 6(a)).
    pub fn f1() -> PerceptualModel {
        PerceptualModel {
            function: PerceptualFunction::F1,
            unit: EccentricityUnit::Pixels,
        }
    }

    /// The budget the F1 case's figure and claim read: a tenth of the exact cost, about the
    /// paper's 10 ms at N = 500 against its base case (about 1/16). The scaled target time itself
    /// (0.1 ms at N = 500) ends before the narrow phase on this machine in a pilot run, so every
    /// pair is deemed under either scheduler there.
    pub const F1_FRACTION: f64 = 0.1;

    /// The schedulers of the paper's F1 case: round-robin and perceptually sorted sequential.
    pub const F1_SCHEDULERS: [SchedulerKind; 2] =
        [SchedulerKind::RoundRobin, SchedulerKind::SortedSequential];

    /// The budgets of the F1 case at `n`: the table's fractions of the exact cost and the
    /// paper's target time (scaled), not its fixed sphere-test budgets.
    pub fn f1_modes(&self, n: u32) -> Vec<Mode> {
        self.table_modes(n)
            .into_iter()
            .filter(|m| !matches!(m, Mode::Tests(_)))
            .collect()
    }

    /// The perceptual model a run schedules and measures with: F1 in the F1 case, else the
    /// protocol's.
    pub fn model_of(&self, part: Part) -> PerceptualModel {
        if part == Part::F1 {
            Self::f1()
        } else {
            self.model
        }
    }

    /// Engine config for one run.
    pub fn sim_config(&self, spec: &RunSpec, exact_cost: f64) -> SimConfig {
        SimConfig {
            scene: SceneConfig {
                truth: self.truth,
                ..SceneConfig::paper(spec.n, spec.seed)
            },
            budget: spec.mode.budget(exact_cost),
            scheduler: spec.scheduler,
            eccentricity_threshold_deg: self.threshold_deg,
            schedule_model: self.model_of(spec.part),
            measure_model: self.model_of(spec.part),
            audit: true,
            calibration_frames: self.calibration_frames,
            ..SimConfig::default()
        }
    }

    /// Interrupted modes of the table part for `n`.
    pub fn table_modes(&self, n: u32) -> Vec<Mode> {
        let mut modes: Vec<Mode> = self.fractions.iter().map(|&f| Mode::Fraction(f)).collect();
        if let (Some(scale), Some(ms)) = (self.paper_ms_scale, paper_target_ms(n)) {
            modes.push(Mode::WallMs(ms / scale));
        }
        modes.extend(self.tests_budgets.iter().map(|&t| Mode::Tests(t)));
        modes
    }

    /// Every run of the study, grouped by (part, N, seed) in execution order.
    pub fn plan(&self) -> Vec<RunSpec> {
        let mut out = Vec::new();
        let base = |part, n, seed, mode, scheduler, frames| RunSpec {
            part,
            n,
            seed,
            mode,
            scheduler,
            frames,
        };
        if self.table {
            for &n in &self.ns {
                for &seed in &self.seeds {
                    let f = self.frames;
                    out.push(base(
                        Part::Table,
                        n,
                        seed,
                        Mode::Exact,
                        SchedulerKind::RoundRobin,
                        f,
                    ));
                    out.push(base(
                        Part::Table,
                        n,
                        seed,
                        Mode::Zero,
                        SchedulerKind::RoundRobin,
                        f,
                    ));
                    for mode in self.table_modes(n) {
                        for &s in &self.schedulers {
                            out.push(base(Part::Table, n, seed, mode, s, f));
                        }
                    }
                }
            }
        }
        if self.f1 {
            for &n in &self.ns {
                for &seed in &self.seeds {
                    let f = self.frames;
                    out.push(base(
                        Part::F1,
                        n,
                        seed,
                        Mode::Zero,
                        SchedulerKind::RoundRobin,
                        f,
                    ));
                    for mode in self.f1_modes(n) {
                        for s in Self::F1_SCHEDULERS {
                            out.push(base(Part::F1, n, seed, mode, s, f));
                        }
                    }
                }
            }
        }
        if let Some(c) = &self.curves {
            for &n in &c.ns {
                for &seed in &self.seeds {
                    for &fr in &c.fractions {
                        for &s in &self.schedulers {
                            out.push(base(Part::Curves, n, seed, Mode::Fraction(fr), s, c.frames));
                        }
                    }
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The F1 case runs round-robin and sorted-sequential at each N's fractions of the exact
    /// cost and its target time, with the interrupt-at-0 case, scheduling and measuring with F1
    /// while the table keeps its model.
    #[test]
    fn the_f1_case_schedules_and_measures_with_f1() {
        let cfg = StudyConfig::tiny();
        let f1: Vec<RunSpec> = cfg
            .plan()
            .into_iter()
            .filter(|r| r.part == Part::F1)
            .collect();
        // Zero, then 2 schedulers at the fraction and the target time (not the tests budget).
        assert_eq!(f1.len(), cfg.ns.len() * cfg.seeds.len() * 5);
        for r in &f1 {
            assert!(!matches!(r.mode, Mode::Tests(_) | Mode::Exact), "{r:?}");
            let sim = cfg.sim_config(r, 100.0);
            assert_eq!(sim.schedule_model, StudyConfig::f1());
            assert_eq!(sim.measure_model, StudyConfig::f1());
        }
        assert!(
            f1.iter()
                .any(|r| r.scheduler == SchedulerKind::SortedSequential)
        );
        let table = cfg
            .plan()
            .into_iter()
            .find(|r| r.part == Part::Table)
            .expect("table runs");
        assert_eq!(cfg.sim_config(&table, 100.0).measure_model, cfg.model);
        assert_eq!(
            cfg.f1_modes(10),
            vec![Mode::Fraction(0.1), Mode::WallMs(0.05)]
        );
    }
}
