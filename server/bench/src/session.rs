//! A recorded server session (`foveal-server --record FILE`) re-run two ways.
//!
//! 1. Closed loop, bit for bit: the recorded scenes with the recorded scheduler, budget and
//!    per-frame fixations, every frame's report compared with the recorded one
//!    ([`foveal_session::replay`]). Under sphere-test budgets any difference is a bug (or a
//!    changed engine); under wall-clock budgets only what does not depend on the clock is
//!    compared, and the report says the replay is not exact.
//! 2. Open loop: the recorded fixations drive every scheduler on the identical frames of one
//!    exact run of each recorded scene ([`crate::open_loop::run_frames`]), at the session's own
//!    budget and a few fractions of each frame's exact cost, against the clairvoyant bound. The
//!    same tables as `foveal-bench open-loop`, for a real viewer's gaze.

use std::fmt::Write as _;

use foveal_engine::{BudgetSpec, Fixation, FrameBudget, SchedulerKind, SimConfig, Simulation};
use foveal_session::{FrameRecord, ReplayOutcome, Session};

use crate::error::BenchError;
use crate::gaze::ViewerModel;
use crate::open_loop::{self as ol, Budget, Condition, GazeFeed, OpenLoopConfig, SchedulerSpec};

/// What to run on a session.
#[derive(Debug, Clone, PartialEq)]
pub struct SessionConfig {
    /// Fractions of each frame's exact cost the open loop also runs at, beside the session's own.
    pub fractions: Vec<f64>,
    /// Run the open-loop comparison (the closed-loop replay always runs).
    pub open_loop: bool,
    /// At most this many frames of each scene in the open loop, from the scene's first (None:
    /// all). The closed-loop replay always checks every frame.
    pub open_loop_frames: Option<u32>,
}

impl Default for SessionConfig {
    fn default() -> Self {
        Self {
            fractions: vec![0.01, 0.03, 0.1, 0.3],
            open_loop: true,
            open_loop_frames: None,
        }
    }
}

/// What a session's re-runs found.
#[derive(Debug, Clone)]
pub struct SessionReport {
    /// The closed-loop replay.
    pub replay: ReplayOutcome,
    /// The whole report (markdown).
    pub markdown: String,
}

/// One scene of the session and its frames.
struct Segment<'a> {
    config: SimConfig,
    frames: &'a [FrameRecord],
}

fn segments(session: &Session) -> Vec<Segment<'_>> {
    let mut out = Vec::new();
    let mut config = session.header.sim.clone();
    let mut start = 0usize;
    let frames = &session.frames;
    for scene in &session.scenes {
        let end = frames.partition_point(|f| f.index < scene.first_frame);
        if end > start {
            out.push(Segment {
                config: config.clone(),
                frames: &frames[start..end],
            });
        }
        start = end.max(start);
        config = scene.sim.clone();
    }
    if frames.len() > start {
        out.push(Segment {
            config,
            frames: &frames[start..],
        });
    }
    out
}

fn budget_text(b: &BudgetSpec) -> String {
    match b {
        BudgetSpec::Exact => "exact".into(),
        BudgetSpec::InterruptAtZero => "zero".into(),
        BudgetSpec::WallMs(ms) => format!("{ms}ms"),
        BudgetSpec::SphereTests(n) => format!("{n}tests"),
        BudgetSpec::FractionOfExact(f) => format!("{f}x"),
    }
}

