//! Runs the plan: one [`Simulation`] per run, stepped with an `Instant` clock and the run's gaze, its
//! per-frame records written as CSV (the paper's section 4 record, plus the audit's true values) and
//! summarised.

use std::collections::HashMap;
use std::fs::File;
use std::io::{BufWriter, IsTerminal, Write};
use std::path::Path;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use foveal_engine::{BudgetSpec, FrameReport, FrozenClock, SchedulerKind, Simulation};
use indicatif::{ProgressBar, ProgressStyle};

use crate::clock::InstantClock;
use crate::error::BenchError;
use crate::gaze::{Gaze, RecordedGaze, ScriptedGaze};
use crate::protocol::{GazeSpec, RunSpec, StudyConfig};
use crate::stats::Accum;

/// Header of the per-frame CSV.
pub const FRAME_HEADER: &str = "frame,sim_time_s,fix_x,fix_y,fix_age_s,t_ms,broad_ms,narrow_ms,response_ms,\
delta,p,true_delta,true_p,false_positives,true_positives,candidate_pairs,real_collisions,deemed,\
sphere_tests,budget_exhausted,resolved_l1,resolved_l2,resolved_l3,resolved_l4,resolved_l5,resolved_l6";

/// Per-run summary over its frames.
#[derive(Debug, Clone)]
pub struct RunSummary {
    /// The run.
    pub spec: RunSpec,
    /// Mean exact narrow-phase cost (sphere tests per frame) measured for this N and seed.
    pub exact_cost: f64,
    /// The per-frame sphere-test budget in force (None: exact or wall clock).
    pub budget_tests: Option<u64>,
    /// T, collision-handling time (ms).
    pub t_ms: Accum,
    /// Narrow phase alone (ms).
    pub narrow_ms: Accum,
    /// Estimated geometric inaccuracy Δ.
    pub delta: Accum,
    /// Estimated perceived inaccuracy P.
    pub p: Accum,
    /// True Δ (audit).
    pub true_delta: Accum,
    /// True P (audit).
    pub true_p: Accum,
    /// Deemed pairs that do not collide.
    pub false_positives: Accum,
    /// Deemed pairs.
    pub deemed: Accum,
    /// Candidate pairs.
    pub candidates: Accum,
    /// Real collisions found.
    pub real: Accum,
    /// Sphere tests.
    pub tests: Accum,
    /// Fraction of frames whose budget ran out.
    pub exhausted: Accum,
    /// Wall time of the run (s), including audit and I/O.
    pub wall_s: f64,
}

impl RunSummary {
    fn new(spec: RunSpec, exact_cost: f64, budget: BudgetSpec) -> Self {
        let budget_tests = match budget {
            BudgetSpec::InterruptAtZero => Some(0),
            BudgetSpec::SphereTests(t) => Some(t),
            _ => None,
        };
        Self {
            spec,
            exact_cost,
            budget_tests,
            t_ms: Accum::default(),
            narrow_ms: Accum::default(),
            delta: Accum::default(),
            p: Accum::default(),
            true_delta: Accum::default(),
            true_p: Accum::default(),
            false_positives: Accum::default(),
            deemed: Accum::default(),
            candidates: Accum::default(),
            real: Accum::default(),
            tests: Accum::default(),
            exhausted: Accum::default(),
            wall_s: 0.0,
        }
    }

    fn push(&mut self, r: &FrameReport) {
        let audit = r.audit.unwrap_or_default();
        self.t_ms.push(r.profile.collision_ns() as f64 * 1e-6);
        self.narrow_ms.push(r.profile.narrow_ns as f64 * 1e-6);
        self.delta.push(r.geometric_inaccuracy);
        self.p.push(r.perceived_inaccuracy.unwrap_or(f64::NAN));
        self.true_delta.push(audit.geometric_inaccuracy);
        self.true_p
            .push(audit.perceived_inaccuracy.unwrap_or(f64::NAN));
        self.false_positives.push(f64::from(audit.false_positives));
        self.deemed.push(f64::from(r.deemed));
        self.candidates.push(f64::from(r.candidate_pairs));
        self.real.push(f64::from(r.real_collisions));
        self.tests.push(r.sphere_tests as f64);
        self.exhausted.push(f64::from(u8::from(r.budget_exhausted)));
    }
}

fn opt(v: Option<f64>) -> String {
    v.map(|x| format!("{x:.6}")).unwrap_or_default()
}

