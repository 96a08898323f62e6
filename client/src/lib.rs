//! # foveal-client
//!
//! The client side of foveal: it feeds the server gaze (scripted, replayed from a recording, or
//! bridged live from an eye tracker), watches the frames and metrics that come back, and checks
//! the server's health. The `foveal` binary is a thin command line over this library; tests and
//! experiment scripts use the library directly.
//!
//! # Layout
//! - [`connect`], [`connect_with`], [`endpoint`], [`ClientError`]: one way to reach a server, with
//!   a short connect timeout so that a missing server fails fast instead of hanging a script, and
//!   [`ConnectOptions`]: the bearer token and the CA certificate of a server behind TLS.
//! - [`gaze`]: the `foveal-gaze` crate, re-exported: pure parsers and generators of
//!   [`gaze::GazeSample`]s (CSV, EyeLink ASC, Gazepoint Open Gaze, scripted gaze), validation,
//!   filters and fixation detection.
//! - [`pacer`]: maps sample timestamps to wall-clock deadlines for real-time or N× replay.
//! - [`sender`]: [`sender::GazeSender`], one interface over the two gaze rpcs (client streaming
//!   `StreamGaze`, unary batched `PushGaze`) that returns one [`sender::SendSummary`].
//! - [`source`]: sample sources as channels: recordings (CSV or ASC, detected), live CSV lines
//!   from stdin, a Gazepoint tracker over TCP, scripts.
//! - [`pupil`]: a Pupil Core tracker (Pupil Remote and its gaze topics over ZeroMQ) as a source.
//! - [`lsl`]: a Lab Streaming Layer outlet as a source, over LSL's wire protocol in Rust.
//! - [`bridge`]: [`bridge::forward`], the one loop from a source through the pacer into a sender
//!   that keeps going past malformed input and counts what it saw.
//! - [`fixations`]: `foveal fixations`, the online detector run over a recording, scored against a
//!   reference list.
//! - [`watch`]: subscribes to frames, prints a summary line per second, writes frame metrics as CSV.
//! - [`health`]: the standard gRPC health check.
//! - [`cli`]: the `foveal` command line (clap): its subcommands and flags, and the [`commands`]
//!   they describe.
//! - [`commands`]: the `foveal` subcommands, one call each, that the binary parses its arguments
//!   into: what `gaze` and `bridge` send, the server they talk to, how each ends.

use std::time::Duration;

use foveal_proto::pb::foveal_client::FovealClient;
use thiserror::Error;
use tonic::metadata::{Ascii, MetadataValue};
use tonic::service::Interceptor;
use tonic::service::interceptor::InterceptedService;
use tonic::transport::{Certificate, Channel, ClientTlsConfig, Endpoint};

pub mod bridge;
pub mod cli;
pub mod commands;
pub mod fixations;
pub use foveal_gaze as gaze;
pub mod health;
pub mod load;
pub mod lsl;
pub mod pacer;
pub mod pupil;
pub mod sender;
pub mod source;
pub mod watch;

/// Address the server listens on by default.
pub const DEFAULT_ADDR: &str = "http://127.0.0.1:50051";

/// How long [`connect`] waits for the TCP (and HTTP/2) connection. Short, because the usual
/// cause of a slow connect is a server that is not there, and scripts should hear so quickly.
pub const CONNECT_TIMEOUT: Duration = Duration::from_secs(5);

/// Largest message the client accepts. Frames with poses grow with the body count (28 bytes per
/// body), so the 4 MiB default of gRPC would cut `watch --poses` off at about 150k bodies.
pub const MAX_MESSAGE_BYTES: usize = 256 * 1024 * 1024;

