//! What a frame reports (paper section 4's per-frame record, DESIGN.md "Frame record").

use serde::{Deserialize, Serialize};

use crate::config::MAX_DEPTH;
use crate::fixation::Fixation;

/// Time spent in each phase of the frame, nanoseconds by the caller's clock (all 0 with a frozen
/// clock). `collision` = broad + prioritise + narrow + response is the paper's T.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct PhaseProfile {
    /// Renumbering the bodies in spatial order (every [`crate::SimConfig::renumber_every`]
    /// frames at large N; 0 in other frames).
    pub renumber_ns: u64,
    /// Integration of positions and orientations.
    pub integrate_ns: u64,
    /// Broad phase (sweep and prune, candidate list).
    pub broad_ns: u64,
    /// Prioritisation of the candidate pairs (projection, eccentricity, weights).
    pub prioritise_ns: u64,
    /// Narrow phase: scheduling and sphere tests, interruption.
    pub narrow_ns: u64,
    /// Collision response.
    pub response_ns: u64,
    /// Metrics and audit (instrumentation, not part of T). In an exact frame it includes the
    /// counts the narrow phase sums block by block as it resolves the pairs (timed around each
    /// block; see `Collider::collide_exact`), so `narrow_ns` is the sphere tests' alone.
    pub measure_ns: u64,
}

impl PhaseProfile {
    /// T: collision-handling time (broad + prioritise + narrow + response), as the paper
    /// measures it.
    pub fn collision_ns(&self) -> u64 {
        self.broad_ns + self.prioritise_ns + self.narrow_ns + self.response_ns
    }

    /// The whole step: every phase, metrics included.
    pub fn step_ns(&self) -> u64 {
        self.renumber_ns + self.integrate_ns + self.collision_ns() + self.measure_ns
    }
}

/// The exact answer for the frame's deemed pairs (audit mode).
///
/// A field missing from a serialized record takes its default, as in [`FrameReport`].
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct AuditReport {
    /// Deemed pairs that are not colliding (true false positives).
    pub false_positives: u32,
    /// Deemed pairs that do collide.
    pub true_positives: u32,
    /// Of [`Self::false_positives`], those within [`FOVEAL_DEG`] of the fixation (the midpoint of
    /// the two centres, as [`FrameReport::foveal_pairs`] counts): the wrong guesses where the
    /// viewer looks. 0 without a fixation.
    pub foveal_false_positives: u32,
    /// True Δ: the sum over deemed pairs of the gap each leaves (the separation of its leaf-sphere
    /// sets), 0 for a deemed pair that truly collides: the quantity
    /// [`FrameReport::geometric_inaccuracy`] estimates.
    pub geometric_inaccuracy: f64,
    /// True P with the measuring model (None without a fixation).
    pub perceived_inaccuracy: Option<f64>,
    /// Candidate pairs of this frame's positions (boxes overlapping) that the frame did not
    /// collide because their region was stale: what shedding the broad phase cost.
    pub missed_pairs: u32,
}

/// What an audit found of one deemed pair: whether deeming it colliding was right. The protocol
/// sends these as one byte a pair (`Collisions.deemed_truth`), so the values are fixed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum DeemedTruth {
    /// No audit settled the pair (a sampled audit passed it by).
    NotAudited = 0,
    /// The pair does collide: the guess was right and nothing shows.
    Touching = 1,
    /// The pair is apart: its response will push the bodies apart across a visible gap, the
    /// error Δ and P measure.
    Apart = 2,
}

/// Eccentricity (degrees of visual angle) within which a frame counts its pairs as foveal: the
/// fovea and parafovea, where the paper's model weighs errors most.
pub const FOVEAL_DEG: f64 = 5.0;

