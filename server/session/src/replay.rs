//! Closed-loop replay: the recorded scenes re-run with the recorded fixation of every frame, each
//! frame's report compared with the recorded one.
//!
//! The engine is deterministic: under a budget that does not read the clock (sphere tests, a
//! fraction of the exact cost, exact, interrupt at zero) the same configuration and fixations
//! give the same frames, bit for bit, whatever machine runs them. Under a wall-clock budget how
//! far the narrow phase gets depends on the machine's speed at that moment, so only the fields
//! that do not depend on it (index, simulated time, the fixation used) are compared there, and
//! the outcome says the replay is not exact.

use foveal_engine::{BudgetSpec, ConfigError, FrameReport, FrozenClock, SimConfig, Simulation};

use crate::format::FrameRecord;
use crate::io::Session;

/// The first field that differs between a recorded and a replayed frame.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Mismatch {
    /// Protocol index of the frame.
    pub frame: u64,
    /// The report's field, by its name in the file.
    pub field: &'static str,
    /// The recorded value.
    pub recorded: String,
    /// The replayed value.
    pub replayed: String,
}

impl std::fmt::Display for Mismatch {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "frame {}: `{}` was recorded as {} but replays as {}",
            self.frame, self.field, self.recorded, self.replayed
        )
    }
}

/// What a closed-loop replay found.
#[derive(Debug, Clone, PartialEq)]
pub struct ReplayOutcome {
    /// Frames replayed and compared.
    pub frames: u64,
    /// Frames compared field by field, bit for bit (those under deterministic budgets).
    pub exact_frames: u64,
    /// Frames under a wall-clock budget, where only index, time and fixation are compared.
    pub wall_clock_frames: u64,
    /// The first difference, if any (the replay stops there: later frames follow from it).
    pub mismatch: Option<Mismatch>,
    /// The first frame index missing from the recording (dropped by a writer that fell
    /// behind); the replay stops before it, since the fixations from there on are unknown.
    pub gap_at: Option<u64>,
}

impl ReplayOutcome {
    /// Every frame of the session replayed, bit for bit.
    pub fn is_bit_for_bit(&self) -> bool {
        self.mismatch.is_none() && self.gap_at.is_none() && self.wall_clock_frames == 0
    }
}

/// Whether frames under `config` replay bit for bit.
pub fn is_deterministic(config: &SimConfig) -> bool {
    !matches!(config.budget, BudgetSpec::WallMs(_))
}

/// Replay `session` closed loop (see the module documentation).
pub fn replay(session: &Session) -> Result<ReplayOutcome, ConfigError> {
    let mut outcome = ReplayOutcome {
        frames: 0,
        exact_frames: 0,
        wall_clock_frames: 0,
        mismatch: None,
        gap_at: None,
    };
    let mut config = session.header.sim.clone();
    let mut sim = Simulation::new(config.clone())?;
    let mut scenes = session.scenes.iter().peekable();
    for (expected, frame) in (0u64..).zip(&session.frames) {
        // Swaps take effect at their frame boundary; of several at one boundary the last stands.
        let mut swap = None;
        while let Some(scene) = scenes.next_if(|s| s.first_frame <= frame.index) {
            swap = Some(scene);
        }
        if let Some(scene) = swap {
            config = scene.sim.clone();
            sim = Simulation::new(config.clone())?;
        }
        if frame.index != expected {
            outcome.gap_at = Some(expected);
            break;
        }
        let replayed = sim.step(Some(frame.fixation), &FrozenClock);
        let exact = is_deterministic(&config);
        outcome.frames += 1;
        if exact {
            outcome.exact_frames += 1;
        } else {
            outcome.wall_clock_frames += 1;
        }
        if let Some(m) = compare(frame, replayed, exact) {
            outcome.mismatch = Some(m);
            break;
        }
    }
    Ok(outcome)
}

/// The first field of `replayed` that differs from `recorded`'s report: every field but the
/// phase timings when `exact`, else only those that do not depend on the machine's speed.
///
/// Values are compared by their `Debug` text, which for floats is the shortest text that
/// parses back to the same bits: equal text is equal bits (0.0 and -0.0 differ), and the
/// mismatch prints what a reader can check against the file.
pub fn compare(recorded: &FrameRecord, replayed: &FrameReport, exact: bool) -> Option<Mismatch> {
    let r = &recorded.report;
    let mut first: Option<Mismatch> = None;
    let mut check = |field: &'static str, a: String, b: String| {
        if first.is_none() && a != b {
            first = Some(Mismatch {
                frame: recorded.index,
                field,
                recorded: a,
                replayed: b,
            });
        }
    };
    macro_rules! fields {
        ($($name:ident),* $(,)?) => {
            $(check(
                stringify!($name),
                format!("{:?}", r.$name),
                format!("{:?}", replayed.$name),
            );)*
        };
    }
    fields!(index, sim_time, fixation, fixation_rejected);
    if exact {
        fields!(
            geometric_inaccuracy,
            perceived_inaccuracy,
            candidate_pairs,
            real_collisions,
            deemed,
            responses,
            resolved_per_level,
            sphere_tests,
            metrics_stride,
            geometric_inaccuracy_se,
            perceived_inaccuracy_se,
            foveal_pairs,
            foveal_deemed,
            budget_exhausted,
            ordering_shed,
            gaze_rings,
            budget_spent_before_narrow,
            audit,
        );
    }
    first
}
