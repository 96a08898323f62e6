//! Online fixation detection: I-VT and I-DT (Salvucci & Goldberg 2000), in degrees of visual angle
//! through the [`ViewingGeometry`], one sample at a time.
//!
//! Both detectors are causal: [`Detector::push`] looks only at the samples pushed so far, and what
//! it reports for a sample is never revised by a later one. A fixation is reported as *current*
//! once it is long enough to count, and as *finished* once no later sample can change it (for
//! I-VT, when the merge window after it has passed).
//!
//! Missing samples (validity 0: blinks, track loss) never become part of a fixation; a gap longer
//! than `max_gap_s` ends the fixation at its last valid sample.
//!
//! # Thresholds (defaults and sources)
//! - I-VT velocity threshold 30 deg/s: the Tobii I-VT filter (Olsen 2012) and EyeLink's
//!   "cognitive" parser configuration both use 30 deg/s.
//! - I-VT velocity window 4 ms: velocity is the angle between the current sample and the one
//!   about 4 ms before it, over the time between them, which averages out a 1 kHz tracker's
//!   sample-to-sample noise (EyeLink's own velocity filter spans 5 samples, also about 4 ms).
//!   The fixation's onset is the older end of the window that first falls below the threshold.
//! - Merge adjacent fixations less than 75 ms and 0.5 deg apart, discard fixations shorter than
//!   60 ms: Olsen (2012), the defaults of the Tobii I-VT filter.
//! - I-DT dispersion 1.0 deg (max-min of azimuth plus max-min of elevation) and minimum duration
//!   100 ms: Salvucci & Goldberg (2000), Blignaut (2009).
//! - Largest gap of missing samples inside a fixation: 75 ms (as the merge window: a gap longer
//!   than a short blink ends the fixation).

use std::collections::VecDeque;

use crate::geometry::ViewingGeometry;
use crate::{Eye, GazeSample};

/// One detected fixation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FixationEvent {
    /// The eye of the samples it was detected on.
    pub eye: Eye,
    /// Time of its first sample, seconds (the source's clock).
    pub start_s: f64,
    /// Time of its last sample, seconds.
    pub end_s: f64,
    /// Mean normalised x of its samples.
    pub x: f64,
    /// Mean normalised y of its samples.
    pub y: f64,
    /// Valid samples in it.
    pub samples: u32,
}

impl FixationEvent {
    /// Duration, seconds.
    #[must_use]
    pub fn duration_s(&self) -> f64 {
        self.end_s - self.start_s
    }
}

/// What one sample told the detector.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DetectorOutput {
    /// A fixation completed by this sample: final, no later sample changes it.
    pub finished: Option<FixationEvent>,
    /// The fixation in progress, if the eye is in one that is long enough to count; its end is
    /// the latest sample so far.
    pub current: Option<FixationEvent>,
}

/// I-VT parameters (see the module documentation for the defaults and their sources).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IvtParams {
    /// Samples slower than this are fixation samples, deg/s.
    pub velocity_threshold_deg_s: f64,
    /// Span of the velocity estimate, seconds (0: sample to sample).
    pub velocity_window_s: f64,
    /// Fixations separated by less than this (and [`Self::merge_angle_deg`]) are one, seconds.
    pub merge_gap_s: f64,
    /// Fixations whose centres are closer than this (and [`Self::merge_gap_s`]) are one, deg.
    pub merge_angle_deg: f64,
    /// Shorter fixations are discarded, seconds.
    pub min_duration_s: f64,
    /// A longer run of missing samples ends the fixation, seconds.
    pub max_gap_s: f64,
}

impl Default for IvtParams {
    fn default() -> Self {
        Self {
            velocity_threshold_deg_s: 30.0,
            velocity_window_s: 0.004,
            merge_gap_s: 0.075,
            merge_angle_deg: 0.5,
            min_duration_s: 0.060,
            max_gap_s: 0.075,
        }
    }
}

/// I-DT parameters (see the module documentation for the defaults and their sources).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IdtParams {
    /// Largest dispersion of a fixation: (max - min azimuth) + (max - min elevation), deg.
    pub max_dispersion_deg: f64,
    /// Shortest fixation, seconds.
    pub min_duration_s: f64,
    /// A longer run of missing samples ends the fixation, seconds.
    pub max_gap_s: f64,
}

