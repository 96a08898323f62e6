//! Command-line flags and environment variables of `foveal-server`.
//!
//! Every flag has an environment variable (`FOVEAL_*`) so that a container can be configured
//! without a command line. Parsing turns them into a [`ServerConfig`], validated with the same
//! rules and messages as Configure.

use std::net::SocketAddr;
use std::path::{Path, PathBuf};
use std::str::FromStr;
use std::time::Duration;

use clap::{Parser, ValueEnum};
use foveal_engine::broad_phase::BroadPhaseKind;
use foveal_engine::{
    BudgetSpec, ConfigError, EccentricityUnit, PerceptualFunction, PerceptualModel, SchedulerKind,
    SimConfig, TreeKind, Truth,
};

use crate::auth::{Role, Tokens};
use crate::config::{Security, ServerConfig, TlsIdentity};
use crate::error::ServerError;
use crate::limits::{self, Limits};
use crate::origin::AllowedOrigin;
use crate::transport::{self, ConnectionLimits};

/// Bodies of the scene the server starts with: enough that an exact frame (11-20 ms on a loaded
/// 2-core machine) does not fit [`DEFAULT_BUDGET`], so the budget is needed, and few enough that
/// the side by side (`--compare`) holds 60 fps beside it (docs/BENCHMARKS.md "Side by side").
pub const DEFAULT_BODIES: u32 = 5000;

/// Bodies of the staged demonstration (`--demo`).
pub const DEMO_BODIES: u32 = 5000;
/// Sphere tests a frame of the staged demonstration (`--demo`).
pub const DEMO_TESTS: u64 = 10_000;

/// Budget the server starts with: a real one, wall clock for the whole frame, a quarter of the
/// 60 Hz frame period. What is deemed then depends on the machine, as in an application.
pub const DEFAULT_BUDGET: &str = "4ms";

