//! A frame's metrics (paper section 3): Δ and P summed over the deemed pairs, counts per level,
//! and the pairs in the fovea, at a cost the frame can afford.
//!
//! Δ and P need each deemed pair's evidence (a projection and two visual angles for P), about a
//! hundred nanoseconds a pair; at a million bodies under a tight budget over a million pairs are
//! deemed, and summing them all would cost more than the frame. So:
//! - up to [`EXACT_LIMIT`] deemed pairs (or, under a wall-clock budget, as many as a share of the
//!   budget pays for: [`Effort`], sized in `shedding`), every one is summed (exact);
//! - beyond it, a systematic sample is summed: the deemed pairs whose index is a multiple of the
//!   stride k, scaled by k, with its standard error (Bernoulli sampling at rate 1/k:
//!   se^2 = (1 - 1/k) k^2 sum of the sampled x^2). The report says the stride and both errors.
//!
//! Work is split into fixed runs of [`CHUNK`] pairs whose partial sums are added in run order,
//! so the result is the same for every thread count; a frame of at most one run sums in plain
//! pair order.

use crate::clock::Clock;
use crate::fixation::FrameView;
use crate::math::Vec3;
use crate::narrow_phase::{MARK_IN, MARK_OUT, NarrowPhase, PairState, PairStatus};
use crate::perception::Viewer;
use crate::simd::widest;
use crate::sphere_tree::SphereTree;
use crate::world::World;

/// Most deemed pairs whose evidence is summed exactly; beyond, a sample of about this many. A
/// pair's P costs two visual angles (about 150 ns), so this bounds the sum at a few milliseconds.
pub const EXACT_LIMIT: u32 = 25_000;
/// Pairs per run of the chunked sums. Changing it changes the rounding of the sums of Δ and P
/// over more pairs than this, never the counts.
pub const CHUNK: usize = 8_192;

/// Fewest pairs whose metrics are shared out among threads. At N = 10,000 (28,000 pairs, four
/// runs) the split once paid (0.10 -> 0.08 ms a frame); on a 2-core Intel Xeon under a 4 ms
/// budget the pass took 171 us a frame on two threads against 145 us on one (medians of
/// three alternating runs' p50 over 600 frames): waking the second thread cost more than its half of
/// the work. The answers do not depend on the thread count either way.
pub const PARALLEL_MIN_PAIRS: usize = 65_536;

/// What the metrics pass found.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Metrics {
    /// Δ (exact, or the sample's estimate).
    pub delta: f64,
    /// P with the view's model (0 without a view).
    pub p: f64,
    /// Standard error of Δ (0 when exact).
    pub delta_se: f64,
    /// Standard error of P (0 when exact).
    pub p_se: f64,
    /// Sampling stride (1: exact).
    pub stride: u32,
    /// Pairs resolved colliding.
    pub real: u32,
    /// Pairs resolved at each level.
    pub per_level: [u32; crate::config::MAX_DEPTH],
    /// Candidate pairs within the foveal threshold of the fixation.
    pub foveal: u32,
    /// Of those, deemed.
    pub foveal_deemed: u32,
    /// Deemed pairs whose Δ and P were summed (the sample, or every deemed pair when exact).
    pub sampled: u32,
    /// The clock's reading when that sum started (None when measured without a clock or with
    /// nothing deemed): it is the pass's last work, so the caller's next reading ends it.
    pub sample_started_ns: Option<u64>,
}

/// A fovea test: whether a screen point is within a visual angle of the fixation, exact in f64:
/// the angle between the unit eye rays of the two points is within the threshold iff their chord
/// is within the threshold's chord, 2 sin(threshold / 2), which costs a square root and no
/// trigonometry.
///
/// Every candidate pair is tested each frame, so [`Self::contains_point`] tests a world point
/// without projecting it: the viewer's eye ray through a point's screen position is the
/// camera-space vector `u = (k x, -k y, depth)` normalised, `k` being the pixel pitch times the
/// focal length over the viewing distance, and the angle to the fixation's ray `f` is within
/// the threshold iff `u . f >= |u| cos(threshold)`, which with both sides squared needs no
/// division and no square root (a few multiplications, against a projection, a division and
/// two square roots).
#[derive(Debug, Clone, Copy)]
pub struct Fovea<'a> {
    viewer: &'a Viewer,
    fixation_ray: [f64; 3],
    threshold_chord: f64,
    /// cos and sin of the threshold angle (for thresholds below 90 degrees).
    cos: f64,
    sin: f64,
    /// Pixel pitch times focal length over viewing distance.
    k: f64,
}

impl<'a> Fovea<'a> {
    /// Points within `threshold_deg` of `fixation_px`.
    pub fn new(viewer: &'a Viewer, fixation_px: [f64; 2], threshold_deg: f64) -> Self {
        let t = threshold_deg.clamp(0.0, 89.0).to_radians();
        let d = &viewer.display;
        Self {
            viewer,
            fixation_ray: d.eye_ray(fixation_px),
            threshold_chord: 2.0 * (0.5 * threshold_deg.clamp(0.0, 180.0)).to_radians().sin(),
            cos: t.cos(),
            sin: t.sin(),
            k: d.pixel_pitch_cm() * viewer.focal_px() / d.viewing_distance_cm,
        }
    }

    /// Whether world point `p` is seen within the threshold of the fixation (as
    /// `contains_px(viewer.project(p))`, without the projection; thresholds up to 89 degrees).
    #[inline]
    pub fn contains_point(&self, p: Vec3) -> bool {
        self.contains_xyz(p.x, p.y, p.z)
    }

