//! Priced scheduling (ours, beyond the paper): always take the step whose pair offers the most
//! expected false-positive perceived error removed per expected sphere test.
//!
//! Section 3's perceived error of a deemed pair is F(g', e); a deemed pair that truly collides adds
//! nothing a viewer could see. So the worth of settling a pair is its perceptual fall-off at the
//! pair (from [`super::Priorities`]) times its on-screen scale times the *expected true gap it would
//! leave if deemed*: P(not colliding | state) times the mean true gap of such pairs, both calibrated
//! ([`super::calibration`]). Its price is the expected number of sphere tests to settle it from its
//! state. Value over price orders the work; after each step the pair's state changes and it is
//! priced again. Cheap-first emerges from the prices: an untested pair whose root spheres cannot
//! touch is settled by one test with certainty, and round-robin's first round owes its strength
//! to exactly such pairs.
//!
//! What a pair will cost is what the state predicts worst, and what matters most: pricing every
//! pair by its true cost would raise the share of the achievable reduction at a tenth of the exact
//! cost from 0.79 to 0.88 (open loop, N = 500, C = 5 degrees). Bodies move little between frames,
//! so the scheduler remembers the pairs its last run settled separate below the root and the tests
//! each took ([`Memory`]); such a pair is priced from a calibrated bin of its remembered cost, and
//! after each step by what its memory says is left, until it has cost more than remembered. The
//! memory is kept under sphere-test budgets only: under a wall-clock budget, looking every pair
//! up costs more of the budget than the better order gives back (measured at 10,000 bodies).
//!
//! The queue is a bucketed max-queue on the bits of the f32 value (quarter octaves): push and pop
//! are a few instructions, not a heap's log n comparisons, because under wall-clock budgets this
//! bookkeeping is paid from the same budget as the sphere tests. Within a bucket the order is last
//! in, first out; values within a bucket are treated as equal. The frame's first prices
//! (every pair untested) are not pushed one by one: they are counting-sorted into one array in a
//! pass that only writes sequential arrays, and the queue holds only pairs put back after a step;
//! popping takes whichever of the two is higher, so the order is exactly the queue's.

use super::calibration::{self, Bin};
use super::{Needs, Passes, Prioritise, Scheduler, Work};
use crate::budget::Meter;
use crate::config::PricedOptions;
use crate::narrow_phase::{NarrowPhase, StepOutcome};

/// How far (in quarter octaves) a pair being worked on may fall below the best waiting pair before
/// it is put back: 1 is a factor of about 1.19 (0, 2 and 4 measured the same under sphere-test
/// budgets).
const COMMIT_BUCKETS: usize = 1;

/// Buckets of the queue: f32 exponent and two mantissa bits of a positive value.
const BUCKETS: usize = 1024;
const WORDS: usize = BUCKETS / 64;

/// A max-queue of pair indices on bucketed f32 keys.
#[derive(Debug, Clone)]
struct BucketQueue {
    buckets: Vec<Vec<u32>>,
    mask: [u64; WORDS],
    summary: u16,
    len: usize,
}

impl Default for BucketQueue {
    fn default() -> Self {
        Self {
            buckets: vec![Vec::new(); BUCKETS],
            mask: [0; WORDS],
            summary: 0,
            len: 0,
        }
    }
}

impl BucketQueue {
    fn clear(&mut self) {
        for w in 0..WORDS {
            let mut m = self.mask[w];
            while m != 0 {
                let b = m.trailing_zeros() as usize;
                self.buckets[w * 64 + b].clear();
                m &= m - 1;
            }
        }
        self.mask = [0; WORDS];
        self.summary = 0;
        self.len = 0;
    }

    #[inline]
    fn key(value: f32) -> usize {
        // Positive floats order like their bits; NaN, zero and negatives go to the bottom.
        // The positive floats, +inf included, are exactly the bit patterns 1..=0x7f80_0000,
        // whose top 11 bits are at most 1020. Tested on the bits and applied by a product so
        // that it stays free of branches: zero weights (far from the fixation) and positive
        // ones mix unpredictably, and a comparison of floats compiled to a branch.
        let bits = value.to_bits();
        let positive = bits.wrapping_sub(1) < 0x7f80_0000;
        (bits >> 21) as usize * usize::from(positive)
    }

    #[inline]
    fn push(&mut self, value: f32, pair: u32) {
        let k = Self::key(value);
        self.buckets[k].push(pair);
        self.mask[k / 64] |= 1 << (k % 64);
        self.summary |= 1 << (k / 64);
        self.len += 1;
    }

