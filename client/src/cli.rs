//! The command line of the `foveal` binary: its subcommands and flags (clap), and what each
//! subcommand's flags describe, as the [`crate::commands`] that run it take it.
//!
//! The binary parses a [`Cli`] and makes one call per [`Command`], e.g. for `foveal gaze`:
//! `commands::send(&args.server(), args.send(), args.input())`.

use std::path::PathBuf;
use std::time::Duration;

use clap::{Args, Parser, Subcommand, ValueEnum};

use crate::commands::{
    Detector, FixationsCommand, GazeInput, LoadCommand, LslInput, LslUnits, PupilInput,
    SendOptions, Server, Speed, WatchCommand, psych,
};
use crate::gaze::opengaze;
use crate::gaze::script::GazeScript;
use crate::gaze::{Binocular, Eye, ScreenPx};
use crate::sender::Transport;
use crate::source::GazepointOptions;
use crate::watch::WatchOptions;

/// Client of the foveal collision server: send gaze, bridge eye trackers, watch frames.
///
/// Logs go to stderr (filter with RUST_LOG, e.g. RUST_LOG=debug); results go to stdout.
#[derive(Debug, Parser)]
#[command(name = "foveal", version, about)]
pub struct Cli {
    /// The subcommand.
    #[command(subcommand)]
    pub command: Command,
}

/// A subcommand and its flags.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Send scripted or recorded gaze, paced in real time, and print the server's summary.
    Gaze(GazeArgs),
    /// Forward a live or recorded eye-tracker stream to the server.
    Bridge(BridgeArgs),
    /// Watch frames: a summary line per second, optionally every frame as CSV.
    Watch(WatchArgs),
    /// Check the server's gRPC health; exit 0 if SERVING, 1 otherwise.
    Health(HealthArgs),
    /// Detect fixations in a recording (CSV or ASC, mono or binocular) with the server's online
    /// detector; print them as CSV (`eye,start_s,end_s,x_px,y_px`, seconds from the first
    /// sample), and with --compare the agreement with a reference list as `#` lines.
    Fixations(FixationsArgs),
    /// Load the server with gaze streams and watchers (some never reading) and measure the loop:
    /// frame rate, step-time p99, samples sent versus accepted, server RSS over time.
    Load(LoadArgs),
    /// Psychophysics: fit the perceptual functions F1, F2 and F3 to a viewer's responses, or
    /// check the fit on simulated viewers.
    #[command(subcommand)]
    Psych(PsychCommand),
}

/// `foveal psych` subcommands.
#[derive(Debug, Subcommand)]
pub enum PsychCommand {
    /// Fit F1, F2 and F3 by maximum likelihood to results CSVs (columns `participant`,
    /// `eccentricity_deg`, `gap_deg`, `response` = apart|touching, optional `valid`), pooled and
    /// per participant; print the report, F2's C with its bootstrap interval and the model
    /// string `--schedule-model` takes.
    Fit(PsychFitArgs),
    /// Simulate viewers with a known F2 (400 trials each by default), fit each, and report how
    /// often the fit recovers C within 20% and how often its 95% interval covers it; exit 1
    /// when coverage is under 90%.
    Simulate(PsychSimulateArgs),
}

/// Flags of `foveal psych fit`.
#[derive(Debug, Args)]
pub struct PsychFitArgs {
    /// Results CSVs.
    #[arg(required = true)]
    results: Vec<PathBuf>,
    /// Also write the report (fit.md), the figure (fit.svg) and the pooled F2 model string
    /// (model.txt) in this directory.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Bootstrap replicates for F2's interval.
    #[arg(long, default_value_t = 200, value_parser = clap::value_parser!(u32).range(20..=100_000))]
    replicates: u32,
    /// Cross-validation folds.
    #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u32).range(2..=100))]
    folds: u32,
    /// Seed of the bootstrap and the folds.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// F3's breaks, E1,E2 in degrees (E1 < E2).
    #[arg(long, default_value = "2.5,10", value_parser = parse_breaks)]
    f3_breaks: (f64, f64),
    /// Fit the pooled trials only, not each participant apart.
    #[arg(long)]
    pooled_only: bool,
    /// Fit only the trials whose COLUMN holds VALUE, as written in the CSV (repeatable; all must
    /// hold): `--where distractors=8` fits one distractor level of experiment 3 or 4,
    /// `--where design=experiment2` one experiment of several files.
    #[arg(long = "where", value_name = "COLUMN=VALUE", value_parser = parse_selection)]
    selection: Vec<(String, String)>,
}

