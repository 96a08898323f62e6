//! The sphere tree kinds against each other on identical frames (docs/DESIGN.md "Sphere tree"):
//! the exact narrow phase of one steady frame of the paper scene, timed under each tree in turn,
//! round after round, so that a shared machine's drift reaches every tree alike; medians and
//! ratios to the octree come from one run.

use std::fmt::Write as _;
use std::time::Instant;

use foveal_engine::narrow_phase::NarrowPhase;
use foveal_engine::shape::Star;
use foveal_engine::sphere_tree::SphereTree;
use foveal_engine::{
    BudgetSpec, FrozenClock, SceneConfig, SchedulerKind, SimConfig, Simulation, TreeKind, Truth,
};

use crate::error::BenchError;

/// What one tree did with the frame.
#[derive(Debug, Clone)]
pub struct TreeTiming {
    /// The tree.
    pub tree: TreeKind,
    /// Sphere tests of the frame's exact narrow phase (the same every round).
    pub tests: u64,
    /// Median time of the exact narrow phase over the rounds (ms).
    pub median_ms: f64,
    /// The rounds' fastest and slowest (ms).
    pub range_ms: (f64, f64),
}

/// Frame 61 of the paper scene with `n` bodies (seed 1) under `truth`, its exact narrow phase on
/// `threads` threads timed `rounds` times under each tree in turn (the witnesses and near
/// misses of frame 60 kept, as a running scene has them). Every tree's answers are the same
/// (they share the leaves); returns each tree's tests and times, the octree last.
pub fn compare(
    n: u32,
    truth: Truth,
    threads: usize,
    rounds: u32,
) -> Result<Vec<TreeTiming>, BenchError> {
    let cfg = SimConfig {
        scene: SceneConfig {
            truth,
            ..SceneConfig::paper(n, 1)
        },
        budget: BudgetSpec::Exact,
        scheduler: SchedulerKind::Sequential,
        ..SimConfig::default()
    };
    let mut sim = Simulation::new(cfg.clone())?;
    for _ in 0..60 {
        sim.step(None, &FrozenClock);
    }
    let (before, before_pairs) = (sim.world().clone(), sim.candidate_pairs().to_vec());
    sim.step(None, &FrozenClock);
    let (world, pairs) = (sim.world().clone(), sim.candidate_pairs().to_vec());
    let mut runs = Vec::new();
    for tree in [TreeKind::Parts, TreeKind::Fitted, TreeKind::Octree] {
        let t = SphereTree::build_kind(
            Star::new(cfg.scene.shape_radius),
            cfg.scene.depth as usize,
            tree,
        )?
        .with_truth(truth);
        let mut np = NarrowPhase::default();
        np.reset(&before_pairs);
        np.resolve_all(&t, &before, threads);
        np.remember_witnesses(before.len());
        runs.push((tree, t, np, Vec::with_capacity(rounds as usize)));
    }
    for _ in 0..rounds.max(1) {
        for (_, t, np, times) in &mut runs {
            let start = Instant::now();
            np.reset(&pairs);
            np.resolve_all(t, &world, threads);
            times.push(start.elapsed().as_secs_f64() * 1e3);
        }
    }
    Ok(runs
        .into_iter()
        .map(|(tree, _, np, mut times)| {
            times.sort_by(f64::total_cmp);
            TreeTiming {
                tree,
                tests: np.tests,
                median_ms: times[times.len() / 2],
                range_ms: (times[0], times[times.len() - 1]),
            }
        })
        .collect())
}

/// A markdown table of [`compare`]'s result, with each tree's ratio to the octree.
pub fn markdown(n: u32, truth: Truth, threads: usize, rounds: u32, rows: &[TreeTiming]) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "Exact narrow phase of frame 61, N = {n}, truth {truth}, {threads} thread(s), {rounds} rounds interleaved.\n"
    );
    let _ = writeln!(
        s,
        "| tree | sphere tests | median ms (range) | tests / octree | time / octree |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|");
    let octree = rows.iter().find(|r| r.tree == TreeKind::Octree);
    for r in rows {
        let (t, m) = octree.map_or((f64::NAN, f64::NAN), |o| {
            (r.tests as f64 / o.tests as f64, r.median_ms / o.median_ms)
        });
        let _ = writeln!(
            s,
            "| {} | {} | {:.3} ({:.3}-{:.3}) | {t:.3} | {m:.3} |",
            r.tree, r.tests, r.median_ms, r.range_ms.0, r.range_ms.1
        );
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every tree settles the same frame; the parts tree with fewer tests than the octree.
    #[test]
    fn every_tree_is_timed_on_the_same_frame() {
        let rows = compare(300, Truth::LeafSpheres, 1, 2).expect("runs");
        assert_eq!(rows.len(), 3);
        let tests = |k: TreeKind| rows.iter().find(|r| r.tree == k).map_or(0, |r| r.tests);
        assert!(tests(TreeKind::Parts) < tests(TreeKind::Octree));
        assert!(
            rows.iter()
                .all(|r| r.median_ms > 0.0 && r.range_ms.0 <= r.range_ms.1)
        );
        let md = markdown(300, Truth::LeafSpheres, 1, 2, &rows);
        assert!(md.contains("| parts |") && md.contains("| octree |"));
    }
}