/// Re-run `session` closed loop and, if asked, open loop.
pub fn run(session: &Session, cfg: &SessionConfig) -> Result<SessionReport, BenchError> {
    let replay = foveal_session::replay(session)?;
    let t = &session.trailer;
    let mut md = String::new();
    let _ = writeln!(
        md,
        "Session: {} frames, {} gaze samples, {} scene change(s), {} records dropped while recording.\n",
        t.frames, t.gaze_samples, t.scenes, t.dropped
    );
    let _ = writeln!(md, "### Closed-loop replay\n");
    for (i, seg) in segments(session).iter().enumerate() {
        let c = &seg.config;
        let (first, last) = match (seg.frames.first(), seg.frames.last()) {
            (Some(a), Some(b)) => (a.index, b.index),
            _ => continue,
        };
        let _ = writeln!(
            md,
            "- scene {i}: frames {first}..={last}, N = {}, seed {}, scheduler {}, budget {}{}",
            c.scene.bodies,
            c.scene.seed,
            c.scheduler.name(),
            budget_text(&c.budget),
            if foveal_session::is_deterministic(c) {
                ""
            } else {
                " (wall clock: not exactly replayable)"
            }
        );
    }
    md.push('\n');
    md.push_str(&replay_verdict(&replay));
    if cfg.open_loop {
        let _ = writeln!(
            md,
            "\n### Schedulers on identical frames, the recorded gaze\n"
        );
        for (i, seg) in segments(session).iter().enumerate() {
            md.push_str(&open_loop_segment(i, seg, cfg)?);
        }
    }
    Ok(SessionReport {
        replay,
        markdown: md,
    })
}

/// One paragraph on the closed-loop outcome.
pub fn replay_verdict(r: &ReplayOutcome) -> String {
    let mut s = String::new();
    if let Some(m) = &r.mismatch {
        let _ = writeln!(
            s,
            "**Replay differs** after {} identical frames: {m}.",
            r.frames.saturating_sub(1)
        );
    } else if r.wall_clock_frames > 0 {
        let _ = writeln!(
            s,
            "Replay is **not exact**: {} of {} frames ran under a wall-clock budget, whose work \
             depends on the machine's speed; on those only index, simulated time and fixation \
             were compared (all equal). {} frames under deterministic budgets are bit for bit.",
            r.wall_clock_frames, r.frames, r.exact_frames
        );
    } else {
        let _ = writeln!(
            s,
            "**Bit for bit**: all {} frames replay with every metric equal to the recorded one \
             (timings aside).",
            r.frames
        );
    }
    if let Some(gap) = r.gap_at {
        let _ = writeln!(
            s,
            "The recording lacks frame {gap} (dropped while recording): the replay stopped there."
        );
    }
    s
}

