//! What `foveal gaze` and `foveal bridge` send: a script, a recording, CSV lines from stdin or
//! a live tracker, described as the command line gives it ([`GazeInput`]) and opened as a
//! source with the name the server sees and the pace to send it at.

use std::path::{Path, PathBuf};
use std::time::Duration;

use tokio::sync::mpsc;
use tracing::info;

use super::{CommandError, LOG_TARGET};
use crate::bridge;
use crate::gaze::lsl::{ChannelMap, Units};
use crate::gaze::script::{GazeScript, ScriptedGaze};
use crate::gaze::{Binocular, Eye, ScreenPx};
use crate::lsl::{self, LslOptions};
use crate::pacer::Pace;
use crate::pupil::{self, PupilOptions};
use crate::source::{self, GazepointOptions, ReadOptions, RecordingFormat, SourceItem};

/// The gaze a command sends.
#[derive(Debug, Clone)]
pub enum GazeInput {
    /// Scripted gaze at `rate_hz` samples a second, in real time (`foveal gaze fixed|circle|saccades`).
    Script {
        /// The script.
        script: GazeScript,
        /// Samples per second.
        rate_hz: f64,
    },
    /// A recording, its format detected, at its own pace scaled by `speed` (`foveal gaze replay`).
    Replay {
        /// The recording.
        file: PathBuf,
        /// Replay speed.
        speed: Speed,
        /// Screen size for pixel gaze.
        screen: Option<ScreenPx>,
        /// The eyes of a binocular recording to send.
        eyes: Binocular,
    },
    /// CSV gaze (`foveal bridge csv`): a file at its own pace (or `speed`, or unpaced), or with
    /// no file or `-` the lines of stdin as they arrive (or paced by `speed`).
    Csv {
        /// The file; `None` or `-` for stdin.
        file: Option<PathBuf>,
        /// Pace by the timestamps at this speed.
        speed: Option<f64>,
        /// Send a file without waiting between samples.
        as_fast_as_possible: bool,
        /// Screen size for pixel gaze.
        screen: Option<ScreenPx>,
        /// The eyes of a binocular recording to send.
        eyes: Binocular,
    },
    /// An EyeLink ASC file at its own pace scaled by `speed` (`foveal bridge asc`).
    Asc {
        /// The file.
        file: PathBuf,
        /// Replay speed.
        speed: Speed,
        /// Screen size for pixel gaze.
        screen: Option<ScreenPx>,
        /// The eyes of a binocular recording to send.
        eyes: Binocular,
    },
    /// A Gazepoint tracker over the Open Gaze API (`foveal bridge gazepoint`).
    Gazepoint(GazepointOptions),
    /// A Pupil Core tracker (`foveal bridge pupil`).
    Pupil(PupilInput),
    /// A Lab Streaming Layer outlet (`foveal bridge lsl`).
    Lsl(LslInput),
}

/// How fast a recording is replayed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Speed {
    /// 2 sends a 10 s recording in 5 s.
    pub speed: f64,
    /// Send without waiting between samples (wins over `speed`).
    pub as_fast_as_possible: bool,
}

impl Speed {
    /// The pace.
    ///
    /// # Errors
    /// [`CommandError::Usage`] for a speed that is not finite and positive.
    pub fn pace(self) -> Result<Pace, CommandError> {
        if self.as_fast_as_possible {
            return Ok(Pace::AsFastAsPossible);
        }
        Pace::scaled(self.speed).map_err(CommandError::Usage)
    }
}

/// A Pupil Core tracker as the command line gives it.
#[derive(Debug, Clone, PartialEq)]
pub struct PupilInput {
    /// Pupil Remote host.
    pub host: String,
    /// Pupil Remote port.
    pub port: u16,
    /// Gaze topic prefix.
    pub topic: String,
    /// Surface whose gaze to send, if any.
    pub surface: Option<String>,
    /// Only this eye's gaze, or every datum.
    pub eye: Option<Eye>,
    /// Confidence below which gaze is sent as missing.
    pub min_confidence: f64,
    /// Seconds allowed to connect and for each answer of Pupil Remote (`--connect-timeout`).
    pub connect_timeout_s: f64,
}

/// The units of an LSL outlet's x and y channels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LslUnits {
    /// 0..1 of the screen.
    Normalised,
    /// Screen pixels (needs a screen size).
    Pixels,
}

