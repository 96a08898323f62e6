//! The loop's once-per-interval summary: one log line (fps, T p50/p99, Δ, P, pairs, subscribers,
//! gaze rate) and the rates GetStatus reports.

use std::time::{Duration, Instant};

use foveal_engine::FrameReport;

use crate::metrics::Metrics;

/// Accumulates one window of frames.
#[derive(Debug)]
pub struct Summary {
    interval: Duration,
    window_start: Instant,
    collision_ns: Vec<u64>,
    step_ns: Vec<u64>,
    delta_sum: f64,
    p_sum: f64,
    pairs_sum: u64,
    deemed_sum: u64,
    real_sum: u64,
    /// Pairs and deemed pairs within 5 degrees of the fixation (near) and beyond it (far).
    near: (u64, u64),
    far: (u64, u64),
    /// Of the audited frames (their own audit, or the side by side's paired one): pairs and
    /// deemed pairs truly apart (wrong guesses), within 5 degrees of the fixation and beyond.
    apart_near: (u64, u64),
    apart_far: (u64, u64),
    /// The last frame recorded, for its side by side's paired audit when it had none of its own.
    last_pairs: Option<(u32, u32)>,
    /// True P of the frames with an audit, and their count.
    true_p: (f64, u64),
    /// The side by side's second collider: its time per frame (ns) and its true P.
    compare_ns: Vec<u64>,
    compare_true_p: f64,
    paired_main_true_p: f64,
    /// Integration and broad-phase time of the frames whose wall-clock budget they spent.
    starved_fixed_ns: Vec<u64>,
    overruns_at_start: u64,
    gaze_at_start: u64,
}

/// The `q`-quantile (0..=1) of sorted values by nearest rank, the one definition of every figure
/// foveal prints ([`foveal_gaze::quantile`]); 0 for none.
pub fn quantile(sorted: &[u64], q: f64) -> u64 {
    foveal_gaze::quantile::nearest_rank(sorted, q).unwrap_or(0)
}

fn ms(ns: u64) -> f64 {
    ns as f64 * 1e-6
}

impl Summary {
    /// A window starting at `now`.
    pub fn new(interval: Duration, now: Instant, metrics: &Metrics) -> Self {
        Self {
            interval,
            window_start: now,
            collision_ns: Vec::new(),
            step_ns: Vec::new(),
            delta_sum: 0.0,
            p_sum: 0.0,
            pairs_sum: 0,
            deemed_sum: 0,
            real_sum: 0,
            near: (0, 0),
            far: (0, 0),
            apart_near: (0, 0),
            apart_far: (0, 0),
            last_pairs: None,
            true_p: (0.0, 0),
            compare_ns: Vec::new(),
            compare_true_p: 0.0,
            paired_main_true_p: 0.0,
            starved_fixed_ns: Vec::new(),
            overruns_at_start: metrics.overruns(),
            gaze_at_start: metrics.gaze_accepted(),
        }
    }

    /// Add a frame and the wall time its step took.
    pub fn record(&mut self, r: &FrameReport, step: Duration) {
        self.collision_ns.push(r.profile.collision_ns());
        self.step_ns
            .push(u64::try_from(step.as_nanos()).unwrap_or(u64::MAX));
        self.delta_sum += r.geometric_inaccuracy;
        self.p_sum += r.perceived_inaccuracy.unwrap_or(0.0);
        self.pairs_sum += u64::from(r.candidate_pairs);
        self.deemed_sum += u64::from(r.deemed);
        self.real_sum += u64::from(r.real_collisions);
        self.near.0 += u64::from(r.foveal_pairs);
        self.near.1 += u64::from(r.foveal_deemed);
        self.far.0 += u64::from(r.candidate_pairs.saturating_sub(r.foveal_pairs));
        self.far.1 += u64::from(r.deemed.saturating_sub(r.foveal_deemed));
        if let Some(p) = r.audit.and_then(|a| a.perceived_inaccuracy) {
            self.true_p.0 += p;
            self.true_p.1 += 1;
        }
        let pairs = (
            r.foveal_pairs,
            r.candidate_pairs.saturating_sub(r.foveal_pairs),
        );
        self.last_pairs = Some(pairs);
        if let Some(a) = &r.audit {
            self.record_apart(pairs, a);
            self.last_pairs = None;
        }
        if r.budget_spent_before_narrow {
            let p = &r.profile;
            self.starved_fixed_ns
                .push(p.renumber_ns + p.integrate_ns + p.broad_ns);
        }
    }

