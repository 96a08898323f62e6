//! The descent of one pair, one level of one tree per step, over a run of pairs with its own
//! scratch arena (a [`Lane`]), and the shape truth's test at the leaves.

use super::*;
use crate::simd::widest;

/// Mutable view of a run of pairs with its own scratch arena: what one step needs. Lanes over
/// disjoint runs can step in parallel ([`NarrowPhase::resolve_all`]).
pub(super) struct Lane<'a> {
    pub(super) pairs: &'a mut [PairState],
    /// Last frame's near misses (shape truth).
    pub(super) near: &'a NearTable,
    /// Where a near miss settled this frame leaves its memo, index-parallel to `pairs` (empty
    /// under the leaf truth).
    pub(super) memo_out: &'a mut [Memo],
    pub(super) frames: &'a mut [PairFrame],
    /// Pairs are resolved one at a time, each in one go: every pair's frame is `frames[0]`.
    pub(super) one_frame: bool,
    /// Test eight children at a time where the processor can ([`Avx2`]).
    pub(super) wide: bool,
    pub(super) arena: &'a mut Vec<[u16; 2]>,
    pub(super) scratch: &'a mut [Vec<[u16; 2]>; 2],
    pub(super) witness: &'a [Witness],
    pub(super) tests: &'a mut u64,
}

/// One pair's step (or, `WHOLE`, its whole descent) in eight-lane kernels, as the value pulp's
/// `vectorize` compiles for AVX2, rather than a closure. Why: a closure this small is handed
/// over in registers, and the compiler then left the closure's body (everything inlined into
/// it) out of line, compiled without the processor's features, with every intrinsic a call:
/// pairs stepped or resolved one at a time ran at 30-60 ns a sphere test against 3-6 inside
/// the exact frame's runs, which take the other branch of `vectorize`.
#[cfg(target_arch = "x86_64")]
struct OnePair<'l, 'a, 't, const WHOLE: bool> {
    lane: &'l mut Lane<'a>,
    simd: V3,
    i: usize,
    tree: &'t SphereTree,
    world: &'t World,
}

#[cfg(target_arch = "x86_64")]
impl<const WHOLE: bool> pulp::NullaryFnOnce for OnePair<'_, '_, '_, WHOLE> {
    type Output = StepOutcome;

    #[inline(always)]
    fn call(self) -> StepOutcome {
        let kernel = Avx2(self.simd);
        if WHOLE {
            self.lane
                .resolve_pair_in(kernel, self.i, self.tree, self.world)
        } else {
            self.lane.step_in(kernel, self.i, self.tree, self.world)
        }
    }
}

/// What every lane of a pass reads alike.
#[derive(Clone, Copy)]
pub(super) struct LaneShared<'a> {
    /// Last frame's near misses (shape truth).
    pub(super) near: &'a NearTable,
    /// Last frame's witnesses.
    pub(super) witness: &'a [Witness],
    /// Test eight children at a time where the processor can ([`Avx2`]).
    pub(super) wide: bool,
}

impl<'a> Lane<'a> {
    /// A lane whose pairs are resolved one at a time, each in one go, every pair's frame kept
    /// in `slot`: the lanes of the parallel passes, each with its own storage.
    pub(super) fn one_at_a_time(
        pairs: &'a mut [PairState],
        memo_out: &'a mut [Memo],
        slot: &'a mut [PairFrame; 1],
        shared: LaneShared<'a>,
        (arena, scratch): LaneStore<'a>,
        tests: &'a mut u64,
    ) -> Self {
        Self {
            pairs,
            near: shared.near,
            memo_out,
            frames: slot,
            one_frame: true,
            wide: shared.wide,
            arena,
            scratch,
            witness: shared.witness,
            tests,
        }
    }
}