/// The open-loop tables of one scene.
fn open_loop_segment(
    i: usize,
    seg: &Segment<'_>,
    session: &SessionConfig,
) -> Result<String, BenchError> {
    let fractions = &session.fractions;
    let c = &seg.config;
    let mut budgets: Vec<Budget> = Vec::new();
    let mut note = String::new();
    // The session's own budget as the server ran it: fraction-of-exact budgets are calibrated to
    // a fixed number of tests when the scene is built.
    match c.budget {
        BudgetSpec::SphereTests(_) | BudgetSpec::FractionOfExact(_) => {
            if let FrameBudget::Tests(n) = Simulation::new(c.clone())?.frame_budget() {
                budgets.push(Budget::FixedTests(n));
            }
        }
        BudgetSpec::WallMs(ms) => {
            let _ = writeln!(
                note,
                "The session's budget ({ms} ms, wall clock) depends on the machine; the \
                 comparison uses fractions of each frame's exact cost instead.\n"
            );
        }
        BudgetSpec::Exact | BudgetSpec::InterruptAtZero => {}
    }
    budgets.extend(fractions.iter().map(|&f| Budget::Tests(f)));
    let n = c.scene.bodies;
    let recorded = u32::try_from(seg.frames.len()).unwrap_or(u32::MAX);
    let frames = session
        .open_loop_frames
        .map_or(recorded, |cap| cap.min(recorded));
    if frames < recorded {
        let _ = writeln!(
            note,
            "The open loop runs the first {frames} of the scene's {recorded} recorded frames \
             (`--session-frames`).\n"
        );
    }
    let all: Vec<SchedulerSpec> = SchedulerKind::ALL
        .into_iter()
        .map(SchedulerSpec::plain)
        .collect();
    let name = format!(
        "scene {i}: {} scheduled, {} measured",
        model_text(&c.schedule_model),
        model_text(&c.measure_model)
    );
    let cfg = OpenLoopConfig {
        primary: Vec::new(),
        ns: vec![n],
        seeds: vec![c.scene.seed],
        frames: vec![(n, frames)],
        warmup: 0,
        timing_frames: 0,
        budgets,
        conditions: vec![
            Condition {
                name: name.clone(),
                schedule_model: c.schedule_model,
                measure_model: c.measure_model,
                feed: GazeFeed::Viewer,
                viewer: ViewerModel::Script,
                suppress_saccades: false,
                schedulers: all,
            },
            Condition {
                name: format!("{name}, centre-fed"),
                schedule_model: c.schedule_model,
                measure_model: c.measure_model,
                feed: GazeFeed::Centre,
                viewer: ViewerModel::Script,
                suppress_saccades: false,
                schedulers: vec![
                    SchedulerSpec::plain(SchedulerKind::RoundRobin),
                    SchedulerSpec::plain(SchedulerKind::Priced),
                ],
            },
        ],
        jobs: 1,
        fovea_first: c.fovea_first,
        truth: c.scene.truth,
        out: std::path::PathBuf::new(),
    };
    // Frame k of the exact run (simulated time (k + 1) dt at its end; its start is k dt) is
    // steered by the k-th recorded frame's fixation.
    let dt = c.scene.dt;
    let fixations: Vec<Fixation> = seg.frames.iter().map(|f| f.fixation).collect();
    let mut gaze = |t: f64| {
        let k = (t / dt).round().max(0.0) as usize;
        let f = fixations[k.min(fixations.len().saturating_sub(1))];
        Fixation::at(f.x, f.y)
    };
    let run = ol::run_frames(&cfg, c, c.scene.seed, &mut gaze)?;
    let runs = [run];
    let rows = ol::summarise(&cfg, &runs);
    let mut s = note;
    let _ = writeln!(
        s,
        "#### Scene {i}: N = {n}, {frames} frames, exact cost {:.0} sphere tests per frame\n",
        runs[0].exact_tests
    );
    s.push_str("True P per frame (mean over the frames):\n\n");
    s.push_str(&crate::open_loop::budget_table_head(&cfg.budgets));
    let cond = &cfg.conditions[0];
    for label in cond
        .schedulers
        .iter()
        .map(|x| x.label.as_str())
        .chain(["clairvoyant"])
    {
        let _ = write!(s, "| {label} |");
        for b in &cfg.budgets {
            let cell = rows
                .iter()
                .find(|r| r.condition == cond.name && r.budget == b.label() && r.scheduler == label)
                .map_or(String::new(), |r| format!("{:.4e}", r.true_p.mean));
            let _ = write!(s, " {cell} |");
        }
        s.push('\n');
    }
    s.push('\n');
    s.push_str(&ol::markdown(&cfg, &runs, &rows));
    Ok(s)
}

