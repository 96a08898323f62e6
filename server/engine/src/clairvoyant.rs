//! The clairvoyant bound (DESIGN.md, ours): the least true perceived error any schedule could
//! leave in a frame with a given number of sphere tests.
//!
//! A scheduler only lowers true P by *settling* a pair that truly does not collide (a deemed pair
//! that collides costs nothing, section 3; partial work on a pair that is deemed anyway changes
//! nothing). So with each candidate pair's true weight w (its perceived error if deemed) and its
//! exact cost c (sphere tests to settle it), the best schedule solves a 0/1 knapsack: settle the set
//! of pairs of largest total w within the budget. Its fractional relaxation (take pairs by w / c,
//! the last one in part) is solved exactly by sorting and is never above the 0/1 optimum's
//! remaining error, so it is a valid lower bound for every scheduler.
//!
//! Costs are measured by the same traversal the schedulers use, without last frame's witnesses: a
//! witness re-test only ever *adds* a test to a pair that does not collide, so the bound stays a
//! lower bound.

use crate::config::Truth;
use crate::fixation::FrameView;
use crate::math::Vec3;
use crate::narrow_phase::{NarrowPhase, StepOutcome, separation, shape_separation};
use crate::sphere_tree::SphereTree;
use crate::world::World;

/// The truth about one candidate pair.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairTruth {
    /// Sphere tests to settle the pair from scratch.
    pub cost: u32,
    /// Whether it truly collides.
    pub colliding: bool,
    /// True separation of the leaf-sphere sets (0 when colliding).
    pub separation: f64,
    /// Facing points of the closest leaf spheres (the true gap's ends; world).
    pub gap_ends: [Vec3; 2],
}

impl PairTruth {
    /// True perceived error if this pair is deemed: F of `view`'s model on the true gap, at the
    /// gap's midpoint; 0 for a pair that truly collides.
    pub fn weight(&self, view: &FrameView<'_>) -> f64 {
        if self.colliding {
            0.0
        } else {
            let [a, b] = self.gap_ends;
            view.weight_points(a, b, (a + b) * 0.5)
        }
    }
}

/// Settle every pair of `candidates` exactly and record its truth.
pub fn truths(
    tree: &SphereTree,
    world: &World,
    candidates: &[(u32, u32)],
    out: &mut Vec<PairTruth>,
) {
    let mut np = NarrowPhase::default();
    np.reset(candidates);
    let mut stack = Vec::new();
    out.clear();
    for (i, &(a, b)) in candidates.iter().enumerate() {
        let before = np.tests;
        let colliding = np.resolve_fully(i, tree, world) == StepOutcome::Hit;
        let cost = (np.tests - before) as u32;
        let (a, b) = (a as usize, b as usize);
        let (sep, gap_ends) = if colliding {
            (0.0, [world.position[a]; 2])
        } else if tree.truth() == Truth::Shape {
            let (sep, ga, gb) = shape_separation(tree, world, a, b);
            (sep.max(0.0), [ga, gb])
        } else {
            let (sep, ca, cb) = separation(tree, world, a, b, &mut stack);
            let sep = sep.max(0.0);
            let u = (cb - ca).normalize_or_zero();
            let d = (cb - ca).length();
            let ga = ca + u * (0.5 * (d - sep));
            (sep, [ga, ga + u * sep])
        };
        out.push(PairTruth {
            cost,
            colliding,
            separation: sep,
            gap_ends,
        });
    }
}

/// The fractional-knapsack bound: the least true P left by any schedule of `budget` sphere tests,
/// given each pair's (true weight, cost). `items` is reordered.
pub fn bound(items: &mut Vec<(f64, u32)>, budget: u64) -> f64 {
    sort_for_bound(items);
    bound_sorted(items, budget)
}

/// Order `items` (true weight, cost) for [`bound_sorted`]: best weight per test first. Pairs of
/// weight 0 (truly colliding) are dropped: they come last and leave nothing whatever the budget.
/// Sorting once serves every budget of a frame.
pub fn sort_for_bound(items: &mut Vec<(f64, u32)>) {
    items.retain(|&(w, _)| w > 0.0);
    items.sort_unstable_by(|x, y| {
        let (rx, ry) = (x.0 / f64::from(x.1.max(1)), y.0 / f64::from(y.1.max(1)));
        ry.total_cmp(&rx)
    });
}

/// [`bound`] on items already ordered by [`sort_for_bound`].
pub fn bound_sorted(items: &[(f64, u32)], budget: u64) -> f64 {
    let mut left = budget as f64;
    let mut remaining = 0.0;
    for &(w, c) in items {
        let c = f64::from(c.max(1));
        if left >= c {
            left -= c;
        } else if left > 0.0 {
            remaining += w * (1.0 - left / c);
            left = 0.0;
        } else {
            remaining += w;
        }
    }
    remaining
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bound_takes_the_best_ratio_first_and_a_fraction_of_the_last() {
        // Ratios 5, 1, 0.5: with 3 tests take the first whole (cost 2) and half of the second.
        let mut items = vec![(2.0, 4), (10.0, 2), (2.0, 2)];
        assert_eq!(bound(&mut items, 3), 2.0 + 1.0);
        assert_eq!(bound(&mut items, 0), 14.0);
        assert_eq!(bound(&mut items, 100), 0.0);
        // A truly colliding pair (weight 0) leaves nothing and takes no budget from the others.
        let mut items = vec![(0.0, 1), (2.0, 4), (10.0, 2), (2.0, 2)];
        assert_eq!(bound(&mut items, 3), 2.0 + 1.0);
        assert_eq!(items.len(), 3);
    }
}
