//! Uniform grid over fixed-size boxes, rebuilt by a two-level counting sort every frame.
//!
//! Every box is the cube of half-size `h` around its body's centre (paper section 2), so two boxes
//! overlap iff the centres are within `reach = 2h` on every axis. Cells are at least `reach` wide
//! in y and z and at least `reach / 2` wide in x, so an overlapping pair lies in adjacent rows
//! (y, z within one cell) and within two cells in x.
//!
//! Why a grid at large N: sweep and prune keeps its sorted lists between frames (I-COLLIDE [5]),
//! which is the right trade at the paper's N, but at a million bodies those lists are scattered
//! through memory and their repair is dominated by cache misses. Here every pass is a forward scan
//! over flat arrays:
//! - the sort is a radix sort in two levels: bodies are read in id order (their cells computed
//!   four at a time where the processor has AVX2) and their ids and cells dealt into a few
//!   hundred contiguous *buckets* of cells at most (sized by the last frame's counts, so in one
//!   pass), then each bucket, small enough to stay in cache, is counting-sorted by cell, and its
//!   bodies' centres copied into place from the positions, read nearly in order as the bodies
//!   are renumbered in the cell order at large N;
//! - the y-rows of a z-plane are taken in pairs, and a pair's cells are numbered x-cell by x-cell,
//!   the two rows' cells of an x-cell side by side; so the x-cells `ix - 2 ..= ix + 2` of a pair
//!   of rows are one contiguous slice. A body's candidates are four such slices (see
//!   [`Rows::span`]), where rows taken one by one would need five, each scanned a round of slots
//!   at a time in vector registers (the sorted bodies are kept one array a coordinate for this)
//!   and without a branch on the (unpredictable) overlap outcome. A slice holds about 4.4 bodies
//!   at the paper's density (the body's own, about half that), so with eight slots a round most
//!   take one round; where the processor has AVX-512, the body's own pair and the pair above
//!   (empty in the lower row) share one round when they fit in it together, so most bodies take
//!   three rounds, not four;
//! - a round is eight slots where the processor has AVX-512 (chosen at run time): a round's tests
//!   leave a bit mask and one instruction packs the pairs it keeps, about 38 instructions a round
//!   (a shared round adds a load and an expand for each of its four arrays).
//!   On any other x86-64 processor a round is four slots in SSE2, about 75 instructions. Both give
//!   the same pairs in the same order;
//! - half-width x cells cut the candidates a body is tested against by about a sixth, compared with
//!   cubic cells, for one more entry per cell in the cell index.
//!
//! Memory is fixed by N: about 41 bytes per body (its id and cell dealt into its bucket, with a
//! sixteenth of room to spare, 8 bytes; the body sorted, one array a field, 32), 4 bytes per cell
//! (about 2.2 cells per body at the paper's density, at most 4 plus a constant), and the pair
//! buffer, which shrinks after a pathological frame (see [`super::SHRINK_AFTER_FRAMES`]).
//!
//! The output depends only on this frame's positions: bodies are ordered by cell, then by id, and
//! pairs are listed body by body in that order. It does not depend on how many threads produce it:
//! with several, the first sorting level splits the bodies into consecutive id ranges, the second
//! the buckets into consecutive runs, and the pair search the z-planes, each part writing its own
//! output, concatenated in order; every body lands in the same slot and every pair in the same
//! place as on one thread.
//!
//! Positions outside the volume are clamped into the edge cells, which keeps every overlapping pair
//! within the neighbourhood above because clamping is monotone.

use std::fmt;
use std::ops::Range;

use super::{LANES, PairBuffer, Region, RegionPass, put_lanes};
use crate::math::Vec3;
use crate::prefetch::Prefetcher;
use crate::simd::widest;
#[cfg(target_arch = "x86_64")]
use pulp::x86::{V3, V4};
use wide::{CmpLe, f64x4};

/// Cells are made wider than their minimum by this factor, so that the rounding of the cell
/// arithmetic (relative error ~1e-13 at any grid size allowed here, also far from the origin) can
/// never put two centres `reach` apart further apart in cells than the neighbourhood searched.
const CELL_MARGIN: f64 = 1.0 + 1.0 / (1u64 << 20) as f64;

/// x cells per y-z cell width: candidates come from x-cells `ix - X_SPLIT ..= ix + X_SPLIT`.
const X_SPLIT: usize = 2;

/// At most this many cells per body (plus a constant): bounds memory for sparse scenes; cells only
/// ever get wider, which is always correct.
const MAX_CELLS_PER_BODY: usize = 4;

/// Cells per bucket of the first sorting level, a power of two at most `2^MAX_BUCKET_SHIFT`, chosen
/// for at most `TARGET_BUCKETS` buckets: fewer output streams for the first level against smaller
/// buckets for the second. At N = 1,000,000 that is 275 buckets of about 3,600 bodies, whose
/// second level counts and scatters in cache even when the bodies have drifted from the cell
/// order they were numbered in: in a simulation (bodies renumbered at creation, measured 60-80
/// frames later, when the buckets still held the bodies' centres) the sort took 16 ms against
/// 20 ms with 18 buckets, though 18 were 7% faster for bodies in random order.
const MAX_BUCKET_SHIFT: u32 = 24;
const TARGET_BUCKETS: usize = 512;

/// The regions a frame budget sheds tile the screen-facing x-y plane in at most this many columns
/// and rows, and the depth in at most [`REGION_SLABS`] slabs: few enough that ordering them costs
/// tens of microseconds.
const REGION_TILES: usize = 16;

/// Slabs of the depth (z) per region column. A column through the whole depth projects, under
/// perspective, onto a wedge from its near end's screen position towards the screen centre, so
/// with whole columns 112 of 256 regions could hold a pair within 5 degrees of a central
/// fixation; cut into slabs, only the slabs the fovea's cone passes through do.
const REGION_SLABS: usize = 4;

/// Room a bucket's segment keeps for bodies beyond its last count (see [`Grid::sort`]): a
/// sixteenth more, and at least this many: a few frames' drift across the buckets' edges.
const SEGMENT_SLACK_DIVISOR: u32 = 16;
const SEGMENT_SLACK_MIN: u32 = 16;

/// Slots past the last body in each of [`Sorted`]'s arrays: the widest round's.
const PAD: usize = 8;

/// Fewest bodies worth handing to one thread: waking a sleeping thread of the pool costs tens of
/// microseconds, about the grid's time for this many bodies.
const MIN_BODIES_PER_THREAD: usize = 20_000;

/// One body dealt into its bucket: its id and cell (8 bytes). Not its centre: the second level
/// reads that from the positions once the bucket is sorted, which writes and reads 24 bytes
/// less of a body that has left the cache between the two levels.
#[derive(Debug, Clone, Copy, Default)]
struct Slot {
    id: u32,
    cell: u32,
}

/// The bodies in cell order, one array a field, so that the pair search loads a window's
/// candidates a round at a time into vector registers; each array has [`PAD`] slots of padding
/// past the last body, so a window's last load never runs off the end.
#[derive(Debug, Clone)]
struct Sorted {
    x: Vec<f64>,
    y: Vec<f64>,
    z: Vec<f64>,
    id: Vec<u32>,
    cell: Vec<u32>,
}

impl Sorted {
    fn new(bodies: usize) -> Self {
        let n = bodies + PAD;
        Self {
            x: vec![0.0; n],
            y: vec![0.0; n],
            z: vec![0.0; n],
            id: vec![0; n],
            cell: vec![0; n],
        }
    }

    fn view(&self) -> SortedRef<'_> {
        SortedRef {
            x: &self.x,
            y: &self.y,
            z: &self.z,
            id: &self.id,
            cell: &self.cell,
        }
    }

    fn view_mut(&mut self) -> SortedMut<'_> {
        SortedMut {
            x: &mut self.x,
            y: &mut self.y,
            z: &mut self.z,
            id: &mut self.id,
            cell: &mut self.cell,
        }
    }
}

/// Read-only [`Sorted`], shared by the partitions of the pair search.
#[derive(Clone, Copy)]
struct SortedRef<'a> {
    x: &'a [f64],
    y: &'a [f64],
    z: &'a [f64],
    id: &'a [u32],
    cell: &'a [u32],
}

/// A run of [`Sorted`]'s slots, written by one part of the sort.
struct SortedMut<'a> {
    x: &'a mut [f64],
    y: &'a mut [f64],
    z: &'a mut [f64],
    id: &'a mut [u32],
    cell: &'a mut [u32],
}