/// Headless foveal server: runs the budgeted, gaze-scheduled collision loop and serves it over gRPC.
#[derive(Debug, Clone, Parser)]
#[command(name = "foveal-server", version, about)]
pub struct Cli {
    /// Address to listen on (use 0.0.0.0:50051 in a container).
    #[arg(long, env = "FOVEAL_ADDR", default_value = "127.0.0.1:50051")]
    pub addr: SocketAddr,
    /// Also serve the standard gRPC health service, and nothing else, in plaintext on this
    /// address: for orchestrators' probes (Kubernetes' gRPC probe speaks neither TLS nor tokens).
    /// Health is open on --addr as well; this port only says whether frames complete.
    #[arg(long, env = "FOVEAL_HEALTH_ADDR")]
    pub health_addr: Option<SocketAddr>,
    /// Number of bodies.
    #[arg(short = 'n', long, env = "FOVEAL_BODIES", default_value_t = DEFAULT_BODIES)]
    pub bodies: u32,
    /// Seed of the scene generator.
    #[arg(long, env = "FOVEAL_SEED", default_value_t = 1)]
    pub seed: u64,
    /// Sphere-tree depth (1..=6).
    #[arg(long, env = "FOVEAL_DEPTH", default_value_t = 4)]
    pub depth: u32,
    /// Narrow-phase scheduler. The default, `priced`, orders work by the false-positive perceived
    /// error a step is expected to remove per sphere test (probabilities and costs calibrated on
    /// exact runs; under a sphere-test budget, a pair's cost last frame where it is remembered);
    /// on identical frames it reaches 0.81-1.00 of the reduction a clairvoyant schedule could
    /// make over round-robin under sphere-test budgets. A wall-clock frame settles the pairs
    /// apart at the root in one pass first, then the pairs within 5 degrees of the fixation,
    /// whole and nearest first (so what the viewer looks at is exact), then orders the rest, or
    /// runs round-robin over it when the frame cannot pay for ordering: at a tenth of the exact
    /// narrow phase this leaves 0.33-0.87x round-robin's perceived error at N = 10,000, at a
    /// third 0.01-0.41x (docs/BENCHMARKS.md).
    #[arg(long, env = "FOVEAL_SCHEDULER", default_value = "priced", value_parser = parse_scheduler)]
    pub scheduler: SchedulerKind,
    /// Worker threads for the frame's phases (1..=64; default: the machine's cores but one, at
    /// least 1 and at most 64):
    /// with more than one, every frame runs on a pool of this many threads kept for the whole
    /// run (in exact frames its threads wait for the frame's parts awake, yielding their cores,
    /// instead of sleeping, and before every frame they spin for 200 us so that it does not
    /// start on sleeping processors). Under sphere-test and exact budgets the reports do not depend on
    /// it; under a wall-clock budget more threads settle more pairs in the same time.
    #[arg(long, env = "FOVEAL_THREADS", default_value_t = default_threads())]
    pub threads: u32,
    /// Broad phase: `auto` (sweep and prune at small N, a uniform grid at large N),
    /// `sweep-and-prune` or `grid`.
    #[arg(long, env = "FOVEAL_BROAD_PHASE", default_value = "auto", value_parser = parse_broad_phase)]
    pub broad_phase: BroadPhaseKind,
    /// Per-frame budget: `exact`, `zero` (deem every pair), `<ms>ms` (wall clock for the whole
    /// frame, integration to metrics, e.g. `2.5ms`), `<n>tests` (sphere tests in the narrow
    /// phase, e.g. `20000tests`), or `<f>x` (fraction of the exact cost, e.g. `0.3x`).
    #[arg(long, env = "FOVEAL_BUDGET", default_value = DEFAULT_BUDGET)]
    pub budget: BudgetArg,
    /// What "colliding" means: `shape` (the drawn stars, core ball and six cones, touch) or
    /// `leaf-spheres` (a leaf sphere of one body's sphere tree overlaps one of the other's: the
    /// paper's definition, for its replication; the leaves overshoot the star near the spike
    /// tips, so bodies may bounce across a visible gap).
    #[arg(long, env = "FOVEAL_TRUTH", default_value = "shape", value_parser = parse_truth)]
    pub truth: Truth,
    /// How the sphere tree groups its leaves: `parts` (level 2 the star's core and six spikes,
    /// every inner sphere fitted: the fewest sphere tests), `fitted` (the octree's cells with
    /// fitted spheres) or `octree` (the paper's, for its replication). The leaves, and so every
    /// exact answer, are the same under each (docs/DESIGN.md "Sphere tree").
    #[arg(long, env = "FOVEAL_TREE", default_value = "parts", value_parser = parse_tree)]
    pub tree: TreeKind,
    /// Frames per second the loop runs at.
    #[arg(long, env = "FOVEAL_FRAME_RATE", default_value_t = 60.0)]
    pub frame_rate: f64,
    /// Eccentricity (degrees) splitting the priority schedulers' two queues.
    #[arg(long, env = "FOVEAL_ECCENTRICITY_THRESHOLD", default_value_t = 5.0)]
    pub eccentricity_threshold_deg: f64,
    /// Model the scheduler ranks pairs with: `f1[:unit]`, `f2:<c>[:unit]`,
    /// `f2range:<c_min>,<c_max>[:unit]` (F2 averaged over C log-uniform in the range) or
    /// `f3:<c1>,<c2>,<c3>,<e1>,<e2>[:unit]`, unit `deg` (default) or `px`.
    /// The default averages F2 over C in [1, 10] degrees: never worse than gaze-blind round-robin
    /// whichever C the viewer has (docs/BENCHMARKS.md).
    #[arg(
        long,
        env = "FOVEAL_SCHEDULE_MODEL",
        default_value = "f2range:1,10:deg"
    )]
    pub schedule_model: ModelArg,
    /// Model the perceived inaccuracy P is measured with (same syntax as --schedule-model).
    #[arg(long, env = "FOVEAL_MEASURE_MODEL", default_value = "f2:5:deg")]
    pub measure_model: ModelArg,
    /// Compute the exact answer for every deemed pair (true false positives, true Δ and P).
    #[arg(long, env = "FOVEAL_AUDIT")]
    pub audit: bool,
    /// A staged demonstration, for a first look on any machine: 5,000 bodies under a budget of
    /// 10,000 sphere tests a frame (the same work whatever the machine, where the default's
    /// wall-clock budget deems what the machine cannot settle) with the side by side against
    /// round-robin on, so that the page colours the wrong guesses (deemed pairs truly apart) in
    /// both views. With the gaze held, the share of the pairs within 5 degrees of it left as wrong
    /// guesses is about half the share beyond (docs/BENCHMARKS.md "Side by side"). The budget is
    /// chosen to show the effect, not by what a frame can afford: the page and the log say it is
    /// staged. It sets -n, --budget and --compare, so it is not combined with them.
    #[arg(long, env = "FOVEAL_DEMO", conflicts_with_all = ["bodies", "budget", "compare"])]
    pub demo: bool,
    /// The side by side: also settle every frame with a gaze-blind collider (`round-robin` under
    /// the same budget, or `exact`) and send its metrics and collisions beside the frame's
    /// (`off`, `round-robin`, `exact`), with both sides' true error measured on the same pairs.
    /// Refused above 5,000 bodies, where the second collider no longer fits the frame period
    /// (docs/BENCHMARKS.md).
    #[arg(long, env = "FOVEAL_COMPARE", default_value = "off", value_parser = crate::compare::Compare::parse)]
    pub compare: crate::compare::Compare,
    /// Under a wall-clock budget, settle every pair within 5 degrees of the fixation before any
    /// other (priced scheduler), over every candidate and before anything else. Without it the
    /// priced scheduler already does so through the gaze rings where sweep and prune locates
    /// the pairs and the frame can pay for placing the rings (at N = 10,000 and 4 ms, frames
    /// with every foveal pair settled: 99.5-100%, against 0-1.3% before the rings did it;
    /// docs/BENCHMARKS.md).
    #[arg(long, env = "FOVEAL_FOVEA_FIRST")]
    pub fovea_first: bool,
    /// Display width in pixels.
    #[arg(long, env = "FOVEAL_DISPLAY_WIDTH_PX", default_value_t = 1680)]
    pub display_width_px: u32,
    /// Display height in pixels.
    #[arg(long, env = "FOVEAL_DISPLAY_HEIGHT_PX", default_value_t = 1050)]
    pub display_height_px: u32,
    /// Display diagonal in inches.
    #[arg(long, env = "FOVEAL_DISPLAY_DIAGONAL_IN", default_value_t = 22.0)]
    pub display_diagonal_in: f64,
    /// Eye-to-screen distance in centimetres.
    #[arg(long, env = "FOVEAL_VIEWING_DISTANCE_CM", default_value_t = 70.0)]
    pub viewing_distance_cm: f64,
    /// Gaze older than this many seconds no longer steers the scheduler (frames fall back to the
    /// screen centre and say so).
    #[arg(
        long = "gaze-max-age",
        env = "FOVEAL_GAZE_MAX_AGE",
        default_value_t = 0.5
    )]
    pub gaze_max_age_s: f64,
    /// Fixation detection on incoming gaze: `off` (every valid sample steers, lowest latency),
    /// `ivt` (velocity threshold, 30 deg/s) or `idt` (dispersion threshold, 1 deg). With a
    /// detector, saccade samples no longer steer: the last fixation is held.
    #[arg(long, env = "FOVEAL_GAZE_DETECTOR", value_enum, default_value = "off")]
    pub gaze_detector: GazeDetectorArg,
    /// Smooth gaze with a 1-euro filter (Casiez et al. 2012) before it steers.
    #[arg(long, env = "FOVEAL_GAZE_FILTER")]
    pub gaze_filter: bool,
    /// Eyes of a binocular tracker: the mean of the valid eyes, or one eye.
    #[arg(long, env = "FOVEAL_GAZE_EYES", value_enum, default_value = "mean")]
    pub gaze_eyes: GazeEyesArg,
    /// Token of the `viewer` role (WatchFrames, GetScene, GetStatus). Prefer the environment
    /// variable: a flag's value is visible to other users in the process list.
    #[arg(long, env = "FOVEAL_VIEWER_TOKEN", hide_env_values = true)]
    pub viewer_token: Option<String>,
    /// Token of the `gaze` role (StreamGaze, PushGaze).
    #[arg(long, env = "FOVEAL_GAZE_TOKEN", hide_env_values = true)]
    pub gaze_token: Option<String>,
    /// Token of the `admin` role (Configure, and everything else).
    #[arg(long, env = "FOVEAL_ADMIN_TOKEN", hide_env_values = true)]
    pub admin_token: Option<String>,
    /// Tokens file: one `role token` (or `role=token`) per line, roles viewer, gaze, admin; `#`
    /// starts a comment. Adds to the tokens from the environment.
    #[arg(long, env = "FOVEAL_TOKENS")]
    pub tokens: Option<PathBuf>,
    /// Serve without tokens on an address other than loopback (anyone who can reach it may
    /// reconfigure the scene). Without tokens the server otherwise refuses to start there.
    #[arg(long, env = "FOVEAL_INSECURE")]
    pub insecure: bool,
    /// TLS certificate chain (PEM); with --tls-key the server speaks TLS only.
    #[arg(long, env = "FOVEAL_TLS_CERT", requires = "tls_key")]
    pub tls_cert: Option<PathBuf>,
    /// TLS private key (PEM).
    #[arg(long, env = "FOVEAL_TLS_KEY", requires = "tls_cert")]
    pub tls_key: Option<PathBuf>,
    /// Add an origin browsers may use the viewer and grpc-web from (`https://viewer.example.org`,
    /// `http://lab-pc.local:50051`; repeat, or comma-separated in the variable). Its host is then
    /// also accepted in `Host`. Without it browsers are answered only at IP addresses and
    /// `localhost`, from the server's own or a loopback origin (DNS rebinding protection).
    #[arg(long, env = "FOVEAL_ALLOWED_ORIGINS", value_delimiter = ',')]
    pub allowed_origin: Vec<AllowedOrigin>,
    /// Connections held at once; one more is closed at once [default: 1024, or fewer when
    /// `ulimit -n` leaves less room than that plus 64].
    #[arg(long, env = "FOVEAL_MAX_CONNECTIONS")]
    pub max_connections: Option<usize>,
    /// Seconds a new connection has to send its first byte (TLS: to finish its handshake and
    /// send it); a connection that sends nothing is closed.
    #[arg(long, env = "FOVEAL_FIRST_BYTE_TIMEOUT", default_value_t = transport::DEFAULT_FIRST_BYTE_TIMEOUT.as_secs_f64())]
    pub first_byte_timeout: f64,
    /// Seconds a request head has to arrive once its first byte has (every HTTP/1.1 head, also
    /// between keep-alive requests; on HTTP/2 the first request's).
    #[arg(long, env = "FOVEAL_HEADER_TIMEOUT", default_value_t = transport::DEFAULT_HEADER_TIMEOUT.as_secs_f64())]
    pub header_timeout: f64,
    /// Seconds a request body may send nothing before its call fails with DEADLINE_EXCEEDED
    /// (StreamGaze over HTTP/2 excepted: a tracker may pause).
    #[arg(long, env = "FOVEAL_BODY_IDLE_TIMEOUT", default_value_t = transport::DEFAULT_BODY_IDLE_TIMEOUT.as_secs_f64())]
    pub body_idle_timeout: f64,
    /// Seconds a connection may stay open with no call in progress.
    #[arg(long, env = "FOVEAL_IDLE_TIMEOUT", default_value_t = transport::DEFAULT_IDLE_TIMEOUT.as_secs_f64())]
    pub idle_timeout: f64,
    /// Refuse scenes (at start-up and in Configure) whose expected broad-phase candidate pairs
    /// per frame exceed this.
    #[arg(long, env = "FOVEAL_MAX_CANDIDATE_PAIRS", default_value_t = limits::DEFAULT_MAX_CANDIDATE_PAIRS)]
    pub max_candidate_pairs: u64,
    /// Refuse scenes whose estimated memory exceeds this many MiB.
    #[arg(long, env = "FOVEAL_MAX_MEMORY_MIB", default_value_t = limits::DEFAULT_MAX_MEMORY_MIB)]
    pub max_memory_mib: u64,
    /// Gaze samples per second one stream (or one connection's PushGaze calls) may deliver;
    /// samples above it are dropped and counted (`rate_limited`).
    #[arg(long, env = "FOVEAL_MAX_GAZE_RATE", default_value_t = limits::DEFAULT_MAX_GAZE_RATE_HZ)]
    pub max_gaze_rate: f64,
    /// Record the session to this file (JSON lines, docs/PROTOCOL.md "Recorded sessions"): the
    /// configuration, every gaze sample with its receipt time, every frame's fixation and
    /// metrics, scene changes. Replay it with `foveal-bench replay FILE`.
    #[arg(long, env = "FOVEAL_RECORD")]
    pub record: Option<PathBuf>,
    /// Directory of the `/psych` experiments' results: one CSV per participant and session,
    /// with a JSON header beside it (created with the first session).
    #[arg(long, env = "FOVEAL_PSYCH_RESULTS", default_value = crate::psych::DEFAULT_RESULTS_DIR)]
    pub psych_results: PathBuf,
    /// Directory of the lab's experiment designs (`NAME.json`, run as `/psych?design=NAME`),
    /// looked up before the built-in ones (`experiment1`).
    #[arg(long, env = "FOVEAL_PSYCH_DESIGNS")]
    pub psych_designs: Option<PathBuf>,
    /// Log filter (`info`, `debug`, `foveal_server=debug,info`, ...).
    #[arg(long, env = "FOVEAL_LOG", default_value = "info")]
    pub log_level: String,
    /// Log format.
    #[arg(long, env = "FOVEAL_LOG_FORMAT", value_enum, default_value_t = LogFormat::Text)]
    pub log_format: LogFormat,
}