    /// [`Self::contains_point`] on the point's coordinates: one lane of
    /// [`Self::contains_points8`].
    #[inline(always)]
    fn contains_xyz(&self, x: f64, y: f64, z: f64) -> bool {
        let e = self.viewer.eye;
        let r = [x - e.x, y - e.y, z - e.z];
        let depth = (-r[2]).max(1e-9 * (1.0 + r[0].abs() + r[1].abs()));
        let u = [self.k * r[0], -self.k * r[1], depth];
        let f = self.fixation_ray;
        let dot = u[0] * f[0] + u[1] * f[1] + u[2] * f[2];
        (dot > 0.0) & (dot * dot >= self.cos * self.cos * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]))
    }

    /// [`Self::contains_point`] for eight points given by their coordinates: the same operations
    /// in the same order, lane by lane, so the same answers.
    #[inline(always)]
    fn contains_points8(&self, x: [f64; 8], y: [f64; 8], z: [f64; 8]) -> [bool; 8] {
        let mut out = [false; 8];
        for (j, o) in out.iter_mut().enumerate() {
            *o = self.contains_xyz(x[j], y[j], z[j]);
        }
        out
    }

    /// Whether some point within `radius` of world point `p` may be seen within the threshold:
    /// false only if none is ([`Self::contains_point`] is false for every one of them).
    ///
    /// Why: the fovea holds a few percent of a frame's pairs, and testing a pair's centre needs
    /// both bodies' positions, the second a cache miss at large N. A pair's centre lies within
    /// half the pair's centre distance of its first body, so most pairs are ruled out from the
    /// first body alone. In the eye-ray space of [`Self::contains_point`] (camera space with x and
    /// y scaled by `k`) a world ball of radius r lies within a ball of radius max(k, 1) r, and the
    /// distance from a point at angle φ from the fixation ray to the cone of half-angle θ is
    /// |u| sin(φ - θ) = |u × f| cos θ - (u · f) sin θ (for φ - θ up to 90 degrees; beyond, this
    /// underestimates it, which only makes the test keep more).
    #[inline]
    pub fn may_contain_ball(&self, p: Vec3, radius: f64) -> bool {
        self.may_contain_grown(p, self.k.max(1.0) * radius)
    }

    /// [`Self::may_contain_ball`] for every point of `ps`, into `out`: the same answers, in a
    /// loop the compiler can vectorise (the test has no branch).
    ///
    /// Compiled for AVX2 where the processor has it (the same answers: Rust never fuses a
    /// multiply and an add on its own): at a million bodies, 8.7 ms a frame in SSE2 on one core.
    pub fn may_contain_balls(&self, ps: &[Vec3], radius: f64, out: &mut [bool]) {
        let grow = self.k.max(1.0) * radius;
        let mut fill = {
            #[inline(always)]
            || {
                // Eight bodies at a time, their coordinates first gathered into lanes, so the
                // test runs on whole vectors.
                let mut outs = out.chunks_exact_mut(8);
                let mut chunks = ps.chunks_exact(8);
                for (o8, p8) in (&mut outs).zip(&mut chunks) {
                    let x: [f64; 8] = std::array::from_fn(|j| p8[j].x);
                    let y: [f64; 8] = std::array::from_fn(|j| p8[j].y);
                    let z: [f64; 8] = std::array::from_fn(|j| p8[j].z);
                    let inside = self.may_contain_grown8(x, y, z, grow);
                    for (o, i) in o8.iter_mut().zip(inside) {
                        *o = i;
                    }
                }
                for (o, &p) in outs.into_remainder().iter_mut().zip(chunks.remainder()) {
                    *o = self.may_contain_grown(p, grow);
                }
            }
        };
        widest!(V3, fill)
    }

    /// The test of [`Self::may_contain_ball`] for a ball already grown into ray space: with
    /// both sides squared, `|u × f| cos θ <= m + (u · f) sin θ` (m the margin) holds iff the
    /// right side is not negative and `|u × f|^2 cos^2 θ <= (m + (u · f) sin θ)^2`, so no square
    /// root and no branch.
    #[inline(always)]
    fn may_contain_grown(&self, p: Vec3, grow: f64) -> bool {
        self.may_contain_grown_xyz(p.x, p.y, p.z, grow)
    }

    /// [`Self::may_contain_grown`] on the point's coordinates: one lane of
    /// [`Self::may_contain_grown8`].
    #[inline(always)]
    fn may_contain_grown_xyz(&self, x: f64, y: f64, z: f64, grow: f64) -> bool {
        let e = self.viewer.eye;
        let r = [x - e.x, y - e.y, z - e.z];
        let depth = -r[2];
        let u = [self.k * r[0], -self.k * r[1], depth];
        let f = self.fixation_ray;
        let dot = u[0] * f[0] + u[1] * f[1] + u[2] * f[2];
        let c = [
            u[1] * f[2] - u[2] * f[1],
            u[2] * f[0] - u[0] * f[2],
            u[0] * f[1] - u[1] * f[0],
        ];
        let cross_sq = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
        // A margin far above the rounding of either test (relative 1e-15).
        let rhs = grow * (1.0 + 1e-9) + 1e-9 * depth + dot * self.sin;
        // Near or behind the eye the ray space is not a linear image of the world: keep.
        (depth <= grow) | ((rhs >= 0.0) & (cross_sq * (self.cos * self.cos) <= rhs * rhs))
    }

    /// [`Self::may_contain_grown`] for eight points given by their coordinates: the same
    /// operations in the same order, lane by lane, so the same answers.
    #[inline(always)]
    fn may_contain_grown8(&self, x: [f64; 8], y: [f64; 8], z: [f64; 8], grow: f64) -> [bool; 8] {
        let mut out = [false; 8];
        for (j, o) in out.iter_mut().enumerate() {
            *o = self.may_contain_grown_xyz(x[j], y[j], z[j], grow);
        }
        out
    }

    /// Whether the screen point `px` is within the threshold.
    #[inline]
    pub fn contains_px(&self, px: [f64; 2]) -> bool {
        let r = self.viewer.display.eye_ray(px);
        let d = [
            r[0] - self.fixation_ray[0],
            r[1] - self.fixation_ray[1],
            r[2] - self.fixation_ray[2],
        ];
        (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt() <= self.threshold_chord
    }
}

/// How much of a frame's metrics to sum exactly: a whole-frame budget lowers both bounds to what
/// its time left allows (see `shedding`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Effort {
    /// Most deemed pairs whose Δ and P are summed exactly; beyond, a systematic sample of about
    /// this many (at least 1).
    pub sample_limit: u32,
    /// Only the first this many pairs can be foveal: pairs are listed by region in perceptual
    /// order and the regions after these lie wholly outside the fovea, so they are not tested.
    pub fovea_pairs: usize,
    /// The foveal pairs, all settled, when the frame's foveal pass already tested exactly the
    /// metrics' fovea over the same pairs (see `Collider::foveal_known`): not tested again.
    pub foveal_known: Option<u32>,
    /// The narrow phase's selection marks ([`NarrowPhase::selection_marks`]) are the frame's
    /// foveal pass's test of exactly the metrics' fovea: a pass cut by its budget still tested
    /// most of the foveal prefix, and the pairs it marked are not tested again.
    pub foveal_marked: bool,
    /// The counts (statuses, levels and the metrics' fovea) of every pair, already summed by
    /// the frame's narrow phase as it resolved them ([`NarrowPhase::resolve_frame_tallied`]):
    /// the pass over the pairs is not made again.
    pub counted: Option<Counts>,
    /// Fewest pairs whose passes are shared out among the threads ([`PARALLEL_MIN_PAIRS`];
    /// tests lower it to check that the answers do not depend on the thread count).
    pub parallel_min_pairs: usize,
}

