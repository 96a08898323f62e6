//! The collision-handling part of a frame on poses handed in: prioritisation, the budgeted narrow
//! phase, interruption, metrics (section 3) and the audit.
//!
//! [`crate::Simulation`] runs it inside its closed loop, after integration and the broad phase.
//! The open-loop protocol (DESIGN.md) runs it on frames someone else produced: one exact run gives
//! the poses and candidate pairs, and every scheduler and budget is evaluated on exactly those, so
//! a comparison of schedulers is not confounded by the different physics each would cause. A
//! collider keeps only what a scheduler legitimately carries between frames (the narrow phase's
//! witnesses and its buffers).

use crate::budget::gate::RINGS_SHARE;
use crate::budget::{Clock, CostGate, ExactGate, FrameBudget, Meter};
use crate::config::{SimConfig, Truth};
use crate::fixation::{Fixation, FrameView};
use crate::metrics::{self, Fovea};
use crate::narrow_phase::{NarrowPhase, PairState, PairStatus, separation, shape_separation};
use crate::perception::Viewer;
use crate::report::{AuditReport, DeemedTruth, FOVEAL_DEG, FrameReport, PassCost, PhaseProfile};
use crate::schedule::calibration::Calibration;
use crate::schedule::{self, Passes, Priorities, Prioritiser, Scheduler, Work};
use crate::sphere_tree::SphereTree;
use crate::validate::ConfigError;
use crate::world::World;

/// One frame's poses and candidates, as the collider sees them.
#[derive(Debug, Clone, Copy)]
pub struct FrameInput<'a> {
    /// The shared sphere tree.
    pub tree: &'a SphereTree,
    /// Body state (positions and bases of this frame).
    pub world: &'a World,
    /// Candidate pairs of the broad phase.
    pub candidates: &'a [(u32, u32)],
    /// Where each broad-phase column's candidates lie (sweep and prune), for the gaze rings of
    /// frames that shed their ordering; None where the broad phase has no columns.
    pub columns: Option<&'a crate::broad_phase::Columns>,
    /// Camera and display.
    pub viewer: &'a Viewer,
}

/// One frame's narrow phase as [`Collider::collide_frame`] is asked to run it.
#[derive(Clone, Copy)]
pub struct NarrowFrame<'c> {
    /// Where the viewer looks, if known and usable.
    pub fixation: Option<Fixation>,
    /// The narrow phase's budget.
    pub budget: FrameBudget,
    /// Times the passes and enforces a wall-clock budget.
    pub clock: &'c dyn Clock,
    /// A whole-frame budget's frame (see [`crate::budget::shedding`]) whose first this many
    /// candidates are the pairs of the regions that may hold foveal pairs: the pairs among them
    /// whose centre is within [`FOVEAL_DEG`] of the fixation (widened by its uncertainty) are
    /// resolved to completion first, and round-robin then spends what is left on the rest. At
    /// that scale the region order is the gaze ordering, and it costs one fovea test per pair of
    /// those regions instead of a prioritisation of every pair.
    pub foveal_prefix: Option<usize>,
}

impl std::fmt::Debug for NarrowFrame<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("NarrowFrame")
            .field("fixation", &self.fixation)
            .field("budget", &self.budget)
            .field("foveal_prefix", &self.foveal_prefix)
            .finish_non_exhaustive()
    }
}

/// A budgeted frame's passes in flight: what they share.
struct Run<'c> {
    clock: &'c dyn Clock,
    budget: FrameBudget,
    meter: Meter<'c>,
    /// When the frame's meter started.
    t_meter: u64,
    /// Candidate pairs.
    n: usize,
    /// The fixation in pixels, and its uncertainty (degrees; 0 without one).
    fixation_px: Option<[f64; 2]>,
    uncertainty_deg: f64,
    /// Time the sphere-test passes before the ordering took (ns): narrow-phase time.
    pass_ns: u64,
}

/// Whether this frame asked for the gaze rings' fovea pass, and whether it placed them.
#[derive(Debug, Clone, Copy, Default)]
struct RingsState {
    asked: bool,
    placed: bool,
}

/// Prioritisation, scheduling, interruption, metrics and audit for one configuration.
#[derive(Debug)]
pub struct Collider {
    config: SimConfig,
    scheduler: Box<dyn Scheduler>,
    /// What the scheduler asks of a frame beyond its own run.
    passes: Passes,
    prioritiser: Prioritiser,
    calibration: Calibration,
    narrow: NarrowPhase,
    priorities: Priorities,
    audit_stack: Vec<(f32, u16, u16, u8, u8)>,
    /// The last audit's answer for each deemed pair, in pair order (empty when the last frame
    /// was not audited).
    deemed_truth: Vec<DeemedTruth>,
    /// Gaze-blind round-robin, for frames whose wall-clock budget cannot pay for the ordering.
    fallback: Box<dyn Scheduler>,
    /// The cheap gaze order of those frames, where the broad phase has columns.
    rings: crate::schedule::rings::Rings,
    /// What placing the rings costs (ns), learnt from the shed frames that placed them.
    rings_cost: CostGate,
    /// What prioritising and ordering cost (ns per candidate pair), learnt from the wall-clock
    /// frames that ordered.
    ordering_cost: CostGate,
    /// Whether a wall-clock frame can afford the exact pass outright.
    exact_gate: ExactGate,
    /// The last foveal pass: pairs it settled and the time it took (ns).
    foveal_pass: Option<(u32, u64)>,
    /// The last frame's foveal pairs, when its foveal pass selected exactly the pairs the
    /// metrics count as foveal and settled every one (see [`Self::foveal_known`]).
    foveal_known: Option<u32>,
    /// The narrow phase's selection marks are this frame's foveal pass's test of the metrics'
    /// fovea (see [`Self::foveal_marked`]).
    foveal_marked: bool,
    /// An exact frame's counts, summed by its narrow phase as it resolved the pairs, with the
    /// fixation (in pixels) whose fovea they counted: the metrics use them instead of counting
    /// every pair again (see [`Self::exact_pass`]).
    counted: Option<(Option<[f64; 2]>, metrics::Counts)>,
}

/// The narrow phase's passes as they ran, timed by the clock reads they made: the first pass's
/// first reading (where the reset ended), the last pass's last one (where the ordering starts),
/// and the sphere tests counted when the last pass ended.
#[derive(Debug, Default)]
struct PassClock {
    first_start: Option<u64>,
    last_end: Option<u64>,
    tests: u64,
}

impl PassClock {
    /// A pass that ran from `times.0` to `times.1` (None: it did not run) with `tests_now`
    /// sphere tests counted at its end, into `slot`.
    fn record(&mut self, slot: &mut PassCost, times: Option<(u64, u64)>, tests_now: u64) {
        if let Some((start, end)) = times {
            self.first_start.get_or_insert(start);
            *slot = pass_cost((start, self.tests), (end, tests_now));
            self.last_end = Some(end);
        }
        self.tests = tests_now;
    }
}

/// The cost of a pass that started at `start` (clock, sphere tests) and ended at `end`.
fn pass_cost(start: (u64, u64), end: (u64, u64)) -> PassCost {
    PassCost {
        ns: end.0.saturating_sub(start.0),
        tests: end.1.saturating_sub(start.1),
    }
}