impl<'a> SortedMut<'a> {
    /// The first `k` slots, and the rest.
    fn split_at(self, k: usize) -> (Self, Self) {
        let (x, x1) = self.x.split_at_mut(k);
        let (y, y1) = self.y.split_at_mut(k);
        let (z, z1) = self.z.split_at_mut(k);
        let (id, id1) = self.id.split_at_mut(k);
        let (cell, cell1) = self.cell.split_at_mut(k);
        (
            Self { x, y, z, id, cell },
            Self {
                x: x1,
                y: y1,
                z: z1,
                id: id1,
                cell: cell1,
            },
        )
    }
}

/// Cell arithmetic, copied out of the grid so that it can be used while the buffers are borrowed.
#[derive(Debug, Clone, Copy)]
struct Dims {
    lo: Vec3,
    /// Cells per unit length in y and z, and in x.
    inv_cell: f64,
    inv_cell_x: f64,
    /// Cells per axis in y and z, and in x (`X_SPLIT * n`).
    n: usize,
    nx: usize,
    /// The last cell's index in y and z, and in x, as f64: converted once, not per body (a
    /// 64-bit unsigned conversion is a long sequence in the baseline's instructions).
    top: f64,
    top_x: f64,
}

impl Dims {
    /// Cell of a centre: numbered by z-plane, then pair of y-rows, then x-cell, then which row
    /// of the pair; positions outside the volume clamp to the edge cells.
    #[inline]
    fn cell_of(&self, p: Vec3) -> u32 {
        let d = p - self.lo;
        // Truncation of a value clamped to [0, n-1] is its floor; NaN clamps to 0 (`max`
        // returns the other operand). `max` then `min` rather than `clamp`, which checks its
        // bounds' order on every call. Through u32 rather than straight to usize: the 64-bit
        // unsigned conversion is a longer sequence on x86-64, and this runs for every body every
        // frame (the sort about 9% faster).
        let (top, top_x) = (self.top, self.top_x);
        let ix = (d.x * self.inv_cell_x).max(0.0).min(top_x) as u32 as usize;
        let iy = (d.y * self.inv_cell).max(0.0).min(top) as u32 as usize;
        let iz = (d.z * self.inv_cell).max(0.0).min(top) as u32 as usize;
        (((iz * self.row_pairs() + iy / 2) * self.nx + ix) * 2 + iy % 2) as u32
    }

    /// Pairs of y-rows in a z-plane (with an odd count of rows, the last pair's upper row has no
    /// cell inside the volume and stays empty).
    fn row_pairs(&self) -> usize {
        self.n.div_ceil(2)
    }

    /// Cells in a pair of rows.
    fn pair_cells(&self) -> usize {
        2 * self.nx
    }

    /// Cells in a z-plane.
    fn plane_cells(&self) -> usize {
        self.row_pairs() * self.pair_cells()
    }

    fn cells(&self) -> usize {
        self.n * self.plane_cells()
    }
}

/// How the first sorting level computes the cells of four centres at once.
trait Cells4: Copy {
    /// [`Dims::cell_of`] of each of `p`.
    fn cells(self, dims: &Dims, p: &[Vec3; 4]) -> [u32; 4];
}

/// One centre at a time.
#[derive(Clone, Copy)]
struct Scalar;

impl Cells4 for Scalar {
    #[inline(always)]
    fn cells(self, dims: &Dims, p: &[Vec3; 4]) -> [u32; 4] {
        p.map(|p| dims.cell_of(p))
    }
}

/// Four centres at a time in AVX2, by the same operations in the same order as
/// [`Dims::cell_of`], so to the same cells (NaN and infinities included): the scalar version's
/// three clamped conversions and index arithmetic are a chain of some fifty instructions a body,
/// which took the deal 9.8 ms at a million bodies against 5.6 ms with the cells given. Used only
/// where the processor has AVX2 ([`V3::try_new`]).
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy)]
struct Avx2(V3);

#[cfg(target_arch = "x86_64")]
impl Cells4 for Avx2 {
    #[inline(always)]
    fn cells(self, dims: &Dims, p: &[Vec3; 4]) -> [u32; 4] {
        let Self(simd) = self;
        let (sse2, sse41) = (simd.sse2, simd.sse4_1);
        let lo = dims.lo;
        let ix = axis4(simd, p.map(|p| p.x), lo.x, dims.inv_cell_x, dims.top_x);
        let iy = axis4(simd, p.map(|p| p.y), lo.y, dims.inv_cell, dims.top);
        let iz = axis4(simd, p.map(|p| p.z), lo.z, dims.inv_cell, dims.top);
        // (((iz * row_pairs + iy / 2) * nx + ix) * 2 + iy % 2), in 32-bit lanes: the scalar
        // version's usize arithmetic cut to u32 gives the same bits (products, sums and shifts
        // left commute with the cut), and the cell indices fit anyway.
        let splat = |v: usize| sse2._mm_set1_epi32(v as u32 as i32);
        let plane = sse41._mm_mullo_epi32(iz, splat(dims.row_pairs()));
        let pair = sse2._mm_add_epi32(plane, sse2._mm_srli_epi32::<1>(iy));
        let at = sse2._mm_add_epi32(sse41._mm_mullo_epi32(pair, splat(dims.nx)), ix);
        let upper = sse2._mm_and_si128(iy, splat(1));
        pulp::cast(sse2._mm_add_epi32(sse2._mm_slli_epi32::<1>(at), upper))
    }
}

/// One axis of [`Avx2::cells`]: `((v - lo) * inv).max(0).min(top)`, truncated, in four lanes
/// (`max` with zero second returns zero for NaN, as `f64::max` does).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn axis4(simd: V3, v: [f64; 4], lo: f64, inv: f64, top: f64) -> std::arch::x86_64::__m128i {
    let avx = simd.avx;
    let v: std::arch::x86_64::__m256d = pulp::cast(v);
    let d = avx._mm256_mul_pd(
        avx._mm256_sub_pd(v, avx._mm256_set1_pd(lo)),
        avx._mm256_set1_pd(inv),
    );
    let clamped = avx._mm256_min_pd(
        avx._mm256_max_pd(d, avx._mm256_setzero_pd()),
        avx._mm256_set1_pd(top),
    );
    avx._mm256_cvttpd_epi32(clamped)
}

/// One part's share of the first sorting level ([`Grid::deal`]).
#[derive(Clone, Copy)]
struct Dealer {
    dims: Dims,
    shift: u32,
    /// Id of the part's first body.
    first: usize,
}

impl Dealer {
    /// Deal `chunk` into the part's segments `out` of each bucket, counting each bucket's
    /// bodies into `counts`; a body past its segment's room is only counted.
    #[inline(always)]
    fn deal<C: Cells4>(
        self,
        cells: C,
        chunk: &[Vec3],
        out: &mut [&mut [Slot]],
        counts: &mut [u32],
    ) {
        let (quads, rest) = chunk.as_chunks::<4>();
        for (q, quad) in quads.iter().enumerate() {
            for (j, cell) in cells.cells(&self.dims, quad).into_iter().enumerate() {
                self.put(4 * q + j, cell, out, counts);
            }
        }
        let done = 4 * quads.len();
        for (k, &p) in rest.iter().enumerate() {
            self.put(done + k, self.dims.cell_of(p), out, counts);
        }
    }

    #[inline(always)]
    fn put(self, k: usize, cell: u32, out: &mut [&mut [Slot]], counts: &mut [u32]) {
        let b = (cell >> self.shift) as usize;
        let dealt = counts[b];
        // Past a segment's room the body is only counted: the caller deals again.
        if let Some(slot) = out[b].get_mut(dealt as usize) {
            *slot = Slot {
                id: (self.first + k) as u32,
                cell,
            };
        }
        counts[b] = dealt + 1;
    }
}

