//! What a pair's traversal state says about it: the probability that it is truly *not* colliding,
//! the true gap it has if so, and the sphere tests still needed to settle it, measured on exact runs
//! of the paper scene (DESIGN.md "Scene") and shipped as a small table.
//!
//! These are the prices of the [`super::Priced`] scheduler. Deeming a pair that truly collides costs
//! nothing perceptually (section 3: the error is the gap left by a *non*-collision), so the value of
//! working on a pair is the false-positive error it is expected to remove, and its price the tests
//! it is expected to take. Both depend strongly on where the pair stands: about half of all
//! candidate pairs are settled separate by the one root test, pairs whose centres are close almost
//! always collide, and a pair whose overlap list has grown long is expensive to finish.
//!
//! A state is keyed by the stage of the traversal (0 untested, then one per level descended), the
//! length of the overlap list (16 buckets; for untested pairs, whether last frame's witness leaf
//! pair will be re-tested, or else what the pair cost last frame if the scheduler remembers it:
//! see [`remembered_key`]), and the centre distance over the root diameter (64 buckets). Sparse bins
//! are shrunk towards the pooled estimate of their (stage, list) row and that towards the stage, so
//! every bin has a usable value. Keys are scale-free (distances over the root diameter, gaps over the
//! shape radius), so the table holds for any shape radius; it is tied to the tree depth, and a
//! simulation with another depth calibrates its own table at start-up on a small copy of its scene
//! ([`crate::calibrate`], which runs whole simulations and so sits above the schedulers).
//!
//! `foveal-bench calibrate` regenerates the shipped table and reports its reliability on held-out
//! seeds.

use serde::Serialize;

use crate::config::{TreeKind, Truth};
use crate::narrow_phase::NarrowPhase;

/// Centre-distance buckets (over the root diameter) per state.
pub const DIST_BUCKETS: usize = 64;
/// Centre distance / root diameter covered by the buckets; candidate pairs reach sqrt(3).
pub(crate) const DIST_RANGE: f32 = 2.0;
/// Overlap-list buckets: lengths 1 to 8 each their own, then 9-12, 13-16, 17-24, 25-32, 33-48,
/// 49-64, 65-128 and beyond (see [`list_bucket`]).
pub const LIST_BUCKETS: usize = 32;
/// Length buckets of [`list_bucket`]; the list key is that bucket plus this for pairs with a
/// witness from last frame (which most likely collide again, at every stage).
pub(crate) const LENGTH_BUCKETS: usize = 16;

/// List key of an untested pair remembered from last frame as settled separate below its root
/// after `cost` sphere tests: 1 to [`LENGTH_BUCKETS`] - 1, by half-octaves of the cost (2 and
/// less, 3, 4-5, 6-7, 8-11, ..., 256 and beyond; a pair settled below its root took at least 9
/// tests, so keys 1-4 do not occur in the paper scene). Why: an untested pair's cost to settle is otherwise
/// priced by its distance alone, while the same pair's cost last frame predicts this frame's
/// closely (bodies move little between frames: the logarithms of the two correlate at 0.92 in
/// the paper scene), and the cost is what a schedule most needs to know (pricing every pair by
/// its true cost would take the share of the achievable reduction at a tenth of the exact cost
/// from 0.79 to 0.88). Untested keys 1-15 are otherwise unused: an untested pair has no list.
#[inline]
pub fn remembered_key(cost: u32) -> usize {
    let c = cost.max(2);
    let octave = 31 - c.leading_zeros() as usize;
    // The upper half of the octave: c >= 2^octave * sqrt(2), i.e. c^2 >= 2^(2 octave + 1).
    let upper = usize::from(u64::from(c) * u64::from(c) >= 1u64 << (2 * octave + 1));
    (2 * octave + upper - 1).min(LENGTH_BUCKETS - 1)
}

/// Bucket of an overlap-list length: exact up to 8 (where a pair's first descents land), then
/// half-octaves.
#[inline]
pub fn list_bucket(len: u32) -> usize {
    match len {
        0..=8 => len.max(1) as usize - 1,
        9..=12 => 8,
        13..=16 => 9,
        17..=24 => 10,
        25..=32 => 11,
        33..=48 => 12,
        49..=64 => 13,
        65..=128 => 14,
        _ => 15,
    }
}
/// Pseudo-count of the shrinkage towards the pooled estimate, for bins with fewer than
/// [`DENSE`] observations; denser bins stand on their own (a pooled cost can be 40 tests where
/// the bin's own is exactly 1).
pub(crate) const SHRINK: f64 = 20.0;
/// Observations from which a bin's own frequencies are used unshrunk.
pub(crate) const DENSE: f64 = 100.0;

