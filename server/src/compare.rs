//! The side by side (`SceneConfig.compare`): a second, gaze-blind collider run on every frame the
//! loop simulates, so that a viewer sees the same frame settled twice under the same budget, once
//! steered by the gaze and once blind to it, each with its own true P.
//!
//! It is the engine's open-loop protocol run live (docs/DESIGN.md "Open-loop protocol"): the loop
//! steps one world, whose physics follows the main scheduler, and after each step hands the
//! frame's poses and candidate pairs ([`Simulation::frame_input`]) to a [`Collider`] of its own.
//! Both colliders see exactly the same frame, so the difference in true P is the schedulers' alone.
//!
//! Each side's true P is measured on the same pairs ([`PairedAudit`]): the pairs either side deemed
//! are settled exactly once for both, all of them up to [`MAX_AUDITED_PAIRS`] a frame and a
//! systematic sample beyond, so that the audit's cost (microseconds a pair under the shape truth)
//! stays within the frame whatever the scene deems. The frame's own audit (`audit`) is not needed.
//!
//! The second collider costs time in every frame: its narrow phase, its metrics and the paired
//! audit. Above [`MAX_COMPARE_BODIES`] that no longer fits a 60 Hz frame period on a 2-core
//! machine (docs/BENCHMARKS.md "Side by side"), so the mode is refused there.

use foveal_engine::collider::{Collider, true_weight};
use foveal_engine::fixation::FrameView;
use foveal_engine::metrics::Fovea;
use foveal_engine::narrow_phase::{PairState, PairStatus};
use foveal_engine::report::FOVEAL_DEG;
use foveal_engine::{
    AuditReport, Clock, ConfigError, DeemedTruth, Fixation, FrameBudget, FrameReport,
    SchedulerKind, SimConfig, Simulation,
};
use foveal_proto::pb;

/// The gaze-blind collider of the side by side.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Compare {
    /// No second collider.
    #[default]
    Off,
    /// Round-robin, under the main frame's budget.
    RoundRobin,
    /// The exact answer, whatever it costs.
    Exact,
}

/// Most bodies the side by side runs at: measured on a loaded 2-core machine at the default 4 ms
/// budget and 60 Hz, the second collider and the paired audit took 4-6 ms a frame (p50) at 5,000
/// bodies and the loop held 60 fps; at 7,500 it overran its period up to 10 times a second, and at
/// 10,000 with 8 ms it fell to 39-54 fps (docs/BENCHMARKS.md "Side by side").
pub const MAX_COMPARE_BODIES: u32 = 5_000;

impl Compare {
    /// The name used by the flag and the logs.
    pub fn name(self) -> &'static str {
        match self {
            Self::Off => "off",
            Self::RoundRobin => "round-robin",
            Self::Exact => "exact",
        }
    }

    /// Whether a second collider runs.
    pub fn is_on(self) -> bool {
        self != Self::Off
    }

    /// From the flag's spelling.
    pub fn parse(s: &str) -> Result<Self, String> {
        match s {
            "off" => Ok(Self::Off),
            "round-robin" => Ok(Self::RoundRobin),
            "exact" => Ok(Self::Exact),
            other => Err(format!(
                "compare `{other}`: expected `off`, `round-robin` or `exact`"
            )),
        }
    }

    /// The protocol's value.
    pub fn to_pb(self) -> pb::Compare {
        match self {
            Self::Off => pb::Compare::Off,
            Self::RoundRobin => pb::Compare::RoundRobin,
            Self::Exact => pb::Compare::Exact,
        }
    }

    /// Configure's merge rule for `compare`: without a mask an unspecified value keeps `current`;
    /// with one, it is taken only when the mask lists `compare`, and must then name a value.
    pub fn merge(
        current: Self,
        req: &pb::SceneConfig,
        mask: &[String],
    ) -> Result<Self, ConfigError> {
        if mask.is_empty() {
            return Ok(Self::from_pb(req.compare)?.unwrap_or(current));
        }
        if !mask.iter().any(|p| p == "compare") {
            return Ok(current);
        }
        Self::from_pb(req.compare)?.ok_or_else(|| ConfigError {
            field: "compare",
            value: "COMPARE_UNSPECIFIED".into(),
            expected: "must name a Compare value when listed in update_mask".into(),
        })
    }

    /// From the protocol: None for "unspecified" (keep), an error naming `compare` for a value
    /// out of range.
    pub fn from_pb(raw: i32) -> Result<Option<Self>, ConfigError> {
        match pb::Compare::try_from(raw) {
            Ok(pb::Compare::Unspecified) => Ok(None),
            Ok(pb::Compare::Off) => Ok(Some(Self::Off)),
            Ok(pb::Compare::RoundRobin) => Ok(Some(Self::RoundRobin)),
            Ok(pb::Compare::Exact) => Ok(Some(Self::Exact)),
            Err(_) => Err(ConfigError {
                field: "compare",
                value: raw.to_string(),
                expected:
                    "must be a Compare value (COMPARE_OFF, COMPARE_ROUND_ROBIN, COMPARE_EXACT)"
                        .into(),
            }),
        }
    }

    /// Whether the side by side may run on `sim`: refused, naming `compare`, `scene.bodies` and
    /// the limit, above [`MAX_COMPARE_BODIES`].
    pub fn check(self, sim: &SimConfig) -> Result<(), ConfigError> {
        if self.is_on() && sim.scene.bodies > MAX_COMPARE_BODIES {
            return Err(ConfigError {
                field: "compare",
                value: format!("{} with `scene.bodies` = {}", self.name(), sim.scene.bodies),
                expected: format!(
                    "the side by side runs a second collider every frame and holds the frame rate up to {MAX_COMPARE_BODIES} bodies: lower `scene.bodies` or set compare to off"
                ),
            });
        }
        Ok(())
    }
}