/// Persistent uniform-grid state.
#[derive(Clone)]
pub(super) struct Grid {
    reach: f64,
    dims: Dims,
    bodies: usize,
    /// First-level buckets hold `2^bucket_shift` consecutive cells each.
    bucket_shift: u32,
    /// `bucket_start[b]..bucket_start[b + 1]` are bucket b's slots in `sorted`.
    bucket_start: Vec<u32>,
    /// Slots of each part's segment of each bucket in `staged` (`parts` rows of `buckets`).
    segment_room: Vec<u32>,
    /// Where each segment starts in `staged`, bucket by bucket, part by part within a bucket.
    segment_start: Vec<u32>,
    /// Passes the last sort's first level took over the bodies (1, or 2 after an overflow).
    deal_passes: u8,
    /// Bodies dealt into buckets: each part's segment of a bucket in id order (see `deal`).
    staged: Vec<Slot>,
    /// Bodies sorted by cell, then id.
    sorted: Sorted,
    /// `start[c]..start[c + 1]` are cell c's slots; past the last cell, one pair of rows of empty
    /// cells stands in for the rows beyond the volume's faces.
    start: Vec<u32>,
    /// Per-part bucket counts of the first level (`parts` rows of `buckets`).
    part_counts: Vec<u32>,
    /// Per-part per-cell counters of the bucket being sorted.
    cursors: Vec<Vec<u32>>,
    threads: usize,
    /// The pair search may take AVX-512 rounds (tests turn them off to compare).
    wide_rounds: bool,
    /// Fewer bodies than this per thread and fewer threads are used (tests lower it).
    min_bodies_per_thread: usize,
    pairs: PairBuffer,
    /// Output of partitions 1.. when running on several threads.
    partition_pairs: Vec<PairBuffer>,
    /// x-cells and y-rows per region, and regions per axis (x, then y).
    tile: [usize; 3],
    tiles: [usize; 3],
    /// Each region's box (its cells: a column of x-y tiles over a slab of the depth).
    regions: Vec<Region>,
    /// Each region's pairs as of the last update that searched it.
    region_pairs: Vec<Vec<(u32, u32)>>,
    /// `region_pairs` holds pairs (an update in order ran since the last full update).
    regions_live: bool,
    /// Pairs listed after each region the last update in order searched, in its order.
    searched_ends: Vec<usize>,
}

impl fmt::Debug for Grid {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Grid")
            .field("reach", &self.reach)
            .field("dims", &self.dims)
            .field("bodies", &self.bodies)
            .field("buckets", &(self.bucket_start.len() - 1))
            .field("threads", &self.threads)
            .field("pairs", &self.pairs.as_slice().len())
            .finish_non_exhaustive()
    }
}

impl Grid {
    /// State for boxes of half-size `half` in the cubic volume [lo, lo + side]^3.
    pub(super) fn new(half: f64, lo: Vec3, side: f64, bodies: usize) -> Self {
        let reach = 2.0 * half;
        // `as usize` saturates (and maps NaN to 0), so degenerate sizes land in the clamp.
        let by_size = (side / (reach * CELL_MARGIN)).floor() as usize;
        let by_count = ((MAX_CELLS_PER_BODY * bodies + 64) as f64 / X_SPLIT as f64)
            .cbrt()
            .floor() as usize;
        let n = by_size.min(by_count).max(1);
        let nx = X_SPLIT * n;
        let dims = Dims {
            lo,
            inv_cell: n as f64 / side,
            inv_cell_x: nx as f64 / side,
            n,
            nx,
            top: (n - 1) as f64,
            top_x: (nx - 1) as f64,
        };
        let cells = dims.cells();
        let per_bucket = cells.div_ceil(TARGET_BUCKETS).max(1);
        let bucket_shift = (usize::BITS - (per_bucket - 1).leading_zeros()).min(MAX_BUCKET_SHIFT);
        let buckets = cells.div_ceil(1 << bucket_shift);
        // Regions hold whole pairs of rows, as the search visits them.
        let tile = [
            nx.div_ceil(REGION_TILES),
            n.div_ceil(REGION_TILES).next_multiple_of(2),
            n.div_ceil(REGION_SLABS),
        ];
        let tiles = [
            nx.div_ceil(tile[0]),
            n.div_ceil(tile[1]),
            n.div_ceil(tile[2]),
        ];
        let count = tiles[0] * tiles[1] * tiles[2];
        let regions = (0..count)
            .map(|r| {
                let [x, y, z] = region_cells(tile, tiles, [nx, n, n], r);
                let at = |c: [usize; 3]| {
                    lo + Vec3::new(
                        c[0] as f64 * side / nx as f64,
                        c[1] as f64 * side / n as f64,
                        c[2] as f64 * side / n as f64,
                    )
                };
                Region {
                    lo: at([x[0], y[0], z[0]]),
                    hi: at([x[1], y[1], z[1]]),
                }
            })
            .collect::<Vec<_>>();
        Self {
            reach,
            dims,
            bodies,
            bucket_shift,
            bucket_start: vec![0; buckets + 1],
            segment_room: Vec::new(),
            segment_start: Vec::new(),
            deal_passes: 0,
            staged: Vec::new(),
            sorted: Sorted::new(bodies),
            start: vec![0; cells + dims.pair_cells() + 1],
            part_counts: Vec::new(),
            cursors: vec![vec![0; (1usize << bucket_shift).min(cells)]],
            threads: 1,
            wide_rounds: true,
            min_bodies_per_thread: MIN_BODIES_PER_THREAD,
            pairs: PairBuffer::default(),
            partition_pairs: Vec::new(),
            tile,
            tiles,
            region_pairs: vec![Vec::new(); regions.len()],
            regions,
            regions_live: false,
            searched_ends: Vec::new(),
        }
    }

    pub(super) fn regions(&self) -> &[Region] {
        &self.regions
    }

    pub(super) fn regions_live(&self) -> bool {
        self.regions_live
    }

    pub(super) fn region_pairs_before(&self, k: usize) -> usize {
        match k {
            0 => 0,
            k => self
                .searched_ends
                .get(k - 1)
                .copied()
                .unwrap_or(self.pairs.as_slice().len()),
        }
    }

    pub(super) fn bodies(&self) -> usize {
        self.bodies
    }

    /// Body ids in cell order (cell, then id) as of the last sort: a spatial order in which a
    /// body's candidates lie in a few forward streams (its row, the next row and three rows of the
    /// next z-plane), which is why the simulation renumbers its bodies in it.
    pub(super) fn cell_order(&self) -> Vec<u32> {
        self.sorted.id[..self.bodies].to_vec()
    }

    /// Renumber the bodies: old id `i` becomes `new_of_old[i]`. What persists between updates and
    /// names bodies (the regions' kept pairs, the last pairs, the sort) is rewritten, each pair as
    /// (smaller, larger); the next update sorts again from the positions it is given.
    pub(super) fn renumber(&mut self, new_of_old: &[u32]) {
        let map = |(a, b): (u32, u32)| {
            let (x, y) = (new_of_old[a as usize], new_of_old[b as usize]);
            (x.min(y), x.max(y))
        };
        for pairs in &mut self.region_pairs {
            pairs.iter_mut().for_each(|p| *p = map(*p));
        }
        self.pairs
            .as_mut_slice()
            .iter_mut()
            .for_each(|p| *p = map(*p));
        for id in &mut self.sorted.id[..self.bodies] {
            *id = new_of_old[*id as usize];
        }
    }

    #[cfg(test)]
    pub(super) fn pair_storage(&self) -> usize {
        self.pairs.capacity()
    }

    pub(super) fn set_threads(&mut self, threads: usize) {
        self.threads = threads.max(1);
        self.partition_pairs
            .resize_with(self.threads - 1, PairBuffer::default);
        let per_bucket = self.cursors[0].len();
        self.cursors
            .resize_with(self.threads, || vec![0; per_bucket]);
    }

    /// Parts the work is split into this frame: one per thread, but at least
    /// `min_bodies_per_thread` bodies and one z-plane per part.
    fn parts(&self) -> usize {
        self.threads
            .min(self.bodies / self.min_bodies_per_thread)
            .min(self.dims.n)
            .max(1)
    }

    /// Search in the baseline rounds only, as on a processor without AVX-512.
    #[cfg(test)]
    pub(super) fn baseline_rounds(&mut self) {
        self.wide_rounds = false;
    }

    /// Split the work over the threads even for tiny scenes (so tests exercise the partitions).
    #[cfg(test)]
    pub(super) fn partition_tiny_scenes(&mut self) {
        self.min_bodies_per_thread = 1;
    }