/// An error of the client library.
#[derive(Debug, Error)]
pub enum ClientError {
    /// The server address does not parse as a URI.
    #[error("invalid server address {addr:?}: {source}")]
    InvalidAddress {
        /// The address as given.
        addr: String,
        /// Why it does not parse.
        #[source]
        source: tonic::transport::Error,
    },
    /// The connection could not be made.
    #[error("cannot connect to {addr}: {source}")]
    Connect {
        /// The address.
        addr: String,
        /// The transport error.
        #[source]
        source: tonic::transport::Error,
    },
    /// The server answered a call with an error status.
    #[error("{rpc} failed: {status}")]
    Rpc {
        /// The rpc, e.g. `StreamGaze`.
        rpc: &'static str,
        /// The status the server (or the transport) gave.
        status: tonic::Status,
    },
    /// Local input or output failed (a recording, the CSV output).
    #[error("{what}: {source}")]
    Io {
        /// What was being done, e.g. `open recording.csv`.
        what: String,
        /// The I/O error.
        #[source]
        source: std::io::Error,
    },
    /// An option has a value that cannot work.
    #[error("invalid option `{name}`: {reason}")]
    InvalidOption {
        /// Option name.
        name: &'static str,
        /// What is wrong.
        reason: String,
    },
}

impl ClientError {
    /// Wraps an I/O error with what was being done.
    pub(crate) fn io(what: impl Into<String>, source: std::io::Error) -> Self {
        Self::Io {
            what: what.into(),
            source,
        }
    }
}

/// `addr` as a URI to dial: `http://` prepended when it names no scheme, and an unspecified
/// host (`0.0.0.0`, `[::]`) replaced by loopback. Both let the server's own listen address
/// (`FOVEAL_ADDR=0.0.0.0:50051` in a container) serve as the client's, as a container health
/// check does.
#[must_use]
pub fn normalise_addr(addr: &str) -> String {
    let (scheme, rest) = addr.split_once("://").unwrap_or(("http", addr));
    let rest = if let Some(port) = rest.strip_prefix("0.0.0.0:") {
        format!("127.0.0.1:{port}")
    } else if let Some(port) = rest.strip_prefix("[::]:") {
        format!("[::1]:{port}")
    } else {
        rest.to_owned()
    };
    format!("{scheme}://{rest}")
}

/// How to reach a server beyond its address: the bearer token its roles need and, for a server
/// behind TLS (`https://`) whose certificate no system root signed, the CA certificate (PEM) that did.
#[derive(Clone, Default)]
pub struct ConnectOptions {
    /// Sent as `authorization: Bearer <token>` on every call.
    pub token: Option<String>,
    /// The CA certificate to trust, PEM, for `https://` addresses (the only one trusted then);
    /// without it the system's trusted roots are.
    pub ca_pem: Option<Vec<u8>>,
}

// The token is a secret: never in a log line.
impl std::fmt::Debug for ConnectOptions {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ConnectOptions")
            .field("token", &self.token.as_ref().map(|_| "<set>"))
            .field("ca_pem_bytes", &self.ca_pem.as_ref().map(Vec::len))
            .finish()
    }
}

/// Adds the bearer token (if any) to every call.
#[derive(Debug, Clone, Default)]
pub struct Credentials {
    header: Option<MetadataValue<Ascii>>,
}

impl Credentials {
    /// Credentials presenting `token`.
    ///
    /// # Errors
    /// [`ClientError::InvalidOption`] for a token that cannot be a header value.
    pub fn bearer(token: Option<&str>) -> Result<Self, ClientError> {
        let header = token
            .map(|t| {
                format!("Bearer {t}")
                    .parse::<MetadataValue<Ascii>>()
                    .map_err(|_| ClientError::InvalidOption {
                        name: "token",
                        reason: "must be printable ASCII without spaces".into(),
                    })
            })
            .transpose()?;
        Ok(Self { header })
    }
}

impl Interceptor for Credentials {
    fn call(&mut self, mut req: tonic::Request<()>) -> Result<tonic::Request<()>, tonic::Status> {
        if let Some(h) = &self.header {
            req.metadata_mut().insert("authorization", h.clone());
        }
        Ok(req)
    }
}

/// A connection with credentials.
pub type Connection = InterceptedService<Channel, Credentials>;
/// The foveal client every part of this library uses.
pub type Client = FovealClient<Connection>;

