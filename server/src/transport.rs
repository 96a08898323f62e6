//! The listener and its connections: how many a client may hold, and for how long.
//!
//! tonic's own server loop retries a failed accept at once (at the descriptor limit it spins a
//! core and says nothing), gives HTTP/1.1 no timer (a half-sent request head is held forever),
//! and offers only h2 over TLS (so a browser cannot load the viewer from an `https://` server).
//! So the server runs its connections itself, on hyper, with tonic's routes as the service:
//!
//! - at most [`ConnectionLimits::max_connections`] at once; one more is accepted and closed at
//!   once (a client fails fast and retries instead of waiting in the listen backlog);
//! - an accept that fails for want of descriptors or memory (EMFILE, ENFILE, ENOBUFS, ENOMEM)
//!   backs off, 5 ms doubling to 1 s, with one log line per [`LOG_EVERY`];
//! - timeouts: the first byte (the TLS handshake included), the first request's head after its
//!   first byte (and every HTTP/1.1 head, also between keep-alive requests), a request body that
//!   sends nothing, and a connection with no call in progress;
//! - TLS offers h2 and http/1.1 (ALPN), so the viewer works over `https://`;
//! - at shutdown every connection is asked to finish (GOAWAY, or close after the response in
//!   progress), and those still open after [`SHUTDOWN_LINGER`] are dropped.

use std::future::Future;
use std::io;
use std::net::SocketAddr;
use std::pin::Pin;
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, PoisonError};
use std::task::{Context, Poll};
use std::time::{Duration, Instant};

use http_body::{Body as HttpBody, Frame, SizeHint};
use hyper::body::{Bytes, Incoming};
use hyper_util::rt::{TokioExecutor, TokioIo, TokioTimer};
use hyper_util::server::conn::auto;
use hyper_util::service::TowerToHyperService;
use tokio::io::{AsyncRead, AsyncWrite, ReadBuf};
use tokio::net::{TcpListener, TcpStream};
use tokio::sync::{Semaphore, watch};
use tokio::task::JoinSet;
use tokio::time::Sleep;
use tokio_rustls::TlsAcceptor;
use tokio_rustls::server::TlsStream;
use tonic::body::Body;
use tonic::codegen::http::{self, Request, Response, Version};
use tonic::transport::server::TcpConnectInfo;
use tower::Service;

use crate::config::TlsIdentity;
use crate::error::ServerError;
use crate::limits;
use crate::shutdown::Shutdown;

type BoxError = Box<dyn std::error::Error + Send + Sync>;
type BoxFuture<T> = Pin<Box<dyn Future<Output = T> + Send>>;

/// Connections the server holds at once unless `--max-connections` says otherwise (fewer when
/// the process may not open that many descriptors, see [`effective_max_connections`]).
pub const DEFAULT_MAX_CONNECTIONS: usize = 1024;
/// Descriptors kept back from the connection limit for everything else the process opens
/// (the listener, the runtime, the record file, standard streams, a client's burst).
pub const RESERVED_DESCRIPTORS: u64 = 64;
/// Default time a new connection has to send its first byte (a TLS connection: to finish its
/// handshake and send its first byte). Browsers open connections ahead of need; 10 s keeps those
/// while a port scan or a stalled client frees its descriptor soon.
pub const DEFAULT_FIRST_BYTE_TIMEOUT: Duration = Duration::from_secs(10);
/// Default time a request head has to arrive once its first byte has (hyper's default is 30 s;
/// a head is one packet from every real client).
pub const DEFAULT_HEADER_TIMEOUT: Duration = Duration::from_secs(10);
/// Default time a request body may send nothing before the call is failed (nginx's
/// `client_body_timeout` is 60 s; a unary message here is at most 4 MiB and leaves at once).
pub const DEFAULT_BODY_IDLE_TIMEOUT: Duration = Duration::from_secs(30);
/// Default time a connection may stay open with no call in progress (Envoy's stream idle
/// timeout; gRPC clients reconnect on their own when they need the connection again).
pub const DEFAULT_IDLE_TIMEOUT: Duration = Duration::from_secs(300);
/// Longest timeout accepted for any of the above.
pub const MAX_TIMEOUT: Duration = Duration::from_secs(24 * 3600);
/// At most one log line per this long for a repeated condition (descriptors exhausted, the
/// connection limit, refused credentials); the next line says how many were not logged.
pub const LOG_EVERY: Duration = Duration::from_secs(10);
/// After open calls have finished at shutdown, how long responses already written get to leave
/// before the connections still open (a subscriber that stopped reading) are abandoned.
pub const SHUTDOWN_LINGER: Duration = Duration::from_millis(250);
/// First pause after an accept failed for want of resources; doubles up to [`MAX_BACKOFF`].
const MIN_BACKOFF: Duration = Duration::from_millis(5);
/// Longest pause between accepts while descriptors or memory are exhausted.
const MAX_BACKOFF: Duration = Duration::from_secs(1);
/// The one client-streaming method: its body is a live gaze stream that may pause for as long
/// as the tracker does; HTTP/2 keepalive finds a dead peer and shutdown ends it in its handler.
const STREAM_GAZE_PATH: &str = "/foveal.v1.Foveal/StreamGaze";

