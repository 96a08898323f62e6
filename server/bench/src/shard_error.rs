//! What can stop a sharded run or a merge, and the names a partial file carries.
//!
//! Apart from `shard` because `shard` imports the runner and the open loop, which report through
//! [`crate::error::BenchError`]; with this enum in `shard`, `BenchError`'s `Shard` variant would
//! close a circle of imports. This module imports nothing of the crate.

use std::path::{Path, PathBuf};

/// What a partial file says it is; a merge refuses any other.
pub const PARTIAL_FORMAT: &str = "foveal-bench partial 1";

/// The file-name ending of partial results: `merge DIR` reads every such file in `DIR`.
pub const PARTIAL_SUFFIX: &str = ".partial.json";

/// Most cells a merge error lists by name before it counts the rest.
const LISTED: usize = 30;

/// What can stop a sharded run or a merge.
#[derive(Debug, thiserror::Error)]
pub enum ShardError {
    /// `--shard` is not `I/N`.
    #[error("shard {value:?}: expected I/N with 0 <= I < N (for example 0/8)")]
    Syntax {
        /// The value given.
        value: String,
    },
    /// The index is not below the count.
    #[error("shard index {index} is out of range: shards are numbered 0 to {} of {count}", count.saturating_sub(1))]
    OutOfRange {
        /// The index.
        index: u64,
        /// The count.
        count: u64,
    },
    /// No shards at all.
    #[error("the shard count must be at least 1 (got 0)")]
    ZeroCount,
    /// An environment variable that carries the index or count is not a number.
    #[error("{var}={value:?} is not a non-negative integer")]
    Env {
        /// The variable.
        var: &'static str,
        /// Its value.
        value: String,
    },
    /// An index came from the environment, but not how many shards there are.
    #[error(
        "{var} gives this task's shard index, but not the number of shards: pass --shards N (or \
         set FOVEAL_SHARDS) to the same N as the Job's completions or the array's size"
    )]
    MissingCount {
        /// The variable that gave the index.
        var: &'static str,
    },
    /// A count was given without any index.
    #[error(
        "--shards {count} without a shard index: give --shard I/{count}, or run as a Kubernetes \
         indexed Job (JOB_COMPLETION_INDEX) or a Slurm array task (SLURM_ARRAY_TASK_ID)"
    )]
    CountWithoutIndex {
        /// The count.
        count: u64,
    },
    /// Two cells of the protocol have the same name.
    #[error("cell {0} appears twice in the protocol (a budget or N given twice?)")]
    DuplicateCell(String),
    /// A file could not be read or written.
    #[error("{path}: {source}")]
    Io {
        /// The file or directory.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// A partial could not be decoded.
    #[error("{path}: not a foveal-bench partial result: {source}")]
    Parse {
        /// The file.
        path: PathBuf,
        /// What the decoder said.
        source: serde_json::Error,
    },
    /// A partial could not be encoded.
    #[error("encoding the partial result: {0}")]
    Encode(serde_json::Error),
    /// Nothing to merge.
    #[error("no partial result (*{PARTIAL_SUFFIX}) in {0}")]
    NoPartials(String),
    /// A partial of another format.
    #[error("{path}: format {found:?}; this foveal-bench reads {PARTIAL_FORMAT:?}")]
    Format {
        /// The file.
        path: PathBuf,
        /// Its format.
        found: String,
    },
    /// Partials of different commands (`study`, `open-loop`).
    #[error("{path} is a partial of `{found}`, {first} of `{expected}`")]
    Command {
        /// The odd file.
        path: PathBuf,
        /// Its command.
        found: String,
        /// The first file.
        first: PathBuf,
        /// The first file's command.
        expected: String,
    },
    /// Partials of different protocols.
    #[error(
        "{path} ran protocol {found}, {first} ran protocol {expected}: the shards of one run must \
         be given the same protocol flags"
    )]
    Protocol {
        /// The odd file.
        path: PathBuf,
        /// Its protocol hash.
        found: String,
        /// The first file.
        first: PathBuf,
        /// The first file's hash.
        expected: String,
    },
    /// The protocol recorded in a partial is not the one its flags give in this build.
    #[error(
        "{path}: its flags give protocol {here} in this foveal-bench, but the shard ran protocol \
         {recorded}: merge with the build the shards ran"
    )]
    ProtocolDrift {
        /// The file.
        path: PathBuf,
        /// The hash recorded.
        recorded: String,
        /// The hash its flags give here.
        here: String,
    },
    /// Partials computed by different engine sources.
    #[error(
        "{path} was computed by engine sources {found}, {first} by {expected}: rerun the shards \
         from one build"
    )]
    Engine {
        /// The odd file.
        path: PathBuf,
        /// Its engine hash.
        found: String,
        /// The first file.
        first: PathBuf,
        /// The first file's hash.
        expected: String,
    },
    /// A partial holds a cell the protocol does not have.
    #[error("{path}: cell {cell} is not a cell of the protocol")]
    UnknownCell {
        /// The file.
        path: PathBuf,
        /// The cell.
        cell: String,
    },
    /// A cell's record does not fit the protocol's shape.
    #[error("{path}: cell {cell}: {what}")]
    Shape {
        /// The file.
        path: PathBuf,
        /// The cell.
        cell: String,
        /// What does not fit.
        what: String,
    },
    /// The partials do not cover the protocol's cells exactly once.
    #[error("{}", coverage_message(missing_shards, missing, *total, doubled))]
    Coverage {
        /// Shards (`I/N`) of which no partial was given.
        missing_shards: Vec<String>,
        /// Cells no partial holds.
        missing: Vec<String>,
        /// Cells in the protocol.
        total: usize,
        /// Cells more than one partial holds, with those files.
        doubled: Vec<(String, Vec<PathBuf>)>,
    },
}