/// How log lines are written.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum LogFormat {
    /// Human-readable lines.
    Text,
    /// One JSON object per line (for log collectors).
    Json,
}

fn parse_broad_phase(s: &str) -> Result<BroadPhaseKind, String> {
    BroadPhaseKind::from_name(s).ok_or_else(|| {
        let names: Vec<_> = BroadPhaseKind::ALL.iter().map(|k| k.name()).collect();
        format!("unknown broad phase `{s}`; one of: {}", names.join(", "))
    })
}

/// The `--threads` default: every core the process may use but one (each phase splits its work
/// only where it is large enough to pay for a thread), at least 1 and at most the 64 the engine
/// accepts. The core left is for what shares the machine with the loop, first of all the viewer:
/// on 2 cores with the browser viewer open, a 2-thread pool under the default 4 ms budget waited
/// for a preempted thread until the budget was spent before the narrow phase in 44-57 of 60
/// frames; one thread never was (docs/BENCHMARKS.md "Side by side").
fn default_threads() -> u32 {
    std::thread::available_parallelism()
        .map_or(1, |n| n.get().saturating_sub(1).clamp(1, 64) as u32)
}

fn parse_tree(s: &str) -> Result<TreeKind, String> {
    s.parse().map_err(|e: ConfigError| e.to_string())
}

