//! Sweep and prune over y-z grid columns with insertion-sort repair (paper section 2, after
//! I-COLLIDE [5]).
//!
//! Every body's box is the cube of half-size `h` (the sphere tree's root radius) around its centre,
//! so two boxes overlap iff the centres are within `2h` on every axis. A single global sweep axis
//! does not scale to large uniform scenes: the slab of width 2h along one axis holds O(N^(2/3))
//! bodies, so the sweep would be O(N^(5/3)). We therefore keep one sorted endpoint list per *column*
//! of a y-z grid whose cells are at least `2h` wide, and sweep each column against itself and its
//! four forward neighbours. Each list is kept between frames and repaired by insertion sort, which
//! costs O(n + swaps) because bodies move a small fraction of a box per frame; bodies that change
//! column (about 2% per frame in the paper scene) are moved between lists and sorted in the same pass.
//! With fixed-size boxes a box's two endpoints keep their order, so one key (the centre) per box
//! stands for both endpoints.
//!
//! The order of the pairs this produces is part of the engine's determinism contract at the paper's
//! N (the schedulers see it), so this file's arithmetic and iteration order are pinned by a test.
//! On several threads the sweep (most of the update's time at N = 10,000) is split
//! into consecutive ranges of z-rows whose outputs are concatenated in order, so the pairs, their
//! order and the index are the same for any thread count; the key refresh and the insertion sorts
//! are split the same way, and only the few bodies that change column are moved on the calling
//! thread.

use super::{Columns, LANES, PairBuffer, RUNS, put_lanes};
use crate::math::Vec3;
use wide::{CmpGt, CmpLe, CmpLt, f64x4};

/// Most columns per grid axis: bounds memory for absurdly sparse configs (cells only ever get wider,
/// which is always correct).
const MAX_COLUMNS_PER_AXIS: usize = 2048;

/// Fewest bodies worth one thread of the sweep: it costs about 50 ns a body at the paper's
/// density and waking a sleeping thread of the pool up to tens of microseconds.
const MIN_BODIES_PER_THREAD: usize = 4_000;

#[derive(Debug, Clone, Copy)]
struct Entry {
    x: f64,
    y: f64,
    z: f64,
    id: u32,
}

/// Persistent sweep-and-prune state.
#[derive(Debug, Clone)]
pub(super) struct SweepAndPrune {
    reach: f64,
    grid_lo: [f64; 2],
    inv_cell: f64,
    n: usize,
    columns: Vec<Vec<Entry>>,
    body_column: Vec<u32>,
    /// Bodies that left their column this update, per part of the refresh, in column order.
    part_moved: Vec<Vec<u32>>,
    pairs: PairBuffer,
    /// Output of sweep parts 1.. when running on several threads.
    partition_pairs: Vec<PairBuffer>,
    threads: usize,
    /// Fewer bodies than this per thread and fewer threads are used (tests lower it).
    min_bodies_per_thread: usize,
    /// Where each column's pairs start in `pairs` (the sweep's own bookkeeping, kept for the
    /// gaze rings, see [`Columns`]).
    index: Columns,
}

impl SweepAndPrune {
    /// State for boxes of half-size `half` in the cubic volume [lo, lo + side]^3.
    pub(super) fn new(half: f64, lo: Vec3, side: f64, bodies: usize) -> Self {
        let reach = 2.0 * half;
        let by_size = (side / reach).floor().max(1.0) as usize;
        let by_count = ((4 * bodies + 1) as f64).sqrt().ceil() as usize;
        let n = by_size.min(by_count).clamp(1, MAX_COLUMNS_PER_AXIS);
        let cell = side / n as f64;
        Self {
            reach,
            grid_lo: [lo.y, lo.z],
            inv_cell: 1.0 / cell,
            n,
            columns: vec![Vec::new(); n * n],
            body_column: vec![u32::MAX; bodies],
            part_moved: Vec::new(),
            pairs: PairBuffer::default(),
            partition_pairs: Vec::new(),
            threads: 1,
            min_bodies_per_thread: MIN_BODIES_PER_THREAD,
            index: Columns {
                per_axis: n,
                lo: [lo.y, lo.z],
                cell,
                half_reach: half,
                nonempty: 0,
                start: vec![0; n * n + 1],
                bodies: vec![0; n * n + 1],
                xs: Vec::new(),
                runs: Vec::new(),
            },
        }
    }

