//! Broad phase: candidate pairs of overlapping fixed-size bounding boxes (paper section 2).
//!
//! Every body's box is the cube of half-size `h` (the sphere tree's root radius) around its centre,
//! so two boxes overlap iff the centres are within `2h` on every axis (touching counts). Two
//! algorithms produce exactly the same set of pairs, each as (smaller id, larger id):
//! - [`BroadPhaseKind::SweepAndPrune`] (`sap.rs`): the paper's choice, after I-COLLIDE \[5\]: sorted
//!   lists per y-z column kept between frames and repaired by insertion sort, exploiting temporal
//!   coherence. Its pair *order* is what the schedulers see at the paper's N, and is pinned by the
//!   golden determinism hash and by a test here.
//! - [`BroadPhaseKind::Grid`] (`grid.rs`): a uniform grid keyed by the fixed box size, counting-sorted
//!   into flat arrays every frame. At a million bodies the sorted lists of sweep and prune are
//!   scattered through memory and their repair is dominated by cache misses; the grid's passes are
//!   forward scans, and its pair search can be split over threads with an identical output (as can
//!   sweep and prune's sweep).
//!
//! [`BroadPhaseKind::Auto`] picks sweep and prune below [`AUTO_GRID_MIN_BODIES`] and the grid from
//! there on.
//!
//! The output buffer is reused between frames but does not stay grown after one pathological frame:
//! see [`SHRINK_AFTER_FRAMES`].

mod grid;
mod sap;

use serde::{Deserialize, Serialize};

use crate::math::Vec3;
use grid::Grid;
use sap::SweepAndPrune;

/// Whether the grid's pair search takes its AVX-512 rounds on this processor (the same check
/// the search makes), so that a report can say which rounds its figures were measured with.
pub fn wide_rounds_available() -> bool {
    grid::wide_rounds_available()
}

/// [`BroadPhaseKind::Auto`] uses the grid from this many bodies on, sweep and prune below.
///
/// Measured with criterion on the paper scene, one thread (`broad_phase` group of
/// `benches/step.rs`, one update per frame of motion; a shared 2-core machine, medians): sweep and
/// prune takes 36 / 31 / 117 / 142 ns per body at N = 1,000 / 3,000 / 10,000 / 30,000 and the grid
/// 60 / 59 / 82 / 92, so the grid wins from somewhere between 3,000 and 10,000 bodies (and by 2.5x
/// at a million). Sweep and prune is nevertheless kept for every N up to 10,000, the largest scene
/// of the paper's study: its pair order is what the schedulers see at that scale, and the golden
/// determinism hash pins it.
pub const AUTO_GRID_MIN_BODIES: usize = 10_001;

/// The pair buffer is shrunk once it has been more than 4x larger than needed (plus
/// [`PAIR_SLACK`]) for this many consecutive updates (two seconds at 60 Hz): one pathological frame
/// costs its memory for a while, never forever, and a steady scene never reallocates.
pub const SHRINK_AFTER_FRAMES: u32 = 120;

/// Pairs of headroom the shrink rule always allows, so small scenes never reallocate.
pub const PAIR_SLACK: usize = 1024;

/// Candidates of one body tested at once by sweep and prune, and by the grid where the processor
/// has no AVX-512 (the grid's wider rounds are its own): four f64 lanes (two SSE2 registers).
const LANES: usize = 4;

/// Write body `p`'s pair with each of the [`LANES`] candidates `q` to `out`, kept (the cursor
/// advanced past it) for each bit j of `hits`, in lane order; returns how many were kept. Every
/// slot is written and the count advanced by its bit, so the (unpredictable) overlap outcome costs
/// no branch. `out` is the [`LANES`] slots from the cursor on.
#[inline(always)]
fn put_lanes(out: &mut [(u32, u32)], p: u32, q: [u32; LANES], hits: usize) -> usize {
    let out = &mut out[..LANES];
    let mut found = 0;
    for (j, q) in q.into_iter().enumerate() {
        // `found <= j < LANES`: the mask only spares the bounds check.
        out[found & (LANES - 1)] = (p.min(q), p.max(q));
        found += (hits >> j) & 1;
    }
    found
}

/// A block of the grid's cells (a column over a slab of the volume's depth): the unit of
/// broad-phase work a whole-frame budget sheds (see [`BroadPhase::update_in_order`]). Bodies whose cell is in the
/// region search it; the pairs they find may reach into a neighbouring region.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Region {
    /// Lowest corner of the region's cells.
    pub lo: Vec3,
    /// Highest corner.
    pub hi: Vec3,
}

/// What an update in order did.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct RegionPass {
    /// Regions searched this update.
    pub searched: u32,
    /// Regions not reached: their pairs are those of the last update that searched them.
    pub stale: u32,
    /// Pairs held by the stale regions.
    pub stale_pairs: u32,
}