impl Default for Effort {
    fn default() -> Self {
        Self {
            sample_limit: EXACT_LIMIT,
            fovea_pairs: usize::MAX,
            foveal_known: None,
            foveal_marked: false,
            counted: None,
            parallel_min_pairs: PARALLEL_MIN_PAIRS,
        }
    }
}

/// Sum the metrics of `np`'s pairs on up to `threads` threads. `view` measures P (None: P is 0);
/// `fovea` counts foveal pairs (None: 0).
pub fn measure(
    np: &NarrowPhase,
    tree: &SphereTree,
    world: &World,
    view: Option<&FrameView<'_>>,
    fovea: Option<&Fovea<'_>>,
    threads: usize,
) -> Metrics {
    measure_within(
        np,
        tree,
        world,
        view,
        fovea,
        threads,
        Effort::default(),
        None,
    )
}

/// [`measure`] within an [`Effort`].
///
/// Two passes, each over fixed runs of [`CHUNK`] pairs shared out among the threads:
/// 1. **Counts**, over every pair: per status and level (a histogram, so no pair branches on its
///    status), and the fovea test over the pairs that may be foveal. Integer sums: the same for
///    every thread count.
/// 2. **Δ and P** over the sample only: the deemed pairs whose index is a multiple of the stride,
///    which pass 1's deemed count fixes. The pass visits one pair in `stride` (in an exact frame,
///    none), and its floating-point partial sums are added in run order.
///
/// With a `clock`, the clock is read when the sum of Δ and P starts
/// ([`Metrics::sample_started_ns`]): that sum is the pass's last work, so a whole-frame budget's
/// next reading ends it and can size the next frame's sample by what it cost here.
#[allow(clippy::too_many_arguments)]
pub fn measure_within(
    np: &NarrowPhase,
    tree: &SphereTree,
    world: &World,
    view: Option<&FrameView<'_>>,
    fovea: Option<&Fovea<'_>>,
    threads: usize,
    effort: Effort,
    clock: Option<&dyn Clock>,
) -> Metrics {
    let pairs = &np.pairs[..];
    let n = pairs.len();
    let threads = if n < effort.parallel_min_pairs {
        1
    } else {
        threads
    };
    let runs: Vec<(usize, usize)> = (0..n.div_ceil(CHUNK).max(1))
        .map(|k| (k * CHUNK, ((k + 1) * CHUNK).min(n)))
        .collect();
    let centre_reach = centre_reach(tree);
    // A fovea already counted is not tested again.
    let fovea = fovea.filter(|_| effort.foveal_known.is_none());
    let marks = if effort.foveal_marked {
        np.selection_marks()
    } else {
        &[]
    };
    // What the foveal pass found of pair `i`, where it tested it.
    let marked = |i: usize| match marks.get(i) {
        Some(&MARK_IN) => Some(true),
        Some(&MARK_OUT) => Some(false),
        _ => None,
    };
    let fovea_end = effort.fovea_pairs.min(n);
    // Every pair tested, none of them marked by a foveal pass (the marks cover most of the
    // pairs where there are any), and not counted already: a whole frame's count.
    let whole = (fovea_end == n && marks.is_empty() && effort.counted.is_none())
        .then(|| FrameCount::new(fovea.copied(), n, tree, world, threads));
    let count = |lo: usize, hi: usize| -> Counts {
        let mut c = Counts::default();
        if let Some(whole) = &whole {
            whole.count(&pairs[lo..hi], &mut c);
            return c;
        }
        c.count_all(&pairs[lo..hi]);
        let pos = &world.position;
        let mid = |p: &PairState| (pos[p.a as usize] + pos[p.b as usize]) * 0.5;
        if let Some(f) = fovea.filter(|_| lo < fovea_end) {
            let tested = &pairs[lo..hi.min(fovea_end)];
            if fovea_end < n {
                // A shed frame's prefix: the pairs of the regions that may hold foveal pairs,
                // about half of them foveal. Every centre the foveal pass did not test is
                // tested, without a branch on the outcome (the marked ones lie in long runs: the
                // pass stops near the end of each of its runs, if at all).
                for (k, p) in tested.iter().enumerate() {
                    let inside = marked(lo + k).unwrap_or_else(|| f.contains_point(mid(p)));
                    c.foveal += u32::from(inside);
                    c.foveal_deemed += u32::from(inside & (p.status == PairStatus::Deemed));
                }
            } else {
                // Every pair, some marked by the foveal pass: the filter per pair where the
                // pass did not test it.
                for (k, p) in tested.iter().enumerate() {
                    let inside = marked(lo + k).unwrap_or_else(|| {
                        f.may_contain_ball(pos[p.a as usize], centre_reach)
                            && f.contains_point(mid(p))
                    });
                    if inside {
                        c.foveal += 1;
                        c.foveal_deemed += u32::from(p.status == PairStatus::Deemed);
                    }
                }
            }
        }
        c
    };
    let mut counts = Counts::default();
    if let Some(c) = effort.counted {
        counts = c;
    } else {
        for c in in_runs(&runs, threads, &count) {
            counts.add(&c);
        }
    }
    // Freed before the sum starts: the sum's timing is the sum's.
    drop(whole);
    let mut m = counts.metrics();
    if let Some(known) = effort.foveal_known {
        m.foveal = known;
        m.foveal_deemed = 0;
    }
    let deemed = counts.of(PairStatus::Deemed);
    let stride = deemed.div_ceil(effort.sample_limit.max(1)).max(1) as usize;
    if deemed > 0 {
        m.sample_started_ns = clock.map(|c| c.now_ns());
        let sample = |lo: usize, hi: usize| -> Sums {
            let mut s = Sums::default();
            for i in (lo.next_multiple_of(stride)..hi).step_by(stride) {
                if pairs[i].status != PairStatus::Deemed {
                    continue;
                }
                let ev = np.evidence(i, tree, world);
                s.pairs += 1;
                s.delta += ev.gap;
                s.delta_sq += ev.gap * ev.gap;
                if let Some(v) = view {
                    let w = v.weight(&ev);
                    s.p += w;
                    s.p_sq += w * w;
                }
            }
            s
        };
        let mut total = Sums::default();
        for s in in_runs(&runs, threads, &sample) {
            total.add(&s);
        }
        m.sampled = total.pairs;
        m.delta = total.delta;
        m.p = total.p;
        if stride > 1 {
            let k = stride as f64;
            m.delta *= k;
            m.p *= k;
            let var = (1.0 - 1.0 / k) * k * k;
            m.delta_se = (var * total.delta_sq).sqrt();
            m.p_se = (var * total.p_sq).sqrt();
        }
    }
    m.stride = stride as u32;
    m
}

