//! One frame of the paper's main loop (section 2): integrate, broad phase, narrow phase under the
//! budget, response; then measure (section 3) and, in audit mode, check every deemed pair against
//! the exact answer.

use crate::broad_phase::BroadPhase;
use crate::budget::{Clock, FrameBudget, FrozenClock, Meter};
use crate::config::{BudgetSpec, ConfigError, SimConfig};
use crate::fixation::{Fixation, FrameView};
use crate::narrow_phase::{NarrowPhase, PairState, PairStatus, separation};
use crate::perception::{EccentricityUnit, Viewer};
use crate::report::{AuditReport, FrameReport, PhaseProfile};
use crate::response::exchange_velocities;
use crate::schedule::{self, Scheduler, Work};
use crate::shape::Star;
use crate::sphere_tree::SphereTree;
use crate::world::World;

/// A running simulation.
#[derive(Debug)]
pub struct Simulation {
    config: SimConfig,
    tree: SphereTree,
    world: World,
    broad: BroadPhase,
    narrow: NarrowPhase,
    scheduler: Box<dyn Scheduler>,
    viewer: Viewer,
    budget: FrameBudget,
    report: FrameReport,
    next_index: u64,
    sim_time: f64,
    /// Per-body screen positions, reused by prioritisation every frame.
    screen: Vec<[f64; 2]>,
    /// Scratch stack of the audit's separation queries.
    audit_stack: Vec<(f32, u16, u16, u8, u8)>,
}

impl Simulation {
    /// Validate `config`, generate its scene and, for a budget given as a fraction of the exact cost,
    /// calibrate it by running the exact narrow phase on a private copy of the scene.
    pub fn new(config: SimConfig) -> Result<Self, ConfigError> {
        config.validate()?;
        let sc = &config.scene;
        let tree = SphereTree::build(Star::new(sc.shape_radius), sc.depth as usize)?;
        let world = World::generate(sc);
        let side = sc.volume_side();
        let broad = BroadPhase::new(tree.root_radius(), world.lo, side, world.len());
        let viewer = Viewer::new(&config.camera, &config.display, world.lo, side);
        let mut sim = Self::from_parts(config, tree, world, broad, viewer);
        sim.budget = match sim.config.budget {
            BudgetSpec::Exact => FrameBudget::Unlimited,
            BudgetSpec::InterruptAtZero => FrameBudget::Tests(0),
            BudgetSpec::SphereTests(n) => FrameBudget::Tests(n),
            BudgetSpec::WallMs(_) => FrameBudget::Unlimited, // resolved per frame in `step`
            BudgetSpec::FractionOfExact(f) => {
                let mean = sim.exact_cost(sim.config.calibration_frames);
                FrameBudget::Tests((f * mean).round() as u64)
            }
        };
        sim.broad.update(&sim.world.position);
        Ok(sim)
    }

    /// Mean sphere tests per frame of the exact narrow phase over `frames` frames of this scene,
    /// counted after `calibration_warmup` uncounted frames, measured on a copy (this simulation is
    /// not advanced).
    pub fn exact_cost(&self, frames: u32) -> f64 {
        let mut cfg = self.config.clone();
        cfg.budget = BudgetSpec::Exact;
        cfg.scheduler = crate::config::SchedulerKind::Sequential;
        cfg.audit = false;
        let mut copy = Self::from_parts(
            cfg,
            self.tree.clone(),
            self.world.clone(),
            self.broad.clone(),
            self.viewer,
        );
        for _ in 0..self.config.calibration_warmup {
            copy.step(None, &FrozenClock);
        }
        let total: u64 = (0..frames.max(1))
            .map(|_| copy.step(None, &FrozenClock).sphere_tests)
            .sum();
        total as f64 / f64::from(frames.max(1))
    }

    /// A simulation over existing state, at frame 0, with an unlimited budget.
    fn from_parts(
        config: SimConfig,
        tree: SphereTree,
        world: World,
        broad: BroadPhase,
        viewer: Viewer,
    ) -> Self {
        Self {
            scheduler: schedule::for_kind(config.scheduler),
            budget: FrameBudget::Unlimited,
            tree,
            world,
            broad,
            narrow: NarrowPhase::default(),
            viewer,
            report: FrameReport::default(),
            next_index: 0,
            sim_time: 0.0,
            screen: Vec::new(),
            audit_stack: Vec::new(),
            config,
        }
    }

    /// The configuration in force.
    pub fn config(&self) -> &SimConfig {
        &self.config
    }

