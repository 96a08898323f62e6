//! The exact answer and the audit, checked against brute force on whole simulated frames.

use std::collections::BTreeSet;

use foveal_engine::broad_phase::brute_force_pairs;
use foveal_engine::metrics::Fovea;
use foveal_engine::narrow_phase::{PairStatus, brute_force_colliding};
use foveal_engine::report::FOVEAL_DEG;
use foveal_engine::{
    BudgetSpec, DeemedTruth, Fixation, FrozenClock, SchedulerKind, SimConfig, Simulation, TreeKind,
    Truth,
};

fn config(n: u32, depth: u32, budget: BudgetSpec, kind: SchedulerKind) -> SimConfig {
    let mut cfg = SimConfig::default();
    cfg.scene.bodies = n;
    cfg.scene.depth = depth;
    cfg.scene.seed = 77;
    cfg.budget = budget;
    cfg.scheduler = kind;
    cfg.audit = true;
    cfg
}

#[test]
fn exact_frames_equal_brute_force_at_every_depth() {
    for depth in 1..=6 {
        let mut sim = Simulation::new(config(
            150,
            depth,
            BudgetSpec::Exact,
            SchedulerKind::RoundRobin,
        ))
        .expect("valid");
        for _ in 0..5 {
            sim.step(None, &FrozenClock);
        }
        let w = sim.world();
        let all: BTreeSet<_> = brute_force_pairs(&w.position, sim.tree().root_radius())
            .into_iter()
            .collect();
        let cand: BTreeSet<_> = sim.candidate_pairs().iter().copied().collect();
        assert_eq!(cand, all, "depth {depth}: broad phase");
        for p in sim.pairs() {
            let want = brute_force_colliding(sim.tree(), w, p.a as usize, p.b as usize);
            assert_eq!(
                p.status == PairStatus::Colliding,
                want,
                "depth {depth}: pair {:?}",
                (p.a, p.b)
            );
        }
    }
}

/// The tree kinds share their leaves, so an exact frame is the same under each, pair by pair and
/// in every body's pose after the responses, under both truths; the fitted ones take fewer
/// sphere tests.
#[test]
fn every_tree_gives_the_octrees_exact_frames_in_fewer_tests() {
    for truth in Truth::ALL {
        let run = |tree: TreeKind| {
            let mut cfg = config(400, 4, BudgetSpec::Exact, SchedulerKind::RoundRobin);
            cfg.scene.truth = truth;
            cfg.scene.tree = tree;
            cfg.audit = false;
            let mut sim = Simulation::new(cfg).expect("valid");
            let mut tests = 0;
            let mut statuses = Vec::new();
            for _ in 0..30 {
                tests += sim.step(None, &FrozenClock).sphere_tests;
                statuses.extend(sim.pairs().iter().map(|p| (p.a, p.b, p.status)));
            }
            let w = sim.world();
            let poses: Vec<_> = w
                .position
                .iter()
                .zip(&w.orientation)
                .map(|(p, q)| {
                    (
                        p.to_array().map(f64::to_bits),
                        q.to_array().map(f64::to_bits),
                    )
                })
                .collect();
            (statuses, poses, tests)
        };
        let (octree, octree_poses, octree_tests) = run(TreeKind::Octree);
        for tree in [TreeKind::Fitted, TreeKind::Parts] {
            let (statuses, poses, tests) = run(tree);
            assert!(
                statuses == octree,
                "{truth} {tree}: a pair's answer differs"
            );
            assert!(
                poses == octree_poses,
                "{truth} {tree}: the bodies moved differently"
            );
            eprintln!("{truth} {tree}: {tests} sphere tests against the octree's {octree_tests}");
            assert!(
                tests < octree_tests,
                "{truth} {tree}: {tests} tests, octree {octree_tests}"
            );
        }
    }
}

