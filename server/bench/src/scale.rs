//! `foveal-bench scale`: the engine at N = 10,000, 100,000 and 1,000,000 bodies, with 1 and 2
//! threads, exact and under a frame budget, each configuration in its own child process so that its
//! peak RSS is its own.
//!
//! Every run is the paper scene (seed 1), round-robin scheduling, a fixation at the centre of the
//! screen and a wall clock ([`InstantClock`]). It warms up for some uncounted frames (random
//! placement starts with deep overlaps) and then times each `Simulation::step` with `Instant`: the
//! whole step, p50 and p99, is that time, not the sum of the profiled phases (which is reported
//! beside it). Phase shares are each profiled phase's total over the run divided by the total step
//! time. "Foveal exact" is the share of frames in which no candidate pair within 5 degrees of the
//! fixation was deemed (`FrameReport::foveal_deemed == 0`).
//!
//! The parent re-executes its own binary once per configuration with a hidden `--child SPEC`
//! argument (SPEC a JSON [`RunSpec`]); the child runs it with [`run_one`] and prints one JSON
//! [`RunResult`] line with its own peak RSS (`VmHWM` of `/proc/self/status`). Configurations run
//! one after another, never side by side.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use foveal_engine::broad_phase::BroadPhaseKind;
use foveal_engine::{
    BudgetSpec, ConfigError, Fixation, PassCosts, PhaseProfile, SceneConfig, SchedulerKind,
    SimConfig, Simulation, TreeKind, Truth,
};
use serde::{Deserialize, Serialize};

use crate::clock::InstantClock;

/// Body counts measured by default.
pub const DEFAULT_NS: [u32; 3] = [10_000, 100_000, 1_000_000];
/// Body counts of `--quick`.
pub const QUICK_NS: [u32; 2] = [10_000, 100_000];
/// Thread counts measured by default.
pub const DEFAULT_THREADS: [u32; 2] = [1, 2];
/// Default output directory.
pub const DEFAULT_OUT: &str = "results/scale";
/// The hidden argument that makes `foveal-bench scale` run one configuration and print its result.
pub const CHILD_ARG: &str = "--child";

/// Pipeline order of the profiled phases; phases the profile has beyond these follow, by name.
const PHASE_ORDER: [&str; 7] = [
    "renumber",
    "integrate",
    "broad",
    "prioritise",
    "narrow",
    "response",
    "measure",
];

/// Everything that can stop a scale run.
#[derive(Debug, thiserror::Error)]
pub enum ScaleError {
    /// The engine refused a configuration.
    #[error(transparent)]
    Config(#[from] ConfigError),
    /// A file could not be written.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// The child process could not be started.
    #[error("starting {exe}: {source}")]
    Spawn {
        /// The executable.
        exe: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// A child process failed or printed no result.
    #[error("run {spec} failed ({status}): {stderr}")]
    Child {
        /// The run, as passed to the child.
        spec: String,
        /// Exit status.
        status: String,
        /// The child's standard error (its last lines).
        stderr: String,
    },
    /// A run spec or result could not be read or written as JSON.
    #[error("{what}: {source}")]
    Json {
        /// What was being read or written.
        what: String,
        /// The cause.
        source: serde_json::Error,
    },
    /// The scale configuration is unusable.
    #[error("invalid scale run: {0}")]
    Invalid(String),
}

impl ScaleError {
    fn io(path: &Path, source: std::io::Error) -> Self {
        Self::Io {
            path: path.to_owned(),
            source,
        }
    }
}

/// The budget of a run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Mode {
    /// Every pair resolved exactly (`BudgetSpec::Exact`).
    Exact,
    /// A wall-clock budget for the frame, in milliseconds (`BudgetSpec::WallMs`).
    BudgetMs(f64),
}

impl Mode {
    /// Label for tables: `exact` or `budget 16 ms`.
    pub fn label(&self) -> String {
        match self {
            Self::Exact => "exact".into(),
            Self::BudgetMs(ms) => format!("budget {ms} ms"),
        }
    }

    fn budget(&self) -> BudgetSpec {
        match *self {
            Self::Exact => BudgetSpec::Exact,
            Self::BudgetMs(ms) => BudgetSpec::WallMs(ms),
        }
    }

    fn budget_ms(&self) -> Option<f64> {
        match *self {
            Self::Exact => None,
            Self::BudgetMs(ms) => Some(ms),
        }
    }

    /// `exact` or `budget`, as the CSV files name the mode.
    fn kind(&self) -> &'static str {
        match self {
            Self::Exact => "exact",
            Self::BudgetMs(_) => "budget",
        }
    }
}

/// One configuration, as handed to a child process.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RunSpec {
    /// Bodies.
    pub n: u32,
    /// `SimConfig::threads`.
    pub threads: u32,
    /// `SimConfig::broad_phase`.
    pub broad_phase: BroadPhaseKind,
    /// Exact or budgeted.
    pub mode: Mode,
    /// The narrow phase's scheduler.
    pub scheduler: SchedulerKind,
    /// `SimConfig::fovea_first`.
    #[serde(default)]
    pub fovea_first: bool,
    /// What "colliding" means (`SceneConfig::truth`).
    #[serde(default)]
    pub truth: Truth,
    /// The sphere tree's hierarchy (`SceneConfig::tree`); the octree in results written before
    /// it was recorded.
    #[serde(default = "TreeKind::before_it_was_recorded")]
    pub tree: TreeKind,
    /// Scene seed.
    pub seed: u64,
    /// Uncounted frames before the measured ones.
    pub warmup: u32,
    /// Measured frames.
    pub frames: u32,
    /// Where the viewer looks, as a fraction of the screen (None: the screen centre).
    #[serde(default)]
    pub viewer: Option<[f64; 2]>,
    /// The scheduler is told the screen centre while the viewer looks at `viewer`: the control
    /// without an eye tracker. Every count at the fovea is then measured where the viewer
    /// looked ([`Simulation::measured_at`]).
    #[serde(default)]
    pub steer_centre: bool,
    /// Audit every frame where the viewer looked, off the clock: the true P of
    /// [`RunResult::true_p_mean`].
    #[serde(default)]
    pub audit: bool,
}

/// What one run measured.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RunResult {
    /// The run.
    pub spec: RunSpec,
    /// Whole step (`Instant` around `Simulation::step`), median over the measured frames (ms).
    pub step_p50_ms: f64,
    /// Whole step, 99th percentile (nearest rank; the maximum below 100 frames) (ms).
    pub step_p99_ms: f64,
    /// Whole step, mean (ms).
    pub step_mean_ms: f64,
    /// Whole step, maximum (ms).
    pub step_max_ms: f64,
    /// Sum of the profiled phases, median (ms).
    pub phases_p50_ms: f64,
    /// Each profiled phase (name without `_ns`) and its share of the total step time.
    pub phase_share: Vec<(String, f64)>,
    /// Median whole step per body (ns).
    pub step_ns_per_body: f64,
    /// Mean broad phase per body (ns).
    pub broad_ns_per_body: f64,
    /// Peak resident set of the child process (`VmHWM`, KiB; 0 where unavailable).
    pub peak_rss_kib: u64,
    /// Share of frames in which every candidate pair within 5 degrees of the fixation was settled
    /// exactly: none deemed, and every region that may hold one searched.
    pub foveal_exact_share: f64,
    /// Share of frames in which a whole-frame budget left some broad-phase region stale.
    pub stale_share: f64,
    /// Mean stale regions per frame, and the regions there are.
    pub stale_regions_mean: f64,
    /// Regions of the broad phase (0: it has none to shed).
    pub regions: u32,
    /// Mean pairs held by stale regions per frame.
    pub stale_pairs_mean: f64,
    /// Mean candidate pairs within 5 degrees of the fixation per frame.
    pub foveal_pairs_mean: f64,
    /// Mean regions per frame that may hold a pair within 5 degrees of the fixation and were
    /// left unsearched (`FrameReport::foveal_stale`).
    #[serde(default)]
    pub foveal_stale_mean: f64,
    /// Mean candidate pairs per frame.
    pub candidates_mean: f64,
    /// Mean deemed pairs per frame.
    pub deemed_mean: f64,
    /// Mean sphere tests per frame.
    pub sphere_tests_mean: f64,
    /// Pairs settled exactly (candidates less deemed) per millisecond of the narrow phase
    /// (prioritising included), over every frame: what the narrow phase's time buys.
    #[serde(default)]
    pub settled_per_ms: f64,
    /// Share of frames that took the exact pass on their budget's word
    /// (`FrameReport::exact_fit`).
    #[serde(default)]
    pub exact_fit_share: f64,
    /// Scene generation and simulation set-up (s).
    pub setup_s: f64,
    /// Warm-up frames (s).
    pub warmup_s: f64,
    /// 1-minute load average when the run started (`None` without `/proc/loadavg`).
    pub load1_start: Option<f64>,
    /// Round of a repeated scale run this run belongs to (1-based; set by the parent, 0 from a
    /// child).
    #[serde(default)]
    pub round: u32,
    /// Mean audited true P per frame where the viewer looked (with [`RunSpec::audit`]).
    #[serde(default)]
    pub true_p_mean: Option<f64>,
    /// Every measured frame, in order: a p99 is one or two frames, and whether those were a
    /// phase the engine mispredicted or a stall of the machine shows only frame by frame
    /// (`frames.csv`).
    #[serde(default)]
    pub frame_trace: Vec<FrameSample>,
}