/// One frame's record.
///
/// A field missing from a serialized record (one written before the field existed) takes its
/// default, so recordings stay readable as flags are added.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct FrameReport {
    /// Frame number, from 0.
    pub index: u64,
    /// Simulated time at the end of the frame (seconds).
    pub sim_time: f64,
    /// The fixation used, if any.
    pub fixation: Option<Fixation>,
    /// A fixation was handed in but was not usable (non-finite) and was ignored.
    pub fixation_rejected: bool,
    /// Geometric inaccuracy Δ, estimated (scene units): the sum over deemed pairs of the gap each
    /// leaves (0 where the pair truly collides), each gap taken as the paper's upper bound, the
    /// distance between the centres of the last two spheres found overlapping (section 3); the
    /// audit's [`AuditReport::geometric_inaccuracy`] is the exact value.
    pub geometric_inaccuracy: f64,
    /// Perceived inaccuracy P with the measuring model (None without a fixation).
    pub perceived_inaccuracy: Option<f64>,
    /// Candidate pairs from the broad phase.
    pub candidate_pairs: u32,
    /// Pairs resolved as colliding by a leaf-leaf overlap.
    pub real_collisions: u32,
    /// Pairs deemed colliding at interruption.
    pub deemed: u32,
    /// Approaching pairs whose velocities were exchanged.
    pub responses: u32,
    /// Pairs resolved (either way) at each level, level 1 first.
    pub resolved_per_level: [u32; MAX_DEPTH],
    /// Sphere tests done by the narrow phase.
    pub sphere_tests: u64,
    /// Sampling stride of Δ and P: 1 when every deemed pair was summed, k when the deemed pairs
    /// of index divisible by k were (see `metrics`).
    pub metrics_stride: u32,
    /// Standard error of Δ from sampling (0 when exact).
    pub geometric_inaccuracy_se: f64,
    /// Standard error of P from sampling (0 when exact; None without a fixation).
    pub perceived_inaccuracy_se: Option<f64>,
    /// Candidate pairs whose centre lies within [`FOVEAL_DEG`] of the fixation (0 without one).
    pub foveal_pairs: u32,
    /// Of those, pairs deemed at interruption rather than settled exactly.
    pub foveal_deemed: u32,
    /// The budget ran out before every pair was resolved.
    pub budget_exhausted: bool,
    /// The wall-clock budget could not pay for the scheduler's ordering: this frame was scheduled
    /// by the gaze rings instead where the broad phase locates its pairs by column and that
    /// placing fitted the time left (see `schedule::rings`), gaze-blind round-robin otherwise.
    pub ordering_shed: bool,
    /// The wall-clock budget was expected to cover the exact narrow phase, and the frame took it:
    /// every pair resolved in one parallel pass, without an order (see
    /// `budget::gate::ExactGate`).
    pub exact_fit: bool,
    /// The frame placed the gaze rings and settled the pairs within the fovea through them,
    /// whole and nearest the fixation first (see `schedule::rings`): a frame of the priced
    /// scheduler before its ordering, and any frame whose ordering was shed as its whole
    /// schedule (round-robin over the rest after the fovea, the outer ring first).
    pub gaze_rings: bool,
    /// The wall-clock budget was spent before the narrow phase could start: integration and the
    /// broad phase (with the learnt tail kept for response and metrics) took all of it, so no
    /// pair was tested and every pair was deemed. The budget is below what this scene's fixed
    /// per-frame work costs on this machine.
    pub budget_spent_before_narrow: bool,
    /// Broad-phase regions a whole-frame wall-clock budget did not reach (see `shedding`): their
    /// pairs were not searched, collided or responded to this frame. 0 under other budgets.
    pub stale_regions: u32,
    /// Of [`Self::stale_regions`], how many regions there are in all (0: the broad phase ran whole).
    pub regions: u32,
    /// Pairs the stale regions held when last searched.
    pub stale_pairs: u32,
    /// Of the stale regions, those that may hold a pair within [`FOVEAL_DEG`] of the fixation:
    /// when not 0, [`Self::foveal_pairs`] misses what those regions hold.
    pub foveal_stale: u32,
    /// How much earlier than its wall-clock budget this frame aimed to end (ns): the guard band
    /// learnt from the recent frames' lateness (see `guard`). 0 under other budgets.
    pub guard_ns: u64,
    /// Per-phase timings.
    pub profile: PhaseProfile,
    /// The narrow phase's passes under a budget: what each cost in time and sphere tests.
    pub passes: PassCosts,
    /// Exact answer for the deemed pairs, when auditing.
    pub audit: Option<AuditReport>,
}

/// What one pass of a frame's narrow phase cost: its wall time (ns, by the frame's clock: 0
/// under a frozen one) and its sphere tests.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default)]
pub struct PassCost {
    /// Wall time, ns.
    pub ns: u64,
    /// Sphere tests.
    pub tests: u64,
}

