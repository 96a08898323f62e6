//! `foveal`: the command-line client of a foveal server.
//!
//! Parses arguments, sets up logging (stderr) and calls into the `foveal_client` library;
//! results go to stdout so that they can be piped while logs stay on the terminal.

use std::fs::File;
use std::io::{self, BufWriter};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Duration;

use anyhow::{Context, Result, bail};
use clap::{Args, Parser, Subcommand, ValueEnum};
use foveal_client::ConnectOptions;
use foveal_client::bridge::{self, BridgeReport, ForwardOptions, StopReason};
use foveal_client::gaze::lsl::{ChannelMap, Units};
use foveal_client::gaze::opengaze;
use foveal_client::gaze::script::{GazeScript, ScriptedGaze};
use foveal_client::gaze::{Binocular, Eye, ScreenPx};
use foveal_client::health;
use foveal_client::load::{self, ChaosOptions, LoadOptions};
use foveal_client::lsl::{self, LslOptions};
use foveal_client::pacer::Pace;
use foveal_client::pupil::{self, PupilOptions};
use foveal_client::sender::{GazeSender, Transport};
use foveal_client::source::{self, GazepointOptions, ReadOptions, RecordingFormat, SourceItem};
use foveal_client::watch::{self, WatchOptions};
use tokio::sync::mpsc;
use tracing::info;
use tracing_subscriber::EnvFilter;

/// Client of the foveal collision server: send gaze, bridge eye trackers, watch frames.
///
/// Logs go to stderr (filter with RUST_LOG, e.g. RUST_LOG=debug); results go to stdout.
#[derive(Debug, Parser)]
#[command(name = "foveal", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
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

#[derive(Debug, Args)]
struct FixationsArgs {
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
    #[arg(long, global = true, env = "FOVEAL_ADDR", default_value = foveal_client::DEFAULT_ADDR)]
    addr: String,
    /// Bearer token for a server with roles (viewer, gaze or admin, as the command needs).
    /// Prefer the environment variable: a flag's value is visible in the process list.
    #[arg(long, global = true, env = "FOVEAL_TOKEN", hide_env_values = true)]
    token: Option<String>,
    /// CA certificate (PEM) to trust for an `https://` server, instead of the system's roots.
    #[arg(long, global = true, env = "FOVEAL_CA")]
    ca: Option<PathBuf>,
}

impl ServerArgs {
    fn options(&self) -> Result<ConnectOptions> {
        let ca_pem = match &self.ca {
            Some(path) => {
                Some(std::fs::read(path).with_context(|| format!("read --ca {}", path.display()))?)
            }
            None => None,
        };
        Ok(ConnectOptions {
            token: self.token.clone().filter(|t| !t.is_empty()),
            ca_pem,
        })
    }
}