/// Settle every root-separated pair of the frame in one pass, as far as `meter` allows (see
/// `NarrowPhase::settle_separate_roots`).
fn settle_roots(narrow: &mut NarrowPhase, input: &FrameInput<'_>, meter: &mut Meter<'_>) {
    narrow.settle_separate_roots(input.tree, input.world, &mut |tests| {
        !meter.exhausted(tests)
    });
}

impl Collider {
    /// A collider for `config` (its scheduler, models, threshold and audit switch; the budget is
    /// handed to each call) over `tree` and `viewer`.
    pub fn new(
        config: &SimConfig,
        tree: &SphereTree,
        viewer: &Viewer,
    ) -> Result<Self, ConfigError> {
        config.validate()?;
        Self::with_scheduler(
            config,
            tree,
            viewer,
            schedule::for_kind(config.scheduler, config.priced),
        )
    }

    /// A collider for `config` that runs `scheduler` instead of the one `config` names (the
    /// scheduler's own declaration, [`Scheduler::passes`], says what the frame does for it).
    pub(crate) fn with_scheduler(
        config: &SimConfig,
        tree: &SphereTree,
        viewer: &Viewer,
        scheduler: Box<dyn Scheduler>,
    ) -> Result<Self, ConfigError> {
        config.validate()?;
        let r = tree.root_radius();
        let passes = scheduler.passes();
        Ok(Self {
            scheduler,
            passes,
            prioritiser: Prioritiser::new(
                viewer,
                &config.schedule_model,
                config.eccentricity_threshold_deg,
                r,
                passes.needs,
            ),
            calibration: if passes.calibrated {
                Calibration::for_tree(tree, &config.scene)?
            } else {
                Calibration::uninformed(tree.depth() as u8)
            },
            narrow: NarrowPhase::default(),
            priorities: Priorities::default(),
            audit_stack: Vec::new(),
            deemed_truth: Vec::new(),
            fallback: schedule::fallback(),
            rings: Default::default(),
            rings_cost: CostGate::default(),
            ordering_cost: CostGate::default(),
            exact_gate: ExactGate::default(),
            foveal_pass: None,
            foveal_known: None,
            foveal_marked: false,
            counted: None,
            config: config.clone(),
        })
    }

    /// Whether a frame under `budget` settles the fovea first over every candidate (see
    /// [`SimConfig::fovea_first`]): wall-clock budgets of a scheduler that asks for it
    /// ([`Passes::fovea_first`]) and orders by gaze.
    fn fovea_first(&self, budget: FrameBudget) -> bool {
        self.config.fovea_first
            && matches!(budget, FrameBudget::Deadline(_) | FrameBudget::Wall(_))
            && self.passes.fovea_first
            && self.passes.gaze
    }

    /// Pair states of the last frame.
    pub fn pairs(&self) -> &[PairState] {
        &self.narrow.pairs
    }

