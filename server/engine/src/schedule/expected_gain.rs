//! Expected-gain scheduling (ours, beyond the paper): always take the step that removes the most
//! expected perceived error per sphere test.
//!
//! The paper's schedulers rank pairs once, by perceptual weight alone, and ignore cost: a pair deep
//! into its descent needs a few tests to finish, while an untested pair needs one test to discard
//! half of its chances (roots overlap in about half of the broad-phase pairs). Here the value of a
//! pair is its current perceived-error estimate F(g', e) (what deeming it would cost, section 3) and
//! its price the tests its next step will do; a max-heap on value / price is re-keyed after every
//! step because each step shrinks g' and changes the price.

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use super::{Needs, Passes, Scheduler, Work, round_robin};
use crate::budget::Meter;
use crate::narrow_phase::{NarrowPhase, PairStatus, StepOutcome};

#[derive(Debug, Clone, Copy, PartialEq)]
struct Entry {
    gain: f32,
    pair: u32,
}

impl Eq for Entry {}

impl Ord for Entry {
    fn cmp(&self, other: &Self) -> Ordering {
        self.gain
            .total_cmp(&other.gain)
            .then(other.pair.cmp(&self.pair))
    }
}

impl PartialOrd for Entry {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// Greedy value-per-test scheduler.
#[derive(Debug, Default)]
pub struct ExpectedGain {
    heap: BinaryHeap<Entry>,
    fallback: Vec<u32>,
}

/// Average branching factor of the star's tree (8, 32/8, 80/32 per level in the octree; 7, 20/7, 4 in
/// the parts tree: 80 leaves over three levels either way), used to price a step.
const BRANCHING: f32 = 4.0;

fn price(np: &NarrowPhase, i: usize) -> f32 {
    match np.pairs[i].status {
        PairStatus::Untested => 1.0,
        _ => np.pairs[i].pending() as f32 * BRANCHING,
    }
}

impl Scheduler for ExpectedGain {
    fn passes(&self) -> Passes {
        Passes::perceptual(Needs {
            weight: true,
            ..Needs::default()
        })
    }

    fn run(&mut self, np: &mut NarrowPhase, work: &Work<'_>, meter: &mut Meter<'_>) {
        let Some(view) = work.view else {
            // No fixation: nothing to weigh by, so every pair is equally important.
            self.fallback.clear();
            self.fallback.extend(0..np.pairs.len() as u32);
            return round_robin(np, &mut self.fallback, work, meter);
        };
        self.heap.clear();
        for i in 0..np.pairs.len() {
            let w = work.priorities.weight(i);
            self.heap.push(Entry {
                gain: w / price(np, i),
                pair: i as u32,
            });
        }
        while let Some(Entry { pair, .. }) = self.heap.pop() {
            if meter.exhausted(np.tests) {
                return;
            }
            let i = pair as usize;
            if np.step(i, work.tree, work.world) == StepOutcome::Active {
                let w = view.weight(&np.evidence(i, work.tree, work.world)) as f32;
                self.heap.push(Entry {
                    gain: w / price(np, i),
                    pair,
                });
            }
        }
    }
}
