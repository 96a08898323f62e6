//! Speed of the paper scene in exact mode (docs/DESIGN.md "Scene"); figures go to docs/BENCHMARKS.md.
//!
//! `cargo bench -p foveal-engine --bench step`
//! - `frame_exact/10000`: one whole frame (integrate, broad, narrow to completion, response).
//! - `broad_phase/{sap,grid,grid-2t,grid-cells,grid-cells-2t}/{10000,100000,1000000}`: one
//!   broad-phase update after a step of motion, per frame, for sweep and prune, the grid, and the
//!   grid on 2 threads (`-2t`, from N = 100,000), with the bodies numbered as generated (random
//!   in space) or in the grid's cell order (`grid-cells`, as a simulation renumbers them at large
//!   N); select one kind with e.g. `-- broad_phase/grid/`.
//! - `narrow_exact/10000`: the exact narrow phase alone over one frame's candidate pairs; the
//!   throughput line gives sphere tests per second.
//! - `narrow_steady/{10000,100000}/{1,2}`: the exact narrow phase over the candidate pairs of
//!   frame 61 (after one second of motion, when the start-up overlaps are gone), with the
//!   witnesses of frame 60, on 1 and 2 threads: what an exact frame's narrow phase costs in the
//!   steady state (about 25 sphere tests per candidate pair, half of the pairs settled by the
//!   root test); per sphere test in the throughput line.
//!   `narrow_steady/{10000,100000}-leaf/{1,2}`: the same under the paper's leaf-sphere truth.
//!   `...-octree/..`: the same frames with the paper's octree instead of the default parts tree.
//! - `shape/{intersects,contact}/10000`: the shape level alone on the pairs of frame 61 whose
//!   leaves overlap, per pair.
//! - `foveal_pass/{stepped,one-go-1t,one-go-2t}/100000`: a whole-frame budget's foveal pass over
//!   frame 61 with a fixation at the centre (every pair within 5 degrees settled), as it was (each
//!   pair stepped level by level) and as it is (each resolved in one go, on 1 and 2 threads); per
//!   foveal pair in the throughput line.
//! - `measure/{settled,deemed}/{10000,100000}`: the metrics pass (counts, the fovea count over
//!   every candidate pair, Δ and P over the deemed ones, sampled beyond 25,000) of one frame
//!   with a fixation, every pair settled exactly or every pair deemed.
//! - `ordering/body-pass/{500,10000}`: the priced scheduler's body pass alone, per body.
//! - `ordering/{reset,reset-roots}/{500,10000}`: a frame's reset of the pair states, alone and
//!   followed by the one-pass root settling of wall-clock frames, per candidate pair.
//! - `ordering/{round-robin,priced}/{500,10000}`: what a scheduler spends before its first sphere
//!   test (the pair list, the body pass, pricing), timed as a frame under a budget of 0 sphere
//!   tests with a fixation; per candidate pair in the throughput line. Under a wall-clock budget
//!   this is paid from the same time as the tests. `ordering/{round-robin,priced}-tests-0.1/..`:
//!   the same frame with a tenth of its exact sphere tests (per sphere test in the throughput).
//!   `ordering/sequential*` (pairs in candidate order, each resolved whole) and `ordering/exact`
//!   (every pair, per sphere test) beside them: what stepping pairs level by level costs a test.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use foveal_engine::broad_phase::{BroadPhase, BroadPhaseKind};
use foveal_engine::narrow_phase::NarrowPhase;
use foveal_engine::narrow_phase::PairStatus;
use foveal_engine::shape::Star;
use foveal_engine::sphere_tree::SphereTree;
use foveal_engine::world::World;
use foveal_engine::{
    BudgetSpec, Clock, FrozenClock, SceneConfig, SchedulerKind, SimConfig, Simulation, TreeKind,
    Truth,
};

struct Mono(Instant);
impl Clock for Mono {
    fn now_ns(&self) -> u64 {
        self.0.elapsed().as_nanos() as u64
    }
}

fn exact(n: u32) -> SimConfig {
    SimConfig {
        scene: SceneConfig::paper(n, 1),
        budget: BudgetSpec::Exact,
        scheduler: SchedulerKind::Sequential,
        ..SimConfig::default()
    }
}