/// A Lab Streaming Layer outlet as the command line gives it.
#[derive(Debug, Clone, PartialEq)]
pub struct LslInput {
    /// Stream type to resolve.
    pub type_: String,
    /// Stream name, when the type alone is ambiguous.
    pub name: Option<String>,
    /// Index of the channel holding x.
    pub x_channel: usize,
    /// Index of the channel holding y.
    pub y_channel: usize,
    /// Units of x and y.
    pub units: LslUnits,
    /// Screen size, for pixels only.
    pub screen: Option<ScreenPx>,
    /// Seconds to look for the stream and to connect to it (`--resolve-timeout`).
    pub resolve_timeout_s: f64,
    /// Add the outlet's clock correction to its time stamps.
    pub time_correction: bool,
    /// Wait for a vanished outlet to come back.
    pub reconnect: bool,
}

/// An input opened: the source name the server sees, the samples, the pace to send them at.
#[derive(Debug)]
pub struct OpenedInput {
    /// The name the sender gives the server, e.g. `replay:session.asc` or `bridge:lsl:Gaze`.
    pub name: String,
    /// The samples.
    pub source: mpsc::Receiver<SourceItem>,
    /// The pace.
    pub pace: Pace,
}

impl GazeInput {
    /// Checks the input's parameters and opens it. A recording is looked ahead into first: one
    /// with nothing to send is an error, an eye it does not have and a pace over a server's
    /// default gaze rate limit are warned about, before anything is sent.
    ///
    /// # Errors
    /// [`CommandError::Usage`] for parameters that cannot work, [`CommandError::Script`],
    /// [`CommandError::Recording`] and [`CommandError::NothingToSend`].
    pub fn open(self) -> Result<OpenedInput, CommandError> {
        let opened = |name: String, source, pace| OpenedInput { name, source, pace };
        Ok(match self {
            Self::Script { script, rate_hz } => open_script(script, rate_hz)?,
            Self::Replay {
                file,
                speed,
                screen,
                eyes,
            } => {
                let pace = speed.pace()?;
                let options = ReadOptions {
                    format: None,
                    screen,
                    eyes,
                };
                let (format, rx) = open_recording(&file, options, pace)?;
                info!(target: LOG_TARGET, file = %file.display(), ?format, "replaying");
                opened(format!("replay:{}", file.display()), rx, pace)
            }
            Self::Csv {
                file,
                speed,
                as_fast_as_possible,
                screen,
                eyes,
            } => open_csv(file, speed, as_fast_as_possible, screen, eyes)?,
            Self::Asc {
                file,
                speed,
                screen,
                eyes,
            } => {
                let pace = speed.pace()?;
                let options = ReadOptions {
                    format: Some(RecordingFormat::Asc),
                    screen,
                    eyes,
                };
                let (_, rx) = open_recording(&file, options, pace)?;
                opened(format!("bridge:asc:{}", file.display()), rx, pace)
            }
            Self::Gazepoint(options) => {
                let name = format!("bridge:gazepoint:{}:{}", options.host, options.port);
                opened(name, source::gazepoint(options), Pace::AsFastAsPossible)
            }
            Self::Pupil(input) => {
                let options = input.options()?;
                let name = format!("bridge:pupil:{}:{}", options.host, options.port);
                opened(name, pupil::pupil(options), Pace::AsFastAsPossible)
            }
            Self::Lsl(input) => {
                let options = input.options()?;
                let label = format!(
                    "bridge:lsl:{}{}",
                    options.type_,
                    options
                        .name
                        .as_deref()
                        .map(|n| format!(":{n}"))
                        .unwrap_or_default()
                );
                opened(label, lsl::lsl(options), Pace::AsFastAsPossible)
            }
        })
    }
}

/// Scripted gaze, in real time.
fn open_script(script: GazeScript, rate_hz: f64) -> Result<OpenedInput, CommandError> {
    let name = match script {
        GazeScript::Fixed { .. } => "fixed",
        GazeScript::Circle { .. } => "circle",
        GazeScript::Saccades { .. } => "saccades",
    };
    let gaze = ScriptedGaze::new(script, rate_hz)?;
    Ok(OpenedInput {
        name: format!("script:{name}"),
        source: source::script(gaze),
        pace: Pace::REAL_TIME,
    })
}