    #[cfg(test)]
    pub(super) fn pair_storage(&self) -> usize {
        self.pairs.capacity()
    }

    pub(super) fn bodies(&self) -> usize {
        self.body_column.len()
    }

    pub(super) fn set_threads(&mut self, threads: usize) {
        self.threads = threads.max(1);
    }

    /// Split the sweep over the threads even for tiny scenes (so tests exercise the parts).
    #[cfg(test)]
    pub(super) fn partition_tiny_scenes(&mut self) {
        self.min_bodies_per_thread = 1;
    }

    /// The column arithmetic, copied out so that it can be used while the lists are borrowed.
    fn locator(&self) -> Locator {
        Locator {
            grid_lo: self.grid_lo,
            inv_cell: self.inv_cell,
            n: self.n,
        }
    }

    fn column_of(&self, p: Vec3) -> u32 {
        self.locator().column_of(p)
    }
}

/// Which column a centre is in.
#[derive(Debug, Clone, Copy)]
struct Locator {
    grid_lo: [f64; 2],
    inv_cell: f64,
    n: usize,
}

impl Locator {
    /// Column index of a centre; positions outside the grid clamp to the edge column, which keeps
    /// every overlapping pair within one column of each other because clamping is monotone.
    #[inline]
    fn column_of(&self, p: Vec3) -> u32 {
        let cy = (p.y - self.grid_lo[0]) * self.inv_cell;
        let cz = (p.z - self.grid_lo[1]) * self.inv_cell;
        let max = (self.n - 1) as f64;
        // Truncation of a value clamped to [0, n-1] is its floor, without a libm call; `as usize`
        // of NaN is 0 (positions are finite anyway).
        let (iy, iz) = (cy.clamp(0.0, max) as usize, cz.clamp(0.0, max) as usize);
        (iz * self.n + iy) as u32
    }
}

impl SweepAndPrune {
    /// Bring the sorted lists up to date with `positions` and regenerate the candidate pairs.
    ///
    /// The lists are refreshed and sorted in the sweep's parts (consecutive z-rows), then the
    /// bodies that changed column are moved on the calling thread, in column order, each
    /// inserted as the insertion sort would have placed it had it been appended to its new
    /// column before the sort: the lists, and so the pairs, are those of one part.
    pub(super) fn update(&mut self, positions: &[Vec3]) {
        let locate = self.locator();
        let parts = self.parts();
        let first_call = self.body_column.first() == Some(&u32::MAX);
        self.part_moved.resize_with(parts, Vec::new);
        self.part_moved.iter_mut().for_each(Vec::clear);
        let per_part = self.columns.len().div_ceil(parts).div_ceil(self.n) * self.n;
        let refresh = |c0: usize, columns: &mut [Vec<Entry>], moved: &mut Vec<u32>| {
            for (c, col) in (c0..).zip(columns.iter_mut()) {
                // Refresh keys in place; note bodies that left their column.
                let mut k = 0;
                while k < col.len() {
                    let id = col[k].id;
                    let p = positions[id as usize];
                    if locate.column_of(p) as usize != c {
                        col.swap_remove(k);
                        moved.push(id);
                        continue;
                    }
                    let e = &mut col[k];
                    (e.x, e.y, e.z) = (p.x, p.y, p.z);
                    k += 1;
                }
                insertion_sort(col);
            }
        };
        if parts == 1 {
            refresh(0, &mut self.columns, &mut self.part_moved[0]);
        } else {
            rayon::in_place_scope(|s| {
                let refresh = &refresh;
                let mut jobs = self
                    .columns
                    .chunks_mut(per_part)
                    .zip(self.part_moved.iter_mut())
                    .enumerate();
                let first = jobs.next();
                for (k, (columns, moved)) in jobs {
                    s.spawn(move |_| refresh(k * per_part, columns, moved));
                }
                if let Some((_, (columns, moved))) = first {
                    refresh(0, columns, moved);
                }
            });
        }
        // First call: every body is "moved" into its column.
        if first_call {
            self.part_moved.iter_mut().for_each(Vec::clear);
            self.part_moved[0].extend(0..positions.len() as u32);
        }
        for &id in self.part_moved[..parts].iter().flatten() {
            let p = positions[id as usize];
            let c = locate.column_of(p);
            self.body_column[id as usize] = c;
            let col = &mut self.columns[c as usize];
            col.push(Entry {
                x: p.x,
                y: p.y,
                z: p.z,
                id,
            });
            // The insertion sort's step for the appended entry.
            let mut j = col.len() - 1;
            let e = col[j];
            while j > 0 && col[j - 1].x > e.x {
                col[j] = col[j - 1];
                j -= 1;
            }
            col[j] = e;
        }
        self.sweep();
    }