impl Default for IdtParams {
    fn default() -> Self {
        Self {
            max_dispersion_deg: 1.0,
            min_duration_s: 0.100,
            max_gap_s: 0.075,
        }
    }
}

/// Which detector, with its parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DetectorParams {
    /// Velocity threshold.
    Ivt(IvtParams),
    /// Dispersion threshold.
    Idt(IdtParams),
}

impl Default for DetectorParams {
    fn default() -> Self {
        Self::Ivt(IvtParams::default())
    }
}

impl DetectorParams {
    /// Checks every parameter: finite, thresholds and durations positive (gaps and windows may
    /// be 0).
    ///
    /// # Errors
    /// The name of the first parameter that cannot work.
    pub fn validate(&self) -> Result<(), &'static str> {
        let positive = |v: f64| v.is_finite() && v > 0.0;
        let non_negative = |v: f64| v.is_finite() && v >= 0.0;
        let checks: Vec<(&'static str, bool)> = match self {
            Self::Ivt(p) => vec![
                (
                    "velocity_threshold_deg_s",
                    positive(p.velocity_threshold_deg_s),
                ),
                ("velocity_window_s", non_negative(p.velocity_window_s)),
                ("merge_gap_s", non_negative(p.merge_gap_s)),
                ("merge_angle_deg", non_negative(p.merge_angle_deg)),
                ("min_duration_s", non_negative(p.min_duration_s)),
                ("max_gap_s", non_negative(p.max_gap_s)),
            ],
            Self::Idt(p) => vec![
                ("max_dispersion_deg", positive(p.max_dispersion_deg)),
                ("min_duration_s", positive(p.min_duration_s)),
                ("max_gap_s", non_negative(p.max_gap_s)),
            ],
        };
        match checks.into_iter().find(|(_, ok)| !ok) {
            Some((name, _)) => Err(name),
            None => Ok(()),
        }
    }
}

/// A run of samples being summed into a fixation.
#[derive(Debug, Clone, Copy)]
struct Run {
    eye: Eye,
    start_s: f64,
    end_s: f64,
    sum_x: f64,
    sum_y: f64,
    samples: u32,
}

impl Run {
    fn new(eye: Eye, start_s: f64, s: &GazeSample) -> Self {
        Self {
            eye,
            start_s,
            end_s: s.t_s,
            sum_x: s.x,
            sum_y: s.y,
            samples: 1,
        }
    }

    fn add(&mut self, s: &GazeSample) {
        self.end_s = s.t_s;
        self.sum_x += s.x;
        self.sum_y += s.y;
        self.samples += 1;
    }

    fn merge(&mut self, later: &Run) {
        self.end_s = later.end_s;
        self.sum_x += later.sum_x;
        self.sum_y += later.sum_y;
        self.samples += later.samples;
    }

    fn centre(&self) -> (f64, f64) {
        let n = f64::from(self.samples);
        (self.sum_x / n, self.sum_y / n)
    }

    fn event(&self) -> FixationEvent {
        let (x, y) = self.centre();
        FixationEvent {
            eye: self.eye,
            start_s: self.start_s,
            end_s: self.end_s,
            x,
            y,
            samples: self.samples,
        }
    }

    fn duration_s(&self) -> f64 {
        self.end_s - self.start_s
    }
}

/// The velocity-threshold detector.
#[derive(Debug, Clone)]
pub struct Ivt {
    params: IvtParams,
    geometry: ViewingGeometry,
    /// Recent valid samples (t, x, y), oldest first: the velocity window.
    recent: VecDeque<(f64, f64, f64)>,
    /// The run of slow samples in progress.
    open: Option<Run>,
    /// A finished run that a next run may still merge with.
    pending: Option<Run>,
    last_valid_s: Option<f64>,
}

impl Ivt {
    /// A detector with `params` (assumed valid) over `geometry`.
    #[must_use]
    pub fn new(params: IvtParams, geometry: ViewingGeometry) -> Self {
        Self {
            params,
            geometry,
            recent: VecDeque::with_capacity(16),
            open: None,
            pending: None,
            last_valid_s: None,
        }
    }

