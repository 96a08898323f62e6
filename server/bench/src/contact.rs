//! First contacts on the drawn shape: how far apart the two stars the viewer sees are when the
//! engine first calls a pair colliding, under each truth (docs/BENCHMARKS.md "Shape truth").
//!
//! Exact frames of the paper scene; a *first contact* is a pair colliding in a frame that did not
//! collide in the frame before (body ids, so renumbering does not count). For each, the gap
//! between the two stars is measured on the shape ([`shape_separation`]; the closed forms and
//! GJK of the shape level, checked against dense surface samples by the engine's tests): under
//! the paper's leaf-sphere truth it is the visible gap across which bodies bounce; under the
//! shape truth it is 0 by construction, and what is left is the time step's own error, the
//! depth by which the stars already overlap when the contact is first seen, reported apart.

use std::collections::HashSet;
use std::fmt::Write as _;
use std::time::Instant;

use foveal_engine::narrow_phase::{PairStatus, shape_separation};
use foveal_engine::{BudgetSpec, FrozenClock, SceneConfig, SimConfig, Simulation, Truth};

use crate::error::BenchError;

/// The runs: every (N, seed) under every truth.
#[derive(Debug, Clone)]
pub struct ContactConfig {
    /// (bodies, seeds) per scene.
    pub scenes: Vec<(u32, Vec<u64>)>,
    /// Frames per run.
    pub frames: u32,
    /// Frames at the start whose first contacts are counted but kept out of the "after warm-up"
    /// share (a random scene starts with overlaps everywhere).
    pub warmup: u32,
    /// Truths to compare.
    pub truths: Vec<Truth>,
    /// Threads per simulation.
    pub threads: u32,
}

impl ContactConfig {
    /// The protocol: N = 500 seeds 1-3 and N = 10,000 seed 1, 600 frames each.
    pub fn standard() -> Self {
        Self {
            scenes: vec![(500, vec![1, 2, 3]), (10_000, vec![1])],
            frames: 600,
            warmup: 60,
            truths: Truth::ALL.to_vec(),
            threads: 1,
        }
    }

    /// N = 500, one seed, 120 frames: seconds.
    pub fn quick() -> Self {
        Self {
            scenes: vec![(500, vec![1])],
            frames: 120,
            warmup: 60,
            truths: Truth::ALL.to_vec(),
            threads: 1,
        }
    }
}

/// What one truth gave at one N, pooled over seeds.
#[derive(Debug, Clone)]
pub struct ContactRow {
    /// The truth the engine ran under.
    pub truth: Truth,
    /// Bodies.
    pub n: u32,
    /// Seeds pooled.
    pub seeds: usize,
    /// Frames per run.
    pub frames: u32,
    /// First contacts seen.
    pub first_contacts: usize,
    /// Of those, the stars more than 0.01R apart.
    pub apart: usize,
    /// Gap quantiles at first contact, in R: p10, p50, p90, p99, max.
    pub gap: [f64; 5],
    /// Penetration depth quantiles at first contact (the time step's own error), in R: p50,
    /// p90, p99, max.
    pub depth: [f64; 4],
    /// Colliding pair-frames after the warm-up, and those whose stars are more than 0.01R apart.
    pub colliding_after_warmup: (usize, usize),
    /// Median wall time of an exact step, ms (single run, 1 thread unless configured).
    pub step_ms_p50: f64,
}

/// Quantile `q` of sorted `v` (nearest rank), 0 for an empty list.
fn quantile(v: &[f64], q: f64) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    let k = ((q * v.len() as f64).ceil() as usize).clamp(1, v.len()) - 1;
    v[k]
}

