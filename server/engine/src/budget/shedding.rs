//! What a whole-frame wall-clock budget sheds, and in which order.
//!
//! Under a wall-clock budget the deadline covers the whole frame: integration, broad phase,
//! prioritisation, narrow phase, response and metrics. At the paper's N the narrow phase is what
//! gets interrupted (section 2), early enough for the learnt tail, and Δ and P are sampled when
//! summing every deemed pair would not fit; at 100,000 bodies and more the per-body and per-pair
//! work around it costs more than the frame, so it too is shed, in perceptual order (section 3:
//! what the viewer does not look at may be wrong first):
//!
//! - **Integration** always runs: every body moves every frame.
//! - **Broad phase.** Every body is sorted into the grid, then the grid's regions (blocks of
//!   cells, see [`crate::broad_phase::Region`]) are searched for pairs in the order
//!   below, for as long as what is left of the frame still pays for the pairs found: a reserve
//!   for the narrow phase ([`NARROW_RESERVE`] of the budget) and each pair's share of the
//!   narrow-phase bookkeeping, response and metrics, learnt from earlier frames. Regions not
//!   reached are *stale*: they keep the pairs of the last frame that searched them, their pairs
//!   are not collided or responded to this frame (those bodies pass through each other until
//!   their region is searched again), and the report counts them.
//! - **Narrow phase**: its meter stops early enough to leave the learnt tail.
//! - **Metrics**: counts over every pair searched; the fovea test only over the regions that can
//!   hold a foveal pair; Δ and P over a sample sized to [`METRICS_SHARE`] of the budget, with its
//!   standard error (see [`crate::metrics::Effort`]).
//!
//! The order of the regions:
//! 1. regions that may hold a pair whose centre is within [`FOVEAL_DEG`] of the fixation (plus
//!    its uncertainty), nearest first: these are searched every frame the budget allows;
//! 2. then the others by (frames since last searched + 1) / (1 + eccentricity / [`FOVEAL_DEG`]):
//!    a region at eccentricity e goes about 1 + e / 5 degrees times as many frames unsearched as
//!    one at the edge of the fovea, and none stays stale for ever.
//!
//! Without a fixation every region is in the second group at eccentricity 0: oldest first.

use crate::broad_phase::Region;
use crate::fixation::Fixation;
use crate::math::Vec3;
use crate::perception::Viewer;
use crate::report::FOVEAL_DEG;

/// Share of the budget kept for prioritisation and sphere tests when the broad phase decides
/// how many regions to search: searching a region whose pairs then cannot be tested only deems
/// them all.
pub const NARROW_RESERVE: f64 = 0.3;

/// Share of the budget the sampled Δ and P sums may take.
pub const METRICS_SHARE: f64 = 0.015;

/// Cost of one sampled pair's Δ and P (its evidence, three projections and two visual angles), ns:
/// converts [`METRICS_SHARE`] into a sample size until a frame has measured it (see
/// [`Shedder::learn_sample`]).
pub const SAMPLE_NS: f64 = 150.0;

/// The narrow phase's reserve covers this multiple of the foveal pass's expected time, so that
/// a frame with a few more foveal pairs than the last still settles them all. 1.25 left 0.98-0.99
/// of the frames with every foveal pair settled at 100,000 bodies with 16 ms on two threads (the
/// issue asks 0.99), the misses frames whose pass ran slow; 1.5 gave 0.992-0.997 over four runs
/// each, alternated, for about 5% fewer candidate pairs searched in the periphery.
const FOVEAL_HEADROOM: f64 = 1.5;

/// Most of the budget the foveal pass's reserve may claim: the rest of the scene is searched with
/// what is left.
const FOVEAL_MAX_SHARE: f64 = 0.6;

/// Weight of a cheaper frame's foveal cost per pair in the learnt one (see
/// [`Shedder::learn_foveal`]).
const FOVEAL_FALL: f64 = 0.05;

/// Most the learnt tail per pair may grow in one frame (see [`Shedder::learn`]).
const TAIL_RISE: f64 = 1.5;

/// Weight of a cheaper frame's tail per pair in the learnt one (see [`Shedder::learn`]).
const TAIL_FALL: f64 = 0.02;

/// Frames whose measured tail bounds the learnt one from above (see [`Shedder::learn`]).
const TAIL_WINDOW: usize = 32;

/// Most of the budget the learnt tail may keep from the narrow phase (see [`Shedder::learn`]).
const TAIL_MAX_SHARE: f64 = 0.5;