    /// Key of the best waiting entry (0 when empty).
    #[inline]
    fn top_key(&self) -> usize {
        if self.summary == 0 {
            return 0;
        }
        let w = 15 - self.summary.leading_zeros() as usize;
        w * 64 + 63 - self.mask[w].leading_zeros() as usize
    }

    #[inline]
    fn pop(&mut self) -> Option<u32> {
        if self.summary == 0 {
            return None;
        }
        let w = 15 - self.summary.leading_zeros() as usize;
        let b = 63 - self.mask[w].leading_zeros() as usize;
        let k = w * 64 + b;
        let pair = self.buckets[k].pop();
        if self.buckets[k].is_empty() {
            self.mask[w] &= !(1 << b);
            if self.mask[w] == 0 {
                self.summary &= !(1 << w);
            }
        }
        self.len -= 1;
        pair
    }
}

/// The frame's first prices, counting-sorted: bucket descending, and within a bucket the higher
/// pair index first (the order a [`BucketQueue`] fed the pairs in index order pops them).
#[derive(Debug, Clone, Default)]
struct Initial {
    /// Bucket key per pair.
    keys: Vec<u16>,
    /// Pairs per bucket of `span`, then where each bucket's run starts in `order`; zero between
    /// sorts.
    counts: Vec<u32>,
    /// (pair, key) in pop order.
    order: Vec<(u32, u16)>,
    /// Next entry of `order` to pop.
    next: usize,
    /// Least and greatest key counted (empty: least > greatest).
    span: (usize, usize),
}

impl Initial {
    /// Make room for `n` pairs' keys, every count zero.
    fn clear(&mut self, n: usize) {
        // Only the length: every pair's key is written before the sort.
        self.keys.resize(n, 0);
        if self.counts.len() != BUCKETS {
            self.counts.clear();
            self.counts.resize(BUCKETS, 0);
        }
        self.next = 0;
        self.span = (BUCKETS, 0);
    }

    /// Key of the next entry (0 when drained, like an empty queue).
    #[inline]
    fn top_key(&self) -> usize {
        self.order.get(self.next).map_or(0, |&(_, k)| k as usize)
    }

    /// Sort the pairs by `keys` (counted in `counts` over `span`) into `order`; key `j` is pair
    /// `index[j]`'s where an index is given, pair `j`'s otherwise.
    fn sort(&mut self, index: Option<&[u32]>) {
        let (lo, hi) = self.span;
        self.next = 0;
        if lo > hi {
            self.order.clear();
            return;
        }
        let counts = &mut self.counts[lo..=hi];
        // Exclusive prefix from the top bucket down: a bucket's run starts after every higher one.
        let mut at = 0u32;
        for c in counts.iter_mut().rev() {
            let k = *c;
            *c = at;
            at += k;
        }
        // Only the length: the sort writes every entry once.
        self.order.resize(self.keys.len(), (0, 0));
        for (j, &k) in self.keys.iter().enumerate().rev() {
            let slot = &mut counts[k as usize - lo];
            let i = index.map_or(j as u32, |index| index[j]);
            self.order[*slot as usize] = (i, k);
            *slot += 1;
        }
        counts.iter_mut().for_each(|c| *c = 0);
    }
}

/// The priced scheduler.
#[derive(Debug, Default)]
pub struct Priced {
    options: PricedOptions,
    queue: BucketQueue,
    initial: Initial,
    /// Per pair: fall-off times scale, the state-independent part of its value.
    weight: Vec<f32>,
    /// Per pair: its centre-distance bucket.
    dist: Vec<u8>,
    /// The open pairs' indices, where only they are priced (see [`Self::price`]).
    open: Vec<u32>,
    /// The pairs in the order of their first prices, for a wall-clock run (see
    /// [`Self::run_whole`]).
    order: Vec<u32>,
    /// Per calibration bin: value per unit weight (gain over price, by the switches), and
    /// whether it is the horizons' rate ([`Bin::rate`]; sphere-test budgets) or the whole
    /// descent's mean (wall-clock budgets, see [`Scheduler::run`]).
    ratio: Vec<f32>,
    ratio_rates: Option<bool>,
    /// Clock time of the last run's pricing pass.
    ordering_ns: u64,
    /// Distance buckets from squared distances.
    buckets: calibration::SquaredBuckets,
    /// Per pair: the sphere tests it took last frame if it was settled separate below its root
    /// then (0: not remembered), and the tests spent on it this frame.
    remembered: Vec<u32>,
    spent: Vec<u32>,
    /// What this scheduler's last run settled, for the next one (see [`Memory`]), and this
    /// run's (first body, second body, tests) of the pairs it settled separate below the root.
    memory: Memory,
    settled: Vec<(u32, u32, u32)>,
}

