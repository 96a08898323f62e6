//! The guard band of a wall-clock frame budget: how much earlier than its budget a frame aims to
//! end, learnt from how late the recent frames ended against what they aimed for.
//!
//! Why: the frame's own estimates (the learnt tail, the pool's hand-back, the meter's reads) keep
//! a frame on time when the machine runs at its usual pace, but a shared machine stalls a thread
//! now and then for one to five milliseconds (at 100,000 bodies on two threads, a pair of about
//! a hundred sphere tests took 1-4 ms in 10 of 660 frames: no work of the engine's, the thread
//! was not running). Such a frame ends late by the stall, and with two threads a stall of either
//! delays the frame at its next join. No estimate of the frame's work foresees that; a margin
//! sized on the machine's recent stalls absorbs them. The margin is the [`GUARD_RANK`]-th
//! greatest lateness of the last [`GUARD_WINDOW`] frames, so one or two frames in a hundred end
//! after their budget at all while the stalls keep their rate and size; it is 0 while fewer
//! frames than that end late, and never above [`GUARD_MAX_SHARE`] of the budget (a budget the
//! fixed per-frame work cannot meet ends every frame late, and there a margin saves nothing).
//!
//! Lateness is measured against the end the frame aimed for (its budget less the margin it
//! had), not against the budget: a margin then does not lower the lateness it learns from, and
//! it settles where the stalls put it instead of ratcheting.
//!
//! Two kinds of frame are late by their own work, not by a stall, and are not learnt from (the
//! simulation leaves them out): those of the first [`GUARD_SETTLE_S`] of simulated time, and
//! those whose integration and broad phase spent the whole budget. In the first second the
//! scene's random placement leaves deep overlaps that cost 2-4x the steady state, buffers grow to
//! the scene's size and the frame's tail is still being learnt: taken in, two such frames held
//! the margin at its cap for the next 40 frames after the scale bench's 60 warm-up frames (0.5-1.2
//! ms of 16 at 100,000 bodies). A frame whose fixed work spends the budget is late whatever the
//! margin, and a margin would only deem more pairs, lengthening its tail (the response walks
//! every deemed pair), so that it never fell again.

/// Frames whose lateness sets the margin: about two seconds at 50 frames a second.
pub const GUARD_WINDOW: usize = 100;

/// Which lateness of the window is the margin, counted from the greatest: the second, so that a
/// single stall in the window does not move it.
pub const GUARD_RANK: usize = 2;

/// Most of the budget the margin may take from the frame's work.
pub const GUARD_MAX_SHARE: f64 = 0.1;

/// Simulated time (s) before which frames are not learnt from: the settling of a random scene,
/// as `SimConfig::calibration_warmup` (60 frames of 1/60 s) allows for.
pub const GUARD_SETTLE_S: f64 = 1.0;

/// The margin and the lateness it is learnt from.
#[derive(Debug, Clone, Default)]
pub struct Guard {
    /// The last [`GUARD_WINDOW`] frames' lateness (ns, negative for early), oldest overwritten.
    late: Vec<i64>,
    next: usize,
    margin_ns: u64,
}

impl Guard {
    /// How much earlier than its budget the next frame aims to end (ns).
    pub fn margin_ns(&self) -> u64 {
        self.margin_ns
    }

    /// After a frame with a budget of `budget_ns` that took `elapsed_ns`, aiming to end
    /// `margin_ns` early (the margin it was given).
    pub fn learn(&mut self, budget_ns: u64, margin_ns: u64, elapsed_ns: u64) {
        let aimed = budget_ns.saturating_sub(margin_ns);
        let late = i64::try_from(elapsed_ns)
            .unwrap_or(i64::MAX)
            .saturating_sub(i64::try_from(aimed).unwrap_or(i64::MAX));
        if self.late.len() < GUARD_WINDOW {
            self.late.push(late);
        } else {
            self.late[self.next] = late;
        }
        self.next = (self.next + 1) % GUARD_WINDOW;
        let mut top = [i64::MIN; GUARD_RANK];
        for &x in &self.late {
            if x > top[GUARD_RANK - 1] {
                top[GUARD_RANK - 1] = x;
                top.sort_unstable_by(|a, b| b.cmp(a));
            }
        }
        let cap = (GUARD_MAX_SHARE * budget_ns as f64) as u64;
        let rank = top[GUARD_RANK - 1];
        self.margin_ns = if rank <= 0 { 0 } else { (rank as u64).min(cap) };
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const BUDGET: u64 = 16_000_000;

    /// Frames that end on time or early need no margin; one late frame in the window does not
    /// make one; two do, sized by the lesser of the two; it is forgotten once they leave the
    /// window, and it never exceeds its share of the budget.
    #[test]
    fn the_margin_is_the_second_latest_frame_of_the_window() {
        let mut g = Guard::default();
        for _ in 0..GUARD_WINDOW {
            g.learn(BUDGET, g.margin_ns(), BUDGET - 500_000);
        }
        assert_eq!(g.margin_ns(), 0);
        g.learn(BUDGET, 0, BUDGET + 3_000_000);
        assert_eq!(g.margin_ns(), 0, "one stall alone");
        g.learn(BUDGET, 0, BUDGET + 1_000_000);
        assert_eq!(g.margin_ns(), 1_000_000);
        for _ in 0..GUARD_WINDOW - 2 {
            let m = g.margin_ns();
            g.learn(BUDGET, m, BUDGET - m);
        }
        assert_eq!(g.margin_ns(), 1_000_000, "both still in the window");
        g.learn(BUDGET, g.margin_ns(), BUDGET - g.margin_ns());
        assert_eq!(g.margin_ns(), 0, "the stalls have left the window");
        for _ in 0..2 {
            g.learn(BUDGET, 0, BUDGET + 50_000_000);
        }
        assert_eq!(g.margin_ns(), BUDGET / 10, "capped");
    }

    /// A machine whose frames end late by the same spread of stalls whatever the margin: the
    /// margin settles at the second-greatest stall and stays there (lateness is measured against
    /// the aimed end, so the margin does not feed back on itself), and with it at most one frame
    /// of the window ends after its budget.
    #[test]
    fn under_stationary_stalls_the_margin_settles_and_holds_the_budget() {
        let mut g = Guard::default();
        let stall = |frame: u64| match frame % 100 {
            7 => 2_500_000,
            31 => 1_200_000,
            70 => 800_000,
            _ => 0,
        };
        let mut over = Vec::new();
        for frame in 0..1_000 {
            let m = g.margin_ns();
            let elapsed = BUDGET - m - 300_000 + stall(frame);
            if frame >= 200 {
                assert_eq!(m, 900_000, "frame {frame}");
                over.push(elapsed > BUDGET);
            }
            g.learn(BUDGET, m, elapsed);
        }
        let late = over.iter().filter(|o| **o).count();
        assert_eq!(late, over.len() / 100, "only the greatest stall ends late");
    }
}