/// `endpoint` with TLS set up when `addr` is `https://`: trusting only the CA of
/// [`ConnectOptions::ca_pem`] when one is given (a deployment with its own CA), the system's
/// trusted roots otherwise (a server with a certificate from a public CA, as a browser would).
///
/// # Errors
/// [`ClientError::InvalidOption`] for a CA that is not PEM, or system roots that cannot be read.
pub fn secure(
    addr: &str,
    endpoint: Endpoint,
    options: &ConnectOptions,
) -> Result<Endpoint, ClientError> {
    if !normalise_addr(addr).starts_with("https://") {
        return Ok(endpoint);
    }
    let (tls, what) = match &options.ca_pem {
        Some(ca) => (
            ClientTlsConfig::new().ca_certificate(Certificate::from_pem(ca)),
            "not a usable PEM CA certificate",
        ),
        None => (
            ClientTlsConfig::new().with_native_roots(),
            "the system's trusted certificates could not be loaded; give the server's CA with --ca PATH (or FOVEAL_CA)",
        ),
    };
    endpoint
        .tls_config(tls)
        .map_err(|e| ClientError::InvalidOption {
            name: "ca",
            reason: format!("{what}: {e}"),
        })
}

/// An endpoint for `addr` (see [`normalise_addr`]) with the given connect timeout.
///
/// # Errors
/// [`ClientError::InvalidAddress`] when the address is not a URI.
pub fn endpoint(addr: &str, connect_timeout: Duration) -> Result<Endpoint, ClientError> {
    let addr = normalise_addr(addr);
    Endpoint::from_shared(addr.clone())
        .map(|e| e.connect_timeout(connect_timeout).tcp_nodelay(true))
        .map_err(|source| ClientError::InvalidAddress { addr, source })
}

/// Opens `endpoint` (built for `addr`), naming `addr` in the error.
pub(crate) async fn open(
    addr: &str,
    endpoint: tonic::transport::Endpoint,
) -> Result<Channel, ClientError> {
    endpoint
        .connect()
        .await
        .map_err(|source| ClientError::Connect {
            addr: normalise_addr(addr),
            source,
        })
}

/// Connects to the foveal server at `addr` (e.g. `http://127.0.0.1:50051`), waiting at most
/// [`CONNECT_TIMEOUT`].
///
/// # Errors
/// [`ClientError::InvalidAddress`] or [`ClientError::Connect`].
pub async fn connect(addr: &str) -> Result<Client, ClientError> {
    connect_with(addr, &ConnectOptions::default()).await
}

/// Connects like [`connect`], presenting `options`' token and trusting its CA.
///
/// # Errors
/// [`ClientError::InvalidAddress`], [`ClientError::Connect`] or [`ClientError::InvalidOption`].
pub async fn connect_with(addr: &str, options: &ConnectOptions) -> Result<Client, ClientError> {
    let endpoint = secure(addr, endpoint(addr, CONNECT_TIMEOUT)?, options)?;
    let credentials = Credentials::bearer(options.token.as_deref())?;
    let channel = open(addr, endpoint).await?;
    Ok(FovealClient::with_interceptor(channel, credentials)
        .max_decoding_message_size(MAX_MESSAGE_BYTES)
        .max_encoding_message_size(MAX_MESSAGE_BYTES))
}

#[cfg(test)]
mod tls_tests {
    use super::*;

    #[test]
    fn https_without_a_ca_trusts_the_system_roots() {
        let addr = "https://foveal.example.org:50051";
        let e = endpoint(addr, Duration::from_secs(1)).expect("an address");
        let options = ConnectOptions {
            token: None,
            ca_pem: None,
        };
        assert!(
            secure(addr, e, &options).is_ok(),
            "an https address needs no --ca"
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn addresses_without_scheme_get_http() {
        assert_eq!(normalise_addr("127.0.0.1:50051"), "http://127.0.0.1:50051");
        assert_eq!(normalise_addr("https://x:1"), "https://x:1");
        assert_eq!(normalise_addr("0.0.0.0:7000"), "http://127.0.0.1:7000");
        assert_eq!(normalise_addr("http://[::]:7000"), "http://[::1]:7000");
        assert!(endpoint("http://[::1", CONNECT_TIMEOUT).is_err());
    }
}
