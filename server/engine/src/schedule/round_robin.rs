//! Round-robin scheduling (paper section 2, after Hubbard [14]): every active pair descends one level
//! per round, so under interruption all pairs end at about the same depth and no perception is used.

use super::{Passes, Scheduler, Work, round_robin};
use crate::budget::Meter;
use crate::narrow_phase::NarrowPhase;

/// Round-robin over the whole candidate list.
#[derive(Debug, Default)]
pub struct RoundRobin {
    queue: Vec<u32>,
}

impl Scheduler for RoundRobin {
    /// Its first round is the root pass's tests in the same order (less the pairs with a
    /// witness, stepped in the round), so a wall-clock frame takes the cheaper pass first.
    fn passes(&self) -> Passes {
        Passes {
            roots_first: true,
            ..Passes::default()
        }
    }

    fn warm(&self) {
        crate::warm::lines(&self.queue);
    }

    fn run(&mut self, np: &mut NarrowPhase, work: &Work<'_>, meter: &mut Meter<'_>) {
        self.queue.clear();
        // A budget already spent (by a foveal pass before this one, or since) steps no pair:
        // say so before the queue is built, a pass over every pair's status (about half a
        // millisecond at a million bodies) that ran after the deadline in every frame whose
        // foveal pass took the rest of the narrow phase's time. A frame without pairs does not
        // ask (its budget is not reported spent, as before).
        if !np.pairs.is_empty() && meter.exhausted_now(np.tests) {
            return;
        }
        // Pairs already settled this frame (a foveal pass before this one) are skipped.
        self.queue
            .extend((0..np.pairs.len() as u32).filter(|&i| np.pairs[i as usize].status.is_open()));
        round_robin(np, &mut self.queue, work, meter);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::budget::{FrameBudget, Manual};
    use crate::config::SceneConfig;
    use crate::narrow_phase::PairStatus;
    use crate::schedule::{Priorities, calibration::Calibration};
    use std::sync::atomic::{AtomicU64, Ordering::Relaxed};

    /// A deadline that passed since the meter last read the clock (its reads are spaced far
    /// from the deadline) stops round robin before it lists a single pair: nothing is stepped,
    /// no queue is left, and the budget is reported spent. With time left it steps every pair.
    #[test]
    fn a_deadline_passed_since_the_last_read_builds_no_queue() {
        let sim = crate::Simulation::new(crate::SimConfig {
            scene: SceneConfig::paper(2_000, 2),
            ..crate::SimConfig::default()
        })
        .expect("valid");
        let input = sim.frame_input();
        assert!(input.candidates.len() > 100, "{}", input.candidates.len());
        let (priorities, calibration) = (Priorities::default(), Calibration::shipped());
        let calibration = calibration.expect("shipped table");
        let work = Work {
            tree: input.tree,
            world: input.world,
            view: None,
            priorities: &priorities,
            calibration: &calibration,
            threads: 1,
        };
        for spent in [true, false] {
            let clock = Manual(AtomicU64::new(0));
            let mut meter = Meter::new(FrameBudget::Deadline(10_000_000), &clock);
            // Read far from the deadline: the next read would come only tens of steps later.
            assert!(!meter.exhausted(0));
            if spent {
                clock.0.store(10_000_000, Relaxed);
            }
            let mut np = NarrowPhase::default();
            np.reset(input.candidates);
            let mut rr = RoundRobin::default();
            rr.run(&mut np, &work, &mut meter);
            let untested = np
                .pairs
                .iter()
                .filter(|p| p.status == PairStatus::Untested)
                .count();
            let expected = if spent { np.pairs.len() } else { 0 };
            assert_eq!(untested, expected, "spent {spent}");
            assert!(
                rr.queue.is_empty(),
                "spent {spent}: {} queued",
                rr.queue.len()
            );
            assert_eq!(meter.was_exhausted(), spent);
        }
    }
}