/// What a connection may hold and for how long (flags `--max-connections`,
/// `--first-byte-timeout`, `--header-timeout`, `--body-idle-timeout`, `--idle-timeout`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ConnectionLimits {
    /// Connections held at once; `None`: [`DEFAULT_MAX_CONNECTIONS`], or fewer when the
    /// descriptor limit is lower.
    pub max_connections: Option<usize>,
    /// From accept to the first byte (TLS: through the handshake to the first byte of HTTP).
    pub first_byte_timeout: Duration,
    /// From a request head's first byte to its end (every HTTP/1.1 head; on HTTP/2 the preface
    /// and the first request's headers).
    pub header_timeout: Duration,
    /// Longest silence of a request body before the call fails (DEADLINE_EXCEEDED). StreamGaze
    /// over HTTP/2 is exempt: a tracker may pause.
    pub body_idle_timeout: Duration,
    /// Longest time a connection stays open with no call in progress.
    pub idle_timeout: Duration,
}

impl Default for ConnectionLimits {
    fn default() -> Self {
        Self {
            max_connections: None,
            first_byte_timeout: DEFAULT_FIRST_BYTE_TIMEOUT,
            header_timeout: DEFAULT_HEADER_TIMEOUT,
            body_idle_timeout: DEFAULT_BODY_IDLE_TIMEOUT,
            idle_timeout: DEFAULT_IDLE_TIMEOUT,
        }
    }
}

impl ConnectionLimits {
    /// Check every limit; the error names the field and the accepted range.
    pub fn validate(&self) -> Result<(), foveal_engine::ConfigError> {
        if self.max_connections == Some(0) {
            return Err(foveal_engine::ConfigError {
                field: "max_connections",
                value: "0".into(),
                expected: "must be >= 1".into(),
            });
        }
        for (field, t) in [
            ("first_byte_timeout", self.first_byte_timeout),
            ("header_timeout", self.header_timeout),
            ("body_idle_timeout", self.body_idle_timeout),
            ("idle_timeout", self.idle_timeout),
        ] {
            if t.is_zero() || t > MAX_TIMEOUT {
                return Err(foveal_engine::ConfigError {
                    field,
                    value: format!("{t:?}"),
                    expected: format!("must be > 0 and <= {} s", MAX_TIMEOUT.as_secs()),
                });
            }
        }
        Ok(())
    }
}

/// The connection limit in force: the configured one, or by default [`DEFAULT_MAX_CONNECTIONS`]
/// lowered to what the soft descriptor limit `nofile` leaves after [`RESERVED_DESCRIPTORS`]
/// (half of it when it is tiny), so that the default never runs the process out of descriptors.
pub fn effective_max_connections(configured: Option<usize>, nofile: Option<u64>) -> usize {
    if let Some(n) = configured {
        return n.max(1);
    }
    let room = match nofile {
        Some(n) if n > 2 * RESERVED_DESCRIPTORS => n - RESERVED_DESCRIPTORS,
        Some(n) => n / 2,
        None => u64::MAX,
    };
    usize::try_from(room)
        .unwrap_or(usize::MAX)
        .clamp(1, DEFAULT_MAX_CONNECTIONS)
}

/// The process's soft descriptor limit, if it has one.
fn descriptor_limit() -> Option<u64> {
    rustix::process::getrlimit(rustix::process::Resource::Nofile).current
}

