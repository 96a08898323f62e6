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
    /// No tokens on an address other than loopback, without `--insecure`.
    #[error(
        "refusing to serve {addr} without tokens: anyone who can reach it could reconfigure the scene. Set FOVEAL_VIEWER_TOKEN, FOVEAL_GAZE_TOKEN and FOVEAL_ADMIN_TOKEN (or --tokens PATH), bind 127.0.0.1, or pass --insecure"
    )]
    Insecure {
        /// The address.
        addr: String,
    },
    /// The tokens could not be loaded.
    #[error(transparent)]
    Tokens(#[from] crate::auth::TokenError),
    /// A TLS file could not be read.
    #[error("reading {what} {path}: {source}")]
    TlsFile {
        /// `--tls-cert` or `--tls-key`.
        what: &'static str,
        /// The path.
        path: String,
        /// The I/O error.
        #[source]
        source: std::io::Error,
    },
    /// A TLS file was read but holds no usable PEM certificate or private key.
    #[error("{what} {path}: {reason}; give a PEM file (e.g. from `openssl req -x509 -newkey ...`)")]
    TlsPem {
        /// `--tls-cert` or `--tls-key`.
        what: &'static str,
        /// The path.
        path: String,
        /// What is wrong with it.
        reason: String,
    },
    /// The TLS certificate and key could not be made into a TLS configuration.
    #[error("TLS: {0}")]
    TlsConfig(String),
    /// `--record FILE` could not be created or could not take the session header.
    #[error("--record {path}: cannot record the session there: {source}")]
    Record {
        /// The path.
        path: String,
        /// What failed.
        #[source]
        source: foveal_session::SessionError,
    },
    /// Building the initial simulation was cancelled or panicked.
    #[error("building the initial simulation: {0}")]
    Build(#[from] tokio::task::JoinError),
}