/// One measured frame of a run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FrameSample {
    /// Whole step (ms).
    pub step_ms: f64,
    /// Each profiled phase (ns), in the order of [`RunResult::phase_share`].
    pub phases_ns: Vec<u64>,
    /// Pairs deemed (not settled exactly).
    pub deemed: u32,
    /// Broad-phase regions left stale.
    pub stale_regions: u32,
    /// Sphere tests.
    pub sphere_tests: u64,
    /// How much earlier than its budget the frame aimed to end (`FrameReport::guard_ns`, ns).
    #[serde(default)]
    pub guard_ns: u64,
    /// Every candidate pair within 5 degrees of the fixation was settled exactly (see
    /// [`RunResult::foveal_exact_share`]).
    #[serde(default)]
    pub foveal_exact: bool,
    /// The frame took the exact pass on its budget's word (`FrameReport::exact_fit`).
    #[serde(default)]
    pub exact_fit: bool,
    /// The narrow phase pass by pass (`FrameReport::passes`).
    #[serde(default)]
    pub passes: PassCosts,
}

/// The whole command.
#[derive(Debug, Clone, PartialEq)]
pub struct ScaleConfig {
    /// Body counts.
    pub ns: Vec<u32>,
    /// Thread counts.
    pub threads: Vec<u32>,
    /// Measured frames per run (None: [`default_frames`]).
    pub frames: Option<u32>,
    /// Warm-up frames per run (None: [`default_warmup`]).
    pub warmup: Option<u32>,
    /// Frame budget per N (ms): empty for [`default_budget_ms`], one value for every N, or one per N.
    pub budget_ms: Vec<f64>,
    /// Smaller frame counts (and, from the command line, [`QUICK_NS`]).
    pub quick: bool,
    /// Also run the baseline (see [`RunSpec::is_baseline`]) where it differs from the 1-thread run.
    pub baseline: bool,
    /// Scene seed.
    pub seed: u64,
    /// The narrow phase's scheduler in every run (default: the server's).
    pub scheduler: SchedulerKind,
    /// `SimConfig::fovea_first` in every run.
    pub fovea_first: bool,
    /// The truth of every run.
    pub truth: Truth,
    /// The sphere tree of every run.
    pub tree: TreeKind,
    /// Rounds: the whole plan is run this many times, one round after another (1..=[`MAX_REPEAT`]).
    pub repeat: u32,
    /// Output directory.
    pub out: PathBuf,
}

/// Most rounds of a repeated scale run: beyond this a sitting drifts more than repeats settle.
pub const MAX_REPEAT: u32 = 25;

impl Default for ScaleConfig {
    fn default() -> Self {
        Self {
            ns: DEFAULT_NS.to_vec(),
            threads: DEFAULT_THREADS.to_vec(),
            frames: None,
            warmup: None,
            budget_ms: Vec::new(),
            quick: false,
            baseline: true,
            seed: 1,
            scheduler: SimConfig::default().scheduler,
            fovea_first: false,
            truth: Truth::default(),
            tree: TreeKind::default(),
            repeat: 1,
            out: PathBuf::from(DEFAULT_OUT),
        }
    }
}

/// Measured frames per run at `n` in `mode`: enough for a p99 where frames are cheap. Exact
/// frames above 30,000 bodies are fewer (200 at 100,000; 20 at 1,000,000, p99 then their
/// maximum) so that the default command finishes in about a quarter of an hour on two cores.
/// Frames under a budget, whose p99 the targets are set on, are 600 at 100,000 and 200
/// at 1,000,000: a nearest-rank p99 of 200 frames is their third slowest and of 20 the slowest,
/// so that one or two stalled frames of the machine decided it; of 600 it is the seventh.
pub fn default_frames(n: u32, quick: bool, mode: Mode) -> u32 {
    let [medium, large] = match mode {
        Mode::Exact => [200, 20],
        Mode::BudgetMs(_) => [600, 200],
    };
    let [small, medium, large] = if quick {
        [20, 6, 2]
    } else {
        [600, medium, large]
    };
    by_size(n, small, medium, large)
}

/// Warm-up frames: one second of simulated time at every N (the engine's own
/// `calibration_warmup`), two with `quick`. Random placement starts with deep overlaps whose cost
/// depends on simulated time, not on N: at N = 100,000 the exact narrow phase does 160 sphere
/// tests per body in frames 15-24, 106 in 30-39, 82 in 60-69, 78 in 90-99 and 76 in 120-129.
/// Fewer warm-up frames at 1,000,000 would measure it in its transient (129 per body over frames
/// 15-44, against 79 at 100,000 over frames 30-229).
pub fn default_warmup(quick: bool) -> u32 {
    if quick { 2 } else { 60 }
}

/// `small` up to 30,000 bodies, `medium` up to 300,000, `large` above.
fn by_size(n: u32, small: u32, medium: u32, large: u32) -> u32 {
    if n <= 30_000 {
        small
    } else if n <= 300_000 {
        medium
    } else {
        large
    }
}

/// The frame budget the issue sets for `n` (ms): 4 up to 10,000 bodies, 16 up to 100,000, 50 above.
pub fn default_budget_ms(n: u32) -> f64 {
    if n <= 10_000 {
        4.0
    } else if n <= 100_000 {
        16.0
    } else {
        50.0
    }
}

impl ScaleConfig {
    /// Refuse configurations that cannot run.
    pub fn validate(&self) -> Result<(), ScaleError> {
        let bad = |m: String| Err(ScaleError::Invalid(m));
        if self.ns.is_empty() || self.threads.is_empty() {
            return bad("at least one N and one thread count are needed".into());
        }
        if self.frames == Some(0) {
            return bad("at least one measured frame is needed".into());
        }
        if !(1..=MAX_REPEAT).contains(&self.repeat) {
            return bad(format!(
                "repeat {} is out of range: give 1 to {MAX_REPEAT} rounds",
                self.repeat
            ));
        }
        if self.budget_ms.len() > 1 && self.budget_ms.len() != self.ns.len() {
            return bad(format!(
                "{} budgets for {} values of N: give one, or one per N",
                self.budget_ms.len(),
                self.ns.len()
            ));
        }
        if let Some(ms) = self
            .budget_ms
            .iter()
            .find(|ms| !(ms.is_finite() && **ms > 0.0))
        {
            return bad(format!("budget {ms} ms is not finite and > 0"));
        }
        for spec in self.plan() {
            sim_config(&spec).validate()?;
        }
        Ok(())
    }

    /// The budget for the `i`-th N.
    fn budget_for(&self, i: usize, n: u32) -> f64 {
        match self.budget_ms.as_slice() {
            [] => default_budget_ms(n),
            [ms] => *ms,
            all => all[i],
        }
    }