/// Allows one log line per period and counts the ones it held back.
#[derive(Debug)]
pub struct Every {
    period: Duration,
    last: Mutex<Option<Instant>>,
    held: AtomicU64,
}

impl Every {
    /// At most one line per `period`.
    pub fn new(period: Duration) -> Self {
        Self {
            period,
            last: Mutex::new(None),
            held: AtomicU64::new(0),
        }
    }

    /// `Some(lines held back since the last one)` when a line may be written now.
    pub fn check(&self, now: Instant) -> Option<u64> {
        let mut last = self.last.lock().unwrap_or_else(PoisonError::into_inner);
        match *last {
            Some(t) if now.saturating_duration_since(t) < self.period => {
                self.held.fetch_add(1, Ordering::Relaxed);
                None
            }
            _ => {
                *last = Some(now);
                Some(self.held.swap(0, Ordering::Relaxed))
            }
        }
    }
}

/// What one connection's calls share (in every request's extensions).
#[derive(Debug)]
pub struct ConnState {
    /// The client's address.
    pub remote: Option<SocketAddr>,
    /// Calls whose response has not finished.
    calls: watch::Sender<usize>,
    /// Whether a request head has ever arrived (ends the first-request deadline).
    started: AtomicBool,
    /// Health watches open on this connection.
    pub health_watches: AtomicUsize,
}

impl ConnState {
    fn new(remote: Option<SocketAddr>) -> Arc<Self> {
        Arc::new(Self {
            remote,
            calls: watch::Sender::new(0),
            started: AtomicBool::new(false),
            health_watches: AtomicUsize::new(0),
        })
    }

    /// Resolves once the connection has had no call in progress for `idle`.
    async fn idle_for(&self, idle: Duration) {
        let mut calls = self.calls.subscribe();
        loop {
            // Err: the sender lives in `self`, which outlives this future.
            let _ = calls.wait_for(|n| *n == 0).await;
            tokio::select! {
                () = tokio::time::sleep(idle) => {
                    if *calls.borrow() == 0 {
                        return;
                    }
                }
                _ = calls.changed() => {}
            }
        }
    }
}

/// One call counted on its connection until its response has finished.
#[derive(Debug)]
struct CallGuard(Arc<ConnState>);

impl CallGuard {
    fn new(conn: Arc<ConnState>) -> Self {
        conn.started.store(true, Ordering::Release);
        conn.calls.send_modify(|n| *n += 1);
        Self(conn)
    }
}

impl Drop for CallGuard {
    fn drop(&mut self) {
        self.0.calls.send_modify(|n| *n = n.saturating_sub(1));
    }
}

/// A response body that keeps `guard` alive until the body is done with (sent or dropped).
#[derive(Debug)]
pub struct Guarded<G> {
    inner: Body,
    _guard: G,
}

impl<G: Send + Unpin + 'static> Guarded<G> {
    /// `inner`, holding `guard` for as long as it lives.
    pub fn body(inner: Body, guard: G) -> Body {
        Body::new(Self {
            inner,
            _guard: guard,
        })
    }
}

impl<G: Unpin> HttpBody for Guarded<G> {
    type Data = Bytes;
    type Error = tonic::Status;

    fn poll_frame(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
    ) -> Poll<Option<Result<Frame<Bytes>, tonic::Status>>> {
        Pin::new(&mut self.get_mut().inner).poll_frame(cx)
    }

    fn is_end_stream(&self) -> bool {
        self.inner.is_end_stream()
    }

    fn size_hint(&self) -> SizeHint {
        self.inner.size_hint()
    }
}

/// How a request's body is watched (put in its extensions by the transport, applied by the
/// gate inside the grpc-web translation, so that its status reaches a browser unchanged).
#[derive(Debug, Clone)]
pub struct BodyPolicy {
    /// Fail the call when the body sends nothing for this long.
    idle: Option<Duration>,
    /// Fail the call when shutdown starts while the body is awaited.
    stop: Option<Shutdown>,
}

impl BodyPolicy {
    /// `body` under this policy.
    pub fn apply<B>(&self, body: B) -> Body
    where
        B: HttpBody<Data = Bytes> + Send + Unpin + 'static,
        B::Error: Into<BoxError>,
    {
        Body::new(IdleBody {
            inner: body,
            idle: self.idle.map(|d| (d, Box::pin(tokio::time::sleep(d)))),
            stop: self
                .stop
                .clone()
                .map(|mut s| -> BoxFuture<()> { Box::pin(async move { s.wait().await }) }),
        })
    }
}