/// Most pair truths the side by side settles in a frame to measure both sides' true P: the exact
/// separation of a pair under the shape truth costs microseconds, and a frame deems thousands of
/// pairs, so beyond this the audit is a systematic sample of the pairs (the same pairs for both
/// sides), scaled by its stride.
pub const MAX_AUDITED_PAIRS: usize = 1_000;

/// A pair's exact answer: None if it collides, else its true gap and the perceived error of it
/// ([`true_weight`]).
type Truth = Option<(f64, f64)>;

/// Both sides' true error on one frame, over the same sample of the pairs either side deemed.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PairedAudit {
    /// The frame's own scheduler (the gaze-steered side).
    pub main: AuditReport,
    /// The gaze-blind collider.
    pub blind: AuditReport,
    /// 1 when every deemed pair was settled; k when one in k (by candidate index) was, and the
    /// sums scaled by k.
    pub stride: u32,
}

/// What the second collider made of one frame.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// Its report (Δ, P and counts; the audit is in `audit`).
    pub report: FrameReport,
    /// Both sides' true error, paired.
    pub audit: PairedAudit,
    /// Its wall-clock time, the paired audit included (ns).
    pub run_ns: u64,
}

/// The second collider of a running scene.
#[derive(Debug)]
pub struct Comparison {
    kind: Compare,
    collider: Collider,
    /// The body slots of the frame before (per body id), to follow a renumbering of the scene.
    slots: Vec<u32>,
    /// The audit's traversal stack.
    stack: Vec<(f32, u16, u16, u8, u8)>,
    /// The paired audit's answer for each deemed pair of the main side (0) and of the second
    /// collider (1), in pair order: what the viewer colours each side's wrong guesses by.
    truths: [Vec<DeemedTruth>; 2],
}

impl Comparison {
    /// The second collider for `sim` (None when `kind` is off): `sim`'s configuration with
    /// round-robin (or any scheduler, for exact frames); its audit is [`PairedAudit`].
    pub fn new(kind: Compare, sim: &Simulation) -> Result<Option<Self>, ConfigError> {
        if !kind.is_on() {
            return Ok(None);
        }
        let mut config = sim.config().clone();
        config.scheduler = SchedulerKind::RoundRobin;
        config.audit = false;
        config.fovea_first = false;
        let collider = Collider::new(&config, sim.tree(), sim.viewer())?;
        Ok(Some(Self {
            kind,
            collider,
            slots: sim.body_slots().to_vec(),
            stack: Vec::new(),
            truths: Default::default(),
        }))
    }

    /// Which collider this is.
    pub fn kind(&self) -> Compare {
        self.kind
    }