    /// Every run, in order: for each N, exact then budgeted, each with every thread count (broad
    /// phase chosen by the engine), then the baseline where the engine's choice at this N is not
    /// sweep and prune (below that N the 1-thread run is the baseline).
    pub fn plan(&self) -> Vec<RunSpec> {
        let mut out = Vec::new();
        for (i, &n) in self.ns.iter().enumerate() {
            let warmup = self.warmup.unwrap_or(default_warmup(self.quick));
            for mode in [Mode::Exact, Mode::BudgetMs(self.budget_for(i, n))] {
                let frames = self.frames.unwrap_or(default_frames(n, self.quick, mode));
                let spec = |threads, broad_phase| RunSpec {
                    n,
                    threads,
                    broad_phase,
                    mode,
                    scheduler: self.scheduler,
                    fovea_first: self.fovea_first,
                    truth: self.truth,
                    tree: self.tree,
                    seed: self.seed,
                    warmup,
                    frames,
                    viewer: None,
                    steer_centre: false,
                    audit: false,
                };
                for &threads in &self.threads {
                    out.push(spec(threads, BroadPhaseKind::Auto));
                }
                let auto = BroadPhaseKind::Auto.resolve(n as usize);
                if self.baseline && auto != BroadPhaseKind::SweepAndPrune {
                    out.push(spec(1, BroadPhaseKind::SweepAndPrune));
                }
            }
        }
        out
    }
}

/// The engine configuration of a run.
fn sim_config(spec: &RunSpec) -> SimConfig {
    SimConfig {
        scene: SceneConfig {
            truth: spec.truth,
            tree: spec.tree,
            ..SceneConfig::paper(spec.n, spec.seed)
        },
        budget: spec.mode.budget(),
        scheduler: spec.scheduler,
        fovea_first: spec.fovea_first,
        // Audited off the clock, after the step (see `run_one`).
        audit: false,
        threads: spec.threads,
        broad_phase: spec.broad_phase,
        ..SimConfig::default()
    }
}

impl RunSpec {
    /// The closest the bench can still come to the engine before threads and the grid: one
    /// thread and the sweep-and-prune broad phase. True for the explicit sweep-and-prune run and
    /// for a 1-thread run whose automatic choice is sweep and prune anyway.
    pub fn is_baseline(&self) -> bool {
        self.threads == 1
            && self.broad_phase.resolve(self.n as usize) == BroadPhaseKind::SweepAndPrune
    }

    /// Broad phase as run (the automatic choice resolved), for tables.
    pub fn broad_label(&self) -> String {
        let resolved = self.broad_phase.resolve(self.n as usize).name();
        match self.broad_phase {
            BroadPhaseKind::Auto => format!("auto ({resolved})"),
            _ => resolved.to_string(),
        }
    }
}

/// The profiled phases of `p`, as (name without `_ns`, nanoseconds), in pipeline order. Read
/// through the profile's serialised form, so a phase added to [`PhaseProfile`] is reported without
/// a change here.
fn phases(p: &PhaseProfile) -> Vec<(String, u64)> {
    let mut out: Vec<(String, u64)> = match serde_json::to_value(p) {
        Ok(serde_json::Value::Object(m)) => m
            .iter()
            .filter_map(|(k, v)| Some((k.strip_suffix("_ns")?.to_string(), v.as_u64()?)))
            .collect(),
        _ => Vec::new(),
    };
    let rank = |name: &str| {
        PHASE_ORDER
            .iter()
            .position(|p| *p == name)
            .unwrap_or(PHASE_ORDER.len())
    };
    out.sort_by(|a, b| rank(&a.0).cmp(&rank(&b.0)).then_with(|| a.0.cmp(&b.0)));
    out
}

/// Nearest-rank percentile of sorted values ([`foveal_gaze::quantile`]); NaN for none.
fn percentile(sorted: &[f64], q: f64) -> f64 {
    foveal_gaze::quantile::nearest_rank(sorted, q).unwrap_or(f64::NAN)
}

/// The three load averages of `/proc/loadavg`.
pub fn load_average() -> Option<[f64; 3]> {
    let text = std::fs::read_to_string("/proc/loadavg").ok()?;
    let mut it = text.split_whitespace().map(|s| s.parse::<f64>().ok());
    Some([it.next()??, it.next()??, it.next()??])
}

/// The processor a run measured, printed above its table: the targets are figures of one
/// machine, and a machine of the same nominal size can be half as fast (a 2-core Intel Xeon at
/// 2.1 GHz ran the million-body exact step 1.2-1.9x slower than a 2-core AMD EPYC with the same
/// binary; `docs/BENCHMARKS.md`).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Machine {
    /// `model name` of `/proc/cpuinfo`'s first processor, with its family and model numbers
    /// (`None` where there is no name).
    pub model: Option<String>,
    /// Processors this process may run on.
    pub logical: usize,
    /// Whether the grid's pair search takes its AVX-512 rounds here.
    pub avx512: bool,
}

impl Machine {
    /// This machine.
    pub fn this() -> Self {
        Self {
            model: std::fs::read_to_string("/proc/cpuinfo")
                .ok()
                .and_then(|t| cpu_model(&t)),
            logical: std::thread::available_parallelism().map_or(0, |n| n.get()),
            avx512: foveal_engine::broad_phase::wide_rounds_available(),
        }
    }
}

impl std::fmt::Display for Machine {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}, {} logical processors, AVX-512 {}",
            self.model
                .as_deref()
                .unwrap_or("processor model unavailable"),
            self.logical,
            if self.avx512 { "yes" } else { "no" }
        )
    }
}

/// The first processor's `model name` of a `/proc/cpuinfo` text, its whitespace collapsed, with
/// its `cpu family` and `model` numbers where the text gives them: a virtual machine's name can
/// be the same for different processors (two 2-core Intel Xeons of different generations both
/// read "Intel(R) Xeon(R) Processor", and ran the same binary at different speeds).
fn cpu_model(cpuinfo: &str) -> Option<String> {
    // The first processor's block ends at the first blank line.
    let first = cpuinfo.split("\n\n").next().unwrap_or("");
    let field = |name: &str| {
        first.lines().find_map(|l| {
            let (key, value) = l.split_once(':')?;
            (key.trim() == name)
                .then(|| value.split_whitespace().collect::<Vec<_>>().join(" "))
                .filter(|v| !v.is_empty())
        })
    };
    let name = field("model name")?;
    Some(match (field("cpu family"), field("model")) {
        (Some(family), Some(model)) => format!("{name} (family {family}, model {model})"),
        _ => name,
    })
}

/// Peak resident set of this process (`VmHWM`, KiB), 0 where `/proc/self/status` has none.
pub fn peak_rss_kib() -> u64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find_map(|l| l.strip_prefix("VmHWM:"))
                .and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
        })
        .unwrap_or(0)
}

