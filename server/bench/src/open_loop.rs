//! Open-loop comparison of schedulers (docs/DESIGN.md "Open-loop protocol"): one exact run of the
//! paper scene gives the frames, and every scheduler and budget is evaluated on exactly those
//! frames, each against the clairvoyant bound of that frame.
//!
//! Per frame of the exact run, every candidate pair is settled once to learn its truth (collides or
//! not, its true gap, its exact cost). A scheduler's true P is then the sum of the true weights of
//! the pairs it deemed, which is what the audit computes, without re-running the audit per
//! scheduler. The bound at a budget is the fractional-knapsack optimum over the same truths
//! ([`foveal_engine::clairvoyant`]), taken at what the budget buys: its sphere tests, or under a
//! wall-clock budget the tests the exact kernel does in that time at its rate measured in the same
//! run; and at least at the most tests any scheduler of that budget used (the last step may overrun
//! a sphere-test budget).
//!
//! Budgets are in sphere tests, as fractions of the frame's exact cost (deterministic), and in
//! wall-clock time, as fractions of the exact narrow phase's time on the machine as it runs the
//! cells: an exact collider follows every frame, timed as the cells are, and a frame's base is the
//! median of the last [`BASE_WINDOW`] (machine-dependent; prioritisation is inside that budget).
//! Wall-clock schedulers run in a rotating order so none is always first into a cold cache.
//!
//! A condition fixes the scheduling model, the measuring model and what the scheduler is told about
//! the gaze: the viewer's fixation, or the screen centre (a control: the same viewer, measured at
//! the true fixation, with a scheduler that has no eye tracker); and who the viewer is
//! ([`ViewerModel`]: the uniform script, a central-bias or scene-driven viewer, or a recording).
//! Every cell reports the paper's estimated P beside the audited true P.

use std::fmt::Write as _;
use std::path::PathBuf;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

use foveal_engine::PricedOptions;
use foveal_engine::clairvoyant::{self, PairTruth};
use foveal_engine::collider::{Collider, FrameInput};
use foveal_engine::fixation::FrameView;
use foveal_engine::warm;
use foveal_engine::{
    BudgetSpec, Clock, EccentricityUnit, Fixation, FrameBudget, FrameReport, FrozenClock,
    PerceptualFunction, PerceptualModel, PhaseProfile, SceneConfig, SchedulerKind, SimConfig,
    Simulation, Truth,
};

use crate::endpoint::{self, Endpoint};
use crate::error::BenchError;
use foveal_gaze::rng::SplitMix64;

use crate::clock::InstantClock;
use crate::gaze::{RecordedGaze, SceneGlance, ScriptedGaze, ViewerModel, ViewerTrack};
use crate::plots::{Figure, PAPER_P_RATIO, Series, panel};
use crate::ratio::{RatioCi, p_below};
use crate::stats::{Interval, MeanCi};
use foveal_gaze::viewer::gaussian_pair;

/// A scheduler under test: a kind and, for the priced one, its ablation switches.
#[derive(Debug, Clone, PartialEq)]
pub struct SchedulerSpec {
    /// Label in tables.
    pub label: String,
    /// The scheduler.
    pub kind: SchedulerKind,
    /// Priced-scheduler switches.
    pub priced: PricedOptions,
    /// The priority queue's eccentricity threshold, degrees (None: the engine's default).
    pub threshold_deg: Option<f64>,
}

impl SchedulerSpec {
    /// A scheduler with default switches, labelled by its name.
    pub fn plain(kind: SchedulerKind) -> Self {
        Self {
            label: kind.name().into(),
            kind,
            priced: PricedOptions::default(),
            threshold_deg: None,
        }
    }

    /// `kind` (a priority-queue scheduler) with its first queue within `deg` of the fixation.
    pub fn with_threshold(kind: SchedulerKind, deg: f64) -> Self {
        Self {
            label: format!("{}@{deg}deg", kind.name()),
            threshold_deg: Some(deg),
            ..Self::plain(kind)
        }
    }

    /// The priced scheduler with these switches, labelled by them.
    pub fn priced(options: PricedOptions) -> Self {
        Self {
            label: options.label(),
            kind: SchedulerKind::Priced,
            priced: options,
            threshold_deg: None,
        }
    }
}

/// What the scheduler is told about the gaze: the viewer's true fixation, or what an imperfect
/// eye tracker (or none) would report. The measurement always uses the true fixation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GazeFeed {
    /// The viewer's fixation (as the measurement uses).
    Viewer,
    /// Always the screen centre: no eye tracker.
    Centre,
    /// A constant tracker bias: the fixation moved this many degrees of visual angle to the
    /// right (at the screen centre's pixels per degree).
    Bias {
        /// Bias, degrees.
        deg: f64,
    },
    /// Tracker noise: independent Gaussian offsets of this standard deviation per axis and
    /// frame, degrees (seeded by the run's seed).
    Noise {
        /// Standard deviation per axis, degrees.
        sd_deg: f64,
    },
    /// End-to-end latency: the scheduler sees where the viewer looked this long ago.
    Latency {
        /// Latency, milliseconds.
        ms: f64,
    },
}

/// Gaze speed above which the viewer is taken to be in a saccade, degrees per second: the usual
/// velocity threshold of I-VT fixation identification (Salvucci and Goldberg 2000).
pub const SACCADE_DEG_PER_S: f64 = 30.0;

/// One experimental condition.
#[derive(Debug, Clone, PartialEq)]
pub struct Condition {
    /// Label in tables.
    pub name: String,
    /// Model the schedulers rank with.
    pub schedule_model: PerceptualModel,
    /// Model true P is measured with.
    pub measure_model: PerceptualModel,
    /// What the schedulers are told about the gaze.
    pub feed: GazeFeed,
    /// Who watches: where the true fixation, which P is measured about, comes from.
    pub viewer: ViewerModel,
    /// Saccadic suppression: frames during which the viewer's gaze moves faster than
    /// [`SACCADE_DEG_PER_S`] are not counted (vision is suppressed during saccades). The
    /// schedulers still run on them, so every condition sees the same sequence of frames.
    pub suppress_saccades: bool,
    /// Schedulers run in this condition (round-robin is always among them).
    pub schedulers: Vec<SchedulerSpec>,
}

/// A budget of the comparison.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Budget {
    /// Sphere tests: this fraction of the frame's exact cost.
    Tests(f64),
    /// Sphere tests: this many every frame (a recorded session's own budget).
    FixedTests(u64),
    /// Wall clock: this fraction of the scene's median exact narrow-phase time.
    Wall(f64),
}

impl Budget {
    /// `tests=0.1`, `8000tests` or `wall=0.333`.
    pub fn label(&self) -> String {
        match self {
            Self::Tests(f) => format!("tests={f}"),
            Self::FixedTests(n) => format!("{n}tests"),
            Self::Wall(f) => format!("wall={f:.3}"),
        }
    }
}

/// The comparison to run.
#[derive(Debug, Clone, PartialEq)]
pub struct OpenLoopConfig {
    /// Body counts.
    pub ns: Vec<u32>,
    /// Seeds (paired: every scheduler sees the same frames per seed).
    pub seeds: Vec<u64>,
    /// Recorded frames per run, by N: `frames(n)`.
    pub frames: Vec<(u32, u32)>,
    /// Unrecorded exact frames first (the random start has deep overlaps).
    pub warmup: u32,
    /// Exact frames before the recorded ones (the wall-clock runs learn on the last of them; 0:
    /// no wall-clock budgets, nothing timed).
    pub timing_frames: u32,
    /// Budgets.
    pub budgets: Vec<Budget>,
    /// Conditions.
    pub conditions: Vec<Condition>,
    /// Worker threads over (N, seed) runs.
    pub jobs: usize,
    /// `SimConfig::fovea_first` for every scheduler (only the priced scheduler's wall-clock
    /// frames take the pass).
    pub fovea_first: bool,
    /// What "colliding" means in every run (`SceneConfig::truth`).
    pub truth: Truth,
    /// The primary endpoints, one cell per claim, named before the run ([`crate::endpoint`]);
    /// every other cell is secondary.
    pub primary: Vec<Endpoint>,
    /// Output directory.
    pub out: PathBuf,
}

/// The study's claims and the cell that decides each (N = 500 is the paper's largest case;
/// F2 with C = 5° its best-fitting model; a tenth of the exact narrow phase's time is the
/// paper's 10 ms at N = 500 over its base case, about 1/16, rounded to a budget the protocol
/// runs). Seeds of these runs are disjoint from the calibration's ([`EVALUATION_SEEDS`]).
pub fn primary_endpoints(paper_n: u32, foveal_n: u32) -> Vec<Endpoint> {
    vec![
        Endpoint {
            claim: "the paper: a priority queue around the fixation roughly halves the perceived \
                    error (section 4, figure 6b)"
                .into(),
            n: paper_n,
            condition: "C=5".into(),
            budget: Budget::Wall(0.1),
            scheduler: SchedulerKind::PriorityOnly.name().into(),
        },
        Endpoint {
            claim: "foveal: the priced scheduler fed the gaze halves the perceived error".into(),
            n: foveal_n,
            condition: "C=5".into(),
            budget: Budget::Wall(0.1),
            scheduler: SchedulerKind::Priced.name().into(),
        },
    ]
}

/// Seeds of the evaluation runs, fixed before the run and disjoint from the seeds the priced
/// scheduler's tables were fitted on (1-2) and held out on (101-102) ([`crate::calibrate`]).
pub const EVALUATION_SEEDS: [u64; 5] = [201, 202, 203, 204, 205];

/// The first `count` evaluation seeds (201, 202, ...: [`EVALUATION_SEEDS`] and on), what
/// `--seeds COUNT` runs.
pub fn evaluation_seeds(count: u64) -> Vec<u64> {
    (0..count.max(1)).map(|i| EVALUATION_SEEDS[0] + i).collect()
}

/// F2 in degrees with fall-off constant `c`.
pub fn f2(c: f64) -> PerceptualModel {
    PerceptualModel {
        function: PerceptualFunction::F2 { c },
        unit: EccentricityUnit::Degrees,
    }
}

/// F2 averaged over C in [lo, hi] degrees.
pub fn f2_range(lo: f64, hi: f64) -> PerceptualModel {
    PerceptualModel {
        function: PerceptualFunction::F2Range {
            c_min: lo,
            c_max: hi,
        },
        unit: EccentricityUnit::Degrees,
    }
}

fn model_label(m: &PerceptualModel) -> String {
    match m.function {
        PerceptualFunction::F2 { c } => format!("C={c}"),
        PerceptualFunction::F2Range { c_min, c_max } => format!("C={c_min}..{c_max}"),
        PerceptualFunction::F1 => "F1".into(),
        PerceptualFunction::F3 { .. } => "F3".into(),
    }
}