/// The status and level histogram of `pairs`, calling `also` on each pair in the same pass. Four
/// interleaved histograms (summed by the caller): consecutive pairs mostly share a bin, and one
/// counter would make every increment wait for the last.
#[inline]
fn histogram_and(pairs: &[PairState], mut also: impl FnMut(&PairState)) -> [[u32; BINS]; 4] {
    let mut hist = [[0u32; BINS]; 4];
    for (i, p) in pairs.iter().enumerate() {
        hist[i & 3][bin(p.status, p.resolved_level)] += 1;
        also(p);
    }
    hist
}

/// Pairs per block of the counts' fovea test (see `measure_within`): small enough to stay in L1.
const NEAR_BLOCK: usize = 256;
// A pair's place in its block is kept as a u16.
const _: () = assert!(NEAR_BLOCK <= 1 << 16);

/// Histogram bins: one per status and resolved level.
const LEVELS: usize = crate::config::MAX_DEPTH + 1;
const STATUSES: usize = 5;
const BINS: usize = STATUSES * LEVELS;

#[inline]
fn bin(status: PairStatus, level: u8) -> usize {
    // Levels never exceed the tree's depth; `min` keeps the index in range without a panic path.
    (status as usize) * LEVELS + (level as usize).min(LEVELS - 1)
}

/// Pass 1's integer sums over some pairs: each status and level's count and the foveal pairs.
/// An exact frame's narrow phase sums them block by block as it resolves its pairs (see
/// [`NarrowPhase::resolve_frame_tallied`] and [`Effort::counted`]); integer sums, so the same
/// in any order and on any thread count.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Counts {
    hist: [u32; BINS],
    foveal: u32,
    foveal_deemed: u32,
}

impl Default for Counts {
    fn default() -> Self {
        Self {
            hist: [0; BINS],
            foveal: 0,
            foveal_deemed: 0,
        }
    }
}

impl Counts {
    /// Add another count.
    pub fn add(&mut self, o: &Counts) {
        self.add_hist(&[o.hist]);
        self.foveal += o.foveal;
        self.foveal_deemed += o.foveal_deemed;
    }

    fn add_hist(&mut self, hist: &[[u32; BINS]]) {
        for h in hist {
            for (a, b) in self.hist.iter_mut().zip(h) {
                *a += b;
            }
        }
    }

    /// Count `pairs`, and those whose centre `fovea` holds. `near` is [`near_bodies`]' filter
    /// of the same fovea (about a tenth of the bodies at a central fixation), and `position`
    /// the bodies' positions.
    ///
    /// Every pair, a few percent of them foveal: the first body rules most out. Block by block,
    /// the histogram pass notes the pairs whose first body is near without a branch, and only
    /// those are tested (also without a branch), while the block is in cache: a branch on the
    /// near flag per pair cost more than the tests it saved.
    fn count_near(
        &mut self,
        pairs: &[PairState],
        fovea: &Fovea<'_>,
        near: &[bool],
        position: &[Vec3],
    ) {
        let mut count = {
            #[inline(always)]
            || self.count_near_in(pairs, fovea, near, position)
        };
        widest!(V3, count)
    }

    /// [`Self::count_near`], compiled for whatever vector width the caller enables: the near
    /// pairs' centres are tested eight at a time.
    #[inline(always)]
    fn count_near_in(
        &mut self,
        pairs: &[PairState],
        fovea: &Fovea<'_>,
        near: &[bool],
        position: &[Vec3],
    ) {
        let mut hist = [[0u32; BINS]; 4];
        let mut near_at = [0u16; NEAR_BLOCK];
        for block in pairs.chunks(NEAR_BLOCK) {
            let mut k = 0;
            for (j, p) in block.iter().enumerate() {
                hist[j & 3][bin(p.status, p.resolved_level)] += 1;
                near_at[k] = j as u16;
                k += usize::from(near[p.a as usize]);
            }
            let mut add = |p: &PairState, inside: bool| {
                self.foveal += u32::from(inside);
                self.foveal_deemed += u32::from(inside & (p.status == PairStatus::Deemed));
            };
            let mut eights = near_at[..k].chunks_exact(8);
            for js in &mut eights {
                let ps: [&PairState; 8] = std::array::from_fn(|l| &block[js[l] as usize]);
                let mid = |l: usize| position[ps[l].a as usize] + position[ps[l].b as usize];
                let mids: [Vec3; 8] = std::array::from_fn(|l| mid(l) * 0.5);
                let inside =
                    fovea.contains_points8(mids.map(|m| m.x), mids.map(|m| m.y), mids.map(|m| m.z));
                for (p, i) in ps.into_iter().zip(inside) {
                    add(p, i);
                }
            }
            for &j in eights.remainder() {
                let p = &block[j as usize];
                let mid = (position[p.a as usize] + position[p.b as usize]) * 0.5;
                add(p, fovea.contains_point(mid));
            }
        }
        self.add_hist(&hist);
    }

    /// [`Self::count_near`] without the bodies' filter: each pair's first body is tested
    /// against the fovea grown by `reach` ([`centre_reach`]), where the pair is. For frames with
    /// fewer pairs than [`uses_near_bodies`] asks: a pass over a million bodies for a few pairs
    /// cost a shed frame 7 ms.
    fn count_filtered(
        &mut self,
        pairs: &[PairState],
        fovea: &Fovea<'_>,
        position: &[Vec3],
        reach: f64,
    ) {
        let hist = histogram_and(pairs, |p| {
            let a = position[p.a as usize];
            // The second body is read only where the first is near: at large N, a cache miss.
            if fovea.may_contain_ball(a, reach)
                && fovea.contains_point((a + position[p.b as usize]) * 0.5)
            {
                self.foveal += 1;
                self.foveal_deemed += u32::from(p.status == PairStatus::Deemed);
            }
        });
        self.add_hist(&hist);
    }

    /// Count `pairs` by status and level alone (no fixation).
    fn count_all(&mut self, pairs: &[PairState]) {
        self.add_hist(&histogram_and(pairs, |_| {}));
    }

    fn of(&self, status: PairStatus) -> u32 {
        let s = status as usize * LEVELS;
        self.hist[s..s + LEVELS].iter().sum()
    }