/// Smallest sample of deemed pairs whatever the budget: its standard error is reported. Small
/// enough for the paper's N and budget (0.1 ms, of which 32 pairs' Δ and P take about 5 us).
pub const MIN_SAMPLE: u32 = 32;

/// Margin, degrees, added to the fovea when deciding which regions may hold a foveal pair: the
/// regions' bounds are taken on the screen's pixel grid, not in visual angle.
const FOVEA_MARGIN_DEG: f64 = 1.0;

/// Per-frame state of the shedding: each region's age and the learnt costs.
#[derive(Debug, Clone, Default)]
pub struct Shedder {
    /// Frames since each region was last searched.
    age: Vec<u32>,
    keys: Vec<(u8, f64, u32)>,
    order: Vec<u32>,
    /// Each region's screen rectangle (pixels: min x, min y, max x, max y), grown by half the
    /// reach. A simulation's camera and regions never change, so this is computed once.
    rects: Vec<[f64; 4]>,
    /// Regions of the first group (may hold foveal pairs) this frame.
    foveal_regions: usize,
    /// ns per searched pair from the end of the narrow phase's meter to the end of the frame
    /// (deeming, witnesses, response, metrics); None until a frame has measured it.
    tail_ns_per_pair: Option<f64>,
    /// The last [`TAIL_WINDOW`] frames' measured tail per pair (a ring; 0 where none yet).
    recent_tails: [f64; TAIL_WINDOW],
    recent_next: usize,
    /// ns per foveal pair settled by the foveal pass, and the foveal pairs of the last frame.
    foveal_ns_per_pair: Option<f64>,
    foveal_pairs: f64,
    /// ns per deemed pair whose Δ and P the metrics summed; None until a frame has measured it.
    sample_ns_per_pair: Option<f64>,
}

/// The broad phase's pacing within one frame: whether one more region still fits.
#[derive(Debug)]
pub struct Pacer {
    deadline: u64,
    /// Time kept for the narrow phase while the regions that may hold foveal pairs are searched
    /// (the first `foveal_regions` calls), and after them.
    reserve: [u64; 2],
    foveal_regions: usize,
    calls: usize,
    tail_ns_per_pair: f64,
    /// Most the tail may keep, ns ([`TAIL_MAX_SHARE`] of the budget).
    tail_cap: f64,
    last: Option<(u64, usize)>,
}

impl Pacer {
    /// Whether the next region may be searched, at `now` with `pairs` found so far: it is assumed
    /// to cost what the last one did, in time and in pairs.
    ///
    /// At the first call (the sort is done) the reserve in force for the first regions is cut to
    /// half the time left if it is more: a fixed reserve larger than what the sort left would
    /// have the frame search nothing and end early with the time unused (at 1,000,000 bodies on
    /// one thread integration and the sort take about 35 ms of a 50 ms frame, against a reserve
    /// of 15 ms), where half of it searches the regions nearest the fixation and the other half
    /// settles what they hold.
    pub fn go_on(&mut self, now: u64, pairs: usize) -> bool {
        let k = usize::from(self.calls >= self.foveal_regions);
        let (dt, dp) = match self.last {
            Some((t, p)) => (now.saturating_sub(t), pairs.saturating_sub(p)),
            None => {
                self.reserve[k] = self.reserve[k].min(self.deadline.saturating_sub(now) / 2);
                (0, 0)
            }
        };
        self.last = Some((now, pairs));
        let reserve = self.reserve[k];
        self.calls += 1;
        let tail = (self.tail_ns_per_pair * (pairs + dp) as f64).min(self.tail_cap);
        (now + dt + reserve) as f64 + tail <= self.deadline as f64
    }
}

impl Shedder {
    /// The regions of `regions` in the order a frame searches them, given where the viewer looks.
    pub fn order(
        &mut self,
        regions: &[Region],
        viewer: &Viewer,
        fixation: Option<Fixation>,
        reach: f64,
    ) -> &[u32] {
        if self.age.len() != regions.len() {
            self.age = vec![0; regions.len()];
        }
        if self.rects.len() != regions.len() {
            self.rects = regions
                .iter()
                .map(|r| screen_rect(r, viewer, reach))
                .collect();
        }
        let fixation_px = fixation.map(|f| {
            let f = f.clamped();
            (viewer.to_pixels(f.x, f.y), f.uncertainty_deg)
        });
        self.keys.clear();
        self.foveal_regions = 0;
        for r in 0..regions.len() {
            let age = f64::from(self.age[r]);
            let (tier, key) = match fixation_px {
                Some((px, radius)) => {
                    let e = fovea_distance_deg(&self.rects[r], viewer, px, radius);
                    if e <= FOVEAL_DEG + FOVEA_MARGIN_DEG {
                        self.foveal_regions += 1;
                        (0, e)
                    } else {
                        (1, -(age + 1.0) / (1.0 + e / FOVEAL_DEG))
                    }
                }
                None => (1, -age),
            };
            self.keys.push((tier, key, r as u32));
        }
        self.keys
            .sort_unstable_by(|a, b| a.0.cmp(&b.0).then(a.1.total_cmp(&b.1)).then(a.2.cmp(&b.2)));
        self.order.clear();
        self.order.extend(self.keys.iter().map(|k| k.2));
        &self.order
    }

