//! One frame's plan under its budget, and what a whole-frame wall-clock budget learns from each
//! frame to plan the next.
//!
//! A wall-clock budget counts from the start of the frame, so integration and the broad phase
//! spend it too. The frame aims to end earlier than its budget by the pool's learnt hand-back
//! and the guard band (see [`super::guard`]); the narrow phase stops earlier still, by the learnt
//! tail (deeming, response and metrics, see [`super::shedding`]). Sphere-test and exact budgets
//! plan nothing: every phase runs whole and only the narrow phase's meter counts.

use super::guard::{GUARD_SETTLE_S, Guard};
use super::shedding::Shedder;
use super::{Clock, FrameBudget};
use crate::metrics::Effort;
use crate::report::FrameReport;

/// What a frame may spend, set at its start.
#[derive(Debug, Clone, Copy)]
pub(crate) struct FramePlan {
    /// The whole frame's budget from its start: under a wall-clock budget a deadline, less the
    /// learnt hand-back and guard band.
    pub budget: FrameBudget,
    /// Under a wall-clock budget: that deadline, and the budget itself (ns).
    pub deadline: Option<(u64, u64)>,
    /// The guard band the deadline keeps (ns; 0 but under a wall-clock budget).
    pub guard_ns: u64,
}

impl FramePlan {
    /// Whether the frame runs under a wall-clock budget (the whole frame spends it).
    pub fn is_wall(&self) -> bool {
        self.deadline.is_some()
    }

    /// The deadline and budget of a frame that sheds its broad phase in perceptual order: a
    /// wall-clock frame whose broad phase has regions (the grid, at large N).
    pub fn shedding(&self, has_regions: bool) -> Option<(u64, u64)> {
        self.deadline.filter(|_| has_regions)
    }
}

/// What a wall-clock budget learns across frames: the guard band, what the frame sheds and its
/// learnt costs, and the wait for the thread pool to hand a frame back.
#[derive(Debug, Clone, Default)]
pub(crate) struct FramePolicy {
    /// What a whole-frame wall-clock budget sheds, and its learnt costs.
    pub shedder: Shedder,
    /// How much earlier than a wall-clock budget frames aim to end, learnt from their lateness.
    guard: Guard,
    /// The last frame's last clock reading, and the learnt wait for the pool to hand a frame
    /// back after it (a wall-clock budget's frames end this much earlier).
    frame_end_ns: u64,
    handback_ns: u64,
}

impl FramePolicy {
    /// The plan of a frame under `budget` started at `t0`.
    pub fn plan(&self, budget: FrameBudget, t0: u64) -> FramePlan {
        let guard_ns = match budget {
            FrameBudget::Wall(_) => self.guard.margin_ns(),
            _ => 0,
        };
        let whole = match budget.starting_at(t0) {
            FrameBudget::Deadline(d) => {
                FrameBudget::Deadline(d.saturating_sub(self.handback_ns.saturating_add(guard_ns)))
            }
            b => b,
        };
        let deadline = match (budget, whole) {
            (FrameBudget::Wall(ns), FrameBudget::Deadline(d)) => Some((d, ns)),
            _ => None,
        };
        FramePlan {
            budget: whole,
            deadline,
            guard_ns,
        }
    }

    /// The narrow phase's budget in a frame with `pairs` candidate pairs: under a wall-clock
    /// budget it stops early enough for the learnt tail (deeming, response, metrics) at every
    /// N, so that the budget covers the whole frame.
    pub fn narrow_budget(&self, plan: &FramePlan, pairs: usize) -> FrameBudget {
        match plan.deadline {
            Some((end, ns)) => FrameBudget::Deadline(self.shedder.narrow_deadline(end, ns, pairs)),
            None => plan.budget,
        }
    }

    /// The metrics' effort: under a wall-clock budget Δ and P are summed over a sample sized to
    /// the budget where summing every deemed pair would not fit (the report gives the stride and
    /// the standard errors; `Simulation::measure_exactly` sums them all, off the clock), and only
    /// the first `foveal_prefix` pairs can be foveal. The foveal pass's findings
    /// (`foveal_known`, `foveal_marked`) spare the metrics testing the fovea again.
    pub fn effort(
        &self,
        plan: &FramePlan,
        foveal_prefix: Option<usize>,
        foveal_known: Option<u32>,
        foveal_marked: bool,
    ) -> Effort {
        match plan.deadline {
            Some((_, ns)) => Effort {
                foveal_known,
                foveal_marked,
                ..self.shedder.effort(ns, foveal_prefix.unwrap_or(usize::MAX))
            },
            None => Effort::default(),
        }
    }

    /// The learnt wait for the pool to hand a frame back (ns).
    #[cfg(test)]
    pub fn handback_ns(&self) -> u64 {
        self.handback_ns
    }

    /// The guard band and what it learnt.
    #[cfg(test)]
    pub fn guard(&self) -> &Guard {
        &self.guard
    }

    /// The frame's last clock reading, `end_ns`: the pool's hand-back is measured from it.
    pub fn frame_ended(&mut self, end_ns: u64) {
        self.frame_end_ns = end_ns;
    }

    /// After a frame started at `t0` under `budget` has been handed back to its caller (by the
    /// pool when `pooled`): learn the guard band from its lateness and the pool's hand-back.
    ///
    /// The frame as its caller sees it ends here (after the pool's hand-back): its lateness sets
    /// the guard band of the next frames, but for two kinds of frame late by their own work
    /// rather than by a stall (see [`super::guard`]). The clock is read only where the reading
    /// is used.
    pub fn after_frame(
        &mut self,
        budget: FrameBudget,
        report: &FrameReport,
        sim_time: f64,
        pooled: bool,
        t0: u64,
        clock: &dyn Clock,
    ) {
        let FrameBudget::Wall(ns) = budget else {
            return;
        };
        let learn = sim_time >= GUARD_SETTLE_S && !report.budget_spent_before_narrow;
        if !learn && !pooled {
            return;
        }
        let end = clock.now_ns();
        if learn {
            self.guard
                .learn(ns, report.guard_ns, end.saturating_sub(t0));
        }
        if pooled {
            // The pool hands the finished frame back after the frame's last clock read: a wait
            // (7 us median, 35 us at the 99th percentile at N = 10,000 on two threads) that the
            // frame's deadline did not see. Learnt as an envelope (a quarter of a rise, a 32nd
            // of a fall a frame) and taken off the next frames' deadlines, so that the frame the
            // caller sees, not only the engine's part of it, holds the budget.
            let back = end.saturating_sub(self.frame_end_ns);
            self.handback_ns = if back > self.handback_ns {
                self.handback_ns + (back - self.handback_ns) / 4
            } else {
                self.handback_ns - (self.handback_ns - back) / 32
            };
        }
    }
}