/// Which broad-phase algorithm to run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BroadPhaseKind {
    /// Sweep and prune below [`AUTO_GRID_MIN_BODIES`] bodies, the grid from there on.
    #[default]
    Auto,
    /// Sweep and prune over y-z columns with temporal coherence (paper section 2, I-COLLIDE \[5\]).
    SweepAndPrune,
    /// Uniform grid keyed by the box size, counting-sorted every frame.
    Grid,
}

impl BroadPhaseKind {
    /// Every kind, `Auto` first.
    pub const ALL: [BroadPhaseKind; 3] = [Self::Auto, Self::SweepAndPrune, Self::Grid];

    /// Stable short name (CLI flags, CSV columns).
    pub fn name(self) -> &'static str {
        match self {
            Self::Auto => "auto",
            Self::SweepAndPrune => "sweep-and-prune",
            Self::Grid => "grid",
        }
    }

    /// Parse a [`Self::name`].
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|k| k.name() == s)
    }

    /// The concrete kind `self` stands for at `bodies` bodies (never `Auto`).
    pub fn resolve(self, bodies: usize) -> Self {
        match self {
            Self::Auto if bodies >= AUTO_GRID_MIN_BODIES => Self::Grid,
            Self::Auto => Self::SweepAndPrune,
            k => k,
        }
    }
}

/// Persistent broad-phase state: one of the [`BroadPhaseKind`]s.
#[derive(Debug, Clone)]
pub struct BroadPhase {
    inner: Inner,
}

#[derive(Debug, Clone)]
enum Inner {
    SweepAndPrune(Box<SweepAndPrune>),
    Grid(Box<Grid>),
}

impl BroadPhase {
    /// State for boxes of half-size `half` in the cubic volume [lo, lo + side]^3, of the kind
    /// [`BroadPhaseKind::Auto`] picks for `bodies`.
    pub fn new(half: f64, lo: Vec3, side: f64, bodies: usize) -> Self {
        Self::with_kind(BroadPhaseKind::Auto, half, lo, side, bodies)
    }

    /// State of the given kind (`Auto` resolved by `bodies`) for boxes of half-size `half` in the
    /// cubic volume [lo, lo + side]^3. Bodies outside the volume are still found: they are clamped
    /// into the edge cells.
    pub fn with_kind(kind: BroadPhaseKind, half: f64, lo: Vec3, side: f64, bodies: usize) -> Self {
        let inner = match kind.resolve(bodies) {
            BroadPhaseKind::Grid => Inner::Grid(Box::new(Grid::new(half, lo, side, bodies))),
            _ => Inner::SweepAndPrune(Box::new(SweepAndPrune::new(half, lo, side, bodies))),
        };
        Self { inner }
    }

    /// The algorithm in use (never `Auto`).
    pub fn kind(&self) -> BroadPhaseKind {
        match self.inner {
            Inner::SweepAndPrune(_) => BroadPhaseKind::SweepAndPrune,
            Inner::Grid(_) => BroadPhaseKind::Grid,
        }
    }

    /// Threads for the update (1 = the calling thread only; 0 is taken as 1). The output is
    /// identical, pair for pair and in the same order, for any count. The grid uses them for its
    /// sort and its pair search with at least 20,000 bodies per thread; sweep and prune for its
    /// sweep with at least 4,000.
    pub fn set_threads(&mut self, threads: usize) {
        match &mut self.inner {
            Inner::SweepAndPrune(s) => s.set_threads(threads),
            Inner::Grid(g) => g.set_threads(threads),
        }
    }

    /// Bring the state up to date with `positions` and regenerate the candidate pairs.
    ///
    /// # Panics
    /// If `positions` does not hold the number of bodies the state was built for.
    pub fn update(&mut self, positions: &[Vec3]) -> &[(u32, u32)] {
        let bodies = match &self.inner {
            Inner::SweepAndPrune(s) => s.bodies(),
            Inner::Grid(g) => g.bodies(),
        };
        assert_eq!(
            positions.len(),
            bodies,
            "body count changed under the broad phase"
        );
        match &mut self.inner {
            Inner::SweepAndPrune(s) => s.update(positions),
            Inner::Grid(g) => g.update(positions),
        }
        self.pairs()
    }

    /// The regions an update in order can shed: the grid's; none for sweep and prune, whose sorted
    /// lists are repaired as a whole.
    pub fn regions(&self) -> &[Region] {
        match &self.inner {
            Inner::SweepAndPrune(_) => &[],
            Inner::Grid(g) => g.regions(),
        }
    }