    /// Regions of the last [`Self::order`] that may hold foveal pairs (they come first).
    pub fn foveal_regions(&self) -> usize {
        self.foveal_regions
    }

    /// Regions of the last [`Self::order`] after its first `searched` that may hold a pair in
    /// the fovea of a viewer at `fixation`, by the test [`Self::order`] puts first: for the
    /// fixation the order was made for, [`Self::foveal_regions`] less `searched`; for another,
    /// what a frame scheduled for one fixation left stale where the viewer looked at the other.
    pub fn foveal_unsearched(&self, searched: usize, viewer: &Viewer, fixation: Fixation) -> usize {
        let f = fixation.clamped();
        let (px, radius) = (viewer.to_pixels(f.x, f.y), f.uncertainty_deg);
        self.order
            .iter()
            .skip(searched)
            .filter(|&&r| {
                self.rects.get(r as usize).is_some_and(|rect| {
                    fovea_distance_deg(rect, viewer, px, radius) <= FOVEAL_DEG + FOVEA_MARGIN_DEG
                })
            })
            .count()
    }

    /// The broad phase's pacing for a frame ending at `deadline` with a budget of `budget_ns`.
    pub fn pacer(&self, deadline: u64, budget_ns: u64) -> Pacer {
        // The regions that may hold foveal pairs are searched while the fixed share is left;
        // the others only while enough is left for the foveal pass to settle about as many
        // foveal pairs as the last frames had (at most FOVEAL_MAX_SHARE of the budget).
        let base = NARROW_RESERVE * budget_ns as f64;
        let foveal = (FOVEAL_HEADROOM * self.foveal_ns_per_pair.unwrap_or(0.0) * self.foveal_pairs)
            .min(FOVEAL_MAX_SHARE * budget_ns as f64);
        Pacer {
            deadline,
            reserve: [base as u64, base.max(foveal) as u64],
            foveal_regions: self.foveal_regions,
            calls: 0,
            tail_ns_per_pair: self.tail_ns_per_pair.unwrap_or(0.0),
            tail_cap: TAIL_MAX_SHARE * budget_ns as f64,
            last: None,
        }
    }

    /// When the narrow phase's meter must stop for a frame ending at `deadline`, with a budget of
    /// `budget_ns` and `pairs` searched pairs: early enough for their tail, which keeps at most
    /// [`TAIL_MAX_SHARE`] of the budget.
    pub fn narrow_deadline(&self, deadline: u64, budget_ns: u64, pairs: usize) -> u64 {
        let tail = (self.tail_ns_per_pair.unwrap_or(0.0) * pairs as f64)
            .min(TAIL_MAX_SHARE * budget_ns as f64);
        deadline.saturating_sub(tail as u64)
    }

    /// The metrics' effort for a budget of `budget_ns` whose first `fovea_pairs` pairs are in
    /// regions that may hold foveal pairs: a sample of deemed pairs that costs [`METRICS_SHARE`]
    /// of the budget at the learnt cost per sampled pair.
    pub fn effort(&self, budget_ns: u64, fovea_pairs: usize) -> crate::metrics::Effort {
        let per_pair = self.sample_ns_per_pair.unwrap_or(SAMPLE_NS);
        let sample = (METRICS_SHARE * budget_ns as f64 / per_pair) as u32;
        crate::metrics::Effort {
            sample_limit: sample.clamp(MIN_SAMPLE, crate::metrics::EXACT_LIMIT),
            fovea_pairs,
            ..crate::metrics::Effort::default()
        }
    }