    /// Re-sort the bodies into their cells and regenerate the candidate pairs.
    pub(super) fn update(&mut self, positions: &[Vec3]) {
        self.sort(positions);
        self.find_pairs();
        if self.regions_live {
            // The regions' pairs are out of date from here on; an update in order must not
            // keep them as if they were last frame's.
            self.region_pairs.iter_mut().for_each(Vec::clear);
            self.regions_live = false;
        }
    }

    /// Re-sort every body, then search the regions in `order` for as long as `go_on` (given the
    /// pairs found so far) allows; the pairs found, region by region in that order, are this
    /// update's pairs. Regions not reached keep their pairs of the last update that searched
    /// them (stale).
    pub(super) fn update_in_order(
        &mut self,
        positions: &[Vec3],
        order: &[u32],
        go_on: &mut dyn FnMut(usize) -> bool,
    ) -> RegionPass {
        self.sort(positions);
        self.regions_live = true;
        let rows = Rows {
            reach: self.reach,
            dims: self.dims,
            sorted: self.sorted.view(),
            start: &self.start,
            wide: self.wide_rounds,
        };
        let (n, nx) = (self.dims.n, self.dims.nx);
        let mut searched = vec![false; self.regions.len()];
        let mut pass = RegionPass::default();
        self.pairs.set_len(0);
        self.searched_ends.clear();
        for &r in order {
            let r = r as usize;
            if r >= searched.len() || searched[r] {
                continue;
            }
            if !go_on(self.pairs.as_slice().len()) {
                break;
            }
            searched[r] = true;
            let [x, y, z] = region_cells(self.tile, self.tiles, [nx, n, n], r);
            let buf = &mut self.region_pairs[r];
            let len = rows.search([z[0]..z[1], y[0]..y[1], x[0]..x[1]], buf, 0);
            buf.truncate(len);
            if buf.capacity() > 4 * len + super::PAIR_SLACK {
                buf.shrink_to(2 * len + super::PAIR_SLACK);
            }
            self.pairs.append(buf);
            self.searched_ends.push(self.pairs.as_slice().len());
            pass.searched += 1;
        }
        for (r, done) in searched.iter().enumerate() {
            if !done {
                pass.stale += 1;
                pass.stale_pairs += self.region_pairs[r].len() as u32;
            }
        }
        self.pairs.end_frame();
        pass
    }

    /// Every candidate pair of the bodies as last sorted (what a full update would list), for
    /// checking an update in order against.
    pub(super) fn all_pairs(&self) -> Vec<(u32, u32)> {
        let rows = Rows {
            reach: self.reach,
            dims: self.dims,
            sorted: self.sorted.view(),
            start: &self.start,
            wide: self.wide_rounds,
        };
        let mut out = PairBuffer::default();
        rows.planes(0, self.dims.n, &mut out);
        out.as_slice().to_vec()
    }

    /// Two-level counting sort by cell, stable in id. With several parts, the bodies are split
    /// into consecutive id ranges for the first level and the buckets into consecutive runs for
    /// the second; every body lands in the same slot as with one part.
    ///
    /// The first level deals the bodies in one pass, each part into its own segment of every
    /// bucket, sized by the last frame's counts with some slack: bodies drift a little from
    /// frame to frame, so the counts of this frame are rarely needed before dealing, and a
    /// separate counting pass would read every position twice. A segment that overflows (a
    /// first frame, or bodies crowding into a few buckets) costs a second pass, with segments
    /// fitted to the counts the first one made.
    fn sort(&mut self, positions: &[Vec3]) {
        let dims = self.dims;
        let shift = self.bucket_shift;
        let parts = self.parts();
        let buckets = self.bucket_start.len() - 1;
        let per_part = positions.len().div_ceil(parts).max(1);
        if self.segment_room.len() != parts * buckets {
            self.segment_room.clear();
            self.segment_room.resize(parts * buckets, 0);
        }
        self.deal_passes = 1;
        if !self.deal(positions, per_part) {
            self.deal_passes = 2;
            self.fit_segments();
            let fitted = self.deal(positions, per_part);
            debug_assert!(fitted, "segments fitted to the counts overflowed");
        }
        // The next frame's segments: fitted to this frame's counts every frame, not only after
        // an overflow, so that only a jump of more than the slack in one frame overflows one.
        // Fitted only after overflows, the rooms fell behind the bodies' drift: at a million
        // bodies on two threads, where each part's ids cover half the volume and a part's
        // segments in the other half's buckets have little room, 61 of 201 frames dealt twice.
        self.fit_segments();
        // Bucket b's bodies, in their final order of slots.
        self.bucket_start[0] = 0;
        for b in 0..buckets {
            let dealt: u32 = (0..parts).map(|t| self.part_counts[t * buckets + b]).sum();
            self.bucket_start[b + 1] = self.bucket_start[b] + dealt;
        }
        // Level 2: counting sort of each bucket by cell, parts taking consecutive buckets.
        let cells = dims.cells();
        let cuts = cut(&self.bucket_start, parts);
        let mut sorted = self.sorted.view_mut();
        let mut start: &mut [u32] = &mut self.start[..cells];
        let mut items = Vec::with_capacity(parts);
        for (w, cursor) in cuts.windows(2).zip(&mut self.cursors) {
            let (b0, b1) = (w[0], w[1]);
            let bodies = (self.bucket_start[b1] - self.bucket_start[b0]) as usize;
            let span = (b1 << shift).min(cells) - (b0 << shift).min(cells);
            let (dest, more) = sorted.split_at(bodies);
            sorted = more;
            let (index, more) = std::mem::take(&mut start).split_at_mut(span);
            start = more;
            items.push((b0..b1, dest, index, cursor));
        }
        let (staged, bucket_start) = (&self.staged[..], &self.bucket_start[..]);
        let (segment_start, part_counts) = (&self.segment_start[..], &self.part_counts[..]);
        in_parallel(items, |(range, dest, index, cursor)| {
            let (s_base, c_base) = (bucket_start[range.start] as usize, range.start << shift);
            for b in range {
                // The bucket's bodies: part 0's segment, then part 1's, ..., so ids stay in order.
                let segments = (0..parts).map(|t| {
                    let s0 = segment_start[b * parts + t] as usize;
                    &staged[s0..s0 + part_counts[t * buckets + b] as usize]
                });
                let c0 = b << shift;
                let c1 = ((b + 1) << shift).min(cells);
                let count = &mut cursor[..c1 - c0];
                count.fill(0);
                for segment in segments.clone() {
                    for s in segment {
                        count[s.cell as usize - c0] += 1;
                    }
                }
                let at0 = bucket_start[b];
                let mut at = at0;
                for (k, c) in count.iter_mut().enumerate() {
                    index[c0 - c_base + k] = at;
                    (at, *c) = (at + *c, at);
                }
                // Ids and cells are scattered into the bucket's slots (cut to one length, so
                // that a body's two stores share one bounds check), then the centres are read
                // in slot order: written in order, and read nearly in order, as the bodies are
                // renumbered in the cell order at large N.
                let (lo, hi) = (at0 as usize - s_base, at as usize - s_base);
                let id = &mut dest.id[lo..hi];
                let m = id.len();
                let cell = &mut dest.cell[lo..hi][..m];
                for segment in segments {
                    for s in segment {
                        let k = s.cell as usize - c0;
                        let j = (count[k] - at0) as usize;
                        id[j] = s.id;
                        cell[j] = s.cell;
                        count[k] += 1;
                    }
                }
                let (x, y, z) = (
                    &mut dest.x[lo..hi][..m],
                    &mut dest.y[lo..hi][..m],
                    &mut dest.z[lo..hi][..m],
                );
                fill_centres(positions, id, [x, y, z]);
            }
        });
        // The end of the last cell, and the row of empty cells beyond it.
        self.start[cells..].fill(self.bodies as u32);
    }

    /// Room for each part's segment of each bucket: its count in the last deal, a sixteenth
    /// more, and [`SEGMENT_SLACK_MIN`] more still.
    fn fit_segments(&mut self) {
        for (room, &count) in self.segment_room.iter_mut().zip(&self.part_counts) {
            *room = count + count / SEGMENT_SLACK_DIVISOR + SEGMENT_SLACK_MIN;
        }
    }

