//! Everything that can stop a bench command, in one place so that every module reports through
//! it without importing back from the crate root.

use std::path::{Path, PathBuf};

use foveal_engine::ConfigError;

use crate::gaze::GazeError;

/// Everything that can stop a study.
#[derive(Debug, thiserror::Error)]
pub enum BenchError {
    /// The engine refused a configuration.
    #[error(transparent)]
    Config(#[from] ConfigError),
    /// The gaze trace could not be used.
    #[error(transparent)]
    Gaze(#[from] GazeError),
    /// A recorded session could not be read.
    #[error("session {path}: {source}")]
    Session {
        /// The file.
        path: PathBuf,
        /// What is wrong with it (the line, for a damaged file).
        source: foveal_session::SessionError,
    },
    /// A file could not be written.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// A figure could not be drawn.
    #[error("figure {path}: {msg}")]
    Plot {
        /// The file.
        path: PathBuf,
        /// What plotters said.
        msg: String,
    },
    /// A sharded run or a merge failed (the shard, the partial and the cells are named).
    #[error(transparent)]
    Shard(#[from] crate::shard_error::ShardError),
    /// The study configuration is unusable.
    #[error("invalid study: {0}")]
    Invalid(String),
}

impl BenchError {
    /// An I/O failure on `path`.
    pub(crate) fn io(path: &Path, source: std::io::Error) -> Self {
        Self::Io {
            path: path.to_owned(),
            source,
        }
    }
}