fn write_frame(w: &mut impl Write, r: &FrameReport) -> std::io::Result<()> {
    let ms = |ns: u64| ns as f64 * 1e-6;
    let (fx, fy, fa) = r
        .fixation
        .map(|f| (Some(f.x), Some(f.y), Some(f.age_s)))
        .unwrap_or_default();
    let a = r.audit;
    write!(
        w,
        "{},{:.5},{},{},{},{:.5},{:.5},{:.5},{:.5},{:.6},{},{},{},{},{},{},{},{},{},{}",
        r.index,
        r.sim_time,
        opt(fx),
        opt(fy),
        opt(fa),
        ms(r.profile.collision_ns()),
        ms(r.profile.broad_ns),
        ms(r.profile.narrow_ns),
        ms(r.profile.response_ns),
        r.geometric_inaccuracy,
        opt(r.perceived_inaccuracy),
        opt(a.map(|a| a.geometric_inaccuracy)),
        opt(a.and_then(|a| a.perceived_inaccuracy)),
        a.map(|a| a.false_positives.to_string()).unwrap_or_default(),
        a.map(|a| a.true_positives.to_string()).unwrap_or_default(),
        r.candidate_pairs,
        r.real_collisions,
        r.deemed,
        r.sphere_tests,
        u8::from(r.budget_exhausted),
    )?;
    for l in r.resolved_per_level {
        write!(w, ",{l}")?;
    }
    writeln!(w)
}

/// The gaze source of a run.
pub fn gaze_for(spec: &GazeSpec, seed: u64, recorded: Option<&RecordedGaze>) -> Gaze {
    match (spec, recorded) {
        (GazeSpec::Csv(_), Some(r)) => Gaze::Recorded(r.clone()),
        _ => Gaze::Scripted(ScriptedGaze::new(seed)),
    }
}

/// Mean exact narrow-phase cost (sphere tests per frame) of the scene of `spec` in its steady state:
/// the scene is run exactly for the warm-up frames, then the engine measures the next
/// `calibration_frames` frames (the measurement [`BudgetSpec::FractionOfExact`] makes, but after
/// the initial interpenetration has been resolved).
pub fn exact_cost(cfg: &StudyConfig, spec: &RunSpec) -> Result<f64, BenchError> {
    let mut c = cfg.sim_config(spec, 0.0);
    c.budget = BudgetSpec::Exact;
    c.scheduler = SchedulerKind::Sequential;
    c.audit = false;
    let mut sim = Simulation::new(c)?;
    for _ in 0..cfg.warmup_frames {
        sim.step(None, &FrozenClock);
    }
    Ok(sim.exact_cost(cfg.calibration_frames)?)
}

/// Run one simulation for `spec.frames` frames; write its frames to `frames_csv` if given.
pub fn run_one(
    cfg: &StudyConfig,
    spec: &RunSpec,
    exact_cost: f64,
    gaze: &mut Gaze,
    frames_csv: Option<&Path>,
    progress: &ProgressBar,
) -> Result<RunSummary, BenchError> {
    let started = Instant::now();
    let sim_cfg = cfg.sim_config(spec, exact_cost);
    let dt = sim_cfg.scene.dt;
    let mut summary = RunSummary::new(spec.clone(), exact_cost, sim_cfg.budget);
    let mut sim = Simulation::new(sim_cfg)?;
    let mut writer = match frames_csv {
        Some(path) => {
            let f = File::create(path).map_err(|e| BenchError::io(path, e))?;
            let mut w = BufWriter::new(f);
            writeln!(w, "{FRAME_HEADER}").map_err(|e| BenchError::io(path, e))?;
            Some((w, path))
        }
        None => None,
    };
    let clock = InstantClock::new();
    // Warm-up: same config and gaze, not recorded (see `StudyConfig::warmup_frames`).
    for i in 0..cfg.warmup_frames {
        sim.step(gaze.at(f64::from(i) * dt), &clock);
    }
    for i in 0..spec.frames {
        // The frame starts at the end of the previous one: its fixation is the gaze at that time.
        let fixation = gaze.at(f64::from(cfg.warmup_frames + i) * dt);
        sim.step(fixation, &clock);
        // A wall-clock frame may sample Δ and P to hold its budget; the study reports them whole.
        let r = sim.measure_exactly();
        summary.push(r);
        if let Some((w, path)) = writer.as_mut() {
            write_frame(w, r).map_err(|e| BenchError::io(path, e))?;
        }
        if i % 64 == 63 {
            progress.inc(64);
        }
    }
    progress.inc(u64::from(spec.frames % 64) + u64::from(cfg.warmup_frames));
    if let Some((mut w, path)) = writer {
        w.flush().map_err(|e| BenchError::io(path, e))?;
    }
    summary.wall_s = started.elapsed().as_secs_f64();
    Ok(summary)
}

