//! Watching frames: a one-line summary per second for a terminal, and every frame's metrics as
//! CSV for analysis.
//!
//! The summary is computed over the frames received in the last interval: the frame rate from
//! the span of frame indices (so it is the server's rate even with `every_k` > 1), T as
//! percentiles (a mean would hide the budget overruns that matter), Δ, P, pairs and deemed as
//! means per frame, and dropped frames as a sum (a slow terminal or network shows up there).
//!
//! The CSV has one row per received frame, header first; the column names are stable so that
//! plotting scripts can rely on them ([`CSV_HEADER`]; new ones are added at the end). Audit
//! columns are empty when the server has audit off, so "no audit" is not confused with "zero
//! false positives".

use std::fmt::Write as _;
use std::future::Future;
use std::io::Write;
use std::time::Duration;

use foveal_proto::pb;
use tokio::time::Instant;

use crate::ClientError;

/// Columns of the frame CSV, in order.
pub const CSV_COLUMNS: [&str; 32] = [
    "index",
    "sim_time_s",
    "fixation_x",
    "fixation_y",
    "fixation_age_s",
    "fixation_source",
    "collision_time_s",
    "delta",
    "p",
    "candidate_pairs",
    "real_collisions",
    "deemed",
    "sphere_tests",
    "dropped_before",
    "true_false_positives",
    "true_delta",
    "true_p",
    "budget_exhausted",
    "integrate_s",
    "broad_s",
    "narrow_s",
    "response_s",
    "bodies",
    "resolved_per_level",
    "received_at_s",
    "metrics_stride",
    "delta_se",
    "p_se",
    "budget_spent_before_narrow",
    "foveal_pairs",
    "foveal_deemed",
    "true_foveal_false_positives",
];

/// The header line of the frame CSV (no terminator).
pub const CSV_HEADER: &str = "index,sim_time_s,fixation_x,fixation_y,fixation_age_s,\
fixation_source,collision_time_s,delta,p,candidate_pairs,real_collisions,deemed,sphere_tests,\
dropped_before,true_false_positives,true_delta,true_p,budget_exhausted,integrate_s,broad_s,\
narrow_s,response_s,bodies,resolved_per_level,received_at_s,metrics_stride,delta_se,p_se,\
budget_spent_before_narrow,foveal_pairs,foveal_deemed,true_foveal_false_positives";

/// Short name of a fixation source, as written in the CSV and the summary.
#[must_use]
pub fn source_name(source: i32) -> &'static str {
    match pb::FixationSource::try_from(source) {
        Ok(pb::FixationSource::Gaze) => "GAZE",
        Ok(pb::FixationSource::FallbackNoGaze) => "FALLBACK_NO_GAZE",
        Ok(pb::FixationSource::FallbackStale) => "FALLBACK_STALE",
        Ok(pb::FixationSource::FallbackTrackLost) => "FALLBACK_TRACK_LOST",
        Ok(pb::FixationSource::Unspecified) | Err(_) => "UNSPECIFIED",
    }
}

/// Bodies in a frame's poses; `None` without poses.
fn body_count(frame: &pb::Frame) -> Option<usize> {
    frame.poses.as_ref().map(|p| p.bodies as usize)
}

/// One CSV row for `frame` (no terminator); `received_at_s` is seconds since watching started.
/// Numbers use Rust's shortest round-trip formatting, so they parse back exactly; the
/// per-level counts are `;`-separated inside their one column.
#[must_use]
pub fn csv_row(frame: &pb::Frame, received_at_s: f64) -> String {
    let fixation = frame.fixation.unwrap_or_default();
    let m = frame.metrics.clone().unwrap_or_default();
    let profile = frame.profile.unwrap_or_default();
    let audit = m.audit;
    let opt = |v: Option<String>| v.unwrap_or_default();
    let levels = m
        .resolved_per_level
        .iter()
        .map(u64::to_string)
        .collect::<Vec<_>>()
        .join(";");
    let mut row = String::with_capacity(256);
    // Writing to a String cannot fail.
    let _ = write!(
        row,
        "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
        frame.index,
        frame.sim_time_s,
        fixation.x,
        fixation.y,
        fixation.age_s,
        source_name(fixation.source),
        m.collision_time_s,
        m.geometric_inaccuracy,
        m.perceived_inaccuracy,
        m.candidate_pairs,
        m.real_collisions,
        m.deemed_at_interruption,
        m.sphere_tests,
        frame.dropped_before,
        opt(audit.map(|a| a.true_false_positives.to_string())),
        opt(audit.map(|a| a.true_geometric_inaccuracy.to_string())),
        opt(audit.map(|a| a.true_perceived_inaccuracy.to_string())),
        u8::from(m.budget_exhausted),
        profile.integrate_s,
        profile.broad_s,
        profile.narrow_s,
        profile.response_s,
        opt(body_count(frame).map(|n| n.to_string())),
        levels,
        received_at_s,
        // A server before the field existed sends 0: every deemed pair was summed.
        m.metrics_stride.max(1),
        m.geometric_inaccuracy_se,
        m.perceived_inaccuracy_se,
        u8::from(m.budget_spent_before_narrow),
        m.foveal_pairs,
        m.foveal_deemed,
        opt(audit.map(|a| a.true_foveal_false_positives.to_string())),
    );
    row
}