fn model_text(m: &foveal_engine::PerceptualModel) -> String {
    use foveal_engine::PerceptualFunction as F;
    let unit = match m.unit {
        foveal_engine::EccentricityUnit::Degrees => "deg",
        foveal_engine::EccentricityUnit::Pixels => "px",
    };
    match m.function {
        F::F1 => format!("F1 ({unit})"),
        F::F2 { c } => format!("F2 C={c} {unit}"),
        F::F2Range { c_min, c_max } => format!("F2 C={c_min}..{c_max} {unit}"),
        F::F3 { .. } => format!("F3 ({unit})"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use foveal_engine::FrozenClock;
    use foveal_gaze::online::ProcessorConfig;
    use foveal_session::{GazeSettings, Header, Record, ServerSettings, SessionWriter};

    /// A session run directly on the engine: 150 bodies, 30 frames, then a swap to 120 bodies.
    fn session() -> Session {
        let mut a = SimConfig::default();
        a.scene.bodies = 150;
        a.budget = BudgetSpec::SphereTests(400);
        let mut b = a.clone();
        b.scene.bodies = 120;
        b.scene.seed = 7;
        let settings = ServerSettings {
            frame_rate_hz: 60.0,
            gaze_max_age_s: 0.5,
            gaze_processing: GazeSettings::from(&ProcessorConfig::default()),
        };
        let mut w =
            SessionWriter::new(Vec::new(), &Header::new(a.clone(), settings)).expect("header");
        let mut index = 0;
        for (config, frames) in [(&a, 30), (&b, 20)] {
            if index > 0 {
                w.write(&Record::Scene(Box::new(foveal_session::SceneRecord {
                    first_frame: index,
                    frame_rate_hz: 60.0,
                    sim: config.clone(),
                })))
                .expect("scene");
            }
            let mut sim = Simulation::new(config.clone()).expect("valid");
            for k in 0..frames {
                let fixation = Fixation::at(0.2 + 0.02 * f64::from(k), 0.4);
                let report = sim.step(Some(fixation), &FrozenClock).clone();
                w.write(&Record::Frame(Box::new(FrameRecord {
                    index,
                    t_s: index as f64 / 60.0,
                    fixation,
                    fixation_source: "gaze".into(),
                    report,
                })))
                .expect("frame");
                index += 1;
            }
        }
        let bytes = w.finish(0).expect("trailer").0;
        Session::read(bytes.as_slice()).expect("reads")
    }

    #[test]
    fn a_session_with_a_swap_replays_and_compares_every_scheduler_per_scene() {
        let s = session();
        let cfg = SessionConfig {
            fractions: vec![0.1],
            open_loop: true,
            open_loop_frames: None,
        };
        let out = run(&s, &cfg).expect("runs");
        assert!(out.replay.is_bit_for_bit(), "{:?}", out.replay);
        assert_eq!(out.replay.frames, 50);
        let md = &out.markdown;
        assert!(md.contains("**Bit for bit**: all 50 frames"), "{md}");
        assert!(
            md.contains("Scene 0: N = 150, 30 frames")
                && md.contains("Scene 1: N = 120, 20 frames"),
            "{md}"
        );
        assert!(
            md.contains("| 400tests |") && md.contains("| tests=0.1 |"),
            "{md}"
        );
        assert!(
            md.contains("| clairvoyant |") && md.contains("| priced |"),
            "{md}"
        );
    }

    #[test]
    fn the_open_loop_frame_cap_shortens_each_scene_but_not_the_replay() {
        let s = session();
        let cfg = SessionConfig {
            fractions: vec![0.1],
            open_loop: true,
            open_loop_frames: Some(12),
        };
        let out = run(&s, &cfg).expect("runs");
        assert_eq!(out.replay.frames, 50);
        let md = &out.markdown;
        assert!(
            md.contains("Scene 0: N = 150, 12 frames")
                && md.contains("Scene 1: N = 120, 12 frames"),
            "{md}"
        );
        assert!(
            md.contains("the first 12 of the scene's 30 recorded frames"),
            "{md}"
        );
    }

    #[test]
    fn a_changed_metric_is_reported_with_its_frame() {
        let mut s = session();
        s.frames[35].report.deemed += 1;
        let out = run(
            &s,
            &SessionConfig {
                fractions: vec![],
                open_loop: false,
                open_loop_frames: None,
            },
        )
        .expect("runs");
        let m = out.replay.mismatch.expect("found");
        assert_eq!((m.frame, m.field), (35, "deemed"));
        assert!(
            out.markdown.contains("**Replay differs**"),
            "{}",
            out.markdown
        );
    }
}