    /// The pairs on this frame's collision list (real and deemed), in pair order. After an exact
    /// frame the narrow phase has listed them; otherwise every pair's status is read.
    pub fn collisions(&self) -> impl Iterator<Item = (u32, u32)> + '_ {
        self.collisions_settled().map(|(a, b, _)| (a, b))
    }

    /// [`Self::collisions`], each pair with whether it is a real collision (settled colliding)
    /// rather than deemed at interruption: the shape truth's response needs a contact for the
    /// real ones.
    pub fn collisions_settled(&self) -> impl Iterator<Item = (u32, u32, bool)> + '_ {
        let pairs = &self.narrow.pairs;
        let listed = self.narrow.colliding();
        let scanned = listed.is_none().then(|| {
            pairs
                .iter()
                .filter(|p| p.status.is_collision())
                .map(|p| (p.a, p.b, p.status == PairStatus::Colliding))
        });
        let listed = listed.map(|l| {
            l.map(|i| {
                let p = &pairs[i];
                (p.a, p.b, p.status == PairStatus::Colliding)
            })
        });
        listed
            .into_iter()
            .flatten()
            .chain(scanned.into_iter().flatten())
    }

    /// What prioritisation computed for the last frame's pairs.
    pub fn priorities(&self) -> &Priorities {
        &self.priorities
    }

    /// The last foveal pass of [`Self::collide_frame`]: the pairs it settled and its time
    /// (ns).
    pub fn foveal_pass(&self) -> Option<(u32, u64)> {
        self.foveal_pass
    }

    /// The foveal pairs of the last frame, known without testing them again: its foveal pass
    /// tested every pair that may be foveal with the metrics' own fovea (the fixation had no
    /// uncertainty to widen it) and settled every pair it selected, so the frame has exactly that
    /// many foveal pairs and none of them is deemed. None when the pass did not run, was cut
    /// short by the budget, or used a wider fovea.
    pub fn foveal_known(&self) -> Option<u32> {
        self.foveal_known
    }

    /// Whether this frame's foveal pass, cut or not, tested exactly the metrics' fovea (its
    /// radius not widened by the fixation's uncertainty), so that the narrow phase's selection
    /// marks say which pairs of the prefix it found inside it.
    pub fn foveal_marked(&self) -> bool {
        self.foveal_marked
    }

    /// Renumber the bodies in what is kept between frames (old id `i` becomes `new_of_old[i]`):
    /// the narrow phase's witnesses are renumbered, what the scheduler remembers is dropped.
    pub fn renumber(&mut self, new_of_old: &[u32]) {
        self.narrow.renumber(new_of_old);
        self.scheduler.forget();
    }

    /// The narrow phase (pair states and test count) of the last frame.
    pub fn narrow(&self) -> &NarrowPhase {
        &self.narrow
    }

    /// Read this collider's buffers back into cache, as they would be in a server running it
    /// frame after frame (see [`crate::warm`]; for the open-loop protocol). The pair states go
    /// last: every frame ends working on them, so in a server they are the most recently used.
    /// Warmed first, at N = 10,000 they were evicted by the priced scheduler's own buffers
    /// (more than the cache holds together), and the priced collider's frames that shed their
    /// ordering did 0.74-0.84x the sphere tests of the round-robin collider in the same time.
    pub fn warm(&self) {
        self.priorities.warm();
        self.scheduler.warm();
        self.fallback.warm();
        self.rings.warm();
        crate::warm::lines(self.calibration.bins());
        self.narrow.warm();
    }

    /// Prioritise and run the narrow phase on `input` under `budget`, deem what is left open, and
    /// remember this frame's witnesses: the open-loop entry ([`Self::collide_frame`] with no
    /// foveal prefix). Fills the counts of `r` and the prioritise and narrow timings of
    /// `profile`.
    pub fn collide(
        &mut self,
        input: &FrameInput<'_>,
        fixation: Option<Fixation>,
        budget: FrameBudget,
        clock: &dyn Clock,
        r: &mut FrameReport,
        profile: &mut PhaseProfile,
    ) {
        let frame = NarrowFrame {
            fixation,
            budget,
            clock,
            foveal_prefix: None,
        };
        self.collide_frame(input, &frame, r, profile);
    }

    /// One frame's narrow phase: the passes its scheduler declares ([`Scheduler::passes`]), in
    /// their order, under the frame's budget. The meter runs from the call: the caller decides
    /// whether earlier phases of the frame spend the same budget.
    ///
    /// 1. An exact frame resolves every pair and nothing else (`exact_pass`).
    /// 2. The fovea pass (`fovea_pass`): with a foveal prefix (a whole-frame budget's
    ///    regions, see [`crate::budget::shedding`]), or over every candidate with
    ///    [`SimConfig::fovea_first`]. With regions, round-robin then spends the rest: at that
    ///    scale the region order is the gaze ordering.
    /// 3. The root pass, in a wall-clock frame of a scheduler whose order takes those tests first
    ///    ([`Passes::roots_first`]).
    /// 4. The fovea through the gaze rings ([`Passes::rings_fovea`]), if the frame can pay for
    ///    placing them.
    /// 5. The ordered run (prioritise, then the scheduler) if the frame can pay for the ordering;
    ///    otherwise the fallback: the root pass, the rings or round-robin (`shed_run`).
    pub fn collide_frame(
        &mut self,
        input: &FrameInput<'_>,
        frame: &NarrowFrame<'_>,
        r: &mut FrameReport,
        profile: &mut PhaseProfile,
    ) {
        let (fixation, budget, clock) = (frame.fixation, frame.budget, frame.clock);
        let t0 = clock.now_ns();
        self.foveal_pass = None;
        self.foveal_known = None;
        self.foveal_marked = false;
        self.counted = None;
        if budget == FrameBudget::Unlimited {
            self.exact_pass(input, frame, r, profile, t0, None);
            // (Its time from the profile: no clock read of its own.)
            r.passes.rest = PassCost {
                ns: profile.narrow_ns,
                tests: r.sphere_tests,
            };
            return;
        }
        // A wall-clock frame whose budget is expected to cover the exact pass takes it: no
        // order beats it. Cut short (the expectation was wrong), it is learnt from at the
        // rate it went.
        // The meter the gate asks is the one the pass then runs under (made only when asked:
        // a wall-clock meter reads the clock).
        let n = input.candidates.len();
        let mut asked = None;
        if self.config.exact_when_affordable
            && self
                .exact_gate
                .admits(n, || asked.insert(Meter::new(budget, clock)).wall_left_ns())
            && let Some(mut meter) = asked
        {
            let all = self.exact_pass(input, frame, r, profile, t0, Some(&mut meter));
            let spent = clock.now_ns().saturating_sub(t0);
            r.passes.rest = PassCost {
                ns: spent,
                tests: r.sphere_tests,
            };
            let reached = if all { n } else { n - r.deemed as usize };
            self.exact_gate.learn(spent, reached.max(1));
            r.exact_fit = all;
            return;
        }
        self.narrow.reset(input.candidates);
        self.narrow.make_room_for_frames();
        let fixation_px = fixation.map(|f| {
            let f = f.clamped();
            input.viewer.to_pixels(f.x, f.y)
        });
        let meter = Meter::new(budget, clock);
        // A wall-clock meter starts after the reset, which every scheduler pays: the ordering's
        // cost is measured from its start (a frame deadline set before the reset counts it).
        let t_meter = meter.started_ns().unwrap_or(t0);
        let mut run = Run {
            clock,
            budget,
            meter,
            t_meter,
            n: self.narrow.pairs.len(),
            fixation_px,
            uncertainty_deg: fixation.map_or(0.0, |f| f.clamped().uncertainty_deg),
            pass_ns: 0,
        };
        // The passes are timed by the clock reads they make anyway (a clock read is not free,
        // and a wall-clock budget pays for it): each returns its first and last reading. The
        // reset runs to the first pass (or the ordering), the ordering from the last pass.
        let mut timed = PassClock::default();
        let passes = self.passes;
        // With `fovea_first`, frames without regions settle the fovea first too, over every
        // candidate (see `SimConfig::fovea_first`); then the ordering below spends the rest.
        let whole_fovea = frame.foveal_prefix.is_none() && self.fovea_first(budget);
        if let (Some(prefix), Some(px)) = (
            frame.foveal_prefix.or(whole_fovea.then_some(run.n)),
            fixation_px,
        ) {
            let times = self.fovea_pass(input, &mut run, prefix, px, whole_fovea);
            timed.record(&mut r.passes.fovea, Some(times), self.narrow.tests);
            // At large N round-robin spends the rest (the regions are the gaze order; its first
            // round tests every pair's roots, the cheapest error removed, and settled more pairs a
            // millisecond than whole pairs in region order at 100,000 bodies: 0.68x the exact
            // pass's against 0.50x, docs/BENCHMARKS.md); over every candidate, the ordering
            // below spends it.
            if !whole_fovea {
                self.priorities.clear();
                let work = Work::blind(
                    input.tree,
                    input.world,
                    &self.priorities,
                    &self.calibration,
                    self.config.threads as usize,
                );
                self.fallback.run(&mut self.narrow, &work, &mut run.meter);
                let tests = self.narrow.tests;
                self.scheduler.forget();
                let deemed = self.narrow.close_frame(input.world.len());
                let end = clock.now_ns();
                let from = timed.last_end.unwrap_or(t_meter);
                r.passes.reset = pass_cost((t0, 0), (timed.first_start.unwrap_or(from), 0));
                timed.record(&mut r.passes.rest, Some((from, end)), tests);
                profile.prioritise_ns = 0;
                profile.narrow_ns = end - t0;
                self.report_counts(&run, deemed, r);
                return;
            }
        }
        let roots_first = run.meter.counts_time() && passes.roots_first;
        if roots_first {
            let times = self.root_pass(input, &mut run);
            timed.record(&mut r.passes.roots, Some(times), self.narrow.tests);
        }
        // The gaze rings (see `schedule::rings`), for schedulers that use gaze (not the priced
        // scheduler's gaze-blind ablation), where the broad phase has columns to find the pairs
        // by and the frame's time can pay for placing them (learnt like the ordering's cost,
        // see `CostGate`).
        let rings_at = match (input.columns, fixation_px) {
            (Some(c), Some(px)) if passes.gaze && run.meter.counts_time() && c.covers(run.n) => {
                Some((c, px))
            }
            _ => None,
        };
        // `fovea_first` has settled the fovea already.
        let mut rings = RingsState::default();
        if let Some((columns, px)) =
            rings_at.filter(|_| roots_first && !whole_fovea && passes.rings_fovea)
        {
            rings.asked = true;
            let times = self.rings_fovea_pass(input, &mut run, columns, px, &mut rings, r);
            timed.record(&mut r.passes.fovea, times, self.narrow.tests);
        }
        // Under a wall-clock budget too small to pay for ordering the pairs, ordering them would
        // leave less time for the tests than it is worth: shed it, run round-robin, and say so.
        // The cost is learnt from frames that ordered (see `CostGate`).
        let affordable = self
            .ordering_cost
            .admits(run.n as f64, passes.ordering_share, &run.meter);
        let prioritised = affordable && passes.prioritises(fixation_px.is_some());
        r.ordering_shed = !affordable;
        if prioritised {
            self.prioritiser.prioritise(
                &self.narrow.pairs,
                input.world,
                input.viewer,
                fixation_px.map(|px| (px, run.uncertainty_deg)),
                &mut self.priorities,
                &mut run.meter,
            );
        } else {
            self.priorities.clear();
        }
        let t1 = clock.now_ns();
        let reset_end = timed.first_start.unwrap_or(t1);
        r.passes.reset = pass_cost((t0, 0), (reset_end, 0));
        r.passes.ordering = pass_cost((timed.last_end.unwrap_or(reset_end), 0), (t1, 0));
        let rest_from = (t1, self.narrow.tests);
        if affordable {
            self.ordered_run(input, &mut run, prioritised, t1);
        } else {
            self.shed_run(input, &mut run, roots_first, rings_at, rings, r);
        }
        let tests = self.narrow.tests;
        let deemed = self.narrow.close_frame(input.world.len());
        let t2 = clock.now_ns();
        r.passes.rest = pass_cost(rest_from, (t2, tests));
        // Every pair settled inside the budget: the exact pass would have fitted (it costs
        // less than this frame's order and descents did).
        if deemed == 0 && run.meter.counts_time() && !run.meter.was_exhausted() {
            self.exact_gate.learn(t2.saturating_sub(t0), n);
        }
        // The passes are sphere tests: narrow-phase time.
        profile.prioritise_ns = (t1 - t0).saturating_sub(run.pass_ns);
        profile.narrow_ns = t2 - t1 + run.pass_ns.min(t1 - t0);
        self.report_counts(&run, deemed, r);
    }

    /// The counts of a budgeted frame's narrow phase, into `r`.
    fn report_counts(&self, run: &Run<'_>, deemed: u32, r: &mut FrameReport) {
        r.candidate_pairs = self.narrow.pairs.len() as u32;
        r.deemed = deemed;
        r.sphere_tests = self.narrow.tests;
        r.budget_exhausted = run.meter.was_exhausted();
    }

    /// Pass: settle the first `prefix` candidates whose centre is within [`FOVEAL_DEG`] of the
    /// fixation at `px` (widened by its uncertainty), each to completion, nearest first, as far
    /// as the meter allows. Over every candidate (`whole_fovea`) a pair is tested only if its
    /// first body is near enough to the fovea for the pair's centre to be in it.
    fn fovea_pass(
        &mut self,
        input: &FrameInput<'_>,
        run: &mut Run<'_>,
        prefix: usize,
        px: [f64; 2],
        whole_fovea: bool,
    ) -> (u64, u64) {
        let radius = FOVEAL_DEG + run.uncertainty_deg;
        let fovea = Fovea::new(input.viewer, px, radius.min(89.0));
        let pos = &input.world.position;
        let pass_start = run.clock.now_ns();
        // One pass over the bodies, as the metrics' count does: the exact test is a projection.
        let near = whole_fovea.then(|| {
            let reach = metrics::centre_reach(input.tree);
            metrics::near_bodies(&fovea, pos, reach, self.config.threads as usize)
        });
        // A foveal pair is settled whole, so it is resolved in one go (the same tests as
        // stepping it level by level, without storing and reloading its list at every
        // level), on every thread. The meter is read between pairs, so the pass overshoots
        // its deadline by a few pairs' descents at most (microseconds).
        let select = |p: &PairState| {
            near.as_ref().is_none_or(|near| near[p.a as usize])
                && fovea.contains_point((pos[p.a as usize] + pos[p.b as usize]) * 0.5)
        };
        let mut cut = false;
        let meter = &mut run.meter;
        let settled = self.narrow.resolve_selected(
            input.tree,
            input.world,
            prefix.min(run.n),
            self.config.threads as usize,
            &select,
            &mut |tests| {
                let go = !meter.exhausted(tests);
                cut |= !go;
                go
            },
        );
        let end = run.clock.now_ns();
        run.pass_ns = end.saturating_sub(pass_start);
        self.foveal_pass = Some((settled, run.pass_ns));
        // Not cut: every selected pair was settled. The metrics count the pairs of the same
        // prefix within FOVEAL_DEG of the same point, the same test when the radius is not
        // widened by uncertainty.
        self.foveal_known = (!cut && radius == FOVEAL_DEG).then_some(settled);
        self.foveal_marked = radius == FOVEAL_DEG;
        (pass_start, end)
    }

    /// Pass: settle every root-separated pair of the frame in one go, as far as the meter
    /// allows (see `NarrowPhase::settle_separate_roots`).
    fn root_pass(&mut self, input: &FrameInput<'_>, run: &mut Run<'_>) -> (u64, u64) {
        let roots_start = run.clock.now_ns();
        settle_roots(&mut self.narrow, input, &mut run.meter);
        let end = run.clock.now_ns();
        run.pass_ns += end.saturating_sub(roots_start);
        (roots_start, end)
    }

    /// Pass: the pairs within the fovea, whole and nearest the fixation first, where the gaze
    /// rings find them, if the frame can pay for placing the rings.
    fn rings_fovea_pass(
        &mut self,
        input: &FrameInput<'_>,
        run: &mut Run<'_>,
        columns: &crate::broad_phase::Columns,
        px: [f64; 2],
        rings: &mut RingsState,
        r: &mut FrameReport,
    ) -> Option<(u64, u64)> {
        if !self.rings_cost.admits(1.0, RINGS_SHARE, &run.meter) {
            return None;
        }
        let fovea_start = run.clock.now_ns();
        let work = Work::blind(
            input.tree,
            input.world,
            &self.priorities,
            &self.calibration,
            self.config.threads as usize,
        );
        rings.placed = self
            .rings
            .fovea(
                &mut self.narrow,
                &work,
                columns,
                input.viewer,
                px,
                run.uncertainty_deg,
                &mut run.meter,
            )
            .is_some();
        if rings.placed {
            self.rings_cost.learn(self.rings.setup_ns() as f64);
        }
        r.gaze_rings = rings.placed;
        let end = run.clock.now_ns();
        run.pass_ns += end.saturating_sub(fovea_start);
        Some((fovea_start, end))
    }

    /// Run: the scheduler in its own order (prioritised when it asked, with the frame's view),
    /// and learn what the ordering cost. A prioritisation the deadline cut short is priced per
    /// pair it reached.
    fn ordered_run(
        &mut self,
        input: &FrameInput<'_>,
        run: &mut Run<'_>,
        prioritised: bool,
        t1: u64,
    ) {
        let view = run.fixation_px.map(|px| FrameView {
            viewer: input.viewer,
            fixation_px: px,
            model: self.config.schedule_model,
            uncertainty_deg: run.uncertainty_deg,
        });
        let work = Work {
            tree: input.tree,
            world: input.world,
            view: view.as_ref().filter(|_| prioritised),
            priorities: &self.priorities,
            calibration: &self.calibration,
            threads: self.config.threads as usize,
        };
        self.scheduler.run(&mut self.narrow, &work, &mut run.meter);
        let n = run.n;
        let reached = if !prioritised
            || (self.priorities.bodies_done
                && (self.priorities.reached == n || self.passes.needs.bodies_only))
        {
            n
        } else {
            self.priorities.reached.max(1)
        };
        if matches!(run.budget, FrameBudget::Deadline(_) | FrameBudget::Wall(_)) && n > 0 {
            let spent = t1 - run.t_meter;
            let cost = (spent - run.pass_ns.min(spent) + self.scheduler.ordering_ns()) as f64
                / reached as f64;
            self.ordering_cost.learn(cost);
        }
    }

    /// Run, when the frame cannot pay for its ordering: the root-separated pairs settled in one
    /// pass (before, or here for the schedulers whose order it would have changed), then the
    /// gaze rings where the broad phase has columns to find the pairs by and the scheduler is one
    /// that uses gaze (see `schedule::rings`): the pairs within the fovea resolved whole,
    /// nearest the fixation first, then round-robin, the outer ring first; round-robin in
    /// candidate order otherwise. The placing costs a few dozen flops per column and a pass over
    /// the x of the bodies of the columns near the fixation; a frame too short to pay for it
    /// (learnt like the ordering's cost, see `CostGate`) runs plain round-robin.
    fn shed_run(
        &mut self,
        input: &FrameInput<'_>,
        run: &mut Run<'_>,
        roots_first: bool,
        rings_at: Option<(&crate::broad_phase::Columns, [f64; 2])>,
        rings: RingsState,
        r: &mut FrameReport,
    ) {
        self.scheduler.forget();
        if !roots_first && run.meter.counts_time() {
            settle_roots(&mut self.narrow, input, &mut run.meter);
        }
        let work = Work::blind(
            input.tree,
            input.world,
            &self.priorities,
            &self.calibration,
            self.config.threads as usize,
        );
        if rings.placed {
            // The rings are placed and the fovea done (settled, or the budget spent on it):
            // round-robin over the rest.
            self.rings.rest(&mut self.narrow, &work, &mut run.meter);
            return;
        }
        match rings_at {
            // Asked once a frame: the gate counts the frames that could not pay.
            Some((columns, px))
                if !rings.asked && self.rings_cost.admits(1.0, RINGS_SHARE, &run.meter) =>
            {
                r.gaze_rings = self.rings.run(
                    &mut self.narrow,
                    &work,
                    columns,
                    input.viewer,
                    px,
                    run.uncertainty_deg,
                    &mut run.meter,
                );
                if r.gaze_rings {
                    self.rings_cost.learn(self.rings.setup_ns() as f64);
                } else {
                    self.fallback.run(&mut self.narrow, &work, &mut run.meter);
                }
            }
            _ => self.fallback.run(&mut self.narrow, &work, &mut run.meter),
        }
    }

    /// An exact frame: every order gives the same answer, so skip the ordering and resolve every
    /// pair, on several threads when the frame is large; the reset is done in the runs.
    ///
    /// The metrics' counts (each status and level, and the pairs within [`FOVEAL_DEG`] of the
    /// fixation) are summed block by block as the pairs are resolved, while each block is in
    /// cache ([`NarrowPhase::resolve_frame_tallied`]): at a million bodies a separate pass read
    /// 75 MB of pair states again, 13 ms of a 370 ms frame on one core, and 27 ms with its
    /// fovea test. That work is the metrics': the blocks' tally is timed and counted in
    /// [`PhaseProfile::measure_ns`], not in the narrow phase (on several threads, as its time on
    /// all of them over the threads).
    ///
    /// With a `meter` (a wall-clock frame expected to afford the pass, see [`ExactGate`]), the
    /// meter is asked between blocks of pairs; if it says stop, the pairs not reached are
    /// deemed and the frame closes as a budgeted one. Returns whether every pair was resolved.
    fn exact_pass(
        &mut self,
        input: &FrameInput<'_>,
        frame: &NarrowFrame<'_>,
        r: &mut FrameReport,
        profile: &mut PhaseProfile,
        t0: u64,
        meter: Option<&mut Meter<'_>>,
    ) -> bool {
        let clock = frame.clock;
        self.priorities.clear();
        let threads = self.config.threads as usize;
        // The metrics' fovea: about the fixation itself.
        let fixation_px = self
            .measure_view(input, frame.fixation)
            .map(|v| v.fixation_px);
        let fovea = fixation_px.map(|px| Fovea::new(input.viewer, px, FOVEAL_DEG));
        let count = metrics::FrameCount::new(
            fovea,
            input.candidates.len(),
            input.tree,
            input.world,
            threads,
        );
        let t_near = clock.now_ns();
        let tally = |pairs: &[PairState], acc: &mut (metrics::Counts, u64)| {
            let t = clock.now_ns();
            count.count(pairs, &mut acc.0);
            acc.1 += clock.now_ns().saturating_sub(t);
        };
        let mut go_on = meter.map(|m| move || !m.exhausted_now(0));
        let runs = self.narrow.resolve_frame_until(
            input.candidates,
            input.tree,
            input.world,
            threads,
            Some(&tally),
            go_on.as_mut().map(|f| f as &mut dyn FnMut() -> bool),
        );
        let t_end = clock.now_ns();
        self.scheduler.forget();
        profile.prioritise_ns = 0;
        r.candidate_pairs = self.narrow.pairs.len() as u32;
        let Some(runs) = runs else {
            // Cut: a budgeted frame's end, its metrics counted from the states.
            self.counted = None;
            r.deemed = self.narrow.close_frame(input.world.len());
            r.budget_exhausted = true;
            r.sphere_tests = self.narrow.tests;
            profile.narrow_ns = clock.now_ns().saturating_sub(t0);
            return false;
        };
        let mut counts = metrics::Counts::default();
        let mut tally_ns = 0;
        for (c, ns) in &runs {
            counts.add(c);
            tally_ns += ns;
        }
        self.counted = Some((fixation_px, counts));
        let workers = crate::narrow_phase::threads_for(input.candidates.len(), threads) as u64;
        let tally_wall = (tally_ns / workers).min(t_end.saturating_sub(t_near));
        profile.narrow_ns = t_end.saturating_sub(t_near) - tally_wall;
        profile.measure_ns += t_near.saturating_sub(t0) + tally_wall;
        r.sphere_tests = self.narrow.tests;
        true
    }

    /// Counts per level, Δ and P (section 3) from the pair states; the foveal counts; and, in audit
    /// mode, the exact answer for every deemed pair.
    pub fn measure(
        &mut self,
        input: &FrameInput<'_>,
        fixation: Option<Fixation>,
        r: &mut FrameReport,
    ) {
        self.measure_within(input, fixation, metrics::Effort::default(), r);
    }

    /// [`Self::measure`] within an [`metrics::Effort`] (a whole-frame budget's metrics), and the
    /// audit when it is on.
    pub fn measure_within(
        &mut self,
        input: &FrameInput<'_>,
        fixation: Option<Fixation>,
        effort: metrics::Effort,
        r: &mut FrameReport,
    ) {
        self.measure_metrics(input, fixation, effort, None, r);
        self.audit_frame(input, fixation, r);
    }

    /// How P is measured this frame: about the fixation itself, however uncertain it was.
    fn measure_view<'a>(
        &self,
        input: &FrameInput<'a>,
        fixation: Option<Fixation>,
    ) -> Option<FrameView<'a>> {
        fixation.map(|f| {
            let f = f.clamped();
            FrameView {
                viewer: input.viewer,
                fixation_px: input.viewer.to_pixels(f.x, f.y),
                model: self.config.measure_model,
                uncertainty_deg: 0.0,
            }
        })
    }

    /// The audit (the exact answer for every deemed pair), when the config asks for it: a
    /// diagnostic whose cost grows with the deemed pairs, so a whole-frame budget does not learn
    /// it as part of the frame's tail (see `Simulation::step`).
    pub fn audit_frame(
        &mut self,
        input: &FrameInput<'_>,
        fixation: Option<Fixation>,
        r: &mut FrameReport,
    ) {
        if self.config.audit {
            self.audit_now(input, fixation, r);
        } else {
            self.deemed_truth.clear();
        }
    }

    /// The audit of [`Self::audit_frame`], whether or not the config asks for it: for a frame
    /// measured again off the clock (`Simulation::measured_at`).
    pub(crate) fn audit_now(
        &mut self,
        input: &FrameInput<'_>,
        fixation: Option<Fixation>,
        r: &mut FrameReport,
    ) {
        self.deemed_truth.clear();
        let view = self.measure_view(input, fixation);
        r.audit = Some(audit(
            &self.narrow,
            input,
            view.as_ref(),
            &mut self.audit_stack,
            &mut self.deemed_truth,
        ));
    }

    /// The last audit's answer for each deemed pair of [`Self::pairs`], in pair order: what the
    /// viewer colours a wrong guess by. Empty when the last frame was not audited.
    pub fn deemed_truth(&self) -> &[DeemedTruth] {
        &self.deemed_truth
    }

    /// The metrics of [`Self::measure_within`] without the audit. With a `clock`, returns the
    /// pairs whose Δ and P were summed and the clock's reading when that sum started (the
    /// metrics' last work: the caller's next reading ends it).
    pub fn measure_metrics(
        &mut self,
        input: &FrameInput<'_>,
        fixation: Option<Fixation>,
        effort: metrics::Effort,
        clock: Option<&dyn Clock>,
        r: &mut FrameReport,
    ) -> (u32, Option<u64>) {
        let view = self.measure_view(input, fixation);
        let fixation_px = view.as_ref().map(|v| v.fixation_px);
        let (tree, world) = (input.tree, input.world);
        let fovea = fixation_px.map(|px| Fovea::new(input.viewer, px, FOVEAL_DEG));
        // The exact frame's narrow phase counted this fovea's pairs already.
        let effort = metrics::Effort {
            counted: effort.counted.or(self
                .counted
                .filter(|(px, _)| *px == fixation_px)
                .map(|(_, c)| c)),
            ..effort
        };
        let m = metrics::measure_within(
            &self.narrow,
            tree,
            world,
            view.as_ref(),
            fovea.as_ref(),
            self.config.threads as usize,
            effort,
            clock,
        );
        r.real_collisions = m.real;
        r.resolved_per_level = m.per_level;
        r.geometric_inaccuracy = m.delta;
        r.perceived_inaccuracy = view.map(|_| m.p);
        r.metrics_stride = m.stride;
        r.geometric_inaccuracy_se = m.delta_se;
        r.perceived_inaccuracy_se = view.map(|_| m.p_se);
        r.foveal_pairs = m.foveal;
        r.foveal_deemed = m.foveal_deemed;
        (m.sampled, m.sample_started_ns)
    }

    /// One open-loop frame: collide and measure `input` under `budget`, as a report (integration,
    /// broad phase and response are not this collider's: their timings stay 0).
    pub fn evaluate(
        &mut self,
        input: &FrameInput<'_>,
        fixation: Option<Fixation>,
        budget: FrameBudget,
        clock: &dyn Clock,
    ) -> FrameReport {
        let fixation_rejected = fixation.is_some_and(|f| !f.is_usable());
        let fixation = fixation.filter(Fixation::is_usable);
        let mut r = FrameReport {
            fixation,
            fixation_rejected,
            ..FrameReport::default()
        };
        let mut profile = PhaseProfile::default();
        self.collide(input, fixation, budget, clock, &mut r, &mut profile);
        let t = clock.now_ns();
        self.measure(input, fixation, &mut r);
        profile.measure_ns += clock.now_ns() - t;
        r.profile = profile;
        r
    }
}