/// A request body that fails when it sends nothing for too long, or when the server shuts down
/// while waiting for it: a call never waits on a body that does not arrive.
struct IdleBody<B> {
    inner: B,
    idle: Option<(Duration, Pin<Box<Sleep>>)>,
    stop: Option<BoxFuture<()>>,
}

impl<B> HttpBody for IdleBody<B>
where
    B: HttpBody<Data = Bytes> + Unpin,
    B::Error: Into<BoxError>,
{
    type Data = Bytes;
    type Error = tonic::Status;

    fn poll_frame(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
    ) -> Poll<Option<Result<Frame<Bytes>, tonic::Status>>> {
        let this = self.get_mut();
        if let Poll::Ready(frame) = Pin::new(&mut this.inner).poll_frame(cx) {
            if let Some((d, sleep)) = &mut this.idle {
                sleep.as_mut().reset(tokio::time::Instant::now() + *d);
            }
            return Poll::Ready(frame.map(|f| f.map_err(|e| tonic::Status::from_error(e.into()))));
        }
        if let Some(stop) = &mut this.stop
            && stop.as_mut().poll(cx).is_ready()
        {
            this.stop = None;
            this.idle = None;
            return Poll::Ready(Some(Err(tonic::Status::unavailable(
                "the server is shutting down and the request body had not arrived: retry against another instance or after restart",
            ))));
        }
        if let Some((d, sleep)) = &mut this.idle
            && sleep.as_mut().poll(cx).is_ready()
        {
            let d = *d;
            this.idle = None;
            this.stop = None;
            return Poll::Ready(Some(Err(tonic::Status::deadline_exceeded(format!(
                "the request body sent nothing for {} s (server limit --body-idle-timeout): send the whole request at once",
                d.as_secs_f64()
            )))));
        }
        Poll::Pending
    }

    fn is_end_stream(&self) -> bool {
        self.inner.is_end_stream()
    }

    fn size_hint(&self) -> SizeHint {
        self.inner.size_hint()
    }
}

/// A plain or TLS connection.
enum Io {
    Plain(TcpStream),
    Tls(Box<TlsStream<TcpStream>>),
}

impl AsyncRead for Io {
    fn poll_read(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        buf: &mut ReadBuf<'_>,
    ) -> Poll<io::Result<()>> {
        match self.get_mut() {
            Self::Plain(s) => Pin::new(s).poll_read(cx, buf),
            Self::Tls(s) => Pin::new(s.as_mut()).poll_read(cx, buf),
        }
    }
}

impl AsyncWrite for Io {
    fn poll_write(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        buf: &[u8],
    ) -> Poll<io::Result<usize>> {
        match self.get_mut() {
            Self::Plain(s) => Pin::new(s).poll_write(cx, buf),
            Self::Tls(s) => Pin::new(s.as_mut()).poll_write(cx, buf),
        }
    }

    fn poll_flush(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        match self.get_mut() {
            Self::Plain(s) => Pin::new(s).poll_flush(cx),
            Self::Tls(s) => Pin::new(s.as_mut()).poll_flush(cx),
        }
    }

    fn poll_shutdown(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        match self.get_mut() {
            Self::Plain(s) => Pin::new(s).poll_shutdown(cx),
            Self::Tls(s) => Pin::new(s.as_mut()).poll_shutdown(cx),
        }
    }