    /// Candidate pairs of the last update, each as (smaller id, larger id).
    pub(super) fn pairs(&self) -> &[(u32, u32)] {
        self.pairs.as_slice()
    }

    /// Where each column's pairs lie in [`Self::pairs`].
    pub(super) fn columns(&self) -> &Columns {
        &self.index
    }

    /// Parts the sweep is split into this frame: one per thread, but at least
    /// `min_bodies_per_thread` bodies and one z-row of columns per part.
    fn parts(&self) -> usize {
        self.threads
            .min(self.body_column.len() / self.min_bodies_per_thread)
            .min(self.n)
            .max(1)
    }

    /// List the candidate pairs column by column, and the index of where they lie. With several
    /// parts, each sweeps a consecutive range of z-rows (about equal in bodies) into its own
    /// buffer and index slices, with offsets counted from its own first pair; the buffers are
    /// then concatenated in order and the offsets moved by the pairs before them, so the pairs,
    /// their order and the index are those of one part.
    fn sweep(&mut self) {
        let n = self.n;
        let cols = n * n;
        let reach = self.reach;
        let parts = self.parts();
        let index = &mut self.index;
        // Sized once per frame (a no-op when the body count is unchanged), then written in place.
        let bodies = self.body_column.len();
        index.xs.resize(bodies, 0.0);
        index.runs.resize(RUNS * (bodies + cols), 0);
        let mut at = 0;
        for (first, col) in index.bodies.iter_mut().zip(&self.columns) {
            *first = at;
            at += col.len() as u32;
        }
        index.bodies[cols] = at;
        index.nonempty = self.columns.iter().filter(|c| !c.is_empty()).count();
        // Part boundaries on z-rows, about equal in bodies.
        let mut rows = vec![0; parts + 1];
        for (k, row) in rows.iter_mut().enumerate().skip(1) {
            let want = (bodies * k / parts) as u32;
            let from = rows_floor(&index.bodies, n, want);
            *row = if k == parts { n } else { from };
        }
        // Each part's columns, and its slices of the index.
        let (mut start, mut xs, mut runs): (&mut [u32], &mut [f64], &mut [u32]) =
            (&mut index.start[..cols], &mut index.xs, &mut index.runs);
        let mut jobs = Vec::with_capacity(parts);
        for w in rows.windows(2) {
            let (c0, c1) = (w[0] * n, w[1] * n);
            let b = (index.bodies[c1] - index.bodies[c0]) as usize;
            let (s_here, s_rest) = std::mem::take(&mut start).split_at_mut(c1 - c0);
            let (x_here, x_rest) = std::mem::take(&mut xs).split_at_mut(b);
            let (r_here, r_rest) = std::mem::take(&mut runs).split_at_mut(RUNS * (b + c1 - c0));
            (start, xs, runs) = (s_rest, x_rest, r_rest);
            jobs.push((c0..c1, s_here, x_here, r_here));
        }
        self.partition_pairs
            .resize_with(parts.saturating_sub(1), PairBuffer::default);
        let columns = &self.columns;
        let sweep_part = |(range, start, xs, runs): Job<'_>, buf: &mut Vec<(u32, u32)>| {
            let mut sink = PairSink { buf, len: 0 };
            sweep_columns(columns, n, reach, range, start, xs, runs, &mut sink);
            sink.len
        };
        let mut jobs = jobs.into_iter();
        let first = jobs.next().expect("at least one part");
        let mut lens = vec![0; parts];
        if parts == 1 {
            lens[0] = sweep_part(first, self.pairs.storage());
        } else {
            let (head, tail) = lens.split_at_mut(1);
            let main = self.pairs.storage();
            rayon::in_place_scope(|s| {
                let sweep_part = &sweep_part;
                for ((job, buf), len) in jobs.zip(&mut self.partition_pairs).zip(tail.iter_mut()) {
                    s.spawn(move |_| *len = sweep_part(job, buf.storage()));
                }
                head[0] = sweep_part(first, main);
            });
        }
        // Concatenate, moving each later part's offsets by the pairs before it.
        self.pairs.set_len(lens[0]);
        let mut len = lens[0];
        for (k, w) in rows.windows(2).enumerate().skip(1) {
            let base = len as u32;
            let (c0, c1) = (w[0] * n, w[1] * n);
            for s in &mut index.start[c0..c1] {
                *s += base;
            }
            let r0 = RUNS * (index.bodies[c0] as usize + c0);
            let r1 = RUNS * (index.bodies[c1] as usize + c1);
            for r in &mut index.runs[r0..r1] {
                *r += base;
            }
            let part = &mut self.partition_pairs[k - 1];
            part.finish(lens[k]);
            self.pairs.append(part.as_slice());
            len += lens[k];
        }
        index.start[cols] = len as u32;
        self.pairs.end_frame();
    }

    /// Panic unless every body is in exactly the column its position maps to and every column is
    /// sorted (used by tests).
    pub(super) fn assert_well_formed(&self, positions: &[Vec3]) {
        let mut seen = vec![false; positions.len()];
        for (c, col) in self.columns.iter().enumerate() {
            for w in col.windows(2) {
                assert!(w[0].x <= w[1].x, "column {c} unsorted");
            }
            for e in col {
                assert!(!seen[e.id as usize], "body {} twice", e.id);
                seen[e.id as usize] = true;
                assert_eq!(
                    self.column_of(positions[e.id as usize]) as usize,
                    c,
                    "body {} in wrong column",
                    e.id
                );
            }
        }
        assert!(
            seen.iter().all(|&s| s),
            "a body is missing from the columns"
        );
        self.pairs.assert_well_formed();
    }
}