fn parse_selection(text: &str) -> Result<(String, String), String> {
    let (c, v) = text
        .split_once('=')
        .ok_or_else(|| format!("{text:?} is not COLUMN=VALUE"))?;
    let (c, v) = (c.trim(), v.trim());
    if c.is_empty() || v.is_empty() || c.contains(',') || v.contains(',') {
        return Err(format!(
            "{text:?}: COLUMN and VALUE must be non-empty, without commas"
        ));
    }
    Ok((c.to_owned(), v.to_owned()))
}

fn parse_breaks(text: &str) -> Result<(f64, f64), String> {
    let (a, b) = text
        .split_once(',')
        .ok_or_else(|| format!("{text:?} is not E1,E2"))?;
    let number = |s: &str| {
        s.trim()
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite() && *v >= 0.0)
            .ok_or_else(|| format!("{s:?} is not a finite number of degrees >= 0"))
    };
    let (a, b) = (number(a)?, number(b)?);
    if a >= b {
        return Err(format!("E1 = {a} must be below E2 = {b}"));
    }
    Ok((a, b))
}

fn positive(text: &str) -> Result<f64, String> {
    text.parse::<f64>()
        .ok()
        .filter(|v| v.is_finite() && *v > 0.0)
        .ok_or_else(|| format!("{text:?} is not a finite number > 0"))
}

fn rate(text: &str) -> Result<f64, String> {
    text.parse::<f64>()
        .ok()
        .filter(|v| (0.0..0.1).contains(v))
        .ok_or_else(|| format!("{text:?} is not a rate in [0, 0.1)"))
}

/// Flags of `foveal psych simulate`.
#[derive(Debug, Args)]
pub struct PsychSimulateArgs {
    /// The viewers' true C (degrees).
    #[arg(long, default_value_t = 4.0, value_parser = positive)]
    c: f64,
    /// Their Weibull threshold α (degrees of gap).
    #[arg(long, default_value_t = 0.05, value_parser = positive)]
    alpha: f64,
    /// Their Weibull slope β.
    #[arg(long, default_value_t = 2.5, value_parser = positive)]
    beta: f64,
    /// Their guess (false-alarm) rate.
    #[arg(long, default_value_t = 0.05, value_parser = rate)]
    guess: f64,
    /// Their lapse rate.
    #[arg(long, default_value_t = 0.02, value_parser = rate)]
    lapse: f64,
    /// Viewers simulated.
    #[arg(long, default_value_t = 50, value_parser = clap::value_parser!(u32).range(1..=10_000))]
    observers: u32,
    /// Repetitions of each cell of the design (5 eccentricities x 4 gaps, each with as many
    /// touching trials): 10 makes 400 trials.
    #[arg(long, default_value_t = 10, value_parser = clap::value_parser!(u32).range(1..=1_000))]
    repetitions: u32,
    /// Bootstrap replicates per viewer.
    #[arg(long, default_value_t = 200, value_parser = clap::value_parser!(u32).range(20..=100_000))]
    replicates: u32,
    /// Seed (viewer i draws from seed + i).
    #[arg(long, default_value_t = 1000)]
    seed: u64,
    /// Also write every simulated trial to this results CSV (participants `sim<seed + i>`),
    /// for `foveal psych fit`.
    #[arg(long)]
    trials_out: Option<PathBuf>,
}

