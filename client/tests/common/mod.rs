//! An in-process foveal server on a loopback port, for the client's tests.

use std::path::PathBuf;
use std::time::Duration;

use foveal_server::{Limits, ServerConfig};

/// The shared in-process server of the end-to-end tests, with the client tests' scene and
/// `addr` as the client takes it (`http://127.0.0.1:PORT`).
pub struct TestServer {
    /// `http://127.0.0.1:PORT`.
    pub addr: String,
    inner: foveal_tests::TestServer,
}

impl TestServer {
    /// Starts a small scene (150 bodies) whose gaze stays fresh for a minute, so that frames
    /// keep reporting the last replayed gaze however slow the test machine is. Replays go as
    /// fast as possible, so the gaze rate limit is lifted.
    pub async fn start() -> Self {
        let mut config = ServerConfig::default();
        config.sim.scene.bodies = 150;
        config.gaze_max_age = Duration::from_secs(60);
        config.shutdown_grace = Duration::from_secs(2);
        config.limits = Limits {
            max_gaze_rate_hz: 1e9,
            ..Limits::default()
        };
        let inner = foveal_tests::TestServer::start(config).await;
        Self {
            addr: inner.url(),
            inner,
        }
    }

    /// Shuts the server down and waits for it.
    pub async fn stop(self) {
        self.inner.stop().await.expect("server ran cleanly");
    }
}

/// A file of the gaze recording in the repository's `data/gaze`. The recording ships with the
/// repository: a missing file is a failure, named here, not a reason to skip.
pub fn gaze_data(name: &str) -> PathBuf {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../data/gaze")
        .join(name);
    assert!(
        path.is_file(),
        "gaze recording not found: {}",
        path.display()
    );
    path
}