impl OpenLoopConfig {
    /// The default protocol: N = 500 and 10,000, 5 seeds, sphere-test budgets 0.005-0.3 and
    /// wall-clock budgets 1/30, 1/10, 1/3; F2 with C = 5 and 1 degrees, each with the viewer's gaze
    /// and the screen-centre control, every scheduler and the priced ablations; and model
    /// mismatch (scheduled with C in {1, 2, 5} or the range 1-10, measured with the others).
    pub fn standard() -> Self {
        let mut all: Vec<SchedulerSpec> = [
            SchedulerKind::RoundRobin,
            SchedulerKind::PriorityOnly,
            SchedulerKind::PrioritySorted,
            SchedulerKind::ExpectedGain,
            SchedulerKind::Priced,
        ]
        .into_iter()
        .map(SchedulerSpec::plain)
        .collect();
        for off in 0..3 {
            all.push(SchedulerSpec::priced(PricedOptions {
                probability: off != 0,
                cost: off != 1,
                gaze: off != 2,
            }));
        }
        let mut conditions = Vec::new();
        for c in [5.0, 1.0] {
            for feed in [GazeFeed::Viewer, GazeFeed::Centre] {
                let suffix = if feed == GazeFeed::Centre {
                    ", centre-fed"
                } else {
                    ""
                };
                conditions.push(Condition {
                    name: format!("C={c}{suffix}"),
                    schedule_model: f2(c),
                    measure_model: f2(c),
                    feed,
                    viewer: ViewerModel::Script,
                    suppress_saccades: false,
                    schedulers: if feed == GazeFeed::Viewer {
                        all.clone()
                    } else {
                        vec![
                            SchedulerSpec::plain(SchedulerKind::RoundRobin),
                            SchedulerSpec::plain(SchedulerKind::PriorityOnly),
                            SchedulerSpec::plain(SchedulerKind::Priced),
                        ]
                    },
                });
            }
        }
        // Who watches (C = 5): beside the uniform script above, a central-bias viewer, a
        // scene-driven one and the shipped recording, each with its screen-centre control, for
        // the headlines' schedulers. Only the viewer-fed runs are new: the centre-fed ones and
        // round-robin schedule the same for every viewer and are measured about each.
        for v in [
            ViewerModel::CentralBias,
            ViewerModel::SceneDriven,
            ViewerModel::Recorded,
        ] {
            for feed in [GazeFeed::Viewer, GazeFeed::Centre] {
                let suffix = if feed == GazeFeed::Centre {
                    ", centre-fed"
                } else {
                    ""
                };
                conditions.push(Condition {
                    name: format!("C=5, {}{suffix}", v.name()),
                    schedule_model: f2(5.0),
                    measure_model: f2(5.0),
                    feed,
                    viewer: v,
                    suppress_saccades: false,
                    schedulers: [
                        SchedulerKind::RoundRobin,
                        SchedulerKind::PriorityOnly,
                        SchedulerKind::Priced,
                    ]
                    .into_iter()
                    .map(SchedulerSpec::plain)
                    .collect(),
                });
            }
        }
        let pair = vec![
            SchedulerSpec::plain(SchedulerKind::RoundRobin),
            SchedulerSpec::plain(SchedulerKind::Priced),
        ];
        let scheds = [f2(1.0), f2(2.0), f2(5.0), f2_range(1.0, 10.0)];
        for s in scheds {
            for m in [1.0, 2.0, 5.0] {
                if s == f2(m) {
                    continue;
                }
                conditions.push(Condition {
                    name: format!("sched {} / measure C={m}", model_label(&s)),
                    schedule_model: s,
                    measure_model: f2(m),
                    feed: GazeFeed::Viewer,
                    viewer: ViewerModel::Script,
                    suppress_saccades: false,
                    schedulers: pair.clone(),
                });
            }
        }
        // Gaze robustness (C = 5): what a tracker's bias, noise and latency cost, and what
        // counting only the frames a viewer can see (saccadic suppression) changes.
        let robustness = [
            ("bias 1 deg", GazeFeed::Bias { deg: 1.0 }, false),
            ("bias 2 deg", GazeFeed::Bias { deg: 2.0 }, false),
            ("bias 4 deg", GazeFeed::Bias { deg: 4.0 }, false),
            ("noise sd 0.5 deg", GazeFeed::Noise { sd_deg: 0.5 }, false),
            ("noise sd 1 deg", GazeFeed::Noise { sd_deg: 1.0 }, false),
            ("latency 20 ms", GazeFeed::Latency { ms: 20.0 }, false),
            ("latency 50 ms", GazeFeed::Latency { ms: 50.0 }, false),
            ("latency 100 ms", GazeFeed::Latency { ms: 100.0 }, false),
            ("saccades not counted", GazeFeed::Viewer, true),
        ];
        for (name, feed, suppress) in robustness {
            conditions.push(Condition {
                name: format!("C=5, {name}"),
                schedule_model: f2(5.0),
                measure_model: f2(5.0),
                feed,
                viewer: ViewerModel::Script,
                suppress_saccades: suppress,
                schedulers: pair.clone(),
            });
        }
        let mut budgets: Vec<Budget> = [0.005, 0.01, 0.03, 0.1, 0.3]
            .into_iter()
            .map(Budget::Tests)
            .collect();
        budgets.extend([1.0 / 30.0, 0.1, 1.0 / 3.0].into_iter().map(Budget::Wall));
        // N = 300 and 500 are the paper's largest cases, 10,000 foveal's; frames per run are
        // chosen so that the default study fits 40 minutes on 2 cores (`docs/BENCHMARKS.md`):
        // seeds, not frames, are the replicates.
        Self {
            ns: vec![300, 500, 10_000],
            seeds: EVALUATION_SEEDS.to_vec(),
            frames: vec![(300, 500), (500, 500), (10_000, 100)],
            warmup: 60,
            timing_frames: 30,
            budgets,
            conditions,
            jobs: 1,
            fovea_first: false,
            truth: Truth::default(),
            primary: primary_endpoints(500, 10_000),
            out: PathBuf::from("results/open-loop"),
        }
    }

    /// The sensitivity grid (`open-loop --grid`): F2 with C in {0.5, 1, 2, 5, 10} degrees, F1 in
    /// pixels and an F3 (C = 20, 50, 200 px below 20, below 100 and beyond 100 px), each
    /// scheduled and measured with the same model; the paper's priority queue with thresholds
    /// of 1, 2, 5 and 10 degrees beside expected-gain and priced; sphere-test budgets 0.005-0.5
    /// of exact and wall-clock budgets 1/30-1/2 of the exact narrow-phase time. Its report ends
    /// with the region where each scheduler halves round-robin's true P.
    pub fn grid() -> Self {
        let mut schedulers = vec![SchedulerSpec::plain(SchedulerKind::RoundRobin)];
        for deg in [1.0, 2.0, 5.0, 10.0] {
            schedulers.push(SchedulerSpec::with_threshold(
                SchedulerKind::PriorityOnly,
                deg,
            ));
        }
        schedulers.push(SchedulerSpec::plain(SchedulerKind::ExpectedGain));
        schedulers.push(SchedulerSpec::plain(SchedulerKind::Priced));
        let mut models: Vec<(String, PerceptualModel)> = [0.5, 1.0, 2.0, 5.0, 10.0]
            .into_iter()
            .map(|c| (format!("F2 C={c}deg"), f2(c)))
            .collect();
        models.push(("F1 px".into(), PerceptualModel::f1_pixels()));
        models.push((
            "F3 px".into(),
            PerceptualModel {
                function: PerceptualFunction::F3 {
                    c1: 20.0,
                    c2: 50.0,
                    c3: 200.0,
                    e1: 20.0,
                    e2: 100.0,
                },
                unit: EccentricityUnit::Pixels,
            },
        ));
        let conditions = models
            .into_iter()
            .map(|(name, m)| Condition {
                name,
                schedule_model: m,
                measure_model: m,
                feed: GazeFeed::Viewer,
                viewer: ViewerModel::Script,
                suppress_saccades: false,
                schedulers: schedulers.clone(),
            })
            .collect();
        let mut budgets: Vec<Budget> = [0.005, 0.01, 0.03, 0.1, 0.3, 0.5]
            .into_iter()
            .map(Budget::Tests)
            .collect();
        budgets.extend(
            [1.0 / 30.0, 0.1, 1.0 / 3.0, 0.5]
                .into_iter()
                .map(Budget::Wall),
        );
        Self {
            // At the paper's N only: the grid is exploratory, and at N = 10,000 it alone would
            // take most of the study's time.
            ns: vec![500],
            budgets,
            conditions,
            // Exploratory: every cell of the grid is secondary.
            primary: Vec::new(),
            out: PathBuf::from("results/open-loop-grid"),
            ..Self::standard()
        }
    }

    /// A seconds-long version of [`Self::standard`]: N = 500, 3 seeds, 60 frames.
    pub fn quick() -> Self {
        Self {
            ns: vec![500],
            seeds: EVALUATION_SEEDS[..3].to_vec(),
            frames: vec![(500, 60)],
            primary: primary_endpoints(500, 500),
            warmup: 30,
            timing_frames: 10,
            out: PathBuf::from("results/open-loop-quick"),
            ..Self::standard()
        }
    }

    /// Recorded frames per run at `n`.
    pub fn frames_for(&self, n: u32) -> u32 {
        self.frames
            .iter()
            .find(|(m, _)| *m == n)
            .or(self.frames.last())
            .map_or(100, |&(_, f)| f)
    }
}

/// Sums over the frames of one run for one (condition, budget, scheduler).
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Cell {
    pub(crate) true_p: f64,
    /// The paper's estimated P (section 3: each deemed pair's gap bound from its evidence), with
    /// the condition's measuring model about the same fixation.
    pub(crate) est_p: f64,
    pub(crate) tests: f64,
    pub(crate) prioritise_ms: f64,
}

/// Per-run result: mean per frame of every cell, the bound and all-deemed P.
#[derive(Debug, Clone)]
pub struct RunResult {
    /// Bodies.
    pub n: u32,
    /// Seed.
    pub seed: u64,
    /// Frames recorded.
    pub frames: u32,
    /// Median over the recorded frames of the wall-clock budgets' base (ms): the exact narrow
    /// phase's time, the median of the last [`BASE_WINDOW`] frames timed alongside the cells.
    pub exact_narrow_ms: f64,
    /// The base's 5th and 95th percentiles over the recorded frames (ms): it follows the frames'
    /// exact cost and the machine's speed.
    pub base_range_ms: (f64, f64),
    /// The same percentiles of the base's time per sphere test (ns, the window's median): the
    /// machine's speed alone.
    pub speed_range_ns: (f64, f64),
    /// Mean exact cost (sphere tests per frame).
    pub exact_tests: f64,
    /// `[condition][budget][scheduler]`: (mean true P, mean tests, mean prioritise ms).
    pub(crate) cells: Vec<Vec<Vec<Cell>>>,
    /// `[condition][budget]`: mean bound.
    pub(crate) bound: Vec<Vec<f64>>,
    /// `[condition][budget]`: mean sphere tests a frame the bound was taken at (what the budget
    /// buys, or the most any scheduler used).
    pub(crate) bound_tests: Vec<Vec<f64>>,
    /// `[condition]`: mean true P with every pair deemed.
    pub(crate) all_deemed: Vec<f64>,
    /// `[condition]`: frames counted (fewer than `frames` under saccadic suppression).
    pub counted: Vec<u32>,
}

/// Frames whose exact narrow-phase times, timed alongside the cells, give a frame's wall-clock
/// budgets their base (the median). Why not one figure timed before the recorded frames: on a
/// shared machine a slow stretch lasts from milliseconds to a second, and timed over 30 frames
/// before them one set a seed's every wall-clock budget 1.3-1.6x too large (round-robin then did
/// 4-5x its tests); timed over all of them in a pass of their own, one seed's came out 1.2x the
/// others'. Tracking the recent frames keeps the budgets a fraction of what the exact frame costs
/// on the machine as it runs the cells, and the median ignores a single slow frame.
const BASE_WINDOW: usize = 31;

/// A seed whose base's time per sphere test has a 95th percentile over its 5th above this is
/// named in the report: the machine's speed moved that much during its run. Its cells are still
/// fair between schedulers, each frame's budgets following the machine, but a reader comparing
/// runs should know.
const BASE_SPREAD: f64 = 1.2;

/// Bring a frame's inputs into cache, as a server's frame finds them (see [`run_one`]).
fn warm_frame(input: &FrameInput<'_>) {
    warm::lines(&input.world.position);
    warm::lines(&input.world.basis);
    warm::lines(input.candidates);
    if let Some(c) = input.columns {
        c.warm();
    }
}

/// One exact frame of `c` on `input`, warmed first as the wall-clock cells are: its
/// prioritisation and narrow phase (ns).
fn time_exact(c: &mut Collider, input: &FrameInput<'_>, clock: &dyn Clock) -> (u64, u64) {
    c.warm();
    warm_frame(input);
    let mut r = FrameReport::default();
    let mut p = PhaseProfile::default();
    c.collide(input, None, FrameBudget::Unlimited, clock, &mut r, &mut p);
    (p.prioritise_ns + p.narrow_ns, r.sphere_tests)
}

/// The sphere tests a frame's bound is taken at: what `budget` buys, and at least `used`, the most
/// tests any scheduler of that budget used (the last step may overrun a sphere-test budget).
/// Under a wall-clock budget what it buys is the tests the exact kernel does in that time at its
/// rate in this run (`rate_ns` a test, the exact frames' window median; the budget is that
/// fraction of `base_ns`), not what a scheduler managed: a scheduler's own overhead must not lower
/// the bound it is judged by. Under a sphere-test budget, its count (a fraction of
/// `frame_tests`, the frame's exact cost).
fn bound_tests_of(budget: &Budget, frame_tests: u64, base_ns: f64, rate_ns: f64, used: u64) -> u64 {
    let buys = match *budget {
        Budget::Wall(x) if rate_ns > 0.0 => (x * base_ns / rate_ns).floor() as u64,
        Budget::Wall(_) => 0,
        Budget::Tests(x) => (x * frame_tests as f64).round() as u64,
        Budget::FixedTests(k) => k,
    };
    buys.max(used)
}