    /// The budget the second collider gets for the frame `main` reports: a sphere-test budget is
    /// the same; under a wall-clock budget, the time the main collider had for its ordering and
    /// narrow phase (the whole frame's budget also paid for integration, the broad phase, the
    /// response and the metrics, which the second collider does not do); exact for exact frames
    /// and for [`Compare::Exact`].
    fn budget(&self, sim: &Simulation, main: &FrameReport) -> FrameBudget {
        if self.kind == Compare::Exact {
            return FrameBudget::Unlimited;
        }
        match sim.frame_budget() {
            FrameBudget::Wall(_) | FrameBudget::Deadline(_) => {
                FrameBudget::Wall(main.profile.prioritise_ns + main.profile.narrow_ns)
            }
            b => b,
        }
    }

    /// Settle `sim`'s latest frame (whose report is `main`) with the second collider, measured
    /// about the fixation the main collider used, and audit both sides.
    pub fn run(&mut self, sim: &Simulation, main: &FrameReport, clock: &dyn Clock) -> Outcome {
        let t0 = clock.now_ns();
        self.follow_renumbering(sim);
        let budget = self.budget(sim, main);
        let input = sim.frame_input();
        let report = self.collider.evaluate(&input, main.fixation, budget, clock);
        let audit = self.paired_audit(sim, main.fixation);
        Outcome {
            report,
            audit,
            run_ns: clock.now_ns().saturating_sub(t0),
        }
    }

    /// Both sides' true Δ and P over the pairs either deemed: every one up to
    /// [`MAX_AUDITED_PAIRS`], else the same systematic sample of them for both, by candidate
    /// index, scaled by its stride. Each sampled pair is settled once for the two sides.
    fn paired_audit(&mut self, sim: &Simulation, fixation: Option<Fixation>) -> PairedAudit {
        let (main, blind) = (sim.pairs(), self.collider.pairs());
        let deemed = |p: Option<&PairState>| p.is_some_and(|p| p.status == PairStatus::Deemed);
        let n = main.len().max(blind.len());
        let either = (0..n)
            .filter(|&i| deemed(main.get(i)) || deemed(blind.get(i)))
            .count();
        let stride = either.div_ceil(MAX_AUDITED_PAIRS).max(1);
        let viewer = sim.viewer();
        let view = fixation.map(|f| {
            let f = f.clamped();
            FrameView {
                viewer,
                fixation_px: viewer.to_pixels(f.x, f.y),
                model: sim.config().measure_model,
                uncertainty_deg: 0.0,
            }
        });
        let (tree, world) = (sim.tree(), sim.world());
        let mut out = PairedAudit {
            stride: stride as u32,
            ..PairedAudit::default()
        };
        let mut p_sum = [0.0f64; 2];
        let mut seen = 0usize;
        let fovea = view
            .as_ref()
            .map(|v| Fovea::new(viewer, v.fixation_px, FOVEAL_DEG));
        for t in &mut self.truths {
            t.clear();
        }
        for i in 0..n {
            let sides = [main.get(i), blind.get(i)];
            if !sides.iter().any(|p| deemed(*p)) {
                continue;
            }
            seen += 1;
            let sampled = (seen - 1).is_multiple_of(stride);
            // The two lists hold the same candidates in the same order; settle a pair once
            // when both name it.
            let mut truth: Option<((u32, u32), Truth)> = None;
            for (side, p) in sides.into_iter().enumerate() {
                let Some(p) = p.filter(|p| p.status == PairStatus::Deemed) else {
                    continue;
                };
                if !sampled {
                    self.truths[side].push(DeemedTruth::NotAudited);
                    continue;
                }
                let t = match truth {
                    Some((ab, t)) if ab == (p.a, p.b) => t,
                    _ => {
                        let t = true_weight(
                            tree,
                            world,
                            p.a as usize,
                            p.b as usize,
                            view.as_ref(),
                            &mut self.stack,
                        );
                        truth = Some(((p.a, p.b), t));
                        t
                    }
                };
                let a = if side == 0 {
                    &mut out.main
                } else {
                    &mut out.blind
                };
                match t {
                    None => {
                        a.true_positives += stride as u32;
                        self.truths[side].push(DeemedTruth::Touching);
                    }
                    Some((sep, w)) => {
                        a.false_positives += stride as u32;
                        a.geometric_inaccuracy += sep * stride as f64;
                        p_sum[side] += w * stride as f64;
                        let mid =
                            (world.position[p.a as usize] + world.position[p.b as usize]) * 0.5;
                        a.foveal_false_positives += stride as u32
                            * u32::from(fovea.as_ref().is_some_and(|f| f.contains_point(mid)));
                        self.truths[side].push(DeemedTruth::Apart);
                    }
                }
            }
        }
        out.main.perceived_inaccuracy = view.map(|_| p_sum[0]);
        out.blind.perceived_inaccuracy = view.map(|_| p_sum[1]);
        out
    }