/// Stable insertion sort on x: O(n + inversions), and the lists are nearly sorted frame to frame.
fn insertion_sort(v: &mut [Entry]) {
    for i in 1..v.len() {
        let e = v[i];
        let mut j = i;
        while j > 0 && v[j - 1].x > e.x {
            v[j] = v[j - 1];
            j -= 1;
        }
        v[j] = e;
    }
}

/// One part of the sweep: its columns, and its slices of the index's `start`, `xs` and `runs`.
type Job<'a> = (
    std::ops::Range<usize>,
    &'a mut [u32],
    &'a mut [f64],
    &'a mut [u32],
);

/// The first z-row whose first body is at least `want` (rows of `n` columns; `first_body` as
/// [`Columns::bodies`]), or `n`.
fn rows_floor(first_body: &[u32], n: usize, want: u32) -> usize {
    (0..n).find(|&iz| first_body[iz * n] >= want).unwrap_or(n)
}

/// Sweep columns `range` (whole z-rows) into `out`, writing their entries of the index with
/// offsets counted from `out`'s start: `start` and the runs' offsets per column, the bodies' x.
#[allow(clippy::too_many_arguments)]
fn sweep_columns(
    columns: &[Vec<Entry>],
    n: usize,
    reach: f64,
    range: std::ops::Range<usize>,
    start: &mut [u32],
    xs: &mut [f64],
    runs: &mut [u32],
    out: &mut PairSink<'_>,
) {
    let (mut xs_at, mut runs_at) = (0, 0);
    let c0 = range.start;
    for c in range {
        let (iy, iz) = (c % n, c / n);
        let a = &columns[c];
        start[c - c0] = out.len as u32;
        for (x, e) in xs[xs_at..xs_at + a.len()].iter_mut().zip(a) {
            *x = e.x;
        }
        xs_at += a.len();
        // Where each body's pairs start in each of the column's runs (see `Columns`).
        let m = a.len() + 1;
        let runs = &mut runs[runs_at..runs_at + RUNS * m];
        runs_at += RUNS * m;
        let (own, neighbours) = runs.split_at_mut(m);
        sweep_self(a, reach, out, own);
        // Forward neighbours: each unordered column pair is visited once.
        for ((dy, dz), offsets) in [(1i64, 0i64), (-1, 1), (0, 1), (1, 1)]
            .into_iter()
            .zip(neighbours.chunks_exact_mut(m))
        {
            let (jy, jz) = (iy as i64 + dy, iz as i64 + dz);
            if jy < 0 || jz < 0 || jy >= n as i64 || jz >= n as i64 {
                offsets.fill(out.len as u32);
                continue;
            }
            let b = &columns[jz as usize * n + jy as usize];
            sweep_pair(a, b, reach, out, offsets);
        }
    }
}

