//! One frame of the paper's main loop (section 2) as a short list of named, timed phases:
//! integrate, broad phase, prioritise, narrow phase under the budget, response, and metrics
//! (section 3) with, in audit mode, the exact answer for every deemed pair. Each phase's time goes
//! into the frame's [`PhaseProfile`]; a wall-clock budget counts from the start of the frame, so
//! every phase spends the same budget.

use crate::broad_phase::BroadPhase;
use crate::budget::{Clock, FrameBudget, FramePlan, FramePolicy, FrozenClock};
use crate::collider::{Collider, FrameInput, NarrowFrame};
use crate::config::{BudgetSpec, ConfigError, SimConfig, Truth};
use crate::fixation::Fixation;
use crate::narrow_phase::{NarrowPhase, PairState};
use crate::perception::Viewer;
use crate::report::{FrameReport, PhaseProfile};
use crate::response::Response;
use crate::shape::Star;
use crate::sphere_tree::SphereTree;
use crate::world::World;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

/// A running simulation.
#[derive(Debug)]
pub struct Simulation {
    config: SimConfig,
    tree: SphereTree,
    world: World,
    broad: BroadPhase,
    collider: Collider,
    response: Response,
    viewer: Viewer,
    budget: FrameBudget,
    report: FrameReport,
    next_index: u64,
    sim_time: f64,
    /// What a wall-clock budget learns across frames: the guard band, the shedding's costs and
    /// the pool's hand-back.
    policy: FramePolicy,
    /// Per body slot, the body's id (its index at generation): the numbering outside the engine.
    ids: Vec<u32>,
    /// Per body id, its slot (the inverse of `ids`).
    slots: Vec<u32>,
    /// The threads a frame runs on, with more than one (see [`Self::step`]).
    pool: Option<Arc<rayon::ThreadPool>>,
    /// Regions the last frame's broad phase searched of its shedding order (None: it searched
    /// every region, unordered), for [`Self::measured_at`].
    last_searched: Option<usize>,
}

/// A pool of `threads` threads, or none for one: a frame on one thread runs where it is called.
/// If the system refuses the threads, frames run on the calling thread, and their parallel
/// phases on rayon's global pool (the same results: no output depends on the threads).
fn thread_pool(threads: usize) -> Option<Arc<rayon::ThreadPool>> {
    if threads <= 1 {
        return None;
    }
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .thread_name(|k| format!("foveal-frame-{k}"))
        .build()
        .ok()
        .map(Arc::new)
}

impl Simulation {
    /// Validate `config`, generate its scene and, for a budget given as a fraction of the exact cost,
    /// calibrate it by running the exact narrow phase on a private copy of the scene.
    pub fn new(config: SimConfig) -> Result<Self, ConfigError> {
        config.validate()?;
        let sc = &config.scene;
        let tree = SphereTree::build_kind(Star::new(sc.shape_radius), sc.depth as usize, sc.tree)?
            .with_truth(sc.truth);
        let world = World::generate(sc);
        let side = sc.volume_side();
        let mut broad = BroadPhase::with_kind(
            config.broad_phase,
            tree.root_radius(),
            world.lo,
            side,
            world.len(),
        );
        broad.set_threads(config.threads as usize);
        let viewer = Viewer::new(&config.camera, &config.display, world.lo, side);
        let mut sim = Self::from_parts(config, tree, world, broad, viewer)?;
        sim.budget = match sim.config.budget {
            BudgetSpec::Exact => FrameBudget::Unlimited,
            BudgetSpec::InterruptAtZero => FrameBudget::Tests(0),
            BudgetSpec::SphereTests(n) => FrameBudget::Tests(n),
            BudgetSpec::WallMs(ms) => FrameBudget::Wall((ms * 1e6).round() as u64),
            BudgetSpec::FractionOfExact(f) => {
                let mean = sim.exact_cost(sim.config.calibration_frames)?;
                FrameBudget::Tests((f * mean).round() as u64)
            }
        };
        sim.on_pool(|sim| {
            sim.broad.update(&sim.world.position);
            if sim.config.renumber_every > 0 {
                sim.renumber();
            }
        });
        Ok(sim)
    }

    /// A simulation of `config` whose narrow phase runs `scheduler` instead of the one `config`
    /// names (for schedulers defined outside the engine's list, as the tests' toy one).
    #[cfg(test)]
    pub(crate) fn with_scheduler(
        config: SimConfig,
        scheduler: Box<dyn crate::schedule::Scheduler>,
    ) -> Result<Self, ConfigError> {
        let mut sim = Self::new(config)?;
        sim.collider = Collider::with_scheduler(&sim.config, &sim.tree, &sim.viewer, scheduler)?;
        Ok(sim)
    }

