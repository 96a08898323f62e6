//! Under a tight budget the scheduler spends it near the fixation; the wall-clock budget holds.

use std::time::Duration;

use foveal_engine::{BudgetSpec, EccentricityUnit, PerceptualFunction, PerceptualModel};
use foveal_proto::pb;
use foveal_tests::*;

/// Sums of estimated P, true P (audit) and deemed pairs over `n` frames from `first` on.
async fn perceived_error(
    frames: &mut tonic::Streaming<pb::Frame>,
    first: u64,
    n: usize,
) -> (f64, f64, u64) {
    let mut p = 0.0;
    let mut true_p = 0.0;
    let mut deemed = 0;
    let mut seen = 0;
    while seen < n {
        let f = next_frame(frames).await;
        if f.index < first {
            continue;
        }
        assert_eq!(fixation(&f).source, FixationSource::Gaze as i32);
        let m = f.metrics.expect("metrics");
        p += m.perceived_inaccuracy;
        true_p += m.audit.expect("audit is on").true_perceived_inaccuracy;
        deemed += m.deemed_at_interruption;
        seen += 1;
    }
    (p, true_p, deemed)
}

async fn configure(
    client: &mut pb::foveal_client::FovealClient<tonic::transport::Channel>,
    scheduler: pb::Scheduler,
) -> u64 {
    client
        .configure(pb::ConfigureRequest {
            config: Some(pb::SceneConfig {
                scheduler: scheduler as i32,
                seed: 3,
                // A bool cannot be left unset in Configure: say it again.
                audit: true,
                ..Default::default()
            }),
            update_mask: None,
        })
        .await
        .expect("Configure")
        .into_inner()
        .first_frame_index
}