/// The last [`BASE_WINDOW`] exact frames' (time, sphere tests), and their medians.
#[derive(Debug, Default)]
struct BaseWindow {
    frames: std::collections::VecDeque<(u64, u64)>,
    sorted: Vec<f64>,
}

impl BaseWindow {
    fn push(&mut self, frame: (u64, u64)) {
        if self.frames.len() == BASE_WINDOW {
            self.frames.pop_front();
        }
        self.frames.push_back(frame);
    }

    /// The median (upper of the middle two) of `f` over the window, 0 if empty.
    fn median_of(&mut self, f: impl Fn((u64, u64)) -> f64) -> f64 {
        self.sorted.clear();
        self.sorted.extend(self.frames.iter().map(|&x| f(x)));
        self.sorted.sort_unstable_by(f64::total_cmp);
        self.sorted
            .get(self.sorted.len() / 2)
            .copied()
            .unwrap_or(0.0)
    }

    /// The median time (ns): the base.
    fn median(&mut self) -> f64 {
        self.median_of(|(ns, _)| ns as f64)
    }

    /// The median time per sphere test (ns): the machine's speed, whatever the frames' cost.
    fn median_rate(&mut self) -> f64 {
        self.median_of(|(ns, tests)| ns as f64 / tests.max(1) as f64)
    }
}

fn sim_config(n: u32, seed: u64, fovea_first: bool, truth: Truth) -> SimConfig {
    SimConfig {
        scene: SceneConfig {
            truth,
            ..SceneConfig::paper(n, seed)
        },
        budget: BudgetSpec::Exact,
        scheduler: SchedulerKind::Sequential,
        fovea_first,
        // Schedulers compared on identical frames under the same budgets: none takes the exact
        // pass on its budget's word.
        exact_when_affordable: false,
        ..SimConfig::default()
    }
}

/// One distinct scheduling run of a frame at one budget. Cells that would schedule identically
/// (the same scheduler and switches, scheduling model, gaze feed and budget, in any part of the
/// protocol) share one run, and each measures the pairs it deemed with its own model: the deemed
/// set does not depend on the measuring model. Round-robin reads neither model nor gaze, so one
/// run per budget serves every condition; the priced scheduler of a model-mismatch condition is
/// the matched condition's. Under sphere-test budgets sharing changes no figure (the runs are
/// deterministic); under wall-clock budgets the cells it serves are measured on one timed run.
struct ScheduleRun {
    spec: SchedulerSpec,
    schedule_model: PerceptualModel,
    feed: GazeFeed,
    /// Who it is told about: an index into the run's viewers.
    viewer: usize,
    /// Index into the union of the parts' budgets.
    budget: usize,
    /// Its configuration (the collider is built for its budget's batch only).
    sim: SimConfig,
    /// Present while its budget's batch runs.
    collider: Option<Collider>,
    /// The (part, condition, budget, scheduler) cells this run serves.
    cells: Vec<(usize, usize, usize, usize)>,
}

/// What a scheduling run reads of its condition: scheduling model, gaze feed, viewer.
type ScheduleKey = (PerceptualModel, GazeFeed, ViewerModel);

/// What a scheduling run of `spec` in condition `c` reads: its scheduling model, gaze feed and
/// viewer. Round-robin and sequential read none of them, and a run fed the screen centre reads no
/// viewer, so cells that differ only there share one run.
fn schedule_key(spec: &SchedulerSpec, c: &Condition) -> ScheduleKey {
    if matches!(
        spec.kind,
        SchedulerKind::RoundRobin | SchedulerKind::Sequential
    ) {
        (
            PerceptualModel::default(),
            GazeFeed::Viewer,
            ViewerModel::Script,
        )
    } else if c.feed == GazeFeed::Centre {
        (c.schedule_model, GazeFeed::Centre, ViewerModel::Script)
    } else {
        (c.schedule_model, c.feed, c.viewer)
    }
}

/// How many distinct scheduling runs every frame of parts run together makes (cells that would
/// schedule identically share one, as in [`run_frames_parts`]): the work of a frame beside its
/// exact step and truths, which a sharded run's cost estimate counts.
pub fn schedule_runs(parts: &[&OpenLoopConfig]) -> usize {
    let mut budgets: Vec<Budget> = Vec::new();
    let mut keys: Vec<(
        usize,
        SchedulerKind,
        PricedOptions,
        Option<f64>,
        ScheduleKey,
    )> = Vec::new();
    for p in parts {
        for c in &p.conditions {
            for b in &p.budgets {
                let ub = index_of(&mut budgets, *b);
                for spec in &c.schedulers {
                    index_of(
                        &mut keys,
                        (
                            ub,
                            spec.kind,
                            spec.priced,
                            spec.threshold_deg,
                            schedule_key(spec, c),
                        ),
                    );
                }
            }
        }
    }
    keys.len()
}

/// Run one (N, seed) of the paper scene, the scripted viewer looking.
pub fn run_one(cfg: &OpenLoopConfig, n: u32, seed: u64) -> Result<RunResult, BenchError> {
    let mut gaze = ScriptedGaze::new(seed);
    let scene = sim_config(n, seed, cfg.fovea_first, cfg.truth);
    run_frames(cfg, &scene, seed, &mut |t| gaze.at(t))
}

/// [`run_one`] for several parts of a protocol at once (see [`run_parts`]).
fn run_one_parts(
    parts: &[&OpenLoopConfig],
    n: u32,
    seed: u64,
) -> Result<Vec<RunResult>, BenchError> {
    let mut gaze = ScriptedGaze::new(seed);
    let fovea_first = parts.first().is_some_and(|p| p.fovea_first);
    let truth = parts.first().map_or(Truth::default(), |p| p.truth);
    let scene = sim_config(n, seed, fovea_first, truth);
    run_frames_parts(parts, &scene, seed, &mut |t| gaze.at(t))
}

/// Run the comparison on the frames of one exact run of `scene` (its budget, scheduler and
/// audit are replaced: the frames come from the exact run), with the viewer's fixation at
/// simulated time `t` (from the first warm-up frame) given by `gaze`. `seed` seeds the noise
/// feed.
pub fn run_frames(
    cfg: &OpenLoopConfig,
    scene: &SimConfig,
    seed: u64,
    gaze: &mut dyn FnMut(f64) -> Fixation,
) -> Result<RunResult, BenchError> {
    let mut v = run_frames_parts(&[cfg], scene, seed, gaze)?;
    Ok(v.remove(0))
}