/// A progress bar over `total` frames on stderr; hidden when disabled or stderr is not a terminal.
pub fn progress_bar(total: u64, enabled: bool) -> ProgressBar {
    if !enabled || !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let pb = ProgressBar::new(total);
    if let Ok(style) = ProgressStyle::with_template(
        "{elapsed_precise} [{bar:40}] {pos}/{len} frames, eta {eta} {msg}",
    ) {
        pb.set_style(style.progress_chars("=> "));
    }
    pb
}

/// Run every run of the plan: the table part in order on this thread (so T is not disturbed by a
/// sibling run), the curves part on `cfg.jobs` threads (its budgets are deterministic). Summaries
/// come back in plan order.
pub fn run_plan(cfg: &StudyConfig, plan: &[RunSpec]) -> Result<Vec<RunSummary>, BenchError> {
    let recorded = match &cfg.gaze {
        GazeSpec::Csv(path) => Some(RecordedGaze::from_csv(path)?),
        GazeSpec::Scripted => None,
    };
    let frames_dir = cfg.out.join("frames");
    if cfg.frame_csv {
        std::fs::create_dir_all(&frames_dir).map_err(|e| BenchError::io(&frames_dir, e))?;
    }
    let total: u64 = plan
        .iter()
        .map(|s| u64::from(s.frames + cfg.warmup_frames))
        .sum();
    let pb = progress_bar(total, cfg.progress);
    let mut costs: HashMap<(u32, u64), f64> = HashMap::new();
    for spec in plan {
        if let std::collections::hash_map::Entry::Vacant(e) = costs.entry((spec.n, spec.seed)) {
            pb.set_message(format!("calibrating N={} seed={}", spec.n, spec.seed));
            e.insert(exact_cost(cfg, spec)?);
        }
    }
    let one = |spec: &RunSpec| -> Result<RunSummary, BenchError> {
        let cost = costs.get(&(spec.n, spec.seed)).copied().unwrap_or(0.0);
        let csv = cfg
            .frame_csv
            .then(|| frames_dir.join(format!("{}.csv", spec.stem())));
        let mut gaze = gaze_for(&cfg.gaze, spec.seed, recorded.as_ref());
        pb.set_message(spec.stem());
        run_one(cfg, spec, cost, &mut gaze, csv.as_deref(), &pb)
    };
    let mut out: Vec<Option<RunSummary>> = vec![None; plan.len()];
    let (parallel, serial): (Vec<usize>, Vec<usize>) =
        (0..plan.len()).partition(|&i| !plan[i].part.is_timed() && cfg.jobs > 1);
    for i in serial {
        out[i] = Some(one(&plan[i])?);
    }
    if !parallel.is_empty() {
        let next = AtomicUsize::new(0);
        let results: Mutex<Vec<(usize, Result<RunSummary, BenchError>)>> = Mutex::new(Vec::new());
        std::thread::scope(|scope| {
            for _ in 0..cfg.jobs.min(parallel.len()) {
                scope.spawn(|| {
                    loop {
                        let k = next.fetch_add(1, Ordering::Relaxed);
                        let Some(&i) = parallel.get(k) else { break };
                        let r = one(&plan[i]);
                        let failed = r.is_err();
                        if let Ok(mut v) = results.lock() {
                            v.push((i, r));
                        }
                        if failed {
                            // Stop handing out work; the others finish their current run.
                            next.store(parallel.len(), Ordering::Relaxed);
                        }
                    }
                });
            }
        });
        let results = results
            .into_inner()
            .map_err(|_| BenchError::Invalid("a worker thread panicked".into()))?;
        for (i, r) in results {
            out[i] = Some(r?);
        }
    }
    pb.finish_and_clear();
    out.into_iter()
        .map(|r| r.ok_or_else(|| BenchError::Invalid("a run did not complete".into())))
        .collect()
}