    /// Add the side by side's run on the frame just recorded: the wall time it took (ns) and both
    /// sides' true P (on the same pairs; the frame's own counts as its true P when the frame has
    /// no audit of its own).
    pub fn record_comparison(&mut self, audit: &crate::compare::PairedAudit, run_ns: u64) {
        self.compare_ns.push(run_ns);
        self.compare_true_p += audit.blind.perceived_inaccuracy.unwrap_or(0.0);
        self.paired_main_true_p += audit.main.perceived_inaccuracy.unwrap_or(0.0);
        if let Some(pairs) = self.last_pairs.take() {
            self.record_apart(pairs, &audit.main);
        }
    }

    /// Add an audited frame's wrong guesses near the fixation and beyond it (`pairs`: its
    /// candidate pairs near and far).
    fn record_apart(&mut self, (near, far): (u32, u32), a: &foveal_engine::AuditReport) {
        let foveal = a.foveal_false_positives.min(a.false_positives);
        self.apart_near.0 += u64::from(near);
        self.apart_near.1 += u64::from(foveal);
        self.apart_far.0 += u64::from(far);
        self.apart_far.1 += u64::from(a.false_positives - foveal);
    }

    /// If the window is over at `now`, log it, publish its rates and start the next one.
    pub fn flush_if_due(&mut self, now: Instant, metrics: &Metrics, subscribers: u32) {
        let elapsed = now.saturating_duration_since(self.window_start);
        if elapsed < self.interval {
            return;
        }
        let secs = elapsed.as_secs_f64();
        let frames = self.collision_ns.len();
        let fps = frames as f64 / secs;
        let gaze = metrics.gaze_accepted();
        let gaze_rate = gaze.saturating_sub(self.gaze_at_start) as f64 / secs;
        metrics.set_gaze_rate(gaze_rate);
        self.collision_ns.sort_unstable();
        self.step_ns.sort_unstable();
        self.compare_ns.sort_unstable();
        let share = |(pairs, deemed): (u64, u64)| {
            if pairs == 0 {
                0.0
            } else {
                deemed as f64 / pairs as f64
            }
        };
        let true_p = if !self.compare_ns.is_empty() {
            self.paired_main_true_p / self.compare_ns.len() as f64
        } else if self.true_p.1 == 0 {
            f64::NAN
        } else {
            self.true_p.0 / self.true_p.1 as f64
        };
        let compare_true_p = if self.compare_ns.is_empty() {
            f64::NAN
        } else {
            self.compare_true_p / self.compare_ns.len() as f64
        };
        let per_frame = |v: f64| if frames == 0 { 0.0 } else { v / frames as f64 };
        tracing::info!(
            target: "foveal::summary",
            fps = format_args!("{fps:.1}"),
            t_p50_ms = format_args!("{:.3}", ms(quantile(&self.collision_ns, 0.5))),
            t_p99_ms = format_args!("{:.3}", ms(quantile(&self.collision_ns, 0.99))),
            step_p99_ms = format_args!("{:.3}", ms(quantile(&self.step_ns, 0.99))),
            delta = format_args!("{:.4}", per_frame(self.delta_sum)),
            p = format_args!("{:.4}", per_frame(self.p_sum)),
            pairs = format_args!("{:.0}", per_frame(self.pairs_sum as f64)),
            deemed = format_args!("{:.0}", per_frame(self.deemed_sum as f64)),
            real = format_args!("{:.1}", per_frame(self.real_sum as f64)),
            deemed_near = format_args!("{:.3}", share(self.near)),
            deemed_far = format_args!("{:.3}", share(self.far)),
            apart_near = format_args!("{:.4}", share(self.apart_near)),
            apart_far = format_args!("{:.4}", share(self.apart_far)),
            true_p = format_args!("{true_p:.4}"),
            compare_p50_ms = format_args!("{:.3}", ms(quantile(&self.compare_ns, 0.5))),
            compare_p99_ms = format_args!("{:.3}", ms(quantile(&self.compare_ns, 0.99))),
            compare_true_p = format_args!("{compare_true_p:.4}"),
            overruns = metrics.overruns().saturating_sub(self.overruns_at_start),
            subscribers,
            gaze_hz = format_args!("{gaze_rate:.0}"),
            "frames"
        );
        if let Some(warning) = self.starved_warning(frames) {
            tracing::warn!(target: "foveal::summary", "{warning}");
        }
        *self = Self::new(self.interval, now, metrics);
    }