/// [`run_frames`] for several parts of a protocol (say the standard comparison and the
/// sensitivity grid) on the same frames: the scene is stepped, its pairs' truths learnt and each
/// distinct scheduling run made once for all parts, and each part gets its own result. The parts
/// must agree on warm-up, timing frames and frames per N.
pub fn run_frames_parts(
    parts: &[&OpenLoopConfig],
    scene: &SimConfig,
    seed: u64,
    gaze: &mut dyn FnMut(f64) -> Fixation,
) -> Result<Vec<RunResult>, BenchError> {
    let Some(&cfg) = parts.first() else {
        return Ok(Vec::new());
    };
    let n = scene.scene.bodies;
    for p in parts {
        if p.warmup != cfg.warmup
            || p.timing_frames != cfg.timing_frames
            || p.frames_for(n) != cfg.frames_for(n)
        {
            return Err(BenchError::Invalid(
                "parts run on the same frames must agree on warm-up, timing frames and frames"
                    .into(),
            ));
        }
    }
    let any_wall = parts
        .iter()
        .any(|p| p.budgets.iter().any(|b| matches!(b, Budget::Wall(_))));
    if cfg.timing_frames == 0 && any_wall {
        return Err(BenchError::Invalid(
            "wall-clock budgets need at least one timing frame".into(),
        ));
    }
    let base = SimConfig {
        budget: BudgetSpec::Exact,
        scheduler: SchedulerKind::Sequential,
        audit: false,
        ..scene.clone()
    };
    let dt = base.scene.dt;
    let clock = InstantClock::new();
    // The union of the parts' budgets, and each part's budgets in it.
    let mut budgets: Vec<Budget> = Vec::new();
    let budget_of: Vec<Vec<usize>> = parts
        .iter()
        .map(|p| {
            p.budgets
                .iter()
                .map(|b| index_of(&mut budgets, *b))
                .collect()
        })
        .collect();
    // The viewers watching, and the recording if one of them replays it.
    let mut viewers: Vec<ViewerModel> = Vec::new();
    for p in parts {
        for c in &p.conditions {
            index_of(&mut viewers, c.viewer);
        }
    }
    let recording = if viewers.contains(&ViewerModel::Recorded) {
        Some(RecordedGaze::from_csv(std::path::Path::new(
            crate::gaze::RECORDING,
        ))?)
    } else {
        None
    };
    // True weights and bound items per distinct (measuring model, viewer) (conditions share them).
    let mut models: Vec<(PerceptualModel, usize)> = Vec::new();
    let model_of: Vec<Vec<usize>> = parts
        .iter()
        .map(|p| {
            p.conditions
                .iter()
                .map(|c| {
                    let v = index_of(&mut viewers, c.viewer);
                    index_of(&mut models, (c.measure_model, v))
                })
                .collect()
        })
        .collect();
    // Distinct scheduling runs, each with its collider; `run_of[p][ci][bi][si]` is a cell's run.
    let mut runs: Vec<ScheduleRun> = Vec::new();
    let mut run_of: Vec<Vec<Vec<Vec<usize>>>> = Vec::new();
    for (pi, p) in parts.iter().enumerate() {
        let mut per_cond = Vec::new();
        for (ci, c) in p.conditions.iter().enumerate() {
            let mut per_budget = Vec::new();
            for (bi, &ub) in budget_of[pi].iter().enumerate() {
                let mut per_sched = Vec::new();
                for (si, spec) in c.schedulers.iter().enumerate() {
                    let (model, feed, viewer) = schedule_key(spec, c);
                    let viewer = index_of(&mut viewers, viewer);
                    let same = |r: &ScheduleRun| {
                        r.budget == ub
                            && r.spec.kind == spec.kind
                            && r.spec.priced == spec.priced
                            && r.spec.threshold_deg == spec.threshold_deg
                            && r.schedule_model == model
                            && r.feed == feed
                            && r.viewer == viewer
                    };
                    let u = match runs.iter().position(same) {
                        Some(u) => u,
                        None => {
                            let sc = SimConfig {
                                scheduler: spec.kind,
                                priced: spec.priced,
                                schedule_model: model,
                                eccentricity_threshold_deg: spec
                                    .threshold_deg
                                    .unwrap_or(base.eccentricity_threshold_deg),
                                ..base.clone()
                            };
                            runs.push(ScheduleRun {
                                spec: spec.clone(),
                                schedule_model: model,
                                feed,
                                viewer,
                                budget: ub,
                                sim: sc,
                                collider: None,
                                cells: Vec::new(),
                            });
                            runs.len() - 1
                        }
                    };
                    runs[u].cells.push((pi, ci, bi, si));
                    per_sched.push(u);
                }
                per_budget.push(per_sched);
            }
            per_cond.push(per_budget);
        }
        run_of.push(per_cond);
    }
    let by_budget: Vec<Vec<usize>> = (0..budgets.len())
        .map(|ub| (0..runs.len()).filter(|&u| runs[u].budget == ub).collect())
        .collect();
    let frames = cfg.frames_for(n);
    let mut cells: Vec<Vec<Vec<Vec<Cell>>>> = parts
        .iter()
        .map(|p| {
            p.conditions
                .iter()
                .map(|c| vec![vec![Cell::default(); c.schedulers.len()]; p.budgets.len()])
                .collect()
        })
        .collect();
    let mut bound: Vec<Vec<Vec<f64>>> = parts
        .iter()
        .map(|p| vec![vec![0.0; p.budgets.len()]; p.conditions.len()])
        .collect();
    let mut bound_tests = bound.clone();
    let mut all_deemed: Vec<Vec<f64>> = parts
        .iter()
        .map(|p| vec![0.0; p.conditions.len()])
        .collect();
    let mut counted: Vec<Vec<u32>> = parts.iter().map(|p| vec![0; p.conditions.len()]).collect();
    let mut count: Vec<Vec<bool>> = counted.iter().map(|c| vec![true; c.len()]).collect();
    let mut truths: Vec<PairTruth> = Vec::new();
    let mut weights: Vec<Vec<f64>> = vec![Vec::new(); models.len()];
    let mut items: Vec<Vec<(f64, u32)>> = vec![Vec::new(); models.len()];
    let mut run_tests = vec![0u64; runs.len()];
    let mut exact_tests = 0.0;
    let mut bases = Vec::with_capacity(frames as usize);
    let mut rates = Vec::with_capacity(frames as usize);
    let centre = Fixation::at(0.5, 0.5);
    // One batch per budget: the frames are replayed from the start for each (the exact run is
    // deterministic, so every batch sees the same frames), and only that budget's colliders are
    // alive at a time. Holding every budget's colliders at once took most of the study's memory
    // (1.9 GB for one seed of N = 10,000); a budget's schedulers are compared with each other
    // and its bound within one batch. The frame-level sums (exact tests, all-deemed P, counted
    // frames) are taken in the first batch.
    for (batch, here) in by_budget.iter().enumerate() {
        let first = batch == 0;
        let ub = batch;
        let budget = budgets[ub];
        let mut source = Simulation::new(base.clone())?;
        for _ in 0..cfg.warmup {
            source.step(None, &FrozenClock);
        }
        for &u in here {
            let c = Collider::new(&runs[u].sim, source.tree(), source.viewer())?;
            runs[u].collider = Some(c);
        }
        // The wall-clock budgets' base (see BASE_WINDOW): an exact collider follows every frame,
        // timed as the wall-clock cells are, the timing frames filling the window.
        // A sphere-test batch after the first needs no base: its budgets do not read it.
        let timed = cfg.timing_frames > 0 && (first || matches!(budget, Budget::Wall(_)));
        let mut exact = Collider::new(&base, source.tree(), source.viewer())?;
        let mut window = BaseWindow::default();
        for _ in 0..cfg.timing_frames {
            source.step(None, &FrozenClock);
            if timed {
                window.push(time_exact(&mut exact, &source.frame_input(), &clock));
            }
        }
        let mut base_ns = window.median();
        let mut rate_ns = window.median_rate();
        // Wall-clock runs first see the last timing frame, uncounted (gaze at the screen centre),
        // as a server that has been running would have seen the frame before: they learn what
        // their ordering costs here and keep that frame's witnesses. Sphere-test runs do not, so
        // their rows replay bit for bit.
        if let (Budget::Wall(x), true) = (budget, cfg.timing_frames > 0) {
            let input = source.frame_input();
            let fb = FrameBudget::Wall((x * base_ns).round() as u64);
            for &u in here {
                let Some(collider) = runs[u].collider.as_mut() else {
                    continue;
                };
                for _ in 0..foveal_engine::budget::LEARN_FRAMES {
                    let mut r = FrameReport::default();
                    let mut prof = PhaseProfile::default();
                    collider.warm();
                    collider.collide(
                        &input,
                        Some(Fixation::at(0.5, 0.5)),
                        fb,
                        &clock,
                        &mut r,
                        &mut prof,
                    );
                }
            }
        }
        let viewer = *source.viewer();
        let display = viewer.display;
        let px_per_deg =
            display.viewing_distance_cm * 1f64.to_radians().tan() / display.pixel_pitch_cm();
        let aspect = f64::from(display.width_px) / f64::from(display.height_px);
        let mut noise = SplitMix64::new(seed ^ 0x0015_E5EE_D000_0000);
        // Each replay of the frames gets the same gaze: every track starts afresh.
        let mut tracks = viewers
            .iter()
            .map(|&v| ViewerTrack::new(v, seed, aspect, recording.as_ref()))
            .collect::<Result<Vec<_>, _>>()?;
        let mut fixes: Vec<Fixation> = Vec::with_capacity(viewers.len());
        let mut saccade: Vec<bool> = Vec::with_capacity(viewers.len());
        let mut est: Vec<(usize, f64)> = Vec::new();
        for f in 0..frames {
            let t = f64::from(cfg.warmup + cfg.timing_frames + f) * dt;
            let (g1, g2) = gaussian_pair(&mut noise);
            let frame_tests = source.step(None, &FrozenClock).sphere_tests;
            if first {
                exact_tests += frame_tests as f64;
            }
            let input = source.frame_input();
            if timed {
                window.push(time_exact(&mut exact, &input, &clock));
                base_ns = window.median();
                rate_ns = window.median_rate();
                // What the report quotes of the base and the machine's speed is the first
                // batch's: one pass over the frames, not several replays at different times.
                if first {
                    bases.push(base_ns);
                    rates.push(rate_ns);
                }
            }
            clairvoyant::truths(input.tree, input.world, input.candidates, &mut truths);
            // Where each viewer looks (a scene-driven one choosing from this frame's truths), and
            // whether it is in a saccade.
            let colliding = |k: usize| truths.get(k).is_some_and(|t| t.colliding);
            let glance = SceneGlance {
                camera: input.viewer,
                world: input.world,
                candidates: input.candidates,
                colliding: &colliding,
                px_per_deg,
            };
            fixes.clear();
            saccade.clear();
            for tr in &mut tracks {
                let before = tr.at(t - dt, &mut *gaze, &glance);
                let now = tr.at(t, &mut *gaze, &glance);
                fixes.push(now);
                saccade.push(
                    display.visual_angle_deg(
                        viewer.to_pixels(now.x, now.y),
                        viewer.to_pixels(before.x, before.y),
                    ) > SACCADE_DEG_PER_S * dt,
                );
            }
            let px_of = |v: usize| {
                let f = fixes[v];
                input.viewer.to_pixels(f.x, f.y)
            };
            for (mi, &(model, v)) in models.iter().enumerate() {
                let view = FrameView {
                    viewer: input.viewer,
                    fixation_px: px_of(v),
                    model,
                    uncertainty_deg: 0.0,
                };
                let w = &mut weights[mi];
                w.clear();
                w.extend(truths.iter().map(|t| t.weight(&view)));
                let it = &mut items[mi];
                it.clear();
                it.extend(w.iter().zip(&truths).map(|(&w, t)| (w, t.cost)));
                clairvoyant::sort_for_bound(it);
            }
            for (pi, p) in parts.iter().enumerate() {
                for (ci, c) in p.conditions.iter().enumerate() {
                    let in_saccade = saccade[models[model_of[pi][ci]].1];
                    let counts = !(c.suppress_saccades && in_saccade);
                    count[pi][ci] = counts;
                    if counts && first {
                        counted[pi][ci] += 1;
                        all_deemed[pi][ci] += weights[model_of[pi][ci]].iter().sum::<f64>();
                    }
                }
            }
            let shifted = |fixation: Fixation, dx_deg: f64, dy_deg: f64| {
                let (w, h) = (f64::from(display.width_px), f64::from(display.height_px));
                Fixation::at(
                    (fixation.x + dx_deg * px_per_deg / w).clamp(0.0, 1.0),
                    (fixation.y + dy_deg * px_per_deg / h).clamp(0.0, 1.0),
                )
            };
            let fb = match budget {
                Budget::Tests(x) => FrameBudget::Tests((x * frame_tests as f64).round() as u64),
                Budget::FixedTests(k) => FrameBudget::Tests(k),
                Budget::Wall(x) => FrameBudget::Wall((x * base_ns).round() as u64),
            };
            let clk: &dyn Clock = match budget {
                Budget::Tests(_) | Budget::FixedTests(_) => &FrozenClock,
                Budget::Wall(_) => &clock,
            };
            for j in 0..here.len() {
                // Rotate the order so no scheduler always runs first into cold caches.
                let u = here[(j + f as usize) % here.len()];
                let run = &mut runs[u];
                let vi = run.viewer;
                let fixation = fixes.get(vi).copied().unwrap_or(centre);
                let fed = match run.feed {
                    GazeFeed::Viewer => fixation,
                    GazeFeed::Centre => centre,
                    GazeFeed::Bias { deg } => shifted(fixation, deg, 0.0),
                    GazeFeed::Noise { sd_deg } => shifted(fixation, sd_deg * g1, sd_deg * g2),
                    GazeFeed::Latency { ms } => match tracks.get_mut(vi) {
                        Some(tr) => tr.at((t - ms * 1e-3).max(0.0), &mut *gaze, &glance),
                        None => centre,
                    },
                };
                let Some(collider) = run.collider.as_mut() else {
                    continue;
                };
                let mut r = FrameReport::default();
                let mut prof = PhaseProfile::default();
                if matches!(budget, Budget::Wall(_)) {
                    // A server runs one collider, whose buffers and frame stay cached between
                    // frames; here dozens take turns, so bring this one's back before timing it.
                    collider.warm();
                    warm_frame(&input);
                }
                collider.collide(&input, Some(fed), fb, clk, &mut r, &mut prof);
                run_tests[u] = r.sphere_tests;
                est.clear();
                for &(pi, ci, bi, si) in &run.cells {
                    if !count[pi][ci] {
                        continue;
                    }
                    // The paper's estimate, once per (measuring model, viewer) this run serves.
                    let mi = model_of[pi][ci];
                    let ep = match est.iter().find(|e| e.0 == mi) {
                        Some(&(_, ep)) => ep,
                        None => {
                            let (model, v) = models[mi];
                            let view = FrameView {
                                viewer: input.viewer,
                                fixation_px: px_of(v),
                                model,
                                uncertainty_deg: 0.0,
                            };
                            let ep = foveal_engine::metrics::measure(
                                collider.narrow(),
                                input.tree,
                                input.world,
                                Some(&view),
                                None,
                                1,
                            )
                            .p;
                            est.push((mi, ep));
                            ep
                        }
                    };
                    let tp: f64 = collider
                        .pairs()
                        .iter()
                        .zip(&weights[model_of[pi][ci]])
                        .filter(|(p, _)| {
                            p.status == foveal_engine::narrow_phase::PairStatus::Deemed
                        })
                        .map(|(_, w)| w)
                        .sum();
                    let cell = &mut cells[pi][ci][bi][si];
                    cell.true_p += tp;
                    cell.est_p += ep;
                    cell.tests += r.sphere_tests as f64;
                    cell.prioritise_ms += prof.prioritise_ns as f64 * 1e-6;
                }
            }
            for (pi, p) in parts.iter().enumerate() {
                for ci in 0..p.conditions.len() {
                    if !count[pi][ci] {
                        continue;
                    }
                    for bi in (0..p.budgets.len()).filter(|&bi| budget_of[pi][bi] == ub) {
                        let used = run_of[pi][ci][bi]
                            .iter()
                            .map(|&u| run_tests[u])
                            .max()
                            .unwrap_or(0);
                        let max_tests =
                            bound_tests_of(&p.budgets[bi], frame_tests, base_ns, rate_ns, used);
                        bound_tests[pi][ci][bi] += max_tests as f64;
                        bound[pi][ci][bi] +=
                            clairvoyant::bound_sorted(&items[model_of[pi][ci]], max_tests);
                    }
                }
            }
        }
        for &u in here {
            runs[u].collider = None;
        }
    }
    bases.sort_unstable_by(f64::total_cmp);
    rates.sort_unstable_by(f64::total_cmp);
    let pct = |v: &[f64], q: f64| foveal_gaze::quantile::nearest_rank(v, q).unwrap_or(0.0);
    let base_ms = pct(&bases, 0.5) * 1e-6;
    let base_range_ms = (pct(&bases, 0.05) * 1e-6, pct(&bases, 0.95) * 1e-6);
    let speed_range_ns = (pct(&rates, 0.05), pct(&rates, 0.95));
    // Means over the frames each condition counted.
    let mut out = Vec::with_capacity(parts.len());
    for (pi, p) in parts.iter().enumerate() {
        let mut cells = std::mem::take(&mut cells[pi]);
        let mut bound = std::mem::take(&mut bound[pi]);
        let mut bound_tests = std::mem::take(&mut bound_tests[pi]);
        let mut all_deemed = std::mem::take(&mut all_deemed[pi]);
        for ci in 0..p.conditions.len() {
            let k = 1.0 / f64::from(counted[pi][ci].max(1));
            for c in cells[ci].iter_mut().flatten() {
                c.true_p *= k;
                c.est_p *= k;
                c.tests *= k;
                c.prioritise_ms *= k;
            }
            for b in bound[ci].iter_mut().chain(bound_tests[ci].iter_mut()) {
                *b *= k;
            }
            all_deemed[ci] *= k;
        }
        let k = 1.0 / f64::from(frames.max(1));
        out.push(RunResult {
            n,
            seed,
            frames,
            exact_narrow_ms: base_ms,
            base_range_ms,
            speed_range_ns,
            exact_tests: exact_tests * k,
            cells,
            bound,
            bound_tests,
            all_deemed,
            counted: std::mem::take(&mut counted[pi]),
        });
    }
    Ok(out)
}