fn frame(c: &mut Criterion) {
    let mut g = c.benchmark_group("frame_exact");
    g.measurement_time(Duration::from_secs(8));
    for n in [1_000u32, 10_000] {
        let mut sim = Simulation::new(exact(n)).expect("valid");
        for _ in 0..10 {
            sim.step(None, &FrozenClock);
        }
        let clock = Mono(Instant::now());
        g.throughput(Throughput::Elements(u64::from(n)));
        g.bench_function(BenchmarkId::from_parameter(n), |b| {
            b.iter(|| black_box(sim.step(None, &clock).sphere_tests))
        });
    }
    g.finish();
}

fn broad(c: &mut Criterion) {
    let mut g = c.benchmark_group("broad_phase");
    g.measurement_time(Duration::from_secs(6));
    g.sample_size(20);
    for n in [10_000u32, 100_000, 1_000_000] {
        let cfg = SceneConfig::paper(n, 1);
        let tree = SphereTree::build(Star::new(cfg.shape_radius), 4).expect("tree");
        let mut world = World::generate(&cfg);
        // Two consecutive frames: each iteration repairs one frame's worth of motion (forwards or
        // backwards), so the measurement is the broad phase alone, without integration.
        let before = world.position.clone();
        world.integrate(cfg.dt);
        let after = world.position.clone();
        g.throughput(Throughput::Elements(u64::from(n)));
        // The same frames with the bodies numbered in the grid's cell order, as a simulation
        // keeps them at large N (`SimConfig::renumber_every`).
        let half = tree.root_radius();
        let order = {
            let mut bp = BroadPhase::with_kind(
                BroadPhaseKind::Grid,
                half,
                world.lo,
                cfg.volume_side(),
                world.len(),
            );
            bp.update(&before);
            bp.spatial_order().expect("the grid has an order")
        };
        let renumbered: [Vec<_>; 2] =
            [&before, &after].map(|v| order.iter().map(|&i| v[i as usize]).collect());
        let kinds = [
            ("sap", BroadPhaseKind::SweepAndPrune, 1, false),
            ("sap-2t", BroadPhaseKind::SweepAndPrune, 2, false),
            ("grid", BroadPhaseKind::Grid, 1, false),
            ("grid-2t", BroadPhaseKind::Grid, 2, false),
            ("grid-cells", BroadPhaseKind::Grid, 1, true),
            ("grid-cells-2t", BroadPhaseKind::Grid, 2, true),
        ];
        for (id, kind, threads, in_cells) in kinds {
            // Each kind on two threads where it is the scene's broad phase.
            let sap = kind == BroadPhaseKind::SweepAndPrune;
            if threads > 1 && (sap != (n < 100_000)) {
                continue;
            }
            let (before, after) = if in_cells {
                (&renumbered[0], &renumbered[1])
            } else {
                (&before, &after)
            };
            let mut bp =
                BroadPhase::with_kind(kind, half, world.lo, cfg.volume_side(), world.len());
            bp.set_threads(threads);
            bp.update(before);
            let mut flip = false;
            g.bench_function(BenchmarkId::new(id, n), |b| {
                b.iter(|| {
                    flip = !flip;
                    black_box(bp.update(if flip { after } else { before }).len())
                })
            });
        }
    }
    g.finish();
}

fn narrow(c: &mut Criterion) {
    let mut g = c.benchmark_group("narrow_exact");
    g.measurement_time(Duration::from_secs(8));
    let n = 10_000;
    let cfg = SceneConfig::paper(n, 1);
    let tree = SphereTree::build(Star::new(cfg.shape_radius), 4).expect("tree");
    let world = World::generate(&cfg);
    let mut bp = BroadPhase::new(tree.root_radius(), world.lo, cfg.volume_side(), world.len());
    let pairs = bp.update(&world.position).to_vec();
    let mut np = NarrowPhase::default();
    np.reset(&pairs);
    for i in 0..pairs.len() {
        np.resolve_fully(i, &tree, &world);
    }
    let tests = np.tests;
    println!(
        "narrow_exact/{n}: {} candidate pairs, {tests} sphere tests, {:.1} tests per pair",
        pairs.len(),
        tests as f64 / pairs.len() as f64
    );
    g.throughput(Throughput::Elements(tests));
    g.bench_function(BenchmarkId::from_parameter(n), |b| {
        b.iter(|| {
            np.reset(&pairs);
            for i in 0..pairs.len() {
                np.resolve_fully(i, &tree, &world);
            }
            black_box(np.tests)
        })
    });
    g.finish();
}