    /// What to tell the operator when, in at least half the window's frames, the wall-clock
    /// budget was spent before the narrow phase: a budget that silently deems every pair is a
    /// configuration error, not a trade-off.
    fn starved_warning(&mut self, frames: usize) -> Option<String> {
        let starved = self.starved_fixed_ns.len();
        if frames == 0 || 2 * starved < frames {
            return None;
        }
        self.starved_fixed_ns.sort_unstable();
        let fixed = ms(quantile(&self.starved_fixed_ns, 0.5));
        Some(format!(
            "the wall-clock budget was spent before the narrow phase in {starved} of {frames} \
             frames: integration and the broad phase alone take {fixed:.3} ms (median) at this \
             body count, so every pair was deemed colliding; raise --budget well above \
             {fixed:.3} ms, lower --bodies, or use a sphere-test budget (e.g. 20000tests)"
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantiles_by_nearest_rank() {
        let v: Vec<u64> = (1..=100).collect();
        assert_eq!(quantile(&v, 0.5), 50);
        assert_eq!(quantile(&v, 0.99), 99);
        assert_eq!(quantile(&v, 1.0), 100);
        assert_eq!(quantile(&[], 0.5), 0);
    }

    /// A window in which the budget was spent before the narrow phase in most frames says so,
    /// with the fixed work's median; a window where it happened in a minority of frames does not.
    #[test]
    fn a_budget_spent_before_the_narrow_phase_is_reported() {
        let m = Metrics::default();
        let t0 = Instant::now();
        let mut s = Summary::new(Duration::from_secs(1), t0, &m);
        let starved = FrameReport {
            budget_spent_before_narrow: true,
            profile: foveal_engine::PhaseProfile {
                integrate_ns: 300_000,
                broad_ns: 1_200_000,
                ..Default::default()
            },
            ..FrameReport::default()
        };
        for k in 0..10 {
            let r = if k < 6 {
                &starved
            } else {
                &FrameReport::default()
            };
            s.record(r, Duration::from_millis(2));
        }
        let warning = s.starved_warning(10).expect("6 of 10 frames starved");
        assert!(warning.contains("6 of 10 frames"), "{warning}");
        assert!(warning.contains("1.500 ms"), "{warning}");
        assert!(warning.contains("--budget"), "{warning}");
        let mut s = Summary::new(Duration::from_secs(1), t0, &m);
        for k in 0..10 {
            let r = if k < 4 {
                &starved
            } else {
                &FrameReport::default()
            };
            s.record(r, Duration::from_millis(2));
        }
        assert_eq!(s.starved_warning(10), None);
    }

    #[test]
    fn flush_publishes_rates_and_resets() {
        let m = Metrics::default();
        let t0 = Instant::now();
        let mut s = Summary::new(Duration::from_secs(1), t0, &m);
        for _ in 0..30 {
            s.record(&FrameReport::default(), Duration::from_millis(1));
        }
        m.gaze(120, 0);
        s.flush_if_due(t0 + Duration::from_millis(500), &m, 0);
        assert_eq!(m.gaze_rate_hz(), 0.0, "not due yet");
        s.flush_if_due(t0 + Duration::from_secs(1), &m, 3);
        assert!((m.gaze_rate_hz() - 120.0).abs() < 1e-9);
        assert!(s.collision_ns.is_empty());
    }
}