/// The index of `x` in `v`, pushing it first if it is not there.
fn index_of<T: PartialEq>(v: &mut Vec<T>, x: T) -> usize {
    match v.iter().position(|y| *y == x) {
        Some(k) => k,
        None => {
            v.push(x);
            v.len() - 1
        }
    }
}

/// Two independent standard normal variates (Box-Muller).
/// Run every (N, seed) on `cfg.jobs` threads; results in (N, seed) order.
pub fn run(cfg: &OpenLoopConfig) -> Result<Vec<RunResult>, BenchError> {
    let mut v = run_parts(&[cfg])?;
    Ok(v.remove(0))
}

/// [`run`] for several parts of a protocol on the same frames (see [`run_frames_parts`]): per
/// part, its results in (N, seed) order. The parts must agree on N, seeds and frames; the first
/// part's `jobs` is used.
pub fn run_parts(parts: &[&OpenLoopConfig]) -> Result<Vec<Vec<RunResult>>, BenchError> {
    let Some(&cfg) = parts.first() else {
        return Ok(Vec::new());
    };
    if parts.iter().any(|p| p.ns != cfg.ns || p.seeds != cfg.seeds) {
        return Err(BenchError::Invalid(
            "parts run on the same frames must agree on N and seeds".into(),
        ));
    }
    run_parts_on(parts, &cells(cfg))
}

/// Every (N, seed) run of `cfg`, in (N, seed) order: the cells a sharded run distributes.
pub fn cells(cfg: &OpenLoopConfig) -> Vec<(u32, u64)> {
    cfg.ns
        .iter()
        .flat_map(|&n| cfg.seeds.iter().map(move |&s| (n, s)))
        .collect()
}

/// [`run_parts`] on the (N, seed) runs of `plan` only (a shard's share): per part, the results in
/// `plan` order. The parts must agree on frames, warm-up and timing frames.
pub fn run_parts_on(
    parts: &[&OpenLoopConfig],
    plan: &[(u32, u64)],
) -> Result<Vec<Vec<RunResult>>, BenchError> {
    run_parts_timed_on(parts, plan).map(|(r, _)| r)
}

/// [`run_parts_on`], with each (N, seed) run's wall time (s, in `plan` order): a shard records
/// what its cells cost, which is what the cost estimate of a sharded run is fitted to.
pub fn run_parts_timed_on(
    parts: &[&OpenLoopConfig],
    plan: &[(u32, u64)],
) -> Result<(Vec<Vec<RunResult>>, Vec<f64>), BenchError> {
    let Some(&cfg) = parts.first() else {
        return Ok((Vec::new(), Vec::new()));
    };
    // Largest N first, so the short runs fill in behind the long ones on the other threads.
    let mut order: Vec<usize> = (0..plan.len()).collect();
    order.sort_by_key(|&k| std::cmp::Reverse(plan[k].0));
    let next = AtomicUsize::new(0);
    type Slot = (usize, Result<Vec<RunResult>, BenchError>, f64);
    let results: Mutex<Vec<Slot>> = Mutex::new(Vec::new());
    std::thread::scope(|scope| {
        for _ in 0..cfg.jobs.clamp(1, plan.len().max(1)) {
            scope.spawn(|| {
                while let Some(&k) = order.get(next.fetch_add(1, Ordering::Relaxed)) {
                    let (n, seed) = plan[k];
                    let started = std::time::Instant::now();
                    let r = run_one_parts(parts, n, seed);
                    let wall_s = started.elapsed().as_secs_f64();
                    if let Ok(mut v) = results.lock() {
                        v.push((k, r, wall_s));
                    }
                }
            });
        }
    });
    let mut results = results
        .into_inner()
        .map_err(|_| BenchError::Invalid("a worker thread panicked".into()))?;
    results.sort_by_key(|(k, _, _)| *k);
    let mut per_part: Vec<Vec<RunResult>> = parts.iter().map(|_| Vec::new()).collect();
    let mut walls = Vec::with_capacity(results.len());
    for (_, r, wall_s) in results {
        for (pi, run) in r?.into_iter().enumerate() {
            per_part[pi].push(run);
        }
        walls.push(wall_s);
    }
    Ok((per_part, walls))
}

/// One row of the summary: a scheduler in a condition at a budget, across seeds.
#[derive(Debug, Clone)]
pub struct SummaryRow {
    /// Bodies.
    pub n: u32,
    /// Condition name.
    pub condition: String,
    /// Budget label.
    pub budget: String,
    /// Scheduler label (`clairvoyant` for the bound).
    pub scheduler: String,
    /// Mean true P per frame.
    pub true_p: MeanCi,
    /// Mean true P over round-robin's, paired by seed ([`RatioCi`]).
    pub ratio_rr: RatioCi,
    /// The same with the paper's estimated P (each scheduler's and round-robin's own estimate).
    pub est_ratio_rr: RatioCi,
    /// Share of the achievable reduction, Σ(P_rr - P_s) / Σ(P_rr - P_bound), paired by seed.
    pub share: RatioCi,
    /// Sphere tests per frame over round-robin's, paired by seed.
    pub tests_rr: RatioCi,
    /// Mean prioritisation time per frame (ms).
    pub prioritise_ms: MeanCi,
    /// One-sided p-value of "true P is below half of round-robin's" (the paper's "roughly
    /// halves"), before any correction ([`crate::ratio::p_below`]); `None` where it cannot be
    /// computed (a seed with zero P, fewer than two seeds).
    pub p_halves: Option<f64>,
    /// One-sided p-value of "true P is below round-robin's".
    pub p_below_rr: Option<f64>,
}

/// Summaries across seeds for every (N, condition, budget, scheduler), with a `clairvoyant` row.
pub fn summarise(cfg: &OpenLoopConfig, runs: &[RunResult]) -> Vec<SummaryRow> {
    let mut rows = Vec::new();
    for &n in &cfg.ns {
        let rs: Vec<&RunResult> = runs.iter().filter(|r| r.n == n).collect();
        for (ci, cond) in cfg.conditions.iter().enumerate() {
            let rr = cond
                .schedulers
                .iter()
                .position(|s| s.kind == SchedulerKind::RoundRobin);
            for (bi, b) in cfg.budgets.iter().enumerate() {
                let p_rr = |r: &RunResult| rr.map_or(f64::NAN, |j| r.cells[ci][bi][j].true_p);
                let e_rr = |r: &RunResult| rr.map_or(f64::NAN, |j| r.cells[ci][bi][j].est_p);
                let t_rr = |r: &RunResult| rr.map_or(f64::NAN, |j| r.cells[ci][bi][j].tests);
                let mut push = |label: &str,
                                p: &dyn Fn(&RunResult) -> f64,
                                e: &dyn Fn(&RunResult) -> f64,
                                t: &dyn Fn(&RunResult) -> f64,
                                pm: &dyn Fn(&RunResult) -> f64| {
                    let pairs: Vec<(f64, f64)> = rs.iter().map(|r| (p(r), p_rr(r))).collect();
                    rows.push(SummaryRow {
                        n,
                        condition: cond.name.clone(),
                        budget: b.label(),
                        scheduler: label.into(),
                        true_p: MeanCi::of(rs.iter().map(|r| p(r))),
                        ratio_rr: RatioCi::of(pairs.iter().copied()),
                        est_ratio_rr: RatioCi::of(rs.iter().map(|r| (e(r), e_rr(r)))),
                        share: RatioCi::of(
                            rs.iter()
                                .map(|r| (p_rr(r) - p(r), p_rr(r) - r.bound[ci][bi])),
                        ),
                        tests_rr: RatioCi::of(rs.iter().map(|r| (t(r), t_rr(r)))),
                        prioritise_ms: MeanCi::of(rs.iter().map(|r| pm(r))),
                        p_halves: p_below(&pairs, PAPER_P_RATIO),
                        p_below_rr: p_below(&pairs, 1.0),
                    });
                };
                for (j, s) in cond.schedulers.iter().enumerate() {
                    push(
                        &s.label,
                        &|r| r.cells[ci][bi][j].true_p,
                        &|r| r.cells[ci][bi][j].est_p,
                        &|r| r.cells[ci][bi][j].tests,
                        &|r| r.cells[ci][bi][j].prioritise_ms,
                    );
                }
                // Its tests over round-robin's: what the budget buys against what round-robin
                // managed (unknown in records written before the bound's tests were kept).
                let bound_tests = |r: &RunResult| {
                    r.bound_tests
                        .get(ci)
                        .and_then(|b| b.get(bi))
                        .copied()
                        .unwrap_or(f64::NAN)
                };
                push(
                    "clairvoyant",
                    &|r| r.bound[ci][bi],
                    &|_| f64::NAN,
                    &bound_tests,
                    &|_| f64::NAN,
                );
            }
        }
    }
    rows
}

/// CSV of the per-run means.
pub fn runs_csv(cfg: &OpenLoopConfig, runs: &[RunResult]) -> String {
    let mut s = String::from(
        "n,seed,frames,exact_narrow_ms,exact_tests,condition,budget,scheduler,true_p,est_p,tests,prioritise_ms,bound,all_deemed,base_p05_ms,base_p95_ms,ns_per_test_p05,ns_per_test_p95\n",
    );
    for r in runs {
        for (ci, cond) in cfg.conditions.iter().enumerate() {
            for (bi, b) in cfg.budgets.iter().enumerate() {
                for (j, sch) in cond.schedulers.iter().enumerate() {
                    let c = r.cells[ci][bi][j];
                    let _ = writeln!(
                        s,
                        "{},{},{},{:.6},{:.1},\"{}\",{},{},{:.6e},{:.6e},{:.1},{:.6},{:.6e},{:.6e},{:.6},{:.6},{:.3},{:.3}",
                        r.n,
                        r.seed,
                        r.frames,
                        r.exact_narrow_ms,
                        r.exact_tests,
                        cond.name,
                        b.label(),
                        sch.label,
                        c.true_p,
                        c.est_p,
                        c.tests,
                        c.prioritise_ms,
                        r.bound[ci][bi],
                        r.all_deemed[ci],
                        r.base_range_ms.0,
                        r.base_range_ms.1,
                        r.speed_range_ns.0,
                        r.speed_range_ns.1,
                    );
                }
            }
        }
    }
    s
}

/// CSV of the summary rows: every ratio with its bootstrap interval and the seeds it counted, the
/// halving test's p-value before and (for secondary cells) after Holm's correction, and whether
/// the cell is a primary endpoint.
pub fn summary_csv(cfg: &OpenLoopConfig, rows: &[SummaryRow]) -> String {
    let adjusted = endpoint::secondary_halving(rows, &cfg.primary);
    let mut s = String::from(
        "n,condition,budget,scheduler,seeds,non_finite,true_p,true_p_ci,ratio_rr,ratio_rr_lo,ratio_rr_hi,est_ratio_rr,est_ratio_rr_lo,est_ratio_rr_hi,share,share_lo,share_hi,tests_rr,tests_rr_lo,tests_rr_hi,prioritise_ms,p_halves,p_halves_holm,primary\n",
    );
    let p = |x: Option<f64>| x.map_or(String::new(), |p| format!("{p:.4e}"));
    for (i, r) in rows.iter().enumerate() {
        let _ = writeln!(
            s,
            "{},\"{}\",{},{},{},{},{:.6e},{:.3e},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.5},{},{},{}",
            r.n,
            r.condition,
            r.budget,
            r.scheduler,
            r.ratio_rr.n,
            r.ratio_rr.non_finite,
            r.true_p.mean,
            r.true_p.half,
            r.ratio_rr.ratio,
            r.ratio_rr.lo,
            r.ratio_rr.hi,
            r.est_ratio_rr.ratio,
            r.est_ratio_rr.lo,
            r.est_ratio_rr.hi,
            r.share.ratio,
            r.share.lo,
            r.share.hi,
            r.tests_rr.ratio,
            r.tests_rr.lo,
            r.tests_rr.hi,
            r.prioritise_ms.mean,
            p(r.p_halves),
            p(adjusted[i]),
            cfg.primary.iter().any(|e| e.is(r)),
        );
    }
    s
}