/// Run one configuration in this process.
pub fn run_one(spec: &RunSpec) -> Result<RunResult, ScaleError> {
    let load1_start = load_average().map(|l| l[0]);
    let started = Instant::now();
    let mut sim = Simulation::new(sim_config(spec))?;
    let setup_s = started.elapsed().as_secs_f64();
    let clock = InstantClock::new();
    let [vx, vy] = spec.viewer.unwrap_or([0.5, 0.5]);
    let viewer = Some(Fixation::at(vx, vy));
    let fixation = if spec.steer_centre {
        Some(Fixation::at(0.5, 0.5))
    } else {
        viewer
    };
    // Measured where the viewer looked, off the clock, whenever that is not what the frame
    // measured itself: every run of a comparison does the same work between its frames.
    let remeasure = spec.audit || spec.steer_centre;
    let started = Instant::now();
    for _ in 0..spec.warmup {
        sim.step(fixation, &clock);
    }
    let warmup_s = started.elapsed().as_secs_f64();

    let frames = spec.frames.max(1) as usize;
    let mut step_ms = Vec::with_capacity(frames);
    let mut phases_ms = Vec::with_capacity(frames);
    let mut phase_totals: Vec<(String, u64)> = Vec::new();
    let (mut good, mut foveal, mut candidates, mut deemed, mut tests) =
        (0u64, 0u64, 0u64, 0u64, 0u64);
    let (mut stale_frames, mut stale_regions, mut stale_pairs, mut regions) = (0u64, 0u64, 0u64, 0);
    let (mut narrow_ns, mut exact_fit) = (0u64, 0u64);
    let (mut true_p, mut audited, mut foveal_stale) = (0.0, 0u64, 0u64);
    let mut frame_trace = Vec::with_capacity(frames);
    for _ in 0..frames {
        let t = Instant::now();
        sim.step(fixation, &clock);
        let ms = t.elapsed().as_secs_f64() * 1e3;
        let seen = remeasure.then(|| sim.measured_at(viewer, spec.audit));
        let r = sim.last_report();
        // The fovea's counts where the viewer looked; what the frame did, as it did it.
        let at_viewer = seen.as_ref().unwrap_or(r);
        if let Some(p) = at_viewer.audit.and_then(|a| a.perceived_inaccuracy) {
            true_p += p;
            audited += 1;
        }
        step_ms.push(ms);
        let ph = phases(&r.profile);
        let foveal_exact = at_viewer.foveal_deemed == 0 && at_viewer.foveal_stale == 0;
        frame_trace.push(FrameSample {
            step_ms: ms,
            phases_ns: ph.iter().map(|(_, ns)| *ns).collect(),
            deemed: r.deemed,
            stale_regions: r.stale_regions,
            sphere_tests: r.sphere_tests,
            guard_ns: r.guard_ns,
            foveal_exact,
            exact_fit: r.exact_fit,
            passes: r.passes,
        });
        phases_ms.push(ph.iter().map(|(_, ns)| *ns as f64).sum::<f64>() * 1e-6);
        if phase_totals.is_empty() {
            phase_totals = ph.iter().map(|(k, _)| (k.clone(), 0)).collect();
        }
        for ((_, total), (_, ns)) in phase_totals.iter_mut().zip(&ph) {
            *total += ns;
        }
        good += u64::from(foveal_exact);
        stale_frames += u64::from(r.stale_regions > 0);
        stale_regions += u64::from(r.stale_regions);
        stale_pairs += u64::from(r.stale_pairs);
        regions = r.regions;
        foveal += u64::from(at_viewer.foveal_pairs);
        foveal_stale += u64::from(at_viewer.foveal_stale);
        candidates += u64::from(r.candidate_pairs);
        deemed += u64::from(r.deemed);
        tests += r.sphere_tests;
        narrow_ns += r.profile.prioritise_ns + r.profile.narrow_ns;
        exact_fit += u64::from(r.exact_fit);
    }
    let total_ms: f64 = step_ms.iter().sum();
    let mean = |v: u64| v as f64 / frames as f64;
    let broad_total = phase_totals
        .iter()
        .find(|(k, _)| k == "broad")
        .map_or(0, |(_, ns)| *ns);
    let mut sorted = step_ms.clone();
    sorted.sort_by(f64::total_cmp);
    phases_ms.sort_by(f64::total_cmp);
    let step_p50_ms = percentile(&sorted, 0.5);
    Ok(RunResult {
        spec: spec.clone(),
        step_p50_ms,
        step_p99_ms: percentile(&sorted, 0.99),
        step_mean_ms: total_ms / frames as f64,
        step_max_ms: sorted.last().copied().unwrap_or(f64::NAN),
        phases_p50_ms: percentile(&phases_ms, 0.5),
        phase_share: phase_totals
            .into_iter()
            .map(|(k, ns)| (k, ns as f64 * 1e-6 / total_ms))
            .collect(),
        step_ns_per_body: step_p50_ms * 1e6 / f64::from(spec.n),
        broad_ns_per_body: mean(broad_total) / f64::from(spec.n),
        peak_rss_kib: peak_rss_kib(),
        foveal_exact_share: mean(good),
        stale_share: mean(stale_frames),
        stale_regions_mean: mean(stale_regions),
        regions,
        stale_pairs_mean: mean(stale_pairs),
        foveal_pairs_mean: mean(foveal),
        foveal_stale_mean: mean(foveal_stale),
        candidates_mean: mean(candidates),
        deemed_mean: mean(deemed),
        sphere_tests_mean: mean(tests),
        settled_per_ms: (candidates - deemed.min(candidates)) as f64
            / (narrow_ns.max(1) as f64 * 1e-6),
        exact_fit_share: mean(exact_fit),
        true_p_mean: (audited > 0).then(|| true_p / audited as f64),
        setup_s,
        warmup_s,
        load1_start,
        round: 0,
        frame_trace,
    })
}

/// The child's side: parse `spec_json`, run it, and return the result as one JSON line.
pub fn child_main(spec_json: &str) -> Result<String, ScaleError> {
    let spec: RunSpec = serde_json::from_str(spec_json).map_err(|source| ScaleError::Json {
        what: format!("run spec {spec_json:?}"),
        source,
    })?;
    let result = run_one(&spec)?;
    serde_json::to_string(&result).map_err(|source| ScaleError::Json {
        what: "run result".into(),
        source,
    })
}

/// Run `spec` in a child process: `exe scale --child SPEC`, reading its one JSON line.
pub fn run_child(exe: &Path, spec: &RunSpec) -> Result<RunResult, ScaleError> {
    let json = serde_json::to_string(spec).map_err(|source| ScaleError::Json {
        what: "run spec".into(),
        source,
    })?;
    let out = Command::new(exe)
        .args(["scale", CHILD_ARG, &json])
        .output()
        .map_err(|source| ScaleError::Spawn {
            exe: exe.to_owned(),
            source,
        })?;
    let stdout = String::from_utf8_lossy(&out.stdout);
    let line = stdout
        .lines()
        .rev()
        .find(|l| l.trim_start().starts_with('{'));
    let fail = |status: String| {
        let stderr = String::from_utf8_lossy(&out.stderr);
        let tail: Vec<&str> = stderr.lines().rev().take(20).collect();
        ScaleError::Child {
            spec: json.clone(),
            status,
            stderr: tail.into_iter().rev().collect::<Vec<_>>().join("\n"),
        }
    };
    if !out.status.success() {
        return Err(fail(out.status.to_string()));
    }
    let Some(line) = line else {
        return Err(fail("no result line".into()));
    };
    serde_json::from_str(line).map_err(|source| ScaleError::Json {
        what: format!("result of {json}"),
        source,
    })
}

/// A target of the issue and whether the run met it.
#[derive(Debug, Clone, PartialEq)]
pub struct TargetCheck {
    /// What is measured, e.g. `N = 100,000 exact, 2 threads: step p50`.
    pub what: String,
    /// The measured value.
    pub value: f64,
    /// The limit.
    pub limit: f64,
    /// Unit of both.
    pub unit: &'static str,
    /// `value <= limit` (`value >= limit` when `at_least`).
    pub met: bool,
    /// The limit is a lower bound.
    pub at_least: bool,
}

/// The spread of one configuration's repeated runs: the least and greatest step p50 and p99 (ms).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spread {
    /// Runs of the configuration.
    pub runs: usize,
    /// Step p50, least and greatest.
    pub p50: [f64; 2],
    /// Step p99, least and greatest.
    pub p99: [f64; 2],
}

/// One row per configuration from `runs`, the results of `rounds` whole plans of `plan_len`
/// configurations, round after round: each configuration's run with the median step p50 (the
/// slower of the middle two for an even count, so that two rounds never report the better run
/// alone; a real run, so its columns belong together), and
/// the spread of its runs (None for a single run).
pub fn median_runs(plan_len: usize, runs: &[RunResult]) -> (Vec<RunResult>, Vec<Option<Spread>>) {
    let mut rows = Vec::with_capacity(plan_len);
    let mut spreads = Vec::with_capacity(plan_len);
    for i in 0..plan_len.min(runs.len()) {
        let mut mine: Vec<&RunResult> = runs.iter().skip(i).step_by(plan_len).collect();
        mine.sort_by(|a, b| a.step_p50_ms.total_cmp(&b.step_p50_ms));
        rows.push(mine[mine.len() / 2].clone());
        let range = |f: fn(&RunResult) -> f64| {
            let v = mine.iter().map(|r| f(r));
            [
                v.clone().fold(f64::INFINITY, f64::min),
                v.fold(f64::NEG_INFINITY, f64::max),
            ]
        };
        spreads.push((mine.len() > 1).then(|| Spread {
            runs: mine.len(),
            p50: range(|r| r.step_p50_ms),
            p99: range(|r| r.step_p99_ms),
        }));
    }
    (rows, spreads)
}