    /// Mean sphere tests per frame of the exact narrow phase over `frames` frames of this scene,
    /// counted after `calibration_warmup` uncounted frames, measured on a copy (this simulation is
    /// not advanced).
    pub fn exact_cost(&self, frames: u32) -> Result<f64, ConfigError> {
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
        )?;
        for _ in 0..self.config.calibration_warmup {
            copy.step(None, &FrozenClock);
        }
        let total: u64 = (0..frames.max(1))
            .map(|_| copy.step(None, &FrozenClock).sphere_tests)
            .sum();
        Ok(total as f64 / f64::from(frames.max(1)))
    }

    /// A simulation over existing state, at frame 0, with an unlimited budget.
    fn from_parts(
        config: SimConfig,
        tree: SphereTree,
        world: World,
        broad: BroadPhase,
        viewer: Viewer,
    ) -> Result<Self, ConfigError> {
        Ok(Self {
            collider: Collider::new(&config, &tree, &viewer)?,
            response: Response::default(),
            budget: FrameBudget::Unlimited,
            report: FrameReport::default(),
            last_searched: None,
            next_index: 0,
            sim_time: 0.0,
            policy: FramePolicy::default(),
            ids: (0..world.len() as u32).collect(),
            slots: (0..world.len() as u32).collect(),
            pool: thread_pool(config.threads as usize),
            tree,
            world,
            broad,
            viewer,
            config,
        })
    }

    /// The configuration in force.
    pub fn config(&self) -> &SimConfig {
        &self.config
    }

    /// The sphere tree shared by all bodies.
    pub fn tree(&self) -> &SphereTree {
        &self.tree
    }

    /// Body state, in slot order: slot `i` holds body [`Self::body_ids`]`[i]`. Slots are the ids
    /// until the first renumbering (only with the grid broad phase and
    /// [`SimConfig::renumber_every`] > 0); every pair the engine lists names slots.
    pub fn world(&self) -> &World {
        &self.world
    }

    /// Per slot, the id of the body there: its index at generation, which never changes.
    pub fn body_ids(&self) -> &[u32] {
        &self.ids
    }

    /// Per body id, the slot it is in now (the inverse of [`Self::body_ids`]).
    pub fn body_slots(&self) -> &[u32] {
        &self.slots
    }

    /// A pair of slots as the pair of body ids it names, smaller id first.
    #[inline]
    pub fn id_pair(&self, (a, b): (u32, u32)) -> (u32, u32) {
        let (x, y) = (self.ids[a as usize], self.ids[b as usize]);
        (x.min(y), x.max(y))
    }

    /// Renumber the bodies in the broad phase's spatial order (the grid's cell order at its last
    /// update): every per-body array moves together, the broad phase's kept pairs and the narrow
    /// phase's witnesses follow, and [`Self::body_ids`] keeps the outside numbering. No answer
    /// changes: which pairs collide does not depend on the numbering (the order in which the
    /// response treats them does, as it depends on the broad phase's order anyway).
    fn renumber(&mut self) {
        let Some(order) = self.broad.spatial_order() else {
            return;
        };
        let mut new_of_old = vec![0u32; order.len()];
        for (new, &old) in order.iter().enumerate() {
            new_of_old[old as usize] = new as u32;
        }
        self.world.reorder(&order);
        self.broad.renumber(&new_of_old);
        self.collider.renumber(&new_of_old);
        self.ids = order.iter().map(|&old| self.ids[old as usize]).collect();
        for (slot, &id) in self.ids.iter().enumerate() {
            self.slots[id as usize] = slot as u32;
        }
    }

    /// Camera and display.
    pub fn viewer(&self) -> &Viewer {
        &self.viewer
    }

    /// The per-frame budget in force: sphere tests (fraction-of-exact budgets after calibration),
    /// a wall-clock allowance per frame, or unlimited.
    pub fn frame_budget(&self) -> FrameBudget {
        self.budget
    }

    /// Candidate pairs of the last broad phase.
    pub fn candidate_pairs(&self) -> &[(u32, u32)] {
        self.broad.pairs()
    }

    /// Pair states of the last frame (status tells real, separate or deemed).
    pub fn pairs(&self) -> &[PairState] {
        self.collider.pairs()
    }

    /// The last frame's audit, pair by pair: for each deemed pair of [`Self::pairs`], in order,
    /// whether it truly collides. Empty when the frame was not audited.
    pub fn deemed_truth(&self) -> &[crate::DeemedTruth] {
        self.collider.deemed_truth()
    }

    /// What prioritisation computed for the last frame's pairs.
    pub fn priorities(&self) -> &crate::schedule::Priorities {
        self.collider.priorities()
    }

    /// The last frame's report.
    pub fn last_report(&self) -> &FrameReport {
        &self.report
    }

    /// This frame's poses and candidates, for a collider.
    pub fn frame_input(&self) -> FrameInput<'_> {
        frame_input(&self.tree, &self.world, &self.broad, &self.viewer)
    }

    /// Run one frame. `fixation` is where the viewer looks (None, or non-finite, means unknown:
    /// no perceptual work is done and P is not measured). `clock` times the phases and enforces a
    /// wall-clock budget; pass [`FrozenClock`] for deterministic runs.
    ///
    /// A wall-clock budget covers the whole frame: at every N the narrow phase stops early enough
    /// for the learnt tail (response and metrics), and Δ and P are summed over a sample when
    /// every deemed pair would not fit. The first frame has learnt no tail and overruns by it; the
    /// audit, when on, runs after the budgeted work (a diagnostic, outside the budget). Where the scene's broad phase has regions (the grid, at
    /// large N), the frame also sheds what does not fit in perceptual order (see
    /// [`crate::budget::shedding`]) and reports it ([`FrameReport::stale_regions`]); sphere-test and exact
    /// budgets run every phase whole.
    ///
    /// With more than one thread the frame runs on the simulation's own pool of that many
    /// threads, so that its phases hand work to threads that are already running (about a
    /// microsecond a phase) instead of starting threads (30-70 us each, several a frame). The
    /// frame's clock starts before the hand-over, so the budget counts it.
    pub fn step(&mut self, fixation: Option<Fixation>, clock: &dyn Clock) -> &FrameReport {
        let t0 = clock.now_ns();
        let pooled = self.pool.is_some();
        match self.pool.clone() {
            // Exact frames only, whose narrow phase is parallel too. Under a wall-clock budget
            // the spinners' end lengthened the frame's hand-back in its tail (p99 4.15-4.78
            // against 4.09-4.29 ms at N = 10,000 with 4 ms); under a sphere-test budget the
            // scheduler runs on one thread and a spinner would only burn its core meanwhile.
            Some(pool) if self.budget == FrameBudget::Unlimited => pool.install(|| {
                keeping_the_pool_awake(|| self.step_from(t0, fixation, clock));
            }),
            Some(pool) => pool.install(|| self.step_from(t0, fixation, clock)),
            None => self.step_from(t0, fixation, clock),
        }
        self.policy
            .after_frame(self.budget, &self.report, self.sim_time, pooled, t0, clock);
        &self.report
    }

    /// Keep every thread of the simulation's pool busy until `clock` reads `until_ns` (at most
    /// [`MAX_POOL_WARM_NS`] from now), then return; with one thread, return at once.
    ///
    /// For a caller that paces its frames. On a machine whose idle processors wake slowly (a
    /// virtual machine's), a pool that slept through the pause before a frame ran that frame up
    /// to twice as slow: the paper scene at N = 10,000, exact, two threads, step p50 3.9-4.0 ms
    /// after a 14 ms pause against 1.9-2.4 ms back to back, every phase slower. With the pool's
    /// threads kept busy for the last 200 us of the pause, 2.1-2.5 ms, for 200 us of processor
    /// time a thread a frame (docs/BENCHMARKS.md).
    pub fn warm_pool_until(&self, clock: &dyn Clock, until_ns: u64) {
        if let Some(pool) = &self.pool {
            let until = until_ns.min(clock.now_ns().saturating_add(MAX_POOL_WARM_NS));
            pool.broadcast(|_| {
                // Bounded by reads too: a clock that does not advance (a frozen one) must not
                // keep the pool spinning for ever. A read takes at least a nanosecond, so the
                // bound is never shorter than the cap.
                for _ in 0..MAX_POOL_WARM_NS {
                    if clock.now_ns() >= until {
                        break;
                    }
                    std::hint::spin_loop();
                }
            });
        }
    }

    /// Run `f` on the simulation's pool when it has one (more than one thread), else here: the
    /// parallel phases then hand their parts to the pool's threads, never to rayon's global pool.
    fn on_pool<R: Send>(&mut self, f: impl FnOnce(&mut Self) -> R + Send) -> R {
        match self.pool.clone() {
            Some(pool) => pool.install(|| f(self)),
            None => f(self),
        }
    }

    /// [`Self::step`] on the calling thread, its frame started at `t0`: the frame's stages in
    /// their order ([`STAGES`]), each timed by [`Self::run_stage`].
    fn step_from(&mut self, t0: u64, fixation: Option<Fixation>, clock: &dyn Clock) {
        let plan = self.policy.plan(self.budget, t0);
        let fixation_rejected = fixation.is_some_and(|f| !f.is_usable());
        let fixation = fixation.filter(Fixation::is_usable);
        let mut frame = Frame {
            clock,
            plan,
            fixation,
            report: FrameReport {
                index: self.next_index,
                fixation,
                fixation_rejected,
                guard_ns: plan.guard_ns,
                ..FrameReport::default()
            },
            profile: PhaseProfile::default(),
            last_ns: t0,
            shedding: plan.shedding(!self.broad.regions().is_empty()),
            searched: 0,
            pairs: 0,
            broad_end_ns: t0,
            narrow_budget: plan.budget,
            foveal_prefix: None,
            sample: (0, None),
            tail_end_ns: t0,
        };
        for stage in STAGES {
            self.run_stage(stage, &mut frame);
        }
        self.policy.frame_ended(frame.last_ns);
        frame.report.profile = frame.profile;
        self.report = frame.report;
    }

    /// Run `stage` of `frame` and time it: the one place a stage's time is read and booked in
    /// the frame's [`PhaseProfile`]. A stage that did nothing ([`Lap::Skipped`]) does not read
    /// the clock (a read is not free); the next stage's time then counts from the last reading.
    fn run_stage(&mut self, stage: Stage, frame: &mut Frame<'_>) {
        let lap = match stage {
            Stage::Renumber => self.renumber_stage(frame),
            Stage::Integrate => self.integrate(),
            Stage::BroadPhase => self.broad_phase(frame),
            Stage::NarrowPhase => self.narrow_phase(frame),
            Stage::Respond => self.respond(frame),
            Stage::Measure => self.measure(frame),
            Stage::Audit => self.audit(frame),
            Stage::Learn => self.learn(frame),
        };
        if lap == Lap::Skipped {
            return;
        }
        let now = frame.clock.now_ns();
        let spent = now - frame.last_ns;
        frame.last_ns = now;
        let p = &mut frame.profile;
        match stage {
            Stage::Renumber => p.renumber_ns += spent,
            Stage::Integrate => p.integrate_ns += spent,
            Stage::BroadPhase => p.broad_ns += spent,
            // The collider splits its time between prioritisation and the narrow phase itself
            // (its passes interleave them), and books an exact frame's counting as measurement.
            Stage::NarrowPhase => {}
            Stage::Respond => p.response_ns += spent,
            // The audit is booked as measurement, but after the tail a wall-clock budget learns
            // (see `Self::learn`).
            Stage::Measure | Stage::Audit => p.measure_ns += spent,
            Stage::Learn => {}
        }
    }

    /// Stage: renumber the bodies every [`SimConfig::renumber_every`] frames (see
    /// [`Self::renumber`]). Under a wall-clock budget the bodies are renumbered only at creation:
    /// a renumbering costs about 0.1 us per body (10 ms at 100,000 bodies), more than such a
    /// frame can spare.
    fn renumber_stage(&mut self, frame: &Frame<'_>) -> Lap {
        let every = u64::from(self.config.renumber_every);
        if every > 0
            && !frame.plan.is_wall()
            && self.next_index > 0
            && self.next_index.is_multiple_of(every)
            && self.broad.has_spatial_order()
        {
            self.renumber();
            Lap::Timed
        } else {
            Lap::Skipped
        }
    }

    /// Stage: advance every body by one time step.
    fn integrate(&mut self) -> Lap {
        self.world
            .integrate_threads(self.config.scene.dt, self.config.threads as usize);
        Lap::Timed
    }

    /// Stage: the broad phase. A wall-clock frame whose broad phase has regions searches them in
    /// perceptual order for as long as the frame can pay for their pairs (see
    /// [`crate::budget::shedding`]); otherwise every region is searched.
    fn broad_phase(&mut self, frame: &mut Frame<'_>) -> Lap {
        let clock = frame.clock;
        let r = &mut frame.report;
        if let Some((end, ns)) = frame.shedding {
            let shedder = &mut self.policy.shedder;
            let mut pacer = shedder.pacer(end, ns);
            let order = shedder.order(
                self.broad.regions(),
                &self.viewer,
                frame.fixation,
                2.0 * self.tree.root_radius(),
            );
            let pass = self
                .broad
                .update_in_order(&self.world.position, order, &mut |pairs| {
                    pacer.go_on(clock.now_ns(), pairs)
                });
            frame.searched = pass.searched as usize;
            self.last_searched = Some(frame.searched);
            r.regions = self.broad.regions().len() as u32;
            r.stale_regions = pass.stale;
            r.stale_pairs = pass.stale_pairs;
            r.foveal_stale = shedder.foveal_regions().saturating_sub(frame.searched) as u32;
        } else {
            self.broad.update(&self.world.position);
            self.last_searched = None;
        }
        Lap::Timed
    }

    /// Stage: prioritise and run the narrow phase under what is left of the budget (the
    /// collider's passes, see [`Collider::collide_frame`]). Pairs are listed region by
    /// region in the searched order, so only the first regions' pairs can be foveal.
    fn narrow_phase(&mut self, frame: &mut Frame<'_>) -> Lap {
        // The broad phase's stage ended at the last reading.
        frame.broad_end_ns = frame.last_ns;
        frame.pairs = self.broad.pairs().len();
        frame.narrow_budget = self.policy.narrow_budget(&frame.plan, frame.pairs);
        frame.report.budget_spent_before_narrow =
            matches!(frame.narrow_budget, FrameBudget::Deadline(d) if frame.last_ns >= d);
        let input = frame_input(&self.tree, &self.world, &self.broad, &self.viewer);
        frame.foveal_prefix = frame.shedding.map(|_| {
            let foveal = self.policy.shedder.foveal_regions().min(frame.searched);
            self.broad.region_pairs_before(foveal)
        });
        let narrow = NarrowFrame {
            fixation: frame.fixation,
            budget: frame.narrow_budget,
            clock: frame.clock,
            foveal_prefix: frame.foveal_prefix,
        };
        self.collider
            .collide_frame(&input, &narrow, &mut frame.report, &mut frame.profile);
        Lap::Timed
    }

    /// Stage: exchange the velocities of approaching pairs on the collision list (real and
    /// deemed); the frame's simulated time advances.
    ///
    /// Under the leaf truth the paper's exchange (whole velocities, along the centre line);
    /// under the shape truth the velocity components along the stars' contact normal, so that
    /// bodies bounce where they visibly touch.
    fn respond(&mut self, frame: &mut Frame<'_>) -> Lap {
        frame.report.responses = match self.config.scene.truth {
            Truth::LeafSpheres => self
                .response
                .exchange(&mut self.world, self.collider.collisions()),
            Truth::Shape => self.response.exchange_on_shape(
                &mut self.world,
                &self.tree,
                self.collider.collisions_settled(),
                self.config.threads as usize,
            ),
        };
        self.next_index += 1;
        self.sim_time += self.config.scene.dt;
        frame.report.sim_time = self.sim_time;
        Lap::Timed
    }

    /// Stage: Δ, P and the counts of the frame (section 3), within the plan's effort (see
    /// [`crate::budget::FramePolicy::effort`]).
    fn measure(&mut self, frame: &mut Frame<'_>) -> Lap {
        let input = frame_input(&self.tree, &self.world, &self.broad, &self.viewer);
        let effort = self.policy.effort(
            &frame.plan,
            frame.foveal_prefix,
            self.collider.foveal_known(),
            self.collider.foveal_marked(),
        );
        frame.sample = self.collider.measure_metrics(
            &input,
            frame.fixation,
            effort,
            frame.plan.deadline.map(|_| frame.clock),
            &mut frame.report,
        );
        Lap::Timed
    }

    /// Stage: the audit, in audit mode: the exact answer for every deemed pair, and the pairs a
    /// shed broad phase missed. The tail a whole-frame budget learns ends where this stage
    /// starts: the audit is a diagnostic that runs after the budgeted work. Counted as tail, its
    /// cost, which grows with the deemed pairs, would deem more pairs the next frame, until every
    /// pair is.
    fn audit(&mut self, frame: &mut Frame<'_>) -> Lap {
        frame.tail_end_ns = frame.last_ns;
        let (sampled, sample_started) = frame.sample;
        if let Some(t) = sample_started {
            self.policy
                .shedder
                .learn_sample(sampled, frame.tail_end_ns.saturating_sub(t));
        }
        let input = frame_input(&self.tree, &self.world, &self.broad, &self.viewer);
        self.collider
            .audit_frame(&input, frame.fixation, &mut frame.report);
        if frame.report.stale_regions > 0
            && let Some(a) = frame.report.audit.as_mut()
        {
            a.missed_pairs = missed_pairs(self.broad.pairs(), self.broad.all_pairs());
        }
        Lap::Timed
    }

    /// Stage: what a wall-clock budget learns from the frame for the next ones (untimed: it
    /// reads no clock). The tail runs from where the narrow phase had to stop (or stopped) to
    /// the end of the measurement. A frame whose broad phase ran past that point starts its tail
    /// where the narrow phase started: counting the overrun as tail would move the next frame's
    /// narrow deadline earlier still, and a budget near the fixed work would lock into deeming
    /// every pair.
    fn learn(&mut self, frame: &Frame<'_>) -> Lap {
        if !frame.plan.is_wall() {
            return Lap::Skipped;
        }
        let (r, profile, t2) = (&frame.report, &frame.profile, frame.broad_end_ns);
        let narrow_end = match frame.narrow_budget {
            FrameBudget::Deadline(d) if r.budget_exhausted => d.max(t2),
            _ => t2 + profile.prioritise_ns + profile.narrow_ns,
        };
        self.policy.shedder.learn(
            frame.searched,
            frame.tail_end_ns.saturating_sub(narrow_end),
            frame.pairs,
        );
        if let Some((settled, ns)) = self.collider.foveal_pass() {
            self.policy
                .shedder
                .learn_foveal(r.foveal_pairs, r.foveal_stale == 0, settled, ns);
        }
        Lap::Skipped
    }

    /// The last frame's report with Δ and P summed over every deemed pair, computed off the
    /// clock. A wall-clock frame sums a sample where every pair would not fit its budget
    /// ([`FrameReport::metrics_stride`] > 1, with standard errors); a study that reports these
    /// figures needs them whole. The frame's timings, counts and audit are kept as they were
    /// (the audit is not run again).
    pub fn measure_exactly(&mut self) -> &FrameReport {
        if self.report.metrics_stride > 1 {
            self.on_pool(|sim| {
                let mut r = sim.report.clone();
                let input = frame_input(&sim.tree, &sim.world, &sim.broad, &sim.viewer);
                let every_pair = crate::metrics::Effort {
                    sample_limit: u32::MAX,
                    ..crate::metrics::Effort::default()
                };
                sim.collider
                    .measure_metrics(&input, r.fixation, every_pair, None, &mut r);
                sim.report = r;
            });
        }
        &self.report
    }

    /// The last frame as a viewer looking at `fixation` saw it, where the frame was scheduled
    /// for the fixation it was given: the report with Δ, P and the foveal counts summed over
    /// every pair for `fixation`, the regions a shedding broad phase left stale counted in its
    /// fovea, and, in audit mode or with `audit`, the audit run for it (a frame not in audit
    /// mode keeps the audit out of its own step, and so out of a timing of it). What the frame
    /// did (its pairs, timings, tests) is as it was. The control of what gaze buys: a frame
    /// scheduled for the screen centre, measured where the viewer looked. Computed off the
    /// clock; the next frame is unaffected. For the fixation the frame was given it is
    /// [`Self::measure_exactly`]'s report.
    pub fn measured_at(&mut self, fixation: Option<Fixation>, audit: bool) -> FrameReport {
        let fixation = fixation.filter(Fixation::is_usable);
        self.on_pool(|sim| {
            let mut r = sim.report.clone();
            r.fixation = fixation;
            let input = frame_input(&sim.tree, &sim.world, &sim.broad, &sim.viewer);
            let every_pair = crate::metrics::Effort {
                sample_limit: u32::MAX,
                ..crate::metrics::Effort::default()
            };
            sim.collider
                .measure_metrics(&input, fixation, every_pair, None, &mut r);
            if let Some(searched) = sim.last_searched {
                r.foveal_stale = fixation.map_or(0, |f| {
                    sim.policy
                        .shedder
                        .foveal_unsearched(searched, &sim.viewer, f) as u32
                });
            }
            if audit || r.audit.is_some() {
                let missed = match r.audit {
                    Some(a) => a.missed_pairs,
                    None if r.stale_regions > 0 => {
                        missed_pairs(sim.broad.pairs(), sim.broad.all_pairs())
                    }
                    None => 0,
                };
                sim.collider.audit_now(&input, fixation, &mut r);
                if let Some(a) = r.audit.as_mut() {
                    a.missed_pairs = missed;
                }
            }
            r
        })
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

/// The stages of a frame, in their order: the paper's main loop (section 2) with the metrics
/// (section 3) and the audit. [`Simulation::step`] runs them in this order and nowhere else.
const STAGES: [Stage; 8] = [
    Stage::Renumber,
    Stage::Integrate,
    Stage::BroadPhase,
    Stage::NarrowPhase,
    Stage::Respond,
    Stage::Measure,
    Stage::Audit,
    Stage::Learn,
];

/// A stage of a frame (see [`STAGES`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Stage {
    /// Renumber the bodies in the broad phase's spatial order, now and then.
    Renumber,
    /// Advance every body by one time step.
    Integrate,
    /// Find the candidate pairs (shed in perceptual order under a whole-frame budget).
    BroadPhase,
    /// Prioritise, and run the narrow phase under the budget (the collider's passes).
    NarrowPhase,
    /// Exchange velocities of the pairs on the collision list.
    Respond,
    /// Δ, P and the frame's counts.
    Measure,
    /// The exact answer for every deemed pair, in audit mode.
    Audit,
    /// What a wall-clock budget learns for the next frames.
    Learn,
}