/// Pairs the last run settled separate below their root, with the sphere tests each took, kept
/// under the pair's first body (two slots a body; a body's further pairs are not kept). Why:
/// bodies move little between frames, so last frame's cost of a pair predicts this frame's far
/// better than its distance does, and a pair a schedule can see will be cheap is worth taking
/// early (see [`calibration::remembered_key`]). Only a run of the frame just before counts: a
/// frame this scheduler did not order leaves nothing ([`Scheduler::forget`]).
///
/// A bit per body says whether it has any slot filled: every candidate pair is looked up when
/// the frame is priced, and at 10,000 bodies reading the slots of every pair's first body (a
/// random read in 160 KB) cost a third more than the pricing pass itself, which under a
/// wall-clock budget is paid from the tests; the bits (1.25 KB) stay in the nearest cache and
/// only a few percent of the bodies have a slot to read.
#[derive(Debug, Clone, Default)]
struct Memory {
    /// Per body: (partner, tests) twice; partner `u32::MAX` where empty. Valid only where the
    /// body's bit in `any` is set.
    slots: Vec<[(u32, u32); 2]>,
    /// Per body, one bit: it has a slot filled.
    any: Vec<u64>,
}

impl Memory {
    const EMPTY: [(u32, u32); 2] = [(u32::MAX, 0); 2];

    fn forget(&mut self) {
        self.slots.clear();
        self.any.clear();
    }

    /// Bodies the memory is sized for.
    fn bodies(&self) -> usize {
        self.slots.len()
    }

    /// The tests pair (a, b) took when remembered (0 if not).
    #[inline]
    fn get(&self, a: u32, b: u32) -> u32 {
        let a = a as usize;
        let set = self.any.get(a / 64).is_some_and(|w| w >> (a % 64) & 1 == 1);
        if !set {
            return 0;
        }
        let s = &self.slots[a];
        let first = if s[0].0 == b { s[0].1 } else { 0 };
        let second = if s[1].0 == b { s[1].1 } else { 0 };
        first | second
    }

    /// Keep `settled` (this run's pairs settled separate below the root: first body, second
    /// body, tests) for `bodies` bodies, in place of the last run's.
    fn keep(&mut self, settled: &[(u32, u32, u32)], bodies: usize) {
        if self.slots.len() != bodies {
            self.slots.clear();
            self.slots.resize(bodies, Self::EMPTY);
        }
        self.any.clear();
        self.any.resize(bodies.div_ceil(64), 0);
        for &(a, b, t) in settled {
            let a = a as usize;
            let Some(s) = self.slots.get_mut(a) else {
                continue;
            };
            let bit = 1u64 << (a % 64);
            if self.any[a / 64] & bit == 0 {
                *s = Self::EMPTY;
                self.any[a / 64] |= bit;
            }
            let k = usize::from(s[0].0 != u32::MAX);
            if s[k].0 == u32::MAX {
                s[k] = (b, t);
            }
        }
    }
}

impl Priced {
    /// A priced scheduler with these ablation switches.
    pub fn new(options: PricedOptions) -> Self {
        Self {
            options,
            ..Self::default()
        }
    }

    #[inline]
    fn value(&self, weight: f32, bin: &Bin, rates: bool) -> f32 {
        if rates && self.options.probability && self.options.cost {
            return weight * bin.rate;
        }
        let gain = if self.options.probability {
            bin.p_separate * bin.gap
        } else {
            1.0
        };
        let price = if self.options.cost { bin.cost } else { 1.0 };
        weight * gain / price
    }

    /// Value per unit weight of pair `i` after a step. A remembered pair is priced by what its
    /// memory says is left, the tests it took last frame less those spent on it now, while that
    /// is positive (its calibrated chance of being separate and gap stand); past that the
    /// memory was wrong and the pair is priced by its state like any other.
    #[inline]
    fn ratio_after_step<const REMEMBER: bool>(
        &self,
        np: &NarrowPhase,
        work: &Work<'_>,
        i: usize,
    ) -> f32 {
        let (remembered, spent) = if REMEMBER {
            (self.remembered[i], self.spent[i])
        } else {
            (0, 0)
        };
        if remembered > spent && self.options.probability && self.options.cost {
            let cal = work.calibration;
            let bin = &cal.bins()[cal.initial_index(false, remembered, self.dist[i])];
            bin.p_separate * bin.gap / (remembered - spent) as f32
        } else {
            self.ratio[work.calibration.index_of(np, i, self.dist[i])]
        }
    }

