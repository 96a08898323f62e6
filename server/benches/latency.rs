//! Latency and fan-out bench of the server over loopback (results go to docs/BENCHMARKS.md).
//!
//! 1. Gaze → frame latency: a client streams one gaze sample at a fresh point, waits for the first
//!    frame whose fixation is that point, and records the time between sending the sample and
//!    receiving that frame; samples are sent at random phases of the frame period. Reported as
//!    p50/p90/p99/max, without and with poses in the watched frames. Beside it, the frame's own
//!    `fixation.age_s`: from the server receiving the sample to the start of the frame that used it
//!    (the part the loop controls; the rest is that frame's compute time and delivery).
//! 2. Fan-out: 32 subscribers watch frames with poses; the loop must hold its frame rate (frames
//!    simulated per second, from GetStatus) whatever the subscribers manage to take (frames
//!    received and `dropped_before`, per subscriber).
//!
//! Run with `cargo bench -p foveal-server --bench latency`. Environment: `FOVEAL_BENCH_BODIES`
//! (default 10000), `FOVEAL_BENCH_RATE` (Hz, default 60), `FOVEAL_BENCH_BUDGET_MS` (wall-clock
//! narrow-phase budget, default 4), `FOVEAL_BENCH_SAMPLES` (latency samples, default 300),
//! `FOVEAL_BENCH_SECONDS` (fan-out duration, default 10), `FOVEAL_LOG` (server log filter,
//! default `warn`; `info` shows the server's per-second summary lines).

use std::time::{Duration, Instant};

use foveal_engine::BudgetSpec;
use foveal_proto::pb;
use foveal_server::ServerConfig;
use foveal_tests::TestServer as Server;

type BoxError = Box<dyn std::error::Error + Send + Sync>;