/// What [`run_and_write`] produced.
#[derive(Debug, Clone)]
pub struct OpenLoopOutput {
    /// Files written: per-run CSV, summary CSV, report.
    pub files: Vec<PathBuf>,
    /// The report (markdown), as written.
    pub report: String,
}

/// The head of a markdown table with a column per budget: `| scheduler | <budget> | ... |` and
/// its rule, each ending in a newline.
pub(crate) fn budget_table_head(budgets: &[Budget]) -> String {
    let mut head = String::from("| scheduler |");
    let mut rule = String::from("| --- |");
    for b in budgets {
        let _ = write!(head, " {} |", b.label());
        rule.push_str(" --- |");
    }
    format!("{head}\n{rule}\n")
}

/// Run `cfg` and write `open_loop_runs.csv`, `open_loop_summary.csv` and `open_loop_report.md`
/// under `cfg.out`, the report stamped with the machine's load average before and after.
pub fn run_and_write(cfg: &OpenLoopConfig) -> Result<OpenLoopOutput, BenchError> {
    let mut v = run_and_write_parts(&[cfg])?;
    Ok(v.remove(0))
}

/// [`run_and_write`] for several parts run on the same frames ([`run_parts`]), each written under
/// its own `out`; every report carries the load average and the wall time of the whole run.
pub fn run_and_write_parts(parts: &[&OpenLoopConfig]) -> Result<Vec<OpenLoopOutput>, BenchError> {
    let load_start = load_average();
    let started = std::time::Instant::now();
    let all = run_parts(parts)?;
    let stamp = RunStamp {
        load_start,
        load_end: load_average(),
        wall_s: started.elapsed().as_secs_f64(),
    };
    write_parts(parts, &all, &stamp)
}

/// The machine's load average as `/proc/loadavg` gives it (`unknown` elsewhere): reports stamp
/// their wall-clock figures with it, since a loaded machine moves them.
pub fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .map(|s| s.trim().to_string())
        .unwrap_or_else(|_| "unknown".into())
}

/// When and how long the runs behind a report ran: the load average at start and end and the
/// wall time (s). A merged report lists the shards' own, joined by ` / `.
#[derive(Debug, Clone, PartialEq)]
pub struct RunStamp {
    /// Load average when the runs started.
    pub load_start: String,
    /// Load average when they ended.
    pub load_end: String,
    /// Wall time of the runs (s; for several shards, the slowest one's).
    pub wall_s: f64,
}

/// Write each part's CSVs, report and figures under its own `out` from its results `all[p]`
/// (as [`run_parts`] returns them); the reports end with `stamp`. A sharded run's merge calls
/// this with the results gathered from every shard, so its files are those of one run.
pub fn write_parts(
    parts: &[&OpenLoopConfig],
    all: &[Vec<RunResult>],
    stamp: &RunStamp,
) -> Result<Vec<OpenLoopOutput>, BenchError> {
    let RunStamp {
        load_start,
        load_end,
        wall_s,
    } = stamp;
    let mut outputs = Vec::new();
    for (cfg, runs) in parts.iter().zip(all) {
        let rows = summarise(cfg, runs);
        let shared = if parts.len() > 1 {
            format!(" ({} parts on the same frames)", parts.len())
        } else {
            String::new()
        };
        let stamp = crate::stamp::current();
        let report = format!(
            "{}\nLoad average at start: {}; at end: {}; wall time {:.0} s{shared}. Generated by \
             {}.\n",
            markdown(cfg, runs, &rows),
            load_start,
            load_end,
            wall_s,
            stamp.line()
        );
        std::fs::create_dir_all(&cfg.out).map_err(|e| BenchError::io(&cfg.out, e))?;
        let mut files = Vec::new();
        for (name, text) in [
            ("open_loop_runs.csv", stamp.csv(&runs_csv(cfg, runs))),
            ("open_loop_summary.csv", stamp.csv(&summary_csv(cfg, &rows))),
            ("open_loop_report.md", report.clone()),
        ] {
            let path = cfg.out.join(name);
            std::fs::write(&path, text).map_err(|e| BenchError::io(&path, e))?;
            files.push(path);
        }
        let figs = open_loop_figures(cfg, &rows);
        if !figs.is_empty() {
            let dir = cfg.out.join("figures");
            std::fs::create_dir_all(&dir).map_err(|e| BenchError::io(&dir, e))?;
            for (stem, fig) in &figs {
                let r = crate::plots::render(fig, &dir.join(stem))?;
                files.push(r.svg);
                files.push(r.png);
            }
        }
        outputs.push(OpenLoopOutput { files, report });
    }
    Ok(outputs)
}

/// Markdown tables: per N and condition, one row per scheduler, one column per budget, each cell
/// "true P / round-robin's (share of achievable reduction)".
pub fn markdown(cfg: &OpenLoopConfig, runs: &[RunResult], rows: &[SummaryRow]) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "Truth: `{}` (what \"colliding\" means for every exact answer, true gap and true P).\n",
        cfg.truth
    );
    let _ = writeln!(
        s,
        "Cells: mean true P over round-robin's on the same frames, paired by seed, with its 95% \
         bootstrap interval over seeds in brackets; after the slash the share of the achievable \
         reduction Σ(P_rr - P_s) / Σ(P_rr - P_clairvoyant), same form; then `est`, the same \
         ratio on the paper's estimated P (section 3: each deemed pair's gap bounded from its \
         evidence), which is what the paper plotted. Wall-clock columns add the sphere tests done \
         over round-robin's. n (seeds) is in each heading; a cell that counted fewer says so.\n"
    );
    s.push_str(&endpoint::markdown(&cfg.primary, rows));
    for &n in &cfg.ns {
        let rs: Vec<&RunResult> = runs.iter().filter(|r| r.n == n).collect();
        let narrow = MeanCi::of(rs.iter().map(|r| r.exact_narrow_ms));
        let tests = MeanCi::of(rs.iter().map(|r| r.exact_tests));
        let _ = writeln!(
            s,
            "### N = {n} ({} seeds x {} frames; exact narrow phase {}, {} sphere tests per frame)\n",
            rs.len(),
            cfg.frames_for(n),
            if cfg.timing_frames == 0 {
                "not timed".to_string()
            } else {
                format!("{} ms", narrow.fmt(3))
            },
            tests.fmt(3)
        );
        if cfg.timing_frames > 0 {
            let listed: Vec<String> = rs
                .iter()
                .map(|r| {
                    let ((lo, hi), (a, b)) = (r.base_range_ms, r.speed_range_ns);
                    format!("{lo:.4}-{hi:.4} ms ({a:.2}-{b:.2} ns a sphere test)")
                })
                .collect();
            let _ = writeln!(
                s,
                "Wall-clock budgets are fractions of the exact narrow phase's time, the median of \
                 the last {BASE_WINDOW} frames timed alongside the cells; its 5-95% range over \
                 the frames, by seed: {}.\n",
                listed.join(", ")
            );
            for r in &rs {
                let (lo, hi) = r.speed_range_ns;
                if hi > BASE_SPREAD * lo {
                    let _ = writeln!(
                        s,
                        "Seed {}: the machine's speed moved during the run (the exact frames took \
                         {lo:.2}-{hi:.2} ns a sphere test, {:.2}x); each frame's budgets \
                         followed it.\n",
                        r.seed,
                        hi / lo
                    );
                }
            }
        }
        for (ci, cond) in cfg.conditions.iter().enumerate() {
            if cond.suppress_saccades {
                let c = MeanCi::of(rs.iter().map(|r| f64::from(r.counted[ci])));
                let _ = writeln!(
                    s,
                    "**{}** (frames with gaze slower than {SACCADE_DEG_PER_S} deg/s: {} of {})\n",
                    cond.name,
                    c.fmt(3),
                    cfg.frames_for(n)
                );
            } else {
                let _ = writeln!(s, "**{}**\n", cond.name);
            }
            s.push_str(&budget_table_head(&cfg.budgets));
            let labels: Vec<String> = cond
                .schedulers
                .iter()
                .map(|x| x.label.clone())
                .chain(std::iter::once("clairvoyant".to_string()))
                .collect();
            for label in labels {
                let _ = write!(s, "| {label} |");
                for b in &cfg.budgets {
                    let Some(r) = rows.iter().find(|r| {
                        r.n == n
                            && r.condition == cond.name
                            && r.budget == b.label()
                            && r.scheduler == label
                    }) else {
                        s.push_str(" |");
                        continue;
                    };
                    let mut cell = format!(" {} / {}", r.ratio_rr.fmt_cell(2), r.share.fmt_cell(2));
                    if r.est_ratio_rr.ratio.is_finite() {
                        let _ = write!(cell, "; est {:.2}", r.est_ratio_rr.ratio);
                    }
                    if matches!(b, Budget::Wall(_)) && r.tests_rr.ratio.is_finite() {
                        let _ = write!(cell, "; tests {}", r.tests_rr.fmt_cell(2));
                    }
                    let _ = write!(s, "{cell} |");
                }
                s.push('\n');
            }
            s.push('\n');
            s.push_str(&rank_disagreements(rows, n, &cond.name));
        }
    }
    s.push_str(&halving_markdown(cfg, rows));
    s
}

/// A sentence naming the cells of one table where the paper's estimated P and the audited true P
/// put a scheduler on opposite sides of round-robin, each beyond its 95% interval (one ratio's
/// interval wholly below 1, the other's wholly above): there the paper's measure would rank the
/// two schedulers the other way. Empty where they agree or either could lie on 1.
fn rank_disagreements(rows: &[SummaryRow], n: u32, condition: &str) -> String {
    let flips: Vec<String> = rows
        .iter()
        .filter(|r| r.n == n && r.condition == condition)
        .filter(|r| r.scheduler != "round-robin" && r.scheduler != "clairvoyant")
        .filter(|r| {
            let (e, t) = (&r.est_ratio_rr, &r.ratio_rr);
            (e.hi < 1.0 && t.lo > 1.0) || (e.lo > 1.0 && t.hi < 1.0)
        })
        .map(|r| {
            format!(
                "{} at {} (estimated {:.2}, true {:.2})",
                r.scheduler, r.budget, r.est_ratio_rr.ratio, r.ratio_rr.ratio
            )
        })
        .collect();
    if flips.is_empty() {
        return String::new();
    }
    format!(
        "The estimate and the truth rank these against round-robin the other way (both 95% \
         intervals clear of 1): {}.\n\n",
        flips.join("; ")
    )
}