    /// The sphere tree shared by all bodies.
    pub fn tree(&self) -> &SphereTree {
        &self.tree
    }

    /// Body state.
    pub fn world(&self) -> &World {
        &self.world
    }

    /// Camera and display.
    pub fn viewer(&self) -> &Viewer {
        &self.viewer
    }

    /// The per-frame budget after calibration (sphere tests for fraction-of-exact budgets).
    pub fn frame_budget(&self) -> FrameBudget {
        self.budget
    }

    /// Candidate pairs of the last broad phase.
    pub fn candidate_pairs(&self) -> &[(u32, u32)] {
        self.broad.pairs()
    }

    /// Pair states of the last frame (status tells real, separate or deemed).
    pub fn pairs(&self) -> &[PairState] {
        &self.narrow.pairs
    }

    /// The last frame's report.
    pub fn last_report(&self) -> &FrameReport {
        &self.report
    }

    /// Run one frame. `fixation` is where the viewer looks (None, or non-finite, means unknown:
    /// no perceptual work is done and P is not measured). `clock` times the phases and enforces a
    /// wall-clock budget; pass [`FrozenClock`] for deterministic runs.
    pub fn step(&mut self, fixation: Option<Fixation>, clock: &dyn Clock) -> &FrameReport {
        let mut profile = PhaseProfile::default();
        let t0 = clock.now_ns();
        self.world.integrate(self.config.scene.dt);
        let t1 = clock.now_ns();
        profile.integrate_ns = t1 - t0;

        let candidates = self.broad.update(&self.world.position);
        self.narrow.reset(candidates);
        let t2 = clock.now_ns();
        profile.broad_ns = t2 - t1;

        let fixation_rejected = fixation.is_some_and(|f| !f.is_usable());
        let fixation = fixation.filter(Fixation::is_usable);
        let fixation_px = fixation.map(|f| {
            let f = f.clamped();
            self.viewer.to_pixels(f.x, f.y)
        });
        let schedule_view = fixation_px
            .filter(|_| self.config.scheduler.needs_priority())
            .map(|px| FrameView {
                viewer: &self.viewer,
                fixation_px: px,
                model: self.config.schedule_model,
            });
        let budget = match self.config.budget {
            // The paper's target time covers all collision handling, so the deadline counts from
            // the start of the broad phase.
            BudgetSpec::WallMs(ms) => FrameBudget::Deadline(t1 + (ms * 1e6) as u64),
            _ => self.budget,
        };
        let mut meter = Meter::new(budget, clock);
        if let Some(view) = &schedule_view {
            prioritise(
                &mut self.narrow,
                &self.world,
                view,
                self.config.eccentricity_threshold_deg,
                &mut self.screen,
                &mut meter,
            );
        }
        let work = Work {
            tree: &self.tree,
            world: &self.world,
            view: schedule_view.as_ref(),
        };
        self.scheduler.run(&mut self.narrow, &work, &mut meter);
        let deemed = self.narrow.deem_open();
        self.narrow.remember_witnesses(self.world.len());
        let t3 = clock.now_ns();
        profile.narrow_ns = t3 - t2;

        let collisions = self
            .narrow
            .pairs
            .iter()
            .filter(|p| p.status.is_collision())
            .map(|p| (p.a, p.b));
        let responses = exchange_velocities(&mut self.world, collisions);
        let t4 = clock.now_ns();
        profile.response_ns = t4 - t3;

        let mut r = FrameReport {
            index: self.next_index,
            fixation,
            fixation_rejected,
            candidate_pairs: self.narrow.pairs.len() as u32,
            deemed,
            responses,
            sphere_tests: self.narrow.tests,
            budget_exhausted: deemed > 0,
            ..FrameReport::default()
        };
        self.next_index += 1;
        self.sim_time += self.config.scene.dt;
        r.sim_time = self.sim_time;
        let measure_view = fixation_px.map(|px| FrameView {
            viewer: &self.viewer,
            fixation_px: px,
            model: self.config.measure_model,
        });
        self.measure(&mut r, measure_view.as_ref());
        if self.config.audit {
            r.audit = Some(audit(
                &self.narrow,
                &self.tree,
                &self.world,
                measure_view.as_ref(),
                &mut self.audit_stack,
            ));
        }
        profile.measure_ns = clock.now_ns() - t4;
        r.profile = profile;
        self.report = r;
        &self.report
    }