    /// The scene renumbers its bodies now and then (large N): the collider's memory of the frame
    /// before (witnesses) follows, as the scene's own collider's does.
    fn follow_renumbering(&mut self, sim: &Simulation) {
        let now = sim.body_slots();
        if now == self.slots.as_slice() {
            return;
        }
        let mut new_of_old = vec![0u32; now.len()];
        for (&old, &new) in self.slots.iter().zip(now) {
            if let Some(slot) = new_of_old.get_mut(old as usize) {
                *slot = new;
            }
        }
        if self.slots.len() == now.len() {
            self.collider.renumber(&new_of_old);
        }
        self.slots.clear();
        self.slots.extend_from_slice(now);
    }

    /// The second collider's collision list of the latest frame, by body id, with the paired
    /// audit's answer for each deemed pair.
    pub fn collisions(&self, sim: &Simulation) -> pb::Collisions {
        crate::convert::collision_list(sim, self.collider.pairs(), &self.truths[1])
    }

    /// The paired audit's answer for each deemed pair of the main side's latest frame, in pair
    /// order: its collision list's truths when the frame has no audit of its own.
    pub fn main_truth(&self) -> &[DeemedTruth] {
        &self.truths[0]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use foveal_engine::{BudgetSpec, Fixation, FrozenClock};

    fn sim(bodies: u32, budget: BudgetSpec) -> Simulation {
        let mut c = SimConfig::default();
        c.scene.bodies = bodies;
        c.budget = budget;
        c.audit = true;
        Simulation::new(c).expect("valid")
    }

    #[test]
    fn the_second_collider_settles_the_same_frame_under_the_same_test_budget() {
        let mut s = sim(2_000, BudgetSpec::SphereTests(3_000));
        let mut cmp = Comparison::new(Compare::RoundRobin, &s)
            .expect("valid")
            .expect("on");
        let mut worse = 0;
        for _ in 0..30 {
            let main = s.step(Some(Fixation::at(0.3, 0.4)), &FrozenClock).clone();
            let out = cmp.run(&s, &main, &FrozenClock);
            let r = &out.report;
            assert_eq!(r.candidate_pairs, main.candidate_pairs);
            assert!(r.sphere_tests <= 3_000 + 6_400, "{}", r.sphere_tests);
            assert!(r.budget_exhausted);
            // The paired audit of the frame's own side is the engine's audit of it, when every
            // deemed pair was settled.
            let own = main.audit.expect("audit");
            let paired = out.audit;
            if paired.stride == 1 {
                assert_eq!(paired.main.false_positives, own.false_positives);
                assert_eq!(paired.main.true_positives, own.true_positives);
                let (x, y) = (
                    paired.main.perceived_inaccuracy.expect("view"),
                    own.perceived_inaccuracy.expect("view"),
                );
                assert!((x - y).abs() <= 1e-9 * y.abs().max(1.0), "{x} vs {y}");
            }
            if paired.stride == 1 {
                let settled = paired.blind.false_positives + paired.blind.true_positives;
                assert_eq!(settled, r.deemed);
            }
            let (a, b) = (
                paired.main.perceived_inaccuracy.expect("view"),
                paired.blind.perceived_inaccuracy.expect("view"),
            );
            worse += usize::from(b > a);
        }
        // Gaze-blind round-robin leaves more true P about the fixation than the priced scheduler.
        assert!(worse > 20, "{worse} of 30");
    }

    /// A small scene deems fewer pairs than the audit's cap: every one is settled, and the frame's
    /// own side is exactly what the engine's audit says.
    #[test]
    fn a_small_frame_is_audited_whole_and_matches_the_engine() {
        let mut s = sim(300, BudgetSpec::SphereTests(150));
        let mut cmp = Comparison::new(Compare::RoundRobin, &s)
            .expect("valid")
            .expect("on");
        for _ in 0..10 {
            let main = s.step(Some(Fixation::at(0.6, 0.5)), &FrozenClock).clone();
            let out = cmp.run(&s, &main, &FrozenClock);
            assert_eq!(out.audit.stride, 1);
            let own = main.audit.expect("audit");
            assert_eq!(out.audit.main.false_positives, own.false_positives);
            assert_eq!(out.audit.main.true_positives, own.true_positives);
            assert_eq!(
                out.audit.main.foveal_false_positives,
                own.foveal_false_positives
            );
            // Pair by pair too: the answers the viewer colours the gaze side by.
            assert_eq!(cmp.main_truth(), s.deemed_truth());
            let blind = out.audit.blind;
            assert_eq!(
                blind.false_positives + blind.true_positives,
                out.report.deemed
            );
            let c = cmp.collisions(&s);
            let truths: Vec<u8> = c.deemed_with_truth().map(|(_, t)| t).collect();
            let apart = truths
                .iter()
                .filter(|&&t| t == DeemedTruth::Apart as u8)
                .count();
            assert_eq!(truths.len(), out.report.deemed as usize);
            assert!(truths.iter().all(|&t| t != DeemedTruth::NotAudited as u8));
            assert_eq!(apart as u32, blind.false_positives);
        }
    }

    /// Above the audit's cap one pair in `stride` is settled: the others are sent as not
    /// audited, and the counts of those settled, scaled by the stride, are the audit's.
    #[test]
    fn a_sampled_audit_marks_the_pairs_it_passed_by() {
        let mut s = sim(3_000, BudgetSpec::SphereTests(500));
        let mut cmp = Comparison::new(Compare::RoundRobin, &s)
            .expect("valid")
            .expect("on");
        let main = s.step(Some(Fixation::at(0.5, 0.5)), &FrozenClock).clone();
        let out = cmp.run(&s, &main, &FrozenClock);
        let k = out.audit.stride;
        assert!(k > 1, "{} deemed", main.deemed);
        for (truth, audit, deemed) in [
            (cmp.main_truth(), out.audit.main, main.deemed),
            (&cmp.truths[1][..], out.audit.blind, out.report.deemed),
        ] {
            assert_eq!(truth.len() as u32, deemed);
            let count = |t: DeemedTruth| truth.iter().filter(|&&x| x == t).count() as u32;
            assert_eq!(count(DeemedTruth::Apart) * k, audit.false_positives);
            assert_eq!(count(DeemedTruth::Touching) * k, audit.true_positives);
            assert!(count(DeemedTruth::NotAudited) > 0);
        }
    }

    #[test]
    fn exact_comparison_deems_nothing_and_off_builds_nothing() {
        let mut s = sim(500, BudgetSpec::SphereTests(200));
        assert!(Comparison::new(Compare::Off, &s).expect("valid").is_none());
        let mut cmp = Comparison::new(Compare::Exact, &s)
            .expect("valid")
            .expect("on");
        let main = s.step(Some(Fixation::at(0.5, 0.5)), &FrozenClock).clone();
        let out = cmp.run(&s, &main, &FrozenClock);
        assert_eq!(out.report.deemed, 0);
        assert!(main.deemed > 0);
        assert_eq!(out.audit.blind.perceived_inaccuracy, Some(0.0));
        assert!(out.audit.main.perceived_inaccuracy.expect("view") > 0.0);
        let c = cmp.collisions(&s);
        assert!(c.deemed.is_empty());
        assert_eq!(c.real.len() / 8, out.report.real_collisions as usize);
    }

    #[test]
    fn refused_above_the_limit_naming_the_field() {
        let mut c = SimConfig::default();
        c.scene.bodies = MAX_COMPARE_BODIES + 1;
        let e = Compare::RoundRobin.check(&c).expect_err("over");
        assert_eq!(e.field, "compare");
        assert!(e.expected.contains(&MAX_COMPARE_BODIES.to_string()));
        Compare::Off.check(&c).expect("off is always fine");
        c.scene.bodies = MAX_COMPARE_BODIES;
        Compare::Exact.check(&c).expect("at the limit");
    }
}