fn narrow_steady(c: &mut Criterion) {
    let mut g = c.benchmark_group("narrow_steady");
    g.measurement_time(Duration::from_secs(8));
    for (n, truth) in [10_000u32, 100_000]
        .into_iter()
        .flat_map(|n| [(n, Truth::Shape), (n, Truth::LeafSpheres)])
    {
        let mut cfg = exact(n);
        cfg.scene.truth = truth;
        let label = match truth {
            Truth::Shape => n.to_string(),
            Truth::LeafSpheres => format!("{n}-leaf"),
        };
        let mut sim = Simulation::new(cfg.clone()).expect("valid");
        for _ in 0..60 {
            sim.step(None, &FrozenClock);
        }
        let (before, before_pairs) = (sim.world().clone(), sim.candidate_pairs().to_vec());
        sim.step(None, &FrozenClock);
        let (world, pairs) = (sim.world().clone(), sim.candidate_pairs().to_vec());
        // The same frames under each tree: the leaves, and so the bodies' motion, are the same.
        for kind in [TreeKind::Parts, TreeKind::Octree] {
            let tree = SphereTree::build_kind(Star::new(cfg.scene.shape_radius), 4, kind)
                .expect("tree")
                .with_truth(truth);
            let label = match kind {
                TreeKind::Parts => label.clone(),
                _ => format!("{label}-{kind}"),
            };
            for threads in [1usize, 2] {
                let mut np = NarrowPhase::default();
                np.reset(&before_pairs);
                np.resolve_all(&tree, &before, threads);
                np.remember_witnesses(before.len());
                np.reset(&pairs);
                np.resolve_all(&tree, &world, threads);
                g.throughput(Throughput::Elements(np.tests));
                g.bench_function(BenchmarkId::new(label.clone(), threads), |b| {
                    b.iter(|| {
                        np.reset(&pairs);
                        np.resolve_all(&tree, &world, threads);
                        black_box(np.tests)
                    })
                });
            }
        }
    }
    g.finish();
}

/// The shape level alone: every pair of frame 61 at N = 10,000 (shape truth) whose leaves
/// overlap, tested on the stars (`intersects`, what the narrow phase runs) and fully
/// (`contact`, what the response and the audit run); per pair in the throughput line. Beside
/// `narrow_steady`'s ns per sphere test this gives `SHAPE_TEST_COST`.
fn shape(c: &mut Criterion) {
    use foveal_engine::narrow_phase::shape_pose;
    let mut g = c.benchmark_group("shape");
    let n = 10_000;
    let mut cfg = exact(n);
    cfg.scene.truth = Truth::LeafSpheres;
    let mut sim = Simulation::new(cfg).expect("valid");
    for _ in 0..61 {
        sim.step(None, &FrozenClock);
    }
    let poses: Vec<_> = sim
        .pairs()
        .iter()
        .filter(|p| p.status == PairStatus::Colliding)
        .map(|p| shape_pose(sim.world(), p.a as usize, p.b as usize))
        .collect();
    let geometry = *sim.tree().geometry();
    g.throughput(Throughput::Elements(poses.len() as u64));
    g.bench_function(BenchmarkId::new("intersects", n), |b| {
        b.iter(|| {
            poses
                .iter()
                .filter(|p| geometry.intersects(black_box(p)))
                .count()
        })
    });
    g.bench_function(BenchmarkId::new("contact", n), |b| {
        b.iter(|| {
            poses
                .iter()
                .map(|p| geometry.contact(black_box(p)).signed_distance())
                .sum::<f64>()
        })
    });
    g.finish();
}

