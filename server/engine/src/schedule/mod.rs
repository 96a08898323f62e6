//! Schedulers: the order in which the narrow phase spends its budget (paper sections 2 and 4).
//!
//! A scheduler only decides *which pair steps next*; stepping, counting and interruption belong to
//! [`NarrowPhase`] and [`Meter`]. What else a scheduler wants of a frame (prioritisation, the passes
//! the narrow phase runs around its own run, whether its ordering is worth a wall-clock frame's
//! time) it declares through [`Scheduler::passes`]: the collider asks nothing else of it. Adding a
//! scheduler is one file implementing [`Scheduler`] plus a line in [`for_kind`] (the unit tests
//! define a toy one and run it open and closed loop). Pairs left open when a scheduler returns are
//! deemed colliding by the caller.

pub mod calibration;
mod expected_gain;
pub mod priced;
pub mod priority;
mod priority_queue;
pub mod rings;
mod round_robin;
mod sequential;

pub use expected_gain::ExpectedGain;
pub use priced::Priced;
pub use priority::{Needs, Priorities, Prioritiser};
pub use priority_queue::PriorityQueue;
pub use round_robin::RoundRobin;
pub use sequential::Sequential;

use crate::budget::Meter;
use crate::config::{PricedOptions, SchedulerKind};
use crate::fixation::FrameView;
use crate::narrow_phase::{NarrowPhase, StepOutcome};
use crate::sphere_tree::SphereTree;
use crate::world::World;

/// What a scheduler may read while it works.
#[derive(Debug, Clone, Copy)]
pub struct Work<'a> {
    /// The shared sphere tree.
    pub tree: &'a SphereTree,
    /// Body state.
    pub world: &'a World,
    /// Screen, fixation and scheduling model, when there is a fixation and the scheduler uses it.
    pub view: Option<&'a FrameView<'a>>,
    /// Per-pair priorities, filled in before the scheduler runs (see [`priority`]).
    pub priorities: &'a Priorities,
    /// Calibrated state prices (see [`calibration`]).
    pub calibration: &'a calibration::Calibration,
    /// Threads the frame may use, the calling thread one of them: under a wall-clock budget
    /// a scheduler may settle pairs whole on all of them
    /// ([`NarrowPhase::resolve_ordered`]).
    pub threads: usize,
}

impl<'a> Work<'a> {
    /// What a gaze-blind pass may read: no view.
    pub fn blind(
        tree: &'a SphereTree,
        world: &'a World,
        priorities: &'a Priorities,
        calibration: &'a calibration::Calibration,
        threads: usize,
    ) -> Self {
        Self {
            tree,
            world,
            view: None,
            priorities,
            calibration,
            threads,
        }
    }
}

/// When a scheduler's order needs the frame's prioritisation (see [`priority`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Prioritise {
    /// Never: the order is blind to gaze.
    Never,
    /// When the frame has a fixation: the priorities are perceptual.
    WithFixation,
    /// Always: the scheduler needs distances and scales even without a fixation.
    Always,
}

/// What a scheduler asks of a frame beyond its own run (see [`Scheduler::passes`]): the passes
/// the narrow phase runs before it, and what prioritisation computes for it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Passes {
    /// A wall-clock frame settles every root-separated pair first, in one pass
    /// (`NarrowPhase::settle_separate_roots`), at about 2 ns a pair against 10-20 ns a step: for a
    /// scheduler whose own order would take those tests first anyway. The paper's priority
    /// schedulers rank every pair's first test by priority, and sequential resolution takes each
    /// pair whole in turn: both orders this would change, so they take the pass only in frames
    /// that shed their order for round-robin.
    pub roots_first: bool,
    /// After the root pass, a wall-clock frame settles the pairs within the fovea first, whole and
    /// nearest the fixation first, through the gaze rings (see [`rings`]), where the broad phase
    /// has columns to find them by and the frame can pay for placing them.
    pub rings_fovea: bool,
    /// With [`crate::SimConfig::fovea_first`], a wall-clock frame settles the fovea first over
    /// every candidate.
    pub fovea_first: bool,
    /// The order uses gaze: the rings and the fovea passes are for such schedulers only.
    pub gaze: bool,
    /// When the frame prioritises for this scheduler.
    pub prioritise: Prioritise,
    /// What prioritisation must compute.
    pub needs: Needs,
    /// A wall-clock frame orders (prioritises and runs this scheduler) only if the expected cost
    /// of the ordering is at most this share of the time left; above it, gaze-blind round-robin
    /// does more good with the same time (see [`crate::budget::gate`]).
    pub ordering_share: f64,
    /// The scheduler prices pair states by the tree's calibration (see [`calibration`]); others
    /// are handed an uninformed one.
    pub calibrated: bool,
}

impl Default for Passes {
    /// A gaze-blind scheduler that asks for no pass and no prioritisation.
    fn default() -> Self {
        Self {
            roots_first: false,
            rings_fovea: false,
            fovea_first: false,
            gaze: false,
            prioritise: Prioritise::Never,
            needs: Needs::default(),
            ordering_share: crate::budget::gate::ORDERING_SHARE,
            calibrated: false,
        }
    }
}