/// Horizons (steps ahead) over which a state's [`Bin::rate`] is taken. Why not the mean cost to
/// settle alone: the scheduler may leave a pair after any step, so what a state is worth is the
/// best rate of any plan "work on it for h more steps", as in a Gittins index restricted to fixed
/// horizons. A state that settles half its pairs in the next step and leaves the rest to a long
/// descent is priced by that next step, not by the long mean. A depth-4 pair takes at most 7
/// steps; deeper trees' longer horizons are covered by the whole descent.
pub const HORIZONS: usize = 8;

/// One state's calibrated values.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Bin {
    /// Probability that a pair in this state is truly not colliding.
    pub p_separate: f32,
    /// Mean true gap (leaf-sphere separation, over the shape radius) of such pairs that are not.
    pub gap: f32,
    /// Mean sphere tests from this state until the pair is settled.
    pub cost: f32,
    /// The most false-positive gap settled per sphere test that working on the pair for a few
    /// more steps yields, over horizons of 1 to [`HORIZONS`] steps and to the end (see
    /// [`Observations::record`]): at least `p_separate * gap / cost`, and more where a state
    /// often settles soon but sometimes descends long.
    pub rate: f32,
    /// Observations behind the bin before shrinkage.
    pub count: u32,
}

/// Calibrated values for every state of one tree depth.
#[derive(Debug, Clone, PartialEq)]
pub struct Calibration {
    pub(crate) depth: u8,
    pub(crate) bins: Vec<Bin>,
}

/// Number of open stages of a depth-`depth` traversal: untested (0), then one per level
/// descended up to `2 * depth - 2`, the last one before both trees are at their leaves.
pub(crate) fn stages(depth: u8) -> usize {
    2 * depth as usize - 1
}

/// Distance bucket of a centre distance over the root diameter.
#[inline]
pub fn dist_bucket(dist: f32) -> u8 {
    ((dist.max(0.0) * (DIST_BUCKETS as f32 / DIST_RANGE)) as usize).min(DIST_BUCKETS - 1) as u8
}

/// Steps of [`dist_bucket_of_squared`]'s table over the squared range.
const SQUARED_STEPS: usize = 4096;

/// Distance bucket from the *squared* distance over the root diameter, without a square root:
/// the squared range is cut into fine steps and each step's bucket read from a table. A step is
/// at most 0.004 wide in squared distance, so a step holds at most one bucket edge (buckets are
/// 0.125 wide in distance); the edge's side is then decided by one comparison.
#[inline]
pub fn dist_bucket_of_squared(d2: f32) -> u8 {
    squared_table().bucket(d2)
}

/// The tables of [`dist_bucket_of_squared`], for loops that keep their own copy (no lazy
/// initialisation check per call) and want it branch-free.
#[derive(Debug, Clone)]
pub struct SquaredBuckets {
    /// Bucket of the low end of each squared step.
    low: [u8; SQUARED_STEPS],
    /// Squared lower edge of each bucket after the first (+inf past the last bucket).
    next_edge2: [f32; DIST_BUCKETS + 1],
}

impl Default for SquaredBuckets {
    fn default() -> Self {
        squared_table().clone()
    }
}

impl SquaredBuckets {
    fn new() -> Self {
        let mut low = [0u8; SQUARED_STEPS];
        for (k, v) in low.iter_mut().enumerate() {
            let d2 = k as f32 * (DIST_RANGE * DIST_RANGE / SQUARED_STEPS as f32);
            *v = dist_bucket(d2.sqrt());
        }
        let mut next_edge2 = [f32::INFINITY; DIST_BUCKETS + 1];
        for (lo, e) in next_edge2.iter_mut().enumerate().take(DIST_BUCKETS - 1) {
            let edge = (lo + 1) as f32 * (DIST_RANGE / DIST_BUCKETS as f32);
            *e = edge * edge;
        }
        Self { low, next_edge2 }
    }