    /// Bring the state up to date with `positions`, then search for pairs region by region in
    /// `order` (indices into [`Self::regions`]) for as long as `go_on` allows it, given the pairs
    /// found so far: a whole-frame budget's broad phase, which spends its time where the viewer
    /// looks first. [`Self::pairs`] are then the searched regions' pairs, in that order; regions
    /// not reached keep the pairs they had when last searched and are reported as stale. Sweep
    /// and prune has no regions: it does a full [`Self::update`] and reports nothing stale.
    ///
    /// # Panics
    /// If `positions` does not hold the number of bodies the state was built for.
    pub fn update_in_order(
        &mut self,
        positions: &[Vec3],
        order: &[u32],
        go_on: &mut dyn FnMut(usize) -> bool,
    ) -> RegionPass {
        match &mut self.inner {
            Inner::SweepAndPrune(_) => {
                self.update(positions);
                RegionPass::default()
            }
            Inner::Grid(g) => {
                assert_eq!(
                    positions.len(),
                    g.bodies(),
                    "body count changed under the broad phase"
                );
                g.update_in_order(positions, order, go_on)
            }
        }
    }

    /// Pairs the first `k` regions searched by the last [`Self::update_in_order`] contributed
    /// (they come first in [`Self::pairs`]); every pair after a full update.
    pub fn region_pairs_before(&self, k: usize) -> usize {
        match &self.inner {
            Inner::Grid(g) if g.regions_live() => g.region_pairs_before(k),
            _ => self.pairs().len(),
        }
    }

    /// Every candidate pair of the current positions, whatever the last update shed (the grid
    /// searches its current sort again; for the audit). Sweep and prune always has them all.
    pub fn all_pairs(&self) -> Vec<(u32, u32)> {
        match &self.inner {
            Inner::SweepAndPrune(s) => s.pairs().to_vec(),
            Inner::Grid(g) => g.all_pairs(),
        }
    }

    /// Candidate pairs of the last update, each as (smaller id, larger id).
    pub fn pairs(&self) -> &[(u32, u32)] {
        match &self.inner {
            Inner::SweepAndPrune(s) => s.pairs(),
            Inner::Grid(g) => g.pairs(),
        }
    }

    /// Where each column's pairs lie in [`Self::pairs`]: sweep and prune's; None for the grid,
    /// whose regions serve the same purpose under a whole-frame budget.
    pub fn columns(&self) -> Option<&Columns> {
        match &self.inner {
            Inner::SweepAndPrune(s) => Some(s.columns()),
            Inner::Grid(_) => None,
        }
    }

    /// Whether [`Self::spatial_order`] has one (without building it).
    pub fn has_spatial_order(&self) -> bool {
        matches!(self.inner, Inner::Grid(_))
    }

    /// A spatial order of the bodies as of the last update, for keeping bodies that are near in
    /// space near in memory: the grid's cell order (see [`crate::Simulation`]'s renumbering).
    /// None for sweep and prune, whose per-column lists are not one order and whose persistent
    /// state is kept per body.
    pub fn spatial_order(&self) -> Option<Vec<u32>> {
        match &self.inner {
            Inner::SweepAndPrune(_) => None,
            Inner::Grid(g) => Some(g.cell_order()),
        }
    }

    /// Renumber the bodies (old id `i` becomes `new_of_old[i]`) in everything kept between
    /// updates. Only the grid can be renumbered ([`Self::spatial_order`] is `Some`).
    ///
    /// # Panics
    /// For sweep and prune, or if `new_of_old` does not hold one entry per body.
    pub fn renumber(&mut self, new_of_old: &[u32]) {
        match &mut self.inner {
            Inner::SweepAndPrune(_) => {
                panic!("sweep and prune keeps per-body state: not renumbered")
            }
            Inner::Grid(g) => {
                assert_eq!(new_of_old.len(), g.bodies(), "renumber: wrong body count");
                g.renumber(new_of_old);
            }
        }
    }

    /// Panic unless the state is consistent with `positions` (used by tests).
    pub fn assert_well_formed(&self, positions: &[Vec3]) {
        match &self.inner {
            Inner::SweepAndPrune(s) => s.assert_well_formed(positions),
            Inner::Grid(g) => g.assert_well_formed(positions),
        }
    }

    #[cfg(test)]
    fn partition_tiny_scenes(&mut self) {
        match &mut self.inner {
            Inner::SweepAndPrune(s) => s.partition_tiny_scenes(),
            Inner::Grid(g) => g.partition_tiny_scenes(),
        }
    }

    /// The grid's pair search in the baseline's rounds only, as on a processor without AVX-512.
    #[cfg(test)]
    fn baseline_rounds(&mut self) {
        if let Inner::Grid(g) = &mut self.inner {
            g.baseline_rounds();
        }
    }

    #[cfg(test)]
    fn pair_storage(&self) -> usize {
        match &self.inner {
            Inner::SweepAndPrune(s) => s.pair_storage(),
            Inner::Grid(g) => g.pair_storage(),
        }
    }
}

/// Runs of a sweep-and-prune column: its bodies against each other, and against each of its four
/// forward neighbours.
pub const RUNS: usize = 5;

