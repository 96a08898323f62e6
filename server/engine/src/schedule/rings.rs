//! Gaze rings: round-robin, nearest the fixation first, for wall-clock frames too short to pay for
//! pricing every pair.
//!
//! Why: under a wall-clock budget of a tenth of the exact narrow phase, a pass that projects every
//! body and prices every pair costs more than the whole budget, so those frames shed the ordering
//! (see `collider`) and ran gaze-blind round-robin, whose first round (one root test per pair,
//! which settles most pairs) does not even reach every pair. Perceived error (paper section 3)
//! falls off with eccentricity, so the same round-robin serving the pairs near the fixation first
//! removes much more of it for the same tests. And the broad phase already knows where its pairs
//! are: sweep and prune lists them column by column, body by body along x
//! ([`crate::broad_phase::Columns`]), and a column is a rod along the screen's x axis at one height
//! and depth. So no pair is read to place it: per column, its band on screen is tested against the
//! rings, and each ring's x-window is counted off the column's sorted x, which gives each ring's
//! pairs as a range or two of the candidate list per run of the column.
//!
//! The rings are nested squares around the fixation ([`RINGS_DEG`]). The pairs of the two rings
//! within the fovea's 5 degrees are resolved whole first, nearest the fixation first (by the
//! screen distance of the pair's centre); then every round of round-robin takes the outer ring,
//! then every other pair, a pair stepped one level a round. Why whole: a wall-clock frame of
//! round-robin or the priced scheduler has already settled every root-separated pair in one pass
//! (`NarrowPhase::settle_separate_roots`), so every pair left open overlaps at the root and needs
//! a descent of about 20 tests to settle; stepped a level a round, such frames settled almost none
//! of them, and ended on a plateau of true P that a third of the exact narrow phase did not
//! lower below a tenth's. Resolved whole (without storing and reloading its list at every level),
//! the pairs a viewer sees are settled, and the same time does more tests. Before the root pass,
//! stepping was better (deep descents into true collisions remove no error, and the root tests
//! came first): measured in docs/BENCHMARKS.md. The first round of the rest runs straight off
//! the ranges; only pairs left open are queued for the next.
//!
//! Cost: a few dozen flops per column and a pass over the x of the bodies of the columns whose band
//! meets the outer ring, and a projection of each open pair of the inner two rings (a few dozen
//! pairs at the paper's N) to sort them. The order is a heuristic: every
//! pair's test is exact whichever ring it is in, and every pair is in exactly one place of the
//! order.

use super::Work;
use crate::broad_phase::{Columns, RUNS};
use crate::budget::Meter;
use crate::narrow_phase::{NarrowPhase, StepOutcome};
use crate::perception::Viewer;

/// Ring half-widths, degrees of visual angle, nearest first: about the fovea; where the steep end
/// of the scheduling model's fall-off (F2, exp(-e / C), with C = 1 degree) is down to 1%; and
/// where its shallow end (C = 10) still weighs a pair about a third. Measured against 3/8/20,
/// 2/6/20 and 1.5/4/9 (docs/BENCHMARKS.md): none better. The rings are squares in pixels,
/// converted at the screen centre, where a degree spans the fewest pixels: away from the centre
/// a ring spans somewhat fewer degrees than its name.
pub const RINGS_DEG: [f64; 3] = [2.0, 5.0, 12.0];

const RINGS: usize = RINGS_DEG.len();

/// The rings whose pairs are resolved whole, nearest the fixation first, before any other pair
/// is stepped: the two within the fovea's 5 degrees ([`crate::report::FOVEAL_DEG`]). Measured
/// open loop against none, the inner ring alone and all three (docs/BENCHMARKS.md).
const WHOLE_RINGS: usize = 2;

/// Ranges of the candidate list, written without a branch per range.
#[derive(Debug, Default)]
struct Ranges {
    buf: Vec<[u32; 2]>,
    len: usize,
}

impl Ranges {
    /// Empty, with room for `n` ranges; storage a much larger frame left is given back.
    fn reset(&mut self, n: usize) {
        if self.buf.len() < n {
            self.buf.resize(n, [0, 0]);
        } else if self.buf.len() > 4 * n.max(1024) {
            self.buf.truncate(2 * n.max(1024));
            self.buf.shrink_to_fit();
        }
        self.len = 0;
    }

    /// Append `lo..hi` if it is not empty (most ranges of a frame are, unpredictably: the slot is
    /// written either way and kept only if not).
    #[inline]
    fn put(&mut self, lo: u32, hi: u32) {
        self.buf[self.len] = [lo, hi];
        self.len += usize::from(lo < hi);
    }