/// The exact answer for every deemed pair: whether it collides, and for those that do not, the
/// true gap (separation of the leaf-sphere sets) and its perceived weight at the closest points.
/// Each pair's answer goes to `truths`, in pair order.
fn audit(
    np: &NarrowPhase,
    input: &FrameInput<'_>,
    view: Option<&FrameView<'_>>,
    stack: &mut Vec<(f32, u16, u16, u8, u8)>,
    truths: &mut Vec<DeemedTruth>,
) -> AuditReport {
    let (tree, world) = (input.tree, input.world);
    let fovea = view.map(|v| Fovea::new(input.viewer, v.fixation_px, FOVEAL_DEG));
    let mut a = AuditReport::default();
    let mut p_sum = 0.0;
    for p in np.pairs.iter().filter(|p| p.status == PairStatus::Deemed) {
        let (i, j) = (p.a as usize, p.b as usize);
        match true_weight(tree, world, i, j, view, stack) {
            None => {
                a.true_positives += 1;
                truths.push(DeemedTruth::Touching);
            }
            Some((sep, w)) => {
                a.false_positives += 1;
                a.geometric_inaccuracy += sep;
                p_sum += w;
                let mid = (world.position[i] + world.position[j]) * 0.5;
                a.foveal_false_positives +=
                    u32::from(fovea.as_ref().is_some_and(|f| f.contains_point(mid)));
                truths.push(DeemedTruth::Apart);
            }
        }
    }
    a.perceived_inaccuracy = view.map(|_| p_sum);
    a
}

