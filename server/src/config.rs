//! The server's configuration: the engine's [`SimConfig`] plus what only the server knows about
//! (frame rate, how old a gaze sample may be before it stops steering the scheduler, buffer sizes).
//!
//! Errors reuse the engine's [`ConfigError`] so that every invalid setting, whether it came from a
//! flag, the environment or a `Configure` call, is reported the same way: field, value, range.

use std::time::Duration;

use foveal_engine::{ConfigError, SimConfig};

use crate::auth::Tokens;
use crate::limits::Limits;
use crate::origin::AllowedOrigin;
use crate::transport::ConnectionLimits;

/// Slowest frame rate accepted (frames per second): below this a "frame loop" is a batch job.
pub const MIN_FRAME_RATE_HZ: f64 = 1.0;
/// Fastest frame rate accepted (frames per second): beyond this the OS sleep granularity, not the
/// loop, sets the pace.
pub const MAX_FRAME_RATE_HZ: f64 = 1000.0;
/// Longest gaze max age accepted: older gaze than an hour is not gaze.
pub const MAX_GAZE_MAX_AGE: Duration = Duration::from_secs(3600);

/// Everything [`crate::run`] needs.
#[derive(Debug, Clone, PartialEq)]
pub struct ServerConfig {
    /// The simulation the server starts with (Configure can replace it later).
    pub sim: SimConfig,
    /// Target frame rate of the loop (frames per second). The loop never runs faster; when a frame
    /// overruns its period the next one starts at once and the overrun is counted.
    pub frame_rate_hz: f64,
    /// Gaze older than this (server clock, from receipt) no longer steers the scheduler: frames
    /// fall back to the screen centre and say so.
    pub gaze_max_age: Duration,
    /// Frames the fan-out keeps for subscribers that fall behind, before they start losing frames.
    pub frame_buffer: usize,
    /// How often the loop logs its one-line summary and refreshes the rates in GetStatus.
    pub summary_interval: Duration,
    /// How long shutdown waits for open calls to finish before giving up on them.
    pub shutdown_grace: Duration,
    /// Online gaze processing (eyes, filter, fixation detector, track loss); by default raw
    /// samples steer, the lowest latency from gaze to schedule.
    pub gaze_processing: foveal_gaze::online::ProcessorConfig,
    /// Who may call what, and whether the transport is encrypted.
    pub security: Security,
    /// Limits protecting the loop (scene cost, gaze rate).
    pub limits: Limits,
    /// How many connections the server holds and for how long (timeouts).
    pub connections: ConnectionLimits,
    /// Write the session (configuration, every gaze sample the processing received, every
    /// frame's fixation and report, scene changes) to this file (`foveal-session` format).
    pub record: Option<std::path::PathBuf>,
    /// The `/psych` experiments' results directory and designs.
    pub psych: crate::psych::PsychConfig,
    /// Health turns NOT_SERVING when no frame has completed for this many frame periods, and back
    /// to SERVING when frames flow again.
    pub stall_periods: u32,
    /// The side by side's second, gaze-blind collider (`--compare`); Configure can change it.
    pub compare: crate::compare::Compare,
}

/// Health's default stall threshold in frame periods (half a second at 60 Hz).
pub const DEFAULT_STALL_PERIODS: u32 = 30;

/// A certificate chain and its private key (PEM), for TLS.
#[derive(Clone, PartialEq, Eq)]
pub struct TlsIdentity {
    /// The certificate chain, PEM.
    pub cert_pem: Vec<u8>,
    /// The private key, PEM.
    pub key_pem: Vec<u8>,
}

// The key is a secret: never in a log line.
impl std::fmt::Debug for TlsIdentity {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("TlsIdentity")
            .field("cert_pem_bytes", &self.cert_pem.len())
            .finish_non_exhaustive()
    }
}

/// Authentication and encryption.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Security {
    /// Bearer tokens by role; empty means open (allowed on loopback only, or with `insecure`).
    pub tokens: Tokens,
    /// TLS certificate and key; `None` serves plaintext HTTP/2.
    pub tls: Option<TlsIdentity>,
    /// Serve without tokens on a non-loopback address (`--insecure`).
    pub insecure: bool,
    /// Origins browsers may call from besides loopback ones and the server's own address
    /// (`--allowed-origin`); their host names are also accepted in `Host`.
    pub allowed_origins: Vec<AllowedOrigin>,
}

