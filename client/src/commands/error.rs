//! Why a command could not run.

use std::io;
use std::path::PathBuf;

use crate::ClientError;
use crate::gaze::geometry::GeometryError;
use crate::gaze::script::ScriptError;

/// Why a `foveal` subcommand could not run. Its message names the flag or the file at fault;
/// the cause, if any, is its [`source`](std::error::Error::source).
#[derive(Debug, thiserror::Error)]
pub enum CommandError {
    /// A flag's value, or a combination of flags, that cannot work; the message says which.
    #[error("{0}")]
    Usage(String),
    /// The CA certificate given with `--ca` cannot be read.
    #[error("read --ca {}", path.display())]
    ReadCa {
        /// The file.
        path: PathBuf,
        /// Why.
        #[source]
        source: io::Error,
    },
    /// A recording cannot be read (`read`) or opened to send (`open`).
    #[error("{action} {}", path.display())]
    Recording {
        /// `read` (the look ahead) or `open`.
        action: &'static str,
        /// The file.
        path: PathBuf,
        /// Why.
        #[source]
        source: io::Error,
    },
    /// A recording that holds nothing to send; the message says why.
    #[error("{0}")]
    NothingToSend(String),
    /// The CSV file of `foveal watch --csv` cannot be created.
    #[error("create {}", path.display())]
    CreateCsv {
        /// The file.
        path: PathBuf,
        /// Why.
        #[source]
        source: io::Error,
    },
    /// The viewing geometry of `foveal fixations` is not usable.
    #[error("--screen-cm / --distance-cm")]
    Geometry(#[source] GeometryError),
    /// The results cannot be written to stdout.
    #[error("write stdout")]
    WriteStdout(#[source] io::Error),
    /// A script's parameters cannot make gaze.
    #[error(transparent)]
    Script(#[from] ScriptError),
    /// The client library failed: connecting, a call, a file.
    #[error(transparent)]
    Client(#[from] ClientError),
}