    /// Deal every body into its part's segment of its bucket (level 1 of [`Self::sort`]),
    /// counting each segment's bodies into `part_counts`; whether every segment had room. The
    /// segments take `segment_room` slots each, bucket by bucket and part by part within one.
    fn deal(&mut self, positions: &[Vec3], per_part: usize) -> bool {
        let (dims, shift) = (self.dims, self.bucket_shift);
        let buckets = self.bucket_start.len() - 1;
        let parts = self.segment_room.len() / buckets;
        self.segment_start.clear();
        self.segment_start.push(0);
        let mut total = 0;
        for b in 0..buckets {
            for t in 0..parts {
                total += self.segment_room[t * buckets + b];
                self.segment_start.push(total);
            }
        }
        let total = total as usize;
        self.staged.resize(total, Slot::default());
        if self.staged.capacity() > 2 * total + SEGMENT_SLACK_MIN as usize {
            self.staged.shrink_to(total);
        }
        let mut rest: &mut [Slot] = &mut self.staged;
        let mut outputs: Vec<Vec<&mut [Slot]>> =
            (0..parts).map(|_| Vec::with_capacity(buckets)).collect();
        for b in 0..buckets {
            for (t, out) in outputs.iter_mut().enumerate() {
                let room = self.segment_room[t * buckets + b] as usize;
                let (head, tail) = std::mem::take(&mut rest).split_at_mut(room);
                out.push(head);
                rest = tail;
            }
        }
        self.part_counts.clear();
        self.part_counts.resize(parts * buckets, 0);
        let items = positions
            .chunks(per_part)
            .zip(outputs)
            .zip(self.part_counts.chunks_mut(buckets))
            .enumerate()
            .collect();
        type Deal<'a, 'b> = (usize, ((&'a [Vec3], Vec<&'b mut [Slot]>), &'a mut [u32]));
        in_parallel(items, |(t, ((chunk, mut out), counts)): Deal<'_, '_>| {
            let part = Dealer {
                dims,
                shift,
                first: t * per_part,
            };
            widest!(
                V3,
                |simd| part.deal(Avx2(simd), chunk, &mut out, counts),
                part.deal(Scalar, chunk, &mut out, counts),
            );
        });
        (0..parts * buckets).all(|k| {
            let (t, b) = (k / buckets, k % buckets);
            self.part_counts[k] <= self.segment_room[t * buckets + b]
        })
    }

    fn find_pairs(&mut self) {
        let rows = Rows {
            reach: self.reach,
            dims: self.dims,
            sorted: self.sorted.view(),
            start: &self.start,
            wide: self.wide_rounds,
        };
        let parts = self.parts();
        // Cut the z-planes where the running body count crosses k/parts of the total.
        let plane = self.dims.plane_cells();
        let plane_starts: Vec<u32> = (0..=self.dims.n).map(|iz| self.start[iz * plane]).collect();
        let cuts = cut(&plane_starts, parts);
        let outs = std::iter::once(&mut self.pairs).chain(&mut self.partition_pairs);
        let items = cuts.windows(2).map(|w| (w[0], w[1])).zip(outs).collect();
        in_parallel(
            items,
            |((z0, z1), out): ((usize, usize), &mut PairBuffer)| {
                rows.planes(z0, z1, out);
            },
        );
        for part in &mut self.partition_pairs[..parts - 1] {
            self.pairs.append(part.as_slice());
            part.end_frame();
        }
        self.pairs.end_frame();
    }

    /// Candidate pairs of the last update, each as (smaller id, larger id).
    pub(super) fn pairs(&self) -> &[(u32, u32)] {
        self.pairs.as_slice()
    }

    /// Panic unless every body is in exactly one slot, of the cell its position maps to, in
    /// (cell, id) order and with its current centre (used by tests).
    pub(super) fn assert_well_formed(&self, positions: &[Vec3]) {
        let cells = self.dims.cells();
        assert_eq!(self.start[0], 0, "first cell does not start at 0");
        assert!(
            self.start[cells..]
                .iter()
                .all(|&s| s as usize == self.bodies),
            "cells do not end at the body count"
        );
        let mut seen = vec![false; positions.len()];
        for c in 0..cells {
            let (a, b) = (self.start[c] as usize, self.start[c + 1] as usize);
            assert!(a <= b, "cell {c} ends before it starts");
            let s = &self.sorted;
            for k in a..b {
                let id = s.id[k] as usize;
                assert!(!seen[id], "body {id} twice");
                seen[id] = true;
                let p = positions[id];
                assert_eq!(self.dims.cell_of(p) as usize, c, "body {id} in wrong cell");
                assert_eq!(
                    s.cell[k] as usize, c,
                    "body {id} labelled with a wrong cell"
                );
                // Bit for bit, so that a NaN centre compares equal to itself.
                let bits = |v: [f64; 3]| v.map(f64::to_bits);
                assert_eq!(
                    bits([s.x[k], s.y[k], s.z[k]]),
                    bits(p.to_array()),
                    "body {id} stale"
                );
            }
            for w in s.id[a..b].windows(2) {
                assert!(w[0] < w[1], "cell {c} not in id order");
            }
        }
        assert!(seen.iter().all(|&s| s), "a body is missing from the cells");
        self.pairs.assert_well_formed();
    }
}

/// Slots a centre is asked for ahead of its copy in [`fill_centres`]: about a memory latency's
/// worth of the copy's pace (24 measured 0.6 ms faster than none at a million bodies; the
/// processor's own prefetchers follow only the runs of consecutive ids).
const FILL_AHEAD: usize = 24;

/// Copy each slot's centre from `positions`, by the slot's id, into the coordinate arrays `xyz`
/// (the last step of [`Grid::sort`]'s second level). The ids follow the cells' order only as
/// closely as the bodies' numbering does, so the reads are nearly but not quite in order: each
/// is asked of the memory [`FILL_AHEAD`] slots early, which only hints and never faults.
#[inline(always)]
fn fill_centres(positions: &[Vec3], id: &[u32], [x, y, z]: [&mut [f64]; 3]) {
    let m = id.len();
    let (x, y, z) = (&mut x[..m], &mut y[..m], &mut z[..m]);
    let prefetch = Prefetcher::new();
    for j in 0..m {
        if let Some(&ahead) = id.get(j + FILL_AHEAD) {
            prefetch.hint(positions, ahead as usize);
        }
        let p = positions[id[j] as usize];
        (x[j], y[j], z[j]) = (p.x, p.y, p.z);
    }
}

/// Whether this processor has what the AVX-512 rounds need ([`V4::try_new`]).
pub(super) fn wide_rounds_available() -> bool {
    #[cfg(target_arch = "x86_64")]
    return V4::try_new().is_some();
    #[cfg(not(target_arch = "x86_64"))]
    false
}

/// Read-only view of the sorted cells, shared by the partitions.
struct Rows<'a> {
    reach: f64,
    dims: Dims,
    sorted: SortedRef<'a>,
    start: &'a [u32],
    /// Search in AVX-512 rounds ([`Avx512`]) where the processor has them.
    wide: bool,
}

impl Rows<'_> {
    /// All candidate pairs whose first body (in slot order) is in z-planes `z0..z1`, body by body,
    /// into `out`.
    fn planes(&self, z0: usize, z1: usize, out: &mut PairBuffer) {
        let Dims { n, nx, .. } = self.dims;
        let len = self.search([z0..z1, 0..n, 0..nx], out.storage(), 0);
        out.set_len(len);
    }

    /// The candidate pairs whose first body (in slot order) is in the cells `[z, y, x]` (ranges
    /// of cells on each axis), row by row and body by body, written into `buf` from `len` on
    /// (growing it as needed); returns the new length. In AVX-512 rounds where the processor has
    /// them (the same pairs in the same order), else in the baseline's.
    fn search(&self, cells: [Range<usize>; 3], buf: &mut Vec<(u32, u32)>, len: usize) -> usize {
        widest!(
            V4 if self.wide,
            |simd| self.search_in(Avx512(simd), cells, buf, len),
            self.search_in(Baseline, cells, buf, len),
        )
    }

    #[inline(always)]
    fn search_in<L: Rounds>(
        &self,
        rounds: L,
        [z, y, x]: [Range<usize>; 3],
        buf: &mut Vec<(u32, u32)>,
        mut len: usize,
    ) -> usize {
        // Regions hold whole pairs of rows; a range ending at an odd row count ends the plane.
        for iz in z {
            for pair in y.start / 2..y.end.div_ceil(2) {
                len = self.span(rounds, iz, pair, x.start, x.end, buf, len);
            }
        }
        len
    }

