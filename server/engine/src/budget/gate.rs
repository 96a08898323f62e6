//! Whether a wall-clock frame can pay for its optional work: the ordering of the narrow phase's
//! pairs, and the gaze rings of the frames that shed it (see [`crate::schedule::rings`]). Each is
//! a [`CostGate`] that learns the work's cost from the frames that did it. And whether it can
//! pay for the exact narrow phase outright ([`ExactGate`]), which no budgeted order beats.

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

/// Frames in a row without the exact pass after which one whose estimate is within
/// [`PROBE_NEAR`] of the time left takes it again (half a second at 60 Hz): at 10,000 bodies
/// and a 4 ms budget the pass fits with room, yet a first estimate from a cold frame kept the
/// gate shut for [`PROBE_EVERY`] frames at a time.
pub const PROBE_NEAR_EVERY: u32 = 30;

/// How far over the time left an estimate may be for [`PROBE_NEAR_EVERY`]'s probe.
pub const PROBE_NEAR: f64 = 1.5;

/// Headroom the exact narrow phase's expected cost must leave in a wall-clock frame for the
/// frame to take it ([`ExactGate`]): the frame-to-frame spread of its cost at 10,000 bodies
/// on two threads (p99 over p50 about 1.1-1.2), so that a frame that takes it does not run
/// late by its own variation.
pub const EXACT_HEADROOM: f64 = 1.25;

/// Whether a wall-clock frame can resolve every pair exactly, in the exact frame's one parallel
/// pass, inside its narrow phase's budget: learnt per candidate pair from the frames that took
/// the pass, and bounded from above by the budgeted frames that settled every pair anyway.
///
/// Why: a budget must never make a frame slower or worse than an exact one. An ordered frame
/// pays for its order (the root pass, the gaze rings, prioritising and pricing) before its
/// first descent; when the budget covers the exact frame those are pure cost, and at 10,000
/// bodies a 4 ms frame whose exact narrow phase takes 1.9 ms still deemed about 900 pairs.
/// The pass a frame takes on this gate's word is cut at its deadline like any budgeted work
/// (`NarrowPhase::resolve_frame_until`), so a wrong word costs that frame its order, not its
/// budget; the estimate is therefore learnt from every such frame, quick to rise and slow to
/// fall (the opposite of [`CostGate`]'s). The first estimate comes from an ordered frame that
/// settled every pair, or else from the frame after the first [`LEARN_FRAMES`] (which learn the
/// order's costs), which takes the pass to measure it. Since the estimate falls only in frames
/// that take the pass, a frame takes it again after [`PROBE_NEAR_EVERY`] frames in a row that
/// did not if its estimate is within [`PROBE_NEAR`] of the time left (a first measurement in a
/// cold frame is often the dearest), and after [`PROBE_EVERY`] if within twice it (the frame's
/// work may have shrunk).
#[derive(Debug, Clone, Copy, Default)]
pub struct ExactGate {
    /// Expected ns per candidate pair of the exact narrow phase.
    per_pair: Option<f64>,
    /// Frames in a row that did not take the pass.
    streak: u32,
}

impl ExactGate {
    /// Whether a frame of `pairs` candidate pairs whose narrow phase has `left()` ns (None: no
    /// wall clock, never) takes the exact pass: expected to fit with [`EXACT_HEADROOM`], or
    /// a probe; recorded as this frame's answer. `left` is asked only with an estimate or for
    /// a probe (it may read a clock, which a frame's budget pays for).
    pub fn admits(&mut self, pairs: usize, left: impl FnOnce() -> Option<u64>) -> bool {
        let probe = self.per_pair.is_none() && self.streak >= LEARN_FRAMES;
        let known = match self.per_pair {
            Some(per_pair) => left().map(|left| (per_pair, left)),
            None if probe => left().map(|_| (0.0, 0)),
            None => None,
        };
        let yes = match known {
            None => false,
            Some(_) if probe => true,
            Some((per_pair, left)) => {
                let cost = per_pair * pairs as f64;
                let left = left as f64;
                cost * EXACT_HEADROOM <= left
                    || (self.streak >= PROBE_NEAR_EVERY && cost <= PROBE_NEAR * left)
                    || (self.streak >= PROBE_EVERY && cost <= 2.0 * left)
            }
        };
        self.streak = if yes {
            0
        } else {
            self.streak.saturating_add(1)
        };
        yes
    }

    /// Learn from a frame that resolved `pairs` pairs exactly in `ns`: in the exact pass (if
    /// it was cut, the pairs it reached), or (an upper bound) in a budgeted order that settled
    /// every pair.
    pub fn learn(&mut self, ns: u64, pairs: usize) {
        if pairs == 0 {
            return;
        }
        let cost = ns as f64 / pairs as f64;
        self.per_pair = Some(match self.per_pair {
            Some(old) if cost > old => cost,
            Some(old) => 0.8 * old + 0.2 * cost,
            None => cost,
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_exact_gate_admits_what_fits_with_headroom_and_probes_after_a_streak() {
        let mut g = ExactGate::default();
        for _ in 0..LEARN_FRAMES {
            assert!(
                !g.admits(1000, || Some(u64::MAX)),
                "the order's costs learnt first"
            );
        }
        assert!(!g.admits(1000, || None), "no wall clock, no probe");
        assert!(g.admits(1000, || Some(1)), "then a probe");
        g.learn(1_000_000, 1000); // 1 us a pair
        assert!(!g.admits(1000, || None), "no wall clock, no pass");
        assert!(g.admits(1000, || Some(1_250_000)));
        assert!(!g.admits(1000, || Some(1_249_999)));
        // Quick to rise, slow to fall.
        g.learn(2_000_000, 1000);
        assert!(!g.admits(1000, || Some(2_400_000)));
        g.learn(1_000_000, 1000);
        assert!(
            !g.admits(1000, || Some(2_000_000)),
            "0.8 * 2 + 0.2 * 1 = 1.8 us a pair"
        );
        assert!(g.admits(1000, || Some(2_250_000)));
        // A streak without the pass probes again: soon within 1.5 times the time left, after
        // a long one within twice it.
        for _ in 0..PROBE_NEAR_EVERY {
            assert!(!g.admits(1000, || Some(1_250_000)));
        }
        assert!(
            !g.admits(1000, || Some(1_100_000)),
            "1.8 us a pair is over 1.5x"
        );
        assert!(g.admits(1000, || Some(1_250_000)));
        for _ in 0..PROBE_EVERY {
            assert!(!g.admits(1000, || Some(1_000_000)));
        }
        assert!(
            !g.admits(1000, || Some(800_000)),
            "beyond twice the time left"
        );
        assert!(g.admits(1000, || Some(900_000)));
        assert!(!g.admits(1000, || Some(900_000)), "the streak starts again");
    }
}
