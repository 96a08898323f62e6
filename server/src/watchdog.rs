//! Health follows the loop: NOT_SERVING when no frame has completed for a stated number of frame
//! periods ([`crate::ServerConfig::stall_periods`]), SERVING again as soon as frames complete.
//! A loop paused on purpose (Pause) is not stalled, and a resumed one is given its periods from
//! the moment it resumed.
//!
//! Without it, health said SERVING and GetStatus its last good fps while frames took seconds each.

use std::sync::Arc;
use std::time::{Duration, Instant};

use tonic_health::ServingStatus;
use tonic_health::server::HealthReporter;

use crate::shutdown::Shutdown;
use crate::state::Shared;

/// How often the watchdog looks, at most (it also looks every frame period at fast rates).
const MAX_CHECK_INTERVAL: Duration = Duration::from_millis(50);

/// Whether the loop counts as stalled at `now`: its latest frame (or its start, before any frame)
/// is more than `periods` frame periods old.
pub fn stalled(last: Instant, now: Instant, period: Duration, periods: u32) -> bool {
    now.saturating_duration_since(last) > period * periods
}

/// The foveal service's status and the server's as a whole (`""`, what probes ask by default).
pub async fn set(health: &HealthReporter, status: ServingStatus) {
    for service in ["", crate::FOVEAL_SERVICE_NAME] {
        health.set_service_status(service, status).await;
    }
}

/// Watch the loop until shutdown, flipping health on transitions and logging them.
pub async fn run(
    shared: Arc<Shared>,
    health: HealthReporter,
    periods: u32,
    mut shutdown: Shutdown,
) {
    let started = Instant::now();
    let mut serving = true;
    loop {
        let period = crate::config::frame_period(shared.scene().frame_rate_hz);
        let check = period.min(MAX_CHECK_INTERVAL);
        tokio::select! {
            () = shutdown.wait() => return,
            () = tokio::time::sleep(check) => {}
        }
        let mut last = shared.metrics.last_frame_at().unwrap_or(started);
        if let Some(resumed) = shared.resumed_at() {
            last = last.max(resumed);
        }
        let now = Instant::now();
        let is_stalled = !shared.paused() && stalled(last, now, period, periods);
        if is_stalled && serving {
            serving = false;
            tracing::warn!(
                since_last_frame_ms = now.saturating_duration_since(last).as_secs_f64() * 1e3,
                stall_periods = periods,
                "no frame completed for the stall threshold; health is NOT_SERVING"
            );
            set(&health, ServingStatus::NotServing).await;
        } else if !is_stalled && !serving {
            serving = true;
            tracing::info!("frames complete again; health is SERVING");
            set(&health, ServingStatus::Serving).await;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stalled_after_the_stated_periods() {
        let t0 = Instant::now();
        let p = Duration::from_millis(10);
        assert!(!stalled(t0, t0 + Duration::from_millis(300), p, 30));
        assert!(stalled(t0, t0 + Duration::from_millis(301), p, 30));
    }
}