    /// Finalises the pending run: it is a fixation if long enough.
    fn release_pending(&mut self) -> Option<FixationEvent> {
        let run = self.pending.take()?;
        (run.duration_s() >= self.params.min_duration_s).then(|| run.event())
    }

    /// Closes the open run: it becomes pending (and any older pending one is released).
    fn close_open(&mut self) -> Option<FixationEvent> {
        let run = self.open.take()?;
        let released = self.release_pending();
        self.pending = Some(run);
        released
    }

    fn push(&mut self, s: &GazeSample) -> DetectorOutput {
        let mut finished = None;
        let mut keep = |event: Option<FixationEvent>| {
            if event.is_some() {
                finished = event;
            }
        };
        // The merge window of a pending run has passed: nothing can change it any more.
        if self
            .pending
            .is_some_and(|p| s.t_s - p.end_s > self.params.merge_gap_s)
        {
            keep(self.release_pending());
        }
        let in_order = self.last_valid_s.is_none_or(|t| s.t_s >= t);
        if !s.is_valid() || !s.t_s.is_finite() || !in_order {
            if self
                .last_valid_s
                .is_some_and(|t| s.t_s - t > self.params.max_gap_s)
            {
                keep(self.close_open());
                self.recent.clear();
            }
            return DetectorOutput {
                finished,
                current: self.current(),
            };
        }
        if self
            .last_valid_s
            .is_some_and(|t| s.t_s - t > self.params.max_gap_s)
        {
            // Back from a long gap: the eye may be anywhere; start afresh.
            keep(self.close_open());
            self.recent.clear();
        }
        self.last_valid_s = Some(s.t_s);
        self.recent.push_back((s.t_s, s.x, s.y));
        while self.recent.len() > 2
            && self
                .recent
                .get(1)
                .is_some_and(|&(t, _, _)| s.t_s - t >= self.params.velocity_window_s)
        {
            self.recent.pop_front();
        }
        let slow = match self.recent.front() {
            Some(&(t0, x0, y0)) if self.recent.len() > 1 && s.t_s > t0 => {
                let angle = self.geometry.angle_between((x0, y0), (s.x, s.y));
                angle / (s.t_s - t0) < self.params.velocity_threshold_deg_s
            }
            // The first sample after a gap: no velocity yet; a fixation may start here.
            _ => true,
        };
        if slow {
            match &mut self.open {
                Some(run) => run.add(s),
                None => {
                    let start = self.recent.front().map_or(s.t_s, |&(t, _, _)| t);
                    let mut run = Run::new(s.eye, start, s);
                    // Merge with the pending run if it is close in time and place.
                    if let Some(p) = self.pending {
                        let (a, b) = (p.centre(), (s.x, s.y));
                        if start - p.end_s <= self.params.merge_gap_s
                            && self.geometry.angle_between(a, b) <= self.params.merge_angle_deg
                        {
                            let mut merged = p;
                            merged.merge(&run);
                            run = merged;
                            self.pending = None;
                        }
                    }
                    self.open = Some(run);
                }
            }
        } else {
            keep(self.close_open());
        }
        DetectorOutput {
            finished,
            current: self.current(),
        }
    }

    fn current(&self) -> Option<FixationEvent> {
        self.open
            .filter(|r| r.duration_s() >= self.params.min_duration_s)
            .map(|r| r.event())
    }

    fn finish(&mut self) -> Vec<FixationEvent> {
        let mut out = Vec::new();
        if let Some(e) = self.close_open() {
            out.push(e);
        }
        out.extend(self.release_pending());
        out
    }
}

/// A valid sample in the I-DT window: time, position, direction in degrees.
#[derive(Debug, Clone, Copy)]
struct Point {
    t: f64,
    x: f64,
    y: f64,
    az: f64,
    el: f64,
}

/// The dispersion-threshold detector.
#[derive(Debug, Clone)]
pub struct Idt {
    params: IdtParams,
    geometry: ViewingGeometry,
    eye: Eye,
    window: VecDeque<Point>,
    /// Sum of the window's x and y (so a long fixation's centre costs O(1) per sample).
    sum: (f64, f64),
    /// min az, max az, min el, max el of the window.
    bounds: [f64; 4],
    last_valid_s: Option<f64>,
}