impl PsychFitArgs {
    /// The fit.
    pub fn command(&self) -> psych::FitCommand {
        psych::FitCommand {
            results: self.results.clone(),
            out: self.out.clone(),
            selection: self.selection.clone(),
            options: foveal_psych::report::Options {
                replicates: self.replicates as usize,
                folds: self.folds as usize,
                seed: self.seed,
                f3_breaks: [self.f3_breaks.0, self.f3_breaks.1],
                per_participant: !self.pooled_only,
            },
        }
    }
}

impl PsychSimulateArgs {
    /// The simulation.
    pub fn command(&self) -> psych::SimulateCommand {
        psych::SimulateCommand {
            observer: psych::f2_observer(self.c, self.alpha, self.beta, self.guess, self.lapse),
            observers: self.observers as usize,
            repetitions: self.repetitions,
            replicates: self.replicates as usize,
            seed: self.seed,
            trials_out: self.trials_out.clone(),
        }
    }
}

#[derive(Debug, Clone, Copy, ValueEnum)]
enum DetectorArg {
    /// Velocity threshold (I-VT).
    Ivt,
    /// Dispersion threshold (I-DT).
    Idt,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
enum EyesArg {
    /// Mean of the valid eyes.
    Mean,
    /// Left eye only.
    Left,
    /// Right eye only.
    Right,
    /// Each eye detected apart.
    Both,
}

impl EyesArg {
    fn binocular(self) -> Binocular {
        match self {
            Self::Mean => Binocular::Mean,
            Self::Left => Binocular::Left,
            Self::Right => Binocular::Right,
            Self::Both => Binocular::Both,
        }
    }
}

/// The eyes of a binocular recording, for the bridges and replays.
#[derive(Debug, Args)]
struct EyesOpt {
    /// Eyes of a binocular recording to send: their mean, one of them, or both (two samples an
    /// instant, each tagged with its eye, for a server that combines them itself:
    /// foveal-server --gaze-eyes). A monocular recording sends its one eye.
    #[arg(long, value_enum, default_value = "mean")]
    eyes: EyesArg,
}

/// The flags of `foveal fixations`.
#[derive(Debug, Args)]
pub struct FixationsArgs {
    /// The recording.
    file: PathBuf,
    /// A reference fixation list (`eye,start_s,end_s,x_px,y_px`) to score against (Hooge et al.
    /// 2018: precision, recall, F1, onset and offset differences).
    #[arg(long)]
    compare: Option<PathBuf>,
    /// Detector.
    #[arg(long, value_enum, default_value = "ivt")]
    detector: DetectorArg,
    /// I-VT velocity threshold, degrees per second (default 30, Olsen 2012).
    #[arg(long)]
    velocity_threshold: Option<f64>,
    /// I-DT dispersion threshold, degrees (default 1.0, Salvucci and Goldberg 2000).
    #[arg(long)]
    dispersion: Option<f64>,
    /// Shortest fixation, milliseconds (default 60 for I-VT, 100 for I-DT).
    #[arg(long)]
    min_duration_ms: Option<f64>,
    /// Eyes of a binocular recording.
    #[arg(long, value_enum, default_value = "mean")]
    eyes: EyesArg,
    /// Physical screen size, WIDTHxHEIGHT in cm (default 53.1x29.9, a 24-inch 16:9 monitor).
    #[arg(long, value_parser = parse_size_cm)]
    screen_cm: Option<(f64, f64)>,
    /// Eye to screen distance, cm (default 60).
    #[arg(long)]
    distance_cm: Option<f64>,
    #[command(flatten)]
    screen: ScreenArg,
}

fn parse_size_cm(text: &str) -> Result<(f64, f64), String> {
    let (w, h) = text
        .split_once(['x', 'X'])
        .ok_or_else(|| format!("{text:?} is not WIDTHxHEIGHT"))?;
    let number = |s: &str| {
        s.trim()
            .parse::<f64>()
            .map_err(|_| format!("{s:?} is not a number"))
    };
    Ok((number(w)?, number(h)?))
}

/// Where the server is.
#[derive(Debug, Args)]
struct ServerArgs {
    /// Server address.
    #[arg(long, global = true, env = "FOVEAL_ADDR", default_value = crate::DEFAULT_ADDR)]
    addr: String,
    /// Bearer token for a server with roles (viewer, gaze or admin, as the command needs).
    /// Prefer the environment variable: a flag's value is visible in the process list.
    #[arg(long, global = true, env = "FOVEAL_TOKEN", hide_env_values = true)]
    token: Option<String>,
    /// CA certificate (PEM) to trust for an `https://` server, instead of the system's roots.
    #[arg(long, global = true, env = "FOVEAL_CA")]
    ca: Option<PathBuf>,
}

/// The flags of `foveal load`.
#[derive(Debug, Args)]
pub struct LoadArgs {
    #[command(flatten)]
    server: ServerArgs,
    /// Token for the gaze streams (default: --token).
    #[arg(long, env = "FOVEAL_GAZE_TOKEN", hide_env_values = true)]
    gaze_token: Option<String>,
    /// Token for the watchers and status calls (default: --token).
    #[arg(long, env = "FOVEAL_VIEWER_TOKEN", hide_env_values = true)]
    viewer_token: Option<String>,
    /// Gaze streams (M).
    #[arg(long, default_value_t = 8)]
    streams: usize,
    /// Samples per second per gaze stream.
    #[arg(long, default_value_t = 2000.0)]
    rate: f64,
    /// Watchers (K), stalled ones included.
    #[arg(long, default_value_t = 64)]
    watchers: usize,
    /// Watchers that subscribe and never read a frame (S <= K).
    #[arg(long, default_value_t = 16)]
    stalled: usize,
    /// Watchers ask for poses.
    #[arg(long)]
    poses: bool,
    /// Seconds to run (T); default 60, or 600 with --chaos.
    #[arg(long, visible_alias = "duration")]
    seconds: Option<f64>,
    /// The server's process id, for its RSS (default: the process listening on the port).
    #[arg(long)]
    server_pid: Option<u32>,
    /// A chaos run: the same load while clients are killed mid-call (one a second), 200
    /// connections are left idle and 16 request bodies stalled mid-message (renewed every 10 s),
    /// and Configure is called every second (needs an admin token on a server with roles); a
    /// fresh client's connect and GetStatus is timed every 250 ms throughout.
    #[arg(long)]
    chaos: bool,
    /// Token for Configure in a chaos run (default: --token).
    #[arg(long, env = "FOVEAL_ADMIN_TOKEN", hide_env_values = true)]
    admin_token: Option<String>,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
enum TransportArg {
    /// StreamGaze: one client stream (lowest latency).
    Stream,
    /// PushGaze: unary batches of --batch samples.
    Push,
}

/// How samples travel.
#[derive(Debug, Args)]
struct SendArgs {
    /// Gaze rpc to use.
    #[arg(long, global = true, value_enum, default_value = "stream")]
    transport: TransportArg,
    /// Samples per PushGaze call (with --transport push).
    #[arg(long, global = true, default_value_t = 32)]
    batch: usize,
    /// Stop after this many seconds of tracker time (from the first sample).
    #[arg(long, global = true)]
    duration: Option<f64>,
}

/// Replay speed of a recording.
#[derive(Debug, Args)]
struct SpeedArgs {
    /// Replay speed: 2 sends a 10 s recording in 5 s.
    #[arg(long, default_value_t = 1.0, conflicts_with = "as_fast_as_possible")]
    speed: f64,
    /// Send without waiting between samples.
    #[arg(long)]
    as_fast_as_possible: bool,
}

/// The flags of `foveal gaze`.
#[derive(Debug, Args)]
pub struct GazeArgs {
    #[command(flatten)]
    server: ServerArgs,
    #[command(flatten)]
    send: SendArgs,
    /// Samples per second of scripted gaze (a replay keeps its recording's own rate).
    #[arg(long, global = true, default_value_t = 120.0)]
    rate: f64,
    #[command(subcommand)]
    script: ScriptCommand,
}

#[derive(Debug, Subcommand)]
enum ScriptCommand {
    /// Look at one point.
    Fixed {
        /// x, normalised 0..1 from the left edge.
        #[arg(long, default_value_t = 0.5)]
        x: f64,
        /// y, normalised 0..1 from the top edge.
        #[arg(long, default_value_t = 0.5)]
        y: f64,
    },
    /// Go round a circle (clockwise on screen, starting at its rightmost point).
    Circle {
        /// Centre x, normalised.
        #[arg(long, default_value_t = 0.5)]
        cx: f64,
        /// Centre y, normalised.
        #[arg(long, default_value_t = 0.5)]
        cy: f64,
        /// Radius, normalised.
        #[arg(long, default_value_t = 0.25)]
        radius: f64,
        /// Seconds per turn.
        #[arg(long, default_value_t = 4.0)]
        period: f64,
    },
    /// Random fixations (150-400 ms) joined by saccades.
    Saccades {
        /// Seed of the random sequence.
        #[arg(long, default_value_t = 0)]
        seed: u64,
    },
    /// Replay a recording (CSV or EyeLink ASC, detected from the extension or content).
    Replay {
        /// The recording.
        file: PathBuf,
        #[command(flatten)]
        speed: SpeedArgs,
        #[command(flatten)]
        screen: ScreenArg,
        #[command(flatten)]
        eyes: EyesOpt,
    },
}

/// Screen size for pixel gaze.
#[derive(Debug, Args)]
struct ScreenArg {
    /// Screen size for pixel gaze, WIDTHxHEIGHT (wins over a size declared in the input).
    #[arg(long, value_parser = parse_screen)]
    screen: Option<ScreenPx>,
}

fn parse_screen(text: &str) -> Result<ScreenPx, String> {
    let (w, h) = text
        .split_once(['x', 'X'])
        .ok_or_else(|| format!("{text:?} is not WIDTHxHEIGHT"))?;
    let number = |s: &str| {
        s.trim()
            .parse::<f64>()
            .map_err(|_| format!("{s:?} is not a number"))
    };
    ScreenPx::new(number(w)?, number(h)?).ok_or_else(|| format!("{text:?} is not a valid screen"))
}

/// The flags of `foveal bridge`.
#[derive(Debug, Args)]
pub struct BridgeArgs {
    #[command(flatten)]
    server: ServerArgs,
    #[command(flatten)]
    send: SendArgs,
    #[command(subcommand)]
    tracker: TrackerCommand,
}

#[derive(Debug, Subcommand)]
enum TrackerCommand {
    /// CSV gaze from a file, sent at the file's own pace (its timestamps; --speed to change),
    /// or with `-` or nothing from stdin, forwarded line by line as the lines arrive. Layouts:
    /// `t_s,x,y[,validity][,fixation]` (normalised) or `t_s,xpos,ypos` (pixels; screen size
    /// from --screen or a `# screen WxH px` comment), or either with `_left`/`_right` columns.
    Csv {
        /// The file, or `-` for stdin.
        file: Option<PathBuf>,
        /// Pace by the timestamps at this speed (a file's default is 1, stdin's is to forward
        /// lines as they arrive).
        #[arg(long, conflicts_with = "as_fast_as_possible")]
        speed: Option<f64>,
        /// Send a file without waiting between samples. A server's gaze rate limit then drops
        /// most of a long recording (the bridge says how much before it starts).
        #[arg(long)]
        as_fast_as_possible: bool,
        #[command(flatten)]
        screen: ScreenArg,
        #[command(flatten)]
        eyes: EyesOpt,
    },
    /// An EyeLink ASC file, replayed at its own pace.
    Asc {
        /// The file.
        file: PathBuf,
        #[command(flatten)]
        speed: SpeedArgs,
        #[command(flatten)]
        screen: ScreenArg,
        #[command(flatten)]
        eyes: EyesOpt,
    },
    /// A Gazepoint tracker over the Open Gaze API (TCP).
    Gazepoint {
        /// Tracker host.
        #[arg(long, default_value = "127.0.0.1")]
        host: String,
        /// Tracker port.
        #[arg(long, default_value_t = opengaze::DEFAULT_PORT)]
        port: u16,
        /// Reconnection attempts per outage before giving up.
        #[arg(long, default_value_t = 5)]
        retries: u32,
    },
    /// A Pupil Core tracker (Pupil Capture or Service) over its network API: asks Pupil Remote
    /// for the SUB port and subscribes to gaze. `norm_pos` is in the world camera's image unless
    /// --surface maps it onto a surface (e.g. one marked on the display); y is flipped to
    /// foveal's top-left origin. Pupil's eye 0 is the right eye. Gaze below --min-confidence is
    /// sent as a missing sample. The Pupil timestamp is the tracker time.
    Pupil {
        /// Pupil Remote host.
        #[arg(long, default_value = "127.0.0.1")]
        host: String,
        /// Pupil Remote port.
        #[arg(long, default_value_t = crate::gaze::pupil::DEFAULT_REMOTE_PORT)]
        port: u16,
        /// Gaze topic prefix to subscribe to, e.g. gaze.3d.01. for binocular 3D gaze only.
        #[arg(long, default_value = "gaze.")]
        topic: String,
        /// Subscribe to surfaces.NAME and send its gaze_on_surfaces (surface coordinates).
        #[arg(long, value_name = "NAME")]
        surface: Option<String>,
        /// Only this eye's gaze (left = Pupil's eye 1, right = eye 0).
        #[arg(long, value_enum, default_value = "any")]
        eye: PupilEyeArg,
        /// Confidence below which gaze is sent as missing (Pupil Labs recommend 0.6).
        #[arg(long, default_value_t = crate::gaze::pupil::DEFAULT_MIN_CONFIDENCE)]
        min_confidence: f64,
        /// Seconds allowed to connect, and for each answer of Pupil Remote (it is asked for its
        /// clock every second, so a vanished Pupil ends the bridge within this).
        #[arg(long, default_value_t = 3.0)]
        connect_timeout: f64,
    },
    /// A Lab Streaming Layer outlet, found by type (and name) on this machine or the local
    /// network, spoken to in LSL's own protocol (no liblsl needed). Time stamps get the outlet's
    /// clock correction, so they are on this machine's LSL clock. A NaN channel value is sent as
    /// a missing sample.
    Lsl {
        /// Stream type to resolve.
        #[arg(long = "type", default_value = "Gaze")]
        type_: String,
        /// Stream name, when the type alone is ambiguous.
        #[arg(long)]
        name: Option<String>,
        /// Index of the channel holding x.
        #[arg(long, default_value_t = 0)]
        x_channel: usize,
        /// Index of the channel holding y.
        #[arg(long, default_value_t = 1)]
        y_channel: usize,
        /// Units of x and y (origin top-left either way); pixels need --screen.
        #[arg(long, value_enum, default_value = "normalised")]
        units: UnitsArg,
        #[command(flatten)]
        screen: ScreenArg,
        /// Seconds to look for the stream and to connect to it.
        #[arg(long, default_value_t = 5.0)]
        resolve_timeout: f64,
        /// Keep the outlet's time stamps on its own clock.
        #[arg(long)]
        no_time_correction: bool,
        /// When the outlet goes away, exit with an error (status 1) instead of waiting for it to
        /// come back (found again by name, type and source id) and carrying on.
        #[arg(long)]
        no_reconnect: bool,
    },
}

#[derive(Debug, Clone, Copy, ValueEnum)]
enum PupilEyeArg {
    /// Every gaze datum.
    Any,
    /// Eye 1 only.
    Left,
    /// Eye 0 only.
    Right,
    /// Gaze of both eyes mapped together only.
    Binocular,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
enum UnitsArg {
    /// 0..1 of the screen.
    Normalised,
    /// Screen pixels (give --screen).
    Pixels,
}

/// The flags of `foveal watch`.
#[derive(Debug, Args)]
pub struct WatchArgs {
    #[command(flatten)]
    server: ServerArgs,
    /// Receive every K-th frame.
    #[arg(long, default_value_t = 1)]
    every: u32,
    /// Ask for body poses (the summary then shows the body count).
    #[arg(long)]
    poses: bool,
    /// Write every received frame's metrics to this CSV file (`-` for stdout, which then
    /// carries no summary lines).
    #[arg(long)]
    csv: Option<PathBuf>,
    /// Exit after this many frames.
    #[arg(long)]
    frames: Option<u64>,
}

/// The flags of `foveal health`.
#[derive(Debug, Args)]
pub struct HealthArgs {
    #[command(flatten)]
    server: ServerArgs,
    /// Service to ask about: "" for the whole server, or foveal.v1.Foveal.
    #[arg(long, default_value = "")]
    service: String,
    /// Connect and call timeout, milliseconds.
    #[arg(long, default_value_t = 2000)]
    timeout_ms: u64,
}

impl ServerArgs {
    fn server(&self) -> Server {
        Server {
            addr: self.addr.clone(),
            token: self.token.clone(),
            ca: self.ca.clone(),
        }
    }
}

impl SendArgs {
    fn send(&self) -> SendOptions {
        let transport = match self.transport {
            TransportArg::Stream => Transport::Stream,
            TransportArg::Push => Transport::Push { batch: self.batch },
        };
        SendOptions {
            transport,
            duration_s: self.duration,
        }
    }
}

impl SpeedArgs {
    fn speed(&self) -> Speed {
        Speed {
            speed: self.speed,
            as_fast_as_possible: self.as_fast_as_possible,
        }
    }
}

impl GazeArgs {
    /// The server to send to.
    pub fn server(&self) -> Server {
        self.server.server()
    }