/// What to subscribe to and when to stop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WatchOptions {
    /// Receive every k-th frame (0 and 1: every frame).
    pub every_k: u32,
    /// Ask for body poses.
    pub poses: bool,
    /// Stop after this many frames; `None` until the stream ends or shutdown.
    pub frames: Option<u64>,
    /// Time between summary lines.
    pub interval: Duration,
}

impl Default for WatchOptions {
    fn default() -> Self {
        Self {
            every_k: 1,
            poses: false,
            frames: None,
            interval: Duration::from_secs(1),
        }
    }
}

/// Totals of a watch.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct WatchReport {
    /// Frames received (count).
    pub frames: u64,
    /// Frames the server dropped for this subscriber (count).
    pub dropped: u64,
    /// Index of the last frame received.
    pub last_index: Option<u64>,
}

/// Statistics of the frames of one summary interval.
#[derive(Debug, Clone, Default)]
pub struct Window {
    /// Index of the frame before the window (the previous window's last); `None` at the start.
    before_index: Option<u64>,
    first_index: Option<u64>,
    last_index: Option<u64>,
    times_s: Vec<f64>,
    delta: f64,
    p: f64,
    pairs: u64,
    deemed: u64,
    dropped: u64,
    last_fixation: Option<pb::Fixation>,
    bodies: Option<usize>,
}

/// Nearest-rank percentile `q` (0..=1) of sorted `values` ([`crate::gaze::quantile`]); `None`
/// when empty.
#[must_use]
pub fn percentile(sorted: &[f64], q: f64) -> Option<f64> {
    crate::gaze::quantile::nearest_rank(sorted, q)
}

impl Window {
    /// Adds one frame.
    pub fn push(&mut self, frame: &pb::Frame) {
        let m = frame.metrics.clone().unwrap_or_default();
        self.first_index.get_or_insert(frame.index);
        self.last_index = Some(frame.index);
        self.times_s.push(m.collision_time_s);
        self.delta += m.geometric_inaccuracy;
        self.p += m.perceived_inaccuracy;
        self.pairs += m.candidate_pairs;
        self.deemed += m.deemed_at_interruption;
        self.dropped += frame.dropped_before;
        self.last_fixation = frame.fixation;
        self.bodies = body_count(frame).or(self.bodies);
    }

    /// Frames in the window.
    #[must_use]
    pub fn len(&self) -> usize {
        self.times_s.len()
    }

    /// Whether the window has no frame.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.times_s.is_empty()
    }

    /// The summary line for a window that lasted `elapsed`, then an empty window that carries on
    /// from this one's last frame index.
    pub fn take_line(&mut self, elapsed: Duration) -> String {
        let line = self.line(elapsed);
        *self = Self {
            before_index: self.last_index.or(self.before_index),
            bodies: self.bodies,
            ..Self::default()
        };
        line
    }

    /// Server frames simulated during the window, from the index span.
    fn simulated(&self) -> u64 {
        match (self.before_index, self.first_index, self.last_index) {
            (Some(before), _, Some(last)) => last.saturating_sub(before),
            (None, Some(first), Some(last)) => last - first + 1,
            _ => 0,
        }
    }

    /// The summary line (see the module documentation).
    #[must_use]
    pub fn line(&self, elapsed: Duration) -> String {
        let n = self.len();
        let secs = elapsed.as_secs_f64();
        let fps = if secs > 0.0 {
            self.simulated() as f64 / secs
        } else {
            0.0
        };
        let mut sorted = self.times_s.clone();
        sorted.sort_by(f64::total_cmp);
        let ms = |v: Option<f64>| v.map_or_else(|| "-".to_owned(), |s| format!("{:.3}", s * 1e3));
        let mean = |sum: f64| if n > 0 { sum / n as f64 } else { 0.0 };
        let mut line = format!(
            "frame {} fps {fps:.1} T p50 {} p99 {} ms  Δ {:.4} P {:.4} pairs {:.1} deemed {:.1} dropped {}",
            self.last_index
                .map_or_else(|| "-".to_owned(), |i| i.to_string()),
            ms(percentile(&sorted, 0.5)),
            ms(percentile(&sorted, 0.99)),
            mean(self.delta),
            mean(self.p),
            mean(self.pairs as f64),
            mean(self.deemed as f64),
            self.dropped,
        );
        if let Some(f) = self.last_fixation {
            let _ = write!(
                line,
                "  fix {} ({:.3},{:.3}) age {:.0} ms",
                source_name(f.source),
                f.x,
                f.y,
                f.age_s * 1e3
            );
        }
        if let Some(bodies) = self.bodies {
            let _ = write!(line, "  bodies {bodies}");
        }
        line
    }
}

