//! Limits that protect the frame loop from what clients ask of it.
//!
//! A configuration is refused before anything is built when its derived cost would stall the loop:
//! the density must be in a stated range (a tiny density makes the volume, and every pose,
//! infinite), and the expected broad-phase candidate pairs and the memory they need must stay
//! under stated limits (a dense scene puts every pair of bodies into the narrow phase, and even a
//! zero budget still has to list, prioritise and deem them). The estimate is the exact expectation
//! for the paper scene's uniform random positions, so it is known before the scene is generated.
//!
//! Gaze is limited per stream (and per connection for PushGaze) by a token bucket: samples above
//! the rate are dropped and counted, never queued, since only the newest sample matters to a frame.

use std::collections::HashMap;
use std::net::SocketAddr;
use std::sync::{Mutex, PoisonError};
use std::time::{Duration, Instant};

use foveal_engine::{ConfigError, SimConfig};

/// Smallest density accepted (bodies per cubic scene unit).
pub const MIN_DENSITY: f64 = 1e-3;
/// Largest density accepted (bodies per cubic scene unit); the paper uses 10. Ten times denser
/// gives about 36 candidate pairs per body; a density of 1,000 already gives 200 per body and takes
/// a 2,000-body scene over a minute to build.
pub const MAX_DENSITY: f64 = 100.0;
/// Default limit on the expected broad-phase candidate pairs of a scene (count): the paper scene
/// up to the 2,000,000 bodies `--bodies` allows (about 6.2 million pairs) fits; what it stops is a
/// density that puts most pairs of bodies into the narrow phase.
pub const DEFAULT_MAX_CANDIDATE_PAIRS: u64 = 8_000_000;
/// Default limit on the estimated memory of a scene (MiB).
pub const DEFAULT_MAX_MEMORY_MIB: u64 = 2048;
/// Bytes per body in the memory estimate (state, poses, broad-phase entries, per-frame buffers).
/// With [`BYTES_PER_PAIR`] the estimate for the paper scene at N = 1,000,000 (3.1 pairs per body)
/// is 653 MB, against a measured peak RSS of 596 MiB (625 MB) for the exact run.
pub const BYTES_PER_BODY: u64 = 256;
/// Bytes per expected candidate pair in the memory estimate (pair list, priorities, narrow-phase
/// work lists, metrics).
pub const BYTES_PER_PAIR: u64 = 128;
/// Upper bound of the level-1 sphere radius over the shape radius R (about 1.11 for the star
/// shape at every depth): the half-size of each body's bounding box.
pub const BOX_HALF_SIZE_OVER_R: f64 = 1.12;
/// Default gaze rate limit per stream (samples per second): twice the fastest common tracker.
pub const DEFAULT_MAX_GAZE_RATE_HZ: f64 = 4000.0;
/// Burst the gaze limit lets through at once, in seconds of the rate (pacing jitter and batches).
pub const GAZE_BURST_S: f64 = 0.25;
/// Largest request message the server decodes (bytes); larger ones answer RESOURCE_EXHAUSTED.
pub const MAX_REQUEST_BYTES: usize = 4 << 20;
/// HTTP/2 streams one connection may have open at once.
pub const MAX_STREAMS_PER_CONNECTION: u32 = 128;
/// Calls one connection may have in progress at once (a WatchFrames counts only while it is being
/// set up; a StreamGaze for as long as it runs); more answer RESOURCE_EXHAUSTED.
pub const MAX_CALLS_PER_CONNECTION: usize = 64;
/// WatchFrames subscribers the server serves at once; more answer RESOURCE_EXHAUSTED.
pub const MAX_SUBSCRIBERS: u32 = 1024;
/// StreamGaze calls the server serves at once; more answer RESOURCE_EXHAUSTED.
pub const MAX_GAZE_STREAMS: u32 = 256;
/// Health watches one connection may have open at once (a client watches one service or two).
pub const MAX_HEALTH_WATCHES_PER_CONNECTION: usize = 8;
/// Health watches the server serves at once, all connections together.
pub const MAX_HEALTH_WATCHES: usize = 1024;
/// HTTP/2 keepalive: ping an idle connection this often...
pub const KEEPALIVE_INTERVAL: Duration = Duration::from_secs(20);
/// ... and close it when the ping is not answered within this.
pub const KEEPALIVE_TIMEOUT: Duration = Duration::from_secs(10);