#[test]
fn audit_counts_true_false_positives_of_deemed_pairs() {
    let mut sim = Simulation::new(config(
        400,
        4,
        BudgetSpec::SphereTests(3_000),
        SchedulerKind::PriorityOnly,
    ))
    .expect("valid");
    let (mut saw_fp, mut saw_foveal_fp) = (false, false);
    for _ in 0..20 {
        let r = sim.step(Some(Fixation::at(0.4, 0.6)), &FrozenClock).clone();
        let a = r.audit.expect("audit on");
        assert_eq!(a.false_positives + a.true_positives, r.deemed);
        let w = sim.world();
        let viewer = sim.viewer();
        let fovea = Fovea::new(viewer, viewer.to_pixels(0.4, 0.6), FOVEAL_DEG);
        let (mut fp, mut foveal_fp) = (0, 0);
        let deemed = sim
            .pairs()
            .iter()
            .filter(|p| p.status == PairStatus::Deemed);
        // The audit answers for every deemed pair, in order: the list the viewer colours by.
        assert_eq!(sim.deemed_truth().len() as u32, r.deemed);
        for (p, &truth) in deemed.zip(sim.deemed_truth()) {
            let apart = !brute_force_colliding(sim.tree(), w, p.a as usize, p.b as usize);
            let want = if apart {
                DeemedTruth::Apart
            } else {
                DeemedTruth::Touching
            };
            assert_eq!(truth, want, "pair {:?}", (p.a, p.b));
            if apart {
                fp += 1;
                let mid = (w.position[p.a as usize] + w.position[p.b as usize]) * 0.5;
                foveal_fp += u32::from(fovea.contains_point(mid));
            }
        }
        assert_eq!(a.false_positives, fp);
        assert_eq!(a.foveal_false_positives, foveal_fp);
        assert!(foveal_fp <= r.foveal_deemed);
        saw_foveal_fp |= foveal_fp > 0;
        saw_fp |= fp > 0;
        // The estimate is an upper bound on the true gap sum: centres of intersecting spheres are
        // further apart than the true separation of the leaves below them.
        assert!(
            a.geometric_inaccuracy <= r.geometric_inaccuracy + 1e-9,
            "{a:?} vs Δ {}",
            r.geometric_inaccuracy
        );
        assert!(a.perceived_inaccuracy.expect("fixation given") >= 0.0);
    }
    assert!(saw_fp && saw_foveal_fp);
    // A frame that is not audited has no answers to colour by.
    let mut cfg = config(
        400,
        4,
        BudgetSpec::SphereTests(3_000),
        SchedulerKind::PriorityOnly,
    );
    cfg.audit = false;
    let mut sim = Simulation::new(cfg).expect("valid");
    let r = sim.step(Some(Fixation::at(0.4, 0.6)), &FrozenClock).clone();
    assert!(r.deemed > 0 && sim.deemed_truth().is_empty());
}

#[test]
fn exact_budget_has_no_deemed_pairs_and_zero_error() {
    let mut sim = Simulation::new(config(
        300,
        4,
        BudgetSpec::Exact,
        SchedulerKind::PrioritySorted,
    ))
    .expect("valid");
    let r = sim.step(Some(Fixation::at(0.5, 0.5)), &FrozenClock).clone();
    assert_eq!(
        (r.deemed, r.geometric_inaccuracy, r.perceived_inaccuracy),
        (0, 0.0, Some(0.0))
    );
    assert_eq!(r.audit.expect("audit").false_positives, 0);
}

#[test]
fn fraction_of_exact_budget_is_calibrated_in_sphere_tests() {
    let sim = Simulation::new(config(
        300,
        4,
        BudgetSpec::FractionOfExact(0.5),
        SchedulerKind::RoundRobin,
    ))
    .expect("valid");
    let exact = sim.exact_cost(30).expect("valid");
    match sim.frame_budget() {
        foveal_engine::FrameBudget::Tests(n) => assert_eq!(n, (0.5 * exact).round() as u64),
        other => panic!("unexpected budget {other:?}"),
    }
}

