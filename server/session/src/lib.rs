//! # foveal-session
//!
//! A recorded `foveal-server` session (`foveal-server --record FILE`) and its replay: the
//! configuration, every gaze sample the server's processing received with its receipt time,
//! every frame with the fixation the engine was handed and the engine's report, and every scene
//! change, one JSON object per line (docs/PROTOCOL.md, "Recorded sessions").
//!
//! Shared by the server, which writes sessions, and the bench, which replays them, without
//! either depending on the other. Pure like the engine: no files, threads or clocks; writers
//! and readers are handed in.
//!
//! # Layout
//! - [`format`]: the header and the records.
//! - [`gaze_settings`]: the gaze processing's configuration as the header states it.
//! - [`io`]: [`SessionWriter`] and [`Session::read`], with errors naming the line.
//! - [`replay`]: the closed-loop, bit-for-bit replay and the frame comparison.

pub mod format;
pub mod gaze_settings;
pub mod io;
pub mod replay;

pub use format::{
    FORMAT, FrameRecord, GazeRecord, Header, Record, SceneRecord, ServerSettings, Trailer, VERSION,
};
pub use gaze_settings::GazeSettings;
pub use io::{Session, SessionError, SessionWriter};
pub use replay::{Mismatch, ReplayOutcome, compare, is_deterministic, replay};

#[cfg(test)]
mod tests;