    /// The run, with the memory (`REMEMBER`) or without any of its bookkeeping.
    fn run_with<const REMEMBER: bool>(
        &mut self,
        np: &mut NarrowPhase,
        work: &Work<'_>,
        meter: &mut Meter<'_>,
    ) {
        let cal = work.calibration;
        let started = meter.now_ns();
        self.queue.clear();
        let n = np.pairs.len();
        // Only the lengths: the pricing pass writes every pair's weight, distance and memory,
        // and a pair's tests are zeroed by its first step (filling 28,000 entries of each a
        // frame, at 10,000 bodies, is time a wall-clock budget pays).
        self.weight.resize(n, 0.0);
        self.dist.resize(n, 0);
        if REMEMBER {
            self.remembered.resize(n, 0);
            self.spent.resize(n, 0);
        }
        if self.memory.bodies() != work.world.len() {
            self.memory.forget();
        }
        self.settled.clear();
        if self.ratio.len() != cal.bins().len() || self.ratio_rates != Some(REMEMBER) {
            self.ratio = cal
                .bins()
                .iter()
                .map(|b| self.value(1.0, b, REMEMBER))
                .collect();
            self.ratio_rates = Some(REMEMBER);
        }
        // Every open pair is untested; pairs a foveal pass settled first are skipped below.
        debug_assert!(
            np.pairs
                .iter()
                .all(|p| !p.status.is_open() || p.stage() == 0)
        );
        self.price::<REMEMBER>(np, work, meter.counts_time());
        self.ordering_ns = meter.now_ns().saturating_sub(started);
        if meter.counts_time() {
            self.run_whole(np, work, meter);
            return;
        }
        'work: loop {
            // The higher of the sorted first prices and the pairs put back; on a tie the put-back
            // pair, as the queue's last-in-first-out would.
            let pair = if self.queue.len > 0 && self.queue.top_key() >= self.initial.top_key() {
                self.queue.pop()
            } else if let Some(&(p, _)) = self.initial.order.get(self.initial.next) {
                self.initial.next += 1;
                Some(p)
            } else {
                None
            };
            let Some(pair) = pair else { break };
            let i = pair as usize;
            if !np.pairs[i].status.is_open() {
                continue;
            }
            // Work on the pair while it stays within COMMIT_BUCKETS of the best other one: a
            // descent abandoned half way is sphere tests spent for nothing, and re-pricing after
            // every step would hop between near-equal pairs and leave many of them half done.
            loop {
                if meter.exhausted(np.tests) {
                    break 'work;
                }
                if !REMEMBER {
                    if np.step(i, work.tree, work.world) != StepOutcome::Active {
                        break;
                    }
                } else {
                    if np.pairs[i].stage() == 0 {
                        self.spent[i] = 0;
                    }
                    let before = np.tests;
                    let outcome = np.step(i, work.tree, work.world);
                    self.spent[i] += (np.tests - before) as u32;
                    if outcome != StepOutcome::Active {
                        let p = &np.pairs[i];
                        if outcome == StepOutcome::Separate && p.resolved_level > 1 {
                            self.settled.push((p.a, p.b, self.spent[i]));
                        }
                        break;
                    }
                }
                let v = self.weight[i] * self.ratio_after_step::<REMEMBER>(np, work, i);
                let top = self.queue.top_key().max(self.initial.top_key());
                if BucketQueue::key(v) + COMMIT_BUCKETS < top {
                    self.queue.push(v, pair);
                    break;
                }
            }
        }
        if REMEMBER {
            self.memory.keep(&self.settled, work.world.len());
        }
    }

    /// Under a wall-clock budget: settle the pairs whole, in the order of their first prices, on
    /// the frame's threads and the exact frame's kernels, asking the meter between pairs
    /// ([`NarrowPhase::resolve_ordered`]). Why not step by step as under a sphere-test
    /// budget: there a step is the unit of account, and re-pricing after each one spends it
    /// where it buys the most; against a clock each step loads the pair, its frame and its list,
    /// prices it again and puts it back, on one thread, while whole pairs run as the exact
    /// pass's descents do, on every thread. An untested pair's first price is already its
    /// whole descent's (expected gap removed over expected tests to settle it, see
    /// [`Bin::cost`]), so the order is the same.
    fn run_whole(&mut self, np: &mut NarrowPhase, work: &Work<'_>, meter: &mut Meter<'_>) {
        self.order.clear();
        self.order
            .extend(self.initial.order.iter().map(|&(pair, _)| pair));
        np.resolve_ordered(
            work.tree,
            work.world,
            &self.order,
            work.threads,
            &mut |tests| !meter.exhausted_between_pairs(tests),
        );
    }

    /// Price every (untested) pair into the initial stream. The weight at a pair is the mean of
    /// its two bodies' (a few degrees apart at most), and the squared centre distance keys the
    /// calibrated state: one pass writing sequential arrays and a histogram, without a per-pair
    /// projection, division, square root or queue push.
    ///
    /// With `open_only` (wall-clock frames, whose root-separated pairs are settled before the
    /// ordering, about 60% of them at the paper's N: see `Collider`), the open pairs are listed
    /// first and only they are priced.
    fn price<const REMEMBER: bool>(&mut self, np: &NarrowPhase, work: &Work<'_>, open_only: bool) {
        let gaze = self.options.gaze && work.view.is_some();
        let full = work.priorities.body_records().len() == work.world.len();
        // The switches are fixed for the frame: as constants, the pass has no branch on them
        // per pair. Under a wall-clock budget this pass is paid from the tests' time, so every
        // nanosecond a pair counts (see "The priced ordering made cheaper" in BENCHMARKS.md).
        match (gaze, full, open_only && !REMEMBER) {
            (true, true, false) => self.price_with::<REMEMBER, true, true, false>(np, work),
            (false, true, false) => self.price_with::<REMEMBER, false, true, false>(np, work),
            (_, false, false) => self.price_with::<REMEMBER, false, false, false>(np, work),
            (true, true, true) => self.price_with::<REMEMBER, true, true, true>(np, work),
            (false, true, true) => self.price_with::<REMEMBER, false, true, true>(np, work),
            (_, false, true) => self.price_with::<REMEMBER, false, false, true>(np, work),
        }
    }

    fn price_with<const REMEMBER: bool, const GAZE: bool, const FULL: bool, const OPEN: bool>(
        &mut self,
        np: &NarrowPhase,
        work: &Work<'_>,
    ) {
        let pr = work.priorities;
        let cal = work.calibration;
        let inv_d2 = (0.25 / (work.tree.root_radius() * work.tree.root_radius())) as f32;
        let records = pr.body_records();
        // Every pair is untested: its value per unit weight depends only on its distance bucket,
        // whether it has a witness from last frame, and what it cost last frame if remembered.
        // Indexed by witness * DIST_BUCKETS + bucket, so that the witness selects by arithmetic
        // rather than by a branch (a tenth to a fifth of the pairs have one, in no order).
        let mut first = [0f32; 2 * calibration::DIST_BUCKETS];
        for (j, r) in first.iter_mut().enumerate() {
            let (w, d) = (j / calibration::DIST_BUCKETS, j % calibration::DIST_BUCKETS);
            *r = self.ratio[cal.initial_index(w == 1, 0, d as u8)];
        }
        let ratio = &self.ratio;
        let memory = &self.memory;
        let remembered_out = &mut self.remembered;
        let table = &self.buckets;
        let init = &mut self.initial;
        // The open pairs' indices, written without a branch per pair (which of them are open is
        // as good as random).
        let m = if OPEN {
            let open = &mut self.open;
            open.resize(np.pairs.len(), 0);
            let mut len = 0;
            for (i, p) in np.pairs.iter().enumerate() {
                open[len] = i as u32;
                len += usize::from(p.status.is_open());
            }
            open.truncate(len);
            len
        } else {
            np.pairs.len()
        };
        init.clear(m);
        let counts = &mut init.counts[..BUCKETS];
        let (mut lo, mut hi) = (BUCKETS, 0);
        let (weight, dist, open) = (&mut self.weight, &mut self.dist, &self.open);
        for (j, k_out) in init.keys.iter_mut().enumerate() {
            let i = if OPEN { open[j] as usize } else { j };
            let p = &np.pairs[i];
            let (a, b) = (p.a as usize, p.b as usize);
            let (w, d2) = if FULL {
                let (ra, rb) = (records[a], records[b]);
                let w = if GAZE {
                    0.5 * (ra[3] + rb[3])
                } else {
                    0.5 * (pr.body_scale(a) + pr.body_scale(b))
                };
                let d = [rb[0] - ra[0], rb[1] - ra[1], rb[2] - ra[2]];
                (w, (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) * inv_d2)
            } else {
                // No body pass (a deadline cut it short): distances from the world, no weight.
                let d = work.world.position[b] - work.world.position[a];
                (1.0, d.length_squared() as f32 * inv_d2)
            };
            let bucket = table.bucket(d2);
            weight[i] = w;
            dist[i] = bucket;
            let witness = np.has_witness(i);
            let remembered = if REMEMBER {
                let t = memory.get(p.a, p.b);
                remembered_out[i] = t;
                t
            } else {
                0
            };
            let r = if remembered > 0 && !witness {
                ratio[cal.initial_index(false, remembered, bucket)]
            } else {
                first[usize::from(witness) * calibration::DIST_BUCKETS
                    + bucket as usize % calibration::DIST_BUCKETS]
            };
            *k_out = BucketQueue::key(w * r) as u16;
        }
        // Counted in a pass of their own, four counters a bucket: the pricing's chain of
        // dependent loads no longer ends in a read-modify-write that the next pair's may wait
        // for, and runs of equal keys (the zero weights far from the fixation) do not chain
        // through one counter.
        let mut quad = [[0u32; 4]; BUCKETS];
        let mut chunks = init.keys.chunks_exact(4);
        for c in &mut chunks {
            for (lane, &k) in c.iter().enumerate() {
                quad[k as usize][lane] += 1;
            }
        }
        for &k in chunks.remainder() {
            quad[k as usize][0] += 1;
        }
        for (k, (q, c)) in quad.iter().zip(counts.iter_mut()).enumerate() {
            *c = q[0] + q[1] + q[2] + q[3];
            if *c > 0 {
                lo = lo.min(k);
                hi = hi.max(k);
            }
        }
        init.span = (lo, hi);
        init.sort(if OPEN { Some(&self.open[..]) } else { None });
    }
}