/// At most `max` bytes of a client's string for a log line or a message: control characters
/// become `?`, and a longer string is cut at a character boundary and marked with `…` and its
/// length, so that nothing a client sends is ever copied unbounded.
pub fn excerpt(s: &str, max: usize) -> String {
    let mut out = String::new();
    for c in s.chars() {
        if out.len() + c.len_utf8() > max {
            out.push_str(&format!("… ({} bytes)", s.len()));
            return out;
        }
        out.push(if c.is_control() { '?' } else { c });
    }
    out
}

/// The limits a server enforces (flags `--max-candidate-pairs`, `--max-memory-mib`,
/// `--max-gaze-rate`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// Largest expected candidate pairs of a scene (count).
    pub max_candidate_pairs: u64,
    /// Largest estimated memory of a scene (MiB).
    pub max_memory_mib: u64,
    /// Gaze samples per second one stream (or one connection's PushGaze calls) may deliver.
    pub max_gaze_rate_hz: f64,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            max_candidate_pairs: DEFAULT_MAX_CANDIDATE_PAIRS,
            max_memory_mib: DEFAULT_MAX_MEMORY_MIB,
            max_gaze_rate_hz: DEFAULT_MAX_GAZE_RATE_HZ,
        }
    }
}

/// What a scene is expected to cost.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SceneCost {
    /// Expected broad-phase candidate pairs per frame (count).
    pub candidate_pairs: f64,
    /// Estimated memory (MiB).
    pub memory_mib: f64,
}

/// The expected cost of `c` (its density already in range): two bodies are candidates when
/// their boxes of half-size h overlap, i.e. their centres are closer than w = 2h on every axis;
/// for two uniform points in [0, s] that has probability 2w/s - (w/s)^2 per axis.
pub fn scene_cost(c: &SimConfig) -> SceneCost {
    let n = f64::from(c.scene.bodies);
    let side = (n / c.scene.density).cbrt();
    let w = 2.0 * BOX_HALF_SIZE_OVER_R * c.scene.shape_radius;
    let r = w / side;
    let per_axis = if r >= 1.0 { 1.0 } else { 2.0 * r - r * r };
    let candidate_pairs = n * (n - 1.0) / 2.0 * per_axis.powi(3);
    let bytes = n * BYTES_PER_BODY as f64 + candidate_pairs * BYTES_PER_PAIR as f64;
    SceneCost {
        candidate_pairs,
        memory_mib: bytes / f64::from(1u32 << 20),
    }
}

impl Limits {
    /// Check the limits themselves.
    pub fn validate(&self) -> Result<(), ConfigError> {
        let r = self.max_gaze_rate_hz;
        if !(r.is_finite() && r >= 1.0) {
            return Err(ConfigError {
                field: "max_gaze_rate_hz",
                value: r.to_string(),
                expected: "must be finite and >= 1 (samples per second)".into(),
            });
        }
        Ok(())
    }

    /// Refuse a configuration whose derived cost would stall the loop; the error names the field
    /// to change and the limit.
    pub fn check(&self, c: &SimConfig) -> Result<SceneCost, ConfigError> {
        let d = c.scene.density;
        if !(d.is_finite() && (MIN_DENSITY..=MAX_DENSITY).contains(&d)) {
            return Err(ConfigError {
                field: "scene.density",
                value: format!("{d:e}"),
                expected: format!(
                    "must be in [{MIN_DENSITY}, {MAX_DENSITY}] bodies per cubic unit (the paper uses 10)"
                ),
            });
        }
        let cost = scene_cost(c);
        if cost.candidate_pairs > self.max_candidate_pairs as f64 {
            return Err(ConfigError {
                field: "scene.bodies",
                value: format!(
                    "{} at density {d} (about {:.0} candidate pairs per frame)",
                    c.scene.bodies, cost.candidate_pairs
                ),
                expected: format!(
                    "the expected candidate pairs must be at most {} (server limit --max-candidate-pairs): lower bodies, density or shape_radius",
                    self.max_candidate_pairs
                ),
            });
        }
        if cost.memory_mib > self.max_memory_mib as f64 {
            return Err(ConfigError {
                field: "scene.bodies",
                value: format!(
                    "{} (about {:.0} MiB estimated)",
                    c.scene.bodies, cost.memory_mib
                ),
                expected: format!(
                    "the estimated memory must be at most {} MiB (server limit --max-memory-mib): lower bodies or density",
                    self.max_memory_mib
                ),
            });
        }
        Ok(cost)
    }
}

/// A token bucket: `rate` per second, holding at most `burst`.
#[derive(Debug, Clone, Copy)]
pub struct RateLimiter {
    rate: f64,
    burst: f64,
    tokens: f64,
    last: Instant,
}