fn parse_truth(s: &str) -> Result<Truth, String> {
    Truth::from_name(s).ok_or_else(|| {
        let names: Vec<_> = Truth::ALL.iter().map(|t| t.name()).collect();
        format!("unknown truth `{s}`; one of: {}", names.join(", "))
    })
}

fn parse_scheduler(s: &str) -> Result<SchedulerKind, String> {
    SchedulerKind::from_name(s).ok_or_else(|| {
        let names: Vec<_> = SchedulerKind::ALL.iter().map(|k| k.name()).collect();
        format!("unknown scheduler `{s}`; one of: {}", names.join(", "))
    })
}

/// A budget flag (see `--budget`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BudgetArg(pub BudgetSpec);

impl FromStr for BudgetArg {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        let s = s.trim();
        let num = |v: &str| {
            v.trim()
                .parse::<f64>()
                .map_err(|e| format!("budget `{s}`: {e}"))
        };
        let spec = if s == "exact" {
            BudgetSpec::Exact
        } else if s == "zero" {
            BudgetSpec::InterruptAtZero
        } else if let Some(v) = s.strip_suffix("ms") {
            BudgetSpec::WallMs(num(v)?)
        } else if let Some(v) = s.strip_suffix("tests") {
            BudgetSpec::SphereTests(v.trim().parse().map_err(|e| format!("budget `{s}`: {e}"))?)
        } else if let Some(v) = s.strip_suffix('x') {
            BudgetSpec::FractionOfExact(num(v)?)
        } else {
            return Err(format!(
                "budget `{s}`: expected `exact`, `zero`, `<ms>ms`, `<n>tests` or `<fraction>x`"
            ));
        };
        spec.validate().map_err(|e| e.to_string())?;
        Ok(Self(spec))
    }
}

