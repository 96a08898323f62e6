//! Errors of the server library (the binary wraps them in `anyhow`).

use foveal_engine::ConfigError;

/// Why [`crate::run`] could not start or did not stop cleanly.
#[derive(Debug, thiserror::Error)]
pub enum ServerError {
    /// The configuration is invalid (field, value and accepted range in the message).
    #[error(transparent)]
    Config(#[from] ConfigError),
    /// The gRPC transport failed.
    #[error("gRPC transport: {0}")]
    Transport(#[from] tonic::transport::Error),
    /// The reflection service could not be built from the descriptor set.
    #[error("reflection service: {0}")]
    Reflection(#[from] tonic_reflection::server::Error),
    /// The frame loop thread could not be started.
    #[error("starting the frame loop thread: {0}")]
    SpawnLoop(#[source] std::io::Error),
    /// The frame loop thread panicked (the engine hit a bug).
    #[error("the frame loop thread panicked: {0}")]
    LoopPanicked(String),
    /// Building the initial simulation was cancelled or panicked.
    #[error("building the initial simulation: {0}")]
    Build(#[from] tokio::task::JoinError),
}