/// What a scale run produced.
#[derive(Debug, Clone, Default)]
pub struct ScaleOutput {
    /// One row per configuration, in plan order: its run, or with several rounds its median run
    /// (see [`median_runs`]).
    pub results: Vec<RunResult>,
    /// With several rounds, each row's spread over its rounds (aligned with `results`).
    pub spreads: Vec<Option<Spread>>,
    /// Every run, in the order run (`RunResult::round` says which round).
    pub runs: Vec<RunResult>,
    /// Load averages (1, 5, 15 min) before the first run and after the last.
    pub load_start: Option<[f64; 3]>,
    /// See `load_start`.
    pub load_end: Option<[f64; 3]>,
    /// The processor the runs measured.
    pub machine: Machine,
    /// Wall time of the whole command (s).
    pub wall_s: f64,
    /// Files written.
    pub files: Vec<PathBuf>,
}

impl ScaleOutput {
    /// The run with the engine's own broad-phase choice.
    fn find(&self, n: u32, threads: u32, exact: bool) -> Option<&RunResult> {
        self.results.iter().find(|r| {
            r.spec.broad_phase == BroadPhaseKind::Auto
                && r.spec.n == n
                && r.spec.threads == threads
                && (r.spec.mode == Mode::Exact) == exact
        })
    }

    /// The baseline run of `spec`'s N and mode: the explicit sweep-and-prune run, or else the
    /// 1-thread run when that is the baseline itself.
    pub fn baseline_of(&self, spec: &RunSpec) -> Option<&RunResult> {
        let same = |r: &&RunResult| r.spec.n == spec.n && r.spec.mode == spec.mode;
        let explicit = |r: &&RunResult| r.spec.broad_phase == BroadPhaseKind::SweepAndPrune;
        let runs = || self.results.iter().filter(same);
        runs()
            .filter(|r| r.spec.is_baseline())
            .find(explicit)
            .or_else(|| runs().find(|r| r.spec.is_baseline()))
    }

    /// The targets that this run's configurations can answer (2-thread rows unless a
    /// target names one thread; budget targets only when the budget is the issue's).
    pub fn targets(&self) -> Vec<TargetCheck> {
        let mut out = Vec::new();
        let mut check = |what: String, value: f64, limit: f64, unit, at_least: bool| {
            let met = if at_least {
                value >= limit
            } else {
                value <= limit
            };
            out.push(TargetCheck {
                what,
                value,
                limit,
                unit,
                met,
                at_least,
            });
        };
        let budget_is = |r: &RunResult, ms: f64| r.spec.mode == Mode::BudgetMs(ms);
        if let Some(r) = self.find(10_000, 2, true) {
            check(
                "N = 10,000 exact, 2 threads: step p50".into(),
                r.step_p50_ms,
                2.0,
                "ms",
                false,
            );
        }
        if let Some(r) = self.find(100_000, 2, true) {
            check(
                "N = 100,000 exact, 2 threads: step p50".into(),
                r.step_p50_ms,
                25.0,
                "ms",
                false,
            );
            if let Some(one) = self.find(100_000, 1, true) {
                check(
                    "N = 100,000 exact: 2-thread speed-up (p50, 1 thread / 2 threads)".into(),
                    one.step_p50_ms / r.step_p50_ms,
                    1.7,
                    "x",
                    true,
                );
            }
        }
        if let Some(r) = self.find(100_000, 2, false).filter(|r| budget_is(r, 16.0)) {
            check(
                "N = 100,000, 16 ms budget, 2 threads: step p99".into(),
                r.step_p99_ms,
                16.7,
                "ms",
                false,
            );
            check(
                "N = 100,000, 16 ms budget, 2 threads: frames with every pair within 5° settled exactly".into(),
                100.0 * r.foveal_exact_share,
                99.0,
                "%",
                true,
            );
        }
        if let Some(r) = self
            .find(1_000_000, 2, false)
            .filter(|r| budget_is(r, 50.0))
        {
            check(
                "N = 1,000,000, 50 ms budget, 2 threads: step p99".into(),
                r.step_p99_ms,
                52.0,
                "ms",
                false,
            );
        }
        if let Some(r) = self.find(1_000_000, 2, true) {
            check(
                "N = 1,000,000 exact, 2 threads: step p50".into(),
                r.step_p50_ms,
                250.0,
                "ms",
                false,
            );
        }
        let rss_1m = self
            .results
            .iter()
            .filter(|r| {
                r.spec.n == 1_000_000
                    && r.spec.mode == Mode::Exact
                    && r.spec.broad_phase == BroadPhaseKind::Auto
            })
            .map(|r| r.peak_rss_kib)
            .max();
        if let Some(kib) = rss_1m {
            check(
                "N = 1,000,000 exact: peak RSS (largest over thread counts)".into(),
                kib as f64 / 1024.0,
                600.0,
                "MiB",
                false,
            );
        }
        if let Some(r) = self.find(1_000_000, 1, true) {
            check(
                "N = 1,000,000 exact, 1 thread: broad phase per body".into(),
                r.broad_ns_per_body,
                40.0,
                "ns",
                false,
            );
        }
        // A budget buys at least nine tenths of the settled pairs per millisecond the exact
        // pass does, on as many threads (the target at every N).
        for n in [10_000, 100_000, 1_000_000] {
            for threads in [1, 2] {
                let (Some(exact), Some(budget)) =
                    (self.find(n, threads, true), self.find(n, threads, false))
                else {
                    continue;
                };
                check(
                    format!(
                        "N = {}, {}, {threads} thread{}: settled pairs per narrow-phase ms, over the exact run's",
                        grouped(n),
                        budget.spec.mode.label(),
                        if threads == 1 { "" } else { "s" }
                    ),
                    budget.settled_per_ms / exact.settled_per_ms,
                    0.9,
                    "x",
                    true,
                );
            }
        }
        let worst_measure = self
            .results
            .iter()
            .filter(|r| r.spec.broad_phase == BroadPhaseKind::Auto)
            .filter_map(|r| {
                let share = r.phase_share.iter().find(|(k, _)| k == "measure")?.1;
                Some((share, r))
            })
            .max_by(|a, b| a.0.total_cmp(&b.0));
        if let Some((share, r)) = worst_measure {
            check(
                format!(
                    "metrics share of the step, worst run (N = {}, {}, threads = {})",
                    r.spec.n,
                    r.spec.mode.label(),
                    r.spec.threads
                ),
                100.0 * share,
                5.0,
                "%",
                false,
            );
        }
        out
    }
}

/// Every phase name of `results`, in pipeline order.
fn phase_names(results: &[RunResult]) -> Vec<String> {
    let mut names: Vec<String> = Vec::new();
    for r in results {
        for (k, _) in &r.phase_share {
            if !names.contains(k) {
                names.push(k.clone());
            }
        }
    }
    names
}

pub fn fmt_load(l: Option<[f64; 3]>) -> String {
    l.map_or("unavailable".into(), |l| {
        format!("{:.2} {:.2} {:.2}", l[0], l[1], l[2])
    })
}