    fn as_slice(&self) -> &[[u32; 2]] {
        &self.buf[..self.len]
    }

    fn pairs(&self) -> usize {
        self.as_slice().iter().map(|r| (r[1] - r[0]) as usize).sum()
    }
}

/// The rings' reusable buffers.
#[derive(Debug, Default)]
pub struct Rings {
    /// Per ring, nearest first, then the rest: the pairs' ranges.
    ranges: [Ranges; RINGS + 1],
    /// Pairs left open by the first round, for the next rounds.
    queue: Vec<u32>,
    /// The open pairs of the rings resolved whole, keyed by their squared distance on screen
    /// from the fixation.
    near: Vec<(u64, u32)>,
    /// The same pairs in that order.
    order: Vec<u32>,
    /// Clock time of the last run's placing.
    setup_ns: u64,
}

impl Rings {
    /// Read the buffers back into cache (see [`crate::warm`]).
    pub fn warm(&self) {
        for r in &self.ranges {
            crate::warm::lines(r.as_slice());
        }
        crate::warm::lines(&self.queue);
    }

    /// Pairs the last [`Self::run`] placed in each ring, nearest first, and elsewhere (last).
    pub fn placed(&self) -> [usize; RINGS + 1] {
        std::array::from_fn(|k| self.ranges[k].pairs())
    }

    /// Clock time the last [`Self::run`] spent placing the pairs before its first test (ns).
    pub fn setup_ns(&self) -> u64 {
        self.setup_ns
    }

    /// Place the candidates (laid out by `columns`) in rings around `fixation_px` widened by
    /// `uncertainty_deg`; resolve the open pairs of the inner [`WHOLE_RINGS`] whole, nearest
    /// first, then run round-robin over the rest, each round the outer ring first, until every
    /// pair is settled or `meter` says stop. False, and nothing done, if `columns` does not
    /// describe `np`'s pairs (another frame's index).
    #[allow(clippy::too_many_arguments)]
    pub fn run(
        &mut self,
        np: &mut NarrowPhase,
        work: &Work<'_>,
        columns: &Columns,
        viewer: &Viewer,
        fixation_px: [f64; 2],
        uncertainty_deg: f64,
        meter: &mut Meter<'_>,
    ) -> bool {
        match self.fovea(
            np,
            work,
            columns,
            viewer,
            fixation_px,
            uncertainty_deg,
            meter,
        ) {
            None => false,
            Some(false) => true,
            Some(true) => {
                self.rest(np, work, meter);
                true
            }
        }
    }

    /// The rest of [`Self::run`] after [`Self::fovea`]: round-robin over the pairs outside the
    /// inner rings as last placed, each round the outer ring first, until every pair is settled
    /// or `meter` says stop.
    pub fn rest(&mut self, np: &mut NarrowPhase, work: &Work<'_>, meter: &mut Meter<'_>) {
        // The first round straight off the ranges: no queue of every pair is built.
        self.queue.clear();
        for ranges in &self.ranges[WHOLE_RINGS..] {
            for &[lo, hi] in ranges.as_slice() {
                for i in lo..hi {
                    if meter.exhausted(np.tests) {
                        return;
                    }
                    if np.pairs[i as usize].status.is_open()
                        && np.step(i as usize, work.tree, work.world) == StepOutcome::Active
                    {
                        self.queue.push(i);
                    }
                }
            }
        }
        np.compact_if_sparse();
        super::round_robin(np, &mut self.queue, work, meter);
    }