    /// After a frame: which regions were searched (the first `searched` of the last order), and
    /// the tail measured, `tail_ns` over `pairs` searched pairs. A tail measured after a meter that
    /// ran out is the whole tail; one measured after a narrow phase that finished early misses
    /// the deeming, so the estimate is quick to rise and slow to fall; but one frame can raise it
    /// by at most [`TAIL_RISE`]: on a shared machine a single frame's tail can be ten times the
    /// usual (a page-fault storm, a preempted thread), and taken whole it made the broad phase
    /// shed every region, the foveal ones included, for the twenty frames it took to decay.
    ///
    /// It falls by [`TAIL_FALL`] of the difference a frame, close to an envelope of the recent
    /// frames rather than their mean: a frame's tail per pair depends on how many of its pairs
    /// end up deemed (the response exchanges their velocities, a cache miss each at a million
    /// bodies), which swings by 2-3x from frame to frame, and an estimate that followed the cheap
    /// frames (it fell by a tenth a frame) overran the budget in the next expensive one by the
    /// difference: 2-4 ms of a 50 ms frame at 1,000,000 bodies, every 5-20 frames. The price:
    /// after a stall the estimate stays high for longer (it loses a fifth of the excess in ten
    /// frames), so a loaded machine sheds more.
    ///
    /// Two bounds keep a stall from starving the narrow phase for seconds. The estimate is never
    /// above the dearest tail of the last [`TAIL_WINDOW`] frames, so a stall is forgotten that
    /// many frames after it ends (expensive frames that come back within the window stay
    /// covered); and the tail keeps at most [`TAIL_MAX_SHARE`] of the budget from the narrow
    /// phase. Without them a frame's first tail, taken whole, set the estimate for the next
    /// hundred frames: on a loaded machine the first tail at 3,000 bodies (a cold frame, 7.6 ms
    /// against the usual 0.2 ms) left no narrow phase in any frame of a 2 ms budget for four
    /// seconds. At 1,000,000 bodies with 50 ms the tail is 3-12 ms, under either bound.
    pub fn learn(&mut self, searched: usize, tail_ns: u64, pairs: usize) {
        self.learn_shed(searched, tail_ns, pairs);
    }

    /// The foveal pass of a frame with `foveal_pairs` foveal pairs settled `settled` of them in
    /// `ns` (see [`crate::collider::Collider::collide_frame`]).
    ///
    /// The count is smoothed (a fifth of the new value each frame): a frame whose foveal regions
    /// were not all searched counts fewer foveal pairs than there are and must not shrink the
    /// reserve that would have searched them, so such a frame only ever raises the count. The
    /// cost per pair is learnt like the tail (see [`Self::learn`]): quick to rise (at most
    /// [`TAIL_RISE`] a frame), slow to fall ([`FOVEAL_FALL`] of the difference), an envelope of
    /// the recent passes rather than their mean. The pass's cost per pair swings from frame to
    /// frame (a slower spell of a shared machine, more foveal pairs in deep contact); a reserve
    /// sized on the mean left every slower pass short, and at 100,000 bodies with 16 ms those
    /// frames deemed hundreds to thousands of the pairs the viewer looks at (docs/BENCHMARKS.md).
    pub fn learn_foveal(&mut self, foveal_pairs: u32, complete: bool, settled: u32, ns: u64) {
        let count = f64::from(foveal_pairs);
        if complete || count > self.foveal_pairs {
            self.foveal_pairs = if self.foveal_pairs == 0.0 {
                count
            } else {
                0.8 * self.foveal_pairs + 0.2 * count
            };
        }
        // A clock that did not advance says nothing about the cost (and a learnt 0 could never
        // rise again).
        if settled > 0 && ns > 0 {
            let cost = ns as f64 / f64::from(settled);
            self.foveal_ns_per_pair = Some(envelope(self.foveal_ns_per_pair, cost, FOVEAL_FALL));
        }
    }

    /// The metrics summed Δ and P over `pairs` deemed pairs in `ns`. Why learnt: what a sampled
    /// pair costs (its evidence, three projections, two visual angles) depends on the machine
    /// and on the scene's memory footprint (190-220 ns at 10,000 bodies here, against the 150
    /// ns assumed before), and the sample sized on a fixed guess overspent its share of the
    /// budget by a third. Smoothed like the foveal pairs' count (a fifth of each frame) from the
    /// assumed [`SAMPLE_NS`], rising at most [`TAIL_RISE`] a frame, so that one stalled sum (or
    /// the first, on cold caches) does not shrink the next frames' samples to the minimum.
    ///
    /// The time is the whole sum's, so it includes the sum's fixed part (reading the status of
    /// every pair at the stride; with several threads and more than one run of pairs, starting
    /// a thread, tens of microseconds): spread over the pairs, it sizes the sample so that the
    /// whole sum keeps to its share, and where that fixed part alone nears the share (a large
    /// scene on several threads with a budget of a few milliseconds) the sample falls towards
    /// [`MIN_SAMPLE`].
    pub fn learn_sample(&mut self, pairs: u32, ns: u64) {
        // A handful of pairs times mostly the pass's fixed cost, and a clock that did not
        // advance says nothing.
        if pairs < MIN_SAMPLE || ns == 0 {
            return;
        }
        let cost = ns as f64 / f64::from(pairs);
        let old = self.sample_ns_per_pair.unwrap_or(SAMPLE_NS);
        self.sample_ns_per_pair = Some((0.8 * old + 0.2 * cost).min(TAIL_RISE * old));
    }

