//! The `foveal` subcommands, one function each: the binary parses its arguments into the
//! descriptions here and makes one call. Results go to stdout and diagnostics to stderr, as the
//! command line promises; the function's [`Outcome`] is the exit status.
//!
//! - [`server`]: where the server is, as the command line says it ([`Server`]).
//! - [`input`]: what `foveal gaze` and `foveal bridge` send ([`GazeInput`]), opened as a source.
//! - [`send`]: `foveal gaze` and `foveal bridge`: the input forwarded to the server.
//! - [`watch`]: `foveal watch`.
//! - [`health`]: `foveal health`.
//! - [`fixations`]: `foveal fixations`.
//! - [`load`]: `foveal load`.
//! - [`psych`]: `foveal psych fit` and `foveal psych simulate`.
//! - [`CommandError`]: why a command could not run.

mod error;
pub mod fixations;
pub mod health;
pub mod input;
pub mod load;
pub mod psych;
pub mod send;
pub mod server;
pub mod watch;

pub use error::CommandError;
pub use fixations::{Detector, FixationsCommand, fixations};
pub use health::health;
pub use input::{GazeInput, LslInput, LslUnits, PupilInput, Speed};
pub use load::{LoadCommand, load};
pub use send::{SendOptions, send};
pub use server::Server;
pub use watch::{WatchCommand, watch};

/// The target of the commands' own log lines: the binary's name, as `RUST_LOG=foveal=debug`
/// filters them.
pub(crate) const LOG_TARGET: &str = "foveal";

/// How a command ended, for the exit status: it did what was asked (0), or it ran and reported
/// a failure on stdout or stderr (1). A command that could not run returns a [`CommandError`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    /// Exit status 0.
    Success,
    /// Exit status 1.
    Failure,
}

impl From<Outcome> for std::process::ExitCode {
    fn from(outcome: Outcome) -> Self {
        match outcome {
            Outcome::Success => Self::SUCCESS,
            Outcome::Failure => Self::FAILURE,
        }
    }
}

/// Completes on Ctrl-C; never, if the signal cannot be listened to.
pub(crate) async fn ctrl_c() {
    if let Err(err) = tokio::signal::ctrl_c().await {
        tracing::warn!(target: LOG_TARGET, "cannot listen for Ctrl-C: {err}");
        std::future::pending::<()>().await;
    }
    tracing::info!(target: LOG_TARGET, "interrupted; finishing");
}