/// Whether a stage did work to be timed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Lap {
    Timed,
    Skipped,
}

/// One frame in flight: what its stages read (the plan under the budget, the fixation, the
/// clock) and what they hand on (the report, the profile and what the budget learns from).
struct Frame<'c> {
    clock: &'c dyn Clock,
    plan: FramePlan,
    /// The fixation, if usable.
    fixation: Option<Fixation>,
    report: FrameReport,
    profile: PhaseProfile,
    /// The last clock reading: where the running stage started.
    last_ns: u64,
    /// Under a whole-frame budget whose broad phase has regions: its deadline and budget (ns).
    shedding: Option<(u64, u64)>,
    /// Regions the broad phase searched, of its order.
    searched: usize,
    /// Candidate pairs of the broad phase.
    pairs: usize,
    /// When the broad phase ended.
    broad_end_ns: u64,
    /// The narrow phase's budget (see [`FramePolicy::narrow_budget`]).
    narrow_budget: FrameBudget,
    /// The candidates that may be foveal (the pairs of the first regions searched), when shedding.
    foveal_prefix: Option<usize>,
    /// The pairs the metrics summed Δ and P over, and when that sum started.
    sample: (u32, Option<u64>),
    /// Where the measurement ended: the end of the tail a whole-frame budget learns.
    tail_end_ns: u64,
}