    fn learn_shed(&mut self, searched: usize, tail_ns: u64, pairs: usize) {
        for a in &mut self.age {
            *a = a.saturating_add(1);
        }
        for &r in &self.order[..searched.min(self.order.len())] {
            self.age[r as usize] = 0;
        }
        if pairs > 0 {
            let cost = tail_ns as f64 / pairs as f64;
            self.recent_tails[self.recent_next] = cost;
            self.recent_next = (self.recent_next + 1) % TAIL_WINDOW;
            let dearest = self.recent_tails.iter().copied().fold(0.0, f64::max);
            let learnt = envelope(self.tail_ns_per_pair, cost, TAIL_FALL).min(dearest);
            self.tail_ns_per_pair = Some(learnt);
        }
    }
}

/// A cost learnt as an envelope of the recent frames' (the tail's and the foveal pass's): a dearer
/// frame raises it at once, by at most [`TAIL_RISE`] (one stalled frame is not taken whole), and a
/// cheaper one lowers it by `fall` of the difference; the first measurement is taken as it is.
fn envelope(old: Option<f64>, cost: f64, fall: f64) -> f64 {
    match old {
        Some(old) if cost > old => cost.min(TAIL_RISE * old),
        Some(old) => (1.0 - fall) * old + fall * cost,
        None => cost,
    }
}

/// How far (degrees) a region's screen rectangle lies beyond a fixation at `fixation_px` whose
/// uncertainty is `radius_deg`: 0 when it reaches the fixation's uncertain disc. A region within
/// [`FOVEAL_DEG`] plus [`FOVEA_MARGIN_DEG`] of it may hold foveal pairs.
fn fovea_distance_deg(
    rect: &[f64; 4],
    viewer: &Viewer,
    fixation_px: [f64; 2],
    radius_deg: f64,
) -> f64 {
    (nearest_angle_deg(rect, viewer, fixation_px) - radius_deg).max(0.0)
}

/// The least visual angle (degrees) from `fixation_px` to a screen rectangle of
/// [`screen_rect`].
fn nearest_angle_deg(rect: &[f64; 4], viewer: &Viewer, fixation_px: [f64; 2]) -> f64 {
    let nearest = [
        fixation_px[0].clamp(rect[0], rect[2].max(rect[0])),
        fixation_px[1].clamp(rect[1], rect[3].max(rect[1])),
    ];
    viewer.display.visual_angle_deg(fixation_px, nearest)
}

