//! The kernels of one level of a descent: a sphere's children tested four at a time on any
//! processor, or eight at a time where the processor has AVX2, with the same answers.

use super::*;

/// Whether sphere `a` (A's frame, radius in w) overlaps a sphere at `b` (A's frame) of radius `rb`.
/// Touching counts as overlapping.
#[inline]
pub fn spheres_overlap(a: Vec4, b: LVec3, rb: f32) -> bool {
    let r = a.w + rb;
    (LVec3::from_vec4(a) - b).length_squared() <= r * r
}

/// Which of four sphere pairs overlap (bit q for lane q), from the centre differences and the sums
/// of the radii: `(dx² + dy²) + dz² <= r²`, the same operations in the same order as
/// [`spheres_overlap`] on one pair, so a lane's answer is that function's, bit for bit.
#[inline]
pub(super) fn overlap_mask(dx: Vec4, dy: Vec4, dz: Vec4, r: Vec4) -> u32 {
    let d2 = (dx * dx + dy * dy) + dz * dz;
    d2.cmple(r * r).bitmask()
}

/// One level of a pair's descent: every sphere pair of `list` is replaced by its children's pairs
/// (A's children if `descend_a`, else B's) that overlap, written to `out` in list and child order.
/// Returns how many were kept and the sphere tests done. At the leaves one overlap settles the
/// pair, so the expansion stops after the first entry whose children hit (`out[0]` is the first
/// hit). `out` must hold 8 entries per list entry.
///
/// Children are written without a branch on the outcome (a table lists each four-test mask's
/// overlapping lanes): overlap outcomes are close to coin flips, and a branch per test would
/// mispredict half the time.
#[inline]
pub(super) fn expand(
    tree: &SphereTree,
    frame: &PairFrame,
    descend_a: bool,
    at_leaves: bool,
    list: &[[u16; 2]],
    out: &mut [[u16; 2]],
) -> (usize, u64) {
    let mut end = 0;
    let mut tests = 0u64;
    // While A descends, B's sphere is the same from entry to entry (its root, all the way down
    // A's tree): it is mapped when it changes, not once per entry.
    let mut fixed_b = (NONE, Vec4::ZERO);
    for &[sa, sb] in list {
        let kids = tree.kids(if descend_a { sa } else { sb } as usize);
        tests += u64::from(kids.count);
        let fixed = fixed_sphere(tree, frame, descend_a, [sa, sb], &mut fixed_b);
        let (fx, fy, fz, fr) = (
            Vec4::splat(fixed.x),
            Vec4::splat(fixed.y),
            Vec4::splat(fixed.z),
            Vec4::splat(fixed.w),
        );
        // Four children per vector, kept in child order, as one test after another keeps them.
        let halves = if kids.count as usize > LANES { 2 } else { 1 };
        for h in 0..halves {
            let mask = if descend_a {
                overlap_mask(
                    kids.x[h] - fx,
                    kids.y[h] - fy,
                    kids.z[h] - fz,
                    kids.r[h] + fr,
                )
            } else {
                let [x, y, z] = frame.map_lanes(kids.x[h], kids.y[h], kids.z[h]);
                overlap_mask(fx - x, fy - y, fz - z, fr + kids.r[h])
            };
            let base = kids.first as usize + h * LANES;
            // One bounds check for the four slots. The kept children are written to the
            // first slots from a table of each mask's lanes in order, every slot's address
            // known up front: a running count of the kept lanes as each slot's address made
            // every store wait for the test before it.
            let slots: &mut [[u16; 2]; LANES] = match out.get_mut(end..end + LANES) {
                Some(s) => s.try_into().unwrap_or_else(|_| unreachable!()),
                None => unreachable!("expand: `out` holds 8 slots per entry"),
            };
            // Four lanes, four bits (the mask says so to the index check too).
            let mask = mask as usize & (KEPT_LANES.len() - 1);
            let kept = &KEPT_LANES[mask];
            for (slot, &q) in slots.iter_mut().zip(kept) {
                let kid = (base + usize::from(q)) as u16;
                *slot = if descend_a { [kid, sb] } else { [sa, kid] };
            }
            end += mask.count_ones() as usize;
        }
        if at_leaves && end > 0 {
            break;
        }
    }
    (end, tests)
}