/// Where the pairs of each sweep-and-prune column lie in the candidate list, down to each body.
///
/// The sweep lists the pairs column by column (`c = iz * per_axis + iy`); a column's pairs are
/// [`RUNS`] runs (the column against itself, then against each forward neighbour), and within a
/// run they come body by body of the column in order of x, each body's pairs together. So the
/// pairs whose swept body lies in an x-interval of a column are, in each run, one range of the
/// candidate list, whose ends are counted off the column's sorted x. A column is a rod along x
/// through one y-z cell, which the camera (looking down -z) sees as a horizontal band at one
/// depth: a gaze ordering finds the pairs near the fixation without reading the others (see
/// [`crate::schedule::rings`]). A by-product of the sweep, in its order; the pairs are unchanged.
///
/// A body outside the grid is swept in the edge column it clamps to, so it lies outside that
/// column's cell: the index still lists its pairs, a gaze ordering may just place them farther
/// from the fixation than they are (the engine keeps bodies in the volume).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Columns {
    /// Columns per axis (y and z).
    pub per_axis: usize,
    /// y and z of the grid's low corner.
    pub lo: [f64; 2],
    /// Column width in y and z. Bodies outside the grid are swept in the edge columns.
    pub cell: f64,
    /// Half the boxes' reach (their half-size): a pair's centre is within this of each of its
    /// bodies on every axis.
    pub half_reach: f64,
    /// Columns holding at least one body.
    pub nonempty: usize,
    /// `per_axis^2 + 1` entries: column `c`'s pairs are `start[c]..start[c + 1]`.
    pub start: Vec<u32>,
    /// `per_axis^2 + 1` entries: column `c`'s bodies are `bodies[c]..bodies[c + 1]` of `xs`.
    pub bodies: Vec<u32>,
    /// The swept bodies' x, column by column, ascending within a column.
    pub xs: Vec<f64>,
    /// Per column, per run, per body `k` of the column: where its pairs start in the candidate
    /// list (entry `k = m` is the run's end); see [`Self::run`].
    pub runs: Vec<u32>,
}

impl Columns {
    /// Read the index back into cache (see [`crate::warm`]).
    pub fn warm(&self) {
        crate::warm::lines(&self.start);
        crate::warm::lines(&self.bodies);
        crate::warm::lines(&self.xs);
        crate::warm::lines(&self.runs);
    }

    /// Column `c`'s pairs in the candidate list.
    #[inline]
    pub fn block(&self, c: usize) -> std::ops::Range<usize> {
        self.start[c] as usize..self.start[c + 1] as usize
    }

    /// Column `c`'s bodies' x, ascending.
    #[inline]
    pub fn xs(&self, c: usize) -> &[f64] {
        &self.xs[self.bodies[c] as usize..self.bodies[c + 1] as usize]
    }

    /// Run `r` of column `c`: `m + 1` offsets for its `m` bodies; the pairs of bodies `k0..k1`
    /// in this run are `run[k0]..run[k1]` of the candidate list.
    #[inline]
    pub fn run(&self, c: usize, r: usize) -> &[u32] {
        let m = (self.bodies[c + 1] - self.bodies[c]) as usize + 1;
        let base = RUNS * (self.bodies[c] as usize + c) + r * m;
        &self.runs[base..base + m]
    }

    /// Whether the index describes a candidate list of `pairs` pairs (the last update's).
    pub fn covers(&self, pairs: usize) -> bool {
        self.start.len() == self.len() + 1 && self.start.last() == Some(&(pairs as u32))
    }

    /// Number of columns.
    pub fn len(&self) -> usize {
        self.per_axis * self.per_axis
    }

    /// Whether there are no columns.
    pub fn is_empty(&self) -> bool {
        self.per_axis == 0
    }
}

/// Reused output storage: the first `len` entries are this frame's pairs. The storage is never
/// re-zeroed between frames, and it is shrunk by the rule of [`SHRINK_AFTER_FRAMES`].
#[derive(Debug, Clone, Default)]
struct PairBuffer {
    buf: Vec<(u32, u32)>,
    len: usize,
    /// Consecutive updates with the storage more than 4x larger than needed.
    oversized: u32,
}

impl PairBuffer {
    /// Storage to write a frame's pairs into from index 0; grow it with `resize`.
    fn storage(&mut self) -> &mut Vec<(u32, u32)> {
        &mut self.buf
    }

    /// The frame's pairs are the first `len` entries of the storage.
    fn set_len(&mut self, len: usize) {
        assert!(len <= self.buf.len(), "pair count beyond the storage");
        self.len = len;
    }

    /// Append pairs after the first `len`.
    fn append(&mut self, more: &[(u32, u32)]) {
        let end = self.len + more.len();
        if end > self.buf.len() {
            self.buf.resize(end, (0, 0));
        }
        self.buf[self.len..end].copy_from_slice(more);
        self.len = end;
    }

    /// `set_len` and `end_frame` in one.
    fn finish(&mut self, len: usize) {
        self.set_len(len);
        self.end_frame();
    }