    /// The candidate pairs whose first body (in slot order) is in x-cells `x0..x1` of the pair
    /// of rows `pair` of z-plane `iz`, body by body, written into `buf` from `len` on (growing it
    /// as needed); returns the new length.
    ///
    /// A body in row `iy` of the pair meets the other row of its own pair, and in the next plane
    /// the rows `iy - 1 ..= iy + 1`, which lie in two pairs; the lower row of a pair meets the
    /// row below it only through the pair below, whose upper row looks forward to it. So a body
    /// has four windows, each the x-cells `ix - 2 ..= ix + 2` of a pair of rows, one slice:
    /// - its own pair, from the next body on (the bodies before it found their pairs with it);
    /// - in the upper row, the pair above in its plane (empty in the lower row);
    /// - the next plane's pair below and its own pair (lower row), or its own pair and the pair
    ///   above (upper row).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn span<L: Rounds>(
        &self,
        rounds: L,
        iz: usize,
        pair: usize,
        x0: usize,
        x1: usize,
        buf: &mut Vec<(u32, u32)>,
        mut len: usize,
    ) -> usize {
        let Dims { n, nx, .. } = self.dims;
        let (cells, row) = (self.dims.cells(), self.dims.pair_cells());
        let (start, sorted, r) = (self.start, self.sorted, self.reach);
        let own = (iz * self.dims.row_pairs() + pair) * row;
        let up = own + self.dims.plane_cells();
        let higher = pair + 1 < self.dims.row_pairs();
        let next = iz + 1 < n;
        // Pairs of rows by where they are; `cells` is the empty pair.
        let above = if higher { own + row } else { cells };
        let next_below = if next && pair > 0 { up - row } else { cells };
        let next_own = if next { up } else { cells };
        let next_above = if next && higher { up + row } else { cells };
        let SortedRef { x, y, z, id, cell } = sorted;
        // One length for all five arrays, so that one bounds check covers a round's loads.
        let slots = x.len();
        let (y, z, id, cell) = (&y[..slots], &z[..slots], &id[..slots], &cell[..slots]);
        let sorted = SortedRef { x, y, z, id, cell };
        for i in start[own + 2 * x0] as usize..start[own + 2 * x1] as usize {
            let at = cell[i] as usize - own;
            let (ix, upper) = (at / 2, at % 2 == 1);
            let p = Probe {
                at: [x[i], y[i], z[i]],
                id: id[i],
                reach: r,
            };
            let (lo, hi) = (
                2 * ix.saturating_sub(X_SPLIT),
                2 * (ix + X_SPLIT + 1).min(nx),
            );
            let others = if upper {
                [above, next_own, next_above]
            } else {
                [cells, next_below, next_own]
            };
            let mut windows = [(i + 1, start[own + hi] as usize); 4];
            for (w, &b) in windows[1..].iter_mut().zip(&others) {
                *w = (start[b + lo] as usize, start[b + hi] as usize);
            }
            let most: usize = windows.iter().map(|w| w.1 - w.0 + L::WIDTH).sum();
            if buf.len() < len + most {
                buf.resize((2 * buf.len()).max(len + most) + 64, (0, 0));
            }
            // The output, cut once to what this body may write: the rounds then index a slice
            // held in registers rather than reloading the vector's length and pointer.
            let out = &mut buf[..len + most];
            let [w0, w1, w2, w3] = windows;
            // The own pair's window and the one above (empty in the lower row) share one round
            // where they fit in it together, as they mostly do.
            if (w0.1 - w0.0) + (w1.1 - w1.0) <= L::MERGED {
                len += rounds.merged(sorted, w0, w1, p, &mut out[len..len + 2 * L::WIDTH]);
            } else {
                len = window(rounds, sorted, w0, p, out, len);
                len = window(rounds, sorted, w1, p, out, len);
            }
            len = window(rounds, sorted, w2, p, out, len);
            len = window(rounds, sorted, w3, p, out, len);
        }
        len
    }
}

/// The pairs of body `p` with the slots `b0..b1` whose boxes overlap its own, written into `out`
/// from `len` on; returns the new length. `out` has room for the window's slots and one round
/// more.
///
/// The slots are tested a round at a time, the tests past the window's end masked; most windows
/// hold fewer bodies than a round, so most take one round and the loop's exit is rarely
/// mispredicted.
#[inline(always)]
fn window<L: Rounds>(
    rounds: L,
    sorted: SortedRef,
    (b0, b1): (usize, usize),
    p: Probe,
    out: &mut [(u32, u32)],
    mut len: usize,
) -> usize {
    let mut k = b0;
    loop {
        len += rounds.round(sorted, k, b1, p, &mut out[len..len + L::WIDTH]);
        k += L::WIDTH;
        if k >= b1 {
            break len;
        }
    }
}

/// One round of the pair search: the slots `k..b1` (at most [`Self::WIDTH`] of them, the rest of
/// the round masked) tested against the box at `p`.
trait Rounds: Copy {
    /// Slots a round tests.
    const WIDTH: usize;

    /// Write body `p`'s pair with each slot whose box overlaps its own (touching counts, as
    /// [`super::brute_force_pairs`] has it: |q - p| <= reach on every axis, in f64) to `out`,
    /// in slot order, each as (smaller id, larger id); returns how many. Every slot's pair may be
    /// written, so `out` has [`Self::WIDTH`] slots; the slots exist (padding, [`PAD`]).
    fn round(self, s: SortedRef, k: usize, b1: usize, p: Probe, out: &mut [(u32, u32)]) -> usize;

    /// Two windows together of at most this many slots are tested by [`Self::merged`].
    const MERGED: usize;

    /// The pairs of windows `a` then `b`, together at most [`Self::MERGED`] slots, as
    /// [`Self::round`] over `a` and then over `b` would write them; `out` has twice
    /// [`Self::WIDTH`] slots. As two rounds where the processor cannot merge them.
    #[inline(always)]
    fn merged(
        self,
        s: SortedRef,
        a: (usize, usize),
        b: (usize, usize),
        p: Probe,
        out: &mut [(u32, u32)],
    ) -> usize {
        let found = self.round(s, a.0, a.1, p, out);
        found + self.round(s, b.0, b.1, p, &mut out[found..])
    }
}

/// The body a window is searched for: its centre, its id, and how far a centre may be on each
/// axis for the boxes to overlap.
#[derive(Clone, Copy)]
struct Probe {
    at: [f64; 3],
    id: u32,
    reach: f64,
}

/// Rounds of [`LANES`] slots in the baseline's vector registers (SSE2: two lanes of f64 each).
#[derive(Clone, Copy)]
struct Baseline;

impl Rounds for Baseline {
    const WIDTH: usize = LANES;
    const MERGED: usize = LANES;

    #[inline(always)]
    fn round(self, s: SortedRef, k: usize, b1: usize, p: Probe, out: &mut [(u32, u32)]) -> usize {
        let hits = near(s.x, s.y, s.z, k, p.at, p.reach) & ((1 << (b1 - k).min(LANES)) - 1);
        // Every slot's pair is written and the cursor advanced by its test, so the unpredictable
        // outcome costs no branch.
        let q: [u32; LANES] = s.id[k..k + LANES].try_into().unwrap_or([0; LANES]);
        put_lanes(out, p.id, q, hits)
    }
}

/// Rounds of eight slots in AVX-512 registers: a round's tests leave a mask, and the pairs it
/// keeps are packed by one compress instruction, with neither a branch nor a chain through the
/// count. Used only where the processor has AVX-512 ([`V4::try_new`]).
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy)]
struct Avx512(V4);

#[cfg(target_arch = "x86_64")]
impl Rounds for Avx512 {
    const WIDTH: usize = 8;
    const MERGED: usize = 8;

    #[inline(always)]
    fn round(self, s: SortedRef, k: usize, b1: usize, p: Probe, out: &mut [(u32, u32)]) -> usize {
        let f = self.0.avx512f;
        // Slots before the window's end: one vector comparison of slot numbers.
        let slots = f._mm512_add_epi64(
            f._mm512_set1_epi64(k as i64),
            f._mm512_set_epi64(7, 6, 5, 4, 3, 2, 1, 0),
        );
        let live = f._mm512_cmplt_epu64_mask(slots, f._mm512_set1_epi64(b1 as i64));
        let at = [lanes8(s.x, k), lanes8(s.y, k), lanes8(s.z, k)];
        self.test(at, ids8(s.id, k), live, p, out)
    }