/// Output buffer that appends without a branch on the (unpredictable) overlap outcome: the pair is
/// always written and the cursor advanced only on overlap.
struct PairSink<'a> {
    buf: &'a mut Vec<(u32, u32)>,
    len: usize,
}

impl PairSink<'_> {
    #[inline]
    fn offer(&mut self, p: &Entry, q: &Entry, reach: f64) {
        if self.len == self.buf.len() {
            self.buf.resize(self.len * 2 + 64, (0, 0));
        }
        let hit = ((q.y - p.y).abs() <= reach) & ((q.z - p.z).abs() <= reach);
        self.buf[self.len] = (p.id.min(q.id), p.id.max(q.id));
        self.len += usize::from(hit);
    }

    /// The pairs of `p` with `q[j]` for every bit j of `hits`, in lane order.
    #[inline]
    fn offer_lanes(&mut self, p: &Entry, q: &[Entry], hits: u32) {
        if self.len + LANES > self.buf.len() {
            self.buf.resize(self.len * 2 + 64, (0, 0));
        }
        let ids = [q[0].id, q[1].id, q[2].id, q[3].id];
        let out = &mut self.buf[self.len..self.len + LANES];
        self.len += put_lanes(out, p.id, ids, hits as usize);
    }
}

/// The candidates `b[k..]` of `p`, in order, up to the first whose x is more than `reach` past
/// `p`'s: the scalar loop `for q in &b[k..] { if q.x - p.x > reach { break } offer }`, run
/// [`LANES`] candidates a round. Within a round no branch depends on a candidate: the lanes
/// before the first one past `reach` are offered, masked, and the round ends the run iff some
/// lane was past `reach`; most runs hold fewer than four candidates, so the one branch a run
/// costs (its end) is what the scalar loop paid per candidate. The arithmetic is the scalar
/// loop's, lane by lane, so the pairs and their order are the same.
#[inline]
fn sweep_run(p: &Entry, b: &[Entry], mut k: usize, reach: f64, out: &mut PairSink<'_>) {
    let (px, r) = (f64x4::splat(p.x), f64x4::splat(reach));
    let (py, pz) = (f64x4::splat(p.y), f64x4::splat(p.z));
    while let Some(q) = b.get(k..k + LANES) {
        let lane = |f: fn(&Entry) -> f64| f64x4::from([f(&q[0]), f(&q[1]), f(&q[2]), f(&q[3])]);
        let past = (lane(|e| e.x) - px).cmp_gt(r).move_mask() as u32;
        let near = ((lane(|e| e.y) - py).abs().cmp_le(r) & (lane(|e| e.z) - pz).abs().cmp_le(r))
            .move_mask() as u32;
        // Lanes before the first one past `reach` (all four when none is).
        let stop = (past | 1 << LANES).trailing_zeros();
        out.offer_lanes(p, q, near & ((1 << stop) - 1));
        if stop < LANES as u32 {
            return;
        }
        k += LANES;
    }
    for q in &b[k.min(b.len())..] {
        if q.x - p.x > reach {
            break;
        }
        out.offer(p, q, reach);
    }
}

