//! Start-up calibration: the prices of the priced scheduler's states (see
//! [`crate::schedule::calibration`]) measured on exact runs of whole simulations. It runs
//! [`Simulation`]s, so it sits at the engine's top level, above the schedulers whose table it
//! fills: a tree of the shipped depth takes the shipped table, any other depth calibrates its own
//! on a small copy of its scene when its simulation is built, and `foveal-bench calibrate`
//! regenerates the shipped table from [`Observations`].

use serde::Serialize;

use crate::config::{SceneConfig, Truth};
use crate::narrow_phase::{NarrowPhase, StepOutcome, separation, shape_separation};
use crate::schedule::calibration::*;
use crate::shape::Star;
use crate::sphere_tree::SphereTree;
use crate::validate::ConfigError;
use crate::{BudgetSpec, FrozenClock, SchedulerKind, SimConfig, Simulation};

impl Calibration {
    /// The shipped table for the paper's depth, or a table calibrated now for another depth.
    pub fn for_tree(tree: &SphereTree, scene: &SceneConfig) -> Result<Self, ConfigError> {
        let depth = tree.depth() as u8;
        if let Some(shipped) =
            Self::shipped_for_tree(tree.truth(), tree.kind()).filter(|c| c.depth == depth)
        {
            return Ok(shipped);
        }
        // A small copy of the paper scene at this depth: a few hundred thousand state visits,
        // in well under a second.
        let mut small = SceneConfig::paper(1_000, 1);
        small.depth = scene.depth;
        small.shape_radius = scene.shape_radius;
        small.truth = tree.truth();
        small.tree = tree.kind();
        Ok(Observations::record(&[small], 30, 10)?.calibration())
    }
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
            let tree = SphereTree::build_kind(
                Star::new(scene.shape_radius),
                scene.depth as usize,
                scene.tree,
            )?
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

    /// Both truths' shipped tables read, for the paper's depth, for the default tree and the
    /// octree; the fitted octree ships none.
    #[test]
    fn the_shipped_tables_read() {
        for truth in Truth::ALL {
            for tree in [crate::TreeKind::Parts, crate::TreeKind::Octree] {
                let cal = Calibration::shipped_for_tree(truth, tree).expect("shipped table reads");
                assert_eq!(cal.depth(), 4, "{truth:?} {tree}");
            }
            assert!(Calibration::shipped_for_tree(truth, crate::TreeKind::Fitted).is_none());
        }
    }
}