/// The screen rectangle (pixels) bounding the image of `region` grown by half the box reach on
/// every side (a pair's centre is within half the reach of the body that finds it): the eight
/// corners are projected and their bounding rectangle taken. A projection is a central one, so
/// the image of the box lies within that rectangle.
fn screen_rect(region: &Region, viewer: &Viewer, reach: f64) -> [f64; 4] {
    let grow = Vec3::splat(0.5 * reach);
    let (lo, hi) = (region.lo - grow, region.hi + grow);
    let mut rect = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for k in 0..8 {
        let c = Vec3::new(
            if k & 1 == 0 { lo.x } else { hi.x },
            if k & 2 == 0 { lo.y } else { hi.y },
            if k & 4 == 0 { lo.z } else { hi.z },
        );
        let [x, y] = viewer.project(c);
        rect = [
            rect[0].min(x),
            rect[1].min(y),
            rect[2].max(x),
            rect[3].max(y),
        ];
    }
    rect
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::broad_phase::{BroadPhase, BroadPhaseKind};
    use crate::budget::Ticking;
    use crate::config::{BudgetSpec, SceneConfig, SchedulerKind, SimConfig};
    use crate::metrics::Fovea;
    use crate::simulation::Simulation;
    use crate::world::World;

    /// Cheap frames between expensive ones do not wear the estimate down to the cheap frames'
    /// tail: once it has risen to the expensive frames' (at most TAIL_RISE a frame, so after two
    /// of them), it still covers nine tenths of theirs before each (a fall of a tenth a frame
    /// left three quarters).
    #[test]
    fn the_learnt_tail_covers_the_expensive_frames_among_cheap_ones() {
        let mut s = Shedder::default();
        let deadline = 16_000_000;
        let (pairs, cheap, dear) = (1_000, 1_000_000, 2_000_000);
        for frame in 0..80 {
            if frame % 8 == 7 {
                let covered = deadline - s.narrow_deadline(deadline, deadline, pairs);
                if frame > 16 {
                    assert!(
                        10 * covered >= 9 * dear,
                        "frame {frame}: {covered} ns of {dear}"
                    );
                }
                s.learn(0, dear, pairs);
            } else {
                s.learn(0, cheap, pairs);
            }
        }
    }

    /// The foveal pass's reserve covers the frames whose pass is slower than most (a slower
    /// spell of the machine, more foveal pairs deep in contact), not only their mean: with the
    /// mean (a fifth of each frame) it fell short of every such frame by a fifth.
    #[test]
    fn the_foveal_reserve_covers_the_slower_passes_among_quick_ones() {
        let mut s = Shedder::default();
        let (budget, deadline) = (16_000_000, 100_000_000);
        let pairs = 40_000u32;
        let (quick, slow) = (100 * u64::from(pairs), 180 * u64::from(pairs));
        for frame in 0..90 {
            let dear = frame % 6 == 5;
            if dear && frame > 20 {
                let reserve = s.pacer(deadline, budget).reserve[1];
                assert!(
                    reserve >= slow,
                    "frame {frame}: {reserve} ns for a {slow} ns pass"
                );
            }
            s.learn_foveal(pairs, true, pairs, if dear { slow } else { quick });
        }
    }

    /// The metrics' sample is sized by what a sampled pair was measured to cost: its cost stays
    /// near the metrics' share of the budget whatever the machine, and one stalled sum raises
    /// the estimate by at most half.
    #[test]
    fn the_sample_is_sized_by_its_measured_cost() {
        let budget = 4_000_000;
        let mut s = Shedder::default();
        let guessed = s.effort(budget, 0).sample_limit;
        assert_eq!(guessed, (METRICS_SHARE * budget as f64 / SAMPLE_NS) as u32);
        for _ in 0..40 {
            let n = s.effort(budget, 0).sample_limit;
            s.learn_sample(n, u64::from(n) * 300);
        }
        let n = s.effort(budget, 0).sample_limit;
        let spent = f64::from(n) * 300.0 / budget as f64;
        assert!(
            (spent - METRICS_SHARE).abs() < 0.001,
            "{n} pairs, {spent} of the budget"
        );
        assert!(n < guessed, "{n} against {guessed}");
        s.learn_sample(n, 10_000_000);
        let after = s.effort(budget, 0).sample_limit;
        assert!(3 * after >= 2 * n - 3, "{after} after a stall, {n} before");
        // Too few pairs to time the pass by, or a clock that did not advance: ignored.
        s.learn_sample(MIN_SAMPLE - 1, 10_000_000);
        s.learn_sample(n, 0);
        assert_eq!(s.effort(budget, 0).sample_limit, after);
    }

    /// When the sort leaves less than twice the reserve, the first regions are still searched
    /// with half of what is left; with time enough the reserve is kept whole.
    #[test]
    fn a_late_sort_still_searches_the_first_regions() {
        let s = Shedder::default();
        let (budget, deadline) = (50_000_000, 100_000_000);
        let reserve = (NARROW_RESERVE * budget as f64) as u64;
        let mut late = s.pacer(deadline, budget);
        assert!(late.go_on(deadline - reserve + 1_000_000, 0), "searched");
        assert!(
            !late.go_on(deadline - reserve / 4, 0),
            "and no further than half"
        );
        let mut early = s.pacer(deadline, budget);
        assert!(early.go_on(deadline - 40_000_000, 0));
        assert!(
            !early.go_on(deadline - 25_000_000, 0),
            "the whole reserve is kept when the sort left enough"
        );
    }

    /// One slow frame raises the learnt tail by at most TAIL_RISE; a run of them raises it to
    /// what they cost, up to half the budget; fast frames lower it slowly, and a window of them
    /// forgets the stall.
    #[test]
    fn one_slow_frame_does_not_take_the_next_frames_budget() {
        let mut s = Shedder::default();
        let (deadline, budget) = (16_000_000, 16_000_000);
        s.learn(0, 1_000_000, 1_000); // 1 us a pair
        assert_eq!(
            s.narrow_deadline(deadline, budget, 1_000),
            deadline - 1_000_000
        );
        s.learn(0, 20_000_000, 1_000); // a 20 ms stall
        assert_eq!(
            s.narrow_deadline(deadline, budget, 1_000),
            deadline - 1_500_000
        );
        for _ in 0..10 {
            s.learn(0, 20_000_000, 1_000);
        }
        assert_eq!(
            s.narrow_deadline(deadline, budget, 1_000),
            deadline - budget / 2,
            "a slow machine is learnt, and keeps half the budget from the narrow phase at most"
        );
        for frame in 1..TAIL_WINDOW {
            s.learn(0, 1_000_000, 1_000);
            let after = s.narrow_deadline(deadline, budget, 1_000);
            assert_eq!(
                after,
                deadline - budget / 2,
                "forgotten slowly: frame {frame}"
            );
        }
        s.learn(0, 1_000_000, 1_000);
        assert_eq!(
            s.narrow_deadline(deadline, budget, 1_000),
            deadline - 1_000_000,
            "and whole once the window holds no stall"
        );
    }

    /// A frame's first tail is taken whole, and a cold first frame can cost thirty times the
    /// usual: the narrow phase still gets half the budget, and the window's fast frames bring the
    /// estimate back. The broad phase's pacer keeps no more for the tail than the narrow phase.
    #[test]
    fn a_cold_first_frame_does_not_starve_the_next_ones() {
        let mut s = Shedder::default();
        let (budget, pairs) = (2_000_000, 3_000);
        let deadline = 10 * budget;
        s.learn(0, 7_600_000, pairs);
        assert_eq!(
            s.narrow_deadline(deadline, budget, pairs),
            deadline - budget / 2
        );
        let mut pacer = s.pacer(deadline, budget);
        let reserve = (NARROW_RESERVE * budget as f64) as u64;
        assert!(pacer.go_on(deadline - budget / 2 - reserve - 1_000, pairs));
        for _ in 0..TAIL_WINDOW {
            s.learn(0, 200_000, pairs);
        }
        assert_eq!(
            s.narrow_deadline(deadline, budget, pairs),
            deadline - 200_000
        );
    }

    /// Regions of the first group hold every pair whose centre is within the fovea, wherever the
    /// viewer looks: searching only those regions lists every foveal pair.
    #[test]
    fn the_first_regions_hold_every_foveal_pair() {
        let scene = SceneConfig::paper(20_000, 3);
        let world = World::generate(&scene);
        let cfg = SimConfig::default();
        let viewer = Viewer::new(&cfg.camera, &cfg.display, world.lo, scene.volume_side());
        let half = 1.11 * scene.shape_radius;
        let mut bp = BroadPhase::with_kind(
            BroadPhaseKind::Grid,
            half,
            world.lo,
            scene.volume_side(),
            world.len(),
        );
        let mut shedder = Shedder::default();
        let mut checked = 0;
        for (x, y) in [(0.5, 0.5), (0.1, 0.2), (0.9, 0.85), (0.3, 0.7), (1.2, -0.1)] {
            let fixation = Fixation::at(x, y);
            let order = shedder
                .order(bp.regions(), &viewer, Some(fixation), 2.0 * half)
                .to_vec();
            let first = shedder.foveal_regions();
            assert!(first < order.len(), "every region foveal at {x}, {y}");
            let mut calls = 0;
            bp.update_in_order(&world.position, &order, &mut |_| {
                calls += 1;
                calls <= first
            });
            let mut listed = bp.pairs().to_vec();
            listed.sort_unstable();
            let fovea = Fovea::new(&viewer, viewer.to_pixels(x, y), FOVEAL_DEG);
            for (a, b) in bp.all_pairs() {
                let c = (world.position[a as usize] + world.position[b as usize]) * 0.5;
                if fovea.contains_point(c) {
                    checked += 1;
                    assert!(
                        listed.binary_search(&(a, b)).is_ok(),
                        "foveal pair ({a}, {b}) outside the first {first} regions at {x}, {y}"
                    );
                }
            }
        }
        assert!(checked > 1_000, "only {checked} foveal pairs checked");
    }

    /// With room for a few regions a frame, the first group is searched every frame and every
    /// other region again within a bounded number of frames: nothing stays stale for ever.
    #[test]
    fn no_region_stays_stale_for_ever() {
        let scene = SceneConfig::paper(20_000, 3);
        let world = World::generate(&scene);
        let cfg = SimConfig::default();
        let viewer = Viewer::new(&cfg.camera, &cfg.display, world.lo, scene.volume_side());
        let bp = BroadPhase::with_kind(
            BroadPhaseKind::Grid,
            0.222,
            world.lo,
            scene.volume_side(),
            world.len(),
        );
        let regions = bp.regions().len();
        let mut shedder = Shedder::default();
        let mut last_searched = vec![0usize; regions];
        let fixation = Some(Fixation::at(0.5, 0.5));
        for frame in 1..=400 {
            let order = shedder
                .order(bp.regions(), &viewer, fixation, 0.444)
                .to_vec();
            let first = shedder.foveal_regions();
            let searched = first + 8;
            for &r in &order[..searched] {
                last_searched[r as usize] = frame;
            }
            shedder.learn(searched, 0, 0);
            if frame > 200 {
                for &r in &order[..first] {
                    assert_eq!(shedder.age[r as usize], 0);
                }
                let oldest = last_searched.iter().map(|&f| frame - f).max().unwrap_or(0);
                assert!(oldest < 200, "a region unsearched for {oldest} frames");
            }
        }
    }

    /// A clock that advances by a fixed step at every reading.
    /// A wall-clock budget too small for the whole frame at a large N: the frame ends within the
    /// budget (on a clock that advances at every reading), sheds regions far from the fixation
    /// and none that may hold a foveal pair, settles foveal pairs first, and the audit
    /// counts the candidate pairs the stale regions cost, none of them foveal.
    #[test]
    fn a_whole_frame_budget_sheds_the_periphery_and_holds_the_deadline() {
        let mut cfg = SimConfig::default();
        cfg.scene = SceneConfig::paper(20_000, 5);
        cfg.scheduler = SchedulerKind::Priced;
        cfg.audit = true;
        let budget_ns = 400_000;
        cfg.budget = BudgetSpec::WallMs(budget_ns as f64 * 1e-6);
        let mut sim = Simulation::new(cfg).expect("valid config");
        // Every clock reading costs 500 ns of this clock: the broad phase reads it once per
        // region (784 here), so per-region time is still the larger part of a region's cost.
        let tick = 500;
        let clock = Ticking(std::sync::atomic::AtomicU64::new(0), tick);
        let fixation = Some(Fixation::at(0.5, 0.5));
        let mut shed_frames = 0;
        for _ in 0..12 {
            let start = clock.0.load(std::sync::atomic::Ordering::Relaxed);
            let r = sim.step(fixation, &clock).clone();
            let spent = clock.0.load(std::sync::atomic::Ordering::Relaxed) - start;
            // One reading past the deadline at most per phase boundary.
            assert!(spent <= budget_ns + 8 * tick, "frame took {spent} ns");
            assert!(r.regions > 16, "{} regions", r.regions);
            if r.stale_regions == 0 {
                continue;
            }
            shed_frames += 1;
            assert_eq!(r.foveal_stale, 0, "a foveal region was shed");
            assert!(r.foveal_pairs > 0);
            let audit = r.audit.expect("audit on");
            // The audit's count, against a broad phase run whole on the same positions; and no
            // pair the shedding missed is foveal.
            let world = sim.world();
            let half = sim.tree().root_radius();
            let mut full = BroadPhase::with_kind(
                BroadPhaseKind::Grid,
                half,
                world.lo,
                sim.config().scene.volume_side(),
                world.len(),
            );
            let all = full.update(&world.position).to_vec();
            let mut listed = sim.candidate_pairs().to_vec();
            listed.sort_unstable();
            let viewer = sim.viewer();
            let fovea = Fovea::new(viewer, viewer.to_pixels(0.5, 0.5), FOVEAL_DEG);
            let mut missed = 0;
            for (a, b) in all {
                if listed.binary_search(&(a, b)).is_err() {
                    missed += 1;
                    let c = (world.position[a as usize] + world.position[b as usize]) * 0.5;
                    assert!(!fovea.contains_point(c), "missed foveal pair ({a}, {b})");
                }
            }
            assert_eq!(audit.missed_pairs, missed);
            assert!(missed > 0);
            // How many foveal pairs the budget settles is a matter of time (the bench measures
            // it); on this clock it is some, first.
            assert!(r.foveal_deemed < r.foveal_pairs, "no foveal pair settled");
        }
        assert!(shed_frames >= 6, "only {shed_frames} frames shed");
    }
}
