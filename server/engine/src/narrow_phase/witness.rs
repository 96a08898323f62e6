//! Temporal coherence: the leaf pair that proved a collision last frame (a witness), and the near
//! misses of the shape truth remembered between frames.

use super::*;

/// Temporal coherence for colliding pairs: the leaf pair that proved a collision last frame.
/// Contact persists over several frames, and one leaf-leaf overlap settles a pair exactly, so a
/// persisting pair is resolved by one test instead of a descent of a hundred or more.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Witness {
    pub(super) partner: u32,
    pub(super) leaves: [u16; 2],
}

/// Read every body's centre, basis and witness in order, so that a thread of a parallel narrow
/// phase takes them into its cache as one stream before its runs (up to [`WARM_MAX_BYTES`]).
///
/// Integration, on the frame's threads, has just written each body's centre and basis on one
/// of them, and the frame's thread the witnesses; each run reads bodies from all over. Without
/// this, a thread met the others' lines one miss at a time, inside the pairs' descents: at
/// N = 10,000 the narrow phase took 21% more processor time on two threads than on one for the
/// same pairs, and the load of a body's basis 6.84% of its samples against 2.27%. Read in order,
/// the lines arrive many at a time (about 0.7 MiB at N = 10,000), and the step took 6% less
/// time. Only a hint: nothing read here is used.
pub(super) fn warm_bodies(world: &World, witness: &[Witness]) {
    let mut bits = 0u64;
    for p in &world.position {
        bits ^= p.x.to_bits();
    }
    for b in &world.basis {
        bits ^= u64::from(b.x_axis.x.to_bits());
    }
    for w in witness {
        bits ^= u64::from(w.partner);
    }
    std::hint::black_box(bits);
}

pub(super) const NO_WITNESS: Witness = Witness {
    partner: u32::MAX,
    leaves: [NONE, NONE],
};

/// Keep colliding pair `p`'s witness under its first body, and note the body as holding one (see
/// [`NarrowPhase::forget_witnesses`]).
#[inline]
pub(super) fn remember(witness: &mut [Witness], witnessed: &mut Vec<u32>, p: &PairState) {
    witness[p.a as usize] = Witness {
        partner: p.b,
        leaves: p.last,
    };
    witnessed.push(p.a);
}

/// Keep pair `p`'s leaf pair as its first body's witness unless a colliding pair already holds
/// that body's slot this frame: a near miss (see [`near_miss`]) is worth a witness too, but a
/// collision more.
#[inline]
pub(super) fn remember_near(witness: &mut [Witness], witnessed: &mut Vec<u32>, p: &PairState) {
    if witness[p.a as usize].partner == NO_WITNESS.partner {
        remember(witness, witnessed, p);
    }
}

/// Whether pair `p` was settled apart by the shape level (under the shape truth): its leaves
/// overlap (`last` is a pair of leaves, indices from `leaves` on) and its stars do not touch.
/// Such pairs are approaching or interlocked, and next frame their leaves most likely overlap
/// again: with the leaf pair as a witness the pair goes straight to its shape test (two sphere
/// tests) instead of a descent through two interpenetrating trees (hundreds). Under the leaf
/// truth no separate pair has a pair of leaves as its last overlap.
#[inline]
pub(super) fn near_miss(p: &PairState, leaves: Option<u16>) -> bool {
    leaves.is_some_and(|leaves| {
        p.status == PairStatus::Separate
            && p.last[0] != NONE
            && p.last[0] >= leaves
            && p.last[1] >= leaves
    })
}

/// The memo slots of the first `n` pairs in runs of `size`, one per run of pairs (empty slices
/// under the leaf truth, which keeps none).
pub(super) fn memo_chunks(
    memo_out: &mut [Memo],
    shape: bool,
    n: usize,
    size: usize,
) -> Box<dyn Iterator<Item = &mut [Memo]> + '_> {
    if shape {
        Box::new(memo_out[..n].chunks_mut(size))
    } else {
        Box::new(std::iter::repeat_with(|| -> &mut [Memo] { &mut [] }))
    }
}

/// The first leaf's index for [`near_miss`] under the shape truth, `None` under the leaf truth.
#[inline]
pub(super) fn near_leaves(tree: &SphereTree) -> Option<u16> {
    (tree.truth() == Truth::Shape).then(|| tree.leaves().start as u16)
}
