//! An in-process foveal server on a loopback port, for the client's tests.

use std::path::PathBuf;
use std::time::Duration;

use foveal_server::{ServerConfig, ServerError};
use tokio::net::TcpListener;
use tokio::sync::oneshot;
use tokio::task::JoinHandle;

/// A running server; [`TestServer::stop`] shuts it down and checks it stopped cleanly.
pub struct TestServer {
    /// `http://127.0.0.1:PORT`.
    pub addr: String,
    stop: Option<oneshot::Sender<()>>,
    task: JoinHandle<Result<(), ServerError>>,
}

impl TestServer {
    /// Starts a small scene (150 bodies) whose gaze stays fresh for a minute, so that frames
    /// keep reporting the last replayed gaze however slow the test machine is.
    pub async fn start() -> Self {
        let listener = TcpListener::bind("127.0.0.1:0").await.expect("bind");
        let addr = format!("http://{}", listener.local_addr().expect("local addr"));
        let mut config = ServerConfig::default();
        config.sim.scene.bodies = 150;
        config.gaze_max_age = Duration::from_secs(60);
        config.shutdown_grace = Duration::from_secs(2);
        let (stop, stopped) = oneshot::channel::<()>();
        let task = tokio::spawn(foveal_server::run(listener, config, async {
            let _ = stopped.await;
        }));
        Self {
            addr,
            stop: Some(stop),
            task,
        }
    }

    /// Shuts the server down and waits for it.
    pub async fn stop(mut self) {
        if let Some(stop) = self.stop.take() {
            let _ = stop.send(());
        }
        let served = tokio::time::timeout(Duration::from_secs(10), &mut self.task)
            .await
            .expect("server stops within 10 s")
            .expect("server task did not panic");
        served.expect("server ran cleanly");
    }
}

/// A file of the shared gaze recordings.
pub fn gaze_data(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../shared/data/gaze")
        .join(name)
}