impl Lane<'_> {
    /// Where pair `i`'s frame is kept.
    #[inline]
    pub(super) fn frame_slot(&self, i: usize) -> usize {
        if self.one_frame { 0 } else { i }
    }

    /// Advance pair `i` by one level of one tree, in the widest [`Kernel`] the processor has.
    pub(super) fn step(&mut self, i: usize, tree: &SphereTree, world: &World) -> StepOutcome {
        self.one_pair::<false>(i, tree, world)
    }

    /// Step pair `i` until it is resolved ([`Self::resolve_pair_in`]), in the widest
    /// [`Kernel`] the processor has.
    pub(super) fn resolve_pair(
        &mut self,
        i: usize,
        tree: &SphereTree,
        world: &World,
    ) -> StepOutcome {
        self.one_pair::<true>(i, tree, world)
    }

    /// Pair `i`'s step, or (`WHOLE`) its whole descent, in the widest [`Kernel`] the processor
    /// has (see [`OnePair`]).
    fn one_pair<const WHOLE: bool>(
        &mut self,
        i: usize,
        tree: &SphereTree,
        world: &World,
    ) -> StepOutcome {
        #[cfg(target_arch = "x86_64")]
        if let Some(simd) = V3::try_new().filter(|_| self.wide) {
            return simd.vectorize(OnePair::<WHOLE> {
                lane: self,
                simd,
                i,
                tree,
                world,
            });
        }
        if WHOLE {
            self.resolve_pair_in(Baseline, i, tree, world)
        } else {
            self.step_in(Baseline, i, tree, world)
        }
    }

    /// Resolve every open pair of the lane in one go, each pair's state first written from
    /// `cands` where it has one (index-parallel), listing the colliding pairs (numbered from
    /// `base`) in `hits`: a run of [`NarrowPhase::resolve_runs`], the processor asked once for
    /// its widest [`Kernel`]. `go_on` is asked before each block of [`TALLY_BLOCK`] pairs;
    /// returns the pairs gone through (all of them unless it said stop, else a whole number of
    /// blocks: the states of the rest are not written).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn resolve_run<T>(
        &mut self,
        cands: &[(u32, u32)],
        base: usize,
        hits: (&mut Vec<u32>, &mut Vec<u32>),
        tree: &SphereTree,
        world: &World,
        mut tally: Option<(Tally<'_, T>, &mut T)>,
        go_on: &mut dyn FnMut() -> bool,
    ) -> usize {
        widest!(
            V3 if self.wide,
            |simd| self.resolve_run_in(
                Avx2(simd),
                cands,
                base,
                hits,
                tree,
                world,
                &mut tally,
                go_on
            ),
            self.resolve_run_in(Baseline, cands, base, hits, tree, world, &mut tally, go_on),
        )
    }

    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    pub(super) fn resolve_run_in<K: Kernel, T>(
        &mut self,
        kernel: K,
        cands: &[(u32, u32)],
        base: usize,
        (hits, near): (&mut Vec<u32>, &mut Vec<u32>),
        tree: &SphereTree,
        world: &World,
        tally: &mut Option<(Tally<'_, T>, &mut T)>,
        go_on: &mut dyn FnMut() -> bool,
    ) -> usize {
        let n = self.pairs.len();
        let leaves = near_leaves(tree);
        for start in (0..n).step_by(TALLY_BLOCK) {
            if !go_on() {
                return start;
            }
            let end = (start + TALLY_BLOCK).min(n);
            for i in start..end {
                if let Some(&(a, b)) = cands.get(i) {
                    self.pairs[i] = PairState::new(a, b);
                }
                if self.pairs[i].status.is_open() {
                    self.resolve_pair_in(kernel, i, tree, world);
                    // Resolved pairs keep no list: one pair's descent at a time.
                    self.arena.clear();
                }
                if self.pairs[i].status == PairStatus::Colliding {
                    hits.push((base + i) as u32);
                } else if near_miss(&self.pairs[i], leaves) {
                    near.push((base + i) as u32);
                }
            }
            if let Some((f, acc)) = tally {
                f(&self.pairs[start..end], acc);
            }
        }
        n
    }

    /// Advance pair `i` by one level of one tree. A pair that collided last frame first re-tests the
    /// leaf pair that proved it (one test); if that still overlaps, the pair is resolved colliding
    /// at the leaves, exactly as its full descent would have.
    #[inline(always)]
    pub(super) fn step_in<K: Kernel>(
        &mut self,
        kernel: K,
        i: usize,
        tree: &SphereTree,
        world: &World,
    ) -> StepOutcome {
        let depth = tree.depth() as u8;
        let p = self.pairs[i];
        debug_assert!(p.status.is_open());
        if p.status == PairStatus::Untested {
            let (a, b) = (p.a as usize, p.b as usize);
            let root = tree.sphere(0);
            let mut framed = false;
            // A near miss of last frame whose roots still touch (a root test settles the rest
            // for less): its proof may still hold; if not, its stars are
            // tested at once. Apart, the pair is settled whatever its leaves do (the shape
            // truth is leaves and stars; stars apart is enough). Touching, it goes down the
            // leaves as any pair does and ends at the shape level again (a few hundred pairs a
            // frame at N = 10,000, most of them with a witness).
            let d = LVec3::from((world.position[b] - world.position[a]).as_vec3());
            let roots_touch = d.length_squared() <= (root.w + root.w) * (root.w + root.w);
            if let Some(m) = self.near.get(p.a, p.b).filter(|_| roots_touch) {
                let pose = shape_pose(world, a, b);
                let clearance = f64::from(m.clearance);
                let motion = m.motion(&pose, tree.geometry().radius);
                let proof = if motion < clearance {
                    *self.tests += 1;
                    Some(clearance - motion)
                } else {
                    *self.tests += SHAPE_TEST_COST;
                    tree.geometry().intersects_or_bound(&pose)
                };
                if let Some(clearance) = proof {
                    let memo = self.memo_out.get_mut(i);
                    return settle_apart(
                        &mut self.pairs[i],
                        memo,
                        m.leaves,
                        clearance,
                        &pose,
                        depth,
                    );
                }
            }
            if let Some(w) = self.witness.get(a).filter(|w| w.partner == p.b) {
                let frame = PairFrame::new(world, a, b);
                let k = self.frame_slot(i);
                self.frames[k] = frame;
                framed = true;
                let (la, lb) = (
                    tree.sphere(w.leaves[0] as usize),
                    tree.sphere(w.leaves[1] as usize),
                );
                *self.tests += 2;
                let st = &mut self.pairs[i];
                if spheres_overlap(la, frame.map(lb), lb.w) {
                    st.last = w.leaves;
                    st.levels = [depth, depth];
                    return leaves_overlap(st, tree);
                }
            } else {
                *self.tests += 1;
            }
            let st = &mut self.pairs[i];
            // The root is centred on its body, so the root test needs the centre distance alone:
            // no rotation into A's frame (whose length it would only round), and no frame for the
            // pairs it settles, which are most of them.
            let d = LVec3::from((world.position[b] - world.position[a]).as_vec3());
            let reach = root.w + root.w;
            if d.length_squared() > reach * reach {
                return resolve(st, PairStatus::Separate, 1);
            }
            if !framed {
                self.frames[if self.one_frame { 0 } else { i }] = PairFrame::new(world, a, b);
            }
            st.last = [0, 0];
            st.levels = [1, 1];
            if depth == 1 {
                return leaves_overlap(st, tree);
            }
            st.status = PairStatus::Active;
            st.list_start = self.arena.len() as u32;
            st.list_len = 1;
            self.arena.push([0, 0]);
            return StepOutcome::Active;
        }
        if shape_pending(&p, depth) {
            return shape_step(
                &mut self.pairs[i],
                self.tests,
                self.memo_out.get_mut(i),
                tree,
                world,
            );
        }
        // A to its leaves against B's root first, then B (see `next_levels`).
        let (descend_a, new_levels) = next_levels(p.levels, depth);
        let at_leaves = new_levels == [depth, depth];
        let frame = self.frames[self.frame_slot(i)];
        let (lo, hi) = (p.list_start as usize, (p.list_start + p.list_len) as usize);
        // The arena is grown to the worst case (8 children per entry) and cut back after.
        let start = self.arena.len();
        self.arena.resize(start + (hi - lo) * 8, [0, 0]);
        let (head, out) = self.arena.split_at_mut(start);
        let (found, tests) = kernel.expand(tree, &frame, descend_a, at_leaves, &head[lo..hi], out);
        self.arena.truncate(start + found);
        *self.tests += tests;
        let st = &mut self.pairs[i];
        st.levels = new_levels;
        let level = new_levels[0].max(new_levels[1]);
        if at_leaves && found > 0 {
            st.last = self.arena[start];
            self.arena.truncate(start);
            return leaves_overlap(st, tree);
        }
        if found == 0 {
            return resolve(st, PairStatus::Separate, level);
        }
        st.last = self.arena[start + found - 1];
        st.list_start = start as u32;
        st.list_len = found as u32;
        StepOutcome::Active
    }

    /// Step pair `i` until it is resolved: exactly what repeated [`Self::step`] calls do (the same
    /// tests in the same order, the same state at the end), but after the first step the descent
    /// runs level after level between two scratch lists instead of through the pair's state and
    /// the arena, which costs a store and a reload of both per level.
    #[inline(always)]
    pub(super) fn resolve_pair_in<K: Kernel>(
        &mut self,
        kernel: K,
        i: usize,
        tree: &SphereTree,
        world: &World,
    ) -> StepOutcome {
        let o = self.step_in(kernel, i, tree, world);
        if o != StepOutcome::Active {
            return o;
        }
        let depth = tree.depth() as u8;
        let p = self.pairs[i];
        if shape_pending(&p, depth) {
            return shape_step(
                &mut self.pairs[i],
                self.tests,
                self.memo_out.get_mut(i),
                tree,
                world,
            );
        }
        // Under the shape truth a pair resolved in one go whose roots touch has its stars
        // tested at once, below the root: the star's seven parts, pruned by their own bounds,
        // settle it for less than a descent through 80 leaves a side (at N = 10,000 about 290
        // ns a pair whose roots touch on the leaves, where bodies interpenetrate their leaf
        // envelopes far more under this truth). Apart, that is the answer; touching, the
        // leaves are descended to confirm it (the truth is leaves and stars), and their hit
        // needs no second shape test.
        let mut touching = false;
        if tree.truth() == Truth::Shape && p.levels == [1, 1] && depth > 1 {
            let pose = shape_pose(world, p.a as usize, p.b as usize);
            *self.tests += SHAPE_TEST_COST;
            match tree.geometry().intersects_or_bound(&pose) {
                Some(clearance) => {
                    let leaf = tree.leaves().start as u16;
                    self.arena.truncate(p.list_start as usize);
                    // A pair of leaves as its last overlap marks it a near miss (see
                    // `near_miss`); which leaves is of no consequence for a settled pair.
                    let memo = self.memo_out.get_mut(i);
                    return settle_apart(
                        &mut self.pairs[i],
                        memo,
                        [leaf, leaf],
                        clearance,
                        &pose,
                        depth,
                    );
                }
                None => touching = true,
            }
        }
        let frame = self.frames[self.frame_slot(i)];
        let [cur, next] = &mut *self.scratch;
        let (lo, hi) = (p.list_start as usize, (p.list_start + p.list_len) as usize);
        // Both lists only ever grow (their lengths are kept, the live part is tracked in `len`),
        // so after the first frames no level writes a byte more than it keeps.
        let mut len = hi - lo;
        if cur.len() < len {
            cur.resize(len, [0, 0]);
        }
        cur[..len].copy_from_slice(&self.arena[lo..hi]);
        // The list was the arena's last (a first step pushes it there): give its room back.
        if hi == self.arena.len() {
            self.arena.truncate(lo);
        }
        let mut levels = p.levels;
        let mut last = p.last;
        loop {
            let (descend_a, new_levels) = next_levels(levels, depth);
            let at_leaves = new_levels == [depth, depth];
            if next.len() < len * 8 {
                next.resize(len * 8, [0, 0]);
            }
            let (found, tests) = kernel.expand(
                tree,
                &frame,
                descend_a,
                at_leaves,
                &cur[..len],
                &mut next[..len * 8],
            );
            *self.tests += tests;
            levels = new_levels;
            let level = new_levels[0].max(new_levels[1]);
            let status = if at_leaves && found > 0 {
                last = next[0];
                PairStatus::Colliding
            } else if found == 0 {
                PairStatus::Separate
            } else {
                last = next[found - 1];
                std::mem::swap(cur, next);
                len = found;
                continue;
            };
            let st = &mut self.pairs[i];
            st.levels = levels;
            st.last = last;
            if status == PairStatus::Colliding && tree.truth() == Truth::Shape && !touching {
                return shape_step(st, self.tests, self.memo_out.get_mut(i), tree, world);
            }
            return resolve(st, status, level);
        }
    }
}