impl Idt {
    /// A detector with `params` (assumed valid) over `geometry`.
    #[must_use]
    pub fn new(params: IdtParams, geometry: ViewingGeometry) -> Self {
        Self {
            params,
            geometry,
            eye: Eye::Unspecified,
            window: VecDeque::with_capacity(256),
            sum: (0.0, 0.0),
            bounds: [0.0; 4],
            last_valid_s: None,
        }
    }

    fn push_point(&mut self, p: Point) {
        self.sum.0 += p.x;
        self.sum.1 += p.y;
        self.window.push_back(p);
    }

    fn pop_point(&mut self) {
        if let Some(p) = self.window.pop_front() {
            self.sum.0 -= p.x;
            self.sum.1 -= p.y;
        }
    }

    fn clear_window(&mut self) {
        self.window.clear();
        self.sum = (0.0, 0.0);
    }

    fn dispersion(b: &[f64; 4]) -> f64 {
        (b[1] - b[0]) + (b[3] - b[2])
    }

    fn recompute_bounds(&mut self) {
        let mut b = [
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        for p in &self.window {
            b = [
                b[0].min(p.az),
                b[1].max(p.az),
                b[2].min(p.el),
                b[3].max(p.el),
            ];
        }
        self.bounds = b;
    }

    fn window_duration(&self) -> f64 {
        match (self.window.front(), self.window.back()) {
            (Some(a), Some(b)) => b.t - a.t,
            _ => 0.0,
        }
    }

    fn window_event(&self) -> Option<FixationEvent> {
        let first = self.window.front()?;
        let last = self.window.back()?;
        let n = self.window.len();
        let (sx, sy) = self.sum;
        #[allow(clippy::cast_precision_loss)]
        let nf = n as f64;
        Some(FixationEvent {
            eye: self.eye,
            start_s: first.t,
            end_s: last.t,
            x: sx / nf,
            y: sy / nf,
            samples: u32::try_from(n).unwrap_or(u32::MAX),
        })
    }

    fn in_fixation(&self) -> bool {
        !self.window.is_empty() && self.window_duration() >= self.params.min_duration_s
    }

    fn end_window(&mut self) -> Option<FixationEvent> {
        let event = if self.in_fixation() {
            self.window_event()
        } else {
            None
        };
        self.clear_window();
        event
    }

    fn push(&mut self, s: &GazeSample) -> DetectorOutput {
        let mut finished = None;
        let in_order = self.last_valid_s.is_none_or(|t| s.t_s >= t);
        if !s.is_valid() || !s.t_s.is_finite() || !in_order {
            if self
                .last_valid_s
                .is_some_and(|t| s.t_s - t > self.params.max_gap_s)
            {
                finished = self.end_window();
            }
            return DetectorOutput {
                finished,
                current: self.current(),
            };
        }
        if self
            .last_valid_s
            .is_some_and(|t| s.t_s - t > self.params.max_gap_s)
        {
            finished = self.end_window();
        }
        self.last_valid_s = Some(s.t_s);
        self.eye = s.eye;
        let (az, el) = self.geometry.degrees(s.x, s.y);
        let p = Point {
            t: s.t_s,
            x: s.x,
            y: s.y,
            az,
            el,
        };
        let b = self.bounds;
        let grown = if self.window.is_empty() {
            [az, az, el, el]
        } else {
            [b[0].min(az), b[1].max(az), b[2].min(el), b[3].max(el)]
        };
        if Self::dispersion(&grown) <= self.params.max_dispersion_deg {
            self.push_point(p);
            self.bounds = grown;
        } else if self.in_fixation() {
            // The fixation ends before this sample; the sample starts a new window.
            finished = self.window_event();
            self.clear_window();
            self.push_point(p);
            self.bounds = [az, az, el, el];
        } else {
            // Not a fixation yet: slide the window's start until it fits.
            self.push_point(p);
            while self.window.len() > 1 {
                self.pop_point();
                self.recompute_bounds();
                if Self::dispersion(&self.bounds) <= self.params.max_dispersion_deg {
                    break;
                }
            }
            if self.window.len() == 1 {
                self.bounds = [az, az, el, el];
                self.sum = (s.x, s.y);
            }
        }
        DetectorOutput {
            finished,
            current: self.current(),
        }
    }

    fn current(&self) -> Option<FixationEvent> {
        if self.in_fixation() {
            self.window_event()
        } else {
            None
        }
    }

    fn finish(&mut self) -> Vec<FixationEvent> {
        self.end_window().into_iter().collect()
    }
}

/// A fixation detector of either kind.
#[derive(Debug, Clone)]
pub enum Detector {
    /// Velocity threshold.
    Ivt(Ivt),
    /// Dispersion threshold.
    Idt(Idt),
}

impl Detector {
    /// A detector for `params` (assumed valid: see [`DetectorParams::validate`]) over `geometry`.
    #[must_use]
    pub fn new(params: DetectorParams, geometry: ViewingGeometry) -> Self {
        match params {
            DetectorParams::Ivt(p) => Self::Ivt(Ivt::new(p, geometry)),
            DetectorParams::Idt(p) => Self::Idt(Idt::new(p, geometry)),
        }
    }

