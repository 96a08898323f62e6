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
use foveal_client::gaze::{Eye, ScreenPx};
use foveal_client::health;
use foveal_client::load::{self, LoadOptions};
use foveal_client::lsl::{self, LslOptions};
use foveal_client::pacer::Pace;
use foveal_client::pupil::{self, PupilOptions};
use foveal_client::sender::{GazeSender, Transport};
use foveal_client::source::{self, GazepointOptions, RecordingFormat, SourceItem};
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
    /// Seconds to run (T).
    #[arg(long, default_value_t = 60.0)]
    seconds: f64,
    /// The server's process id, for its RSS (default: the process listening on the port).
    #[arg(long)]
    server_pid: Option<u32>,
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
    /// CSV gaze lines from a file or, with `-` or nothing, from stdin, forwarded line by line as
    /// they arrive. Layouts: `t_s,x,y[,validity][,fixation]` (normalised) or `t_s,xpos,ypos`
    /// (pixels; screen size from --screen or a `# screen WxH px` comment).
    Csv {
        /// The file, or `-` for stdin.
        file: Option<PathBuf>,
        /// Pace by the timestamps at this speed instead of forwarding lines as they arrive.
        #[arg(long)]
        speed: Option<f64>,
        #[command(flatten)]
        screen: ScreenArg,
    },
    /// An EyeLink ASC file, replayed at its own pace.
    Asc {
        /// The file.
        file: PathBuf,
        #[command(flatten)]
        speed: SpeedArgs,
        #[command(flatten)]
        screen: ScreenArg,
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
    use foveal_client::gaze::Binocular;
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
        eyes: match args.eyes {
            EyesArg::Mean => Binocular::Mean,
            EyesArg::Left => Binocular::Left,
            EyesArg::Right => Binocular::Right,
            EyesArg::Both => Binocular::Both,
        },
    };
    let report = foveal_client::fixations::run(&args.file, args.compare.as_deref(), &options)?;
    for line in report.bad_lines.iter().take(10) {
        eprintln!("skipped: {line}");
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
        } => {
            let (format, rx) = source::recording(file, None, screen.screen)
                .with_context(|| format!("open {}", file.display()))?;
            info!(file = %file.display(), ?format, "replaying");
            (format!("replay:{}", file.display()), rx, speed.pace()?)
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
            screen,
        } => {
            let pace = match speed {
                Some(speed) => Pace::scaled(*speed).map_err(anyhow::Error::msg)?,
                None => Pace::AsFastAsPossible,
            };
            match file.as_deref() {
                None => (
                    "bridge:csv:stdin".to_owned(),
                    source::stdin_csv(screen.screen),
                    pace,
                ),
                Some(path) if path.as_os_str() == "-" => (
                    "bridge:csv:stdin".to_owned(),
                    source::stdin_csv(screen.screen),
                    pace,
                ),
                Some(path) => {
                    let (_, rx) =
                        source::recording(path, Some(RecordingFormat::Csv), screen.screen)
                            .with_context(|| format!("open {}", path.display()))?;
                    (format!("bridge:csv:{}", path.display()), rx, pace)
                }
            }
        }
        TrackerCommand::Asc {
            file,
            speed,
            screen,
        } => {
            let (_, rx) = source::recording(file, Some(RecordingFormat::Asc), screen.screen)
                .with_context(|| format!("open {}", file.display()))?;
            (format!("bridge:asc:{}", file.display()), rx, speed.pace()?)
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

/// Connects, forwards `source` and prints the report; exit 1 if the source failed.
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
    if !(args.seconds.is_finite() && args.seconds > 0.0) {
        bail!("--seconds must be a positive number, not {}", args.seconds);
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
        duration: Duration::from_secs_f64(args.seconds),
        server_pid: args.server_pid,
        ..LoadOptions::default()
    };
    info!(
        streams = options.streams,
        rate_hz = options.rate_hz,
        watchers = options.watchers,
        stalled = options.stalled,
        seconds = args.seconds,
        "loading"
    );
    let report = load::run(&options).await?;
    println!("{report}");
    Ok(ExitCode::SUCCESS)
}