/// Which tree the next step descends, and the levels after it.
///
/// A descends all the way to its leaves against B's root first, then B. B's root is its tightest
/// bound: the octree's intermediate spheres reach out to about 1.6R, the root only to 1.11R, so
/// pruning A against the root discards most of A's spheres before B's looser levels are opened.
/// At N = 10,000 this needs 2.6x fewer sphere tests per frame than alternating the trees, with the
/// same answer (both end at leaf against leaf).
#[inline]
pub(super) fn next_levels(levels: [u8; 2], depth: u8) -> (bool, [u8; 2]) {
    if levels[0] < depth {
        (true, [levels[0] + 1, levels[1]])
    } else {
        (false, [levels[0], levels[1] + 1])
    }
}

/// Settle pair `st` apart on the shape, as a near miss whose leaf pair is `leaves`, leaving its
/// proof (at least `clearance` apart at `pose`) in `memo` for the next frame.
#[inline]
pub(super) fn settle_apart(
    st: &mut PairState,
    memo: Option<&mut Memo>,
    leaves: [u16; 2],
    clearance: f64,
    pose: &Pose,
    depth: u8,
) -> StepOutcome {
    st.last = leaves;
    st.levels = [depth, depth];
    if let Some(out) = memo {
        *out = Memo::new(st.a, st.b, leaves, clearance, pose);
    }
    resolve(st, PairStatus::Separate, depth)
}