    fn poll_write_vectored(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        bufs: &[io::IoSlice<'_>],
    ) -> Poll<io::Result<usize>> {
        match self.get_mut() {
            Self::Plain(s) => Pin::new(s).poll_write_vectored(cx, bufs),
            Self::Tls(s) => Pin::new(s.as_mut()).poll_write_vectored(cx, bufs),
        }
    }

    fn is_write_vectored(&self) -> bool {
        match self {
            Self::Plain(s) => s.is_write_vectored(),
            Self::Tls(s) => s.is_write_vectored(),
        }
    }
}

/// Reads that must bring the first byte by a deadline, and then the first request's head
/// within the header timeout; once a request has arrived they pass through untouched (hyper's
/// HTTP/1.1 head timeout and the idle timeout take over).
struct FirstRequest {
    inner: Io,
    conn: Arc<ConnState>,
    header_timeout: Duration,
    seen_byte: bool,
    deadline: Option<Pin<Box<Sleep>>>,
}

impl AsyncRead for FirstRequest {
    fn poll_read(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        buf: &mut ReadBuf<'_>,
    ) -> Poll<io::Result<()>> {
        let this = self.get_mut();
        if this.deadline.is_some() && this.conn.started.load(Ordering::Acquire) {
            this.deadline = None;
        }
        let before = buf.filled().len();
        let read = Pin::new(&mut this.inner).poll_read(cx, buf);
        let Some(deadline) = &mut this.deadline else {
            return read;
        };
        match read {
            Poll::Ready(Ok(())) => {
                if !this.seen_byte && buf.filled().len() > before {
                    this.seen_byte = true;
                    deadline
                        .as_mut()
                        .reset(tokio::time::Instant::now() + this.header_timeout);
                }
                Poll::Ready(Ok(()))
            }
            Poll::Ready(Err(e)) => Poll::Ready(Err(e)),
            Poll::Pending => {
                if deadline.as_mut().poll(cx).is_ready() {
                    let what = if this.seen_byte {
                        "no request head within the header timeout"
                    } else {
                        "no first byte within the first-byte timeout"
                    };
                    return Poll::Ready(Err(io::Error::new(io::ErrorKind::TimedOut, what)));
                }
                Poll::Pending
            }
        }
    }
}

impl AsyncWrite for FirstRequest {
    fn poll_write(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        buf: &[u8],
    ) -> Poll<io::Result<usize>> {
        Pin::new(&mut self.get_mut().inner).poll_write(cx, buf)
    }

    fn poll_flush(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        Pin::new(&mut self.get_mut().inner).poll_flush(cx)
    }

    fn poll_shutdown(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        Pin::new(&mut self.get_mut().inner).poll_shutdown(cx)
    }

    fn poll_write_vectored(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        bufs: &[io::IoSlice<'_>],
    ) -> Poll<io::Result<usize>> {
        Pin::new(&mut self.get_mut().inner).poll_write_vectored(cx, bufs)
    }

    fn is_write_vectored(&self) -> bool {
        self.inner.is_write_vectored()
    }
}

/// The service of one connection: marks its requests with the connection (address, state),
/// wraps their bodies in the idle timeout and counts calls until their responses finish.
#[derive(Clone)]
struct ConnService<S> {
    inner: S,
    conn: Arc<ConnState>,
    info: TcpConnectInfo,
    body_idle: Duration,
    shutdown: Shutdown,
}

impl<S, RB> Service<Request<Incoming>> for ConnService<S>
where
    S: Service<Request<Body>, Response = Response<RB>, Error = BoxError> + Send + 'static,
    S::Future: Send + 'static,
    RB: HttpBody<Data = Bytes> + Send + 'static,
    RB::Error: Into<BoxError>,
{
    type Response = Response<Body>;
    type Error = BoxError;
    type Future = BoxFuture<Result<Response<Body>, BoxError>>;

    fn poll_ready(&mut self, cx: &mut Context<'_>) -> Poll<Result<(), BoxError>> {
        self.inner.poll_ready(cx)
    }

    fn call(&mut self, req: Request<Incoming>) -> Self::Future {
        let exempt = req.version() == Version::HTTP_2 && req.uri().path() == STREAM_GAZE_PATH;
        let guard = CallGuard::new(Arc::clone(&self.conn));
        let (idle, stop) = if exempt {
            (None, None)
        } else {
            (Some(self.body_idle), Some(self.shutdown.clone()))
        };
        let mut req = req.map(Body::new);
        req.extensions_mut().insert(BodyPolicy { idle, stop });
        req.extensions_mut().insert(self.info.clone());
        req.extensions_mut().insert(Arc::clone(&self.conn));
        let call = self.inner.call(req);
        Box::pin(async move {
            let resp = call.await?;
            Ok(resp.map(|b| Guarded::body(Body::new(b), guard)))
        })
    }
}

/// The TLS acceptor for `identity`, offering h2 and http/1.1.
pub fn tls_acceptor(identity: &TlsIdentity) -> Result<TlsAcceptor, ServerError> {
    use rustls_pki_types::pem::PemObject;
    use rustls_pki_types::{CertificateDer, PrivateKeyDer};
    use tokio_rustls::rustls;
    let bad = |e: String| ServerError::TlsConfig(e);
    let certs = CertificateDer::pem_slice_iter(&identity.cert_pem)
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| bad(format!("--tls-cert: {e}")))?;
    let key = PrivateKeyDer::from_pem_slice(&identity.key_pem)
        .map_err(|e| bad(format!("--tls-key: {e}")))?;
    let provider = Arc::new(rustls::crypto::ring::default_provider());
    let mut config = rustls::ServerConfig::builder_with_provider(provider)
        .with_safe_default_protocol_versions()
        .map_err(|e| bad(e.to_string()))?
        .with_no_client_auth()
        .with_single_cert(certs, key)
        .map_err(|e| {
            bad(format!(
                "the certificate and key do not make an identity: {e}"
            ))
        })?;
    // h2 for gRPC clients, http/1.1 for browsers' grpc-web and the page.
    config.alpn_protocols = vec![b"h2".to_vec(), b"http/1.1".to_vec()];
    Ok(TlsAcceptor::from(Arc::new(config)))
}

/// Whether an accept error means the process or the system ran out of descriptors or memory:
/// retrying at once cannot succeed, and spinning would take the core the frame loop needs.
fn out_of_resources(e: &io::Error) -> bool {
    use rustix::io::Errno;
    e.raw_os_error().is_some_and(|code| {
        let code = Errno::from_raw_os_error(code);
        code == Errno::MFILE
            || code == Errno::NFILE
            || code == Errno::NOBUFS
            || code == Errno::NOMEM
    })
}

/// How the connections are served.
pub struct Settings {
    /// Timeouts and the connection limit.
    pub limits: ConnectionLimits,
    /// TLS, when the server speaks it.
    pub tls: Option<TlsAcceptor>,
    /// Triggered at the start of shutdown (request bodies still awaited fail at once).
    pub shutdown: Shutdown,
}

impl std::fmt::Debug for Settings {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Settings")
            .field("limits", &self.limits)
            .field("tls", &self.tls.is_some())
            .finish_non_exhaustive()
    }
}