fn foveal_pass(c: &mut Criterion) {
    use foveal_engine::metrics::Fovea;
    use foveal_engine::narrow_phase::{PairState, StepOutcome};
    let mut g = c.benchmark_group("foveal_pass");
    g.measurement_time(Duration::from_secs(6));
    g.sample_size(20);
    let n = 100_000u32;
    let mut sim = Simulation::new(exact(n)).expect("valid");
    for _ in 0..60 {
        sim.step(None, &FrozenClock);
    }
    let before = sim.world().clone();
    let before_pairs = sim.candidate_pairs().to_vec();
    sim.step(None, &FrozenClock);
    let (world, pairs, tree) = (sim.world(), sim.candidate_pairs(), sim.tree());
    let viewer = sim.viewer();
    let fovea = Fovea::new(viewer, viewer.to_pixels(0.5, 0.5), 5.0);
    let pos = &world.position;
    let select =
        |p: &PairState| fovea.contains_point((pos[p.a as usize] + pos[p.b as usize]) * 0.5);
    let mut np = NarrowPhase::default();
    np.reset(&before_pairs);
    np.resolve_all(tree, &before, 1);
    np.remember_witnesses(before.len());
    let foveal = pairs
        .iter()
        .filter(|&&(a, b)| fovea.contains_point((pos[a as usize] + pos[b as usize]) * 0.5))
        .count();
    g.throughput(Throughput::Elements(foveal as u64));
    // The pass as it was: each foveal pair stepped level by level until settled.
    g.bench_function(BenchmarkId::new("stepped", n), |b| {
        b.iter(|| {
            np.reset(pairs);
            for i in 0..pairs.len() {
                if select(&np.pairs[i]) {
                    while np.step(i, tree, world) == StepOutcome::Active {}
                }
            }
            black_box(np.tests)
        })
    });
    for threads in [1usize, 2] {
        g.bench_function(BenchmarkId::new(format!("one-go-{threads}t"), n), |b| {
            b.iter(|| {
                np.reset(pairs);
                let settled =
                    np.resolve_selected(tree, world, pairs.len(), threads, &select, &mut |_| true);
                black_box(settled)
            })
        });
    }
    g.finish();
}

fn measure(c: &mut Criterion) {
    use foveal_engine::collider::Collider;
    use foveal_engine::{FrameBudget, FrameReport, PhaseProfile};
    let mut g = c.benchmark_group("measure");
    g.measurement_time(Duration::from_secs(8));
    g.sample_size(20);
    for n in [10_000u32, 100_000] {
        let mut sim = Simulation::new(exact(n)).expect("valid");
        for _ in 0..10 {
            sim.step(None, &FrozenClock);
        }
        let fixation = Some(foveal_engine::Fixation::at(0.4, 0.5));
        let round_robin = SimConfig {
            scheduler: SchedulerKind::RoundRobin,
            ..exact(n)
        };
        for (name, budget) in [
            ("settled", FrameBudget::Unlimited),
            ("deemed", FrameBudget::Tests(0)),
        ] {
            let mut col = Collider::new(&round_robin, sim.tree(), sim.viewer()).expect("valid");
            let input = sim.frame_input();
            let mut r = FrameReport::default();
            let mut p = PhaseProfile::default();
            col.collide(&input, fixation, budget, &FrozenClock, &mut r, &mut p);
            g.throughput(Throughput::Elements(u64::from(r.candidate_pairs)));
            g.bench_function(BenchmarkId::new(name, n), |b| {
                b.iter(|| {
                    col.measure(&input, fixation, &mut r);
                    black_box(r.foveal_pairs)
                })
            });
        }
    }
    g.finish();
}

