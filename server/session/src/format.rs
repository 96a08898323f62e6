//! The records of a session file, one JSON object per line (docs/PROTOCOL.md, "Recorded sessions").
//!
//! The first line is the [`Header`]; then [`Record`]s in the order the server produced them
//! (gaze samples as they were accepted, frames as they completed, scene changes at the frame
//! boundary where they took effect); the last line is the [`Trailer`]. Every float is written
//! by serde_json's shortest round-trip formatting and read back with its `float_roundtrip`
//! parser, so a replay sees exactly the bits the server used.

use foveal_engine::{Fixation, FrameReport, SimConfig};
use serde::{Deserialize, Serialize};

use crate::gaze_settings::GazeSettings;

/// The `format` field of every header: tells a session from any other JSON-lines file.
pub const FORMAT: &str = "foveal-session";
/// The version this crate writes and reads. A reader refuses any other: fields change meaning
/// between versions, and a replay that silently misreads one is worse than none.
pub const VERSION: u32 = 1;

/// The first line: what the server was running when the recording started.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Header {
    /// Always [`FORMAT`].
    pub format: String,
    /// Always [`VERSION`] for files this crate writes.
    pub version: u32,
    /// The engine configuration of the first scene (the whole of it: a replay builds the
    /// simulation from this alone).
    pub sim: SimConfig,
    /// Server settings that shaped the frames.
    pub server: ServerSettings,
}

impl Header {
    /// A header of the current format and version.
    pub fn new(sim: SimConfig, server: ServerSettings) -> Self {
        Self {
            format: FORMAT.to_owned(),
            version: VERSION,
            sim,
            server,
        }
    }
}

/// The server's settings that decide which fixation each frame is handed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ServerSettings {
    /// Frame rate of the first scene, frames per second.
    pub frame_rate_hz: f64,
    /// Gaze older than this no longer steered (frames fell back to the screen centre), seconds.
    pub gaze_max_age_s: f64,
    /// The online gaze processing between receipt and fixation.
    pub gaze_processing: GazeSettings,
}

/// One line after the header.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Record {
    /// A gaze sample handed to the online processing.
    Gaze(GazeRecord),
    /// A completed frame.
    Frame(Box<FrameRecord>),
    /// A Configure swap, effective from `first_frame`.
    Scene(Box<SceneRecord>),
    /// The last line.
    End(Trailer),
}

/// A gaze sample as the server's processing received it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct GazeRecord {
    /// Receipt time on the server's clock (seconds since the server's gaze clock started): the
    /// time the processing was given, and the clock [`FrameRecord::t_s`] is on.
    pub received_s: f64,
    /// Which stream or client sent it: `stream:<n>` for the n-th StreamGaze call (from 0),
    /// `push:<source>@<ip>` for PushGaze with its `source` field and the client's address.
    pub source: String,
    /// The sample's time on the tracker's clock, seconds.
    pub tracker_time_s: f64,
    /// Normalised x; `null` when the sample carried no finite value (only a missing sample can).
    pub x: Option<f64>,
    /// Normalised y; `null` as for `x`.
    pub y: Option<f64>,
    /// Validity 0..=1; 0 marks a missing sample (a blink or track loss), recorded because the
    /// processing uses it to detect track loss.
    pub validity: f32,
    /// `unspecified`, `left`, `right` or `binocular`.
    pub eye: String,
    /// The tracker's own fixation flag, if it sent one.
    pub fixation: Option<bool>,
}

/// A completed frame: what the engine was handed and what it reported.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FrameRecord {
    /// The protocol's frame index (counts across scene changes, from 0).
    pub index: u64,
    /// Frame start on the server's clock (same clock as [`GazeRecord::received_s`]), seconds.
    pub t_s: f64,
    /// The fixation handed to `Simulation::step` (x, y and age at frame start).
    pub fixation: Fixation,
    /// Where it came from: `gaze`, `fallback_no_gaze`, `fallback_stale` or
    /// `fallback_track_lost`.
    pub fixation_source: String,
    /// The engine's report of the frame (its `index` counts from 0 in each scene).
    pub report: FrameReport,
}

/// A Configure swap.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SceneRecord {
    /// Protocol index of the first frame simulated with the new scene.
    pub first_frame: u64,
    /// Its frame rate, frames per second.
    pub frame_rate_hz: f64,
    /// Its whole engine configuration.
    pub sim: SimConfig,
}

/// The last line: what the recording could not keep.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct Trailer {
    /// Frame records written.
    pub frames: u64,
    /// Gaze records written.
    pub gaze_samples: u64,
    /// Scene records written.
    pub scenes: u64,
    /// Records the frame loop or a gaze handler could not hand to the writer because it had
    /// fallen behind (dropped rather than stall a frame). A session with drops does not replay
    /// past its first missing frame.
    pub dropped: u64,
}