/// The sphere an entry `[sa, sb]`'s children are tested against: B's, mapped into A's frame
/// (and kept in `mapped_b` until the entry's B sphere changes), while A descends; A's while B
/// does.
#[inline(always)]
pub(super) fn fixed_sphere(
    tree: &SphereTree,
    frame: &PairFrame,
    descend_a: bool,
    [sa, sb]: [u16; 2],
    mapped_b: &mut (u16, Vec4),
) -> Vec4 {
    if descend_a {
        if mapped_b.0 != sb {
            let b = tree.sphere(sb as usize);
            let c = frame.map(b);
            *mapped_b = (sb, Vec4::new(c.x, c.y, c.z, b.w));
        }
        mapped_b.1
    } else {
        tree.sphere(sa as usize)
    }
}

/// For each 4-bit overlap mask, its set lanes in increasing order, then zeros (slots past the
/// kept count are written but not kept).
pub(super) const KEPT_LANES: [[u8; LANES]; 1 << LANES] = {
    let mut table = [[0u8; LANES]; 1 << LANES];
    let mut mask = 0;
    while mask < 1 << LANES {
        let (mut q, mut at) = (0, 0);
        while q < LANES {
            if mask & (1 << q) != 0 {
                table[mask][at] = q as u8;
                at += 1;
            }
            q += 1;
        }
        mask += 1;
    }
    table
};

/// How one level of a descent ([`expand`]) tests a sphere's children: four at a time in the
/// baseline's vectors, or eight where the processor has AVX2 ([`Avx2`], chosen at run time). Each
/// lane does the same arithmetic in the same order in both, so both keep the same children in the
/// same order, with the same count of tests.
pub(super) trait Kernel: Copy {
    /// One level of a descent, as [`expand`] describes it.
    fn expand(
        self,
        tree: &SphereTree,
        frame: &PairFrame,
        descend_a: bool,
        at_leaves: bool,
        list: &[[u16; 2]],
        out: &mut [[u16; 2]],
    ) -> (usize, u64);
}

/// Children four at a time ([`expand`]), on any processor.
#[derive(Clone, Copy)]
pub(super) struct Baseline;

impl Kernel for Baseline {
    #[inline(always)]
    fn expand(
        self,
        tree: &SphereTree,
        frame: &PairFrame,
        descend_a: bool,
        at_leaves: bool,
        list: &[[u16; 2]],
        out: &mut [[u16; 2]],
    ) -> (usize, u64) {
        expand(tree, frame, descend_a, at_leaves, list, out)
    }
}

/// Children eight at a time, in 256-bit vectors: a sphere's eight children take one test of
/// eight lanes instead of two of four, and the kept children are packed by one permutation
/// and stored in one go. Used only where the processor has AVX2 ([`V3::try_new`]).
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy)]
pub(super) struct Avx2(pub(super) V3);

#[cfg(target_arch = "x86_64")]
impl Kernel for Avx2 {
    #[inline(always)]
    fn expand(
        self,
        tree: &SphereTree,
        frame: &PairFrame,
        descend_a: bool,
        at_leaves: bool,
        list: &[[u16; 2]],
        out: &mut [[u16; 2]],
    ) -> (usize, u64) {
        use std::arch::x86_64::__m256i;
        let simd = self.0;
        let (avx, avx2) = (simd.avx, simd.avx2);
        let lane_index = avx._mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
        let mut end = 0;
        let mut tests = 0u64;
        let mut fixed_b = (NONE, Vec4::ZERO);
        for &[sa, sb] in list {
            let kids = tree.kids(if descend_a { sa } else { sb } as usize);
            tests += u64::from(kids.count);
            let fixed = fixed_sphere(tree, frame, descend_a, [sa, sb], &mut fixed_b);
            let (fx, fy, fz, fr) = (
                avx._mm256_set1_ps(fixed.x),
                avx._mm256_set1_ps(fixed.y),
                avx._mm256_set1_ps(fixed.z),
                avx._mm256_set1_ps(fixed.w),
            );
            let (x, y, z, r) = (
                eight(&kids.x),
                eight(&kids.y),
                eight(&kids.z),
                eight(&kids.r),
            );
            // Each entry is the `[u16; 2]` pair as one u32 (A's sphere in the low half): the
            // children are `first + lane`, in A's half or in B's.
            let (mask, entries) = if descend_a {
                let mask = overlap8(
                    simd,
                    avx._mm256_sub_ps(x, fx),
                    avx._mm256_sub_ps(y, fy),
                    avx._mm256_sub_ps(z, fz),
                    avx._mm256_add_ps(r, fr),
                );
                let first = avx._mm256_set1_epi32((kids.first | u32::from(sb) << 16) as i32);
                (mask, avx2._mm256_add_epi32(first, lane_index))
            } else {
                let [bx, by, bz] = map8(simd, frame, x, y, z);
                let mask = overlap8(
                    simd,
                    avx._mm256_sub_ps(fx, bx),
                    avx._mm256_sub_ps(fy, by),
                    avx._mm256_sub_ps(fz, bz),
                    avx._mm256_add_ps(fr, r),
                );
                let first = avx._mm256_set1_epi32((u32::from(sa) | kids.first << 16) as i32);
                let kid = avx2._mm256_slli_epi32::<16>(lane_index);
                (mask, avx2._mm256_add_epi32(first, kid))
            };
            let order: __m256i = pulp::cast(KEPT_EIGHT[mask]);
            let packed: [[u16; 2]; 8] =
                pulp::cast(avx2._mm256_permutevar8x32_epi32(entries, order));
            let slots: &mut [[u16; 2]; 8] = match out.get_mut(end..end + 8) {
                Some(s) => s.try_into().unwrap_or_else(|_| unreachable!()),
                None => unreachable!("expand: `out` holds 8 slots per entry"),
            };
            *slots = packed;
            end += mask.count_ones() as usize;
            if at_leaves && end > 0 {
                break;
            }
        }
        (end, tests)
    }
}