fn env_or<T: std::str::FromStr>(name: &str, default: T) -> T {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// Nearest-rank quantile ([`foveal_gaze::quantile`]) of sorted durations, ms; NaN for none.
fn quantile_ms(sorted: &[Duration], q: f64) -> f64 {
    foveal_gaze::quantile::nearest_rank(sorted, q).map_or(f64::NAN, |d| d.as_secs_f64() * 1e3)
}

async fn latency(
    server: &Server,
    samples: usize,
    poses: bool,
    period: Duration,
    budget_ms: f64,
) -> Result<(), BoxError> {
    let mut client = server.client().await;
    let mut frames = client
        .watch_frames(pb::WatchFramesRequest {
            every_k: 1,
            include_poses: poses,
            ..Default::default()
        })
        .await?
        .into_inner();
    let (tx, rx) = tokio::sync::mpsc::channel(64);
    let mut gaze_client = server.client().await;
    let gaze = tokio::spawn(async move {
        gaze_client
            .stream_gaze(tokio_stream::wrappers::ReceiverStream::new(rx))
            .await
    });
    let mut rng = foveal_gaze::rng::SplitMix64::new(0x9e37_79b9_7f4a_7c15);
    let mut latencies = Vec::with_capacity(samples);
    let mut ages = Vec::with_capacity(samples);
    let mut profiles = Vec::new();
    let t0 = Instant::now();
    for i in 0..samples {
        // A fresh point each time, so the frame that first uses it is unambiguous.
        let x = 0.1 + 0.8 * ((i as f64 * 0.618_033_988_75) % 1.0);
        let y = 0.2 + 0.6 * rng.next_f64();
        let sample = pb::GazeSample {
            tracker_time_s: t0.elapsed().as_secs_f64(),
            x,
            y,
            validity: 1.0,
            ..Default::default()
        };
        let sent = Instant::now();
        tx.send(sample).await?;
        loop {
            let frame = tokio::time::timeout(Duration::from_secs(5), frames.message())
                .await??
                .ok_or("frame stream ended")?;
            if let Some(p) = frame.profile {
                profiles.push(p);
            }
            if let Some(f) = frame.fixation.filter(|f| f.x == x && f.y == y) {
                latencies.push(sent.elapsed());
                // Receipt by the server to the start of the frame that used it.
                ages.push(Duration::from_secs_f64(f.age_s.max(0.0)));
                break;
            }
        }
        // A random phase of the frame period before the next sample.
        tokio::time::sleep(period.mul_f64(1.0 + rng.next_f64())).await;
    }
    drop(tx);
    gaze.await??;
    latencies.sort_unstable();
    ages.sort_unstable();
    println!(
        "gaze received -> used by a frame (frame start, server clock, poses {}): n={} p50={:.2} ms p90={:.2} ms p99={:.2} ms max={:.2} ms",
        if poses { "on" } else { "off" },
        ages.len(),
        quantile_ms(&ages, 0.5),
        quantile_ms(&ages, 0.9),
        quantile_ms(&ages, 0.99),
        quantile_ms(&ages, 1.0),
    );
    println!(
        "gaze -> frame latency (StreamGaze, loopback, poses {}): n={} p50={:.2} ms p90={:.2} ms p99={:.2} ms max={:.2} ms",
        if poses { "on" } else { "off" },
        latencies.len(),
        quantile_ms(&latencies, 0.5),
        quantile_ms(&latencies, 0.9),
        quantile_ms(&latencies, 0.99),
        quantile_ms(&latencies, 1.0),
    );
    if !poses {
        print_profile(&profiles, budget_ms);
    }
    Ok(())
}

/// Phase times of the frames seen, against the wall-clock budget (which covers broad + narrow).
fn print_profile(profiles: &[pb::PhaseProfile], budget_ms: f64) {
    let phase = |f: &dyn Fn(&pb::PhaseProfile) -> f64| {
        let mut v: Vec<Duration> = profiles
            .iter()
            .map(|p| Duration::from_secs_f64(f(p).max(0.0)))
            .collect();
        v.sort_unstable();
        format!(
            "p50 {:.2} / p99 {:.2} ms",
            quantile_ms(&v, 0.5),
            quantile_ms(&v, 0.99)
        )
    };
    let over = profiles
        .iter()
        .filter(|p| (p.broad_s + p.narrow_s) * 1e3 > budget_ms + 0.5)
        .count();
    println!(
        "phases over {} frames: integrate {}, broad {}, narrow {}, response {}, T {}; broad+narrow over budget+0.5 ms in {} frames ({:.1}%)",
        profiles.len(),
        phase(&|p| p.integrate_s),
        phase(&|p| p.broad_s),
        phase(&|p| p.narrow_s),
        phase(&|p| p.response_s),
        phase(&|p| p.broad_s + p.narrow_s + p.response_s),
        over,
        100.0 * over as f64 / profiles.len().max(1) as f64,
    );
}

async fn fanout(
    server: &Server,
    subscribers: usize,
    seconds: f64,
    rate: f64,
) -> Result<(), BoxError> {
    let mut status_client = server.client().await;
    let deadline = Instant::now() + Duration::from_secs_f64(seconds);
    let mut tasks = Vec::new();
    for _ in 0..subscribers {
        // One connection per subscriber, as separate viewers would have.
        let mut client = server.client().await;
        let mut frames = client
            .watch_frames(pb::WatchFramesRequest {
                every_k: 1,
                include_poses: true,
                ..Default::default()
            })
            .await?
            .into_inner();
        tasks.push(tokio::spawn(async move {
            let (mut received, mut dropped) = (0u64, 0u64);
            while Instant::now() < deadline {
                match tokio::time::timeout_at(deadline.into(), frames.message()).await {
                    Ok(Ok(Some(f))) => {
                        received += 1;
                        dropped += f.dropped_before;
                    }
                    Ok(_) | Err(_) => break,
                }
            }
            (received, dropped)
        }));
    }
    let before = status_client
        .get_status(pb::GetStatusRequest {})
        .await?
        .into_inner();
    let t_before = Instant::now();
    let mut results = Vec::new();
    for t in tasks {
        results.push(t.await?);
    }
    let after = status_client
        .get_status(pb::GetStatusRequest {})
        .await?
        .into_inner();
    let elapsed = t_before.elapsed().as_secs_f64();
    let loop_fps = (after.frames - before.frames) as f64 / elapsed;
    let mut per_sub: Vec<f64> = results.iter().map(|&(r, _)| r as f64 / seconds).collect();
    per_sub.sort_by(f64::total_cmp);
    let dropped: u64 = results.iter().map(|&(_, d)| d).sum();
    let received: u64 = results.iter().map(|&(r, _)| r).sum();
    println!(
        "fan-out: {subscribers} subscribers with poses for {seconds:.0} s: loop {loop_fps:.1} fps (target {rate}, status fps {:.1}); per subscriber received min {:.1} / median {:.1} / max {:.1} fps; frames received {received}, dropped_before total {dropped} ({:.1}%)",
        after.fps,
        per_sub.first().copied().unwrap_or(0.0),
        per_sub[per_sub.len() / 2],
        per_sub.last().copied().unwrap_or(0.0),
        100.0 * dropped as f64 / (received + dropped).max(1) as f64,
    );
    Ok(())
}

fn main() -> Result<(), BoxError> {
    let bodies: u32 = env_or("FOVEAL_BENCH_BODIES", 10_000);
    let rate: f64 = env_or("FOVEAL_BENCH_RATE", 60.0);
    let budget_ms: f64 = env_or("FOVEAL_BENCH_BUDGET_MS", 4.0);
    let samples: usize = env_or("FOVEAL_BENCH_SAMPLES", 300);
    let seconds: f64 = env_or("FOVEAL_BENCH_SECONDS", 10.0);
    let filter = std::env::var("FOVEAL_LOG").unwrap_or_else(|_| "warn".into());
    foveal_server::telemetry::init(&filter, foveal_server::cli::LogFormat::Text)?;

    let mut config = ServerConfig {
        frame_rate_hz: rate,
        ..ServerConfig::default()
    };
    config.sim.scene.bodies = bodies;
    config.sim.budget = BudgetSpec::WallMs(budget_ms);
    println!(
        "foveal-server bench: N={bodies}, {rate} Hz, budget {budget_ms} ms wall clock, scheduler {}, {} cores",
        config.sim.scheduler.name(),
        std::thread::available_parallelism().map_or(0, |n| n.get()),
    );
    let period = config.frame_period();
    let rt = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()?;
    rt.block_on(async {
        let server = Server::start(config).await;
        // Let the loop settle (first frames warm caches and the broad phase).
        tokio::time::sleep(Duration::from_secs(1)).await;
        latency(&server, samples, false, period, budget_ms).await?;
        latency(&server, samples / 3, true, period, budget_ms).await?;
        fanout(&server, 32, seconds, rate).await?;
        Ok::<(), BoxError>(server.stop().await?)
    })
}
