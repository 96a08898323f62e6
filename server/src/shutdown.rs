//! The shutdown signal every long-lived task listens to (mini-redis style: one sender, a receiver
//! per task, `select!` against it).

use tokio::sync::watch;

/// Sending half: flips the flag once.
#[derive(Debug)]
pub struct ShutdownTrigger(watch::Sender<bool>);

/// Receiving half, cheap to clone into every task.
#[derive(Debug, Clone)]
pub struct Shutdown(watch::Receiver<bool>);

/// A new trigger and its first listener.
pub fn channel() -> (ShutdownTrigger, Shutdown) {
    let (tx, rx) = watch::channel(false);
    (ShutdownTrigger(tx), Shutdown(rx))
}

impl ShutdownTrigger {
    /// Tell every listener to stop.
    pub fn trigger(&self) {
        self.0.send_replace(true);
    }
}

impl Shutdown {
    /// Resolves once shutdown has been triggered (or the trigger is gone, which means the same).
    pub async fn wait(&mut self) {
        // Err means the trigger was dropped: the server is going away either way.
        let _ = self.0.wait_for(|stop| *stop).await;
    }

    /// Whether shutdown has been triggered.
    pub fn is_triggered(&self) -> bool {
        *self.0.borrow()
    }
}
