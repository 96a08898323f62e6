//! Whether a wall-clock frame can pay for its optional work: the ordering of the narrow phase's
//! pairs, and the gaze rings of the frames that shed it (see [`crate::schedule::rings`]). Each is
//! a [`CostGate`] that learns the work's cost from the frames that did it.

use super::Meter;

/// A wall-clock frame orders its work only if the expected cost of ordering is at most this
/// share of the time left: above it, gaze-blind round-robin does more good with the same time.
///
/// The line depends on what the ordering buys, so it is the scheduler's. Priced: measured open
/// loop at N = 500 (1,231 pairs), ordering costs about 22 us (p10 19, p90 32), half of a frame
/// whose budget is a third of the exact narrow phase (44-52 us). With the line at a half, that
/// frame ordered or not by the chance of its own timing, and priced reached 0.88-0.94x
/// round-robin's true P there; at three quarters it orders and reaches 0.79x (C = 5) and 0.43x
/// (C = 1) with 0.56x the sphere tests. At a tenth of the exact narrow phase (14 us) the ordering
/// costs more than the whole budget either way and is shed. With the ordering at about 13 us
/// (body pass and pricing, since the pricing pass was made cheaper) a third (28-30 us) orders
/// every frame; shedding there instead left 0.91x (C = 5) and 0.85x (C = 1) round-robin's true P
/// against ordering's 0.89-0.95x and 0.48-0.65x (docs/BENCHMARKS.md), so the line stays.
pub const PRICED_ORDERING_SHARE: f64 = 0.75;

/// The same line for the paper's priority queue and expected-gain, whose ordering buys less per
/// microsecond: at a half (the line drawn for priced before) they already do worse than
/// round-robin in some wall-clock frames, so it is not raised for them.
pub const ORDERING_SHARE: f64 = 0.5;

/// A shed frame places the gaze rings (see [`crate::schedule::rings`]) only if that is expected
/// to cost at most this share of the time left. Measured open loop (5 seeds): placing takes
/// about 3.6 us at N = 500 and 29 us at N = 10,000 (medians); spending even three quarters of a
/// frame on it pays, because the few tests left go to the pairs a viewer sees (at a tenth of
/// the exact narrow phase, N = 500, 12 us: priced's true P 0.69x (C = 5) and 0.48x (C = 1)
/// round-robin's), but at a thirtieth (4 us) no test would be left: placing anyway left
/// 1.02-1.03x round-robin's P. At a half, the tenth's frames placed in only 58% of frames. (These
/// figures predate the root pass and the fovea resolved whole; the gate was kept through both,
/// and docs/BENCHMARKS.md has the current ones.)
pub const RINGS_SHARE: f64 = 0.75;

/// The first wall-clock frames order whatever the estimate says, so that the cost is learnt from
/// several frames, not from the first one alone (cold caches, first allocations).
pub const LEARN_FRAMES: u32 = 3;

/// After this many wall-clock frames in a row shed (4 s at 60 Hz), the next one orders and
/// measures the cost again: often enough to notice a faster machine or a smaller frame, rarely
/// enough that the probes' own cost (a frame that may spend its budget on ordering) stays near 1%.
pub const PROBE_EVERY: u32 = 240;

/// What a frame's optional work costs, learnt from the frames that did it, and whether a frame
/// can pay for it: the ordering, and the gaze rings of the frames that shed it. One slow frame (a
/// cold cache, the first frame's allocations, a preemption) must not shed the work for good, so
/// the first [`LEARN_FRAMES`] do it whatever the estimate says and every [`PROBE_EVERY`]-th
/// frame in a row that would not does it anyway and measures again.
#[derive(Debug, Clone, Copy, Default)]
pub struct CostGate {
    /// The learnt cost: a moving average, quick to fall and slow to rise (slow outliers are
    /// common, fast ones are not).
    cost: Option<f64>,
    /// Frames that did the work and measured it.
    measured: u32,
    /// Frames in a row that could not pay for it.
    streak: u32,
}

impl CostGate {
    /// Whether work of `scale` times the learnt cost fits in `allowance` (None: no limit),
    /// which is asked for only when it matters: it reads the clock.
    pub fn allows(&self, scale: f64, allowance: impl FnOnce() -> Option<f64>) -> bool {
        match self.cost {
            Some(_) if self.measured < LEARN_FRAMES => true,
            Some(cost) => {
                allowance().is_none_or(|a| cost * scale <= a) || self.streak >= PROBE_EVERY
            }
            None => true,
        }
    }

    /// Whether this frame did the work (a frame that could not pay lengthens the streak).
    pub fn record(&mut self, done: bool) {
        self.streak = if done { 0 } else { self.streak + 1 };
    }

    /// Learn from a frame that did the work at `cost`.
    pub fn learn(&mut self, cost: f64) {
        self.measured = self.measured.saturating_add(1);
        self.cost = Some(match self.cost {
            Some(old) if cost < old => cost,
            Some(old) => 0.8 * old + 0.2 * cost,
            None => cost,
        });
    }

    /// Whether work of `scale` times the learnt cost fits in `share` of the time `meter` has
    /// left, recorded as this frame's answer (see [`Self::allows`] and [`Self::record`]).
    pub fn admits(&mut self, scale: f64, share: f64, meter: &Meter<'_>) -> bool {
        let yes = self.allows(scale, || {
            meter.wall_left_ns().map(|left| share * left as f64)
        });
        self.record(yes);
        yes
    }
}