    /// Takes the next sample (times non-decreasing; earlier ones are treated as missing).
    pub fn push(&mut self, s: &GazeSample) -> DetectorOutput {
        match self {
            Self::Ivt(d) => d.push(s),
            Self::Idt(d) => d.push(s),
        }
    }

    /// The end of the input: the fixations still open, in order.
    pub fn finish(&mut self) -> Vec<FixationEvent> {
        match self {
            Self::Ivt(d) => d.finish(),
            Self::Idt(d) => d.finish(),
        }
    }
}

/// Runs a detector over a whole recording: every fixation, in order.
pub fn detect_all<'a>(
    params: DetectorParams,
    geometry: ViewingGeometry,
    samples: impl IntoIterator<Item = &'a GazeSample>,
) -> Vec<FixationEvent> {
    let mut detector = Detector::new(params, geometry);
    let mut out: Vec<FixationEvent> = samples
        .into_iter()
        .filter_map(|s| detector.push(s).finished)
        .collect();
    out.extend(detector.finish());
    out
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::agreement::{Interval, compare};
    use crate::viewer::Viewer;

    fn viewer_samples(seed: u64, rate_hz: f64, duration_s: f64) -> Vec<GazeSample> {
        let mut v = Viewer::new(seed);
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let n = (duration_s * rate_hz) as u32;
        (0..n)
            .map(|i| {
                let t = f64::from(i) / rate_hz;
                let g = v.at(t);
                GazeSample::valid(t, g.x, g.y, Eye::Left)
            })
            .collect()
    }

    fn intervals(events: &[FixationEvent]) -> Vec<Interval> {
        events
            .iter()
            .map(|e| Interval {
                start_s: e.start_s,
                end_s: e.end_s,
            })
            .collect()
    }

    #[test]
    fn both_detectors_find_the_scripted_viewers_fixations() {
        let mut v = Viewer::new(5);
        let truth: Vec<Interval> = v
            .fixations(20.0)
            .iter()
            .map(|&(start_s, end_s, _, _)| Interval { start_s, end_s })
            .collect();
        let samples = viewer_samples(5, 1000.0, 20.0);
        let g = ViewingGeometry::default();
        for params in [
            DetectorParams::Ivt(IvtParams::default()),
            DetectorParams::Idt(IdtParams::default()),
        ] {
            let found = detect_all(params, g, &samples);
            // The last, cut-off fixation is not in the truth.
            let found: Vec<_> = found
                .into_iter()
                .filter(|e| e.end_s < truth[truth.len() - 1].end_s + 1e-9)
                .collect();
            let a = compare(&intervals(&found), &truth);
            // A saccade between two close targets can stay below 30 deg/s (the viewer's saccades
            // last at least 20 ms whatever their size); one such pair in 66 is merged.
            assert!(a.precision == 1.0 && a.f1 >= 0.98, "{params:?}: {a:?}");
            assert!(a.onset.p90_abs_s <= 0.006, "{params:?}: {a:?}");
            assert!(a.offset.p90_abs_s <= 0.006, "{params:?}: {a:?}");
            for e in &found {
                assert!(e.samples > 0 && e.x.is_finite() && e.eye == Eye::Left);
            }
        }
    }

    #[test]
    fn a_blink_longer_than_the_gap_limit_splits_a_fixation_a_short_one_does_not() {
        let fixation_with_gap = |gap_ms: u32| -> Vec<GazeSample> {
            (0..600)
                .map(|i| {
                    let t = f64::from(i) * 0.001;
                    if (200..200 + gap_ms).contains(&i) {
                        GazeSample::missing(t, Eye::Left)
                    } else {
                        GazeSample::valid(t, 0.5, 0.5, Eye::Left)
                    }
                })
                .collect()
        };
        for params in [
            DetectorParams::Ivt(IvtParams::default()),
            DetectorParams::Idt(IdtParams::default()),
        ] {
            let g = ViewingGeometry::default();
            let short = detect_all(params, g, &fixation_with_gap(50));
            assert_eq!(short.len(), 1, "{params:?}: {short:?}");
            assert_eq!((short[0].start_s, short[0].end_s), (0.0, 0.599));
            assert_eq!(short[0].samples, 550);
            let long = detect_all(params, g, &fixation_with_gap(150));
            assert_eq!(long.len(), 2, "{params:?}: {long:?}");
            assert_eq!(long[0].end_s, 0.199);
            assert_eq!(long[1].start_s, f64::from(350) * 0.001);
        }
    }

    #[test]
    fn current_fixation_is_reported_once_long_enough() {
        let mut d = Detector::new(DetectorParams::default(), ViewingGeometry::default());
        let mut first_current = None;
        for i in 0..200 {
            let t = f64::from(i) * 0.001;
            let out = d.push(&GazeSample::valid(t, 0.25, 0.75, Eye::Right));
            assert_eq!(out.finished, None);
            if let (None, Some(c)) = (first_current, out.current) {
                first_current = Some((t, c));
            }
        }
        let (t, c) = first_current.expect("a fixation");
        assert_eq!(t, 0.06, "current once 60 ms long");
        assert_eq!((c.x, c.y, c.start_s, c.eye), (0.25, 0.75, 0.0, Eye::Right));
        let bad = DetectorParams::Ivt(IvtParams {
            velocity_threshold_deg_s: 0.0,
            ..IvtParams::default()
        });
        assert_eq!(bad.validate(), Err("velocity_threshold_deg_s"));
        assert!(DetectorParams::default().validate().is_ok());
    }

    fn arb_samples() -> impl Strategy<Value = Vec<GazeSample>> {
        proptest::collection::vec(
            (
                0.0f64..0.05,
                prop_oneof![3 => (-1.0f64..2.0, -1.0f64..2.0).prop_map(Some), 1 => Just(None)],
            ),
            1..300,
        )
        .prop_map(|steps| {
            let mut t = 0.0;
            steps
                .into_iter()
                .map(|(dt, p)| {
                    t += dt;
                    match p {
                        Some((x, y)) => GazeSample::valid(t, x, y, Eye::Left),
                        None => GazeSample::missing(t, Eye::Left),
                    }
                })
                .collect()
        })
    }

    proptest! {
        /// No NaN out, events in order and inside the input's time span, and causal: the outputs
        /// for a prefix of the input are the prefix of the outputs for the whole.
        #[test]
        fn finite_ordered_and_causal(samples in arb_samples(), cut in 0usize..300, idt in any::<bool>()) {
            let params = if idt {
                DetectorParams::Idt(IdtParams::default())
            } else {
                DetectorParams::Ivt(IvtParams::default())
            };
            let run = |n: usize| {
                let mut d = Detector::new(params, ViewingGeometry::default());
                samples[..n].iter().map(|s| d.push(s)).collect::<Vec<_>>()
            };
            let full = run(samples.len());
            let k = cut.min(samples.len());
            prop_assert_eq!(&run(k)[..], &full[..k]);
            let mut last_end = f64::NEG_INFINITY;
            let t_max = samples[samples.len() - 1].t_s;
            for out in &full {
                for e in out.finished.iter().chain(out.current.iter()) {
                    prop_assert!(e.x.is_finite() && e.y.is_finite());
                    prop_assert!(e.start_s <= e.end_s && e.end_s <= t_max);
                }
                if let Some(e) = out.finished {
                    prop_assert!(e.start_s > last_end, "{:?} after {}", e, last_end);
                    last_end = e.end_s;
                }
            }
        }
    }
}