/// A perceptual model flag (see `--schedule-model`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModelArg(pub PerceptualModel);

impl FromStr for ModelArg {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        let mut parts = s.trim().split(':');
        let name = parts.next().unwrap_or_default();
        let mut rest: Vec<&str> = parts.collect();
        let unit = match rest.last().copied() {
            Some("deg") => {
                rest.pop();
                EccentricityUnit::Degrees
            }
            Some("px") => {
                rest.pop();
                EccentricityUnit::Pixels
            }
            _ => EccentricityUnit::Degrees,
        };
        let consts: Vec<f64> = match rest.as_slice() {
            [] => Vec::new(),
            [list] => list
                .split(',')
                .map(|v| v.trim().parse::<f64>())
                .collect::<Result<_, _>>()
                .map_err(|e| format!("model `{s}`: {e}"))?,
            _ => return Err(format!("model `{s}`: too many `:` parts")),
        };
        let function = match (name, consts.as_slice()) {
            ("f1", []) => PerceptualFunction::F1,
            ("f2", &[c]) => PerceptualFunction::F2 { c },
            ("f2range", &[c_min, c_max]) => PerceptualFunction::F2Range { c_min, c_max },
            ("f3", &[c1, c2, c3, e1, e2]) => PerceptualFunction::F3 { c1, c2, c3, e1, e2 },
            _ => {
                return Err(format!(
                    "model `{s}`: expected `f1[:unit]`, `f2:<c>[:unit]`, `f2range:<c_min>,<c_max>[:unit]` or `f3:<c1>,<c2>,<c3>,<e1>,<e2>[:unit]` with unit `deg` or `px`"
                ));
            }
        };
        let model = PerceptualModel { function, unit };
        model.validate("model").map_err(|e| e.to_string())?;
        Ok(Self(model))
    }
}