/// Run `f` (a frame, on a thread of its pool) while the pool's other threads stay awake for it.
///
/// A thread of the pool that finds no work sleeps after some tens of microseconds, and waking it
/// costs 20-40 us on this kind of machine: as long as some serial steps between a frame's parallel
/// phases last (at N = 10,000, the response before the metrics), so the phase after one ran its
/// first tens of microseconds on one thread. For the frame's length each other thread runs a job
/// that takes the frame's parts as soon as they are handed out (`rayon::yield_now`) and otherwise
/// yields its core (with more threads than cores, spinning would keep the frame's own thread off
/// one); the job ends with the frame. A spinner that the frame's own thread picks up (the others
/// too slow to take it) returns at once: it would wait for a frame it holds up.
fn keeping_the_pool_awake<R>(f: impl FnOnce() -> R) -> R {
    let home = rayon::current_thread_index();
    let others = rayon::current_num_threads().saturating_sub(1);
    let awake = AtomicBool::new(true);
    rayon::in_place_scope(|s| {
        for _ in 0..others {
            let awake = &awake;
            s.spawn(move |_| {
                if rayon::current_thread_index() == home {
                    return;
                }
                while awake.load(Ordering::Acquire) {
                    if rayon::yield_now() != Some(rayon::Yield::Executed) {
                        std::thread::yield_now();
                    }
                }
            });
        }
        // The spinners stop however the frame ends: the scope waits for them before it
        // propagates a panic, so a flag cleared only on return would hang the caller.
        let _stop = StopOnDrop(&awake);
        f()
    })
}