    /// How samples travel.
    pub fn send(&self) -> SendOptions {
        self.send.send()
    }

    /// The script or recording to send.
    pub fn input(&self) -> GazeInput {
        self.script.input(self.rate)
    }
}

impl BridgeArgs {
    /// The server to send to.
    pub fn server(&self) -> Server {
        self.server.server()
    }

    /// How samples travel.
    pub fn send(&self) -> SendOptions {
        self.send.send()
    }

    /// The tracker or file to forward.
    pub fn input(&self) -> GazeInput {
        self.tracker.input()
    }
}

impl HealthArgs {
    /// The server to ask.
    pub fn server(&self) -> Server {
        self.server.server()
    }

    /// The service to ask about ("" for the whole server).
    pub fn service(&self) -> &str {
        &self.service
    }

    /// The connect and call timeout.
    pub fn timeout(&self) -> Duration {
        Duration::from_millis(self.timeout_ms)
    }
}

impl ScriptCommand {
    fn input(&self, rate_hz: f64) -> GazeInput {
        let script = match *self {
            Self::Fixed { x, y } => GazeScript::Fixed { x, y },
            Self::Circle {
                cx,
                cy,
                radius,
                period,
            } => GazeScript::Circle {
                cx,
                cy,
                radius,
                period_s: period,
            },
            Self::Saccades { seed } => GazeScript::Saccades { seed },
            Self::Replay {
                ref file,
                ref speed,
                ref screen,
                ref eyes,
            } => {
                return GazeInput::Replay {
                    file: file.clone(),
                    speed: speed.speed(),
                    screen: screen.screen,
                    eyes: eyes.eyes.binocular(),
                };
            }
        };
        GazeInput::Script { script, rate_hz }
    }
}

impl TrackerCommand {
    fn input(&self) -> GazeInput {
        match self {
            Self::Csv {
                file,
                speed,
                as_fast_as_possible,
                screen,
                eyes,
            } => GazeInput::Csv {
                file: file.clone(),
                speed: *speed,
                as_fast_as_possible: *as_fast_as_possible,
                screen: screen.screen,
                eyes: eyes.eyes.binocular(),
            },
            Self::Asc {
                file,
                speed,
                screen,
                eyes,
            } => GazeInput::Asc {
                file: file.clone(),
                speed: speed.speed(),
                screen: screen.screen,
                eyes: eyes.eyes.binocular(),
            },
            Self::Gazepoint {
                host,
                port,
                retries,
            } => GazeInput::Gazepoint(GazepointOptions {
                host: host.clone(),
                port: *port,
                max_retries: *retries,
                ..GazepointOptions::default()
            }),
            Self::Pupil {
                host,
                port,
                topic,
                surface,
                eye,
                min_confidence,
                connect_timeout,
            } => GazeInput::Pupil(PupilInput {
                host: host.clone(),
                port: *port,
                topic: topic.clone(),
                surface: surface.clone(),
                eye: match eye {
                    PupilEyeArg::Any => None,
                    PupilEyeArg::Left => Some(Eye::Left),
                    PupilEyeArg::Right => Some(Eye::Right),
                    PupilEyeArg::Binocular => Some(Eye::Binocular),
                },
                min_confidence: *min_confidence,
                connect_timeout_s: *connect_timeout,
            }),
            Self::Lsl {
                type_,
                name,
                x_channel,
                y_channel,
                units,
                screen,
                resolve_timeout,
                no_time_correction,
                no_reconnect,
            } => GazeInput::Lsl(LslInput {
                type_: type_.clone(),
                name: name.clone(),
                x_channel: *x_channel,
                y_channel: *y_channel,
                units: match units {
                    UnitsArg::Normalised => LslUnits::Normalised,
                    UnitsArg::Pixels => LslUnits::Pixels,
                },
                screen: screen.screen,
                resolve_timeout_s: *resolve_timeout,
                time_correction: !no_time_correction,
                reconnect: !no_reconnect,
            }),
        }
    }
}

impl WatchArgs {
    /// The server to watch.
    pub fn server(&self) -> Server {
        self.server.server()
    }