pub(super) fn resolve(st: &mut PairState, status: PairStatus, level: u8) -> StepOutcome {
    st.status = status;
    st.resolved_level = level;
    st.list_len = 0;
    if status == PairStatus::Colliding {
        StepOutcome::Hit
    } else {
        StepOutcome::Separate
    }
}

/// Sphere tests a pair's shape test counts for in the frame's test count and in sphere-test
/// budgets. The shipped shape-truth calibration table was fitted with 16. One run of
/// `cargo bench -p foveal-engine --bench step -- 'shape/|narrow_steady/'` measured 186 ns a
/// pair whose leaves overlap against 5.9 ns a sphere test of the leaf truth's steady narrow
/// phase, a ratio of 32 (docs/BENCHMARKS.md "Shape truth"); raising it means regenerating that
/// table and the shape truth's golden hash with it.
pub const SHAPE_TEST_COST: u64 = 16;

/// A pair's leaves overlap: under the leaf truth it collides; under the shape truth it waits for
/// its shape test, one more interruptible level (a pair deemed here is deemed colliding).
#[inline]
pub(super) fn leaves_overlap(st: &mut PairState, tree: &SphereTree) -> StepOutcome {
    let depth = tree.depth() as u8;
    if tree.truth() == Truth::LeafSpheres {
        return resolve(st, PairStatus::Colliding, depth);
    }
    st.status = PairStatus::Active;
    st.list_len = 0;
    StepOutcome::Active
}

/// Whether pair `p` is open with its leaves overlapping and its shape test still to run: the
/// only open state at both trees' leaves (a descent that reaches them settles the pair or hands
/// it here).
#[inline]
pub(super) fn shape_pending(p: &PairState, depth: u8) -> bool {
    p.status == PairStatus::Active && p.levels == [depth, depth]
}

/// The shape level: test the two stars themselves (docs/DESIGN.md "Exact answer").
///
/// A pair found apart leaves its proof in `memo` ([`crate::near_memo`]): next frame it may be
/// settled by its motion alone.
#[inline(never)]
pub(super) fn shape_step(
    st: &mut PairState,
    tests: &mut u64,
    memo: Option<&mut Memo>,
    tree: &SphereTree,
    world: &World,
) -> StepOutcome {
    *tests += SHAPE_TEST_COST;
    let pose = shape_pose(world, st.a as usize, st.b as usize);
    let depth = tree.depth() as u8;
    match tree.geometry().intersects_or_bound(&pose) {
        None => resolve(st, PairStatus::Colliding, depth),
        Some(clearance) => {
            if let Some(m) = memo {
                *m = Memo::new(st.a, st.b, st.last, clearance, &pose);
            }
            resolve(st, PairStatus::Separate, depth)
        }
    }
}
