//! The narrow phase's budget (paper section 2: "the application indicates that it wishes to
//! interrupt collision processing").
//!
//! Time enters the engine only through a [`Clock`] the caller hands in (see `crate::clock`); the
//! engine never reads a wall clock itself. Besides the paper's wall-clock budget there is a deterministic budget counted
//! in sphere tests, so that a run replays bit for bit on any machine.

use crate::clock::Clock;

/// A budget resolved for one frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FrameBudget {
    /// Never interrupt.
    Unlimited,
    /// Stop once the clock reaches this instant (ns, the clock's origin).
    Deadline(u64),
    /// Stop once this many sphere tests have been done this frame.
    Tests(u64),
    /// A wall-clock allowance per frame (ns), counted from the frame's start: the frame's meter
    /// stops at start + allowance ([`Self::starting_at`]).
    Wall(u64),
}

impl FrameBudget {
    /// This budget for a frame that started at `start_ns`: an allowance becomes a deadline.
    pub fn starting_at(self, start_ns: u64) -> Self {
        match self {
            Self::Wall(ns) => Self::Deadline(start_ns.saturating_add(ns)),
            b => b,
        }
    }
}

/// Fewest steps between two clock reads, near the deadline: a read costs about as much as a small
/// step, and a step is at most a few hundred sphere tests, so this bounds the overshoot to well
/// under 10 µs.
const CLOCK_STRIDE: u32 = 8;

/// Most steps between two clock reads, far from the deadline.
const MAX_CLOCK_STRIDE: u32 = 64;

/// The time taken as a step's bound when spacing the reads (ns): a few hundred sphere tests at a
/// few ns each. After a read with `left` ns to go, the next comes after `left / STEP_NS_BOUND`
/// steps (between [`CLOCK_STRIDE`] and [`MAX_CLOCK_STRIDE`]), so steps within the bound cannot
/// carry the frame past its deadline unread, and the last tens of microseconds are read as
/// closely as before.
const STEP_NS_BOUND: u64 = 2_000;

/// The time taken as a sphere test's bound when spacing the reads (ns). A step is not always
/// small: one level of a pair in deep overlap can expand thousands of sphere pairs, so 64 such
/// steps could run milliseconds past the deadline unread. After a read with `left` ns to go the
/// meter also reads once `left / TEST_NS_BOUND` more sphere tests are done, whichever comes first:
/// tests cost 1-5 ns here, so this bound is met with room and only long steps hasten a read.
const TEST_NS_BOUND: u64 = 8;

/// Checks the budget between narrow-phase steps.
pub struct Meter<'c> {
    budget: FrameBudget,
    clock: &'c dyn Clock,
    countdown: u32,
    /// Sphere tests done at the last read, and how many more may be done before the next.
    tests_at_read: u64,
    test_allowance: u64,
    exhausted: bool,
    /// The clock's reading when a wall-clock duration started (None for other budgets).
    started: Option<u64>,
    /// For [`Self::exhausted_between_pairs`]: the last read, the calls since, and the longest
    /// time a call has taken between two reads (ns), decaying.
    last_read_ns: Option<u64>,
    calls_since_read: u32,
    call_ns: u64,
}

impl std::fmt::Debug for Meter<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Meter")
            .field("budget", &self.budget)
            .field("exhausted", &self.exhausted)
            .finish()
    }
}

impl<'c> Meter<'c> {
    /// A meter for one frame.
    pub fn new(budget: FrameBudget, clock: &'c dyn Clock) -> Self {
        let (budget, started) = match budget {
            FrameBudget::Wall(_) => {
                let now = clock.now_ns();
                (budget.starting_at(now), Some(now))
            }
            b => (b, None),
        };
        Self {
            budget,
            clock,
            countdown: 0,
            tests_at_read: 0,
            test_allowance: 0,
            exhausted: false,
            started,
            last_read_ns: None,
            calls_since_read: 0,
            call_ns: 0,
        }
    }

    /// Whether the budget is time (a wall-clock duration or deadline), not sphere tests or none.
    pub fn counts_time(&self) -> bool {
        matches!(self.budget, FrameBudget::Deadline(_) | FrameBudget::Wall(_))
    }