/// With a sphere-test budget and a fixed fixation every frame is deterministic, so this comparison
/// gives the same numbers on every machine, loaded or not.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn tight_budget_is_spent_near_the_fixation() {
    let mut config = small_config(400, 60.0);
    config.sim.budget = BudgetSpec::FractionOfExact(0.4);
    // Measure with a steep fall-off (weight e^-1 per degree), so P counts what happens near the
    // fixation: the claim under test is that near pairs are resolved more often, not that the
    // whole screen's error drops (for the latter see docs/BENCHMARKS.md: at this budget it does not).
    config.sim.measure_model = PerceptualModel {
        function: PerceptualFunction::F2 { c: 1.0 },
        unit: EccentricityUnit::Degrees,
    };
    config.gaze_max_age = Duration::from_secs(600);
    config.sim.audit = true;
    let server = TestServer::start(config).await;
    let mut client = server.client().await;
    client
        .push_gaze(pb::PushGazeRequest {
            samples: vec![sample(0.0, 0.35, 0.4)],
            source: "test".into(),
        })
        .await
        .expect("PushGaze");
    let mut frames = watch(&mut client, 1, false).await;

    const FRAMES: usize = 40;
    let first = configure(&mut client, pb::Scheduler::RoundRobin).await;
    let (p_rr, true_rr, deemed_rr) = perceived_error(&mut frames, first, FRAMES).await;
    assert!(deemed_rr > 0 && true_rr > 0.0, "the budget must bind");
    // Every run is deterministic (sphere-test budget, fixed fixation). The paper's schedulers
    // and expected-gain rank by the estimate, so the estimate is what they must lower; the priced
    // scheduler deliberately leaves pairs that likely collide (a deemed true collision costs a
    // viewer nothing), so the true P of the audit is what it must lower.
    for (scheduler, at_most, truth) in [
        (pb::Scheduler::PriorityOnly, 0.8, false),
        (pb::Scheduler::ExpectedGain, 0.5, false),
        (pb::Scheduler::Priced, 0.5, true),
    ] {
        let first = configure(&mut client, scheduler).await;
        let (p, true_p, deemed) = perceived_error(&mut frames, first, FRAMES).await;
        println!(
            "P over {FRAMES} frames (estimate, true): round-robin {p_rr:.1}, {true_rr:.2} ({deemed_rr} deemed), {} {p:.1}, {true_p:.2} ({deemed} deemed)",
            scheduler.as_str_name()
        );
        let (got, base) = if truth { (true_p, true_rr) } else { (p, p_rr) };
        assert!(
            got < at_most * base,
            "{}: perceived error {got} not well below round-robin's {base}",
            scheduler.as_str_name()
        );
    }
    server.stop().await.expect("clean stop");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn wall_clock_budget_holds() {
    // Integration and the broad phase take about 0.6 ms here in the test build (opt-level 1) and
    // response and metrics about 0.4 ms: 2 ms leaves the narrow phase time, and binds.
    const BUDGET_MS: f64 = 2.0;
    let mut config = small_config(3000, 30.0);
    config.sim.budget = BudgetSpec::WallMs(BUDGET_MS);
    let server = TestServer::start(config).await;
    let mut client = server.client().await;
    let mut frames = watch(&mut client, 1, false).await;
    let mut over = Vec::new();
    let (mut exhausted, mut sampled, mut starved) = (0, 0, 0);
    const FRAMES: usize = 30;
    for _ in 0..FRAMES {
        let f = next_frame(&mut frames).await;
        let prof = f.profile.expect("profile");
        let m = f.metrics.expect("metrics");
        exhausted += usize::from(m.budget_exhausted);
        // Δ and P say how they were summed: every deemed pair (stride 1), or a sample that fitted
        // the budget, with its standard error.
        assert!(m.metrics_stride >= 1, "stride {}", m.metrics_stride);
        if m.metrics_stride > 1 {
            sampled += 1;
            assert!(m.perceived_inaccuracy_se > 0.0 && m.geometric_inaccuracy_se > 0.0);
        } else {
            assert_eq!(
                (m.perceived_inaccuracy_se, m.geometric_inaccuracy_se),
                (0.0, 0.0)
            );
        }
        // A frame preempted on a shared machine (the suite runs tests side by side; with both
        // cores busy elsewhere most frames do) can find its narrow deadline already past; a
        // budget that did not cover the fixed work would find it so in every frame.
        starved += usize::from(m.budget_spent_before_narrow);
        // The deadline counts from the start of the frame and covers every phase: integration,
        // the broad phase, prioritisation, the narrow phase, response and metrics.
        over.push(
            (prof.integrate_s
                + prof.broad_s
                + prof.prioritise_s
                + prof.narrow_s
                + prof.response_s
                + prof.measure_s)
                * 1e3
                - BUDGET_MS,
        );
    }
    over.sort_by(f64::total_cmp);
    let median_over_ms = over[FRAMES / 2];
    println!(
        "budget {BUDGET_MS} ms: median overshoot {median_over_ms:.3} ms, exhausted in {exhausted}/{FRAMES} frames, Δ and P sampled in {sampled}, starved {starved}"
    );
    assert!(exhausted > 0, "the budget must bind at this N");
    // Under a heavy load from elsewhere every one of 30 frames can be preempted past its narrow
    // deadline; a budget that does not cover the fixed work starves every frame however long
    // we watch, so watch up to twice as many more frames for one that is not starved.
    let mut watched = FRAMES;
    while starved == watched && watched < 3 * FRAMES {
        let m = next_frame(&mut frames).await.metrics.expect("metrics");
        starved += usize::from(m.budget_spent_before_narrow);
        watched += 1;
    }
    assert!(
        starved < watched,
        "{BUDGET_MS} ms must cover this scene's fixed work: all {watched} frames spent it before \
         the narrow phase"
    );
    // Generous: the machine running the suite is shared; the overshoot is a few µs unloaded.
    // Tight enough to fail if response and metrics (about 0.4 ms here) ran past the deadline.
    assert!(
        median_over_ms < 0.25,
        "median overshoot {median_over_ms} ms"
    );
    server.stop().await.expect("clean stop");
}