fn ordering(c: &mut Criterion) {
    use foveal_engine::collider::Collider;
    use foveal_engine::{FrameBudget, FrameReport, PhaseProfile};
    let mut g = c.benchmark_group("ordering");
    g.measurement_time(Duration::from_secs(4));
    let at = foveal_engine::Fixation::at(0.4, 0.5);
    let fixation = Some(at);
    for n in [500u32, 10_000] {
        let mut sim = Simulation::new(exact(n)).expect("valid");
        for _ in 0..60 {
            sim.step(None, &FrozenClock);
        }
        {
            // The body pass alone (what the priced scheduler asks of prioritisation).
            use foveal_engine::schedule::{self, Priorities, Prioritiser};
            let cfg = exact(n);
            let prioritiser = Prioritiser::new(
                sim.viewer(),
                &cfg.schedule_model,
                cfg.eccentricity_threshold_deg,
                sim.tree().root_radius(),
                schedule::needs(SchedulerKind::Priced),
            );
            let mut out = Priorities::default();
            let f = at;
            let px = sim.viewer().to_pixels(f.x, f.y);
            let pairs = NarrowPhase::default();
            g.throughput(Throughput::Elements(u64::from(n)));
            g.bench_function(BenchmarkId::new("body-pass", n), |b| {
                b.iter(|| {
                    let mut meter =
                        foveal_engine::budget::Meter::new(FrameBudget::Unlimited, &FrozenClock);
                    prioritiser.prioritise(
                        &pairs.pairs,
                        sim.world(),
                        sim.viewer(),
                        Some((px, 0.0)),
                        &mut out,
                        &mut meter,
                    );
                    black_box(out.body_records().len())
                })
            });
        }
        let exact_tests = sim.last_report().sphere_tests;
        {
            // A frame's reset, alone and followed by the one-pass root settling that wall-clock
            // frames of round-robin and priced start with (per candidate pair).
            let input = sim.frame_input();
            let mut np = NarrowPhase::default();
            g.throughput(Throughput::Elements(input.candidates.len() as u64));
            g.bench_function(BenchmarkId::new("reset", n), |b| {
                b.iter(|| {
                    np.reset(input.candidates);
                    black_box(np.pairs.len())
                })
            });
            g.bench_function(BenchmarkId::new("reset-roots", n), |b| {
                b.iter(|| {
                    np.reset(input.candidates);
                    black_box(np.settle_separate_roots(input.tree, input.world, &mut |_| true))
                })
            });
        }
        {
            // The same frame resolved exactly, pair after pair: the sphere test's own cost.
            let mut col = Collider::new(&exact(n), sim.tree(), sim.viewer()).expect("valid");
            let input = sim.frame_input();
            let mut r = FrameReport::default();
            let mut p = PhaseProfile::default();
            g.throughput(Throughput::Elements(exact_tests));
            g.bench_function(BenchmarkId::new("exact", n), |b| {
                b.iter(|| {
                    col.collide(
                        &input,
                        fixation,
                        FrameBudget::Unlimited,
                        &FrozenClock,
                        &mut r,
                        &mut p,
                    );
                    black_box(r.sphere_tests)
                })
            });
        }
        for kind in [
            SchedulerKind::RoundRobin,
            SchedulerKind::Sequential,
            SchedulerKind::Priced,
        ] {
            let cfg = SimConfig {
                scheduler: kind,
                ..exact(n)
            };
            let mut col = Collider::new(&cfg, sim.tree(), sim.viewer()).expect("valid");
            let input = sim.frame_input();
            let mut r = FrameReport::default();
            let mut p = PhaseProfile::default();
            g.throughput(Throughput::Elements(input.candidates.len() as u64));
            g.bench_function(BenchmarkId::new(kind.name(), n), |b| {
                b.iter(|| {
                    col.collide(
                        &input,
                        fixation,
                        FrameBudget::Tests(0),
                        &FrozenClock,
                        &mut r,
                        &mut p,
                    );
                    black_box(r.deemed)
                })
            });
            // The same frame with a tenth of its exact sphere tests: what the steps cost on top.
            let tenth = FrameBudget::Tests(exact_tests / 10);
            g.throughput(Throughput::Elements(exact_tests / 10));
            g.bench_function(
                BenchmarkId::new(format!("{}-tests-0.1", kind.name()), n),
                |b| {
                    b.iter(|| {
                        col.collide(&input, fixation, tenth, &FrozenClock, &mut r, &mut p);
                        black_box(r.deemed)
                    })
                },
            );
        }
    }
    g.finish();
}

criterion_group!(
    benches,
    foveal_pass,
    frame,
    broad,
    narrow,
    narrow_steady,
    shape,
    measure,
    ordering
);
criterion_main!(benches);
