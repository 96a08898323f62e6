//! `foveal gaze` and `foveal bridge`: an input forwarded to the server, its report printed.

use super::input::{GazeInput, OpenedInput};
use super::{CommandError, Outcome, Server};
use crate::bridge::{self, ForwardOptions, StopReason};
use crate::sender::{GazeSender, Transport};

/// How samples travel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SendOptions {
    /// The gaze rpc.
    pub transport: Transport,
    /// Stop after this many seconds of tracker time (from the first sample).
    pub duration_s: Option<f64>,
}

/// Opens `input`, connects, forwards the samples and prints the report to stdout.
///
/// # Errors
/// The input cannot be opened ([`GazeInput::open`]), a duration that is not a finite number of
/// seconds >= 0, the connection or the stream failing.
pub async fn send(
    server: &Server,
    options: SendOptions,
    input: GazeInput,
) -> Result<Outcome, CommandError> {
    let OpenedInput { name, source, pace } = input.open()?;
    if let Some(d) = options.duration_s
        && !(d.is_finite() && d >= 0.0)
    {
        return Err(CommandError::Usage(format!(
            "--duration must be a finite number of seconds >= 0, not {d}"
        )));
    }
    let client = server.connect().await?;
    let sender = GazeSender::open(client, options.transport, &name)?;
    let forward = ForwardOptions {
        pace,
        duration_s: options.duration_s,
    };
    let report = bridge::forward(source, sender, forward, super::ctrl_c()).await?;
    println!("{report}");
    if let Some(why) = report.nothing_sent() {
        eprintln!("error: {name}: {why}");
        return Ok(Outcome::Failure);
    }
    Ok(match report.stopped {
        StopReason::SourceFailed(_) => Outcome::Failure,
        _ => Outcome::Success,
    })
}