impl Scheduler for Priced {
    /// The priced order puts the root-separated pairs first anyway (each the most
    /// false-positive error removed for one test), so a wall-clock frame settles them in the
    /// cheaper pass. But it alone leaves the foveal pairs likely to collide for last (deeming a
    /// true collision removes no false-positive error), and what the viewer looks at is then not
    /// exact: a wall-clock frame settles the fovea first, through the rings or over every
    /// candidate. At 10,000 bodies and a 4 ms frame budget this took the frames with every
    /// foveal pair settled from 1-2% to 100% (docs/BENCHMARKS.md). It needs distances and
    /// scales even without a fixation, prices pairs itself from per-body values, and its
    /// ordering buys more per microsecond than the paper's (see
    /// [`crate::budget::gate::PRICED_ORDERING_SHARE`]).
    fn passes(&self) -> Passes {
        Passes {
            roots_first: true,
            rings_fovea: true,
            fovea_first: true,
            gaze: self.options.gaze,
            prioritise: Prioritise::Always,
            needs: Needs {
                bodies_only: true,
                ..Needs::default()
            },
            ordering_share: crate::budget::gate::PRICED_ORDERING_SHARE,
            calibrated: true,
        }
    }

    fn ordering_ns(&self) -> u64 {
        self.ordering_ns
    }