impl RateLimiter {
    /// A full bucket for `rate_hz` with a burst of [`GAZE_BURST_S`] seconds (at least one).
    pub fn new(rate_hz: f64, now: Instant) -> Self {
        let burst = (rate_hz * GAZE_BURST_S).max(1.0);
        Self {
            rate: rate_hz,
            burst,
            tokens: burst,
            last: now,
        }
    }

    /// Take one token at `now`; false means the sample is over the limit.
    pub fn allow(&mut self, now: Instant) -> bool {
        let dt = now.saturating_duration_since(self.last).as_secs_f64();
        self.last = now;
        self.tokens = (self.tokens + dt * self.rate).min(self.burst);
        if self.tokens >= 1.0 {
            self.tokens -= 1.0;
            true
        } else {
            false
        }
    }
}

/// Idle time after which a connection's PushGaze bucket is forgotten.
const PUSH_IDLE: Duration = Duration::from_secs(30);

/// Rate limiters of PushGaze, one per connection (peer address), so that many small calls
/// cannot get around the per-stream limit.
#[derive(Debug, Default)]
pub struct PushLimiters {
    buckets: Mutex<HashMap<Option<SocketAddr>, RateLimiter>>,
}

impl PushLimiters {
    /// How many of `n` samples from `peer` fit under `rate_hz` at `now` (the caller keeps the
    /// newest that many).
    pub fn admit(&self, peer: Option<SocketAddr>, n: usize, rate_hz: f64, now: Instant) -> usize {
        let mut buckets = self.buckets.lock().unwrap_or_else(PoisonError::into_inner);
        if buckets.len() > 4096 {
            buckets.retain(|_, b| now.saturating_duration_since(b.last) < PUSH_IDLE);
        }
        let bucket = buckets
            .entry(peer)
            .or_insert_with(|| RateLimiter::new(rate_hz, now));
        (0..n).take_while(|_| bucket.allow(now)).count()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn density_and_cost_limits_name_the_field_and_limit() {
        let limits = Limits {
            max_candidate_pairs: 1_000_000,
            ..Limits::default()
        };
        let mut c = SimConfig::default();
        limits.check(&c).expect("defaults fit");
        c.scene.density = 1e-300;
        let e = limits.check(&c).expect_err("tiny density");
        assert_eq!(e.field, "scene.density");
        assert!(e.expected.contains("[0.001, 100]"), "{e}");
        // The case: 2,000 bodies so dense that every pair is a candidate.
        c.scene.bodies = 2000;
        c.scene.density = 30_000.0;
        let cost = scene_cost(&c);
        assert_eq!(cost.candidate_pairs, 1_999_000.0);
        assert_eq!(limits.check(&c).map_err(|e| e.field), Err("scene.density"));
        // A big paper scene: 400,000 bodies at density 10 are about 1.4 million pairs.
        c.scene.bodies = 400_000;
        c.scene.density = 10.0;
        let e = limits.check(&c).expect_err("too many pairs");
        assert_eq!(e.field, "scene.bodies");
        assert!(e.expected.contains("1000000"), "{e}");
        // The paper scene at N = 10,000 is far inside the limits.
        c.scene.bodies = 10_000;
        c.scene.density = 10.0;
        let cost = limits.check(&c).expect("paper scene fits");
        assert!(
            (20_000.0..60_000.0).contains(&cost.candidate_pairs),
            "{cost:?}"
        );
        let tight = Limits {
            max_memory_mib: 1,
            ..Limits::default()
        };
        let e = tight.check(&c).expect_err("memory");
        assert!(e.expected.contains("1 MiB"), "{e}");
    }

    #[test]
    fn excerpts_are_bounded_and_printable() {
        assert_eq!(excerpt("eyelink", 64), "eyelink");
        assert_eq!(excerpt("a\nb\x1b[31m", 64), "a?b?[31m");
        let long = "é".repeat(100);
        let e = excerpt(&long, 9);
        assert!(e.starts_with("éééé…"), "{e}");
        assert!(e.ends_with("(200 bytes)"), "{e}");
    }

    #[test]
    fn the_bucket_holds_its_rate_and_burst() {
        let t0 = Instant::now();
        let mut b = RateLimiter::new(1000.0, t0);
        // A full bucket: 250 at once, then nothing until time passes.
        assert_eq!((0..1000).filter(|_| b.allow(t0)).count(), 250);
        let t1 = t0 + Duration::from_millis(100);
        assert_eq!((0..1000).filter(|_| b.allow(t1)).count(), 100);
        let push = PushLimiters::default();
        assert_eq!(push.admit(None, 300, 1000.0, t0), 250);
        assert_eq!(push.admit(None, 10, 1000.0, t0), 0);
    }
}