// The eight-lane arithmetic of [`Avx2`], as functions rather than closures: a closure is
// compiled without the processor's features of the function it is written in, and its
// intrinsics, unless it is inlined, become calls.

/// Four vectors of a sphere's children as one of eight lanes.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(super) fn eight(v: &[Vec4; 2]) -> std::arch::x86_64::__m256 {
    pulp::cast([v[0].to_array(), v[1].to_array()])
}

/// Which of eight sphere pairs overlap (bit q for lane q): [`overlap_mask`]'s arithmetic, in
/// the same order, in each lane.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(super) fn overlap8(
    simd: V3,
    dx: std::arch::x86_64::__m256,
    dy: std::arch::x86_64::__m256,
    dz: std::arch::x86_64::__m256,
    r: std::arch::x86_64::__m256,
) -> usize {
    use std::arch::x86_64::_CMP_LE_OQ;
    let avx = simd.avx;
    let d2 = avx._mm256_add_ps(
        avx._mm256_add_ps(avx._mm256_mul_ps(dx, dx), avx._mm256_mul_ps(dy, dy)),
        avx._mm256_mul_ps(dz, dz),
    );
    let le = avx._mm256_cmp_ps::<_CMP_LE_OQ>(d2, avx._mm256_mul_ps(r, r));
    avx._mm256_movemask_ps(le) as usize & 0xff
}

/// Centres of eight B-spheres in A's frame: [`PairFrame::map_lanes`]'s arithmetic, in the
/// same order, in each lane.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(super) fn map8(
    simd: V3,
    frame: &PairFrame,
    x: std::arch::x86_64::__m256,
    y: std::arch::x86_64::__m256,
    z: std::arch::x86_64::__m256,
) -> [std::arch::x86_64::__m256; 3] {
    let avx = simd.avx;
    let (m, t) = (&frame.m, frame.t);
    let mut rows = [avx._mm256_setzero_ps(); 3];
    for (c, row) in rows.iter_mut().enumerate() {
        let (mx, my) = (
            avx._mm256_set1_ps(m.x_axis[c]),
            avx._mm256_set1_ps(m.y_axis[c]),
        );
        let (mz, tc) = (avx._mm256_set1_ps(m.z_axis[c]), avx._mm256_set1_ps(t[c]));
        *row = avx._mm256_add_ps(
            avx._mm256_add_ps(
                avx._mm256_add_ps(avx._mm256_mul_ps(mx, x), avx._mm256_mul_ps(my, y)),
                avx._mm256_mul_ps(mz, z),
            ),
            tc,
        );
    }
    rows
}

/// For each 8-bit overlap mask, its set lanes in increasing order, then zeros: the permutation
/// that packs the kept children of [`Avx2`]'s test to the front.
#[cfg(target_arch = "x86_64")]
pub(super) const KEPT_EIGHT: [[u32; 8]; 256] = {
    let mut table = [[0u32; 8]; 256];
    let mut mask = 0;
    while mask < 256 {
        let (mut q, mut at) = (0, 0);
        while q < 8 {
            if mask & (1 << q) != 0 {
                table[mask][at] = q as u32;
                at += 1;
            }
            q += 1;
        }
        mask += 1;
    }
    table
};