/// Where each scheduler halves round-robin's true P, as secondary findings: per N and scheduler,
/// each condition and budget marked `yes` where "true P below half of round-robin's" holds after
/// Holm's correction over every secondary cell of the report (α = 0.05), `ci` where only the
/// uncorrected bootstrap interval lies below one half, `mean` where only the estimate does;
/// the primary endpoints' cells are marked `primary` (tested alone, above).
pub fn halving_markdown(cfg: &OpenLoopConfig, rows: &[SummaryRow]) -> String {
    let adjusted = endpoint::secondary_halving(rows, &cfg.primary);
    let family = adjusted.iter().flatten().count();
    let held = adjusted
        .iter()
        .flatten()
        .filter(|&&p| p <= endpoint::ALPHA)
        .count();
    let untestable = rows
        .iter()
        .filter(|r| r.scheduler != "round-robin" && r.scheduler != "clairvoyant")
        .filter(|r| !cfg.primary.iter().any(|e| e.is(r)))
        .filter(|r| r.p_halves.is_none())
        .count();
    let mut s = format!(
        "### Where each scheduler halves round-robin's true P (secondary)\n\n`yes`: \"true P below \
         half of round-robin's\" holds after Holm's correction over all {family} secondary cells \
         of this report (one-sided t on per-seed log ratios, α = {}); it holds in {held} of them. \
         `ci`: only the uncorrected 95% bootstrap interval lies below 0.5; `mean`: only the \
         estimate does; blank: not halved; `primary`: a primary endpoint, tested alone above. \
         {untestable} cells could not be tested (a seed with zero or no P, or no spread across \
         seeds) and are left out of the family.\n\n",
        endpoint::ALPHA
    );
    for &n in &cfg.ns {
        let mut labels: Vec<&str> = Vec::new();
        for c in &cfg.conditions {
            for sch in &c.schedulers {
                if sch.kind != SchedulerKind::RoundRobin && !labels.contains(&sch.label.as_str()) {
                    labels.push(&sch.label);
                }
            }
        }
        for label in labels {
            let _ = writeln!(s, "**N = {n}, {label}**\n");
            let mut head = String::from("| condition |");
            let mut rule = String::from("| --- |");
            for b in &cfg.budgets {
                let _ = write!(head, " {} |", b.label());
                rule.push_str(" --- |");
            }
            let _ = writeln!(s, "{head}\n{rule}");
            for c in &cfg.conditions {
                if !c.schedulers.iter().any(|x| x.label == label) {
                    continue;
                }
                let _ = write!(s, "| {} |", c.name);
                for b in &cfg.budgets {
                    let cell = rows
                        .iter()
                        .enumerate()
                        .find(|(_, r)| {
                            r.n == n
                                && r.condition == c.name
                                && r.budget == b.label()
                                && r.scheduler == label
                        })
                        .map_or("", |(i, r)| {
                            if cfg.primary.iter().any(|e| e.is(r)) {
                                "primary"
                            } else if adjusted[i].is_some_and(|p| p <= endpoint::ALPHA) {
                                "yes"
                            } else if r.ratio_rr.hi < PAPER_P_RATIO {
                                "ci"
                            } else if r.ratio_rr.ratio < PAPER_P_RATIO {
                                "mean"
                            } else {
                                ""
                            }
                        });
                    let _ = write!(s, " {cell} |");
                }
                s.push('\n');
            }
            s.push('\n');
        }
    }
    s
}