impl Default for ServerConfig {
    fn default() -> Self {
        Self {
            sim: SimConfig::default(),
            frame_rate_hz: 60.0,
            gaze_max_age: Duration::from_millis(500),
            frame_buffer: 32,
            summary_interval: Duration::from_secs(1),
            shutdown_grace: Duration::from_secs(5),
            gaze_processing: foveal_gaze::online::ProcessorConfig::default(),
            security: Security::default(),
            limits: Limits::default(),
            connections: ConnectionLimits::default(),
            stall_periods: DEFAULT_STALL_PERIODS,
            record: None,
            psych: crate::psych::PsychConfig::default(),
            compare: crate::compare::Compare::Off,
        }
    }
}

impl ServerConfig {
    /// Check every field, the simulation's included; the error names the first offending one.
    pub fn validate(&self) -> Result<(), ConfigError> {
        validate_frame_rate(self.frame_rate_hz)?;
        if self.gaze_max_age.is_zero() || self.gaze_max_age > MAX_GAZE_MAX_AGE {
            return Err(ConfigError {
                field: "gaze_max_age",
                value: format!("{:?}", self.gaze_max_age),
                expected: format!("must be > 0 and <= {} s", MAX_GAZE_MAX_AGE.as_secs()),
            });
        }
        if let Err(field) = self.gaze_processing.validate() {
            return Err(ConfigError {
                field: "gaze_processing",
                value: field.to_owned(),
                expected:
                    "every gaze processing parameter finite and in range (see foveal_gaze::online)"
                        .into(),
            });
        }
        if !(1..=1 << 16).contains(&self.frame_buffer) {
            return Err(ConfigError {
                field: "frame_buffer",
                value: self.frame_buffer.to_string(),
                expected: "must be in 1..=65536".into(),
            });
        }
        if self.summary_interval.is_zero() {
            return Err(ConfigError {
                field: "summary_interval",
                value: "0s".into(),
                expected: "must be > 0".into(),
            });
        }
        if self.stall_periods == 0 {
            return Err(ConfigError {
                field: "stall_periods",
                value: "0".into(),
                expected: "must be >= 1 (frame periods)".into(),
            });
        }
        self.limits.validate()?;
        self.connections.validate()?;
        self.sim.validate()?;
        self.compare.check(&self.sim)?;
        self.limits.check(&self.sim).map(|_| ())
    }

    /// One frame period at the configured rate.
    pub fn frame_period(&self) -> Duration {
        frame_period(self.frame_rate_hz)
    }
}

/// Check a frame rate (shared by the flags and Configure).
pub fn validate_frame_rate(hz: f64) -> Result<(), ConfigError> {
    if hz.is_finite() && (MIN_FRAME_RATE_HZ..=MAX_FRAME_RATE_HZ).contains(&hz) {
        Ok(())
    } else {
        Err(ConfigError {
            field: "frame_rate_hz",
            value: hz.to_string(),
            expected: format!("must be finite and in [{MIN_FRAME_RATE_HZ}, {MAX_FRAME_RATE_HZ}]"),
        })
    }
}

/// The period of a validated frame rate.
pub(crate) fn frame_period(hz: f64) -> Duration {
    Duration::from_secs_f64(1.0 / hz.clamp(MIN_FRAME_RATE_HZ, MAX_FRAME_RATE_HZ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_valid_and_errors_name_the_field() {
        ServerConfig::default()
            .validate()
            .expect("defaults are valid");
        let bad = ServerConfig {
            frame_rate_hz: f64::NAN,
            ..ServerConfig::default()
        };
        assert_eq!(bad.validate().map_err(|e| e.field), Err("frame_rate_hz"));
        let bad = ServerConfig {
            gaze_max_age: Duration::ZERO,
            ..ServerConfig::default()
        };
        assert_eq!(bad.validate().map_err(|e| e.field), Err("gaze_max_age"));
        let mut bad = ServerConfig::default();
        bad.sim.scene.bodies = 0;
        assert_eq!(bad.validate().map_err(|e| e.field), Err("scene.bodies"));
        assert_eq!(frame_period(50.0), Duration::from_millis(20));
    }
}