    /// The first part of [`Self::run`]: place the rings and resolve the open pairs of the inner
    /// [`WHOLE_RINGS`] whole, nearest the fixation first. None, and nothing done, if `columns`
    /// does not describe `np`'s pairs; otherwise whether the budget is left (every foveal pair
    /// settled). Also what a frame that orders its work does first (see `collider`): the
    /// priced order alone leaves the foveal pairs likely to collide for last.
    #[allow(clippy::too_many_arguments)]
    pub fn fovea(
        &mut self,
        np: &mut NarrowPhase,
        work: &Work<'_>,
        columns: &Columns,
        viewer: &Viewer,
        fixation_px: [f64; 2],
        uncertainty_deg: f64,
        meter: &mut Meter<'_>,
    ) -> Option<bool> {
        if !columns.covers(np.pairs.len()) {
            return None;
        }
        let start = meter.now_ns();
        self.place(columns, viewer, fixation_px, uncertainty_deg);
        self.setup_ns = meter.now_ns().saturating_sub(start);
        let pos = &work.world.position;
        self.near.clear();
        for ranges in &self.ranges[..WHOLE_RINGS] {
            for &[lo, hi] in ranges.as_slice() {
                for i in lo..hi {
                    let p = &np.pairs[i as usize];
                    if p.status.is_open() {
                        let s = viewer.project((pos[p.a as usize] + pos[p.b as usize]) * 0.5);
                        let (dx, dy) = (s[0] - fixation_px[0], s[1] - fixation_px[1]);
                        // Non-negative, so the bits order as the values do.
                        self.near.push(((dx * dx + dy * dy).to_bits(), i));
                    }
                }
            }
        }
        self.near.sort_unstable();
        // Whole pairs on the frame's threads and the exact frame's kernels (see
        // `NarrowPhase::resolve_ordered`): at 10,000 bodies the inner rings' open pairs took
        // about 2 ms of a 4 ms frame one by one on one thread.
        self.order.clear();
        self.order.extend(self.near.iter().map(|&(_, i)| i));
        Some(np.resolve_ordered(
            work.tree,
            work.world,
            &self.order,
            work.threads,
            &mut |tests| !meter.exhausted_between_pairs(tests),
        ))
    }