    /// The bucket of squared distance `d2` (see [`dist_bucket_of_squared`]).
    #[inline]
    pub fn bucket(&self, d2: f32) -> u8 {
        const RANGE2: f32 = DIST_RANGE * DIST_RANGE;
        // Clamped in f32 and converted through i32: the same step as converting to usize and
        // clamping after, without the unsigned conversion's extra instructions.
        let k = (d2.max(0.0) * (SQUARED_STEPS as f32 / RANGE2)).min((SQUARED_STEPS - 1) as f32)
            as i32 as usize;
        let lo = self.low[k % SQUARED_STEPS];
        // The next bucket starts inside this step if its edge squared is <= d2.
        lo + u8::from(d2 >= self.next_edge2[lo as usize % (DIST_BUCKETS + 1)])
    }
}

fn squared_table() -> &'static SquaredBuckets {
    static TABLE: std::sync::OnceLock<SquaredBuckets> = std::sync::OnceLock::new();
    TABLE.get_or_init(SquaredBuckets::new)
}

/// Bin index of a state.
#[inline]
pub(crate) fn index(stage: u8, list_key: usize, dist: f32) -> usize {
    index_bucket(stage, list_key, dist_bucket(dist))
}

#[inline]
pub(crate) fn index_bucket(stage: u8, list_key: usize, bucket: u8) -> usize {
    (stage as usize * LIST_BUCKETS + list_key) * DIST_BUCKETS + bucket as usize
}

/// The list key of an untested pair (see [`Calibration::initial_index`]).
#[inline]
pub(crate) fn initial_key(witness: bool, remembered: u32) -> usize {
    if witness {
        LENGTH_BUCKETS
    } else if remembered > 0 {
        remembered_key(remembered)
    } else {
        0
    }
}

/// The list key of pair `i`: its overlap-list bucket (0 when untested), plus
/// [`LENGTH_BUCKETS`] if it has a witness from last frame.
#[inline]
pub(crate) fn list_key(np: &NarrowPhase, i: usize) -> usize {
    let p = &np.pairs[i];
    let len = if p.stage() == 0 {
        0
    } else {
        list_bucket(p.pending())
    };
    len + LENGTH_BUCKETS * usize::from(np.has_witness(i))
}

impl Calibration {
    /// A flat table that knows nothing (every state equally likely to collide, equally costly):
    /// for schedulers that do not price their steps.
    pub fn uninformed(depth: u8) -> Self {
        let bin = Bin {
            p_separate: 0.5,
            gap: 0.1,
            cost: 8.0,
            rate: 0.5 * 0.1 / 8.0,
            count: 0,
        };
        Self {
            depth,
            bins: vec![bin; stages(depth.max(1)) * LIST_BUCKETS * DIST_BUCKETS],
        }
    }

    /// The table shipped with the engine, for the depth it was calibrated at (the paper's, 4).
    pub fn shipped() -> Option<Self> {
        Self::shipped_for(Truth::Shape)
    }

    /// The table shipped for `truth` and the default tree: the outcomes a state predicts differ
    /// between the truths (under the shape truth most pairs whose leaves overlap are apart, and a
    /// contact rarely lasts a frame), so each truth has its own, calibrated on the same scenes.
    pub fn shipped_for(truth: Truth) -> Option<Self> {
        Self::shipped_for_tree(truth, TreeKind::default())
    }

    /// The table shipped for `truth` and `tree`: what a state predicts (its odds, its cost)
    /// depends on the spheres it tests, so the default tree and the paper's octree each have
    /// their own (`server/engine/data/calibration-<truth>[-octree].bin`); the fitted octree has
    /// none and is calibrated when a scene is built.
    pub fn shipped_for_tree(truth: Truth, tree: TreeKind) -> Option<Self> {
        let bytes: &[u8] = match (truth, tree) {
            (Truth::LeafSpheres, TreeKind::Parts) => {
                include_bytes!("../../data/calibration-leaf-spheres.bin")
            }
            (Truth::Shape, TreeKind::Parts) => include_bytes!("../../data/calibration-shape.bin"),
            (Truth::LeafSpheres, TreeKind::Octree) => {
                include_bytes!("../../data/calibration-leaf-spheres-octree.bin")
            }
            (Truth::Shape, TreeKind::Octree) => {
                include_bytes!("../../data/calibration-shape-octree.bin")
            }
            (_, TreeKind::Fitted) => return None,
        };
        Self::from_bytes(bytes).ok()
    }

    /// Tree depth the table is for.
    pub fn depth(&self) -> u8 {
        self.depth
    }

    /// Every bin, in index order.
    pub fn bins(&self) -> &[Bin] {
        &self.bins
    }