/// Open-loop figures (every scheduler on identical frames), one per N and matched-model condition
/// fed the viewer's gaze: the share of the achievable reduction and true P over round-robin's
/// (paired by seed, 95% CIs) against the sphere-test budget, and the ratio against the wall-clock
/// budget with the sphere tests done beside it. The clairvoyant bound is drawn among the ratios;
/// the screen-centre control of the same model (no eye tracker) is dashed.
pub fn open_loop_figures(cfg: &OpenLoopConfig, rows: &[SummaryRow]) -> Vec<(String, Figure)> {
    let mut out = Vec::new();
    let series =
        |n: u32, cond: &str, label: &str, wall: bool, value: fn(&SummaryRow) -> RatioCi| {
            let points: Vec<(f64, Interval)> = cfg
                .budgets
                .iter()
                .filter_map(|b| match (*b, wall) {
                    (Budget::Tests(x), false) | (Budget::Wall(x), true) => Some((x, b.label())),
                    _ => None,
                })
                .filter_map(|(x, label_b)| {
                    rows.iter()
                        .find(|r| {
                            r.n == n
                                && r.condition == cond
                                && r.budget == label_b
                                && r.scheduler == label
                        })
                        .map(|r| (x, value(r).interval()))
                })
                .collect();
            points
        };
    for &n in &cfg.ns {
        for cond in cfg
            .conditions
            .iter()
            .filter(|c| c.feed == GazeFeed::Viewer && c.schedule_model == c.measure_model)
            .filter(|c| !c.suppress_saccades)
        {
            let centre = cfg.conditions.iter().find(|c| {
                c.feed == GazeFeed::Centre
                    && c.viewer == cond.viewer
                    && c.schedule_model == cond.schedule_model
                    && c.measure_model == cond.measure_model
            });
            // The ablations of the priced scheduler are in the tables, not the figure.
            let shown = |s: &&SchedulerSpec| {
                s.kind != SchedulerKind::RoundRobin
                    && (s.kind != SchedulerKind::Priced || s.label == SchedulerKind::Priced.name())
            };
            let labels: Vec<&str> = cond
                .schedulers
                .iter()
                .filter(shown)
                .map(|s| s.label.as_str())
                .collect();
            let mut panels = Vec::new();
            let share_of: fn(&SummaryRow) -> RatioCi = |r| r.share;
            let ratio_of: fn(&SummaryRow) -> RatioCi = |r| r.ratio_rr;
            for (title, y_label, wall, share) in [
                (
                    "Share of the achievable reduction, sphere-test budgets",
                    "(P_rr - P_s) / (P_rr - P_clairvoyant), paired by seed",
                    false,
                    true,
                ),
                (
                    "True P / round-robin's, sphere-test budgets",
                    "ratio of mean true P, paired by seed",
                    false,
                    false,
                ),
                (
                    "True P / round-robin's, wall-clock budgets",
                    "ratio of mean true P, paired by seed",
                    true,
                    false,
                ),
            ] {
                let value = if share { share_of } else { ratio_of };
                let mut ss: Vec<Series> = labels
                    .iter()
                    .map(|&l| Series {
                        name: l.into(),
                        points: series(n, &cond.name, l, wall, value),
                        dashed: false,
                    })
                    .collect();
                if let Some(c) = centre {
                    for s in c
                        .schedulers
                        .iter()
                        .filter(|s| s.kind != SchedulerKind::RoundRobin)
                    {
                        ss.push(Series {
                            name: format!("{}, centre-fed", s.label),
                            points: series(n, &c.name, &s.label, wall, value),
                            dashed: true,
                        });
                    }
                }
                if !share {
                    ss.push(Series {
                        name: "clairvoyant bound".into(),
                        points: series(n, &cond.name, "clairvoyant", wall, value),
                        dashed: false,
                    });
                }
                ss.retain(|s| !s.points.is_empty());
                if ss.is_empty() {
                    continue;
                }
                let mut p = panel(
                    format!("{title} (N = {n}, {})", cond.name),
                    y_label.into(),
                    ss,
                );
                p.x_label = if wall {
                    "budget (fraction of the exact narrow-phase time)".into()
                } else {
                    "budget (fraction of the frame's exact sphere tests)".into()
                };
                p.log_x = true;
                // Shares can be negative and the bound's ratio 0: a linear y.
                p.log_y = false;
                p.references = if share {
                    vec![
                        (0.8, "0.8 of achievable".into()),
                        (0.0, "round-robin".into()),
                    ]
                } else {
                    vec![
                        (PAPER_P_RATIO, "halved (paper)".into()),
                        (1.0, "round-robin".into()),
                    ]
                };
                panels.push(p);
            }
            if panels.is_empty() {
                continue;
            }
            let tag: String = cond
                .name
                .chars()
                .map(|c| {
                    if c.is_ascii_alphanumeric() || c == '.' {
                        c
                    } else {
                        '_'
                    }
                })
                .collect();
            let caption = format!(
                "Open loop, N = {n}, {}: every scheduler on the same frames of one exact run per \
                 seed. Points: over {} seeds x {} frames, the ratio of mean true P to round-robin's \
                 (or the share of the reduction the clairvoyant bound achieves); bars: 95% \
                 percentile-bootstrap intervals over seeds. Dashed: the same scheduler told the \
                 screen centre (no eye tracker).",
                cond.name,
                cfg.seeds.len(),
                cfg.frames_for(n)
            );
            out.push((format!("open_loop_n{n}_{tag}"), Figure { panels, caption }));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The quick protocol cut to N = 150, two seeds and one condition: a fraction of a second.
    fn tiny(frames: u32, timing_frames: u32, budgets: Vec<Budget>) -> OpenLoopConfig {
        let mut cfg = OpenLoopConfig::quick();
        cfg.ns = vec![150];
        cfg.seeds = vec![1, 2];
        cfg.frames = vec![(150, frames)];
        cfg.warmup = 5;
        cfg.timing_frames = timing_frames;
        cfg.budgets = budgets;
        cfg.conditions.truncate(1);
        cfg
    }

    #[test]
    fn tiny_protocol_orders_the_bound_below_every_scheduler() {
        let cfg = tiny(4, 2, vec![Budget::Tests(0.05), Budget::Tests(0.3)]);
        let runs = run(&cfg).expect("runs");
        assert_eq!(runs.len(), 2);
        let rows = summarise(&cfg, &runs);
        for r in &runs {
            for (bi, _) in cfg.budgets.iter().enumerate() {
                for c in &r.cells[0][bi] {
                    assert!(
                        c.true_p >= r.bound[0][bi] - 1e-12,
                        "{} < {}",
                        c.true_p,
                        r.bound[0][bi]
                    );
                    assert!(c.true_p <= r.all_deemed[0] + 1e-12);
                }
            }
        }
        let rr = rows
            .iter()
            .find(|r| r.scheduler == "round-robin")
            .expect("round-robin row");
        assert!((rr.ratio_rr.ratio - 1.0).abs() < 1e-12 && rr.share.ratio.abs() < 1e-12);
        assert!(rows.iter().any(|r| r.scheduler == "clairvoyant"));
        let md = markdown(&cfg, &runs, &rows);
        assert!(md.contains("| priced |") && md.contains("| clairvoyant |"));
        assert!(md.contains("halves round-robin's true P"));
    }

    /// Every viewer model runs: each condition's cells are measured about its own viewer's
    /// fixation (the same scheduler, told different gazes, deems different pairs), centre-fed
    /// and round-robin runs are shared across viewers, and the paper's estimate is reported
    /// beside the truth: positive wherever the truth is, zero where the budget settles every pair.
    #[test]
    fn viewer_models_are_measured_about_their_own_gaze_with_the_estimate_beside() {
        let mut cfg = tiny(6, 0, vec![Budget::Tests(0.05), Budget::Tests(100.0)]);
        let base = cfg.conditions[0].clone();
        cfg.conditions.clear();
        let models = [
            ViewerModel::Script,
            ViewerModel::CentralBias,
            ViewerModel::SceneDriven,
            ViewerModel::Recorded,
        ];
        for v in models {
            for feed in [GazeFeed::Viewer, GazeFeed::Centre] {
                cfg.conditions.push(Condition {
                    name: format!("{} {:?}", v.name(), feed),
                    feed,
                    viewer: v,
                    schedulers: vec![
                        SchedulerSpec::plain(SchedulerKind::RoundRobin),
                        SchedulerSpec::plain(SchedulerKind::Priced),
                    ],
                    ..base.clone()
                });
            }
        }
        // Round-robin once, the centre-fed priced once, the viewer-fed priced once per viewer:
        // six runs for each of the two budgets.
        assert_eq!(schedule_runs(&[&cfg]), 2 * (1 + 1 + models.len()));
        let runs = run(&cfg).expect("runs");
        for r in &runs {
            let priced: Vec<f64> = (0..cfg.conditions.len())
                .map(|ci| r.cells[ci][0][1].true_p)
                .collect();
            // The viewer-fed runs differ between viewers, the centre-fed ones only in where
            // they are measured.
            assert!(
                (0..models.len())
                    .any(|i| (1..models.len()).any(|j| priced[2 * i] != priced[2 * j])),
                "{priced:?}"
            );
            for ci in 0..cfg.conditions.len() {
                for c in &r.cells[ci][0] {
                    assert!(c.true_p == 0.0 || c.est_p > 0.0, "{} {}", c.true_p, c.est_p);
                }
                for c in &r.cells[ci][1] {
                    assert_eq!((c.true_p, c.est_p), (0.0, 0.0));
                }
            }
        }
        let rows = summarise(&cfg, &runs);
        assert!(rows.iter().any(|r| r.est_ratio_rr.ratio.is_finite()));
        let md = markdown(&cfg, &runs, &rows);
        assert!(md.contains("scene-driven viewer") && md.contains("; est "));
    }

    fn row(scheduler: &str, truth: (f64, f64, f64), est: (f64, f64, f64)) -> SummaryRow {
        let ci = |(ratio, lo, hi): (f64, f64, f64)| RatioCi {
            ratio,
            lo,
            hi,
            n: 5,
            non_finite: 0,
        };
        SummaryRow {
            n: 500,
            condition: "C=5".into(),
            budget: "wall=0.100".into(),
            scheduler: scheduler.into(),
            true_p: MeanCi::of([1.0, 1.0]),
            ratio_rr: ci(truth),
            est_ratio_rr: ci(est),
            share: ci((0.0, 0.0, 0.0)),
            tests_rr: ci((1.0, 1.0, 1.0)),
            prioritise_ms: MeanCi::of([0.0, 0.0]),
            p_halves: None,
            p_below_rr: None,
        }
    }

    /// The estimate and the truth are said to rank a scheduler differently only where both
    /// intervals clear 1 on opposite sides.
    #[test]
    fn rank_disagreements_need_both_intervals_clear_of_one() {
        let rows = vec![
            row("priced", (0.67, 0.6, 0.7), (1.2, 1.1, 1.3)),
            row("priority-only", (0.9, 0.8, 1.05), (1.2, 1.1, 1.3)),
            row("expected-gain", (0.5, 0.4, 0.6), (0.8, 0.7, 0.9)),
        ];
        let s = rank_disagreements(&rows, 500, "C=5");
        assert!(
            s.contains("priced at wall=0.100 (estimated 1.20, true 0.67)"),
            "{s}"
        );
        assert!(
            !s.contains("priority-only") && !s.contains("expected-gain"),
            "{s}"
        );
        assert!(rank_disagreements(&rows[1..], 500, "C=5").is_empty());
    }

    /// Under a wall-clock budget the bound is taken at the tests the exact kernel does in that
    /// time at its measured rate, however few a scheduler managed; under a sphere-test budget at
    /// the budget's own count; never below what a scheduler used.
    #[test]
    fn the_bound_is_taken_at_what_the_budget_buys() {
        // 0.3 of a 1 ms exact narrow phase at 10 ns a test buys 30,000 tests.
        let wall = Budget::Wall(0.3);
        assert_eq!(bound_tests_of(&wall, 5_000, 1e6, 10.0, 900), 30_000);
        assert_eq!(bound_tests_of(&wall, 5_000, 1e6, 10.0, 31_000), 31_000);
        assert_eq!(bound_tests_of(&wall, 5_000, 1e6, 0.0, 900), 900);
        assert_eq!(
            bound_tests_of(&Budget::Tests(0.1), 5_000, 1e6, 10.0, 480),
            500
        );
        assert_eq!(
            bound_tests_of(&Budget::Tests(0.1), 5_000, 1e6, 10.0, 507),
            507
        );
        assert_eq!(
            bound_tests_of(&Budget::FixedTests(800), 5_000, 1e6, 10.0, 0),
            800
        );
        // In a run: the mean over frames is at least every scheduler's mean, and still below
        // every scheduler's true P.
        let cfg = tiny(6, 3, vec![Budget::Tests(0.1), Budget::Wall(0.3)]);
        for r in &run(&cfg).expect("runs") {
            for bi in 0..2 {
                let used = r.cells[0][bi].iter().map(|c| c.tests).fold(0.0, f64::max);
                assert!(r.bound_tests[0][bi] >= used - 1e-9);
                for c in &r.cells[0][bi] {
                    assert!(c.true_p >= r.bound[0][bi] - 1e-12);
                }
            }
        }
    }

    #[test]
    fn the_wall_clock_base_is_reported_and_a_moving_machine_named() {
        let cfg = tiny(6, 3, vec![Budget::Tests(0.1), Budget::Wall(0.3)]);
        let mut runs = run(&cfg).expect("runs");
        for r in &runs {
            let (lo, hi) = r.base_range_ms;
            assert!(0.0 < lo && lo <= r.exact_narrow_ms && r.exact_narrow_ms <= hi);
            let (a, b) = r.speed_range_ns;
            assert!(0.0 < a && a <= b && b.is_finite());
        }
        let named = |runs: &[RunResult]| {
            let md = markdown(&cfg, runs, &summarise(&cfg, runs));
            assert!(md.contains("its 5-95% range over the frames"));
            [1, 2].map(|seed| md.contains(&format!("Seed {seed}: the machine's speed moved")))
        };
        // The frames' cost may move the base; only the time per test names a seed.
        runs[0].base_range_ms = (0.080, 0.140);
        runs[0].speed_range_ns = (3.0, 3.0 * BASE_SPREAD);
        runs[1].speed_range_ns = (3.0, 3.1);
        assert_eq!(named(&runs), [false, false]);
        runs[1].speed_range_ns = (3.0, 4.5);
        assert_eq!(named(&runs), [false, true]);
        let csv = runs_csv(&cfg, &runs);
        let header: Vec<&str> = csv.lines().next().expect("header").split(',').collect();
        assert_eq!(
            header[header.len() - 4..],
            [
                "base_p05_ms",
                "base_p95_ms",
                "ns_per_test_p05",
                "ns_per_test_p95"
            ]
        );
        assert!(csv.lines().last().expect("row").ends_with(",3.000,4.500"));
    }

    #[test]
    fn a_wall_window_tracks_the_median_of_its_last_frames() {
        let mut w = BaseWindow::default();
        assert_eq!(w.median(), 0.0);
        for t in 1..=BASE_WINDOW as u64 {
            w.push((t, 2 * t));
        }
        assert_eq!(w.median(), (BASE_WINDOW / 2 + 1) as f64);
        assert_eq!(w.median_rate(), 0.5);
        // One slow frame does not move it; a slow stretch of half the window does.
        w.push((1_000, 4));
        assert_eq!(w.median(), (BASE_WINDOW / 2 + 2) as f64);
        assert_eq!(w.median_rate(), 0.5);
        for _ in 0..BASE_WINDOW / 2 {
            w.push((1_000, 4));
        }
        assert_eq!(w.median(), 1_000.0);
        assert_eq!(w.median_rate(), 250.0);
    }

    #[test]
    fn the_grid_covers_models_thresholds_and_budgets() {
        let g = OpenLoopConfig::grid();
        assert_eq!(g.conditions.len(), 7);
        let labels: Vec<&str> = g.conditions[0]
            .schedulers
            .iter()
            .map(|s| s.label.as_str())
            .collect();
        assert!(labels.contains(&"priority-only@1deg") && labels.contains(&"priority-only@10deg"));
        assert!(g.budgets.contains(&Budget::Tests(0.5)) && g.budgets.contains(&Budget::Wall(0.5)));
        // A tiny run: the halving table marks a cell only where the ratio says so.
        let mut cfg = g.clone();
        cfg.ns = vec![150];
        cfg.seeds = vec![1, 2];
        cfg.frames = vec![(150, 3)];
        cfg.warmup = 5;
        cfg.timing_frames = 1;
        cfg.budgets = vec![Budget::Tests(0.3)];
        cfg.conditions.truncate(2);
        let runs = run(&cfg).expect("runs");
        let rows = summarise(&cfg, &runs);
        let md = halving_markdown(&cfg, &rows);
        let adjusted = endpoint::secondary_halving(&rows, &cfg.primary);
        for (i, r) in rows
            .iter()
            .enumerate()
            .filter(|(_, r)| r.scheduler == "priced")
        {
            let line = md
                .lines()
                .skip_while(|l| !l.contains("N = 150, priced"))
                .find(|l| l.starts_with(&format!("| {} |", r.condition)))
                .expect("row");
            let held = adjusted[i].is_some_and(|p| p <= endpoint::ALPHA);
            assert_eq!(line.contains("yes"), held, "{line} vs {:?}", r.ratio_rr);
            let ci_only = !held && r.ratio_rr.hi < 0.5;
            assert_eq!(line.contains("ci"), ci_only, "{line} vs {:?}", r.ratio_rr);
        }
    }

    /// The standard comparison and the grid on the same frames, with every distinct scheduling
    /// run made once for both, give each part exactly the figures it gets alone.
    #[test]
    fn parts_on_shared_frames_match_separate_runs_bit_for_bit() {
        let tiny = |mut c: OpenLoopConfig| {
            c.ns = vec![150];
            c.seeds = vec![1, 2];
            c.frames = vec![(150, 3)];
            c.warmup = 5;
            c.timing_frames = 1;
            c.jobs = 2;
            c
        };
        let mut a = tiny(OpenLoopConfig::standard());
        a.budgets = vec![Budget::Tests(0.05), Budget::Tests(0.3)];
        a.conditions.truncate(2);
        // The grid's C = 5 condition repeats the standard one's round-robin, priority-only,
        // expected-gain and priced runs; a second budget is its own.
        let mut b = tiny(OpenLoopConfig::grid());
        b.budgets = vec![Budget::Tests(0.3), Budget::Tests(0.5)];
        b.conditions
            .retain(|c| c.name == "F2 C=5deg" || c.name == "F1 px");
        assert_eq!(b.conditions.len(), 2);
        let shared = run_parts(&[&a, &b]).expect("shared");
        for (cfg, together) in [&a, &b].into_iter().zip(&shared) {
            let alone = run(cfg).expect("alone");
            assert_eq!(alone.len(), together.len());
            for (x, y) in alone.iter().zip(together) {
                assert_eq!(x.cells.len(), y.cells.len());
                for (cx, cy) in x
                    .cells
                    .iter()
                    .flatten()
                    .flatten()
                    .zip(y.cells.iter().flatten().flatten())
                {
                    assert_eq!(cx.true_p.to_bits(), cy.true_p.to_bits());
                    assert_eq!(cx.tests.to_bits(), cy.tests.to_bits());
                }
                assert_eq!(x.bound, y.bound);
                assert_eq!(x.all_deemed, y.all_deemed);
                assert!(x.cells.iter().flatten().flatten().any(|c| c.true_p > 0.0));
            }
        }
        // Parts that disagree on the frames are refused, not run on the wrong ones.
        let mut c = b.clone();
        c.frames = vec![(150, 4)];
        assert!(run_parts(&[&a, &c]).is_err());
    }

    fn condition(name: &str, feed: GazeFeed, suppress: bool) -> Condition {
        Condition {
            name: name.into(),
            schedule_model: f2(5.0),
            measure_model: f2(5.0),
            feed,
            viewer: ViewerModel::Script,
            suppress_saccades: suppress,
            schedulers: vec![
                SchedulerSpec::plain(SchedulerKind::RoundRobin),
                SchedulerSpec::plain(SchedulerKind::Priced),
            ],
        }
    }

    #[test]
    fn tracker_faults_reach_the_scheduler_and_suppression_skips_saccades() {
        let mut cfg = OpenLoopConfig::quick();
        cfg.ns = vec![300];
        cfg.seeds = vec![3];
        cfg.frames = vec![(300, 40)];
        cfg.warmup = 5;
        cfg.timing_frames = 1;
        cfg.budgets = vec![Budget::Tests(0.05)];
        cfg.conditions = vec![
            condition("true", GazeFeed::Viewer, false),
            condition("bias 0", GazeFeed::Bias { deg: 0.0 }, false),
            condition("latency 0", GazeFeed::Latency { ms: 0.0 }, false),
            condition("noise 0", GazeFeed::Noise { sd_deg: 0.0 }, false),
            condition("bias 15", GazeFeed::Bias { deg: 15.0 }, false),
            condition("latency 300", GazeFeed::Latency { ms: 300.0 }, false),
            condition("suppressed", GazeFeed::Viewer, true),
        ];
        let runs = run(&cfg).expect("runs");
        let r = &runs[0];
        let priced = |ci: usize| r.cells[ci][0][1].true_p;
        // A fault of size zero is the true gaze, bit for bit.
        for ci in 1..4 {
            assert_eq!(priced(ci).to_bits(), priced(0).to_bits(), "condition {ci}");
        }
        // A gross bias or latency points the scheduler at the wrong place.
        assert!(priced(4) > priced(0), "{} vs {}", priced(4), priced(0));
        assert!(priced(5) != priced(0));
        // The scripted viewer makes saccades within 40 frames: those frames are not counted.
        assert_eq!(r.counted[0], 40);
        assert!(r.counted[6] > 0 && r.counted[6] < 40, "{:?}", r.counted);
        // Round-robin does not see the gaze: the same on every unsuppressed condition.
        for ci in 1..6 {
            assert_eq!(
                r.cells[ci][0][0].true_p.to_bits(),
                r.cells[0][0][0].true_p.to_bits()
            );
        }
    }
}
