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
//! simulation with another depth calibrates its own table at start-up on a small copy of its scene.
//!
//! `foveal-bench calibrate` regenerates the shipped table and reports its reliability on held-out
//! seeds.

use serde::Serialize;

use crate::config::{SceneConfig, Truth};
use crate::narrow_phase::{NarrowPhase, StepOutcome, separation, shape_separation};
use crate::shape::Star;
use crate::sphere_tree::SphereTree;
use crate::validate::ConfigError;
use crate::{BudgetSpec, FrozenClock, SchedulerKind, SimConfig, Simulation};

/// Centre-distance buckets (over the root diameter) per state.
pub const DIST_BUCKETS: usize = 64;
/// Centre distance / root diameter covered by the buckets; candidate pairs reach sqrt(3).
const DIST_RANGE: f32 = 2.0;
/// Overlap-list buckets: lengths 1 to 8 each their own, then 9-12, 13-16, 17-24, 25-32, 33-48,
/// 49-64, 65-128 and beyond (see [`list_bucket`]).
pub const LIST_BUCKETS: usize = 32;
/// Length buckets of [`list_bucket`]; the list key is that bucket plus this for pairs with a
/// witness from last frame (which most likely collide again, at every stage).
const LENGTH_BUCKETS: usize = 16;

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
const SHRINK: f64 = 20.0;
/// Observations from which a bin's own frequencies are used unshrunk.
const DENSE: f64 = 100.0;

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
    depth: u8,
    bins: Vec<Bin>,
}