/// Serve `service` on `listener` until `drained` resolves; then ask every connection to finish
/// and drop those still open after [`SHUTDOWN_LINGER`].
pub async fn serve<S, RB>(
    listener: TcpListener,
    service: S,
    settings: Settings,
    drained: impl Future<Output = ()>,
) where
    S: Service<Request<Body>, Response = Response<RB>, Error = BoxError> + Clone + Send + 'static,
    S::Future: Send + 'static,
    RB: HttpBody<Data = Bytes> + Send + 'static,
    RB::Error: Into<BoxError>,
{
    let nofile = descriptor_limit();
    let cap = effective_max_connections(settings.limits.max_connections, nofile);
    if let Some(n) = nofile
        && (cap as u64).saturating_add(RESERVED_DESCRIPTORS) > n
    {
        tracing::warn!(
            max_connections = cap,
            descriptor_limit = n,
            "the connection limit leaves few descriptors for anything else; raise `ulimit -n` or lower --max-connections"
        );
    }
    tracing::debug!(max_connections = cap, descriptor_limit = ?nofile, "connection limit");
    let permits = Arc::new(Semaphore::new(cap));
    let (close_tx, close_rx) = watch::channel(false);
    let builder = Arc::new(http_builder(&settings.limits));
    let mut tasks = JoinSet::new();
    let mut backoff = Duration::ZERO;
    let exhausted = Every::new(LOG_EVERY);
    let full = Every::new(LOG_EVERY);
    tokio::pin!(drained);
    loop {
        let accepted = tokio::select! {
            () = &mut drained => break,
            Some(_) = tasks.join_next(), if !tasks.is_empty() => continue,
            accepted = listener.accept() => accepted,
        };
        match accepted {
            Ok((tcp, peer)) => {
                backoff = Duration::ZERO;
                let Ok(permit) = Arc::clone(&permits).try_acquire_owned() else {
                    if let Some(held) = full.check(Instant::now()) {
                        tracing::warn!(
                            limit = cap,
                            closed_since_last_line = held,
                            "connection limit reached: new connections are closed at once until one ends (--max-connections)"
                        );
                    }
                    drop(tcp);
                    continue;
                };
                // Frames are small writes that must leave at once: no Nagle delay.
                if let Err(e) = tcp.set_nodelay(true) {
                    tracing::debug!(error = %e, "could not set TCP_NODELAY");
                }
                let conn = Connection {
                    builder: Arc::clone(&builder),
                    limits: settings.limits,
                    tls: settings.tls.clone(),
                    shutdown: settings.shutdown.clone(),
                    close: close_rx.clone(),
                };
                tasks.spawn(conn.run(tcp, peer, service.clone(), permit));
            }
            Err(e) if out_of_resources(&e) => {
                backoff = (backoff * 2).clamp(MIN_BACKOFF, MAX_BACKOFF);
                if let Some(held) = exhausted.check(Instant::now()) {
                    tracing::warn!(
                        error = %e,
                        open_connections = cap - permits.available_permits(),
                        retry_in_ms = backoff.as_millis() as u64,
                        failed_since_last_line = held,
                        "cannot accept connections: out of file descriptors or memory; backing off (raise `ulimit -n` or lower --max-connections)"
                    );
                }
                tokio::select! {
                    () = &mut drained => break,
                    () = tokio::time::sleep(backoff) => {}
                }
            }
            // A connection that failed between the client's SYN and accept (ECONNABORTED and
            // the like): the next one is unaffected.
            Err(e) => tracing::debug!(error = %e, "accept failed"),
        }
    }
    // Closes the listener: from here on a connection attempt is refused at once.
    drop(listener);
    close_tx.send_replace(true);
    let finished = tokio::time::timeout(SHUTDOWN_LINGER, async {
        while tasks.join_next().await.is_some() {}
    })
    .await;
    if finished.is_err() {
        tracing::info!(
            open = tasks.len(),
            "abandoning connections still open (subscribers not reading)"
        );
        tasks.abort_all();
        while tasks.join_next().await.is_some() {}
    }
}