    /// Bin index for pair `i` of `np` in distance bucket `bucket` ([`dist_bucket`]).
    #[inline]
    pub fn index_of(&self, np: &NarrowPhase, i: usize, bucket: u8) -> usize {
        let stage = np.pairs[i].stage().min(stages(self.depth) as u8 - 1);
        index_bucket(stage, list_key(np, i), bucket)
    }

    /// Bin index of an untested pair (stage 0) in distance bucket `bucket`: with a witness from
    /// last frame, or else remembered as settled separate below its root after `remembered`
    /// sphere tests (0: not remembered; see [`remembered_key`]).
    #[inline]
    pub fn initial_index(&self, witness: bool, remembered: u32, bucket: u8) -> usize {
        index_bucket(0, initial_key(witness, remembered), bucket)
    }

    /// The table as the engine ships it (`server/engine/data/calibration-<truth>.bin`, read
    /// with `include_bytes!`): [`TABLE_MAGIC`], the depth (one byte), the bin count (u32), then
    /// per bin `p_separate`, `gap`, `cost`, `rate` (f32) and `count` (u32), all little-endian.
    /// Binary, so that a table is data the engine reads, not 14,000 lines of generated source
    /// the compiler parses, and each value round-trips bit for bit.
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(TABLE_MAGIC.len() + 5 + self.bins.len() * BIN_BYTES);
        out.extend_from_slice(TABLE_MAGIC);
        out.push(self.depth);
        out.extend_from_slice(&(self.bins.len() as u32).to_le_bytes());
        for b in &self.bins {
            for v in [b.p_separate, b.gap, b.cost, b.rate] {
                out.extend_from_slice(&v.to_le_bytes());
            }
            out.extend_from_slice(&b.count.to_le_bytes());
        }
        out
    }

    /// Read a table written by [`Self::to_bytes`]; refused, naming what is wrong, when the
    /// header, the bin count for its depth or the length do not match, or a value is not finite.
    pub fn from_bytes(bytes: &[u8]) -> Result<Self, TableError> {
        let body = bytes
            .strip_prefix(TABLE_MAGIC.as_slice())
            .ok_or(TableError::Magic)?;
        let (&depth, body) = body.split_first().ok_or(TableError::Truncated)?;
        if !(1..=crate::config::MAX_DEPTH as u8).contains(&depth) {
            return Err(TableError::Depth(depth));
        }
        let (count, body) = body.split_first_chunk::<4>().ok_or(TableError::Truncated)?;
        let count = u32::from_le_bytes(*count) as usize;
        let want = stages(depth) * LIST_BUCKETS * DIST_BUCKETS;
        if count != want {
            return Err(TableError::Bins { count, want, depth });
        }
        if body.len() != count * BIN_BYTES {
            return Err(TableError::Length {
                got: body.len(),
                want: count * BIN_BYTES,
            });
        }
        let mut bins = Vec::with_capacity(count);
        for chunk in body.chunks_exact(BIN_BYTES) {
            let word = |k: usize| {
                [
                    chunk[4 * k],
                    chunk[4 * k + 1],
                    chunk[4 * k + 2],
                    chunk[4 * k + 3],
                ]
            };
            let [p_separate, gap, cost, rate] = [0, 1, 2, 3].map(|k| f32::from_le_bytes(word(k)));
            if ![p_separate, gap, cost, rate].iter().all(|v| v.is_finite()) {
                return Err(TableError::NotFinite(bins.len()));
            }
            bins.push(Bin {
                p_separate,
                gap,
                cost,
                rate,
                count: u32::from_le_bytes(word(4)),
            });
        }
        Ok(Self { depth, bins })
    }
}

/// The first bytes of a calibration table file.
pub const TABLE_MAGIC: &[u8; 8] = b"FOVCAL1\0";

/// Bytes a bin takes in a table file: four f32 and a u32.
const BIN_BYTES: usize = 20;

/// Why a calibration table file was refused.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum TableError {
    #[error("not a calibration table (it does not start with FOVCAL1)")]
    Magic,
    #[error("calibration table ends inside its header")]
    Truncated,
    #[error("calibration table for tree depth {0}: depths 1 to {max} are supported", max = crate::config::MAX_DEPTH)]
    Depth(u8),
    #[error("calibration table holds {count} bins; depth {depth} needs {want}")]
    Bins {
        count: usize,
        want: usize,
        depth: u8,
    },
    #[error("calibration table holds {got} bytes of bins; its bin count needs {want}")]
    Length { got: usize, want: usize },
    #[error("calibration table bin {0} holds a value that is not finite")]
    NotFinite(usize),
}