/// Thousands separators, for N in tables.
pub fn grouped(n: u32) -> String {
    let s = n.to_string();
    let mut out = String::new();
    for (i, c) in s.chars().enumerate() {
        if i > 0 && (s.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}

/// The results as a markdown table, with the protocol, load averages and the targets.
pub fn markdown(out: &ScaleOutput) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "Paper scene (seed {}, truth {}, tree {}), scheduler {}{}, fixation at the screen centre, wall clock. Whole step = \
         `Instant` around `Simulation::step` (p99 nearest rank: the maximum below 100 frames); \
         phase shares = phase totals from `FrameReport.profile` over total step time; foveal exact = \
         frames in which no pair within 5° of the fixation was deemed and every region that may hold \
         one was searched; stale = frames in which a whole-frame budget left broad-phase regions \
         unsearched (mean stale regions of all regions, and the pairs they held). Each run in its own \
         process; RSS is its peak (`VmHWM`). Previous engine = the same N and mode with one thread \
         and the sweep-and-prune broad phase (the engine before threads and the grid; its other \
         phases are today's).\n",
        out.results.first().map_or(1, |r| r.spec.seed),
        out.results.first().map_or("-", |r| r.spec.truth.name()),
        out.results.first().map_or("-", |r| r.spec.tree.name()),
        out.results.first().map_or("-", |r| r.spec.scheduler.name()),
        if out.results.first().is_some_and(|r| r.spec.fovea_first) {
            " (fovea first)"
        } else {
            ""
        }
    );
    let rounds = out.spreads.iter().flatten().map(|sp| sp.runs).max();
    if let Some(k) = rounds {
        let _ = writeln!(
            s,
            "Each configuration was run {k} times: the whole plan once per round, one round after \
             another, so that a drift of the machine reaches every configuration alike. Each row is \
             the run with the median step p50 of its {k} (the slower of the middle two for an even \
             count: a real run, whose columns belong together); the targets read those rows; the \
             spread column gives the least and greatest step p50 and p99 over the {k} runs; \
             `scale.csv` holds every run with its round.\n"
        );
    }
    let _ = writeln!(s, "Machine: {}.\n", out.machine);
    let _ = writeln!(
        s,
        "Load average (1/5/15 min): {} at start, {} at end; {} runs in {:.0} s.\n",
        fmt_load(out.load_start),
        fmt_load(out.load_end),
        out.runs.len().max(out.results.len()),
        out.wall_s
    );
    let names = phase_names(&out.results);
    let _ = write!(
        s,
        "| N | mode | threads | broad phase | warm-up + frames | step p50 (ms) | step p99 (ms) |"
    );
    if let Some(k) = rounds {
        let _ = write!(s, " {k} runs: p50 / p99 least-greatest (ms) |");
    }
    let _ = write!(s, " previous engine p50 / p99 (ms) | phases p50 (ms) |");
    for k in &names {
        let _ = write!(s, " {k} |");
    }
    let _ = writeln!(
        s,
        " step ns/body | broad ns/body | peak RSS (MiB) | foveal exact | foveal pairs/frame | candidates/frame | deemed/frame | settled pairs per narrow ms | exact-pass frames | stale frames | stale regions | stale pairs/frame |"
    );
    let _ = write!(s, "|---|---|---|---|---|---|---|---|---|");
    if rounds.is_some() {
        s.push_str("---|");
    }
    for _ in &names {
        let _ = write!(s, "---|");
    }
    let _ = writeln!(s, "---|---|---|---|---|---|---|---|---|---|---|---|");
    for (i, r) in out.results.iter().enumerate() {
        let previous = match out.baseline_of(&r.spec) {
            Some(b) if b.spec == r.spec => "(this run)".to_string(),
            Some(b) => format!("{:.2} / {:.2}", b.step_p50_ms, b.step_p99_ms),
            None => "–".to_string(),
        };
        let _ = write!(
            s,
            "| {} | {} | {} | {} | {} + {} | {:.2} | {:.2} |",
            grouped(r.spec.n),
            r.spec.mode.label(),
            r.spec.threads,
            r.spec.broad_label(),
            r.spec.warmup,
            r.spec.frames,
            r.step_p50_ms,
            r.step_p99_ms,
        );
        if rounds.is_some() {
            match out.spreads.get(i).copied().flatten() {
                Some(sp) => {
                    let _ = write!(
                        s,
                        " {:.2}-{:.2} / {:.2}-{:.2} |",
                        sp.p50[0], sp.p50[1], sp.p99[0], sp.p99[1]
                    );
                }
                None => s.push_str(" – |"),
            }
        }
        let _ = write!(s, " {} | {:.2} |", previous, r.phases_p50_ms);
        for k in &names {
            match r.phase_share.iter().find(|(name, _)| name == k) {
                Some((_, share)) => {
                    let _ = write!(s, " {:.1}% |", 100.0 * share);
                }
                None => s.push_str(" – |"),
            }
        }
        let _ = writeln!(
            s,
            " {:.1} | {:.1} | {:.0} | {:.1}% | {:.1} | {:.0} | {:.0} | {:.0} | {:.1}% | {:.1}% | {:.1} of {} | {:.0} |",
            r.step_ns_per_body,
            r.broad_ns_per_body,
            r.peak_rss_kib as f64 / 1024.0,
            100.0 * r.foveal_exact_share,
            r.foveal_pairs_mean,
            r.candidates_mean,
            r.deemed_mean,
            r.settled_per_ms,
            100.0 * r.exact_fit_share,
            100.0 * r.stale_share,
            r.stale_regions_mean,
            r.regions,
            r.stale_pairs_mean
        );
    }
    let targets = out.targets();
    if !targets.is_empty() {
        let _ = writeln!(
            s,
            "\n| target | measured | limit | met |\n|---|---|---|---|"
        );
        for t in &targets {
            let _ = writeln!(
                s,
                "| {} | {:.2} {} | {} {} {} | {} |",
                t.what,
                t.value,
                t.unit,
                if t.at_least { ">=" } else { "<=" },
                t.limit,
                t.unit,
                if t.met { "**met**" } else { "missed" }
            );
        }
    }
    s
}

/// One CSV row per run.
pub fn csv(results: &[RunResult]) -> String {
    let names = phase_names(results);
    let mut s = String::from(
        "n,mode,budget_ms,threads,broad_phase,baseline,seed,warmup,frames,step_p50_ms,step_p99_ms,step_mean_ms,step_max_ms,phases_p50_ms",
    );
    for k in &names {
        let _ = write!(s, ",share_{k}");
    }
    s.push_str(
        ",step_ns_per_body,broad_ns_per_body,peak_rss_kib,foveal_exact_share,foveal_pairs_mean,\
         candidates_mean,deemed_mean,sphere_tests_mean,setup_s,warmup_s,load1_start,scheduler,\
         stale_share,stale_regions_mean,regions,stale_pairs_mean,round,settled_per_ms,exact_fit_share\n",
    );
    let opt = |v: Option<f64>| v.map_or(String::new(), |v| v.to_string());
    for r in results {
        let _ = write!(
            s,
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
            r.spec.n,
            r.spec.mode.kind(),
            opt(r.spec.mode.budget_ms()),
            r.spec.threads,
            r.spec.broad_phase.resolve(r.spec.n as usize).name(),
            r.spec.is_baseline(),
            r.spec.seed,
            r.spec.warmup,
            r.spec.frames,
            r.step_p50_ms,
            r.step_p99_ms,
            r.step_mean_ms,
            r.step_max_ms,
            r.phases_p50_ms
        );
        for k in &names {
            let share = r.phase_share.iter().find(|(name, _)| name == k);
            let _ = write!(s, ",{}", opt(share.map(|(_, v)| *v)));
        }
        let _ = writeln!(
            s,
            ",{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
            r.step_ns_per_body,
            r.broad_ns_per_body,
            r.peak_rss_kib,
            r.foveal_exact_share,
            r.foveal_pairs_mean,
            r.candidates_mean,
            r.deemed_mean,
            r.sphere_tests_mean,
            r.setup_s,
            r.warmup_s,
            opt(r.load1_start),
            r.spec.scheduler.name(),
            r.stale_share,
            r.stale_regions_mean,
            r.regions,
            r.stale_pairs_mean,
            r.round,
            r.settled_per_ms,
            r.exact_fit_share
        );
    }
    s
}

/// The narrow phase's passes in `frames.csv`'s columns (`FrameReport::passes`).
const PASSES: [&str; 5] = ["reset", "roots", "fovea", "ordering", "rest"];