/// Subscribes to frames and writes, until `options.frames` frames, the end of the stream or
/// `shutdown`: a summary line every `options.interval` to `summary` (if any) and one CSV row
/// per frame to `csv` (if any, header first). Both writers are flushed before returning.
///
/// # Errors
/// [`ClientError::Rpc`] when the subscription fails, [`ClientError::Io`] when a writer fails.
pub async fn watch<C: Write, S: Write>(
    client: &mut crate::Client,
    options: WatchOptions,
    mut csv: Option<C>,
    mut summary: Option<S>,
    shutdown: impl Future<Output = ()>,
) -> Result<WatchReport, ClientError> {
    let write_err = |what: &'static str| move |e| ClientError::io(what, e);
    if let Some(csv) = csv.as_mut() {
        writeln!(csv, "{CSV_HEADER}").map_err(write_err("write CSV"))?;
    }
    let mut report = WatchReport::default();
    if options.frames == Some(0) {
        return Ok(report);
    }
    let request = pb::WatchFramesRequest {
        every_k: options.every_k,
        include_poses: options.poses,
        ..Default::default()
    };
    let mut stream = client
        .watch_frames(request)
        .await
        .map_err(|status| ClientError::Rpc {
            rpc: "WatchFrames",
            status,
        })?
        .into_inner();
    let started = Instant::now();
    let mut window = Window::default();
    let mut window_start = started;
    let mut ticker = tokio::time::interval_at(started + options.interval, options.interval);
    ticker.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
    tokio::pin!(shutdown);
    let result = loop {
        let message = tokio::select! {
            biased;
            () = &mut shutdown => break Ok(()),
            _ = ticker.tick() => {
                let now = Instant::now();
                if let Some(out) = summary.as_mut() {
                    let line = window.take_line(now - window_start);
                    writeln!(out, "{line}").and_then(|()| out.flush()).map_err(write_err("write summary"))?;
                } else {
                    window = Window::default();
                }
                if let Some(csv) = csv.as_mut() {
                    csv.flush().map_err(write_err("write CSV"))?;
                }
                window_start = now;
                continue;
            }
            message = stream.message() => message,
        };
        let frame = match message {
            Ok(Some(frame)) => frame,
            Ok(None) => break Ok(()),
            Err(status) => {
                break Err(ClientError::Rpc {
                    rpc: "WatchFrames",
                    status,
                });
            }
        };
        if let Some(csv) = csv.as_mut() {
            let at = started.elapsed().as_secs_f64();
            writeln!(csv, "{}", csv_row(&frame, at)).map_err(write_err("write CSV"))?;
        }
        window.push(&frame);
        report.frames += 1;
        report.dropped += frame.dropped_before;
        report.last_index = Some(frame.index);
        if options.frames.is_some_and(|n| report.frames >= n) {
            break Ok(());
        }
    };
    if let Some(out) = summary.as_mut()
        && !window.is_empty()
    {
        let line = window.take_line(window_start.elapsed());
        writeln!(out, "{line}")
            .and_then(|()| out.flush())
            .map_err(write_err("write summary"))?;
    }
    if let Some(csv) = csv.as_mut() {
        csv.flush().map_err(write_err("write CSV"))?;
    }
    result.map(|()| report)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(index: u64, t_s: f64, dropped: u64) -> pb::Frame {
        pb::Frame {
            index,
            sim_time_s: index as f64 / 60.0,
            fixation: Some(pb::Fixation {
                x: 0.25,
                y: 0.5,
                age_s: 0.01,
                source: pb::FixationSource::Gaze as i32,
                ..Default::default()
            }),
            metrics: Some(pb::FrameMetrics {
                collision_time_s: t_s,
                geometric_inaccuracy: 1.0,
                perceived_inaccuracy: 0.5,
                candidate_pairs: 10,
                real_collisions: 2,
                deemed_at_interruption: 3,
                resolved_per_level: vec![4, 2, 1],
                sphere_tests: 99,
                budget_exhausted: true,
                audit: None,
                ..Default::default()
            }),
            profile: Some(pb::PhaseProfile::default()),
            dropped_before: dropped,
            poses: None,
            ..Default::default()
        }
    }

    #[test]
    fn header_matches_the_column_list() {
        assert_eq!(CSV_HEADER, CSV_COLUMNS.join(","));
    }

    #[test]
    fn rows_have_one_field_per_column_and_leave_audit_empty_without_audit() {
        let row = csv_row(&frame(7, 0.002, 1), 1.5);
        let fields: Vec<&str> = row.split(',').collect();
        assert_eq!(fields.len(), CSV_COLUMNS.len(), "{row}");
        let col = |name: &str| {
            let i = CSV_COLUMNS.iter().position(|c| *c == name).expect("column");
            fields[i]
        };
        assert_eq!(col("index"), "7");
        assert_eq!(col("fixation_source"), "GAZE");
        assert_eq!(col("collision_time_s"), "0.002");
        assert_eq!(col("deemed"), "3");
        assert_eq!(col("true_false_positives"), "");
        assert_eq!(col("budget_exhausted"), "1");
        assert_eq!(col("resolved_per_level"), "4;2;1");
        assert_eq!(col("bodies"), "");
        assert_eq!(
            col("metrics_stride"),
            "1",
            "0 from an older server reads as 1"
        );
        assert_eq!(col("budget_spent_before_narrow"), "0");
        let mut audited = frame(8, 0.0, 0);
        if let Some(m) = audited.metrics.as_mut() {
            m.audit = Some(pb::AuditMetrics {
                true_false_positives: 2,
                true_geometric_inaccuracy: 0.25,
                true_perceived_inaccuracy: 0.125,
                true_foveal_false_positives: 1,
            });
            m.foveal_pairs = 6;
            m.foveal_deemed = 2;
        }
        let row = csv_row(&audited, 0.0);
        assert!(row.contains(",2,0.25,0.125,"), "{row}");
        // The wrong guesses near the fixation, beside the pairs there and those deemed.
        assert!(row.ends_with(",6,2,1"), "{row}");
        assert!(csv_row(&frame(9, 0.0, 0), 0.0).ends_with(",0,0,"));
    }

    #[test]
    fn percentiles_use_nearest_rank() {
        let v: Vec<f64> = (1..=100).map(f64::from).collect();
        assert_eq!(percentile(&v, 0.5), Some(50.0));
        assert_eq!(percentile(&v, 0.99), Some(99.0));
        assert_eq!(percentile(&v, 1.0), Some(100.0));
        assert_eq!(percentile(&v, 0.0), Some(1.0));
        assert_eq!(percentile(&[3.0], 0.99), Some(3.0));
        assert_eq!(percentile(&[], 0.5), None);
    }

    #[test]
    fn window_rate_counts_server_frames_across_windows() {
        let mut w = Window::default();
        // every_k = 2: indices 0, 2, ..., 58 in the first second.
        for i in (0..60).step_by(2) {
            w.push(&frame(i, 0.001, 0));
        }
        let first = w.take_line(Duration::from_secs(1));
        assert!(first.contains("fps 59.0"), "{first}");
        for i in (60..120).step_by(2) {
            w.push(&frame(i, 0.001, 1));
        }
        let second = w.take_line(Duration::from_secs(1));
        assert!(second.contains("fps 60.0"), "{second}");
        assert!(second.contains("dropped 30"), "{second}");
        assert!(second.contains("T p50 1.000 p99 1.000 ms"), "{second}");
        assert!(
            second.contains("fix GAZE (0.250,0.500) age 10 ms"),
            "{second}"
        );
        let empty = w.line(Duration::from_secs(1));
        assert!(
            empty.contains("fps 0.0") && empty.contains("p50 -"),
            "{empty}"
        );
    }
}
