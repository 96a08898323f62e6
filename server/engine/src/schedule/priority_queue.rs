//! Priority-queue scheduling (paper section 4): pairs whose centre of collision lies within an
//! eccentricity threshold of the fixation form the first queue, the rest the second; the second is
//! touched only once the first is empty. "Priority only" round-robins inside both queues; "priority
//! sorted" sorts the first queue and resolves it sequentially, leaving the second round-robin.

use super::{Needs, Passes, Scheduler, Work, round_robin, sequential, sort_by_priority};
use crate::budget::Meter;
use crate::narrow_phase::NarrowPhase;

/// Two-queue scheduler.
#[derive(Debug)]
pub struct PriorityQueue {
    sorted: bool,
    inner: Vec<u32>,
    outer: Vec<u32>,
}

impl PriorityQueue {
    /// "Priority only" (`false`) or "priority sorted" (`true`).
    pub fn new(sorted: bool) -> Self {
        Self {
            sorted,
            inner: Vec::new(),
            outer: Vec::new(),
        }
    }
}

impl Scheduler for PriorityQueue {
    fn passes(&self) -> Passes {
        Passes::perceptual(Needs {
            inner: true,
            weight: self.sorted,
            ..Needs::default()
        })
    }

    fn run(&mut self, np: &mut NarrowPhase, work: &Work<'_>, meter: &mut Meter<'_>) {
        self.inner.clear();
        self.outer.clear();
        for i in 0..np.pairs.len() {
            if work.priorities.inner(i) {
                self.inner.push(i as u32)
            } else {
                self.outer.push(i as u32)
            }
        }
        if self.sorted {
            sort_by_priority(work.priorities, &mut self.inner);
            sequential(np, &self.inner, work, meter);
        } else {
            round_robin(np, &mut self.inner, work, meter);
        }
        round_robin(np, &mut self.outer, work, meter);
    }
}