/// Run every truth on every scene.
pub fn run(cfg: &ContactConfig) -> Result<Vec<ContactRow>, BenchError> {
    let mut rows = Vec::new();
    for &truth in &cfg.truths {
        for (n, seeds) in &cfg.scenes {
            let (mut gaps, mut depths, mut steps) = (Vec::new(), Vec::new(), Vec::new());
            let (mut apart, mut after, mut after_apart) = (0, 0, 0);
            for &seed in seeds {
                let mut sim = Simulation::new(SimConfig {
                    scene: SceneConfig {
                        truth,
                        ..SceneConfig::paper(*n, seed)
                    },
                    budget: BudgetSpec::Exact,
                    threads: cfg.threads,
                    ..SimConfig::default()
                })?;
                let r = sim.config().scene.shape_radius;
                let mut before: HashSet<(u32, u32)> = HashSet::new();
                for f in 0..cfg.frames {
                    let t0 = Instant::now();
                    sim.step(None, &FrozenClock);
                    steps.push(t0.elapsed().as_secs_f64() * 1e3);
                    let ids = sim.body_ids();
                    let mut now = HashSet::new();
                    for p in sim.pairs() {
                        if p.status != PairStatus::Colliding {
                            continue;
                        }
                        let (x, y) = (ids[p.a as usize], ids[p.b as usize]);
                        let key = (x.min(y), x.max(y));
                        now.insert(key);
                        let (sep, _, _) =
                            shape_separation(sim.tree(), sim.world(), p.a as usize, p.b as usize);
                        let far = sep > 0.01 * r;
                        if f >= cfg.warmup {
                            after += 1;
                            after_apart += usize::from(far);
                        }
                        if !before.contains(&key) {
                            gaps.push(sep.max(0.0) / r);
                            depths.push((-sep).max(0.0) / r);
                            apart += usize::from(far);
                        }
                    }
                    before = now;
                }
            }
            gaps.sort_by(f64::total_cmp);
            depths.sort_by(f64::total_cmp);
            steps.sort_by(f64::total_cmp);
            rows.push(ContactRow {
                truth,
                n: *n,
                seeds: seeds.len(),
                frames: cfg.frames,
                first_contacts: gaps.len(),
                apart,
                gap: [0.1, 0.5, 0.9, 0.99, 1.0].map(|q| quantile(&gaps, q)),
                depth: [0.5, 0.9, 0.99, 1.0].map(|q| quantile(&depths, q)),
                colliding_after_warmup: (after, after_apart),
                step_ms_p50: quantile(&steps, 0.5),
            });
        }
    }
    Ok(rows)
}

/// The rows as a markdown table, with the protocol it came from.
pub fn markdown(cfg: &ContactConfig, rows: &[ContactRow]) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "First contacts in exact frames of the paper scene ({} frames a run; gap and depth \
         between the two drawn stars, in R; \"apart\" = more than 0.01R)\n",
        cfg.frames
    );
    s.push_str(
        "| truth | N | seeds | first contacts | apart | gap p10 | p50 | p90 | p99 | max \
         | depth p50 | p90 | p99 | max | colliding after warm-up: apart | exact step p50 (ms) |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let pct = |a: usize, b: usize| {
            if b == 0 {
                "n/a".to_string()
            } else {
                format!("{:.2}%", 100.0 * a as f64 / b as f64)
            }
        };
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {:.3} | {:.3} | {:.3} | {:.3} | {:.3} | {:.4} | {:.4} \
             | {:.4} | {:.4} | {} of {} | {:.2} |",
            r.truth,
            r.n,
            r.seeds,
            r.first_contacts,
            pct(r.apart, r.first_contacts),
            r.gap[0],
            r.gap[1],
            r.gap[2],
            r.gap[3],
            r.gap[4],
            r.depth[0],
            r.depth[1],
            r.depth[2],
            r.depth[3],
            pct(r.colliding_after_warmup.1, r.colliding_after_warmup.0),
            r.colliding_after_warmup.0,
            r.step_ms_p50,
        );
    }
    s
}

/// The rows as CSV.
pub fn csv(rows: &[ContactRow]) -> String {
    let mut s = String::from(
        "truth,n,seeds,frames,first_contacts,apart,gap_p10,gap_p50,gap_p90,gap_p99,gap_max,\
         depth_p50,depth_p90,depth_p99,depth_max,colliding_after_warmup,colliding_apart,\
         step_ms_p50\n",
    );
    for r in rows {
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
            r.truth,
            r.n,
            r.seeds,
            r.frames,
            r.first_contacts,
            r.apart,
            r.gap[0],
            r.gap[1],
            r.gap[2],
            r.gap[3],
            r.gap[4],
            r.depth[0],
            r.depth[1],
            r.depth[2],
            r.depth[3],
            r.colliding_after_warmup.0,
            r.colliding_after_warmup.1,
            r.step_ms_p50
        );
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Under the leaf truth bodies bounce across a visible gap; under the shape truth no first
    /// contact is more than 0.01R apart (the stars touch when the engine says so).
    #[test]
    fn the_shape_truth_closes_the_gap_at_first_contact() {
        let cfg = ContactConfig {
            scenes: vec![(300, vec![4])],
            frames: 40,
            warmup: 20,
            truths: Truth::ALL.to_vec(),
            threads: 1,
        };
        let rows = run(&cfg).expect("valid");
        let shape = rows.iter().find(|r| r.truth == Truth::Shape).expect("row");
        let leaf = rows
            .iter()
            .find(|r| r.truth == Truth::LeafSpheres)
            .expect("row");
        assert!(
            leaf.first_contacts > 20 && shape.first_contacts > 5,
            "{rows:?}"
        );
        assert_eq!(shape.apart, 0, "{shape:?}");
        assert!(leaf.apart * 2 > leaf.first_contacts, "{leaf:?}");
        assert!(leaf.gap[1] > 0.1, "{leaf:?}");
        assert!(markdown(&cfg, &rows).contains("| shape | 300 |"));
    }
}