    /// Whether work must stop, given the sphere tests done so far. Once true it stays true.
    #[inline]
    pub fn exhausted(&mut self, tests: u64) -> bool {
        if self.exhausted {
            return true;
        }
        self.exhausted = match self.budget {
            FrameBudget::Unlimited => false,
            FrameBudget::Tests(max) => tests >= max,
            FrameBudget::Deadline(t) | FrameBudget::Wall(t) => {
                // Callers pass their frame's running count (0 for work without tests).
                let since = tests.saturating_sub(self.tests_at_read);
                if self.countdown == 0 || since >= self.test_allowance {
                    // Why spaced by the time left: read every 8 steps, a 4 ms frame at 10,000
                    // bodies read the clock 5,000-6,000 times, about 3% of the frame, time the
                    // sphere tests did not get; only the end of the budget needs close reads.
                    let now = self.clock.now_ns();
                    let left = t.saturating_sub(now);
                    let steps = left / STEP_NS_BOUND;
                    self.countdown =
                        steps.clamp(u64::from(CLOCK_STRIDE), u64::from(MAX_CLOCK_STRIDE)) as u32;
                    self.tests_at_read = tests;
                    self.test_allowance = (left / TEST_NS_BOUND).max(1);
                    now >= t
                } else {
                    self.countdown -= 1;
                    false
                }
            }
        };
        self.exhausted
    }

    /// [`Self::exhausted`], reading a wall clock now whatever the spacing of the reads: for a
    /// caller about to start work that costs something before its first check.
    #[inline]
    pub fn exhausted_now(&mut self, tests: u64) -> bool {
        self.countdown = 0;
        self.exhausted(tests)
    }

    /// [`Self::exhausted`] for callers that ask between whole pairs, whose cost the fixed
    /// spacing of the reads does not bound: a pair whose roots touch is a descent of tens to
    /// thousands of sphere tests, and under the shape truth a star test of a microsecond or
    /// more counts as [`crate::narrow_phase::SHAPE_TEST_COST`] tests. The time a call takes is
    /// measured between reads (the longest, decaying by a quarter a read), and the next read
    /// comes once a quarter of the time left could have gone at that rate (at least every
    /// [`MAX_CLOCK_STRIDE`] calls, and at every call near the end). Why: spaced as between
    /// steps, the priced order's whole pairs at 5,000 bodies under the shape truth ran
    /// 0.3-0.8 ms past a 4 ms frame's deadline in 3-5% of frames.
    #[inline]
    pub fn exhausted_between_pairs(&mut self, tests: u64) -> bool {
        let deadline = match self.budget {
            FrameBudget::Deadline(t) | FrameBudget::Wall(t) => t,
            FrameBudget::Unlimited | FrameBudget::Tests(_) => return self.exhausted(tests),
        };
        if self.exhausted {
            return true;
        }
        self.calls_since_read += 1;
        if self.countdown > 0 {
            self.countdown -= 1;
            return false;
        }
        let now = self.clock.now_ns();
        if let Some(last) = self.last_read_ns {
            let per_call = now.saturating_sub(last) / u64::from(self.calls_since_read.max(1));
            self.call_ns = per_call.max(self.call_ns - self.call_ns / 4);
        }
        self.last_read_ns = Some(now);
        self.calls_since_read = 0;
        // Until a call has been timed (or on a clock that does not advance), every call reads.
        let left = deadline.saturating_sub(now);
        self.countdown = match self.call_ns {
            0 => 0,
            ns => (left / (4 * ns)).min(u64::from(MAX_CLOCK_STRIDE)) as u32,
        };
        self.exhausted = now >= deadline;
        self.exhausted
    }

    /// Whether a wall-clock deadline has passed (always false for other budgets). For work that does
    /// no sphere tests, such as prioritisation, which a sphere-test budget does not count.
    #[inline]
    pub fn exhausted_by_clock(&mut self) -> bool {
        match self.budget {
            FrameBudget::Deadline(_) | FrameBudget::Wall(_) => self.exhausted(0),
            FrameBudget::Unlimited | FrameBudget::Tests(_) => false,
        }
    }