    /// One round: the second window's slots are expanded into the lanes past the first's.
    #[inline(always)]
    fn merged(
        self,
        s: SortedRef,
        (a0, a1): (usize, usize),
        (b0, b1): (usize, usize),
        p: Probe,
        out: &mut [(u32, u32)],
    ) -> usize {
        let f = self.0.avx512f;
        let (la, lb) = (a1 - a0, b1 - b0);
        // Lanes `la..` take `b`'s slots; lanes `la + lb..` are past both windows' ends.
        let from_b = (0xff_u32 << la) as u8;
        let live = ((1_u32 << (la + lb)) - 1) as u8;
        let at = [
            f._mm512_mask_expand_pd(lanes8(s.x, a0), from_b, lanes8(s.x, b0)),
            f._mm512_mask_expand_pd(lanes8(s.y, a0), from_b, lanes8(s.y, b0)),
            f._mm512_mask_expand_pd(lanes8(s.z, a0), from_b, lanes8(s.z, b0)),
        ];
        let q = f._mm256_mask_expand_epi32(ids8(s.id, a0), from_b, ids8(s.id, b0));
        self.test(at, q, live, p, out)
    }
}

#[cfg(target_arch = "x86_64")]
impl Avx512 {
    /// Write `p`'s pair with each of the eight slots at `at` (x, y, z), ids `q`, of mask `live`
    /// whose box overlaps its own to `out`, in lane order; returns how many. Each axis narrows
    /// the mask of slots still overlapping (NaN compares false), and one compress packs the
    /// pairs kept.
    #[inline(always)]
    fn test(
        self,
        at: [std::arch::x86_64::__m512d; 3],
        q: std::arch::x86_64::__m256i,
        live: u8,
        p: Probe,
        out: &mut [(u32, u32)],
    ) -> usize {
        let f = self.0.avx512f;
        let hits = narrow8(self.0, at[0], p.at[0], p.reach, live);
        let hits = narrow8(self.0, at[1], p.at[1], p.reach, hits);
        let hits = narrow8(self.0, at[2], p.at[2], p.reach, hits);
        let own = self.0.avx._mm256_set1_epi32(p.id as i32);
        let (lo, hi) = (
            self.0.avx2._mm256_min_epu32(q, own),
            self.0.avx2._mm256_max_epu32(q, own),
        );
        let pairs = f._mm512_or_si512(
            f._mm512_cvtepu32_epi64(lo),
            f._mm512_slli_epi64::<32>(f._mm512_cvtepu32_epi64(hi)),
        );
        let kept: [u64; 8] = pulp::cast(f._mm512_maskz_compress_epi64(hits, pairs));
        for (o, pair) in out[..8].iter_mut().zip(kept) {
            *o = (pair as u32, (pair >> 32) as u32);
        }
        hits.count_ones() as usize
    }
}

/// The eight slots of `v` from `k` on, in one vector (the slots exist, see [`PAD`]).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn lanes8(v: &[f64], k: usize) -> std::arch::x86_64::__m512d {
    pulp::cast(<[f64; 8]>::try_from(&v[k..k + 8]).unwrap_or([0.0; 8]))
}

/// The eight ids from slot `k` on, in one vector.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn ids8(id: &[u32], k: usize) -> std::arch::x86_64::__m256i {
    pulp::cast(<[u32; 8]>::try_from(&id[k..k + 8]).unwrap_or([0; 8]))
}

/// The lanes of `mask` among `v` within `reach` of `c` (|v - c| <= reach; NaN compares false):
/// one axis of an [`Avx512`] round. A function, not a closure: a closure is compiled without the
/// processor's features of the function it is written in, and its intrinsics, unless it is
/// inlined, become calls.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn narrow8(simd: V4, v: std::arch::x86_64::__m512d, c: f64, reach: f64, mask: u8) -> u8 {
    use std::arch::x86_64::_CMP_LE_OQ;
    let f = simd.avx512f;
    let d = f._mm512_abs_pd(f._mm512_sub_pd(v, f._mm512_set1_pd(c)));
    f._mm512_mask_cmp_pd_mask::<_CMP_LE_OQ>(mask, d, f._mm512_set1_pd(reach))
}

/// The cells of region `r` ([x0, x1), [y0, y1), [z0, z1)), regions numbered x fastest, then y,
/// then z, with `tile` cells per region and `tiles` regions per axis over `cells` cells per axis.
fn region_cells(
    tile: [usize; 3],
    tiles: [usize; 3],
    cells: [usize; 3],
    r: usize,
) -> [[usize; 2]; 3] {
    let t = [
        r % tiles[0],
        (r / tiles[0]) % tiles[1],
        r / (tiles[0] * tiles[1]),
    ];
    std::array::from_fn(|a| [t[a] * tile[a], ((t[a] + 1) * tile[a]).min(cells[a])])
}

/// Which of the [`LANES`] slots from `k` on hold a box overlapping the box at `p` (touching
/// counts), as [`super::brute_force_pairs`] has it (|q - p| <= reach on every axis, in f64): bit
/// j for slot `k + j`. Each axis is one vector subtraction, absolute value and comparison.
#[inline(always)]
fn near(x: &[f64], y: &[f64], z: &[f64], k: usize, p: [f64; 3], reach: f64) -> usize {
    let lanes =
        |v: &[f64]| f64x4::from(<[f64; LANES]>::try_from(&v[k..k + LANES]).unwrap_or([0.0; LANES]));
    let axis = |v: &[f64], c: f64| {
        (lanes(v) - f64x4::splat(c))
            .abs()
            .cmp_le(f64x4::splat(reach))
    };
    (axis(x, p[0]) & axis(y, p[1]) & axis(z, p[2])).move_mask() as usize
}

/// Run `f` on every item: the first on the calling thread, the others as jobs of the thread pool
/// it runs on (see `Simulation::step`).
fn in_parallel<T: Send, F: Fn(T) + Sync>(items: Vec<T>, f: F) {
    let mut items = items.into_iter();
    let Some(first) = items.next() else {
        return;
    };
    if items.len() == 0 {
        f(first);
        return;
    }
    rayon::in_place_scope(|s| {
        let f = &f;
        for item in items {
            s.spawn(move |_| f(item));
        }
        f(first);
    });
}