/// The first index from `k` on whose x is not below `limit` (or `b.len()`): the scalar loop
/// `while k < b.len() && b[k].x < limit { k += 1 }`, [`LANES`] entries a round. The entries
/// below `limit` are a prefix of the round's lanes (the column is sorted on x; counted as the
/// lanes before the first that is not, as the scalar loop stops), so a round costs no branch per
/// entry, and most bodies' starts move by fewer than four.
#[inline]
fn skip_below(b: &[Entry], mut k: usize, limit: f64) -> usize {
    let limit4 = f64x4::splat(limit);
    while let Some(q) = b.get(k..k + LANES) {
        let below = f64x4::from([q[0].x, q[1].x, q[2].x, q[3].x])
            .cmp_lt(limit4)
            .move_mask() as u32;
        let stop = (!below).trailing_zeros().min(LANES as u32);
        k += stop as usize;
        if stop < LANES as u32 {
            return k;
        }
    }
    while k < b.len() && b[k].x < limit {
        k += 1;
    }
    k
}

/// `offsets[k]`: where body `k`'s pairs start in `out` (the last entry: the run's end).
fn sweep_self(a: &[Entry], reach: f64, out: &mut PairSink<'_>, offsets: &mut [u32]) {
    for (i, p) in a.iter().enumerate() {
        offsets[i] = out.len as u32;
        sweep_run(p, a, i + 1, reach, out);
    }
    offsets[a.len()] = out.len as u32;
}

/// `offsets` as for [`sweep_self`], for `a`'s bodies.
fn sweep_pair(a: &[Entry], b: &[Entry], reach: f64, out: &mut PairSink<'_>, offsets: &mut [u32]) {
    let mut start = 0;
    for (k, p) in a.iter().enumerate() {
        offsets[k] = out.len as u32;
        start = skip_below(b, start, p.x - reach);
        sweep_run(p, b, start, reach, out);
    }
    offsets[a.len()] = out.len as u32;
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A column of entries sorted on x (ties and equal coordinates included: coordinates are
    /// drawn from a coarse lattice), and a body to sweep.
    fn column_and_body() -> impl Strategy<Value = (Vec<Entry>, Entry, f64)> {
        let entry = || {
            (0i32..40, 0i32..8, 0i32..8).prop_map(|(x, y, z)| Entry {
                x: f64::from(x) * 0.25,
                y: f64::from(y) * 0.25,
                z: f64::from(z) * 0.25,
                id: 0,
            })
        };
        (proptest::collection::vec(entry(), 0..40), entry(), 0i32..12).prop_map(|(mut b, p, r)| {
            b.sort_by(|u, v| u.x.total_cmp(&v.x));
            for (k, e) in b.iter_mut().enumerate() {
                e.id = k as u32 + 1;
            }
            (b, p, f64::from(r) * 0.25)
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]
        /// The four-lane rounds list the pairs the one-entry-at-a-time loops they replace list,
        /// in the same order, from every start, at every run length (ties on the reach
        /// included).
        #[test]
        fn four_lane_rounds_match_the_scalar_loops((b, p, reach) in column_and_body()) {
            for k in 0..=b.len() {
                let (mut fast, mut slow) = (Vec::new(), Vec::new());
                let mut out = PairSink { buf: &mut fast, len: 0 };
                sweep_run(&p, &b, k, reach, &mut out);
                let got = out.len;
                let mut out = PairSink { buf: &mut slow, len: 0 };
                for q in &b[k..] {
                    if q.x - p.x > reach {
                        break;
                    }
                    out.offer(&p, q, reach);
                }
                let want = out.len;
                prop_assert_eq!(&fast[..got], &slow[..want]);

                let limit = p.x - reach;
                let mut j = k;
                while j < b.len() && b[j].x < limit {
                    j += 1;
                }
                prop_assert_eq!(skip_below(&b, k, limit), j);
            }
        }
    }
}