/// Clears its flag when dropped, on return or unwind alike.
struct StopOnDrop<'a>(&'a AtomicBool);

impl Drop for StopOnDrop<'_> {
    fn drop(&mut self) {
        self.0.store(false, Ordering::Release);
    }
}

/// The longest [`Simulation::warm_pool_until`] keeps the pool busy, whatever it is asked: 2 ms.
pub const MAX_POOL_WARM_NS: u64 = 2_000_000;

/// A collider's view of a frame, from the simulation's parts (so that the collider itself can be
/// borrowed mutably beside it).
fn frame_input<'a>(
    tree: &'a SphereTree,
    world: &'a World,
    broad: &'a BroadPhase,
    viewer: &'a Viewer,
) -> FrameInput<'a> {
    FrameInput {
        tree,
        world,
        candidates: broad.pairs(),
        columns: broad.columns(),
        viewer,
    }
}

/// Pairs of `all` (this frame's candidates, whatever was shed) missing from `searched`.
fn missed_pairs(searched: &[(u32, u32)], mut all: Vec<(u32, u32)>) -> u32 {
    let mut have = searched.to_vec();
    have.sort_unstable();
    all.sort_unstable();
    all.iter()
        .filter(|p| have.binary_search(p).is_err())
        .count() as u32
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::broad_phase::BroadPhaseKind;
    use crate::config::SceneConfig;
    use std::collections::BTreeSet;

    fn grid_scene(renumber_every: u32, threads: u32, budget: BudgetSpec) -> Simulation {
        Simulation::new(SimConfig {
            scene: SceneConfig::paper(3_000, 2),
            broad_phase: BroadPhaseKind::Grid,
            renumber_every,
            threads,
            budget,
            ..SimConfig::default()
        })
        .expect("valid")
    }

    /// A frame on the pool is handed back after its last clock reading; under a wall-clock
    /// budget that wait is learnt (here one tick of a clock that advances at every reading) and
    /// comes off the next frames' deadlines. One thread has no pool and nothing to learn.
    #[test]
    fn a_pooled_wall_clock_frame_learns_its_hand_back() {
        let clock = crate::budget::Ticking(std::sync::atomic::AtomicU64::new(0), 1_000);
        let run = |threads| {
            let mut sim = Simulation::new(SimConfig {
                scene: SceneConfig::paper(300, 1),
                budget: BudgetSpec::WallMs(2.0),
                threads,
                ..SimConfig::default()
            })
            .expect("valid");
            for _ in 0..5 {
                sim.step(Some(Fixation::at(0.5, 0.5)), &clock);
            }
            sim.policy.handback_ns()
        };
        assert_eq!(run(1), 0);
        let learnt = run(2);
        assert!((500..=1_000).contains(&learnt), "{learnt}");
    }

    fn colliding_by_id(sim: &Simulation) -> BTreeSet<(u32, u32)> {
        sim.exact_colliding_pairs()
            .into_iter()
            .map(|p| sim.id_pair(p))
            .collect()
    }

    /// The paper scene of `bodies` (seed 3), round-robin, under a wall-clock budget of
    /// `budget_ns`.
    fn round_robin_on_the_clock(bodies: u32, budget_ns: u64) -> Simulation {
        Simulation::new(SimConfig {
            scene: SceneConfig::paper(bodies, 3),
            scheduler: crate::config::SchedulerKind::RoundRobin,
            budget: BudgetSpec::WallMs(budget_ns as f64 * 1e-6),
            // These tests watch the ordered path cut at its deadline; on a clock that
            // advances only when read, the exact pass would fit every budget.
            exact_when_affordable: false,
            ..SimConfig::default()
        })
        .expect("valid")
    }

    /// A wall-clock budget at the paper's N (sweep and prune: nothing to shed but the narrow
    /// phase) covers the frame's tail too: after the first frames have learnt what deeming,
    /// response and metrics cost, the narrow phase stops early enough that the frame ends by its
    /// deadline. The clock advances at every reading, so the tail costs its readings.
    #[test]
    fn a_wall_clock_frame_at_the_papers_n_ends_by_its_deadline_tail_included() {
        let budget_ns = 200_000;
        let mut sim = round_robin_on_the_clock(500, budget_ns);
        assert!(sim.broad.regions().is_empty(), "sweep and prune at N = 500");
        let tick = 5_000;
        let clock = crate::budget::Ticking(std::sync::atomic::AtomicU64::new(0), tick);
        let fixation = Some(Fixation::at(0.5, 0.5));
        for frame in 0..8 {
            let start = clock.0.load(std::sync::atomic::Ordering::Relaxed);
            let r = sim.step(fixation, &clock);
            let spent = clock.0.load(std::sync::atomic::Ordering::Relaxed) - start;
            assert!(r.budget_exhausted && r.deemed > 0, "frame {frame}: not cut");
            assert!(!r.budget_spent_before_narrow);
            if frame >= 2 {
                // The readings that end the tail and the frame (the audit runs between them)
                // are not part of the learnt tail: on this clock, one tick each.
                assert!(
                    spent <= budget_ns + 2 * tick,
                    "frame {frame} took {spent} ns of a {budget_ns} ns budget"
                );
            }
        }
    }

    /// Frames that stall (here the clock jumps at a reading in the frame's last ticks, after its
    /// tail, as if the thread had not run for a while) end late; after two in the window the
    /// next frames aim earlier by about the lesser stall and end that much before their budget,
    /// and once the stalls have left the window the guard is back where it was. A lone stall
    /// moves nothing. (On this clock every frame ends a few readings after its aim, which is the
    /// guard it keeps without stalls.)
    #[test]
    fn late_frames_make_the_next_frames_aim_earlier_until_they_are_forgotten() {
        use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
        const TICK: u64 = 1_000;
        struct Stalling {
            now: AtomicU64,
            stall_from: AtomicU64,
            stall_ns: AtomicU64,
        }
        impl Clock for Stalling {
            fn now_ns(&self) -> u64 {
                let mut step = TICK;
                if self.now.load(Relaxed) >= self.stall_from.load(Relaxed) {
                    self.stall_from.store(u64::MAX, Relaxed);
                    step += self.stall_ns.load(Relaxed);
                }
                self.now.fetch_add(step, Relaxed) + step
            }
        }
        let budget_ns = 200_000;
        let mut sim = round_robin_on_the_clock(3_000, budget_ns);
        let clock = Stalling {
            now: AtomicU64::new(0),
            stall_from: AtomicU64::new(u64::MAX),
            stall_ns: AtomicU64::new(0),
        };
        let fixation = Some(Fixation::at(0.5, 0.5));
        let mut frame = |stall_ns: u64| {
            let start = clock.now.load(Relaxed);
            if stall_ns > 0 {
                // The frame aims to end `margin` before its budget.
                let margin = sim.policy.guard().margin_ns();
                clock
                    .stall_from
                    .store(start + budget_ns - margin - TICK, Relaxed);
                clock.stall_ns.store(stall_ns, Relaxed);
            }
            let r = sim.step(fixation, &clock);
            assert!(r.budget_exhausted, "a frame the budget cuts");
            let guard = r.guard_ns;
            let spent = clock.now.load(Relaxed) - start;
            clock.stall_from.store(u64::MAX, Relaxed);
            (guard, spent)
        };
        // Past the first frames' learning (and their lateness, forgotten with the window).
        for _ in 0..crate::budget::guard::GUARD_WINDOW + 10 {
            frame(0);
        }
        let (calm, spent) = frame(0);
        assert!(calm <= 3 * TICK, "{calm}");
        assert!(spent <= budget_ns + TICK, "{spent}");
        frame(300_000);
        // (Frames without stalls end a reading earlier or later from frame to frame.)
        assert!(frame(0).0 <= calm + TICK, "a lone stall");
        frame(10_000);
        let (guard, spent) = frame(0);
        // The second stall's lateness: what it added to the frame's usual lateness.
        assert!(
            (calm + 5_000..=calm + 12_000).contains(&guard),
            "guard {guard}, {calm} without stalls"
        );
        assert!(
            spent <= budget_ns - guard + calm + TICK,
            "{spent} with a guard of {guard}"
        );
        for _ in 0..crate::budget::guard::GUARD_WINDOW {
            frame(0);
        }
        assert!(frame(0).0 <= calm + TICK, "the stalls have left the window");
    }

    /// A wall-clock budget that integration and the broad phase spend whole is reported as such
    /// (the server warns about it): no sphere test, every pair deemed.
    #[test]
    fn a_budget_the_fixed_work_spends_is_reported() {
        let mut sim = Simulation::new(SimConfig {
            scene: SceneConfig::paper(500, 3),
            budget: BudgetSpec::WallMs(0.008),
            ..SimConfig::default()
        })
        .expect("valid");
        let clock = crate::budget::Ticking(std::sync::atomic::AtomicU64::new(0), 5_000);
        for _ in 0..3 {
            let r = sim.step(Some(Fixation::at(0.5, 0.5)), &clock);
            assert!(r.budget_spent_before_narrow);
            assert_eq!((r.sphere_tests, r.deemed), (0, r.candidate_pairs));
        }
    }

    /// A wall-clock frame that sums Δ and P over a sample says so, and [`Simulation::measure_exactly`]
    /// gives the sums over every deemed pair: the same as measuring the frame without a budget
    /// for the metrics, and within four standard errors of the sample's estimate.
    #[test]
    fn a_sampled_frame_is_measured_exactly_on_request() {
        let mut sim = Simulation::new(SimConfig {
            scene: SceneConfig::paper(500, 4),
            scheduler: crate::config::SchedulerKind::RoundRobin,
            budget: BudgetSpec::WallMs(0.02),
            ..SimConfig::default()
        })
        .expect("valid");
        let clock = crate::budget::Ticking(std::sync::atomic::AtomicU64::new(0), 500);
        let fixation = Some(Fixation::at(0.4, 0.6));
        let mut sampled = 0;
        for _ in 0..6 {
            let est = sim.step(fixation, &clock).clone();
            if est.metrics_stride <= 1 {
                continue;
            }
            sampled += 1;
            let mut want = est.clone();
            let input = frame_input(&sim.tree, &sim.world, &sim.broad, &sim.viewer);
            sim.collider.measure(&input, est.fixation, &mut want);
            let got = sim.measure_exactly().clone();
            assert_eq!(got.metrics_stride, 1);
            assert_eq!(got.geometric_inaccuracy_se, 0.0);
            assert_eq!(got.perceived_inaccuracy_se, Some(0.0));
            assert_eq!(got.geometric_inaccuracy, want.geometric_inaccuracy);
            assert_eq!(got.perceived_inaccuracy, want.perceived_inaccuracy);
            assert_eq!(
                (got.deemed, got.sphere_tests, got.profile),
                (est.deemed, est.sphere_tests, est.profile),
                "the frame itself is kept"
            );
            let (p, p_est) = (
                got.perceived_inaccuracy.expect("a fixation"),
                est.perceived_inaccuracy.expect("a fixation"),
            );
            let se = est.perceived_inaccuracy_se.expect("a fixation");
            assert!(
                se > 0.0 && (p - p_est).abs() <= 4.0 * se,
                "P {p} vs {p_est} ± {se}"
            );
            let (d, d_est) = (got.geometric_inaccuracy, est.geometric_inaccuracy);
            assert!(
                (d - d_est).abs() <= 4.0 * est.geometric_inaccuracy_se,
                "Δ {d} vs {d_est}"
            );
        }
        assert!(sampled >= 3, "only {sampled} frames sampled");
    }

    /// The last frame's candidate pairs whose centre lies within 5 degrees of a fixation at
    /// (`x`, `y`), and how many of them were deemed, pair by pair.
    fn foveal_by_brute_force(sim: &Simulation, x: f64, y: f64) -> (u32, u32) {
        use crate::metrics::Fovea;
        use crate::report::FOVEAL_DEG;
        let (world, viewer) = (sim.world(), sim.viewer());
        let fovea = Fovea::new(viewer, viewer.to_pixels(x, y), FOVEAL_DEG);
        let (mut foveal, mut deemed) = (0, 0);
        for p in sim.pairs() {
            let c = (world.position[p.a as usize] + world.position[p.b as usize]) * 0.5;
            if fovea.contains_point(c) {
                foveal += 1;
                deemed += u32::from(p.status == crate::narrow_phase::PairStatus::Deemed);
            }
        }
        (foveal, deemed)
    }

    /// A frame measured where the viewer looked ([`Simulation::measured_at`]): for the fixation
    /// it was scheduled for, the exact measurement with its own stale count; for another, the
    /// foveal counts of that fovea (brute force), the audit's verdicts unchanged and its P
    /// measured there, and the stale regions counted in that fovea.
    #[test]
    fn a_frame_measured_elsewhere_counts_that_fovea() {
        use crate::budget::Ticking;
        let mut sim = Simulation::new(SimConfig {
            scene: SceneConfig::paper(20_000, 5),
            scheduler: crate::config::SchedulerKind::Priced,
            budget: BudgetSpec::WallMs(0.4),
            audit: true,
            ..SimConfig::default()
        })
        .expect("valid");
        let clock = Ticking(std::sync::atomic::AtomicU64::new(0), 500);
        let (steer, look) = (Fixation::at(0.5, 0.5), Fixation::at(0.15, 0.7));
        let (mut stale_here, mut stale_there) = (0, 0);
        for _ in 0..4 {
            sim.step(Some(steer), &clock);
            let exact = sim.measure_exactly().clone();
            let own = sim.measured_at(Some(steer), false);
            let key = |r: &FrameReport| {
                (
                    r.foveal_pairs,
                    r.foveal_deemed,
                    r.foveal_stale,
                    r.geometric_inaccuracy,
                    r.perceived_inaccuracy,
                )
            };
            assert_eq!(key(&own), key(&exact));
            assert_eq!(own.audit, exact.audit);
            let there = sim.measured_at(Some(look), false);
            let brute = foveal_by_brute_force(&sim, look.x, look.y);
            assert_eq!((there.foveal_pairs, there.foveal_deemed), brute);
            let verdicts = |r: &FrameReport| r.audit.map(|a| (a.false_positives, a.true_positives));
            assert_eq!(verdicts(&there), verdicts(&exact));
            assert_eq!(there.fixation, Some(look));
            assert_ne!(there.perceived_inaccuracy, exact.perceived_inaccuracy);
            stale_here += own.foveal_stale;
            stale_there += there.foveal_stale;
        }
        // Scheduled for the centre, its own fovea is searched first and the viewer's is not.
        assert!(
            stale_here == 0 && stale_there > 0,
            "{stale_here} {stale_there}"
        );
        // Unknown gaze: nothing is foveal.
        let none = sim.measured_at(None, false);
        assert_eq!(
            (
                none.foveal_pairs,
                none.foveal_stale,
                none.perceived_inaccuracy
            ),
            (0, 0, None)
        );
    }

    /// Under a whole-frame budget the report's foveal counts are those of the pairs themselves,
    /// whether the foveal pass settled every foveal pair and the metrics took its count, or the
    /// budget cut the pass short and the metrics tested the pairs again.
    #[test]
    fn the_foveal_counts_are_exact_whoever_counts_them() {
        use crate::budget::Ticking;
        let (mut known, mut tested) = (0, 0);
        for (budget_ns, fx) in [
            (30_000_000u64, 0.5),
            (30_000_000, 0.2),
            (400_000, 0.5),
            (900_000, 0.3),
            (150_000, 0.5),
        ] {
            let mut sim = Simulation::new(SimConfig {
                scene: SceneConfig::paper(20_000, 5),
                scheduler: crate::config::SchedulerKind::Priced,
                budget: BudgetSpec::WallMs(budget_ns as f64 * 1e-6),
                ..SimConfig::default()
            })
            .expect("valid");
            let clock = Ticking(std::sync::atomic::AtomicU64::new(0), 500);
            let fixation = Some(Fixation::at(fx, 0.5));
            for _ in 0..6 {
                let r = sim.step(fixation, &clock).clone();
                if r.foveal_stale > 0 {
                    continue;
                }
                let (foveal, deemed) = foveal_by_brute_force(&sim, fx, 0.5);
                assert_eq!((r.foveal_pairs, r.foveal_deemed), (foveal, deemed));
                assert!(foveal > 0);
                match sim.collider.foveal_known() {
                    Some(k) => {
                        assert_eq!(k, foveal);
                        known += 1;
                    }
                    None => tested += 1,
                }
            }
        }
        assert!(
            known > 0 && tested > 0,
            "{known} counted by the pass, {tested} by the metrics"
        );
    }

    /// An exact frame's counts, summed by its narrow phase block by block, are those of a
    /// separate pass over every pair (statuses, levels, colliding and foveal pairs): with and
    /// without a fixation, on one thread and two, with the bodies' filter (many pairs) and the
    /// pair's own (a sparse scene, fewer pairs than a quarter of the bodies).
    #[test]
    fn an_exact_frame_counts_as_it_resolves_what_a_pass_over_every_pair_counts() {
        use crate::metrics::{Fovea, measure};
        use crate::report::FOVEAL_DEG;
        let dense = SceneConfig::paper(12_000, 3);
        let sparse = SceneConfig {
            density: dense.density / 30.0,
            ..SceneConfig::paper(6_000, 4)
        };
        for (scene, filtered_by_pair) in [(dense, false), (sparse, true)] {
            for threads in [1, 2] {
                let mut sim = Simulation::new(SimConfig {
                    scene: scene.clone(),
                    budget: BudgetSpec::Exact,
                    threads,
                    ..SimConfig::default()
                })
                .expect("valid");
                for fixation in [Some((0.5, 0.5)), None, Some((0.15, 0.8))] {
                    let r = sim
                        .step(fixation.map(|(x, y)| Fixation::at(x, y)), &FrozenClock)
                        .clone();
                    let (world, viewer) = (sim.world(), sim.viewer());
                    let pairs = sim.pairs().len();
                    assert_eq!(
                        !crate::metrics::uses_near_bodies(pairs, world.len()),
                        filtered_by_pair,
                        "{pairs} pairs of {} bodies",
                        world.len()
                    );
                    let fovea = fixation
                        .map(|(x, y)| Fovea::new(viewer, viewer.to_pixels(x, y), FOVEAL_DEG));
                    let m = measure(
                        sim.collider.narrow(),
                        sim.tree(),
                        world,
                        None,
                        fovea.as_ref(),
                        1,
                    );
                    let brute = fovea.map_or(0, |f| {
                        sim.pairs()
                            .iter()
                            .filter(|p| {
                                let (a, b) = (p.a as usize, p.b as usize);
                                f.contains_point((world.position[a] + world.position[b]) * 0.5)
                            })
                            .count() as u32
                    });
                    assert_eq!(
                        (r.real_collisions, r.resolved_per_level, r.foveal_pairs),
                        (m.real, m.per_level, brute),
                        "threads {threads}, fixation {fixation:?}"
                    );
                    assert_eq!(m.foveal, brute);
                    assert_eq!(r.foveal_deemed, 0);
                    assert!(r.real_collisions > 0);
                    assert_eq!(fixation.is_some(), brute > 0, "{fixation:?}");
                }
            }
        }
    }

    /// Renumbering moves bodies, not answers: the renumbered scene is the same scene body for
    /// body (by id) and finds the same colliding pairs by id (not at the same cost: a pair whose
    /// bodies swap order descends the other tree first).
    #[test]
    fn renumbering_moves_bodies_not_answers() {
        let mut moved = grid_scene(2, 1, BudgetSpec::Exact);
        let mut still = grid_scene(0, 1, BudgetSpec::Exact);
        let ids = moved.body_ids().to_vec();
        assert!(ids.iter().enumerate().any(|(s, &id)| s as u32 != id));
        let mut seen = vec![false; ids.len()];
        for (slot, &id) in ids.iter().enumerate() {
            assert!(!seen[id as usize]);
            seen[id as usize] = true;
            assert_eq!(moved.body_slots()[id as usize], slot as u32);
            let (a, b) = (moved.world(), still.world());
            let (s, i) = (slot, id as usize);
            assert_eq!(
                (a.position[s], a.velocity[s], a.orientation[s], a.spin[s]),
                (b.position[i], b.velocity[i], b.orientation[i], b.spin[i])
            );
        }
        assert_eq!(still.body_ids(), still.body_slots());
        // The first frame sees identical bodies: the same collisions.
        moved.step(None, &FrozenClock);
        still.step(None, &FrozenClock);
        assert_eq!(colliding_by_id(&moved), colliding_by_id(&still));
        // Later frames renumber again (every second frame); the lists stay consistent with the
        // bodies they name.
        for _ in 0..5 {
            moved.step(None, &FrozenClock);
            let w = moved.world();
            let listed: BTreeSet<(u32, u32)> = moved.candidate_pairs().iter().copied().collect();
            let brute: BTreeSet<(u32, u32)> =
                crate::broad_phase::brute_force_pairs(&w.position, moved.tree().root_radius())
                    .into_iter()
                    .collect();
            assert_eq!(listed, brute);
            let resolved: BTreeSet<(u32, u32)> = moved
                .pairs()
                .iter()
                .filter(|p| p.status.is_collision())
                .map(|p| (p.a, p.b))
                .collect();
            assert_eq!(
                resolved,
                moved.exact_colliding_pairs().into_iter().collect()
            );
        }
        assert!(
            moved.body_ids() != ids.as_slice(),
            "renumbered as bodies moved"
        );
    }

    /// With renumbering, frame reports and bodies are still bit-identical on 1 and 2 threads.
    #[test]
    fn renumbering_is_deterministic_across_threads() {
        let budget = BudgetSpec::SphereTests(20_000);
        let (mut one, mut two) = (grid_scene(3, 1, budget), grid_scene(3, 2, budget));
        for _ in 0..8 {
            let (a, b) = (
                one.step(None, &FrozenClock).clone(),
                two.step(None, &FrozenClock).clone(),
            );
            assert_eq!(a, b);
        }
        assert_eq!(one.body_ids(), two.body_ids());
        assert_eq!(one.world().position, two.world().position);
        assert_eq!(one.world().velocity, two.world().velocity);
    }

    /// Frames short enough that the pool's other threads often do not take their spinners before
    /// the frame ends (the frame's own thread then runs them, and they return at once), with more
    /// threads than this machine may have cores: every frame completes, and the bodies move
    /// exactly as on one thread.
    #[test]
    fn short_exact_frames_on_a_wide_pool_finish_and_match_one_thread() {
        let run = |threads: u32| {
            let mut cfg = SimConfig::default();
            cfg.scene.bodies = 300;
            cfg.budget = BudgetSpec::Exact;
            cfg.threads = threads;
            let mut sim = Simulation::new(cfg).expect("valid");
            let reports: Vec<_> = (0..40)
                .map(|_| sim.step(None, &FrozenClock).clone())
                .collect();
            (reports, sim.world().position.clone())
        };
        assert_eq!(run(4), run(1));
    }

    /// A frame that panics on a pool whose other threads are kept awake for it hands the panic
    /// to the caller: the threads stop spinning however the frame ends (before, they spun for
    /// ever and the caller hung, so a server could not report its frame loop's panic).
    #[test]
    fn a_frame_that_panics_on_a_kept_awake_pool_returns_the_panic() {
        /// Reads normally, then panics from its `.1`th reading on.
        struct FailingClock(std::sync::atomic::AtomicU64, u64);
        impl Clock for FailingClock {
            fn now_ns(&self) -> u64 {
                let read = self.0.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                assert!(read < self.1, "the clock failed at read {read}");
                read
            }
        }
        let (tx, rx) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            let mut cfg = SimConfig::default();
            cfg.scene.bodies = 300;
            cfg.budget = BudgetSpec::Exact;
            cfg.threads = 2;
            let mut sim = Simulation::new(cfg).expect("valid");
            // The frame's first read is before the hand-over to the pool; the second inside it.
            let clock = FailingClock(std::sync::atomic::AtomicU64::new(0), 1);
            let out = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                sim.step(None, &clock);
            }));
            let _ = tx.send(out.is_err());
        });
        let panicked = rx
            .recv_timeout(std::time::Duration::from_secs(60))
            .expect("the frame neither returned nor panicked within 60 s: the pool hung");
        assert!(panicked, "the failing clock did not fail the frame");
    }

    /// Warming the pool spins every thread of it until the clock reaches the time asked, and no
    /// further than the cap, even on a clock that does not advance; one thread has no pool and
    /// returns without reading the clock.
    #[test]
    fn warming_the_pool_spins_until_the_time_asked_and_no_longer_than_the_cap() {
        let run = |threads: u32, until: u64| {
            let mut cfg = SimConfig::default();
            cfg.scene.bodies = 50;
            cfg.threads = threads;
            let sim = Simulation::new(cfg).expect("valid");
            let clock = crate::budget::Ticking(std::sync::atomic::AtomicU64::new(0), 1_000);
            sim.warm_pool_until(&clock, until);
            clock.0.load(std::sync::atomic::Ordering::Relaxed)
        };
        assert_eq!(run(1, 500_000), 0, "one thread read the clock");
        let reached = run(2, 500_000);
        assert!(reached >= 500_000, "stopped at {reached} ns");
        // Each thread stops at its first reading at or past the time (a tick of 1 us each).
        assert!(reached < 500_000 + 4 * 1_000, "went on to {reached} ns");
        // A clock that does not advance still lets it return.
        let mut cfg = SimConfig::default();
        cfg.scene.bodies = 50;
        cfg.threads = 2;
        Simulation::new(cfg)
            .expect("valid")
            .warm_pool_until(&FrozenClock, u64::MAX);
        let capped = run(2, u64::MAX);
        assert!(
            (MAX_POOL_WARM_NS..MAX_POOL_WARM_NS + 4 * 1_000).contains(&capped),
            "capped at {capped} ns"
        );
    }
}