impl PassCost {
    /// ns per sphere test (None for a pass without tests: a fixed cost).
    pub fn ns_per_test(&self) -> Option<f64> {
        (self.tests > 0).then(|| self.ns as f64 / self.tests as f64)
    }
}

/// A frame's narrow phase pass by pass (docs/DESIGN.md "Narrow phase"): the fixed costs (reset,
/// ordering) beside the passes that test, so that what a budget buys can be read per pass.
/// Their tests sum to [`FrameReport::sphere_tests`]; their times to the narrow phase and
/// prioritisation. Each pass is timed by the clock reads the frame makes anyway (a read is not
/// free, and a wall-clock budget pays for it). An exact frame's single pass is in `rest`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default)]
pub struct PassCosts {
    /// Resetting the pair states for the frame (no test).
    pub reset: PassCost,
    /// The root pass: every pair apart at the root settled in one go (wall-clock frames).
    pub roots: PassCost,
    /// The fovea: the pairs within [`FOVEAL_DEG`] of the fixation settled whole, nearest first
    /// (the gaze rings, the regions of a shed broad phase, or `fovea_first`).
    pub fovea: PassCost,
    /// Ordering: prioritising the pairs for the scheduler (no test).
    pub ordering: PassCost,
    /// The rest: the scheduler's run until every pair was settled or the budget ran out, and
    /// closing the frame (deeming what is left). Where the ordering was shed, the fallback's
    /// run, with the root pass and the gaze rings it did itself.
    pub rest: PassCost,
}

impl FrameReport {
    /// T in seconds.
    pub fn collision_time_s(&self) -> f64 {
        self.profile.collision_ns() as f64 * 1e-9
    }

    /// Feed every deterministic field (everything but timings) to `h`.
    pub fn hash_into(&self, h: &mut Fnv1a) {
        h.u64(self.index);
        h.f64(self.sim_time);
        if let Some(f) = self.fixation {
            h.f64(f.x);
            h.f64(f.y);
            h.f64(f.age_s);
        }
        h.u64(u64::from(self.fixation_rejected));
        h.f64(self.geometric_inaccuracy);
        h.f64(self.perceived_inaccuracy.unwrap_or(-1.0));
        for v in [
            self.candidate_pairs,
            self.real_collisions,
            self.deemed,
            self.responses,
        ] {
            h.u64(u64::from(v));
        }
        for v in self.resolved_per_level {
            h.u64(u64::from(v));
        }
        h.u64(self.sphere_tests);
        h.u64(u64::from(self.budget_exhausted));
        if let Some(a) = self.audit {
            h.u64(u64::from(a.false_positives));
            h.u64(u64::from(a.true_positives));
            h.f64(a.geometric_inaccuracy);
            h.f64(a.perceived_inaccuracy.unwrap_or(-1.0));
        }
    }
}

/// 64-bit FNV-1a, for golden hashes of frame sequences (stable across platforms and versions).
#[derive(Debug, Clone, Copy)]
pub struct Fnv1a(pub u64);

impl Default for Fnv1a {
    fn default() -> Self {
        Self(0xcbf2_9ce4_8422_2325)
    }
}

impl Fnv1a {
    /// Mix in 8 bytes.
    pub fn u64(&mut self, v: u64) {
        for b in v.to_le_bytes() {
            self.0 ^= u64::from(b);
            self.0 = self.0.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }

    /// Mix in the bits of a float.
    pub fn f64(&mut self, v: f64) {
        self.u64(v.to_bits());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A record written before the newer flags existed still reads, with them unset.
    #[test]
    fn a_record_without_the_newer_flags_reads_with_them_unset() {
        let mut json = serde_json::to_value(FrameReport {
            index: 7,
            deemed: 3,
            gaze_rings: true,
            budget_spent_before_narrow: true,
            ..FrameReport::default()
        })
        .expect("serialize");
        let map = json.as_object_mut().expect("an object");
        map.remove("gaze_rings");
        map.remove("budget_spent_before_narrow");
        let r: FrameReport = serde_json::from_value(json).expect("an older record reads");
        assert_eq!((r.index, r.deemed), (7, 3));
        assert!(!r.gaze_rings && !r.budget_spent_before_narrow);
    }
}