    /// The counts as metrics (Δ and P still zero).
    fn metrics(&self) -> Metrics {
        let mut m = Metrics {
            real: self.of(PairStatus::Colliding),
            foveal: self.foveal,
            foveal_deemed: self.foveal_deemed,
            ..Metrics::default()
        };
        for (l, count) in m.per_level.iter_mut().enumerate() {
            *count = (0..STATUSES).map(|s| self.hist[s * LEVELS + l + 1]).sum();
        }
        m
    }
}

/// Pass 2's floating-point sums of one run.
#[derive(Debug, Clone, Copy, Default)]
struct Sums {
    pairs: u32,
    delta: f64,
    p: f64,
    delta_sq: f64,
    p_sq: f64,
}

impl Sums {
    fn add(&mut self, o: &Sums) {
        self.pairs += o.pairs;
        self.delta += o.delta;
        self.p += o.p;
        self.delta_sq += o.delta_sq;
        self.p_sq += o.p_sq;
    }
}

/// `f` over every run, on up to `threads` threads, the results in run order: worker w takes runs
/// w, w + workers, ... (a fixed partition, so the results do not depend on the thread count).
fn in_runs<T: Send>(
    runs: &[(usize, usize)],
    threads: usize,
    f: &(impl Fn(usize, usize) -> T + Sync),
) -> Vec<T> {
    if threads <= 1 || runs.len() <= 1 {
        return runs.iter().map(|&(lo, hi)| f(lo, hi)).collect();
    }
    let workers = threads.min(runs.len());
    let share = move |w: usize| -> Vec<(usize, T)> {
        (w..runs.len())
            .step_by(workers)
            .map(|k| (k, f(runs[k].0, runs[k].1)))
            .collect()
    };
    let share = &share;
    let mut shares: Vec<Vec<(usize, T)>> = (0..workers).map(|_| Vec::new()).collect();
    rayon::in_place_scope(|s| {
        let (first, others) = shares.split_at_mut(1);
        for (w, out) in others.iter_mut().enumerate() {
            s.spawn(move |_| *out = share(w + 1));
        }
        first[0] = share(0);
    });
    let mut done: Vec<(usize, T)> = shares.into_iter().flatten().collect();
    done.sort_unstable_by_key(|&(k, _)| k);
    done.into_iter().map(|(_, t)| t).collect()
}

/// How far a candidate pair's centre can be from its first body: candidate boxes overlap
/// (half-size h = the root radius), so the centres differ by less than 2h on each axis and the
/// pair's centre is within sqrt(3) h of either body. The reach of [`near_bodies`]'s filter.
pub(crate) fn centre_reach(tree: &SphereTree) -> f64 {
    3f64.sqrt() * tree.root_radius()
}

/// A count of every pair of a frame ([`Counts`]), the fovea's pairs included: with the bodies'
/// filter ([`near_bodies`], one pass over the bodies, in body order and without a branch, so a
/// pair reads one byte of its first body instead of its position) where there are pairs enough
/// ([`uses_near_bodies`]), else pair by pair ([`Counts::count_filtered`]). The metrics' pass
/// counts with it, and so does an exact frame's narrow phase as it resolves its pairs.
#[derive(Debug)]
pub struct FrameCount<'a> {
    fovea: Option<Fovea<'a>>,
    near: Option<Vec<bool>>,
    position: &'a [Vec3],
    reach: f64,
}

impl<'a> FrameCount<'a> {
    /// A count of `pairs` candidate pairs of `world`'s bodies, with the foveal pairs of `fovea`
    /// (the bodies' filter, where it is used, runs here on up to `threads` threads).
    pub fn new(
        fovea: Option<Fovea<'a>>,
        pairs: usize,
        tree: &SphereTree,
        world: &'a World,
        threads: usize,
    ) -> Self {
        let (position, reach) = (&world.position[..], centre_reach(tree));
        let near = fovea
            .as_ref()
            .filter(|_| uses_near_bodies(pairs, position.len()))
            .map(|f| near_bodies(f, position, reach, threads));
        Self {
            fovea,
            near,
            position,
            reach,
        }
    }

    /// Add `pairs` (some of the frame's) to `c`.
    pub fn count(&self, pairs: &[PairState], c: &mut Counts) {
        match (&self.fovea, &self.near) {
            (Some(f), Some(near)) => c.count_near(pairs, f, near, self.position),
            (Some(f), None) => c.count_filtered(pairs, f, self.position, self.reach),
            (None, _) => c.count_all(pairs),
        }
    }
}

/// Whether a count over `pairs` candidate pairs of `bodies` bodies filters by body, with one
/// pass over the bodies ([`near_bodies`]), rather than by pair ([`Counts::count_filtered`]):
/// when there are at least a quarter as many pairs as bodies.
pub fn uses_near_bodies(pairs: usize, bodies: usize) -> bool {
    4 * pairs >= bodies
}

/// Bodies fewer than this are filtered on one thread: waking a thread of the pool can cost tens
/// of microseconds.
const NEAR_PER_THREAD: usize = 4_096;