    /// Apply the shrink rule to this frame's count.
    fn end_frame(&mut self) {
        if self.buf.capacity() > 4 * self.len + PAIR_SLACK {
            self.oversized += 1;
        } else {
            self.oversized = 0;
        }
        if self.oversized >= SHRINK_AFTER_FRAMES {
            self.buf.truncate(2 * self.len + PAIR_SLACK);
            self.buf.shrink_to_fit();
            self.oversized = 0;
        }
    }

    #[cfg(test)]
    fn capacity(&self) -> usize {
        self.buf.capacity()
    }

    fn as_slice(&self) -> &[(u32, u32)] {
        &self.buf[..self.len]
    }

    fn as_mut_slice(&mut self) -> &mut [(u32, u32)] {
        &mut self.buf[..self.len]
    }

    fn assert_well_formed(&self) {
        for &(a, b) in self.as_slice() {
            assert!(a < b, "pair ({a}, {b}) not as (smaller id, larger id)");
        }
    }
}

/// All overlapping box pairs by brute force, O(N^2): the reference the broad phase is tested against.
pub fn brute_force_pairs(positions: &[Vec3], half: f64) -> Vec<(u32, u32)> {
    let reach = 2.0 * half;
    let mut out = Vec::new();
    for i in 0..positions.len() {
        for j in i + 1..positions.len() {
            let d = (positions[j] - positions[i]).abs();
            if d.x <= reach && d.y <= reach && d.z <= reach {
                out.push((i as u32, j as u32));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::SceneConfig;
    use crate::world::World;
    use proptest::prelude::*;

    fn sorted(mut v: Vec<(u32, u32)>) -> Vec<(u32, u32)> {
        v.sort_unstable();
        v
    }

    /// Every concrete configuration: sweep and prune and the grid on 1 thread, the grid in the
    /// baseline's rounds (where the processor has AVX-512, the others take those), and each on
    /// 2 and 3 threads with its partitions forced even at tiny N.
    fn every_configuration(half: f64, lo: Vec3, side: f64, n: usize) -> Vec<BroadPhase> {
        let mut baseline = BroadPhase::with_kind(BroadPhaseKind::Grid, half, lo, side, n);
        baseline.baseline_rounds();
        let mut out = vec![
            BroadPhase::with_kind(BroadPhaseKind::SweepAndPrune, half, lo, side, n),
            BroadPhase::with_kind(BroadPhaseKind::Grid, half, lo, side, n),
            baseline,
        ];
        for kind in [BroadPhaseKind::SweepAndPrune, BroadPhaseKind::Grid] {
            for threads in [2, 3] {
                let mut bp = BroadPhase::with_kind(kind, half, lo, side, n);
                bp.set_threads(threads);
                bp.partition_tiny_scenes();
                out.push(bp);
            }
        }
        out
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]
        #[test]
        fn matches_brute_force_on_random_scenes_and_after_many_frames(
            n in 1u32..400, seed in any::<u64>(), radius in 0.05f64..0.6, frames in 0usize..120,
            fast in any::<bool>(), far in any::<bool>()
        ) {
            let mut cfg = SceneConfig::paper(n, seed);
            cfg.shape_radius = radius;
            if fast { cfg.max_speed = 8.0; }
            let mut w = World::generate(&cfg);
            let half = 1.11 * radius;
            // Far from the origin the cell arithmetic rounds: the grid must still be exact.
            let offset = if far { Vec3::new(1.0e6, -3.0e5, 7.5e4) } else { Vec3::ZERO };
            let mut bps = every_configuration(half, w.lo + offset, cfg.volume_side(), w.len());
            for f in 0..=frames {
                let positions: Vec<Vec3> = w.position.iter().map(|&p| p + offset).collect();
                let check = f % 30 == 0 || f == frames;
                let expected = if check { brute_force_pairs(&positions, half) } else { Vec::new() };
                // Per kind, the first configuration's pairs and index.
                type Output = (Vec<(u32, u32)>, Option<Columns>);
                let mut first_of: [Option<Output>; 2] = [None, None];
                for bp in &mut bps {
                    let got = bp.update(&positions).to_vec();
                    // Any thread count gives the 1-thread output, in the same order, and the
                    // same index.
                    let index = bp.columns().cloned();
                    match &first_of[usize::from(bp.kind() == BroadPhaseKind::Grid)] {
                        Some((pairs, cols)) => {
                            prop_assert_eq!(pairs, &got);
                            prop_assert_eq!(cols, &index);
                        }
                        None => {
                            first_of[usize::from(bp.kind() == BroadPhaseKind::Grid)] =
                                Some((got.clone(), index));
                        }
                    }
                    if check {
                        bp.assert_well_formed(&positions);
                        prop_assert_eq!(sorted(got), expected.clone(), "{:?}", bp.kind());
                    }
                }
                w.integrate(cfg.dt);
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(16))]
        #[test]
        fn sweep_and_prune_columns_locate_every_pair_by_its_swept_body(
            n in 1u32..600, seed in any::<u64>(), radius in 0.05f64..0.6, frames in 0usize..40,
        ) {
            let cfg = SceneConfig::paper(n, seed);
            let mut w = World::generate(&cfg);
            let half = 1.11 * radius;
            let mut bp = BroadPhase::with_kind(
                BroadPhaseKind::SweepAndPrune, half, w.lo, cfg.volume_side(), w.len());
            prop_assert!(BroadPhase::with_kind(
                BroadPhaseKind::Grid, half, w.lo, cfg.volume_side(), w.len()).columns().is_none());
            for _ in 0..=frames {
                let pairs = bp.update(&w.position).to_vec();
                let cols = bp.columns().expect("sweep and prune has columns");
                // The blocks tile the candidate list in column order, and each block is its
                // runs, back to back.
                let mut at = 0;
                for c in 0..cols.len() {
                    let block = cols.block(c);
                    prop_assert_eq!(block.start, at);
                    let xs = cols.xs(c);
                    prop_assert!(xs.windows(2).all(|p| p[0] <= p[1]));
                    for r in 0..RUNS {
                        let run = cols.run(c, r);
                        prop_assert_eq!(run.len(), xs.len() + 1);
                        prop_assert_eq!(run[0] as usize, at);
                        prop_assert!(run.windows(2).all(|p| p[0] <= p[1]));
                        // Body k's pairs in this run all hold a body at its x.
                        for (k, &x) in xs.iter().enumerate() {
                            for &(a, b) in &pairs[run[k] as usize..run[k + 1] as usize] {
                                let (xa, xb) = (w.position[a as usize].x, w.position[b as usize].x);
                                prop_assert!(xa == x || xb == x);
                            }
                        }
                        at = run[xs.len()] as usize;
                    }
                    prop_assert_eq!(block.end, at);
                }
                prop_assert_eq!(at, pairs.len());
                prop_assert_eq!(cols.xs.len(), w.len());
                w.integrate(cfg.dt);
            }
        }
    }

    #[test]
    fn touching_boxes_count_and_bodies_outside_the_grid_are_kept() {
        let lo = Vec3::ZERO;
        let positions = vec![
            Vec3::new(0.5, 0.5, 0.5),
            Vec3::new(0.9, 0.5, 0.5), // exactly 2h away on x: touching counts
            Vec3::new(-3.0, -3.0, -3.0),
            Vec3::new(-3.0, -2.7, -3.0),
            Vec3::new(9.0, 9.0, 9.0),
            Vec3::new(9.0, 8.7, 9.3),
        ];
        for mut bp in every_configuration(0.2, lo, 4.0, positions.len()) {
            let got = sorted(bp.update(&positions).to_vec());
            bp.assert_well_formed(&positions);
            assert_eq!(got, brute_force_pairs(&positions, 0.2), "{:?}", bp.kind());
            assert_eq!(got, vec![(0, 1), (2, 3), (4, 5)], "{:?}", bp.kind());
        }
    }

    /// Centres on a lattice of pitch exactly 2h, spanning many cells: every neighbour on the
    /// lattice touches, and many centres sit on (or a rounding away from) cell boundaries.
    #[test]
    fn lattice_at_exactly_touching_pitch_matches_brute_force() {
        for (half, origin) in [(0.25, 0.0), (0.222, 0.0), (0.1, 1.0e7), (0.3, -12.345)] {
            let pitch = 2.0 * half;
            let k = 9;
            let lo = Vec3::splat(origin);
            let positions: Vec<Vec3> = (0..k * k * k)
                .map(|i| {
                    let (a, b, c) = (i % k, i / k % k, i / (k * k));
                    lo + Vec3::new(a as f64, b as f64, c as f64) * pitch
                })
                .collect();
            let expected = brute_force_pairs(&positions, half);
            for side in [pitch * (k - 1) as f64, pitch * 3.5, pitch * k as f64] {
                for mut bp in every_configuration(half, lo, side, positions.len()) {
                    let got = sorted(bp.update(&positions).to_vec());
                    bp.assert_well_formed(&positions);
                    assert_eq!(got, expected, "{:?} half {half} side {side}", bp.kind());
                }
            }
        }
    }

    #[test]
    fn auto_is_sweep_and_prune_at_the_papers_n_and_the_grid_at_large_n() {
        let bp = BroadPhase::new(0.222, Vec3::ZERO, 10.0, 10_000);
        assert_eq!(bp.kind(), BroadPhaseKind::SweepAndPrune);
        let bp = BroadPhase::new(0.222, Vec3::ZERO, 10.0, AUTO_GRID_MIN_BODIES - 1);
        assert_eq!(bp.kind(), BroadPhaseKind::SweepAndPrune);
        let bp = BroadPhase::new(0.222, Vec3::ZERO, 10.0, AUTO_GRID_MIN_BODIES);
        assert_eq!(bp.kind(), BroadPhaseKind::Grid);
        for kind in [BroadPhaseKind::SweepAndPrune, BroadPhaseKind::Grid] {
            for n in [1, 300, 1_000_000] {
                assert_eq!(
                    BroadPhase::with_kind(kind, 0.2, Vec3::ZERO, 1.0, n).kind(),
                    kind
                );
            }
        }
    }

    #[test]
    fn kind_names_and_serde_round_trip() {
        for kind in BroadPhaseKind::ALL {
            assert_eq!(BroadPhaseKind::from_name(kind.name()), Some(kind));
            let json = serde_json::to_string(&kind).expect("serialise");
            assert_eq!(
                serde_json::from_str::<BroadPhaseKind>(&json).ok(),
                Some(kind)
            );
        }
        assert_eq!(
            serde_json::to_string(&BroadPhaseKind::SweepAndPrune)
                .ok()
                .as_deref(),
            Some("\"sweep_and_prune\"")
        );
        assert_eq!(BroadPhaseKind::default(), BroadPhaseKind::Auto);
        assert_eq!(BroadPhaseKind::from_name("octree"), None);
    }

    /// One frame with every body at one point needs N^2/2 pairs; the storage must come back down
    /// after [`SHRINK_AFTER_FRAMES`] ordinary frames, and not before.
    #[test]
    fn pair_storage_shrinks_after_a_pathological_frame() {
        let n = 400;
        let side = (n as f64 / 10.0).cbrt();
        let frames = scripted_frames(n, side, 1.0, 2);
        let clump = vec![Vec3::splat(side / 2.0); n];
        for kind in [BroadPhaseKind::SweepAndPrune, BroadPhaseKind::Grid] {
            let mut bp = BroadPhase::with_kind(kind, 0.222, Vec3::ZERO, side, n);
            assert_eq!(bp.update(&clump).len(), n * (n - 1) / 2);
            let grown = bp.pair_storage();
            assert!(grown >= n * (n - 1) / 2);
            for f in 0..SHRINK_AFTER_FRAMES as usize {
                assert_eq!(bp.pair_storage(), grown, "{kind:?} shrank early, frame {f}");
                let got = sorted(bp.update(&frames[f % 2]).to_vec());
                assert_eq!(got, brute_force_pairs(&frames[f % 2], 0.222));
            }
            let needed = bp.pairs().len();
            assert!(
                bp.pair_storage() <= 4 * needed + PAIR_SLACK,
                "{kind:?} kept {} for {needed} pairs",
                bp.pair_storage()
            );
        }
    }

    /// At a scale where the grid really runs on two threads: the same pairs as sweep and prune,
    /// and the same order on 1 and 2 threads and in the baseline's rounds, over frames of motion.
    #[test]
    fn grid_matches_sweep_and_prune_at_scale_on_one_and_two_threads() {
        let n = 50_000;
        let side = (n as f64 / 10.0).cbrt();
        let half = 1.11 * 0.2;
        let mut sap =
            BroadPhase::with_kind(BroadPhaseKind::SweepAndPrune, half, Vec3::ZERO, side, n);
        let mut one = BroadPhase::with_kind(BroadPhaseKind::Grid, half, Vec3::ZERO, side, n);
        let mut two = one.clone();
        two.set_threads(2);
        let mut baseline = one.clone();
        baseline.baseline_rounds();
        for pos in scripted_frames(n, side, 8.0, 3) {
            let expected = sorted(sap.update(&pos).to_vec());
            let got = one.update(&pos).to_vec();
            assert_eq!(two.update(&pos), &got[..]);
            assert_eq!(baseline.update(&pos), &got[..]);
            one.assert_well_formed(&pos);
            assert_eq!(sorted(got), expected);
        }
    }

    /// An update in order that reaches every region lists exactly the full update's pairs, on
    /// 1 and 2 threads; one that stops early lists a subset, counts the regions it left and the
    /// pairs they held when last searched; a full update forgets the regions' pairs.
    #[test]
    fn update_in_order_lists_the_regions_it_reaches() {
        let n = 30_000;
        let side = (n as f64 / 10.0).cbrt();
        let half = 1.11 * 0.2;
        let frames = scripted_frames(n, side, 8.0, 3);
        for threads in [1, 2] {
            let mut bp = BroadPhase::with_kind(BroadPhaseKind::Grid, half, Vec3::ZERO, side, n);
            bp.set_threads(threads);
            let mut full = bp.clone();
            let regions = bp.regions().len();
            assert!(regions >= 64, "{regions} regions");
            let order: Vec<u32> = (0..regions as u32).rev().collect();
            let pass = bp.update_in_order(&frames[0], &order, &mut |_| true);
            assert_eq!(
                (pass.searched as usize, pass.stale, pass.stale_pairs),
                (regions, 0, 0)
            );
            let expected = sorted(full.update(&frames[0]).to_vec());
            assert_eq!(sorted(bp.pairs().to_vec()), expected);
            assert_eq!(bp.region_pairs_before(regions), expected.len());
            // What each region held in frame 0, from its share of the list.
            let held: Vec<usize> = (0..regions)
                .map(|k| bp.region_pairs_before(k + 1) - bp.region_pairs_before(k))
                .collect();
            let stop = regions / 3;
            let mut seen = Vec::new();
            let pass = bp.update_in_order(&frames[1], &order, &mut |pairs| {
                seen.push(pairs);
                seen.len() <= stop
            });
            assert_eq!(pass.searched as usize, stop);
            assert_eq!(pass.stale as usize, regions - stop);
            assert_eq!(
                pass.stale_pairs as usize,
                held[stop..].iter().sum::<usize>()
            );
            // The pacing callback saw the running count before each region.
            assert_eq!(seen[0], 0);
            assert_eq!(seen[stop], bp.pairs().len());
            let all = sorted(full.update(&frames[1]).to_vec());
            assert_eq!(sorted(bp.all_pairs()), all);
            let got = sorted(bp.pairs().to_vec());
            assert!(got.len() < all.len() && !got.is_empty());
            assert!(got.iter().all(|p| all.binary_search(p).is_ok()));
            bp.update(&frames[2]);
            let pass = bp.update_in_order(&frames[2], &order, &mut |_| false);
            assert_eq!((pass.searched, pass.stale_pairs), (0, 0));
            assert!(bp.pairs().is_empty());
        }
        // Sweep and prune has no regions and always updates whole.
        let mut sap =
            BroadPhase::with_kind(BroadPhaseKind::SweepAndPrune, half, Vec3::ZERO, side, n);
        assert!(sap.regions().is_empty());
        let pass = sap.update_in_order(&frames[0], &[], &mut |_| false);
        assert_eq!(pass, RegionPass::default());
        assert_eq!(
            sorted(sap.pairs().to_vec()),
            sorted(grid_pairs(&frames[0], half, side))
        );
    }

    fn grid_pairs(pos: &[Vec3], half: f64, side: f64) -> Vec<(u32, u32)> {
        let mut g = BroadPhase::with_kind(BroadPhaseKind::Grid, half, Vec3::ZERO, side, pos.len());
        g.update(pos).to_vec()
    }

    /// Deterministic scene independent of the world generator: splitmix64 positions and
    /// velocities in [0, side)^3, moved with reflecting walls.
    fn scripted_frames(n: usize, side: f64, speed: f64, frames: usize) -> Vec<Vec<Vec3>> {
        let mut state = 0x9e37_79b9_7f4a_7c15u64 ^ n as u64;
        let mut next = move || {
            state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut pos: Vec<Vec3> = (0..n)
            .map(|_| Vec3::new(next(), next(), next()) * side)
            .collect();
        let mut vel: Vec<Vec3> = (0..n)
            .map(|_| (Vec3::new(next(), next(), next()) - 0.5) * (2.0 * speed / 60.0))
            .collect();
        let mut out = Vec::with_capacity(frames);
        for _ in 0..frames {
            out.push(pos.clone());
            for (p, v) in pos.iter_mut().zip(&mut vel) {
                *p += *v;
                for a in 0..3 {
                    if p[a] < 0.0 || p[a] > side {
                        v[a] = -v[a];
                        p[a] = p[a].clamp(0.0, side);
                    }
                }
            }
        }
        out
    }

    /// Hash of the sweep-and-prune output, in order, over scripted scenes; pinned from the
    /// algorithm as it was before the grid existed, so that the golden determinism hash (which
    /// sees the pair order through the schedulers) cannot drift.
    fn sap_order_hash() -> u64 {
        // FNV-1a over little-endian u64s, inline so the pin depends on nothing else.
        let mut h = 0xcbf2_9ce4_8422_2325u64;
        let mut mix = |v: u64| {
            for b in v.to_le_bytes() {
                h = (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3);
            }
        };
        for (n, speed, frames) in [
            (300usize, 1.0, 200usize),
            (2_000, 8.0, 60),
            (10_000, 1.0, 8),
        ] {
            let side = (n as f64 / 10.0).cbrt();
            let half = 1.11 * 0.2;
            let mut bp =
                BroadPhase::with_kind(BroadPhaseKind::SweepAndPrune, half, Vec3::ZERO, side, n);
            for pos in scripted_frames(n, side, speed, frames) {
                let pairs = bp.update(&pos);
                mix(pairs.len() as u64);
                for &(a, b) in pairs {
                    mix(u64::from(a) << 32 | u64::from(b));
                }
            }
        }
        h
    }

    #[test]
    fn sweep_and_prune_order_is_pinned() {
        let got = sap_order_hash();
        assert_eq!(got, SAP_ORDER_HASH, "SAP pair order changed: {got:#018x}");
    }

    const SAP_ORDER_HASH: u64 = 0xcd11_f0da_09be_98ef;
}