impl Passes {
    /// The passes of a scheduler that orders by perceptual priority, which needs `needs`.
    pub fn perceptual(needs: Needs) -> Self {
        Self {
            gaze: true,
            prioritise: Prioritise::WithFixation,
            needs,
            ..Self::default()
        }
    }

    /// Whether the frame prioritises, given whether it has a fixation.
    pub fn prioritises(&self, has_fixation: bool) -> bool {
        match self.prioritise {
            Prioritise::Never => false,
            Prioritise::WithFixation => has_fixation,
            Prioritise::Always => true,
        }
    }
}

/// A narrow-phase scheduling strategy.
pub trait Scheduler: std::fmt::Debug + Send {
    /// What this scheduler asks of a frame beyond its own run: the passes before it and what
    /// prioritisation computes (the default asks for nothing).
    fn passes(&self) -> Passes {
        Passes::default()
    }
    /// Step open pairs until none is left or `meter` says stop.
    fn run(&mut self, np: &mut NarrowPhase, work: &Work<'_>, meter: &mut Meter<'_>);
    /// Clock time the last run spent ordering work before its first step (ns; 0 if it does not
    /// measure it), so the caller can tell whether a wall-clock budget can pay for the ordering.
    fn ordering_ns(&self) -> u64 {
        0
    }
    /// Read the scheduler's own buffers back into cache (see [`crate::warm`]).
    fn warm(&self) {}
    /// Drop what the last run carries to the next (a frame this scheduler did not run, or
    /// bodies renumbered, breaks the chain: what it knew names another frame's state).
    fn forget(&mut self) {}
}

/// The scheduler for `kind` (`options` configure [`Priced`] only).
pub fn for_kind(kind: SchedulerKind, options: PricedOptions) -> Box<dyn Scheduler> {
    match kind {
        SchedulerKind::RoundRobin => Box::new(RoundRobin::default()),
        SchedulerKind::Sequential => Box::new(Sequential::new(false)),
        SchedulerKind::SortedSequential => Box::new(Sequential::new(true)),
        SchedulerKind::PriorityOnly => Box::new(PriorityQueue::new(false)),
        SchedulerKind::PrioritySorted => Box::new(PriorityQueue::new(true)),
        SchedulerKind::ExpectedGain => Box::new(ExpectedGain::default()),
        SchedulerKind::Priced => Box::new(Priced::new(options)),
    }
}

/// Round-robin over `queue` (pair indices): each open pair descends one level per round, in queue
/// order, until the queue is empty or the budget is gone. `queue` is consumed.
pub(crate) fn round_robin(
    np: &mut NarrowPhase,
    queue: &mut Vec<u32>,
    work: &Work<'_>,
    meter: &mut Meter<'_>,
) {
    while !queue.is_empty() {
        let mut kept = 0;
        for k in 0..queue.len() {
            if meter.exhausted(np.tests) {
                // The budget is spent: the pairs this round did not reach stay queued after
                // those it kept, as a `retain` would leave them, moved in one copy instead of
                // visited one by one (a pass over up to millions of entries after the deadline,
                // milliseconds at a million bodies, which the frame's learnt tail then took
                // from the next frames' narrow phases).
                let rest = queue.len() - k;
                queue.copy_within(k.., kept);
                queue.truncate(kept + rest);
                return;
            }
            let i = queue[k];
            if np.step(i as usize, work.tree, work.world) == StepOutcome::Active {
                queue[kept] = i;
                kept += 1;
            }
        }
        queue.truncate(kept);
        np.compact_if_sparse();
    }
}

/// Resolve the pairs of `queue` one after another, in order.
pub(crate) fn sequential(
    np: &mut NarrowPhase,
    queue: &[u32],
    work: &Work<'_>,
    meter: &mut Meter<'_>,
) {
    for &i in queue {
        loop {
            if meter.exhausted(np.tests) {
                return;
            }
            if np.step(i as usize, work.tree, work.world) != StepOutcome::Active {
                break;
            }
        }
    }
}

/// Sort pair indices by priority, highest first; ties keep broad-phase order (deterministic).
pub(crate) fn sort_by_priority(pr: &Priorities, queue: &mut [u32]) {
    queue.sort_by(|&x, &y| {
        pr.weight(y as usize)
            .total_cmp(&pr.weight(x as usize))
            .then(x.cmp(&y))
    });
}

/// What prioritisation must compute for `kind`'s scheduler (its [`Passes::needs`]).
pub fn needs(kind: SchedulerKind) -> Needs {
    for_kind(kind, PricedOptions::default()).passes().needs
}

/// The scheduler a wall-clock frame falls back on when it cannot pay for its own ordering:
/// gaze-blind round-robin.
pub fn fallback() -> Box<dyn Scheduler> {
    Box::new(RoundRobin::default())
}

#[cfg(test)]
mod tests;