impl Cli {
    /// The server configuration the flags describe, validated.
    pub fn server_config(&self) -> Result<ServerConfig, ConfigError> {
        let mut sim = SimConfig::default();
        sim.scene.bodies = self.bodies;
        sim.scene.seed = self.seed;
        sim.scene.depth = self.depth;
        sim.scene.truth = self.truth;
        sim.scene.tree = self.tree;
        sim.scheduler = self.scheduler;
        sim.threads = self.threads;
        sim.broad_phase = self.broad_phase;
        sim.budget = self.budget.0;
        sim.eccentricity_threshold_deg = self.eccentricity_threshold_deg;
        sim.schedule_model = self.schedule_model.0;
        sim.measure_model = self.measure_model.0;
        sim.audit = self.audit;
        if self.demo {
            sim.scene.bodies = DEMO_BODIES;
            sim.budget = BudgetSpec::SphereTests(DEMO_TESTS);
        }
        sim.fovea_first = self.fovea_first;
        sim.display.width_px = self.display_width_px;
        sim.display.height_px = self.display_height_px;
        sim.display.diagonal_in = self.display_diagonal_in;
        sim.display.viewing_distance_cm = self.viewing_distance_cm;
        let max_age = self.gaze_max_age_s;
        if !(max_age.is_finite() && max_age > 0.0) {
            return Err(ConfigError {
                field: "gaze_max_age",
                value: max_age.to_string(),
                expected: "must be finite and > 0 (seconds)".into(),
            });
        }
        let gaze_processing = self.gaze_processing(&sim.display);
        let connections = ConnectionLimits {
            max_connections: self.max_connections,
            first_byte_timeout: seconds("first_byte_timeout", self.first_byte_timeout)?,
            header_timeout: seconds("header_timeout", self.header_timeout)?,
            body_idle_timeout: seconds("body_idle_timeout", self.body_idle_timeout)?,
            idle_timeout: seconds("idle_timeout", self.idle_timeout)?,
        };
        let config = ServerConfig {
            sim,
            frame_rate_hz: self.frame_rate,
            gaze_max_age: Duration::from_secs_f64(max_age.min(1e6)),
            gaze_processing,
            limits: Limits {
                max_candidate_pairs: self.max_candidate_pairs,
                max_memory_mib: self.max_memory_mib,
                max_gaze_rate_hz: self.max_gaze_rate,
            },
            record: self.record.clone(),
            psych: crate::psych::PsychConfig {
                results_dir: self.psych_results.clone(),
                designs_dir: self.psych_designs.clone(),
            },
            connections,
            compare: if self.demo {
                crate::compare::Compare::RoundRobin
            } else {
                self.compare
            },
            ..ServerConfig::default()
        };
        config.validate()?;
        Ok(config)
    }

    /// Tokens (environment and file) and TLS files, read and checked.
    pub fn security(&self) -> Result<Security, ServerError> {
        let mut tokens = match &self.tokens {
            Some(path) => Tokens::from_file(path)?,
            None => Tokens::none(),
        };
        for (role, token) in [
            (Role::Viewer, &self.viewer_token),
            (Role::Gaze, &self.gaze_token),
            (Role::Admin, &self.admin_token),
        ] {
            if let Some(t) = token.as_deref().filter(|t| !t.is_empty()) {
                tokens.add(role, t, role.env_var())?;
            }
        }
        let read = |what: &'static str, path: &PathBuf| {
            std::fs::read(path).map_err(|source| ServerError::TlsFile {
                what,
                path: path.display().to_string(),
                source,
            })
        };
        let tls = match (&self.tls_cert, &self.tls_key) {
            (Some(cert), Some(key)) => {
                let identity = TlsIdentity {
                    cert_pem: read("--tls-cert", cert)?,
                    key_pem: read("--tls-key", key)?,
                };
                check_pem(&identity, cert, key)?;
                Some(identity)
            }
            _ => None,
        };
        Ok(Security {
            tokens,
            tls,
            insecure: self.insecure,
            allowed_origins: self.allowed_origin.clone(),
        })
    }
}

/// A timeout flag in seconds as a duration: finite, > 0 and at most [`transport::MAX_TIMEOUT`].
fn seconds(field: &'static str, s: f64) -> Result<Duration, ConfigError> {
    if s.is_finite() && s > 0.0 && s <= transport::MAX_TIMEOUT.as_secs_f64() {
        Ok(Duration::from_secs_f64(s))
    } else {
        Err(ConfigError {
            field,
            value: s.to_string(),
            expected: format!(
                "must be finite, > 0 and <= {} (seconds)",
                transport::MAX_TIMEOUT.as_secs()
            ),
        })
    }
}

/// Refuse TLS files that hold no PEM certificate or no PEM private key at start-up, naming the
/// flag, instead of failing later inside the transport with a message about neither.
fn check_pem(identity: &TlsIdentity, cert: &Path, key: &Path) -> Result<(), ServerError> {
    use rustls_pki_types::pem::PemObject;
    use rustls_pki_types::{CertificateDer, PrivateKeyDer};
    let bad = |what: &'static str, path: &Path, reason: String| ServerError::TlsPem {
        what,
        path: path.display().to_string(),
        reason,
    };
    let certs: Result<Vec<_>, _> = CertificateDer::pem_slice_iter(&identity.cert_pem).collect();
    match certs {
        Ok(c) if !c.is_empty() => {}
        Ok(_) => return Err(bad("--tls-cert", cert, "holds no CERTIFICATE block".into())),
        Err(e) => return Err(bad("--tls-cert", cert, format!("is not valid PEM ({e})"))),
    }
    PrivateKeyDer::from_pem_slice(&identity.key_pem).map_err(|e| {
        bad(
            "--tls-key",
            key,
            format!("holds no usable private key ({e})"),
        )
    })?;
    Ok(())
}