    /// Fill the ranges of every ring and of the rest.
    fn place(
        &mut self,
        columns: &Columns,
        viewer: &Viewer,
        fixation_px: [f64; 2],
        uncertainty_deg: f64,
    ) {
        // Per buffer, at most two ranges per run of a column with bodies (or one for the whole
        // column); a column without bodies has no pairs and is skipped.
        let most = columns.nonempty * RUNS * 2 + 1;
        for r in &mut self.ranges {
            r.reset(most);
        }
        let ppd = viewer.display.pixels_per_degree();
        let radius: [f64; RINGS] =
            std::array::from_fn(|k| (RINGS_DEG[k] + uncertainty_deg.max(0.0)) * ppd);
        let f = viewer.focal_px();
        let inv_f = 1.0 / f;
        let eye = viewer.eye;
        // The fixation relative to the screen centre (pixels, y up like the world's).
        let fx = fixation_px[0] - 0.5 * f64::from(viewer.display.width_px);
        let fy = 0.5 * f64::from(viewer.display.height_px) - fixation_px[1];
        // A pair's centre is within half the boxes' reach of its swept body on every axis, and
        // a column's swept bodies lie in its cell: its pairs' centres lie in the cell grown by
        // half the reach (and a hair, for the rounding of the cell arithmetic).
        let half_reach = columns.half_reach * (1.0 + 1e-6);
        let [q0, q1, q2, rest] = &mut self.ranges;
        let n = columns.per_axis;
        // Nested, from the outside in: an empty ring sits at its outer ring's start.
        let nest = |(l, h): (usize, usize), (ol, oh): (usize, usize)| {
            let (l, h) = (l.max(ol), h.min(oh));
            if l < h { (l, h) } else { (ol, ol) }
        };
        for iz in 0..n {
            // At depth d (from the eye) a point is at screen offset ((x - ex) f / d,
            // (y - ey) f / d); within half-width r of the fixation iff |(x - ex) f - fx d| and
            // |(y - ey) f - fy d| are both at most r d. A layer of columns spans depths d0..d1
            // (its cells grown by half the reach), and both bounds are linear in d, so extreme
            // at d0 or d1: per ring, the x-window of swept bodies whose pairs' centres can be
            // within the ring at some depth of the layer.
            let z0 = columns.lo[1] + iz as f64 * columns.cell;
            let (d0, d1) = (
                (eye.z - (z0 + columns.cell) - half_reach).max(1e-9),
                (eye.z - z0 + half_reach).max(1e-9),
            );
            let window = |r: f64| -> (f64, f64) {
                let (a0, a1) = ((fx - r) * d0 * inv_f, (fx - r) * d1 * inv_f);
                let (b0, b1) = ((fx + r) * d0 * inv_f, (fx + r) * d1 * inv_f);
                (
                    eye.x + a0.min(a1) - half_reach,
                    eye.x + b0.max(b1) + half_reach,
                )
            };
            let windows: [(f64, f64); RINGS] = std::array::from_fn(|j| window(radius[j]));
            for iy in 0..n {
                let c = iz * n + iy;
                let xs = columns.xs(c);
                if xs.is_empty() {
                    continue;
                }
                let block = columns.block(c);
                // The y term over the column's grown cell is linear in (y, d): its extremes are
                // at the corners. A ring the band misses gets an empty window.
                let y0 = columns.lo[0] + iy as f64 * columns.cell;
                let (lo_y, hi_y) = (
                    y0 - half_reach - eye.y,
                    y0 + columns.cell + half_reach - eye.y,
                );
                let corners = [
                    lo_y * f - fy * d0,
                    lo_y * f - fy * d1,
                    hi_y * f - fy * d0,
                    hi_y * f - fy * d1,
                ];
                let (lo, hi) = corners
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &v| {
                        (l.min(v), h.max(v))
                    });
                let missed = |j: usize| lo > radius[j] * d1 || hi < -radius[j] * d1;
                if missed(RINGS - 1) {
                    rest.put(block.start as u32, block.end as u32);
                    continue;
                }
                // The bodies are sorted by x, so a window's bodies k0..k1 are counted, not
                // searched for: one pass over a few dozen values without a branch.
                let mut k = [0usize; 2 * RINGS];
                for &x in xs {
                    for (j, &(x_lo, x_hi)) in windows.iter().enumerate() {
                        k[2 * j] += usize::from(x < x_lo);
                        k[2 * j + 1] += usize::from(x <= x_hi);
                    }
                }
                for (j, pair) in k.chunks_exact_mut(2).enumerate() {
                    if missed(j) {
                        pair.fill(0);
                    }
                }
                let (l2, h2) = (k[4], k[5]);
                if l2 >= h2 {
                    rest.put(block.start as u32, block.end as u32);
                    continue;
                }
                let (l1, h1) = nest((k[2], k[3]), (l2, h2));
                let (l0, h0) = nest((k[0], k[1]), (l1, h1));
                for r in 0..RUNS {
                    let run = columns.run(c, r);
                    rest.put(run[0], run[l2]);
                    rest.put(run[h2], run[xs.len()]);
                    q0.put(run[l0], run[h0]);
                    q1.put(run[l1], run[l0]);
                    q1.put(run[h0], run[h1]);
                    q2.put(run[l2], run[l1]);
                    q2.put(run[h1], run[h2]);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::budget::FrameBudget;
    use crate::narrow_phase::PairStatus;
    use crate::schedule::Priorities;
    use crate::schedule::calibration::Calibration;
    use crate::{FrozenClock, SimConfig, Simulation};

    fn scene(bodies: u32, seed: u64) -> Simulation {
        let mut cfg = SimConfig::default();
        cfg.scene = crate::SceneConfig::paper(bodies, seed);
        let mut sim = Simulation::new(cfg).expect("valid");
        for _ in 0..20 {
            sim.step(None, &FrozenClock);
        }
        sim
    }

    /// Where each pair was placed: its ring (0 nearest), or RINGS for the rest.
    fn placement(rings: &Rings, pairs: usize) -> Vec<Vec<usize>> {
        let mut at = vec![Vec::new(); pairs];
        for (k, r) in rings.ranges.iter().enumerate() {
            for &[lo, hi] in r.as_slice() {
                for i in lo..hi {
                    at[i as usize].push(k);
                }
            }
        }
        at
    }

    #[test]
    fn every_pair_is_placed_once_and_every_pair_within_a_ring_is_in_it_or_nearer() {
        // One body and one column per axis up to the paper's scenes.
        for (bodies, seed) in [(1, 5), (2, 6), (12, 7), (300, 1), (500, 2), (2_000, 3)] {
            let sim = scene(bodies, seed);
            let input = sim.frame_input();
            let columns = input.columns.expect("sweep and prune at this N");
            let viewer = input.viewer;
            let ppd = viewer.display.pixels_per_degree();
            let mut rings = Rings::default();
            // Centre, off centre, a corner and off the screen; a sure fixation and an uncertain
            // one, whose rings grow by the uncertainty.
            for ((x, y), uncertainty) in [(0.5, 0.5), (0.3, 0.6), (0.02, 0.97), (1.3, -0.2)]
                .into_iter()
                .flat_map(|f| [(f, 0.0), (f, 1.5)])
            {
                let px = viewer.to_pixels(x, y);
                rings.place(columns, viewer, px, uncertainty);
                let at = placement(&rings, input.candidates.len());
                let mut near = [0usize; RINGS];
                for (i, &(a, b)) in input.candidates.iter().enumerate() {
                    assert_eq!(at[i].len(), 1, "pair {i} placed {:?}", at[i]);
                    let ring = at[i][0];
                    let pos = &input.world.position;
                    let s = viewer.project((pos[a as usize] + pos[b as usize]) * 0.5);
                    let off = (s[0] - px[0]).abs().max((s[1] - px[1]).abs());
                    for k in 0..RINGS {
                        if off <= (RINGS_DEG[k] + uncertainty) * ppd {
                            near[k] += 1;
                            assert!(ring <= k, "pair {i} {off:.1} px away placed in {ring}");
                        }
                    }
                }
                // The rings are not vacuous: over the volume, the inner one holds the pairs near
                // the fixation, and it does not hold every pair.
                let placed = rings.placed();
                assert_eq!(placed.iter().sum::<usize>(), input.candidates.len());
                if bodies >= 300 && uncertainty == 0.0 {
                    if (0.2..=0.8).contains(&x) && (0.2..=0.8).contains(&y) {
                        assert!(near[0] > 0, "{bodies} {x} {y}");
                    }
                    assert!(placed[0] < input.candidates.len() / 2, "{placed:?}");
                }
            }
        }
    }

    #[test]
    fn the_fovea_is_resolved_whole_nearest_first_then_the_outer_ring_is_stepped() {
        let sim = scene(500, 4);
        let input = sim.frame_input();
        let columns = input.columns.expect("sweep and prune at this N");
        let (pr, cal) = (Priorities::default(), Calibration::uninformed(4));
        let work = Work {
            tree: input.tree,
            world: input.world,
            view: None,
            priorities: &pr,
            calibration: &cal,
            threads: 1,
        };
        let px = input.viewer.to_pixels(0.45, 0.55);
        let mut rings = Rings::default();
        rings.place(columns, input.viewer, px, 0.0);
        let at = placement(&rings, input.candidates.len());
        // The foveal rings' pairs by the screen distance of their centre from the fixation,
        // each with its exact state and the tests a whole descent takes, one by one.
        let pos = &input.world.position;
        let mut order: Vec<(f64, usize)> = (0..input.candidates.len())
            .filter(|&i| at[i][0] < WHOLE_RINGS)
            .map(|i| {
                let (a, b) = input.candidates[i];
                let s = input
                    .viewer
                    .project((pos[a as usize] + pos[b as usize]) * 0.5);
                ((s[0] - px[0]).powi(2) + (s[1] - px[1]).powi(2), i)
            })
            .collect();
        order.sort_by(|x, y| x.partial_cmp(y).expect("finite"));
        assert!(order.len() >= 4, "{} foveal pairs", order.len());
        let whole: Vec<(PairStatus, u64)> = order
            .iter()
            .map(|&(_, i)| {
                let mut np = NarrowPhase::default();
                np.reset(input.candidates);
                np.resolve_fully(i, input.tree, input.world);
                (np.pairs[i].status, np.tests)
            })
            .collect();
        let clock = FrozenClock;
        // A budget of exactly the first half's descents resolves those pairs and nothing else.
        let half = order.len() / 2;
        let budget: u64 = whole[..half].iter().map(|w| w.1).sum();
        let mut np = NarrowPhase::default();
        np.reset(input.candidates);
        let mut meter = Meter::new(FrameBudget::Tests(budget), &clock);
        assert!(rings.run(&mut np, &work, columns, input.viewer, px, 0.0, &mut meter));
        assert_eq!(np.tests, budget);
        let rank: std::collections::HashMap<usize, usize> = order
            .iter()
            .enumerate()
            .map(|(k, &(_, i))| (i, k))
            .collect();
        for (i, p) in np.pairs.iter().enumerate() {
            match rank.get(&i) {
                Some(&k) if k < half => {
                    assert!(!p.status.is_open(), "pair {i}, {k}th nearest, left open");
                    assert_eq!(p.status, whole[k].0, "pair {i}");
                }
                _ => assert_eq!(p.status, PairStatus::Untested, "pair {i} tested"),
            }
        }
        // Every foveal descent and one test for each pair of the outer ring: the fovea settled
        // exactly, the outer ring stepped, the rest untouched.
        let outer = rings.placed()[WHOLE_RINGS];
        assert!(outer > 0);
        let budget: u64 = whole.iter().map(|w| w.1).sum::<u64>() + outer as u64;
        let mut np = NarrowPhase::default();
        np.reset(input.candidates);
        let mut meter = Meter::new(FrameBudget::Tests(budget), &clock);
        assert!(rings.run(&mut np, &work, columns, input.viewer, px, 0.0, &mut meter));
        assert_eq!(np.tests, budget);
        for (i, p) in np.pairs.iter().enumerate() {
            let ring = at[i][0];
            let stepped = p.status != PairStatus::Untested;
            if let Some(&k) = rank.get(&i) {
                assert_eq!(p.status, whole[k].0, "foveal pair {i}");
            } else {
                assert_eq!(stepped, ring == WHOLE_RINGS, "pair {i} in ring {ring}");
            }
        }
    }
}