    fn warm(&self) {
        crate::warm::lines(&self.weight);
        crate::warm::lines(&self.dist);
        crate::warm::lines(&self.ratio);
        crate::warm::lines(&self.initial.keys);
        crate::warm::lines(&self.initial.counts);
        crate::warm::lines(&self.initial.order);
        for b in &self.queue.buckets {
            crate::warm::lines(b);
        }
    }

    fn run(&mut self, np: &mut NarrowPhase, work: &Work<'_>, meter: &mut Meter<'_>) {
        // The memory and the horizons' rates are used where sphere tests are the budget. Under
        // a wall-clock budget they cost more tests than the better order saves: at 10,000
        // bodies and a third of the exact narrow phase, pricing took 393 against 340 us a frame
        // and the tests that followed ran 18% slower (a different mix of steps), for 23% fewer
        // tests and a worse true P (docs/BENCHMARKS.md); so those frames price by the mean cost
        // without a memory, the formula before it (on the regenerated table).
        // The ablations (a part of the price switched off) run without it too: the memory's bins
        // price by cost and probability, which they are meant to leave out.
        if meter.counts_time() || !(self.options.probability && self.options.cost) {
            self.memory.forget();
            self.run_with::<false>(np, work, meter);
        } else {
            self.run_with::<true>(np, work, meter);
        }
    }

