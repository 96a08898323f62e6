//! `foveal watch`: frames watched until Ctrl-C, a count or the end of the stream.

use std::fs::File;
use std::io::{self, BufWriter};
use std::path::PathBuf;

use tracing::info;

use super::{CommandError, LOG_TARGET, Outcome, Server};
use crate::watch::{self, WatchOptions};

/// What `foveal watch` is asked for.
#[derive(Debug, Clone)]
pub struct WatchCommand {
    /// Which frames, whether with poses, how many.
    pub options: WatchOptions,
    /// Write every frame's metrics to this CSV file; `-` for stdout, which then carries no
    /// summary lines (they go to stdout otherwise).
    pub csv: Option<PathBuf>,
}

/// Connects and watches frames: a summary line per interval on stdout, CSV rows to the file.
///
/// # Errors
/// The connection or the subscription failing, a CSV file that cannot be created or written.
pub async fn watch(server: &Server, command: WatchCommand) -> Result<Outcome, CommandError> {
    let mut client = server.connect().await?;
    let WatchCommand { options, csv } = command;
    let report = match csv {
        Some(path) if path.as_os_str() == "-" => {
            let csv = BufWriter::new(io::stdout());
            watch::watch(
                &mut client,
                options,
                Some(csv),
                None::<io::Stdout>,
                super::ctrl_c(),
            )
            .await?
        }
        Some(path) => {
            let file = File::create(&path).map_err(|source| CommandError::CreateCsv {
                path: path.clone(),
                source,
            })?;
            let csv = BufWriter::new(file);
            watch::watch(
                &mut client,
                options,
                Some(csv),
                Some(io::stdout()),
                super::ctrl_c(),
            )
            .await?
        }
        None => {
            watch::watch(
                &mut client,
                options,
                None::<File>,
                Some(io::stdout()),
                super::ctrl_c(),
            )
            .await?
        }
    };
    info!(
        target: LOG_TARGET,
        frames = report.frames,
        dropped = report.dropped,
        "watch ended"
    );
    Ok(Outcome::Success)
}