    /// Counts per level, Δ and P (section 3) from the pair states.
    fn measure(&self, r: &mut FrameReport, view: Option<&FrameView<'_>>) {
        let mut delta = 0.0;
        let mut p_sum = 0.0;
        for (i, p) in self.narrow.pairs.iter().enumerate() {
            match p.status {
                PairStatus::Colliding => r.real_collisions += 1,
                PairStatus::Deemed => {
                    let ev = self.narrow.evidence(i, &self.tree, &self.world);
                    delta += ev.gap;
                    if let Some(v) = view {
                        p_sum += v.weight(&ev);
                    }
                }
                _ => {}
            }
            if p.resolved_level > 0 {
                r.resolved_per_level[p.resolved_level as usize - 1] += 1;
            }
        }
        r.geometric_inaccuracy = delta;
        r.perceived_inaccuracy = view.map(|_| p_sum);
    }

    /// Exact colliding pairs among the current candidates (each resolved to completion).
    pub fn exact_colliding_pairs(&self) -> Vec<(u32, u32)> {
        let mut np = NarrowPhase::default();
        np.reset(self.broad.pairs());
        let mut out = Vec::new();
        for i in 0..np.pairs.len() {
            if np.resolve_fully(i, &self.tree, &self.world) == crate::narrow_phase::StepOutcome::Hit
            {
                out.push((np.pairs[i].a, np.pairs[i].b));
            }
        }
        out
    }
}

/// Fill each pair's priority (F of the scheduling model on its current evidence) and its
/// priority-queue membership (eccentricity in degrees within `threshold_deg`, section 4).
///
/// Every pair is still untested here, so its evidence is the two body centres and its centre of
/// collision their midpoint (equal bounding spheres). Body centres are projected once per body into
/// `screen`, not once per pair, and the eccentricity in degrees serves both the model and the queue
/// threshold when the model works in degrees: this runs over every candidate pair inside the budget.
/// It checks a wall-clock deadline every 64 pairs and stops when it has passed: the pairs it did not
/// reach keep priority 0 in the outer queue, and the scheduler then deems them, so a budget smaller
/// than the prioritisation itself is still held.
fn prioritise(
    np: &mut NarrowPhase,
    world: &World,
    view: &FrameView<'_>,
    threshold_deg: f64,
    screen: &mut Vec<[f64; 2]>,
    meter: &mut Meter<'_>,
) {
    let viewer = view.viewer;
    screen.clear();
    screen.extend(world.position.iter().map(|&p| viewer.project(p)));
    let unit = view.model.unit;
    for (k, p) in np.pairs.iter_mut().enumerate() {
        // Sphere-test budgets do not count this work (it tests no spheres), so pass 0 tests.
        if k % 64 == 0 && meter.exhausted_by_clock() {
            return;
        }
        let (a, b) = (p.a as usize, p.b as usize);
        let centre = viewer.project((world.position[a] + world.position[b]) * 0.5);
        let e_deg = viewer.screen_distance(centre, view.fixation_px, EccentricityUnit::Degrees);
        let e = match unit {
            EccentricityUnit::Degrees => e_deg,
            EccentricityUnit::Pixels => viewer.screen_distance(centre, view.fixation_px, unit),
        };
        let g = viewer.screen_distance(screen[a], screen[b], unit);
        p.priority = view.model.evaluate(g, e) as f32;
        p.inner = e_deg <= threshold_deg;
    }
}

/// The exact answer for every deemed pair: whether it collides, and for those that do not, the
/// true gap (separation of the leaf-sphere sets) and its perceived weight at the closest points.
fn audit(
    np: &NarrowPhase,
    tree: &SphereTree,
    world: &World,
    view: Option<&FrameView<'_>>,
    stack: &mut Vec<(f32, u16, u16, u8, u8)>,
) -> AuditReport {
    let mut a = AuditReport::default();
    let mut p_sum = 0.0;
    for p in np.pairs.iter().filter(|p| p.status == PairStatus::Deemed) {
        let (sep, ca, cb) = separation(tree, world, p.a as usize, p.b as usize, stack);
        if sep <= 0.0 {
            a.true_positives += 1;
            continue;
        }
        a.false_positives += 1;
        a.geometric_inaccuracy += sep;
        if let Some(v) = view {
            // Closest points of the two leaf spheres lie on their centre line; all leaves share
            // one radius, (d - sep) / 2.
            let u = (cb - ca).normalize_or_zero();
            let d = (cb - ca).length();
            let gap_a = ca + u * (0.5 * (d - sep));
            let gap_b = gap_a + u * sep;
            p_sum += v.weight_points(gap_a, gap_b, (gap_a + gap_b) * 0.5);
        }
    }
    a.perceived_inaccuracy = view.map(|_| p_sum);
    a
}