/// hyper's settings: HTTP/1.1 with a head timer, HTTP/2 with keepalive and stream limits.
fn http_builder(limits: &ConnectionLimits) -> auto::Builder<TokioExecutor> {
    let mut builder = auto::Builder::new(TokioExecutor::new());
    builder
        .http1()
        .timer(TokioTimer::new())
        .keep_alive(true)
        .header_read_timeout(limits.header_timeout);
    builder
        .http2()
        .timer(TokioTimer::new())
        .keep_alive_interval(limits::KEEPALIVE_INTERVAL)
        .keep_alive_timeout(limits::KEEPALIVE_TIMEOUT)
        .max_concurrent_streams(limits::MAX_STREAMS_PER_CONNECTION);
    builder
}

/// What a connection task needs besides its socket.
struct Connection {
    builder: Arc<auto::Builder<TokioExecutor>>,
    limits: ConnectionLimits,
    tls: Option<TlsAcceptor>,
    shutdown: Shutdown,
    close: watch::Receiver<bool>,
}

impl Connection {
    async fn run<S, RB>(
        mut self,
        tcp: TcpStream,
        peer: SocketAddr,
        service: S,
        _permit: tokio::sync::OwnedSemaphorePermit,
    ) where
        S: Service<Request<Body>, Response = Response<RB>, Error = BoxError>
            + Clone
            + Send
            + 'static,
        S::Future: Send + 'static,
        RB: HttpBody<Data = Bytes> + Send + 'static,
        RB::Error: Into<BoxError>,
    {
        let first_byte = tokio::time::Instant::now() + self.limits.first_byte_timeout;
        let info = TcpConnectInfo {
            local_addr: tcp.local_addr().ok(),
            remote_addr: Some(peer),
        };
        let io = match &self.tls {
            None => Io::Plain(tcp),
            Some(acceptor) => {
                let handshake = tokio::time::timeout_at(first_byte, acceptor.accept(tcp));
                let done = tokio::select! {
                    done = handshake => done,
                    _ = self.close.wait_for(|c| *c) => return,
                };
                match done {
                    Ok(Ok(s)) => Io::Tls(Box::new(s)),
                    Ok(Err(e)) => {
                        tracing::debug!(%peer, error = %e, "TLS handshake failed");
                        return;
                    }
                    Err(_) => {
                        tracing::debug!(%peer, "no TLS handshake within the first-byte timeout");
                        return;
                    }
                }
            }
        };
        let conn = ConnState::new(Some(peer));
        let io = FirstRequest {
            inner: io,
            conn: Arc::clone(&conn),
            header_timeout: self.limits.header_timeout,
            seen_byte: false,
            deadline: Some(Box::pin(tokio::time::sleep_until(first_byte))),
        };
        // Per connection, as tonic does: a bounded number of calls in progress, more answered
        // RESOURCE_EXHAUSTED at once instead of queued.
        let per_connection = tower::ServiceBuilder::new()
            .layer(tonic::service::RecoverErrorLayer::new())
            .layer(tower::load_shed::LoadShedLayer::new())
            .layer(tower::limit::ConcurrencyLimitLayer::new(
                limits::MAX_CALLS_PER_CONNECTION,
            ))
            .service(service);
        let svc = ConnService {
            inner: per_connection,
            conn: Arc::clone(&conn),
            info,
            body_idle: self.limits.body_idle_timeout,
            shutdown: self.shutdown.clone(),
        };
        let served = self
            .builder
            .serve_connection(TokioIo::new(io), TowerToHyperService::new(svc));
        tokio::pin!(served);
        let mut closing = false;
        loop {
            tokio::select! {
                done = served.as_mut() => {
                    if let Err(e) = done {
                        tracing::debug!(%peer, error = %e, "connection ended with an error");
                    }
                    break;
                }
                _ = self.close.wait_for(|c| *c), if !closing => {
                    closing = true;
                    served.as_mut().graceful_shutdown();
                }
                () = conn.idle_for(self.limits.idle_timeout), if !closing => {
                    tracing::debug!(%peer, "closing a connection idle for the idle timeout");
                    closing = true;
                    served.as_mut().graceful_shutdown();
                }
            }
        }
    }
}