    /// What to watch.
    pub fn command(&self) -> WatchCommand {
        WatchCommand {
            options: WatchOptions {
                every_k: self.every,
                poses: self.poses,
                frames: self.frames,
                ..WatchOptions::default()
            },
            csv: self.csv.clone(),
        }
    }
}

impl FixationsArgs {
    /// What to detect, and how.
    pub fn command(&self) -> FixationsCommand {
        FixationsCommand {
            file: self.file.clone(),
            compare: self.compare.clone(),
            detector: match self.detector {
                DetectorArg::Ivt => Detector::Ivt,
                DetectorArg::Idt => Detector::Idt,
            },
            velocity_threshold: self.velocity_threshold,
            dispersion: self.dispersion,
            min_duration_ms: self.min_duration_ms,
            eyes: self.eyes.binocular(),
            screen_cm: self.screen_cm,
            distance_cm: self.distance_cm,
            screen: self.screen.screen,
        }
    }
}

impl LoadArgs {
    /// The server to load.
    pub fn server(&self) -> Server {
        self.server.server()
    }

    /// The load.
    pub fn command(&self) -> LoadCommand {
        LoadCommand {
            gaze_token: self.gaze_token.clone(),
            viewer_token: self.viewer_token.clone(),
            streams: self.streams,
            rate_hz: self.rate,
            watchers: self.watchers,
            stalled: self.stalled,
            poses: self.poses,
            seconds: self.seconds,
            server_pid: self.server_pid,
            chaos: self.chaos,
            admin_token: self.admin_token.clone(),
        }
    }
}