/// Split items `0..at.len() - 1` into `parts` consecutive runs of about equal weight, where `at`
/// holds the running total of the weights before each item (and the grand total last): returns
/// the `parts + 1` boundaries, from 0 to the item count. Runs may be empty.
fn cut(at: &[u32], parts: usize) -> Vec<usize> {
    let items = at.len() - 1;
    let total = at[items] as usize;
    let mut cuts = Vec::with_capacity(parts + 1);
    cuts.push(0);
    for k in 1..parts {
        let want = total * k / parts;
        let mut i = cuts[k - 1];
        while i < items && (at[i] as usize) < want {
            i += 1;
        }
        cuts.push(i);
    }
    cuts.push(items);
    cuts
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::broad_phase::brute_force_pairs;

    /// A centre that is not finite (NaN, or infinite on an axis) still lands in exactly one cell,
    /// an edge cell, and pairs with nothing, as brute force has it; the finite bodies' pairs are
    /// untouched.
    #[test]
    fn non_finite_centres_land_in_edge_cells_and_pair_with_nothing() {
        let (side, half) = (3.0, 0.222);
        let mut positions: Vec<Vec3> = (0..200)
            .map(|i| {
                let t = f64::from(i);
                Vec3::new((t * 0.37) % side, (t * 0.61) % side, (t * 0.83) % side)
            })
            .collect();
        positions[3] = Vec3::new(f64::NAN, 1.0, 1.0);
        positions[7] = Vec3::splat(f64::NAN);
        positions[11] = Vec3::new(f64::INFINITY, 1.0, 1.0);
        positions[12] = Vec3::new(f64::INFINITY, 1.0, 1.0);
        positions[19] = Vec3::new(1.0, f64::NEG_INFINITY, 2.0);
        let mut g = Grid::new(half, Vec3::ZERO, side, positions.len());
        g.update(&positions);
        g.assert_well_formed(&positions);
        let dims = g.dims;
        assert_eq!(
            dims.cell_of(positions[7]),
            0,
            "NaN in every axis: the first cell"
        );
        let ix = |p: Vec3| (dims.cell_of(p) as usize / 2) % dims.nx;
        assert_eq!(ix(positions[3]), 0, "NaN x: the first x-cell");
        assert_eq!(
            ix(positions[11]),
            dims.nx - 1,
            "infinite x: the last x-cell"
        );
        let mut got = g.pairs().to_vec();
        got.sort_unstable();
        let want = brute_force_pairs(&positions, half);
        assert!(!want.is_empty());
        assert!(want.iter().all(|&(a, b)| ![3, 7, 11, 12, 19].contains(&a)
            && ![3, 7, 11, 12, 19].contains(&b)));
        assert_eq!(got, want);
    }

    /// Where the processor has AVX-512, the own pair's window and the pair above's share one
    /// round when they fit in it together. From sparse scenes, where they always fit, to dense
    /// ones, where many do not, the pairs are brute force's, in the baseline's order, and each
    /// slot holds its body's centre. (Elsewhere both searches take the baseline's rounds, and
    /// only brute force is compared.)
    #[test]
    fn windows_sharing_a_round_give_the_baselines_pairs_in_its_order() {
        let (side, half) = (4.0, 0.3);
        let mut rng = crate::rng::Rng::new(11);
        // Whether some upper-row body's two windows (its own pair's from the next body on, and
        // the pair above's) held at most one round of slots, and whether some held more.
        let mut fit = [false; 2];
        for bodies in [40, 300, 1_000, 2_500] {
            let positions: Vec<Vec3> = (0..bodies)
                .map(|_| Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * side)
                .collect();
            let mut wide = Grid::new(half, Vec3::ZERO, side, bodies);
            let mut baseline = wide.clone();
            baseline.baseline_rounds();
            wide.update(&positions);
            baseline.update(&positions);
            wide.assert_well_formed(&positions);
            assert_eq!(wide.pairs(), baseline.pairs(), "{bodies} bodies");
            let mut got = wide.pairs().to_vec();
            got.sort_unstable();
            assert_eq!(got, brute_force_pairs(&positions, half), "{bodies} bodies");
            let d = wide.dims;
            let slots = |b: usize, ix: usize| {
                let (lo, hi) = (
                    2 * ix.saturating_sub(X_SPLIT),
                    2 * (ix + X_SPLIT + 1).min(d.nx),
                );
                (wide.start[b + hi] - wide.start[b + lo]) as usize
            };
            for iz in 0..d.n {
                for pair in 0..d.row_pairs() - 1 {
                    let own = (iz * d.row_pairs() + pair) * d.pair_cells();
                    for ix in 0..d.nx {
                        let upper = own + 2 * ix + 1;
                        let hi = 2 * (ix + X_SPLIT + 1).min(d.nx);
                        for i in wide.start[upper]..wide.start[upper + 1] {
                            let mine = (wide.start[own + hi] - (i + 1)) as usize;
                            let both = mine + slots(own + d.pair_cells(), ix);
                            fit[usize::from(both <= 8)] = true;
                        }
                    }
                }
            }
        }
        assert_eq!(fit, [true, true], "windows that do not fit, and that fit");
    }

    /// The first level's four-lane cells are the scalar cells, centre for centre: inside the
    /// volume, on cell boundaries, outside it on every side, far from the origin, and not finite.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn four_lane_cells_are_the_scalar_cells() {
        let Some(simd) = V3::try_new() else {
            return;
        };
        for (lo, side, half) in [
            (Vec3::ZERO, 7.0, 0.222),
            (Vec3::new(-3.5, 1e6, -2e9), 46.4, 0.222),
            (Vec3::splat(0.25), 1.0, 0.4),
        ] {
            let g = Grid::new(half, lo, side, 4_000);
            let dims = g.dims;
            let mut rng = crate::rng::Rng::new(7);
            let mut unit = || rng.next_f64();
            // Random centres from a side's width outside the volume to one beyond it.
            let mut points: Vec<Vec3> = (0..4_000)
                .map(|_| lo + (Vec3::new(unit(), unit(), unit()) * 3.0 - 1.0) * side)
                .collect();
            // Exact cell boundaries on each axis, and the volume's corners.
            for k in 0..=dims.nx {
                let b = lo.x + k as f64 * side / dims.nx as f64;
                points.push(Vec3::new(b, lo.y + side * unit(), lo.z + side * unit()));
            }
            for k in 0..=dims.n {
                let b = k as f64 * side / dims.n as f64;
                points.push(Vec3::new(
                    lo.x + side * unit(),
                    lo.y + b,
                    lo.z + side * unit(),
                ));
                points.push(Vec3::new(
                    lo.x + side * unit(),
                    lo.y + side * unit(),
                    lo.z + b,
                ));
            }
            points.extend([lo, lo + Vec3::splat(side)]);
            for bad in [
                f64::NAN,
                f64::INFINITY,
                f64::NEG_INFINITY,
                -0.0,
                f64::MAX,
                f64::MIN,
            ] {
                points.extend([
                    Vec3::new(bad, lo.y + 1.0, lo.z + 1.0),
                    Vec3::new(lo.x + 1.0, bad, lo.z + 1.0),
                    Vec3::new(lo.x + 1.0, lo.y + 1.0, bad),
                    Vec3::splat(bad),
                ]);
            }
            let (quads, _) = points.as_chunks::<4>();
            for quad in quads {
                let want = Scalar.cells(&dims, quad);
                let got = simd.vectorize(
                    #[inline(always)]
                    || Avx2(simd).cells(&dims, quad),
                );
                assert_eq!(got, want, "{quad:?} in a grid from {lo} of side {side}");
            }
        }
    }

    /// The first sorting level deals in one pass while the bodies drift, for as long as they
    /// drift and whichever parts their ids fall in, and in two in a frame that moves them across
    /// buckets wholesale (a first frame, a clump), after which one pass suffices again; its
    /// staging never holds more than the bodies and their slack, and every frame's pairs are
    /// brute force's, on one and two parts.
    #[test]
    fn the_deal_takes_one_pass_while_bodies_drift_and_two_after_a_jump() {
        let (n, side, half) = (4_000usize, 7.0, 0.222);
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut unit = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        // Numbered by depth, as a simulation renumbers them in cell order: each part's ids
        // then fill some buckets and leave the others' segments little room.
        let mut spread: Vec<Vec3> = (0..n)
            .map(|_| Vec3::new(unit(), unit(), unit()) * side)
            .collect();
        spread.sort_by(|a, b| a.z.total_cmp(&b.z));
        let nudge: Vec<Vec3> = (0..n)
            .map(|_| (Vec3::new(unit(), unit(), unit()) - 0.5) * 0.02 + Vec3::new(0.0, 0.0, 0.02))
            .collect();
        let drifted = |frames: f64| -> Vec<Vec3> {
            spread
                .iter()
                .zip(&nudge)
                .map(|(&p, &v)| p + v * frames)
                .collect()
        };
        let clump = vec![Vec3::splat(side / 2.0); n];
        // (positions, passes the deal must take): the clump's dispersal fits its segments'
        // slack on some partitions, so its passes are not prescribed.
        // The bodies also drift in depth together, 1.2 over sixty frames (more than two cells),
        // carrying each part's bodies into the buckets of the other's ids: the segments must
        // follow the counts frame by frame, not stay as first fitted.
        let mut script = vec![(drifted(0.0), Some(2))];
        script.extend((1..60).map(|f| (drifted(f as f64), Some(1))));
        script.push((clump, Some(2)));
        script.push((drifted(60.0), None));
        script.extend((61..64).map(|f| (drifted(f as f64), Some(1))));
        for parts in [1, 2] {
            let mut g = Grid::new(half, Vec3::ZERO, side, n);
            g.partition_tiny_scenes();
            g.set_threads(parts);
            let buckets = g.bucket_start.len() - 1;
            for (f, (positions, passes)) in script.iter().enumerate() {
                g.update(positions);
                if let Some(passes) = passes {
                    assert_eq!(g.deal_passes, *passes, "{parts} parts, frame {f}");
                }
                let room = n + n / SEGMENT_SLACK_DIVISOR as usize;
                let most = room + parts * buckets * SEGMENT_SLACK_MIN as usize;
                assert!(g.staged.len() <= most, "{parts} parts, frame {f}");
                g.assert_well_formed(positions);
                let mut got = g.pairs().to_vec();
                got.sort_unstable();
                assert_eq!(got, brute_force_pairs(positions, half), "frame {f}");
            }
        }
    }
}