/// One CSV row per measured frame of every run: the run's configuration and round, the frame's
/// place in the run (0-based, after the warm-up), its whole step and each profiled phase (ms),
/// deemed pairs, stale regions, sphere tests, the guard band it aimed early by (ms), whether
/// every pair within 5 degrees of the fixation was settled exactly, and each narrow-phase pass's
/// time (ms) and sphere tests.
pub fn frames_csv(results: &[RunResult]) -> String {
    let names = phase_names(results);
    let mut s = String::from("n,mode,budget_ms,threads,broad_phase,baseline,round,frame,step_ms");
    for k in &names {
        let _ = write!(s, ",{k}_ms");
    }
    s.push_str(",deemed,stale_regions,sphere_tests,guard_ms,foveal_exact,exact_fit");
    for pass in PASSES {
        let _ = write!(s, ",{pass}_ms,{pass}_tests");
    }
    s.push('\n');
    for r in results {
        // Where each named phase sits in this run's frames.
        let at: Vec<Option<usize>> = names
            .iter()
            .map(|k| r.phase_share.iter().position(|(name, _)| name == k))
            .collect();
        for (i, f) in r.frame_trace.iter().enumerate() {
            let _ = write!(
                s,
                "{},{},{},{},{},{},{},{},{}",
                r.spec.n,
                r.spec.mode.kind(),
                r.spec
                    .mode
                    .budget_ms()
                    .map_or(String::new(), |v| v.to_string()),
                r.spec.threads,
                r.spec.broad_phase.resolve(r.spec.n as usize).name(),
                r.spec.is_baseline(),
                r.round,
                i,
                f.step_ms
            );
            for ns in at.iter().map(|at| at.and_then(|at| f.phases_ns.get(at))) {
                let _ = write!(
                    s,
                    ",{}",
                    ns.map_or(String::new(), |ns| (*ns as f64 * 1e-6).to_string())
                );
            }
            let _ = write!(
                s,
                ",{},{},{},{},{},{}",
                f.deemed,
                f.stale_regions,
                f.sphere_tests,
                f.guard_ns as f64 * 1e-6,
                f.foveal_exact,
                f.exact_fit
            );
            let p = &f.passes;
            for pass in [p.reset, p.roots, p.fovea, p.ordering, p.rest] {
                let _ = write!(s, ",{},{}", pass.ns as f64 * 1e-6, pass.tests);
            }
            s.push('\n');
        }
    }
    s
}