    fn forget(&mut self) {
        self.memory.forget();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bucket_queue_pops_larger_values_first_and_drains() {
        let mut q = BucketQueue::default();
        let values = [0.5f32, 3.0, 1e-20, 0.0, f32::NAN, 7e10, 2.9, 1.0];
        for (i, &v) in values.iter().enumerate() {
            q.push(v, i as u32);
        }
        let order: Vec<u32> = std::iter::from_fn(|| q.pop()).collect();
        assert_eq!(order.len(), values.len());
        assert_eq!(order[0], 5);
        // 3.0 and 2.9 share a quarter octave; both come before 1.0, 0.5 and the tiny ones.
        assert!(order[1..3].contains(&1) && order[1..3].contains(&6));
        assert_eq!(&order[3..5], &[7, 0]);
        q.push(1.0, 9);
        q.clear();
        assert_eq!(q.pop(), None);
    }

    #[test]
    fn a_key_is_the_top_bits_of_a_positive_value_and_zero_otherwise() {
        // The plain definition the branch-free one must match, bucket for bucket.
        let plain = |v: f32| {
            if v > 0.0 {
                ((v.to_bits() >> 21) as usize).min(BUCKETS - 1)
            } else {
                0
            }
        };
        let edges = [
            0.0f32,
            -0.0,
            f32::from_bits(1),
            f32::MIN_POSITIVE,
            1e-30,
            0.25,
            1.0,
            3.0,
            1e30,
            f32::MAX,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
            -f32::NAN,
            -1.0,
            -f32::MAX,
            f32::from_bits(0x7fc0_0001),
            f32::from_bits(0xffff_ffff),
        ];
        for v in edges {
            assert_eq!(BucketQueue::key(v), plain(v), "{v:e} ({:#x})", v.to_bits());
            assert!(BucketQueue::key(v) < BUCKETS);
        }
        // And over the bit patterns at a coarse stride, every sign and exponent.
        for bits in (0..=u32::MAX).step_by(65_537) {
            let v = f32::from_bits(bits);
            assert_eq!(BucketQueue::key(v), plain(v), "{bits:#x}");
        }
    }

    #[test]
    fn the_sorted_first_prices_pop_like_the_queue() {
        // Values spread over many buckets, with ties, fed in index order to both.
        let values: Vec<f32> = (0..500u32)
            .map(|i| ((i * 7919) % 97) as f32 * 0.37 + if i % 5 == 0 { 0.0 } else { 1e-3 })
            .collect();
        let mut q = BucketQueue::default();
        let mut init = Initial::default();
        init.clear(values.len());
        for (i, &v) in values.iter().enumerate() {
            q.push(v, i as u32);
            let k = BucketQueue::key(v);
            init.keys[i] = k as u16;
            init.counts[k] += 1;
            init.span = (init.span.0.min(k), init.span.1.max(k));
        }
        init.sort(None);
        // A second sort over the same pairs finds every count back at zero.
        assert!(init.counts.iter().all(|&c| c == 0));
        let from_queue: Vec<u32> = std::iter::from_fn(|| q.pop()).collect();
        let from_sort: Vec<u32> = init.order.iter().map(|&(i, _)| i).collect();
        assert_eq!(from_sort, from_queue);
        // The open pairs only (every third settled), keyed by position in their list: the
        // queue's order without the settled ones.
        let open: Vec<u32> = (0..values.len() as u32).filter(|i| i % 3 != 0).collect();
        init.clear(open.len());
        for (j, &i) in open.iter().enumerate() {
            let k = BucketQueue::key(values[i as usize]);
            init.keys[j] = k as u16;
            init.counts[k] += 1;
            init.span = (init.span.0.min(k), init.span.1.max(k));
        }
        init.sort(Some(&open));
        let from_open: Vec<u32> = init.order.iter().map(|&(i, _)| i).collect();
        let expected: Vec<u32> = from_queue.iter().copied().filter(|i| i % 3 != 0).collect();
        assert_eq!(from_open, expected);
        assert_eq!(
            init.top_key(),
            BucketQueue::key(values[expected[0] as usize])
        );
        init.next = init.order.len();
        assert_eq!(init.top_key(), 0);
    }

    /// A scene's first frame after a few exact ones: tree, world and candidates.
    /// A frame of the paper scene under the leaf truth: there a pair's cost is a function of
    /// its pose and witness alone (under the shape truth a near miss's proof from the run
    /// before makes a repeated frame cheaper, which is the point of it).
    fn frame() -> crate::Simulation {
        let mut cfg = crate::SimConfig::default();
        cfg.scene.truth = crate::Truth::LeafSpheres;
        cfg.scene.bodies = 500;
        cfg.scene.seed = 7;
        cfg.budget = crate::BudgetSpec::Exact;
        let mut sim = crate::Simulation::new(cfg).expect("valid");
        for _ in 0..20 {
            sim.step(None, &crate::FrozenClock);
        }
        sim
    }

    /// One priced run over `sim`'s candidates under `budget`, its open pairs then deemed.
    fn run_once(
        priced: &mut Priced,
        np: &mut NarrowPhase,
        sim: &crate::Simulation,
        budget: crate::FrameBudget,
    ) {
        let input = sim.frame_input();
        let cal = calibration::Calibration::shipped().expect("shipped table");
        let priorities = super::super::Priorities::default();
        let work = Work {
            tree: input.tree,
            world: input.world,
            view: None,
            priorities: &priorities,
            calibration: &cal,
            threads: 1,
        };
        np.reset(input.candidates);
        let clock = crate::FrozenClock;
        let mut meter = Meter::new(budget, &clock);
        priced.run(np, &work, &mut meter);
        np.deem_open();
        np.remember_witnesses(input.world.len());
    }

    #[test]
    fn memory_keeps_two_settled_pairs_a_body_and_only_the_last_run_s() {
        let mut m = Memory::default();
        // Body 0's third pair is not kept; body 70's (beyond the first word of bits) is.
        m.keep(
            &[(0, 1, 9), (0, 2, 4), (0, 3, 30), (70, 71, 5), (99, 100, 8)],
            80,
        );
        let got: Vec<u32> = [(0, 1), (0, 2), (0, 3), (70, 71), (1, 0), (2, 3), (99, 100)]
            .iter()
            .map(|&(a, b)| m.get(a, b))
            .collect();
        assert_eq!(
            got,
            [9, 4, 0, 5, 0, 0, 0],
            "a body beyond the memory is not kept"
        );
        // The next run replaces it whole: a body's old slots do not survive it.
        m.keep(&[(0, 2, 6)], 80);
        assert_eq!((m.get(0, 1), m.get(0, 2), m.get(70, 71)), (0, 6, 0));
        m.forget();
        assert_eq!((m.bodies(), m.get(0, 2)), (0, 0));
    }

    #[test]
    fn a_repeated_frame_finds_each_remembered_pair_at_its_remembered_cost() {
        let sim = frame();
        let mut np = NarrowPhase::default();
        let mut priced = Priced::new(PricedOptions::default());
        // A tenth of the frame's exact cost: the root tests and some of the deeper pairs.
        let exact = sim.last_report().sphere_tests;
        run_once(
            &mut priced,
            &mut np,
            &sim,
            crate::FrameBudget::Tests(exact / 10),
        );
        let first: Vec<u32> = np
            .pairs
            .iter()
            .map(|p| priced.memory.get(p.a, p.b))
            .collect();
        let kept = first.iter().filter(|&&t| t > 0).count();
        assert!(kept > 5, "{kept} pairs remembered");
        // The same frame again: every remembered pair is looked up, and one settled again costs
        // exactly what it cost (the same poses and the same witnesses).
        run_once(
            &mut priced,
            &mut np,
            &sim,
            crate::FrameBudget::Tests(exact / 10),
        );
        assert_eq!(priced.remembered, first);
        let mut again = 0;
        for (i, p) in np.pairs.iter().enumerate() {
            if first[i] > 0 && p.status == crate::narrow_phase::PairStatus::Separate {
                assert_eq!(priced.spent[i], first[i], "pair {i}");
                again += 1;
            }
        }
        assert!(again * 2 > kept, "{again} of {kept} settled again");
        // A frame the scheduler did not order breaks the chain.
        priced.forget();
        run_once(
            &mut priced,
            &mut np,
            &sim,
            crate::FrameBudget::Tests(exact / 10),
        );
        assert!(priced.remembered.iter().all(|&t| t == 0));
    }

    #[test]
    fn wall_clock_runs_keep_no_memory() {
        let sim = frame();
        let mut np = NarrowPhase::default();
        let mut priced = Priced::new(PricedOptions::default());
        let exact = sim.last_report().sphere_tests;
        run_once(
            &mut priced,
            &mut np,
            &sim,
            crate::FrameBudget::Tests(exact / 10),
        );
        assert!(priced.memory.bodies() > 0);
        // A wall-clock frame (a frozen clock: the deadline is never reached) drops it and keeps
        // nothing for the next.
        run_once(
            &mut priced,
            &mut np,
            &sim,
            crate::FrameBudget::Wall(1_000_000),
        );
        assert_eq!(priced.memory.bodies(), 0);
        assert!(
            np.pairs.iter().all(|p| !p.status.is_open()),
            "an unmet deadline settles all"
        );
    }

    #[test]
    fn labels_name_the_ablation() {
        assert_eq!(PricedOptions::default().label(), "priced");
        let o = PricedOptions {
            gaze: false,
            ..PricedOptions::default()
        };
        assert_eq!(o.label(), "priced-no-gaze");
    }
}