#[test]
fn non_finite_fixation_is_never_used() {
    let mut sim = Simulation::new(config(
        200,
        4,
        BudgetSpec::SphereTests(500),
        SchedulerKind::SortedSequential,
    ))
    .expect("valid");
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let r = sim.step(Some(Fixation::at(bad, 0.5)), &FrozenClock).clone();
        assert!(r.fixation.is_none() && r.fixation_rejected && r.perceived_inaccuracy.is_none());
    }
    // Huge but finite: legal, just very eccentric.
    let r = sim
        .step(Some(Fixation::at(1e300, -1e300)), &FrozenClock)
        .clone();
    assert!(r.fixation.is_some() && r.perceived_inaccuracy.is_some_and(f64::is_finite));
}

#[test]
fn export_has_tree_bodies_and_exact_pairs() {
    let mut sim = Simulation::new(config(120, 4, BudgetSpec::Exact, SchedulerKind::Sequential))
        .expect("valid");
    sim.step(None, &FrozenClock);
    let v: serde_json::Value = serde_json::from_str(&sim.export_json()).expect("valid JSON");
    assert_eq!(v["format"], "foveal.scene.v1");
    // The default tree: the root, the star's core and six spikes, their groups of four leaves
    // (two in the core, three along each spike), the 80 leaves.
    assert_eq!(v["spheres_per_level"], serde_json::json!([1, 7, 20, 80]));
    assert_eq!(v["sphere_tree"].as_array().map(Vec::len), Some(108));
    assert_eq!(v["sphere_tree"][0]["child_count"], 7);
    assert_eq!(v["bodies"].as_array().map(Vec::len), Some(120));
    assert_eq!(
        v["bodies"][0]["orientation"].as_array().map(Vec::len),
        Some(4)
    );
    let exact: BTreeSet<(u32, u32)> =
        serde_json::from_value(v["exact_colliding_pairs"].clone()).expect("pairs");
    let real: BTreeSet<(u32, u32)> = sim
        .pairs()
        .iter()
        .filter(|p| p.status == PairStatus::Colliding)
        .map(|p| (p.a, p.b))
        .collect();
    assert_eq!(exact, real);
    assert_eq!(
        v["candidate_pairs"].as_array().map(Vec::len),
        Some(sim.candidate_pairs().len())
    );
}

/// A clock that advances 2 µs every time it is read.
struct Ticking(std::sync::atomic::AtomicU64);

impl foveal_engine::Clock for Ticking {
    fn now_ns(&self) -> u64 {
        self.0
            .fetch_add(2_000, std::sync::atomic::Ordering::Relaxed)
            + 2_000
    }
}

#[test]
fn wall_budget_smaller_than_prioritisation_is_held() {
    // 10 µs of budget at 2 µs per clock read: the deadline passes during prioritisation, which
    // must stop there (and the scheduler must then do no sphere test) instead of running over
    // every candidate pair.
    let mut cfg = config(
        3000,
        4,
        BudgetSpec::WallMs(0.01),
        SchedulerKind::PrioritySorted,
    );
    cfg.audit = false;
    let mut sim = Simulation::new(cfg).expect("valid");
    let clock = Ticking(std::sync::atomic::AtomicU64::new(0));
    let r = sim.step(Some(Fixation::at(0.5, 0.5)), &clock).clone();
    assert!(r.budget_exhausted && r.deemed > 0);
    // The deadline counts from the frame's start and is 5 reads later; integration, broad phase
    // and the start of prioritisation take 4 of them, each later read covering at most 576
    // prioritised pairs or 9 steps.
    let reads = clock.0.load(std::sync::atomic::Ordering::Relaxed) / 2_000;
    assert!(reads < 40, "{reads} clock reads");
    assert!(r.sphere_tests <= 8 * 6400, "{}", r.sphere_tests);
    let reached = sim.priorities().reached;
    assert!(
        reached > 0 && reached <= 5 * 576,
        "{reached} of {} pairs prioritised",
        r.candidate_pairs
    );
    assert!(reached < r.candidate_pairs as usize);
}