impl ShardError {
    pub(crate) fn io(path: &Path, source: std::io::Error) -> Self {
        Self::Io {
            path: path.to_owned(),
            source,
        }
    }
}

fn listed(names: impl ExactSizeIterator<Item = String>) -> String {
    let total = names.len();
    let mut v: Vec<String> = names.take(LISTED).collect();
    if total > LISTED {
        v.push(format!("and {} more", total - LISTED));
    }
    v.join(", ")
}

fn coverage_message(
    missing_shards: &[String],
    missing: &[String],
    total: usize,
    doubled: &[(String, Vec<PathBuf>)],
) -> String {
    let mut parts = Vec::new();
    if !missing.is_empty() {
        let shards = if missing_shards.is_empty() {
            String::new()
        } else {
            format!(" (no partial of shard {})", missing_shards.join(", "))
        };
        parts.push(format!(
            "{} of {total} cells missing{shards}: {}",
            missing.len(),
            listed(missing.iter().cloned())
        ));
    }
    if !doubled.is_empty() {
        // By the files that hold them: a shard run twice names its two partials once.
        let mut by_files: Vec<(&[PathBuf], Vec<String>)> = Vec::new();
        for (cell, files) in doubled {
            match by_files.iter_mut().find(|(f, _)| *f == files.as_slice()) {
                Some((_, cells)) => cells.push(cell.clone()),
                None => by_files.push((files, vec![cell.clone()])),
            }
        }
        let groups: Vec<String> = by_files
            .into_iter()
            .map(|(files, cells)| {
                let files: Vec<String> = files.iter().map(|f| f.display().to_string()).collect();
                format!(
                    "{} in each of {}: {}",
                    cells.len(),
                    files.join(" and "),
                    listed(cells.into_iter())
                )
            })
            .collect();
        parts.push(format!(
            "{} cells in more than one partial ({})",
            doubled.len(),
            groups.join("; ")
        ));
    }
    parts.join("; ")
}