/// CSV gaze: a file at its own pace unless `speed` or `as_fast_as_possible` say otherwise, or
/// (no file, or `-`) the lines of stdin as they arrive unless `speed` paces them.
fn open_csv(
    file: Option<PathBuf>,
    speed: Option<f64>,
    as_fast_as_possible: bool,
    screen: Option<ScreenPx>,
    eyes: Binocular,
) -> Result<OpenedInput, CommandError> {
    let speed = speed
        .map(|s| Pace::scaled(s).map_err(CommandError::Usage))
        .transpose()?;
    let Some(path) = file.as_deref().filter(|p| p.as_os_str() != "-") else {
        // Live lines: sent as they arrive unless a speed is given.
        return Ok(OpenedInput {
            name: "bridge:csv:stdin".to_owned(),
            source: source::stdin_csv(screen, eyes),
            pace: speed.unwrap_or(Pace::AsFastAsPossible),
        });
    };
    let pace = match (speed, as_fast_as_possible) {
        (Some(pace), _) => pace,
        (None, true) => Pace::AsFastAsPossible,
        (None, false) => Pace::REAL_TIME,
    };
    let options = ReadOptions {
        format: Some(RecordingFormat::Csv),
        screen,
        eyes,
    };
    let (_, source) = open_recording(path, options, pace)?;
    Ok(OpenedInput {
        name: format!("bridge:csv:{}", path.display()),
        source,
        pace,
    })
}

impl PupilInput {
    /// The bridge's options, checked.
    ///
    /// # Errors
    /// [`CommandError::Usage`] for a connect timeout or an option that cannot work.
    pub fn options(self) -> Result<PupilOptions, CommandError> {
        let options = PupilOptions {
            host: self.host,
            port: self.port,
            topic: self.topic,
            surface: self.surface,
            eye: self.eye,
            min_confidence: self.min_confidence,
            connect_timeout: seconds("--connect-timeout", self.connect_timeout_s)?,
            ..PupilOptions::default()
        };
        options.check().map_err(CommandError::Usage)?;
        Ok(options)
    }
}

impl LslInput {
    /// The bridge's options, checked.
    ///
    /// # Errors
    /// [`CommandError::Usage`] for units and a screen that do not go together, or a resolve
    /// timeout that cannot work.
    pub fn options(self) -> Result<LslOptions, CommandError> {
        let units = match (self.units, self.screen) {
            (LslUnits::Normalised, None) => Units::Normalised,
            (LslUnits::Normalised, Some(_)) => {
                return Err(CommandError::Usage(
                    "--screen is for --units pixels; normalised gaze needs no screen size".into(),
                ));
            }
            (LslUnits::Pixels, Some(screen)) => Units::Pixels(screen),
            (LslUnits::Pixels, None) => {
                return Err(CommandError::Usage(
                    "--units pixels needs --screen WIDTHxHEIGHT".into(),
                ));
            }
        };
        Ok(LslOptions {
            type_: self.type_,
            name: self.name,
            channels: ChannelMap {
                x: self.x_channel,
                y: self.y_channel,
                units,
            },
            resolve_timeout: seconds("--resolve-timeout", self.resolve_timeout_s)?,
            time_correction: self.time_correction,
            reconnect: self.reconnect,
            ..LslOptions::default()
        })
    }
}

/// Seconds from a flag, checked: finite, positive and at most an hour.
fn seconds(flag: &str, value: f64) -> Result<Duration, CommandError> {
    if !(value.is_finite() && value > 0.0 && value <= 3600.0) {
        return Err(CommandError::Usage(format!(
            "{flag} must be a number of seconds in (0, 3600], not {value}"
        )));
    }
    Ok(Duration::from_secs_f64(value))
}

/// Samples a recording is scanned for before it is sent (its rate, its eyes, whether it has
/// any sample at all): a fraction of a second of reading, however long the file.
const SCAN_SAMPLES: u64 = 100_000;

/// Opens a recording to send at `pace`, after a look ahead: a file with nothing to send is one
/// clear error (not thousands of skipped lines and exit 0), an eye asked of a monocular file
/// and a pace over a server's default gaze rate limit are said before anything is sent.
fn open_recording(
    path: &Path,
    options: ReadOptions,
    pace: Pace,
) -> Result<(RecordingFormat, mpsc::Receiver<SourceItem>), CommandError> {
    let recording_error = |action| {
        move |source| CommandError::Recording {
            action,
            path: path.to_owned(),
            source,
        }
    };
    let scan =
        source::scan_recording(path, options, SCAN_SAMPLES).map_err(recording_error("read"))?;
    if let Some(why) = scan.nothing_to_send(path) {
        return Err(CommandError::NothingToSend(why));
    }
    if options.eyes != Binocular::Mean && !scan.binocular {
        tracing::warn!(
        target: LOG_TARGET,
            "--eyes {:?} has no effect: {} records one eye only ({:?}), which is sent",
            options.eyes,
            path.display(),
            scan.eye.unwrap_or_default()
        );
    }
    if let Some(warning) = bridge::pace_warning(pace, scan.rate_hz, scan.samples, scan.complete) {
        tracing::warn!(target: LOG_TARGET, "{warning}");
    }
    source::recording(path, options).map_err(recording_error("open"))
}