/// Run every configuration of `cfg`, each in a child process of `exe` (the `foveal-bench`
/// binary), and write `scale.csv`, `frames.csv` and `scale.md` under `cfg.out`. `progress` prints one line per
/// run to stderr.
pub fn run(cfg: &ScaleConfig, exe: &Path, progress: bool) -> Result<ScaleOutput, ScaleError> {
    cfg.validate()?;
    std::fs::create_dir_all(&cfg.out).map_err(|e| ScaleError::io(&cfg.out, e))?;
    let started = Instant::now();
    let mut out = ScaleOutput {
        load_start: load_average(),
        machine: Machine::this(),
        ..ScaleOutput::default()
    };
    let plan = cfg.plan();
    let total = plan.len() * cfg.repeat as usize;
    let rounds = (1..=cfg.repeat).flat_map(|round| plan.iter().map(move |spec| (round, spec)));
    for (i, (round, spec)) in rounds.enumerate() {
        let t = Instant::now();
        let mut r = run_child(exe, spec)?;
        r.round = round;
        if progress {
            eprintln!(
                "[{}/{}] N={} {} threads={} broad={}: step p50 {:.2} ms, p99 {:.2} ms, RSS {:.0} MiB ({:.0} s)",
                i + 1,
                total,
                spec.n,
                spec.mode.label(),
                spec.threads,
                spec.broad_label(),
                r.step_p50_ms,
                r.step_p99_ms,
                r.peak_rss_kib as f64 / 1024.0,
                t.elapsed().as_secs_f64()
            );
        }
        out.runs.push(r);
    }
    out.load_end = load_average();
    out.wall_s = started.elapsed().as_secs_f64();
    (out.results, out.spreads) = median_runs(plan.len(), &out.runs);
    let csv_path = cfg.out.join("scale.csv");
    std::fs::write(&csv_path, csv(&out.runs)).map_err(|e| ScaleError::io(&csv_path, e))?;
    let md_path = cfg.out.join("scale.md");
    let md = format!("# foveal-bench scale\n\n{}", markdown(&out));
    std::fs::write(&md_path, md).map_err(|e| ScaleError::io(&md_path, e))?;
    let frames_path = cfg.out.join("frames.csv");
    std::fs::write(&frames_path, frames_csv(&out.runs))
        .map_err(|e| ScaleError::io(&frames_path, e))?;
    out.files = vec![csv_path, frames_path, md_path];
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_processor_model_is_read_from_the_first_processor_of_cpuinfo() {
        let text = "processor\t: 0\nvendor_id\t: GenuineIntel\ncpu family\t: 6\n\
                    model\t\t: 207\nmodel name\t: Intel(R) Xeon(R)   Processor\n\
                    cpu MHz\t\t: 2100.000\n\n\
                    processor\t: 1\ncpu family\t: 7\nmodel\t\t: 1\nmodel name\t: Other\n";
        assert_eq!(
            cpu_model(text).as_deref(),
            Some("Intel(R) Xeon(R) Processor (family 6, model 207)")
        );
        // Without the numbers, the name alone; not the next processor's numbers.
        let named = "processor\t: 0\nmodel name\t: Some CPU\n\nprocessor\t: 1\n\
                     cpu family\t: 7\nmodel\t\t: 1\n";
        assert_eq!(cpu_model(named).as_deref(), Some("Some CPU"));
        // `model` alone is not the model's name, and an empty name is none.
        assert_eq!(cpu_model("model\t\t: 207\nmodel name\t:   \n"), None);
        assert_eq!(cpu_model(""), None);
        let m = Machine {
            model: None,
            logical: 2,
            avx512: true,
        };
        assert_eq!(
            m.to_string(),
            "processor model unavailable, 2 logical processors, AVX-512 yes"
        );
    }

    #[test]
    fn percentiles_are_nearest_rank() {
        let v: Vec<f64> = (1..=200).map(f64::from).collect();
        assert_eq!(percentile(&v, 0.5), 100.0);
        assert_eq!(percentile(&v, 0.99), 198.0);
        assert_eq!(percentile(&v[..40], 0.99), 40.0);
        assert!(percentile(&[], 0.5).is_nan());
    }

    #[test]
    fn phases_come_in_pipeline_order() {
        let names: Vec<String> = phases(&PhaseProfile::default())
            .into_iter()
            .map(|(k, _)| k)
            .collect();
        let known: Vec<&str> = PHASE_ORDER
            .iter()
            .copied()
            .filter(|k| names.iter().any(|n| n == k))
            .collect();
        assert_eq!(&names[..known.len()], known.as_slice());
        for k in ["integrate", "broad", "narrow", "response", "measure"] {
            assert!(names.iter().any(|n| n == k), "{k} missing from {names:?}");
        }
    }

    /// A run keeps every measured frame, and `frames.csv` gives each its own row: the step the
    /// run's percentiles were taken from, each phase under its own column, in the run's order.
    #[test]
    fn every_measured_frame_is_traced_and_written_out() {
        let spec = RunSpec {
            n: 1_500,
            threads: 1,
            broad_phase: BroadPhaseKind::Auto,
            mode: Mode::BudgetMs(4.0),
            scheduler: SchedulerKind::Priced,
            fovea_first: false,
            truth: Truth::Shape,
            tree: TreeKind::Parts,
            seed: 3,
            warmup: 2,
            frames: 7,
            viewer: None,
            steer_centre: false,
            audit: false,
        };
        let mut r = run_one(&spec).expect("a small run");
        r.round = 2;
        assert_eq!(r.frame_trace.len(), 7);
        let mut steps: Vec<f64> = r.frame_trace.iter().map(|f| f.step_ms).collect();
        steps.sort_by(f64::total_cmp);
        assert_eq!(r.step_max_ms, steps[6]);
        assert_eq!(r.step_p50_ms, steps[3]);
        let csv = frames_csv(std::slice::from_ref(&r));
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines.len(), 1 + 7, "{csv}");
        let header: Vec<&str> = lines[0].split(',').collect();
        let col = |name: &str| {
            header
                .iter()
                .position(|h| *h == name)
                .unwrap_or_else(|| panic!("{name} missing from {header:?}"))
        };
        let broad_at = r.phase_share.iter().position(|(k, _)| k == "broad");
        let broad_at = broad_at.expect("a broad phase");
        for (i, line) in lines[1..].iter().enumerate() {
            let cells: Vec<&str> = line.split(',').collect();
            assert_eq!(cells.len(), header.len(), "{line}");
            assert_eq!(cells[col("frame")], i.to_string());
            assert_eq!(cells[col("round")], "2");
            assert_eq!(cells[col("mode")], "budget");
            let f = &r.frame_trace[i];
            assert_eq!(cells[col("step_ms")].parse::<f64>().ok(), Some(f.step_ms));
            let broad_ms: f64 = cells[col("broad_ms")].parse().expect("a number");
            assert!((broad_ms - f.phases_ns[broad_at] as f64 * 1e-6).abs() < 1e-9);
            assert_eq!(cells[col("deemed")], f.deemed.to_string());
            let guard_ms: f64 = cells[col("guard_ms")].parse().expect("a number");
            assert!((guard_ms - f.guard_ns as f64 * 1e-6).abs() < 1e-12);
            assert_eq!(cells[col("foveal_exact")], f.foveal_exact.to_string());
            assert_eq!(cells[col("exact_fit")], f.exact_fit.to_string());
            // The passes' tests add up to the frame's.
            let tests: u64 = PASSES
                .iter()
                .map(|p| {
                    cells[col(&format!("{p}_tests"))]
                        .parse::<u64>()
                        .expect("a count")
                })
                .sum();
            assert_eq!(tests, f.sphere_tests, "{line}");
        }
        // Budgeted runs above 30,000 bodies measure more frames than exact ones, so that their
        // p99 is not one or two stalled frames.
        let frames = |n, mode| default_frames(n, false, mode);
        assert_eq!(
            frames(10_000, Mode::Exact),
            frames(10_000, Mode::BudgetMs(4.0))
        );
        assert_eq!(
            [
                frames(100_000, Mode::Exact),
                frames(100_000, Mode::BudgetMs(16.0))
            ],
            [200, 600]
        );
        assert_eq!(
            [
                frames(1_000_000, Mode::Exact),
                frames(1_000_000, Mode::BudgetMs(50.0))
            ],
            [20, 200]
        );
    }

    /// A result of `spec` whose step p50 and p99 are `p50` and `p99`.
    fn result(spec: &RunSpec, p50: f64, p99: f64, round: u32) -> RunResult {
        RunResult {
            spec: spec.clone(),
            step_p50_ms: p50,
            step_p99_ms: p99,
            step_mean_ms: p50,
            step_max_ms: p99,
            phases_p50_ms: p50,
            phase_share: Vec::new(),
            step_ns_per_body: 0.0,
            broad_ns_per_body: 0.0,
            peak_rss_kib: 0,
            foveal_exact_share: 1.0,
            stale_share: 0.0,
            stale_regions_mean: 0.0,
            regions: 0,
            stale_pairs_mean: 0.0,
            foveal_pairs_mean: 0.0,
            foveal_stale_mean: 0.0,
            candidates_mean: 0.0,
            deemed_mean: 0.0,
            sphere_tests_mean: 0.0,
            settled_per_ms: 0.0,
            exact_fit_share: 0.0,
            true_p_mean: None,
            setup_s: 0.0,
            warmup_s: 0.0,
            load1_start: None,
            round,
            frame_trace: Vec::new(),
        }
    }

    /// Each configuration's row is its run with the median p50, whole (its p99 is that run's,
    /// not the median p99), the slower middle one for an even count; the spread covers every run
    /// of the configuration and no other's; one round has no spread.
    #[test]
    fn repeated_runs_give_each_configuration_its_median_run() {
        let plan = ScaleConfig {
            ns: vec![1_000],
            threads: vec![1],
            ..ScaleConfig::default()
        }
        .plan();
        assert_eq!(plan.len(), 2, "exact and budgeted");
        let (a, b) = (&plan[0], &plan[1]);
        // Three rounds: a's p50 3, 1, 2 (median 2, from round 3, p99 9); b's 10, 30, 20.
        let runs = vec![
            result(a, 3.0, 4.0, 1),
            result(b, 10.0, 11.0, 1),
            result(a, 1.0, 50.0, 2),
            result(b, 30.0, 31.0, 2),
            result(a, 2.0, 9.0, 3),
            result(b, 20.0, 21.0, 3),
        ];
        let (rows, spreads) = median_runs(plan.len(), &runs);
        assert_eq!(rows.len(), 2);
        assert_eq!(
            (rows[0].spec.clone(), rows[0].step_p50_ms),
            (a.clone(), 2.0)
        );
        assert_eq!((rows[0].step_p99_ms, rows[0].round), (9.0, 3));
        assert_eq!((rows[1].step_p50_ms, rows[1].round), (20.0, 3));
        let expect = |p50, p99| Some(Spread { runs: 3, p50, p99 });
        assert_eq!(spreads[0], expect([1.0, 3.0], [4.0, 50.0]));
        assert_eq!(spreads[1], expect([10.0, 30.0], [11.0, 31.0]));
        // Two rounds: the slower of the two.
        let (rows, _) = median_runs(plan.len(), &runs[..4]);
        assert_eq!((rows[0].step_p50_ms, rows[1].step_p50_ms), (3.0, 30.0));
        // One round: the runs themselves, no spread.
        let (rows, spreads) = median_runs(plan.len(), &runs[..2]);
        assert_eq!(rows, runs[..2].to_vec());
        assert_eq!(spreads, vec![None, None]);
    }

    #[test]
    fn plan_and_validation() {
        let cfg = ScaleConfig::default();
        let plan = cfg.plan();
        // Two modes x two thread counts per N, plus a sweep-and-prune baseline per mode where the
        // engine picks the grid.
        let baselines = plan
            .iter()
            .filter(|s| s.broad_phase == BroadPhaseKind::SweepAndPrune)
            .count();
        assert_eq!(plan.len(), 3 * 2 * 2 + baselines);
        assert!(
            plan.iter()
                .all(|s| s.broad_phase == BroadPhaseKind::Auto || s.threads == 1)
        );
        for (n, ms) in [(10_000, 4.0), (100_000, 16.0), (1_000_000, 50.0)] {
            let modes: Vec<Mode> = plan.iter().filter(|s| s.n == n).map(|s| s.mode).collect();
            assert!(modes.contains(&Mode::Exact) && modes.contains(&Mode::BudgetMs(ms)));
            let base = plan.iter().filter(|s| s.n == n && s.is_baseline()).count();
            assert_eq!(base, 2, "one baseline per mode at N = {n}");
        }
        cfg.validate().expect("defaults valid");
        let bad = ScaleConfig {
            budget_ms: vec![1.0, 2.0],
            ..ScaleConfig::default()
        };
        assert!(bad.validate().is_err());
        let bad = ScaleConfig {
            threads: vec![0],
            ..ScaleConfig::default()
        };
        assert!(matches!(bad.validate(), Err(ScaleError::Config(_))));
        for repeat in [0, MAX_REPEAT + 1] {
            let bad = ScaleConfig {
                repeat,
                ..ScaleConfig::default()
            };
            match bad.validate() {
                Err(ScaleError::Invalid(m)) => assert!(m.contains("repeat"), "{m}"),
                other => panic!("repeat {repeat}: {other:?}"),
            }
        }
        assert_eq!(grouped(1_000_000), "1,000,000");
        assert_eq!(grouped(999), "999");
    }
}
