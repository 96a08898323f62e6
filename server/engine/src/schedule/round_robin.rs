//! Round-robin scheduling (paper section 2, after Hubbard [14]): every active pair descends one level
//! per round, so under interruption all pairs end at about the same depth and no perception is used.

use super::{Scheduler, Work, round_robin};
use crate::budget::Meter;
use crate::config::SchedulerKind;
use crate::narrow_phase::NarrowPhase;

/// Round-robin over the whole candidate list.
#[derive(Debug, Default)]
pub struct RoundRobin {
    queue: Vec<u32>,
}

impl Scheduler for RoundRobin {
    fn kind(&self) -> SchedulerKind {
        SchedulerKind::RoundRobin
    }

    fn warm(&self) {
        crate::warm::lines(&self.queue);
    }

    fn run(&mut self, np: &mut NarrowPhase, work: &Work<'_>, meter: &mut Meter<'_>) {
        self.queue.clear();
        // A budget already spent (by a foveal pass before this one, or since) steps no pair:
        // say so before the queue is built, a pass over every pair's status (about half a
        // millisecond at a million bodies) that ran after the deadline in every frame whose
        // foveal pass took the rest of the narrow phase's time.
        if meter.exhausted_now(np.tests) {
            return;
        }
        // Pairs already settled this frame (a foveal pass before this one) are skipped.
        self.queue
            .extend((0..np.pairs.len() as u32).filter(|&i| np.pairs[i as usize].status.is_open()));
        round_robin(np, &mut self.queue, work, meter);
    }
}