    /// The clock's reading now (for work that times itself against the budget it spends).
    #[inline]
    pub fn now_ns(&self) -> u64 {
        self.clock.now_ns()
    }

    /// When a wall-clock duration started counting (None for other budgets): the clock reading
    /// the meter took when it was made, so that work timed against the budget needs no read of
    /// its own.
    pub fn started_ns(&self) -> Option<u64> {
        self.started
    }

    /// Nanoseconds left before a wall-clock deadline (None for other budgets).
    pub fn wall_left_ns(&self) -> Option<u64> {
        match self.budget {
            FrameBudget::Deadline(t) => Some(t.saturating_sub(self.clock.now_ns())),
            _ => None,
        }
    }

    /// Whether the budget ran out during the frame.
    pub fn was_exhausted(&self) -> bool {
        self.exhausted
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::clock::{FrozenClock, Manual};
    use std::sync::atomic::{AtomicU64, Ordering::Relaxed};

    #[test]
    fn test_budget_stops_at_the_count_and_stays_stopped() {
        let c = FrozenClock;
        let mut m = Meter::new(FrameBudget::Tests(10), &c);
        assert!(!m.exhausted(9));
        assert!(m.exhausted(10));
        assert!(m.exhausted(0));
        let mut u = Meter::new(FrameBudget::Unlimited, &c);
        assert!(!u.exhausted(u64::MAX));
    }

    /// Far from the deadline the clock is read every [`MAX_CLOCK_STRIDE`] steps; as the
    /// deadline nears the reads close in, and once it has passed it is noticed within
    /// [`CLOCK_STRIDE`] steps.
    #[test]
    fn reads_are_sparse_far_from_the_deadline_and_close_near_it() {
        let clock = Manual(AtomicU64::new(0));
        let reads = |m: &mut Meter<'_>, steps: usize| {
            // Steps until the meter next reads: it reads on the call after its countdown ends.
            let mut n = 0;
            for _ in 0..steps {
                let before = m.countdown;
                assert!(!m.exhausted(0));
                n += usize::from(before == 0);
            }
            n
        };
        let mut m = Meter::new(FrameBudget::Deadline(10_000_000), &clock);
        // 10 ms to go: one read per MAX_CLOCK_STRIDE + 1 calls.
        assert_eq!(reads(&mut m, 650), 10);
        // 20 us to go: about one read per 10 calls.
        clock.0.store(10_000_000 - 20_000, Relaxed);
        let mut m = Meter::new(FrameBudget::Deadline(10_000_000), &clock);
        assert_eq!(reads(&mut m, 110), 10);
        // Read 20 us before the deadline, then the deadline passes at once (steps far slower
        // than the bound): noticed within the 10 calls that read spaced, and from a read within
        // the last few microseconds, within CLOCK_STRIDE calls.
        for (before, most) in [(20_000, 10), (3_000, CLOCK_STRIDE as usize)] {
            clock.0.store(10_000_000 - before, Relaxed);
            let mut m = Meter::new(FrameBudget::Deadline(10_000_000), &clock);
            assert!(!m.exhausted(0));
            clock.0.store(10_000_000, Relaxed);
            assert_eq!(calls_until_stopped(&mut m), most, "{before} ns before");
        }
    }