/// `--gaze-detector`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum GazeDetectorArg {
    /// Every valid sample steers.
    Off,
    /// Velocity threshold (I-VT).
    Ivt,
    /// Dispersion threshold (I-DT).
    Idt,
}

/// `--gaze-eyes`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum GazeEyesArg {
    /// Mean of the valid eyes.
    Mean,
    /// Left eye only.
    Left,
    /// Right eye only.
    Right,
}

impl Cli {
    /// The gaze processing the flags ask for, its degrees measured on the engine's display.
    fn gaze_processing(
        &self,
        display: &foveal_engine::Display,
    ) -> foveal_gaze::online::ProcessorConfig {
        use foveal_gaze::Binocular;
        use foveal_gaze::detect::{DetectorParams, IdtParams, IvtParams};
        let geometry = crate::fixation_cell::viewing_geometry(display);
        foveal_gaze::online::ProcessorConfig {
            eyes: match self.gaze_eyes {
                GazeEyesArg::Mean => Binocular::Mean,
                GazeEyesArg::Left => Binocular::Left,
                GazeEyesArg::Right => Binocular::Right,
            },
            filter: self
                .gaze_filter
                .then(foveal_gaze::filter::OneEuroParams::default),
            detector: match self.gaze_detector {
                GazeDetectorArg::Off => None,
                GazeDetectorArg::Ivt => Some(DetectorParams::Ivt(IvtParams::default())),
                GazeDetectorArg::Idt => Some(DetectorParams::Idt(IdtParams::default())),
            },
            geometry,
            ..foveal_gaze::online::ProcessorConfig::default()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_parse_to_a_valid_config() {
        let cli = Cli::try_parse_from(["foveal-server"]).expect("defaults parse");
        assert_eq!(cli.addr.to_string(), "127.0.0.1:50051");
        let c = cli.server_config().expect("valid");
        // The engine's defaults but for a scene and budget where the budget bites.
        let mut expected = SimConfig::default();
        expected.scene.bodies = DEFAULT_BODIES;
        expected.budget = BudgetSpec::WallMs(4.0);
        // Every core the process may use but one, at least 1 and at most 64.
        expected.threads = default_threads();
        assert!((1..=64).contains(&expected.threads));
        assert_eq!(c.sim, expected);
        assert_eq!(c.gaze_max_age, Duration::from_millis(500));
        let sec = cli.security().expect("no tokens, no TLS");
        assert!(sec.tokens.is_empty() && sec.tls.is_none() && !sec.insecure);
    }

    #[test]
    fn tokens_and_limits_come_from_flags() {
        let cli = Cli::try_parse_from([
            "foveal-server",
            "--admin-token=admin-0123456789abcdef",
            "--max-candidate-pairs=10",
        ])
        .expect("parse");
        let sec = cli.security().expect("valid token");
        assert_eq!(
            sec.tokens.role_of("admin-0123456789abcdef"),
            Some(Role::Admin)
        );
        let e = cli.server_config().expect_err("500 bodies exceed 10 pairs");
        assert_eq!(e.field, "scene.bodies");
        let weak = Cli::try_parse_from(["foveal-server", "--gaze-token=abc"]).expect("parse");
        assert!(weak.security().is_err());
        assert!(
            Cli::try_parse_from(["foveal-server", "--tls-cert=c.pem"]).is_err(),
            "a certificate needs its key"
        );
    }

    #[test]
    fn flags_parse() {
        let cli = Cli::try_parse_from([
            "foveal-server",
            "--addr=0.0.0.0:9000",
            "-n",
            "10000",
            "--scheduler=round-robin",
            "--budget=2.5ms",
            "--measure-model=f1:px",
            "--schedule-model=f3:1,2,4,20,100:px",
            "--log-format=json",
            "--fovea-first",
            "--truth=leaf-spheres",
        ])
        .expect("parse");
        let c = cli.server_config().expect("valid");
        assert_eq!(c.sim.scene.bodies, 10_000);
        assert_eq!(c.sim.scene.truth, Truth::LeafSpheres);
        assert!(c.sim.fovea_first);
        assert_eq!(c.sim.scheduler, SchedulerKind::RoundRobin);
        assert_eq!(c.sim.budget, BudgetSpec::WallMs(2.5));
        assert_eq!(c.sim.measure_model, PerceptualModel::f1_pixels());
        assert!(matches!(
            c.sim.schedule_model.function,
            PerceptualFunction::F3 { e2, .. } if e2 == 100.0
        ));
        assert_eq!(cli.log_format, LogFormat::Json);
    }

    #[test]
    fn the_demo_is_a_staged_preset_and_not_combined_with_what_it_sets() {
        let c = Cli::try_parse_from(["foveal-server", "--demo"])
            .expect("parse")
            .server_config()
            .expect("valid");
        assert_eq!(c.sim.scene.bodies, DEMO_BODIES);
        assert_eq!(c.sim.budget, BudgetSpec::SphereTests(DEMO_TESTS));
        assert_eq!(c.compare, crate::compare::Compare::RoundRobin);
        for clash in [["-n", "100"], ["--budget", "4ms"], ["--compare", "off"]] {
            let e = Cli::try_parse_from(["foveal-server", "--demo", clash[0], clash[1]])
                .expect_err("clashes")
                .to_string();
            assert!(e.contains("--demo"), "{e}");
        }
        // What it leaves alone stays the user's.
        let c = Cli::try_parse_from(["foveal-server", "--demo", "--seed", "7", "--audit"])
            .expect("parse")
            .server_config()
            .expect("valid");
        assert_eq!((c.sim.scene.seed, c.sim.audit), (7, true));
    }

    #[test]
    fn a_bad_truth_names_the_flag_and_the_accepted_values() {
        let e = Cli::try_parse_from(["foveal-server", "--truth", "spheres"])
            .expect_err("not a truth")
            .to_string();
        assert!(e.contains("--truth"), "{e}");
        assert!(e.contains("spheres"), "{e}");
        assert!(e.contains("shape, leaf-spheres"), "{e}");
        let help = Cli::try_parse_from(["foveal-server", "--help"])
            .expect_err("help exits")
            .to_string();
        assert!(help.contains("--truth"), "{help}");
        assert!(help.contains("leaf-spheres"), "{help}");
        assert!(help.contains("[default: shape]"), "{help}");
    }

    #[test]
    fn budgets_and_models_parse_or_explain() {
        let b = |s: &str| s.parse::<BudgetArg>().map(|b| b.0);
        assert_eq!(b("exact"), Ok(BudgetSpec::Exact));
        assert_eq!(b("zero"), Ok(BudgetSpec::InterruptAtZero));
        assert_eq!(b("20000tests"), Ok(BudgetSpec::SphereTests(20_000)));
        assert_eq!(b("0.3x"), Ok(BudgetSpec::FractionOfExact(0.3)));
        assert!(
            b("1.5x")
                .expect_err("fraction > 1")
                .contains("budget.fraction_of_exact")
        );
        assert!(b("-1ms").expect_err("negative").contains("budget.wall_ms"));
        assert!(b("soon").is_err());
        let m = |s: &str| s.parse::<ModelArg>().map(|m| m.0);
        assert_eq!(m("f2:5:deg"), Ok(PerceptualModel::default()));
        assert_eq!(m("f2:5"), Ok(PerceptualModel::default()));
        assert!(m("f2").is_err());
        assert_eq!(
            m("f2range:1,10").map(|m| m.function),
            Ok(PerceptualFunction::F2Range {
                c_min: 1.0,
                c_max: 10.0
            })
        );
        assert!(m("f2range:10,1").is_err(), "range out of order");
        assert!(m("f2:-1").is_err());
        assert!(m("f3:1,2,3,100,20").is_err(), "breaks out of order");
        let bad = Cli::try_parse_from(["foveal-server", "--frame-rate=0"]).expect("parses");
        assert_eq!(
            bad.server_config().map_err(|e| e.field),
            Err("frame_rate_hz")
        );
        let bad = Cli::try_parse_from(["foveal-server", "--gaze-max-age=nan"]).expect("parses");
        assert_eq!(
            bad.server_config().map_err(|e| e.field),
            Err("gaze_max_age")
        );
    }

    #[test]
    fn gaze_processing_flags_reach_the_config() {
        let c = Cli::try_parse_from(["foveal-server"])
            .expect("parses")
            .server_config()
            .expect("valid");
        assert_eq!(
            c.gaze_processing.detector, None,
            "raw samples steer by default"
        );
        let c = Cli::try_parse_from([
            "foveal-server",
            "--gaze-detector",
            "ivt",
            "--gaze-filter",
            "--gaze-eyes",
            "right",
        ])
        .expect("parses")
        .server_config()
        .expect("valid");
        let p = c.gaze_processing;
        assert!(matches!(
            p.detector,
            Some(foveal_gaze::detect::DetectorParams::Ivt(_))
        ));
        assert!(p.filter.is_some());
        assert_eq!(p.eyes, foveal_gaze::Binocular::Right);
        // 22-inch 16:10 at 70 cm, the engine's display.
        assert!((p.geometry.width_cm - 47.4).abs() < 0.1, "{:?}", p.geometry);
        assert_eq!(p.geometry.distance_cm, 70.0);
    }
}