/// The truth of a pair: None if it collides, else its separation and the perceived error of that
/// true gap (0 without a view). Under the leaf truth the gap runs between the two closest leaf
/// spheres' facing points; under the shape truth between the two stars' closest points.
pub fn true_weight(
    tree: &SphereTree,
    world: &World,
    a: usize,
    b: usize,
    view: Option<&FrameView<'_>>,
    stack: &mut Vec<(f32, u16, u16, u8, u8)>,
) -> Option<(f64, f64)> {
    if tree.truth() == Truth::Shape {
        // On the shape the gap's two ends are the stars' closest points.
        let (sep, gap_a, gap_b) = shape_separation(tree, world, a, b);
        if sep <= 0.0 {
            return None;
        }
        let w = view.map_or(0.0, |v| {
            v.weight_points(gap_a, gap_b, (gap_a + gap_b) * 0.5)
        });
        return Some((sep, w));
    }
    let (sep, ca, cb) = separation(tree, world, a, b, stack);
    if sep <= 0.0 {
        return None;
    }
    let w = view.map_or(0.0, |v| {
        // Closest points of the two leaf spheres lie on their centre line; all leaves share one
        // radius, (d - sep) / 2.
        let u = (cb - ca).normalize_or_zero();
        let d = (cb - ca).length();
        let gap_a = ca + u * (0.5 * (d - sep));
        let gap_b = gap_a + u * sep;
        v.weight_points(gap_a, gap_b, (gap_a + gap_b) * 0.5)
    });
    Some((sep, w))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::budget::Ticking;
    use crate::budget::gate::{LEARN_FRAMES, PROBE_EVERY};
    use crate::{BudgetSpec, FrozenClock, SchedulerKind, Simulation};

    /// The default config at `bodies` bodies, exact, and its scene after `frames` exact frames
    /// (so that the pairs have witnesses and the bodies have moved).
    fn stepped_scene(bodies: u32, frames: usize) -> (SimConfig, Simulation) {
        let mut cfg = SimConfig::default();
        cfg.scene.bodies = bodies;
        cfg.budget = BudgetSpec::Exact;
        let mut sim = Simulation::new(cfg.clone()).expect("valid");
        for _ in 0..frames {
            sim.step(None, &FrozenClock);
        }
        (cfg, sim)
    }

    /// A wall-clock budget that covers the exact pass takes it once a frame has shown it fits
    /// (an ordered frame that settled every pair): the same answers as an exact frame, nothing
    /// deemed. An estimate that proves wrong is cut at the deadline, whole pairs settled and the
    /// rest deemed, and the next frame orders again.
    #[test]
    fn a_budget_that_covers_the_exact_pass_takes_it_and_a_wrong_estimate_is_cut() {
        let (cfg, sim) = stepped_scene(2_000, 10);
        let input = sim.frame_input();
        let fixation = Some(Fixation::at(0.5, 0.5));
        let mut exact = Collider::new(&cfg, sim.tree(), sim.viewer()).expect("valid");
        let mut col = Collider::new(&cfg, sim.tree(), sim.viewer()).expect("valid");
        // On a clock that stands still, every budget is generous.
        let wall = FrameBudget::Wall(1_000_000);
        let first = col.evaluate(&input, fixation, wall, &FrozenClock);
        assert!(!first.exact_fit && first.deemed == 0, "{first:?}");
        exact.evaluate(&input, fixation, FrameBudget::Unlimited, &FrozenClock);
        for _ in 0..3 {
            // Both remember the same witnesses from the frame before.
            let want = exact.evaluate(&input, fixation, FrameBudget::Unlimited, &FrozenClock);
            let r = col.evaluate(&input, fixation, wall, &FrozenClock);
            assert!(r.exact_fit && r.deemed == 0 && !r.budget_exhausted);
            assert_eq!(r.sphere_tests, want.sphere_tests);
            assert_eq!(r.real_collisions, want.real_collisions);
            assert!(col.foveal_pass().is_none());
            for (p, q) in col.pairs().iter().zip(exact.pairs()) {
                assert_eq!((p.a, p.b, p.status), (q.a, q.b, q.status));
            }
        }
        // The estimate (nothing, on that clock) is wrong on a clock that advances: the pass is
        // cut, settled pairs exact and the rest deemed.
        let clock = Ticking(std::sync::atomic::AtomicU64::new(0), 1_000);
        let r = col.evaluate(&input, fixation, FrameBudget::Wall(20_000), &clock);
        assert!(!r.exact_fit && r.budget_exhausted && r.deemed > 0, "{r:?}");
        let mut settled = 0;
        for (p, q) in col.pairs().iter().zip(exact.pairs()) {
            assert!(!p.status.is_open());
            if p.status != PairStatus::Deemed {
                assert_eq!(p.status, q.status);
                settled += 1;
            }
        }
        assert!(settled > 0 && r.deemed as usize + settled == col.pairs().len());
        let next = col.evaluate(&input, fixation, FrameBudget::Wall(20_000), &clock);
        assert!(!next.exact_fit && col.pairs().iter().all(|p| !p.status.is_open()));
    }

    /// Every pass's tests sum to the frame's, whatever the budget: a wall-clock frame's root
    /// pass, fovea and rest, an exact frame's one pass, a sphere-test frame's run; the fixed
    /// passes (reset, ordering) test nothing and, on a clock that ticks at every read, take time.
    #[test]
    fn the_passes_account_for_every_sphere_test() {
        let (cfg, sim) = stepped_scene(2_000, 5);
        let clock = Ticking(std::sync::atomic::AtomicU64::new(0), 50);
        let fixation = Some(Fixation::at(0.5, 0.5));
        let mut col = Collider::new(&cfg, sim.tree(), sim.viewer()).expect("valid");
        let mut roots_seen = false;
        for budget in [
            FrameBudget::Wall(400_000),
            FrameBudget::Wall(40_000),
            FrameBudget::Tests(2_000),
            FrameBudget::Unlimited,
        ] {
            for _ in 0..LEARN_FRAMES + 2 {
                let r = col.evaluate(&sim.frame_input(), fixation, budget, &clock);
                let p = r.passes;
                let sum =
                    p.reset.tests + p.roots.tests + p.fovea.tests + p.ordering.tests + p.rest.tests;
                assert_eq!(sum, r.sphere_tests, "{budget:?}: {p:?}");
                assert_eq!((p.reset.tests, p.ordering.tests), (0, 0));
                match budget {
                    FrameBudget::Wall(_) if !r.exact_fit => {
                        assert!(p.reset.ns > 0);
                        roots_seen |= p.roots.tests > 0;
                    }
                    FrameBudget::Tests(_) => {
                        assert_eq!(p.rest.tests, r.sphere_tests);
                        assert_eq!(
                            (p.roots, p.fovea),
                            (PassCost::default(), PassCost::default())
                        );
                    }
                    _ => assert_eq!(p.rest.tests, r.sphere_tests),
                }
            }
        }
        assert!(roots_seen, "no wall-clock frame counted a root pass");
    }

    /// On a clock that advances 1 µs at every read the ordering, a handful of reads, costs far
    /// more than a 2 µs frame can pay.
    #[test]
    fn shed_frames_take_the_gaze_rings_and_sphere_test_budgets_never_do() {
        let (mut cfg, sim) = stepped_scene(200, 5);
        let clock = Ticking(std::sync::atomic::AtomicU64::new(0), 1_000);
        let fixation = Some(Fixation::at(0.5, 0.5));
        for (kind, gaze) in [
            (SchedulerKind::Priced, true),
            (SchedulerKind::Priced, false),
            (SchedulerKind::RoundRobin, true),
        ] {
            cfg.scheduler = kind;
            cfg.priced.gaze = gaze;
            let mut col = Collider::new(&cfg, sim.tree(), sim.viewer()).expect("valid");
            let mut rings = 0;
            for _ in 0..LEARN_FRAMES + 5 {
                let r = col.evaluate(
                    &sim.frame_input(),
                    fixation,
                    FrameBudget::Wall(2_000),
                    &clock,
                );
                // Only the priced scheduler takes the rings' fovea in a frame it orders.
                assert!(r.ordering_shed || !r.gaze_rings || kind == SchedulerKind::Priced);
                rings += usize::from(r.gaze_rings);
            }
            // The priced collider places the rings here (the first frames whatever their cost,
            // to learn it); gaze-blind round-robin and the priced scheduler's gaze-blind
            // ablation never do.
            if kind == SchedulerKind::Priced && gaze {
                assert!(rings >= LEARN_FRAMES as usize, "{rings}");
            } else {
                assert_eq!(rings, 0);
            }
            // Sphere-test budgets never shed, so they never take the rings: they stay
            // deterministic whatever the wall-clock frames before them learnt.
            for tests in [0, 100, 1_000] {
                let r = col.evaluate(
                    &sim.frame_input(),
                    fixation,
                    FrameBudget::Tests(tests),
                    &FrozenClock,
                );
                assert!(!r.ordering_shed && !r.gaze_rings);
            }
        }
    }

    /// A wall-clock frame of round-robin or the priced scheduler too short to step every root
    /// one by one still settles every root-separated pair (in one pass, before its ordering);
    /// the paper's priority schedulers, which rank those first tests, do not take the pass, and
    /// under a sphere-test budget nobody does. On a clock that advances 1 µs a read, 40 µs.
    #[test]
    fn wall_clock_frames_settle_every_separate_root_first() {
        let (mut cfg, sim) = stepped_scene(500, 5);
        let input = sim.frame_input();
        let root = sim.tree().root_radius();
        let separate: Vec<bool> = input
            .candidates
            .iter()
            .map(|&(a, b)| {
                let d =
                    (input.world.position[b as usize] - input.world.position[a as usize]).as_vec3();
                f64::from(d.length()) > 2.0 * root * (1.0 + 1e-6)
            })
            .collect();
        let far = separate.iter().filter(|&&s| s).count();
        assert!(far > input.candidates.len() / 3, "{far}");
        // Of those, the pairs a collider's last frame settled separate.
        let settled = |col: &Collider| {
            col.pairs()
                .iter()
                .zip(&separate)
                .filter(|(p, s)| **s && p.status == crate::narrow_phase::PairStatus::Separate)
                .count()
        };
        let clock = Ticking(std::sync::atomic::AtomicU64::new(0), 1_000);
        let fixation = Some(Fixation::at(0.5, 0.5));
        for kind in [
            SchedulerKind::Priced,
            SchedulerKind::RoundRobin,
            SchedulerKind::PriorityOnly,
        ] {
            cfg.scheduler = kind;
            let mut col = Collider::new(&cfg, sim.tree(), sim.viewer()).expect("valid");
            for budget in [FrameBudget::Wall(25_000), FrameBudget::Tests(50)] {
                let r = col.evaluate(&input, fixation, budget, &clock);
                assert!(r.budget_exhausted, "{kind:?} {budget:?}");
                let settled = settled(&col);
                let takes_pass =
                    kind != SchedulerKind::PriorityOnly && matches!(budget, FrameBudget::Wall(_));
                if takes_pass {
                    assert_eq!(settled, far, "{kind:?}");
                    assert!(r.sphere_tests >= far as u64);
                } else {
                    assert!(settled < far / 2, "{kind:?} {budget:?}: {settled} of {far}");
                }
            }
        }
        // A frame of the paper's scheduler that sheds its ordering runs round-robin: it takes
        // the pass too. 8 µs: the ordering (learnt on the first frames) does not fit, the pass
        // does.
        cfg.scheduler = SchedulerKind::PriorityOnly;
        let mut col = Collider::new(&cfg, sim.tree(), sim.viewer()).expect("valid");
        let clock = Ticking(std::sync::atomic::AtomicU64::new(0), 1_000);
        let mut shed = 0;
        for _ in 0..LEARN_FRAMES + 8 {
            let r = col.evaluate(&input, fixation, FrameBudget::Wall(8_000), &clock);
            if r.ordering_shed {
                shed += 1;
                assert_eq!(settled(&col), far);
            }
        }
        assert!(shed > 0);
    }

    /// `fovea_first`: under a wall-clock budget, where the broad phase has no columns for the
    /// gaze rings, the priced order alone leaves some pairs within FOVEAL_DEG of the fixation
    /// deemed (those likely to collide are worth little per test); with the option, a budget
    /// that pays for the foveal pass settles every one of them, and the pass's count is the
    /// metrics' own. Where the rings can find the fovea's pairs, the priced scheduler settles
    /// them first without the option. Sphere-test budgets are unchanged by the option.
    #[test]
    fn fovea_first_settles_every_foveal_pair_of_a_wall_clock_frame() {
        let (mut cfg, sim) = stepped_scene(2_000, 10);
        // The passes of an ordered frame, which a budget that covers the exact pass skips.
        cfg.exact_when_affordable = false;
        let with_columns = sim.frame_input();
        let input = FrameInput {
            columns: None,
            ..with_columns
        };
        let fixation = Some(Fixation::at(0.45, 0.55));
        let fovea = Fovea::new(input.viewer, input.viewer.to_pixels(0.45, 0.55), FOVEAL_DEG);
        let pos = &input.world.position;
        let foveal = input
            .candidates
            .iter()
            .filter(|&&(a, b)| fovea.contains_point((pos[a as usize] + pos[b as usize]) * 0.5))
            .count() as u32;
        assert!(foveal > 10, "{foveal}");
        let mut plain = Collider::new(&cfg, sim.tree(), sim.viewer()).expect("valid");
        let mut rings = Collider::new(&cfg, sim.tree(), sim.viewer()).expect("valid");
        cfg.fovea_first = true;
        let mut first = Collider::new(&cfg, sim.tree(), sim.viewer()).expect("valid");
        let clock = Ticking(std::sync::atomic::AtomicU64::new(0), 1_000);
        let (mut shown, mut by_rings) = (0, 0);
        for budget_us in [5, 10, 20, 30, 40, 50, 65, 80, 100, 150, 200, 400, 800] {
            let budget = FrameBudget::Wall(budget_us * 1_000);
            let (a, b) = (
                plain.evaluate(&input, fixation, budget, &clock),
                first.evaluate(&input, fixation, budget, &clock),
            );
            let c = rings.evaluate(&with_columns, fixation, budget, &clock);
            assert!(!a.gaze_rings && !b.gaze_rings);
            if c.gaze_rings && !c.ordering_shed && c.foveal_deemed == 0 {
                by_rings += usize::from(a.foveal_deemed > 0);
            }
            assert_eq!((a.foveal_pairs, b.foveal_pairs), (foveal, foveal));
            assert!(plain.foveal_pass().is_none() && first.foveal_pass().is_some());
            if let Some(known) = first.foveal_known() {
                // The pass was not cut: it settled every foveal pair, and counted them.
                assert_eq!((known, b.foveal_deemed), (foveal, 0), "{budget_us} us");
                shown += usize::from(a.foveal_deemed > 0);
            }
        }
        assert!(
            shown > 0,
            "no budget both pays for the pass and deems a foveal pair without it"
        );
        assert!(
            by_rings > 0,
            "no ordered frame settled through the rings a fovea the order alone left deemed"
        );
        for tests in [0, 500, 5_000] {
            let budget = FrameBudget::Tests(tests);
            let (a, b) = (
                plain.evaluate(&input, fixation, budget, &FrozenClock),
                first.evaluate(&input, fixation, budget, &FrozenClock),
            );
            assert_eq!(a, b);
            assert!(first.foveal_pass().is_none());
        }
    }

    #[test]
    fn an_unaffordable_ordering_is_shed_and_measured_again_every_probe() {
        let (mut cfg, sim) = stepped_scene(200, 5);
        cfg.scheduler = SchedulerKind::Priced;
        // The ordering's gate alone (a probe of the exact pass would be a frame between).
        cfg.exact_when_affordable = false;
        let mut col = Collider::new(&cfg, sim.tree(), sim.viewer()).expect("valid");
        let clock = Ticking(std::sync::atomic::AtomicU64::new(0), 1_000);
        let fixation = Some(Fixation::at(0.5, 0.5));
        let shed: Vec<bool> = (0..LEARN_FRAMES + 2 * (PROBE_EVERY + 1))
            .map(|_| {
                col.evaluate(
                    &sim.frame_input(),
                    fixation,
                    FrameBudget::Wall(2_000),
                    &clock,
                )
                .ordering_shed
            })
            .collect();
        // The first LEARN_FRAMES order and learn the cost; then PROBE_EVERY frames shed, one
        // orders to measure again, and so on.
        let mut want = vec![false; LEARN_FRAMES as usize];
        for _ in 0..2 {
            want.extend(std::iter::repeat_n(true, PROBE_EVERY as usize));
            want.push(false);
        }
        assert_eq!(shed, want);
        // A budget that pays for the ordering never sheds it.
        let mut col = Collider::new(&cfg, sim.tree(), sim.viewer()).expect("valid");
        for _ in 0..5 {
            let r = col.evaluate(
                &sim.frame_input(),
                fixation,
                FrameBudget::Wall(1 << 40),
                &clock,
            );
            assert!(!r.ordering_shed);
        }
    }
}