    /// Steps of many sphere tests (a pair in deep overlap) hasten the reads: far from the
    /// deadline the meter reads once the tests done since its last read could have used the time
    /// left, however few the steps; calls without tests keep the step spacing.
    #[test]
    fn long_steps_are_read_by_their_sphere_tests() {
        let clock = Manual(AtomicU64::new(0));
        // 10 ms to go, then steps of 100,000 tests each (about 0.1-0.5 ms at 1-5 ns a test).
        let mut m = Meter::new(FrameBudget::Deadline(10_000_000), &clock);
        assert!(!m.exhausted(0));
        let allowance = 10_000_000 / TEST_NS_BOUND;
        assert_eq!(m.test_allowance, allowance);
        let mut tests = 0;
        let mut calls = 0;
        while tests < allowance {
            tests += 100_000;
            calls += 1;
            assert!(!m.exhausted(tests));
        }
        // Read at the call that reached the allowance, far sooner than MAX_CLOCK_STRIDE steps.
        assert!(calls < MAX_CLOCK_STRIDE as usize);
        assert_eq!(m.tests_at_read, tests);
        // The deadline passes during a long step: noticed at the next call whose tests reach
        // the allowance of the last read (here the next one), not 64 steps later.
        clock.0.store(10_000_000, Relaxed);
        assert!(m.exhausted(tests + m.test_allowance));
        // Without tests (prioritisation), the step spacing alone.
        let mut m = Meter::new(FrameBudget::Deadline(10_000_000), &clock);
        clock.0.store(0, Relaxed);
        assert!(!m.exhausted(0));
        clock.0.store(10_000_000, Relaxed);
        assert_eq!(calls_until_stopped(&mut m), MAX_CLOCK_STRIDE as usize);
    }

    #[test]
    fn deadline_is_noticed_within_the_stride() {
        let clock = Manual(AtomicU64::new(0));
        let mut m = Meter::new(FrameBudget::Deadline(100), &clock);
        assert!(!m.exhausted(0));
        clock.0.store(100, Relaxed);
        assert!(calls_until_stopped(&mut m) <= CLOCK_STRIDE as usize);
    }

    /// A read forced by `exhausted_now` sees a deadline that has passed since the last read, which
    /// the spaced reads would notice only some calls later; a test budget is unaffected.
    #[test]
    fn a_forced_read_sees_the_deadline_at_once() {
        let clock = Manual(AtomicU64::new(0));
        let mut m = Meter::new(FrameBudget::Deadline(10_000_000), &clock);
        assert!(!m.exhausted(0));
        clock.0.store(10_000_000, Relaxed);
        assert!(!m.exhausted(0), "not read yet");
        assert!(m.exhausted_now(0));
        assert!(m.exhausted(0), "and it stays stopped");
        let c = FrozenClock;
        let mut t = Meter::new(FrameBudget::Tests(10), &c);
        assert!(!t.exhausted_now(9));
        assert!(t.exhausted_now(10));
    }

    /// Between whole pairs the reads follow the pairs' measured cost: pairs of 50 us each, with
    /// 1 ms to go, are read often enough that the deadline is passed by less than a pair; cheap
    /// pairs far from the deadline are read every MAX_CLOCK_STRIDE calls; a sphere-test budget
    /// counts tests as before.
    #[test]
    fn reads_between_whole_pairs_follow_their_measured_cost() {
        let clock = Manual(AtomicU64::new(0));
        let deadline = 1_000_000;
        let mut m = Meter::new(FrameBudget::Deadline(deadline), &clock);
        let mut reads = 0;
        let mut now = 0;
        loop {
            let before = m.countdown;
            if m.exhausted_between_pairs(0) {
                break;
            }
            reads += usize::from(before == 0);
            now += 50_000;
            clock.0.store(now, Relaxed);
        }
        assert!(now < deadline + 50_000, "stopped at {now}");
        assert!(reads < 20, "{reads} reads for 20 pairs");
        let mut m = Meter::new(FrameBudget::Deadline(10_000_000), &clock);
        clock.0.store(0, Relaxed);
        let mut reads = 0;
        for k in 0..650u64 {
            let before = m.countdown;
            assert!(!m.exhausted_between_pairs(0));
            reads += usize::from(before == 0);
            clock.0.store(k * 100, Relaxed);
        }
        assert!(reads <= 12, "{reads} reads for 650 cheap pairs");
        let c = FrozenClock;
        let mut t = Meter::new(FrameBudget::Tests(10), &c);
        assert!(!t.exhausted_between_pairs(9));
        assert!(t.exhausted_between_pairs(10));
    }

    /// Calls of `m.exhausted` that say go on before one says stop.
    fn calls_until_stopped(m: &mut Meter<'_>) -> usize {
        let mut calls = 0;
        while !m.exhausted(0) {
            calls += 1;
        }
        calls
    }
}