#[derive(Debug, Args)]
struct LoadArgs {
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

impl SendArgs {
    fn transport(&self) -> Transport {
        match self.transport {
            TransportArg::Stream => Transport::Stream,
            TransportArg::Push => Transport::Push { batch: self.batch },
        }
    }
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

impl SpeedArgs {
    fn pace(&self) -> Result<Pace> {
        if self.as_fast_as_possible {
            return Ok(Pace::AsFastAsPossible);
        }
        Pace::scaled(self.speed).map_err(anyhow::Error::msg)
    }
}

#[derive(Debug, Args)]
struct GazeArgs {
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

#[derive(Debug, Args)]
struct BridgeArgs {
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
        #[arg(long, default_value_t = foveal_client::gaze::pupil::DEFAULT_REMOTE_PORT)]
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
        #[arg(long, default_value_t = foveal_client::gaze::pupil::DEFAULT_MIN_CONFIDENCE)]
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

/// Seconds from a flag, checked: finite and positive.
fn seconds(flag: &str, value: f64) -> Result<Duration> {
    if !(value.is_finite() && value > 0.0 && value <= 3600.0) {
        bail!("{flag} must be a number of seconds in (0, 3600], not {value}");
    }
    Ok(Duration::from_secs_f64(value))
}

#[derive(Debug, Args)]
struct WatchArgs {
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

#[derive(Debug, Args)]
struct HealthArgs {
    #[command(flatten)]
    server: ServerArgs,
    /// Service to ask about: "" for the whole server, or foveal.v1.Foveal.
    #[arg(long, default_value = "")]
    service: String,
    /// Connect and call timeout, milliseconds.
    #[arg(long, default_value_t = 2000)]
    timeout_ms: u64,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    tracing_subscriber::fmt()
        .with_env_filter(
            // zeromq logs each reconnection attempt as a warning; the Pupil bridge reports a
            // Pupil that has gone itself.
            EnvFilter::try_from_default_env()
                .unwrap_or_else(|_| EnvFilter::new("info,zeromq=error")),
        )
        // Colour only on a terminal, and never with NO_COLOR (https://no-color.org): a log
        // piped to a file or another program must read as plain text.
        .with_ansi(
            io::IsTerminal::is_terminal(&io::stderr())
                && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty()),
        )
        .with_writer(io::stderr)
        .init();
    let runtime = match tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
    {
        Ok(runtime) => runtime,
        Err(err) => {
            eprintln!("error: cannot start the async runtime: {err}");
            return ExitCode::FAILURE;
        }
    };
    match runtime.block_on(run(cli)) {
        Ok(code) => code,
        Err(err) => {
            eprintln!("error: {err:#}");
            ExitCode::FAILURE
        }
    }
}

async fn run(cli: Cli) -> Result<ExitCode> {
    match cli.command {
        Command::Gaze(args) => gaze(args).await,
        Command::Bridge(args) => bridge(args).await,
        Command::Watch(args) => watch(args).await,
        Command::Health(args) => health(args).await,
        Command::Fixations(args) => fixations(args),
        Command::Load(args) => run_load(args).await,
    }
}

fn fixations(args: FixationsArgs) -> Result<ExitCode> {
    use foveal_client::gaze::detect::{DetectorParams, IdtParams, IvtParams};
    use foveal_client::gaze::geometry::ViewingGeometry;

    let mut detector = match args.detector {
        DetectorArg::Ivt => DetectorParams::Ivt(IvtParams::default()),
        DetectorArg::Idt => DetectorParams::Idt(IdtParams::default()),
    };
    match &mut detector {
        DetectorParams::Ivt(p) => {
            if args.dispersion.is_some() {
                bail!("--dispersion is an I-DT threshold: use it with --detector idt");
            }
            p.velocity_threshold_deg_s = args
                .velocity_threshold
                .unwrap_or(p.velocity_threshold_deg_s);
            p.min_duration_s = args
                .min_duration_ms
                .map_or(p.min_duration_s, |ms| ms / 1000.0);
        }
        DetectorParams::Idt(p) => {
            if args.velocity_threshold.is_some() {
                bail!("--velocity-threshold is an I-VT threshold: use it with --detector ivt");
            }
            p.max_dispersion_deg = args.dispersion.unwrap_or(p.max_dispersion_deg);
            p.min_duration_s = args
                .min_duration_ms
                .map_or(p.min_duration_s, |ms| ms / 1000.0);
        }
    }
    if let Err(name) = detector.validate() {
        bail!("detector parameter `{name}` must be finite and positive");
    }
    let mut geometry = ViewingGeometry::default();
    if let Some((w, h)) = args.screen_cm {
        (geometry.width_cm, geometry.height_cm) = (w, h);
    }
    geometry.distance_cm = args.distance_cm.unwrap_or(geometry.distance_cm);
    geometry.validate().context("--screen-cm / --distance-cm")?;
    let options = foveal_client::fixations::FixationOptions {
        detector,
        geometry,
        screen: args.screen.screen,
        eyes: args.eyes.binocular(),
    };
    let report = foveal_client::fixations::run(&args.file, args.compare.as_deref(), &options)?;
    for line in report.bad_lines.iter().take(10) {
        eprintln!("skipped: {line}");
    }
    for b in &report.backwards {
        eprintln!(
            "dropped: {} sample(s) of eye {} from t = {:.4} s go back before t = {:.4} s, an \
             earlier sample's time; the detector treats them as missing",
            b.samples, b.eye, b.first_s, b.latest_s
        );
    }
    eprintln!(
        "{} samples ({} missing), {} lines skipped, {} fixations",
        report.samples,
        report.missing,
        report.bad_lines.len(),
        report.fixations.len()
    );
    foveal_client::fixations::write_report(io::stdout().lock(), &report).context("write stdout")?;
    Ok(ExitCode::SUCCESS)
}

/// Completes on Ctrl-C; never, if the signal cannot be listened to.
async fn ctrl_c() {
    if let Err(err) = tokio::signal::ctrl_c().await {
        tracing::warn!("cannot listen for Ctrl-C: {err}");
        std::future::pending::<()>().await;
    }
    info!("interrupted; finishing");
}

async fn gaze(args: GazeArgs) -> Result<ExitCode> {
    let (name, source, pace) = match &args.script {
        ScriptCommand::Replay {
            file,
            speed,
            screen,
            eyes,
        } => {
            let pace = speed.pace()?;
            let options = ReadOptions {
                format: None,
                screen: screen.screen,
                eyes: eyes.eyes.binocular(),
            };
            let (format, rx) = open_recording(file, options, pace)?;
            info!(file = %file.display(), ?format, "replaying");
            (format!("replay:{}", file.display()), rx, pace)
        }
        ScriptCommand::Fixed { .. }
        | ScriptCommand::Circle { .. }
        | ScriptCommand::Saccades { .. } => {
            let (name, script) = match args.script {
                ScriptCommand::Fixed { x, y } => ("fixed", GazeScript::Fixed { x, y }),
                ScriptCommand::Circle {
                    cx,
                    cy,
                    radius,
                    period,
                } => (
                    "circle",
                    GazeScript::Circle {
                        cx,
                        cy,
                        radius,
                        period_s: period,
                    },
                ),
                ScriptCommand::Saccades { seed } => ("saccades", GazeScript::Saccades { seed }),
                ScriptCommand::Replay { .. } => bail!("a replay is not a script"),
            };
            let gaze = ScriptedGaze::new(script, args.rate)?;
            (
                format!("script:{name}"),
                source::script(gaze),
                Pace::REAL_TIME,
            )
        }
    };
    send(&args.server, &args.send, &name, source, pace).await
}

async fn bridge(args: BridgeArgs) -> Result<ExitCode> {
    let (name, source, pace) = match &args.tracker {
        TrackerCommand::Csv {
            file,
            speed,
            as_fast_as_possible,
            screen,
            eyes,
        } => {
            let speed = speed
                .map(|s| Pace::scaled(s).map_err(anyhow::Error::msg))
                .transpose()?;
            let eyes = eyes.eyes.binocular();
            match file.as_deref().filter(|p| p.as_os_str() != "-") {
                // Live lines: sent as they arrive unless a speed is given.
                None => (
                    "bridge:csv:stdin".to_owned(),
                    source::stdin_csv(screen.screen, eyes),
                    speed.unwrap_or(Pace::AsFastAsPossible),
                ),
                Some(path) => {
                    let pace = match (speed, as_fast_as_possible) {
                        (Some(pace), _) => pace,
                        (None, true) => Pace::AsFastAsPossible,
                        (None, false) => Pace::REAL_TIME,
                    };
                    let options = ReadOptions {
                        format: Some(RecordingFormat::Csv),
                        screen: screen.screen,
                        eyes,
                    };
                    let (_, rx) = open_recording(path, options, pace)?;
                    (format!("bridge:csv:{}", path.display()), rx, pace)
                }
            }
        }
        TrackerCommand::Asc {
            file,
            speed,
            screen,
            eyes,
        } => {
            let pace = speed.pace()?;
            let options = ReadOptions {
                format: Some(RecordingFormat::Asc),
                screen: screen.screen,
                eyes: eyes.eyes.binocular(),
            };
            let (_, rx) = open_recording(file, options, pace)?;
            (format!("bridge:asc:{}", file.display()), rx, pace)
        }
        TrackerCommand::Gazepoint {
            host,
            port,
            retries,
        } => {
            let options = GazepointOptions {
                host: host.clone(),
                port: *port,
                max_retries: *retries,
                ..GazepointOptions::default()
            };
            let name = format!("bridge:gazepoint:{host}:{port}");
            (name, source::gazepoint(options), Pace::AsFastAsPossible)
        }
        TrackerCommand::Pupil {
            host,
            port,
            topic,
            surface,
            eye,
            min_confidence,
            connect_timeout,
        } => {
            let options = PupilOptions {
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
                connect_timeout: seconds("--connect-timeout", *connect_timeout)?,
                ..PupilOptions::default()
            };
            options.check().map_err(anyhow::Error::msg)?;
            let name = format!("bridge:pupil:{host}:{port}");
            (name, pupil::pupil(options), Pace::AsFastAsPossible)
        }
        TrackerCommand::Lsl {
            type_,
            name,
            x_channel,
            y_channel,
            units,
            screen,
            resolve_timeout,
            no_time_correction,
            no_reconnect,
        } => {
            let units = match (units, screen.screen) {
                (UnitsArg::Normalised, None) => Units::Normalised,
                (UnitsArg::Normalised, Some(_)) => {
                    bail!("--screen is for --units pixels; normalised gaze needs no screen size")
                }
                (UnitsArg::Pixels, Some(screen)) => Units::Pixels(screen),
                (UnitsArg::Pixels, None) => bail!("--units pixels needs --screen WIDTHxHEIGHT"),
            };
            let options = LslOptions {
                type_: type_.clone(),
                name: name.clone(),
                channels: ChannelMap {
                    x: *x_channel,
                    y: *y_channel,
                    units,
                },
                resolve_timeout: seconds("--resolve-timeout", *resolve_timeout)?,
                time_correction: !no_time_correction,
                reconnect: !no_reconnect,
                ..LslOptions::default()
            };
            let label = format!(
                "bridge:lsl:{type_}{}",
                name.as_deref().map(|n| format!(":{n}")).unwrap_or_default()
            );
            (label, lsl::lsl(options), Pace::AsFastAsPossible)
        }
    };
    send(&args.server, &args.send, &name, source, pace).await
}

/// Samples a recording is scanned for before it is sent (its rate, its eyes, whether it has
/// any sample at all): a fraction of a second of reading, however long the file.
const SCAN_SAMPLES: u64 = 100_000;

/// Opens a recording to send at `pace`, after a look ahead: a file with nothing to send is one
/// clear error (not thousands of skipped lines and exit 0), an eye asked of a monocular file
/// and a pace over a server's default gaze rate limit are said before anything is sent.
fn open_recording(
    path: &std::path::Path,
    options: ReadOptions,
    pace: Pace,
) -> Result<(RecordingFormat, mpsc::Receiver<SourceItem>)> {
    let scan = source::scan_recording(path, options, SCAN_SAMPLES)
        .with_context(|| format!("read {}", path.display()))?;
    if let Some(why) = scan.nothing_to_send(path) {
        bail!("{why}");
    }
    if options.eyes != Binocular::Mean && !scan.binocular {
        tracing::warn!(
            "--eyes {:?} has no effect: {} records one eye only ({:?}), which is sent",
            options.eyes,
            path.display(),
            scan.eye.unwrap_or_default()
        );
    }
    if let Some(warning) = bridge::pace_warning(pace, scan.rate_hz, scan.samples, scan.complete) {
        tracing::warn!("{warning}");
    }
    source::recording(path, options).with_context(|| format!("open {}", path.display()))
}

/// Connects, forwards `source` and prints the report; exit 1 if the source failed or sent
/// nothing.
async fn send(
    server: &ServerArgs,
    send: &SendArgs,
    name: &str,
    source: mpsc::Receiver<SourceItem>,
    pace: Pace,
) -> Result<ExitCode> {
    if let Some(d) = send.duration
        && !(d.is_finite() && d >= 0.0)
    {
        bail!("--duration must be a finite number of seconds >= 0, not {d}");
    }
    let client = foveal_client::connect_with(&server.addr, &server.options()?).await?;
    let sender = GazeSender::open(client, send.transport(), name)?;
    let options = ForwardOptions {
        pace,
        duration_s: send.duration,
    };
    let report: BridgeReport = bridge::forward(source, sender, options, ctrl_c()).await?;
    println!("{report}");
    if let Some(why) = report.nothing_sent() {
        eprintln!("error: {name}: {why}");
        return Ok(ExitCode::FAILURE);
    }
    Ok(match report.stopped {
        StopReason::SourceFailed(_) => ExitCode::FAILURE,
        _ => ExitCode::SUCCESS,
    })
}

async fn watch(args: WatchArgs) -> Result<ExitCode> {
    let mut client =
        foveal_client::connect_with(&args.server.addr, &args.server.options()?).await?;
    let options = WatchOptions {
        every_k: args.every,
        poses: args.poses,
        frames: args.frames,
        ..WatchOptions::default()
    };
    let report = match args.csv {
        Some(path) if path.as_os_str() == "-" => {
            let csv = BufWriter::new(io::stdout());
            watch::watch(
                &mut client,
                options,
                Some(csv),
                None::<io::Stdout>,
                ctrl_c(),
            )
            .await?
        }
        Some(path) => {
            let file = File::create(&path).with_context(|| format!("create {}", path.display()))?;
            let csv = BufWriter::new(file);
            watch::watch(
                &mut client,
                options,
                Some(csv),
                Some(io::stdout()),
                ctrl_c(),
            )
            .await?
        }
        None => {
            watch::watch(
                &mut client,
                options,
                None::<File>,
                Some(io::stdout()),
                ctrl_c(),
            )
            .await?
        }
    };
    info!(
        frames = report.frames,
        dropped = report.dropped,
        "watch ended"
    );
    Ok(ExitCode::SUCCESS)
}

async fn health(args: HealthArgs) -> Result<ExitCode> {
    let timeout = Duration::from_millis(args.timeout_ms);
    let options = args.server.options()?;
    match health::check_with(&args.server.addr, &args.service, timeout, &options).await {
        Ok(status) => {
            println!("{}", status.as_str_name());
            Ok(if status == health::ServingStatus::Serving {
                ExitCode::SUCCESS
            } else {
                ExitCode::FAILURE
            })
        }
        Err(err) => {
            println!("UNREACHABLE");
            eprintln!("error: {err}");
            Ok(ExitCode::FAILURE)
        }
    }
}

async fn run_load(args: LoadArgs) -> Result<ExitCode> {
    let seconds = args
        .seconds
        .unwrap_or(if args.chaos { 600.0 } else { 60.0 });
    if !(seconds.is_finite() && seconds > 0.0) {
        bail!("--seconds (--duration) must be a positive number, not {seconds}");
    }
    let base = args.server.options()?;
    let with = |token: &Option<String>| ConnectOptions {
        token: token.clone().or_else(|| base.token.clone()),
        ..base.clone()
    };
    let options = LoadOptions {
        addr: args.server.addr.clone(),
        gaze: with(&args.gaze_token),
        viewer: with(&args.viewer_token),
        streams: args.streams,
        rate_hz: args.rate,
        watchers: args.watchers,
        stalled: args.stalled,
        poses: args.poses,
        duration: Duration::from_secs_f64(seconds),
        server_pid: args.server_pid,
        chaos: args.chaos.then(|| ChaosOptions {
            admin: with(&args.admin_token),
            ..ChaosOptions::default()
        }),
        ..LoadOptions::default()
    };
    info!(
        streams = options.streams,
        rate_hz = options.rate_hz,
        watchers = options.watchers,
        stalled = options.stalled,
        seconds,
        chaos = args.chaos,
        "loading"
    );
    let report = load::run(&options).await?;
    println!("{report}");
    Ok(ExitCode::SUCCESS)
}