/// Number of open stages of a depth-`depth` traversal: untested (0), then one per level
/// descended up to `2 * depth - 2`, the last one before both trees are at their leaves.
fn stages(depth: u8) -> usize {
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
fn index(stage: u8, list_key: usize, dist: f32) -> usize {
    index_bucket(stage, list_key, dist_bucket(dist))
}

#[inline]
fn index_bucket(stage: u8, list_key: usize, bucket: u8) -> usize {
    (stage as usize * LIST_BUCKETS + list_key) * DIST_BUCKETS + bucket as usize
}

/// The list key of an untested pair (see [`Calibration::initial_index`]).
#[inline]
fn initial_key(witness: bool, remembered: u32) -> usize {
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
fn list_key(np: &NarrowPhase, i: usize) -> usize {
    let p = &np.pairs[i];
    let len = if p.stage() == 0 {
        0
    } else {
        list_bucket(p.pending())
    };
    len + LENGTH_BUCKETS * usize::from(np.has_witness(i))
}

impl Calibration {
    /// The shipped table for the paper's depth, or a table calibrated now for another depth.
    pub fn for_tree(tree: &SphereTree, scene: &SceneConfig) -> Result<Self, ConfigError> {
        let depth = tree.depth() as u8;
        if let Some(shipped) = Self::shipped_for(tree.truth()).filter(|c| c.depth == depth) {
            return Ok(shipped);
        }
        // A small copy of the paper scene at this depth: a few hundred thousand state visits,
        // in well under a second.
        let mut small = SceneConfig::paper(1_000, 1);
        small.depth = scene.depth;
        small.shape_radius = scene.shape_radius;
        small.truth = tree.truth();
        Ok(Observations::record(&[small], 30, 10)?.calibration())
    }

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

    /// The table shipped for `truth`: the outcomes a state predicts differ between the truths
    /// (under the shape truth most pairs whose leaves overlap are apart, and a contact rarely
    /// lasts a frame), so each truth has its own, calibrated on the same scenes.
    pub fn shipped_for(truth: Truth) -> Option<Self> {
        let bytes: &[u8] = match truth {
            Truth::LeafSpheres => include_bytes!("../../data/calibration-leaf-spheres.bin"),
            Truth::Shape => include_bytes!("../../data/calibration-shape.bin"),
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

/// Running sums per bin.
#[derive(Debug, Clone, Copy, Default)]
struct Sums {
    n: f64,
    separate: f64,
    gap: f64,
    cost: f64,
    /// Per horizon h (1 to [`HORIZONS`] steps): the gap of the pairs settled separate within h
    /// steps, and the tests spent within h steps.
    ahead: [[f64; 2]; HORIZONS],
}

impl Sums {
    fn add(&mut self, o: &Sums) {
        self.n += o.n;
        self.separate += o.separate;
        self.gap += o.gap;
        self.cost += o.cost;
        for (a, b) in self.ahead.iter_mut().zip(&o.ahead) {
            a[0] += b[0];
            a[1] += b[1];
        }
    }

    /// The best gap per test over the horizons (0 without observations).
    fn best_ahead(&self) -> f64 {
        self.ahead
            .iter()
            .filter(|a| a[1] > 0.0)
            .map(|a| a[0] / a[1])
            .fold(0.0, f64::max)
    }
}

/// Every visited state of exact runs, with what followed from it.
#[derive(Debug, Clone)]
pub struct Observations {
    depth: u8,
    sums: Vec<Sums>,
    /// Per distance bucket, the remembered untested visits again, for the bins of untested
    /// pairs not remembered (see [`Self::record`]); kept apart so that the reliability counts
    /// each visit once.
    unremembered: Vec<Sums>,
}

/// One row of a reliability table: states whose predicted probability of not colliding falls in
/// `[lo, hi)`, and how often such pairs truly did not collide.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ReliabilityRow {
    /// Lower edge of the predicted-probability bin.
    pub lo: f64,
    /// Upper edge.
    pub hi: f64,
    /// Mean predicted probability of the states in the bin (weighted by visits).
    pub predicted: f64,
    /// Observed frequency of "not colliding" among those visits.
    pub observed: f64,
    /// Visits.
    pub count: f64,
}

impl Observations {
    /// Run each scene exactly for `warmup` unrecorded and `frames` recorded frames and record, for
    /// every candidate pair, each state its traversal passes through, whether it turned out to
    /// collide, its true gap if not, and the tests it took from that state.
    pub fn record(scenes: &[SceneConfig], warmup: u32, frames: u32) -> Result<Self, ConfigError> {
        let depth = scenes.first().map_or(4, |s| s.depth) as u8;
        let mut obs = Self {
            depth,
            sums: vec![Sums::default(); stages(depth) * LIST_BUCKETS * DIST_BUCKETS],
            unremembered: vec![Sums::default(); DIST_BUCKETS],
        };
        for scene in scenes {
            if scene.depth as u8 != depth {
                return Err(ConfigError::new(
                    "scene.depth",
                    scene.depth,
                    format!("every calibration scene must have depth {depth}"),
                ));
            }
            let cfg = SimConfig {
                scene: scene.clone(),
                budget: BudgetSpec::Exact,
                scheduler: SchedulerKind::Sequential,
                ..SimConfig::default()
            };
            let mut sim = Simulation::new(cfg)?;
            let tree = SphereTree::build(Star::new(scene.shape_radius), scene.depth as usize)?
                .with_truth(scene.truth);
            let inv_diameter = (0.5 / tree.root_radius()) as f32;
            let inv_r = 1.0 / scene.shape_radius;
            let mut np = NarrowPhase::default();
            let mut stack = Vec::new();
            let mut visits: Vec<(usize, u64)> = Vec::new();
            // Last frame's pairs settled separate below the root, with their tests (what the
            // priced scheduler remembers), and this frame's.
            let mut remembered = std::collections::HashMap::new();
            let mut now = std::collections::HashMap::new();
            for f in 0..warmup + frames {
                sim.step(None, &FrozenClock);
                let world = sim.world();
                np.reset(sim.candidate_pairs());
                now.clear();
                for i in 0..np.pairs.len() {
                    let (a, b) = (np.pairs[i].a as usize, np.pairs[i].b as usize);
                    let dist =
                        (world.position[b] - world.position[a]).length() as f32 * inv_diameter;
                    visits.clear();
                    let memory = remembered.get(&(a, b)).copied().unwrap_or(0);
                    let outcome = loop {
                        // Under the shape truth, a pair waiting for its shape test shares the
                        // last stage's bins (the leaves' step, whose outcome it completes).
                        let stage = np.pairs[i].stage().min(stages(depth) as u8 - 1);
                        let key = if stage == 0 {
                            initial_key(np.has_witness(i), memory)
                        } else {
                            list_key(&np, i)
                        };
                        visits.push((index(stage, key, dist), np.tests));
                        match np.step(i, &tree, world) {
                            StepOutcome::Active => continue,
                            o => break o,
                        }
                    };
                    let separate = outcome == StepOutcome::Separate;
                    if separate && np.pairs[i].resolved_level > 1 {
                        now.insert((a, b), (np.tests - visits[0].1) as u32);
                    }
                    if f < warmup {
                        continue;
                    }
                    let gap = if separate {
                        let sep = match tree.truth() {
                            Truth::LeafSpheres => separation(&tree, world, a, b, &mut stack).0,
                            Truth::Shape => shape_separation(&tree, world, a, b).0,
                        };
                        sep.max(0.0) * inv_r
                    } else {
                        0.0
                    };
                    for (j, &(k, t0)) in visits.iter().enumerate() {
                        let mut visit = Sums {
                            n: 1.0,
                            separate: f64::from(u8::from(separate)),
                            gap,
                            cost: (np.tests - t0) as f64,
                            ..Sums::default()
                        };
                        for (h, a) in visit.ahead.iter_mut().enumerate() {
                            // Steps j..=j+h: settled within them if the descent ends there.
                            let end = j + h + 1;
                            let (settled, t1) = match visits.get(end) {
                                Some(&(_, t1)) => (false, t1),
                                None => (true, np.tests),
                            };
                            a[0] = if settled { gap } else { 0.0 };
                            a[1] = (t1 - t0) as f64;
                        }
                        obs.sums[k].add(&visit);
                        // An untested pair not remembered is any untested pair: a scheduler
                        // under a budget remembers only the pairs it settled, so its pairs
                        // without a memory are last frame's deemed pairs as well as new ones.
                        // The first visit is the untested one (stage 0): its list key is k's
                        // row; keys 1 to LENGTH_BUCKETS - 1 are the remembered ones.
                        if j == 0 && (1..LENGTH_BUCKETS).contains(&(k / DIST_BUCKETS)) {
                            obs.unremembered[k % DIST_BUCKETS].add(&visit);
                        }
                    }
                }
                np.remember_witnesses(world.len());
                std::mem::swap(&mut remembered, &mut now);
            }
        }
        Ok(obs)
    }

    /// Add another set of observations of the same depth (ignored if the depth differs).
    pub fn merge(&mut self, other: &Observations) {
        if other.depth == self.depth {
            for (a, b) in self.sums.iter_mut().zip(&other.sums) {
                a.add(b);
            }
            for (a, b) in self.unremembered.iter_mut().zip(&other.unremembered) {
                a.add(b);
            }
        }
    }

    /// The calibrated table: each bin's frequencies shrunk towards its (stage, list) row, and the
    /// row towards its stage.
    pub fn calibration(&self) -> Calibration {
        let per_row = DIST_BUCKETS;
        let per_stage = LIST_BUCKETS * DIST_BUCKETS;
        let n_stages = stages(self.depth);
        // Untested pairs not remembered: every untested pair without a witness.
        let mut sums = self.sums.clone();
        for (a, b) in sums.iter_mut().zip(&self.unremembered) {
            a.add(b);
        }
        let mut stage_sums = vec![Sums::default(); n_stages];
        let mut row_sums = vec![Sums::default(); n_stages * LIST_BUCKETS];
        for (k, s) in sums.iter().enumerate() {
            stage_sums[k / per_stage].add(s);
            row_sums[k / per_row].add(s);
        }
        // (p, gap, cost) of a pool, shrunk towards a parent's.
        let shrink = |s: &Sums, parent: (f64, f64, f64)| {
            let k = if s.n < DENSE { SHRINK } else { 0.0 };
            let p = (s.separate + k * parent.0) / (s.n + k);
            let gap = (s.gap + k * parent.0 * parent.1) / (s.separate + k * parent.0);
            let cost = (s.cost + k * parent.2) / (s.n + k);
            (p, if gap.is_finite() { gap } else { parent.1 }, cost)
        };
        let bins = sums
            .iter()
            .enumerate()
            .map(|(k, s)| {
                let st = shrink(&stage_sums[k / per_stage], (0.5, 0.1, 8.0));
                let row = shrink(&row_sums[k / per_row], st);
                // A sparse bin borrows from its nearest distance buckets in the same row first
                // (the prices change smoothly with distance), widening until the window is dense.
                let base = k - k % per_row;
                let d = k % per_row;
                let mut window = *s;
                let mut w = 0;
                while window.n < DENSE && w < per_row {
                    w += 1;
                    window = Sums::default();
                    for j in d.saturating_sub(w)..=(d + w).min(per_row - 1) {
                        window.add(&sums[base + j]);
                    }
                }
                let near = shrink(&window, row);
                let (p, gap, cost) = shrink(s, near);
                let cost = cost.max(1.0);
                // The horizons' rates from the window (the bin itself where it is dense).
                let ahead = if window.n >= DENSE {
                    window.best_ahead()
                } else {
                    0.0
                };
                Bin {
                    p_separate: p as f32,
                    gap: gap as f32,
                    cost: cost as f32,
                    rate: (p * gap / cost).max(ahead) as f32,
                    count: s.n as u32,
                }
            })
            .collect();
        Calibration {
            depth: self.depth,
            bins,
        }
    }

    /// Reliability of `cal` on these observations: visits grouped by predicted probability of not
    /// colliding into `groups` equal-width bins, with the observed frequency in each, plus the
    /// Brier score and the expected calibration error (visit-weighted mean |predicted - observed|).
    pub fn reliability(&self, cal: &Calibration, groups: usize) -> (Vec<ReliabilityRow>, f64, f64) {
        let groups = groups.max(1);
        let mut rows: Vec<ReliabilityRow> = (0..groups)
            .map(|g| ReliabilityRow {
                lo: g as f64 / groups as f64,
                hi: (g + 1) as f64 / groups as f64,
                predicted: 0.0,
                observed: 0.0,
                count: 0.0,
            })
            .collect();
        let (mut brier, mut n) = (0.0, 0.0);
        for (s, b) in self.sums.iter().zip(&cal.bins) {
            if s.n == 0.0 {
                continue;
            }
            let p = f64::from(b.p_separate);
            let g = ((p * groups as f64) as usize).min(groups - 1);
            let r = &mut rows[g];
            r.predicted += p * s.n;
            r.observed += s.separate;
            r.count += s.n;
            // Sum over visits of (p - y)^2, y = 1 for the separate ones.
            brier += s.separate * (1.0 - p).powi(2) + (s.n - s.separate) * p * p;
            n += s.n;
        }
        let mut ece = 0.0;
        for r in &mut rows {
            if r.count > 0.0 {
                r.predicted /= r.count;
                r.observed /= r.count;
                ece += r.count * (r.predicted - r.observed).abs();
            }
        }
        let n = n.max(1.0);
        (rows, brier / n, ece / n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn states_predict_what_follows_them_and_the_table_is_dense() {
        // The paper's truth: there a contact lasts several frames, so a witness predicts one.
        let scene = SceneConfig {
            truth: Truth::LeafSpheres,
            ..SceneConfig::paper(400, 3)
        };
        let obs = Observations::record(&[scene], 20, 5).expect("valid");
        let cal = obs.calibration();
        assert_eq!(cal.bins().len(), 7 * LIST_BUCKETS * DIST_BUCKETS);
        for b in cal.bins() {
            assert!((0.0..=1.0).contains(&b.p_separate) && b.cost >= 1.0 && b.gap >= 0.0);
        }
        // Untested pairs whose root spheres cannot touch (distance over the diameter > 1) are
        // settled separate by their one root test.
        let far = &cal.bins[index(0, 0, 1.3)];
        let witnessed = &cal.bins[index(0, LENGTH_BUCKETS, 0.6)];
        assert!(witnessed.p_separate < 0.5, "{witnessed:?}");
        assert!(
            far.count > 0 && far.p_separate > 0.9 && far.cost < 1.5,
            "{far:?}"
        );
        // Closer centres collide more often: the nearest well-observed distance bucket of untested
        // pairs is far more likely to collide than the far one.
        let near = (0..DIST_BUCKETS)
            .map(|d| &cal.bins[d])
            .find(|b| b.count >= 50)
            .expect("observed");
        assert!(near.p_separate < 0.5 * far.p_separate, "{near:?}");
        // In-sample reliability is good by construction; the held-out check is the bench's.
        let (rows, brier, ece) = obs.reliability(&cal, 10);
        assert_eq!(rows.len(), 10);
        assert!(brier < 0.25 && ece < 0.1, "brier {brier}, ece {ece}");
    }

    #[test]
    fn remembered_costs_key_half_octaves_among_the_untested_keys() {
        let keys: Vec<usize> = [2, 3, 4, 5, 6, 7, 8, 11, 12, 16, 255, 256, 100_000]
            .into_iter()
            .map(remembered_key)
            .collect();
        assert_eq!(keys, [1, 2, 3, 3, 4, 4, 5, 5, 6, 7, 14, 15, 15]);
        let mut last = 1;
        for c in 0..5_000 {
            let k = remembered_key(c);
            assert!((1..LENGTH_BUCKETS).contains(&k) && k >= last, "{c}: {k}");
            last = k;
        }
    }

    #[test]
    fn a_pair_cheap_last_frame_is_priced_cheap_now() {
        // On the leaves: under the shape truth a near miss's memory settles it in one to three
        // tests whatever its last cost, which is what the table then learns.
        let scene = SceneConfig {
            truth: Truth::LeafSpheres,
            ..SceneConfig::paper(500, 3)
        };
        let obs = Observations::record(&[scene], 20, 10).expect("valid");
        let cal = obs.calibration();
        // Untested pairs within root reach, by what they cost last frame (pooled over distance).
        let mean_cost = |keys: std::ops::RangeInclusive<usize>| {
            let (mut n, mut c) = (0.0, 0.0);
            for key in keys {
                for d in 0..DIST_BUCKETS / 2 {
                    let b = &cal.bins[index_bucket(0, key, d as u8)];
                    n += f64::from(b.count);
                    c += f64::from(b.count) * f64::from(b.cost);
                }
            }
            assert!(n >= 30.0, "observed {n}");
            c / n
        };
        // A pair settled below its root took at least one level's tests (9 and up: keys 5-7
        // are 8-22 tests, 11-15 are 64 and beyond).
        let cheap = mean_cost(5..=7);
        let dear = mean_cost(11..=15);
        let any = mean_cost(0..=0);
        assert!(cheap * 4.0 < dear, "cheap {cheap}, dear {dear}");
        assert!(cheap < any && any < dear, "{cheap} < {any} < {dear}");
    }

    #[test]
    fn squared_buckets_equal_the_buckets_of_the_distance() {
        for k in 0..20_000 {
            let d = k as f32 * 1e-4;
            let want = dist_bucket(d);
            let got = dist_bucket_of_squared(d * d);
            // Within one float ulp of an edge either side is right.
            let edge = (d * DIST_BUCKETS as f32 / DIST_RANGE).fract();
            if edge > 1e-4 && edge < 1.0 - 1e-4 {
                assert_eq!(got, want, "d = {d}");
            }
        }
        assert_eq!(dist_bucket_of_squared(-1.0), 0);
        assert_eq!(dist_bucket_of_squared(1e9), DIST_BUCKETS as u8 - 1);
    }

    #[test]
    fn the_table_round_trips_through_its_file_format() {
        let cal = Observations::record(&[SceneConfig::paper(200, 1)], 5, 2)
            .expect("valid")
            .calibration();
        let bytes = cal.to_bytes();
        let back = Calibration::from_bytes(&bytes).expect("reads back");
        assert_eq!(back.depth(), cal.depth());
        assert_eq!(back.bins().len(), cal.bins().len());
        for (a, b) in back.bins().iter().zip(cal.bins()) {
            assert_eq!(
                [a.p_separate, a.gap, a.cost, a.rate].map(f32::to_bits),
                [b.p_separate, b.gap, b.cost, b.rate].map(f32::to_bits)
            );
            assert_eq!(a.count, b.count);
        }
        // Refused, each for its own reason.
        assert_eq!(Calibration::from_bytes(b"CSV,1,2"), Err(TableError::Magic));
        assert_eq!(
            Calibration::from_bytes(&bytes[..bytes.len() - 1]),
            Err(TableError::Length {
                got: bytes.len() - 13 - 1,
                want: bytes.len() - 13
            })
        );
        let mut nan = bytes.clone();
        nan[13..17].copy_from_slice(&f32::NAN.to_le_bytes());
        assert_eq!(Calibration::from_bytes(&nan), Err(TableError::NotFinite(0)));
        let mut deep = bytes;
        deep[8] = 3;
        assert!(matches!(
            Calibration::from_bytes(&deep),
            Err(TableError::Bins { depth: 3, .. })
        ));
    }

    /// Both truths' shipped tables read, for the paper's depth.
    #[test]
    fn the_shipped_tables_read() {
        for truth in Truth::ALL {
            let cal = Calibration::shipped_for(truth).expect("shipped table reads");
            assert_eq!(cal.depth(), 4, "{truth:?}");
        }
    }
}