/// The connection a request came on (the transport puts it in every request's extensions).
pub fn connection_of<B>(req: &http::Request<B>) -> Option<Arc<ConnState>> {
    req.extensions().get::<Arc<ConnState>>().cloned()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_connection_limit_fits_the_descriptor_limit() {
        assert_eq!(
            effective_max_connections(None, None),
            DEFAULT_MAX_CONNECTIONS
        );
        assert_eq!(
            effective_max_connections(None, Some(1 << 20)),
            DEFAULT_MAX_CONNECTIONS
        );
        assert_eq!(effective_max_connections(None, Some(256)), 192);
        assert_eq!(effective_max_connections(None, Some(64)), 32);
        assert_eq!(effective_max_connections(None, Some(0)), 1);
        // Given explicitly, it is the operator's choice (a warning says when it is too many).
        assert_eq!(effective_max_connections(Some(5000), Some(256)), 5000);
    }

    #[test]
    fn every_lets_one_line_through_per_period_and_counts_the_rest() {
        let every = Every::new(Duration::from_secs(10));
        let t0 = Instant::now();
        assert_eq!(every.check(t0), Some(0));
        assert_eq!(every.check(t0 + Duration::from_secs(1)), None);
        assert_eq!(every.check(t0 + Duration::from_secs(2)), None);
        assert_eq!(every.check(t0 + Duration::from_secs(11)), Some(2));
    }

    #[test]
    fn resource_errors_are_told_apart() {
        let e = |c: i32| io::Error::from_raw_os_error(c);
        use rustix::io::Errno;
        assert!(out_of_resources(&e(Errno::MFILE.raw_os_error())));
        assert!(out_of_resources(&e(Errno::NFILE.raw_os_error())));
        assert!(!out_of_resources(&e(Errno::CONNABORTED.raw_os_error())));
        assert!(!out_of_resources(&io::Error::other("x")));
    }

    #[test]
    fn limits_validate() {
        ConnectionLimits::default().validate().expect("defaults");
        let bad = ConnectionLimits {
            header_timeout: Duration::ZERO,
            ..ConnectionLimits::default()
        };
        assert_eq!(bad.validate().map_err(|e| e.field), Err("header_timeout"));
        let bad = ConnectionLimits {
            max_connections: Some(0),
            ..ConnectionLimits::default()
        };
        assert_eq!(bad.validate().map_err(|e| e.field), Err("max_connections"));
    }
}
