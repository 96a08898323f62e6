//! `foveal load`: the server loaded with gaze streams and watchers, the loop measured.

use std::time::Duration;

use tracing::info;

use super::{CommandError, LOG_TARGET, Outcome, Server};
use crate::ConnectOptions;
use crate::load::{self, ChaosOptions, LoadOptions};

/// What `foveal load` is asked for; a token left `None` is the server's.
#[derive(Debug, Clone, Default)]
pub struct LoadCommand {
    /// Token for the gaze streams.
    pub gaze_token: Option<String>,
    /// Token for the watchers and status calls.
    pub viewer_token: Option<String>,
    /// Gaze streams.
    pub streams: usize,
    /// Samples per second per gaze stream.
    pub rate_hz: f64,
    /// Watchers, stalled ones included.
    pub watchers: usize,
    /// Watchers that subscribe and never read a frame.
    pub stalled: usize,
    /// Watchers ask for poses.
    pub poses: bool,
    /// Seconds to run; default 60, or 600 for a chaos run.
    pub seconds: Option<f64>,
    /// The server's process id, for its RSS.
    pub server_pid: Option<u32>,
    /// A chaos run.
    pub chaos: bool,
    /// Token for Configure in a chaos run.
    pub admin_token: Option<String>,
}

/// Runs the load and prints its report to stdout.
///
/// # Errors
/// A duration that is not a positive number, the CA file, the load failing.
pub async fn load(server: &Server, command: LoadCommand) -> Result<Outcome, CommandError> {
    let seconds = command
        .seconds
        .unwrap_or(if command.chaos { 600.0 } else { 60.0 });
    if !(seconds.is_finite() && seconds > 0.0) {
        return Err(CommandError::Usage(format!(
            "--seconds (--duration) must be a positive number, not {seconds}"
        )));
    }
    let base = server.options()?;
    let with = |token: &Option<String>| ConnectOptions {
        token: token.clone().or_else(|| base.token.clone()),
        ..base.clone()
    };
    let options = LoadOptions {
        addr: server.addr.clone(),
        gaze: with(&command.gaze_token),
        viewer: with(&command.viewer_token),
        streams: command.streams,
        rate_hz: command.rate_hz,
        watchers: command.watchers,
        stalled: command.stalled,
        poses: command.poses,
        duration: Duration::from_secs_f64(seconds),
        server_pid: command.server_pid,
        chaos: command.chaos.then(|| ChaosOptions {
            admin: with(&command.admin_token),
            ..ChaosOptions::default()
        }),
        ..LoadOptions::default()
    };
    info!(
        target: LOG_TARGET,
        streams = options.streams,
        rate_hz = options.rate_hz,
        watchers = options.watchers,
        stalled = options.stalled,
        seconds,
        chaos = command.chaos,
        "loading"
    );
    let report = load::run(&options).await?;
    println!("{report}");
    Ok(Outcome::Success)
}