/// Per body: whether a pair it finds may have its centre in the fovea (see
/// [`Fovea::may_contain_ball`]), on up to `threads` threads.
pub(crate) fn near_bodies(
    f: &Fovea<'_>,
    position: &[Vec3],
    reach: f64,
    threads: usize,
) -> Vec<bool> {
    let mut near = vec![false; position.len()];
    let fill = |out: &mut [bool], ps: &[Vec3]| f.may_contain_balls(ps, reach, out);
    let workers = threads.min(position.len() / NEAR_PER_THREAD).max(1);
    if workers == 1 {
        fill(&mut near, position);
        return near;
    }
    let per = position.len().div_ceil(workers);
    rayon::in_place_scope(|s| {
        let fill = &fill;
        let mut parts = near.chunks_mut(per).zip(position.chunks(per));
        let first = parts.next();
        for (out, ps) in parts {
            s.spawn(move |_| fill(out, ps));
        }
        if let Some((out, ps)) = first {
            fill(out, ps);
        }
    });
    near
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::broad_phase::BroadPhase;
    use crate::config::SceneConfig;
    use crate::perception::{CameraConfig, Display, PerceptualModel};
    use crate::shape::Star;

    /// The first frame of the paper scene with `bodies` bodies: its world, tree, viewer and every
    /// candidate pair, untested.
    fn first_frame(bodies: u32, seed: u64) -> (World, SphereTree, Viewer, NarrowPhase) {
        let cfg = SceneConfig::paper(bodies, seed);
        let world = World::generate(&cfg);
        let tree = SphereTree::build(Star::new(cfg.shape_radius), 4).expect("tree");
        let mut bp = BroadPhase::new(tree.root_radius(), world.lo, cfg.volume_side(), world.len());
        let mut np = NarrowPhase::default();
        np.reset(bp.update(&world.position));
        let viewer = Viewer::new(
            &CameraConfig::default(),
            &Display::default(),
            world.lo,
            cfg.volume_side(),
        );
        (world, tree, viewer, np)
    }

    /// The default camera and display over a cube of side 20 at the origin.
    fn viewer_of_a_20_unit_cube() -> Viewer {
        Viewer::new(
            &CameraConfig::default(),
            &Display::default(),
            Vec3::ZERO,
            20.0,
        )
    }

    /// [`measure`] with its passes shared out among `threads` threads however few the pairs.
    fn measure_split(
        np: &NarrowPhase,
        tree: &SphereTree,
        world: &World,
        fovea: &Fovea<'_>,
        threads: usize,
    ) -> Metrics {
        let effort = Effort {
            parallel_min_pairs: 0,
            ..Effort::default()
        };
        measure_within(np, tree, world, None, Some(fovea), threads, effort, None)
    }

    /// The default model's view with the fixation at (`x`, `y`) of the screen.
    fn view_at(viewer: &Viewer, x: f64, y: f64) -> FrameView<'_> {
        FrameView {
            viewer,
            fixation_px: viewer.to_pixels(x, y),
            model: PerceptualModel::default(),
            uncertainty_deg: 0.0,
        }
    }

    #[test]
    fn sampled_sums_estimate_the_exact_ones_within_their_error_for_any_thread_count() {
        let (world, tree, viewer, mut np) = first_frame(3_000, 4);
        np.deem_open();
        let view = view_at(&viewer, 0.5, 0.5);
        let fovea = Fovea::new(&viewer, view.fixation_px, 5.0);
        let exact = measure(&np, &tree, &world, Some(&view), Some(&fovea), 1);
        assert_eq!(exact.stride, 1);
        assert_eq!(exact.delta_se, 0.0);
        let n = np.pairs.len() as u32;
        let limit = Effort {
            sample_limit: n / 10,
            parallel_min_pairs: 0,
            ..Effort::default()
        };
        let on = |threads| {
            measure_within(
                &np,
                &tree,
                &world,
                Some(&view),
                Some(&fovea),
                threads,
                limit,
                None,
            )
        };
        let sampled = on(1);
        assert!(sampled.stride >= 10, "{}", sampled.stride);
        assert!(
            (sampled.delta - exact.delta).abs() <= 4.0 * sampled.delta_se && sampled.delta_se > 0.0,
            "{} vs {} (se {})",
            sampled.delta,
            exact.delta,
            sampled.delta_se
        );
        assert!((sampled.p - exact.p).abs() <= 4.0 * sampled.p_se);
        // Counts are never sampled, and the fovea is counted exactly.
        assert_eq!(
            (sampled.foveal, sampled.foveal_deemed),
            (exact.foveal, exact.foveal)
        );
        assert!(exact.foveal > 0 && exact.foveal < n);
        assert_eq!(on(2), sampled);
    }

    /// On a frame of every status and level, over more than one run of pairs: the counts equal a
    /// count pair by pair, the sample is exactly the deemed pairs at multiples of the stride, and
    /// none of it depends on the thread count or on whether the fovea is filtered per body or per
    /// pair (a shed frame's prefix).
    #[test]
    fn counts_and_sample_match_a_pair_by_pair_sum_on_any_thread_count() {
        let (world, tree, viewer, mut np) = first_frame(20_000, 5);
        assert!(
            np.pairs.len() > CHUNK,
            "{} pairs: one run only",
            np.pairs.len()
        );
        // Settle every third pair, deem the rest.
        np.resolve_selected(
            &tree,
            &world,
            usize::MAX,
            1,
            &|p: &crate::narrow_phase::PairState| (p.a + p.b).is_multiple_of(3),
            &mut |_| true,
        );
        np.deem_open();
        let view = view_at(&viewer, 0.4, 0.6);
        let fovea = Fovea::new(&viewer, view.fixation_px, 5.0);
        let pos = &world.position;
        let centre =
            |p: &crate::narrow_phase::PairState| (pos[p.a as usize] + pos[p.b as usize]) * 0.5;
        for (limit, prefix) in [
            (u32::MAX, usize::MAX),
            (1_000, usize::MAX),
            (700, 9_000),
            (700, 40_000),
        ] {
            let effort = Effort {
                sample_limit: limit,
                fovea_pairs: prefix,
                parallel_min_pairs: 0,
                ..Effort::default()
            };
            let on = |threads, clock: Option<&dyn Clock>| {
                measure_within(
                    &np,
                    &tree,
                    &world,
                    Some(&view),
                    Some(&fovea),
                    threads,
                    effort,
                    clock,
                )
            };
            let m = on(1, None);
            let mut want = Metrics::default();
            let deemed = np
                .pairs
                .iter()
                .filter(|p| p.status == PairStatus::Deemed)
                .count();
            let stride = deemed.div_ceil(limit as usize).max(1);
            let (mut delta, mut p_sum) = (0.0, 0.0);
            for (i, p) in np.pairs.iter().enumerate() {
                want.real += u32::from(p.status == PairStatus::Colliding);
                if p.resolved_level > 0 {
                    want.per_level[p.resolved_level as usize - 1] += 1;
                }
                if i < prefix && fovea.contains_point(centre(p)) {
                    want.foveal += 1;
                    want.foveal_deemed += u32::from(p.status == PairStatus::Deemed);
                }
                if p.status == PairStatus::Deemed && i % stride == 0 {
                    want.sampled += 1;
                    let ev = np.evidence(i, &tree, &world);
                    delta += ev.gap;
                    p_sum += view.weight(&ev);
                }
            }
            assert_eq!(m.stride as usize, stride);
            assert_eq!(m.sampled, want.sampled);
            assert_eq!(m.sample_started_ns, None, "no clock, no reading");
            assert_eq!((m.real, m.per_level), (want.real, want.per_level));
            assert_eq!(
                (m.foveal, m.foveal_deemed),
                (want.foveal, want.foveal_deemed)
            );
            assert!(want.real > 0 && want.foveal_deemed > 0 && want.foveal > want.foveal_deemed);
            let k = stride as f64;
            assert!(
                (m.delta - k * delta).abs() <= 1e-9 * m.delta.abs(),
                "{} {}",
                m.delta,
                k * delta
            );
            assert!((m.p - k * p_sum).abs() <= 1e-9 * m.p.abs());
            for threads in [2, 3] {
                assert_eq!(on(threads, None), m, "{threads} threads");
            }
            // With a clock (frozen at 0): the same sums, and the reading that starts the sum.
            let timed = on(1, Some(&crate::FrozenClock));
            assert_eq!(timed.sample_started_ns, Some(0));
            assert_eq!(
                Metrics {
                    sample_started_ns: None,
                    ..timed
                },
                m
            );
        }
    }

    /// The first-body filter never drops a point of the ball that is in the fovea, rules out most
    /// of a scene, and leaves the fovea count of a frame equal to testing every pair's centre.
    #[test]
    fn the_ball_filter_keeps_every_foveal_point_and_the_count_is_unchanged() {
        let cfg = SceneConfig::paper(20_000, 9);
        let world = World::generate(&cfg);
        let viewer = Viewer::new(
            &CameraConfig::default(),
            &Display::default(),
            world.lo,
            cfg.volume_side(),
        );
        let mut rng = crate::rng::Rng::new(11);
        let (mut ruled_out, mut balls) = (0, 0);
        for (fx, fy, deg) in [(0.5, 0.5, 5.0), (0.05, 0.9, 5.0), (0.6, 0.35, 1.0)] {
            let fovea = Fovea::new(&viewer, viewer.to_pixels(fx, fy), deg);
            for p in world.position.iter().step_by(4) {
                let radius = rng.range(0.0, 0.5);
                let keep = fovea.may_contain_ball(*p, radius);
                balls += 1;
                ruled_out += usize::from(!keep);
                for _ in 0..8 {
                    let d = Vec3::new(
                        rng.range(-1.0, 1.0),
                        rng.range(-1.0, 1.0),
                        rng.range(-1.0, 1.0),
                    );
                    let q = *p + d.normalize_or_zero() * radius * rng.range(0.0, 1.0);
                    assert!(keep || !fovea.contains_point(q), "{p:?} r {radius}: {q:?}");
                }
            }
        }
        assert!(ruled_out * 10 > balls * 8, "{ruled_out} of {balls}");
        // A frame's fovea count equals the centre test over every pair.
        let tree = SphereTree::build(Star::new(cfg.shape_radius), 4).expect("tree");
        let mut bp = BroadPhase::new(tree.root_radius(), world.lo, cfg.volume_side(), world.len());
        let mut np = NarrowPhase::default();
        np.reset(bp.update(&world.position));
        let fovea = Fovea::new(&viewer, viewer.to_pixels(0.45, 0.55), 5.0);
        let brute = np
            .pairs
            .iter()
            .filter(|p| {
                fovea.contains_point(
                    (world.position[p.a as usize] + world.position[p.b as usize]) * 0.5,
                )
            })
            .count() as u32;
        let m = measure(&np, &tree, &world, None, Some(&fovea), 1);
        assert_eq!(m.foveal, brute);
        assert!(brute > 10, "{brute}");
        // The foveal deemed pairs too, on one thread and two (pairs in several runs and blocks).
        for p in np.pairs.iter_mut().step_by(3) {
            p.status = PairStatus::Deemed;
        }
        let deemed = np
            .pairs
            .iter()
            .filter(|p| {
                p.status == PairStatus::Deemed
                    && fovea.contains_point(
                        (world.position[p.a as usize] + world.position[p.b as usize]) * 0.5,
                    )
            })
            .count() as u32;
        assert!(np.pairs.len() > CHUNK && deemed > 10, "{deemed}");
        for threads in [1, 2] {
            let m = measure_split(&np, &tree, &world, &fovea, threads);
            assert_eq!((m.foveal, m.foveal_deemed), (brute, deemed));
        }
        // The last run's last block is a partial one: a fovea on the last pair has pairs there.
        let mid =
            |p: &PairState| (world.position[p.a as usize] + world.position[p.b as usize]) * 0.5;
        let n = np.pairs.len();
        assert!(n % NEAR_BLOCK != 0);
        let at_last = Fovea::new(&viewer, viewer.project(mid(&np.pairs[n - 1])), 5.0);
        let tail = &np.pairs[n - n % NEAR_BLOCK..];
        assert!(tail.iter().any(|p| at_last.contains_point(mid(p))));
        let inside = np.pairs.iter().filter(|p| at_last.contains_point(mid(p)));
        let want = (
            inside.clone().count() as u32,
            inside.filter(|p| p.status == PairStatus::Deemed).count() as u32,
        );
        for threads in [1, 2] {
            let m = measure_split(&np, &tree, &world, &at_last, threads);
            assert_eq!((m.foveal, m.foveal_deemed), want, "{threads} threads");
        }
        // And with fewer pairs than a quarter of the bodies, filtered pair by pair.
        let in_fovea = |p: &&crate::narrow_phase::PairState| {
            fovea
                .contains_point((world.position[p.a as usize] + world.position[p.b as usize]) * 0.5)
        };
        let few: Vec<(u32, u32)> = np
            .pairs
            .iter()
            .filter(in_fovea)
            .chain(np.pairs.iter().take(world.len() / 8))
            .take(world.len() / 5)
            .map(|p| (p.a, p.b))
            .collect();
        let mut some = NarrowPhase::default();
        some.reset(&few);
        let brute = some.pairs.iter().filter(in_fovea).count() as u32;
        assert!(
            4 * few.len() < world.len() && brute > 10,
            "{} {brute}",
            few.len()
        );
        assert_eq!(
            measure(&some, &tree, &world, None, Some(&fovea), 1).foveal,
            brute
        );
    }

    /// A foveal pass cut by its budget marks the pairs of the prefix it tested; the metrics take
    /// those marks and test only the rest: the same foveal and foveal deemed counts as testing
    /// every pair, on one and two threads. Marks that say otherwise are believed (they are read,
    /// not tested again), and ignored when the effort does not vouch for them.
    #[test]
    fn a_cut_foveal_pass_marks_what_it_tested_and_the_counts_stay_exact() {
        let (world, tree, viewer, mut np) = first_frame(20_000, 5);
        let candidates: Vec<(u32, u32)> = np.pairs.iter().map(|p| (p.a, p.b)).collect();
        let view = view_at(&viewer, 0.45, 0.55);
        let fovea = Fovea::new(&viewer, view.fixation_px, 5.0);
        let pos = &world.position;
        let inside =
            |p: &PairState| fovea.contains_point((pos[p.a as usize] + pos[p.b as usize]) * 0.5);
        let effort = |marked, prefix| Effort {
            sample_limit: 1_000,
            fovea_pairs: prefix,
            foveal_marked: marked,
            parallel_min_pairs: 0,
            ..Effort::default()
        };
        // (foveal, foveal deemed) as the metrics count them.
        let counts = |np: &NarrowPhase, threads, marked, prefix| {
            let effort = effort(marked, prefix);
            let m = measure_within(np, &tree, &world, None, Some(&fovea), threads, effort, None);
            (m.foveal, m.foveal_deemed)
        };
        // A prefix of the pairs (a shed frame's foveal regions), and every pair (every region
        // searched may hold foveal pairs).
        for (prefix, threads) in [
            (np.pairs.len() * 3 / 4, 1),
            (np.pairs.len() * 3 / 4, 2),
            (np.pairs.len(), 2),
        ] {
            np.reset(&candidates);
            let mut calls = 0;
            np.resolve_selected(&tree, &world, prefix, threads, &inside, &mut |_| {
                calls += 1;
                calls <= 60
            });
            np.deem_open();
            let marks = np.selection_marks().to_vec();
            let count = |m: u8| marks.iter().filter(|&&k| k == m).count();
            let (unseen, out, within) = (
                count(crate::narrow_phase::MARK_UNSEEN),
                count(MARK_OUT),
                count(MARK_IN),
            );
            assert!(
                unseen > 0 && out > 0 && within > 0,
                "{unseen} {out} {within}"
            );
            let brute = |end: usize| {
                let foveal = np.pairs[..end].iter().filter(|p| inside(p));
                let all = foveal.clone().count() as u32;
                let deemed = foveal.filter(|p| p.status == PairStatus::Deemed).count() as u32;
                (all, deemed)
            };
            assert!(brute(prefix).1 > 0, "some foveal pairs deemed");
            for (marked, t) in [(true, threads), (false, threads), (true, 3 - threads)] {
                let got = counts(&np, t, marked, prefix);
                assert_eq!(got, brute(prefix), "{threads} {marked} {t}");
            }
        }
        // Marks of another selection (every pair it reached) are believed where set.
        let prefix = np.pairs.len() * 3 / 4;
        np.reset(&candidates);
        let mut calls = 0;
        np.resolve_selected(&tree, &world, prefix, 1, &|_| true, &mut |_| {
            calls += 1;
            calls <= 500
        });
        let reached = np
            .selection_marks()
            .iter()
            .filter(|&&k| k == MARK_IN)
            .count();
        let rest = np.pairs[reached..prefix]
            .iter()
            .filter(|p| inside(p))
            .count();
        assert_eq!(counts(&np, 1, true, prefix).0 as usize, reached + rest);
        let all = np.pairs[..prefix].iter().filter(|p| inside(p)).count() as u32;
        assert_eq!(counts(&np, 1, false, prefix).0, all);
    }

    #[test]
    fn the_projection_free_fovea_test_agrees_with_the_visual_angle() {
        let viewer = viewer_of_a_20_unit_cube();
        let mut rng = crate::rng::Rng::new(7);
        let (mut inside, mut checked) = (0, 0);
        for (fx, fy, deg) in [
            (0.5, 0.5, 5.0),
            (0.1, 0.85, 5.0),
            (0.7, 0.3, 2.0),
            (0.4, 0.6, 30.0),
        ] {
            let fix = viewer.to_pixels(fx, fy);
            let fovea = Fovea::new(&viewer, fix, deg);
            for _ in 0..20_000 {
                let p = Vec3::new(
                    rng.range(-5.0, 25.0),
                    rng.range(-5.0, 25.0),
                    rng.range(-10.0, 20.0),
                );
                let angle = viewer.display.visual_angle_deg(viewer.project(p), fix);
                // Points within 1e-9 degrees of the boundary may fall either way by rounding.
                if (angle - deg).abs() < 1e-9 {
                    continue;
                }
                checked += 1;
                assert_eq!(fovea.contains_point(p), angle < deg, "{p:?} at {angle} deg");
                assert_eq!(fovea.contains_px(viewer.project(p)), angle < deg);
                inside += usize::from(angle < deg);
            }
        }
        assert!(
            inside > 500 && inside < checked - 500,
            "{inside} of {checked}"
        );
    }

    /// The filter over a slice, eight bodies at a time in vectors, answers exactly as the test
    /// of each body alone, and so does the centre test of eight points: for bodies anywhere (in
    /// the scene, behind and beside the eye, far from the origin, not finite) and slices of any
    /// length.
    #[test]
    fn the_ball_filter_over_many_bodies_answers_as_each_alone() {
        let viewer = viewer_of_a_20_unit_cube();
        let mut rng = crate::rng::Rng::new(23);
        let specials = [
            viewer.eye,
            viewer.eye + Vec3::new(0.0, 0.0, 1e-12),
            Vec3::new(f64::NAN, 1.0, 1.0),
            Vec3::new(1.0, f64::INFINITY, 1.0),
            Vec3::new(1e15, -1e15, 3.0),
        ];
        let (mut kept, mut total) = (0, 0);
        for (fx, fy, deg) in [(0.5, 0.5, 5.0), (0.1, 0.85, 5.0), (0.7, 0.3, 30.0)] {
            let fovea = Fovea::new(&viewer, viewer.to_pixels(fx, fy), deg);
            for len in [0, 1, 7, 8, 9, 63, 1000] {
                let mut ps: Vec<Vec3> = (0..len)
                    .map(|_| {
                        let scale = if rng.range(0.0, 1.0) < 0.1 { 1e6 } else { 1.0 };
                        Vec3::new(
                            rng.range(-5.0, 25.0),
                            rng.range(-5.0, 25.0),
                            rng.range(-10.0, 40.0),
                        ) * scale
                    })
                    .collect();
                for (p, s) in ps.iter_mut().zip(specials) {
                    *p = s;
                }
                let radius = rng.range(0.0, 2.0);
                let mut out = vec![true; len];
                fovea.may_contain_balls(&ps, radius, &mut out);
                for (p, o) in ps.iter().zip(&out) {
                    assert_eq!(*o, fovea.may_contain_ball(*p, radius), "{p:?} r {radius}");
                    kept += usize::from(*o);
                    total += 1;
                }
                // The centre test eight at a time, likewise.
                for p8 in ps.chunks_exact(8) {
                    let inside = fovea.contains_points8(
                        std::array::from_fn(|j| p8[j].x),
                        std::array::from_fn(|j| p8[j].y),
                        std::array::from_fn(|j| p8[j].z),
                    );
                    for (p, i) in p8.iter().zip(inside) {
                        assert_eq!(i, fovea.contains_point(*p), "{p:?}");
                    }
                }
            }
        }
        assert!(kept > 0 && kept < total, "{kept} of {total}");
    }
}
