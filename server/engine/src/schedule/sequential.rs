//! Sequential scheduling (paper section 2): resolve each pair fully before the next. With `sorted`
//! it is the paper's *perceptually sorted sequential* scheduling: the list is first sorted by
//! perceptual priority, so the collisions that matter most are resolved while there is time.

use super::{Needs, Passes, Scheduler, Work, sequential, sort_by_priority};
use crate::budget::Meter;
use crate::narrow_phase::NarrowPhase;

/// Sequential, optionally sorted by priority.
#[derive(Debug)]
pub struct Sequential {
    sorted: bool,
    queue: Vec<u32>,
}

impl Sequential {
    /// Plain (`false`) or perceptually sorted (`true`).
    pub fn new(sorted: bool) -> Self {
        Self {
            sorted,
            queue: Vec::new(),
        }
    }
}

impl Scheduler for Sequential {
    fn passes(&self) -> Passes {
        if self.sorted {
            Passes::perceptual(Needs {
                weight: true,
                ..Needs::default()
            })
        } else {
            Passes::default()
        }
    }

    fn run(&mut self, np: &mut NarrowPhase, work: &Work<'_>, meter: &mut Meter<'_>) {
        self.queue.clear();
        self.queue.extend(0..np.pairs.len() as u32);
        if self.sorted && work.view.is_some() {
            sort_by_priority(work.priorities, &mut self.queue);
        }
        sequential(np, &self.queue, work, meter);
    }
}
