//! The gate every request passes before it reaches a service: shutdown, authentication (refusals
//! logged at info, at most one line per [`LOG_EVERY`] with the count held back, never the token),
//! the caps on health watches, the count of calls in progress, and the status code of oversize
//! messages.
//!
//! It is a tower layer on the whole server rather than a tonic interceptor because it needs the
//! method path (roles are per method) and the response (to count a call until its handler is done
//! and to correct the code of a message the codec refused).

use std::future::Future;
use std::pin::Pin;
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::task::{Context, Poll};
use std::time::Instant;

use tonic::body::Body;
use tonic::codegen::http;
use tower::{Layer, Service};

use crate::auth::{self, Tokens};
use crate::limits::{
    MAX_HEALTH_WATCHES, MAX_HEALTH_WATCHES_PER_CONNECTION, MAX_REQUEST_BYTES, excerpt,
};
use crate::shutdown::Shutdown;
use crate::transport::{BodyPolicy, ConnState, Every, Guarded, LOG_EVERY, connection_of};

/// The health service's streaming method: each open watch holds a task and a stream, so they
/// are capped per connection and in all.
const HEALTH_WATCH_PATH: &str = "/grpc.health.v1.Health/Watch";

/// What the gate knows.
#[derive(Debug)]
pub struct GateState {
    tokens: Tokens,
    shutdown: Shutdown,
    in_progress: AtomicUsize,
    /// Health watches open on every connection together.
    health_watches: AtomicUsize,
    /// Rate limit of the log line for refused credentials.
    refused: Every,
}

impl GateState {
    /// A gate checking `tokens` and refusing calls once `shutdown` is triggered.
    pub fn new(tokens: Tokens, shutdown: Shutdown) -> Arc<Self> {
        Arc::new(Self {
            tokens,
            shutdown,
            in_progress: AtomicUsize::new(0),
            health_watches: AtomicUsize::new(0),
            refused: Every::new(LOG_EVERY),
        })
    }

    /// Calls whose handler has not finished (a WatchFrames only while it is being set up).
    pub fn in_progress(&self) -> usize {
        self.in_progress.load(Ordering::Acquire)
    }
}

/// The layer.
#[derive(Debug, Clone)]
pub struct GateLayer(pub Arc<GateState>);

impl<S> Layer<S> for GateLayer {
    type Service = Gate<S>;

    fn layer(&self, inner: S) -> Gate<S> {
        Gate {
            inner,
            state: Arc::clone(&self.0),
        }
    }
}

/// The gate around a service.
#[derive(Debug, Clone)]
pub struct Gate<S> {
    inner: S,
    state: Arc<GateState>,
}

/// Counts a call as in progress until dropped.
struct InProgress(Arc<GateState>);

impl Drop for InProgress {
    fn drop(&mut self) {
        self.0.in_progress.fetch_sub(1, Ordering::AcqRel);
    }
}

/// One health watch counted on its connection and in all until its stream is dropped.
struct WatchSlot {
    state: Arc<GateState>,
    conn: Option<Arc<ConnState>>,
}

impl Drop for WatchSlot {
    fn drop(&mut self) {
        self.state.health_watches.fetch_sub(1, Ordering::AcqRel);
        if let Some(c) = &self.conn {
            c.health_watches.fetch_sub(1, Ordering::AcqRel);
        }
    }
}

/// A slot for one more health watch, or the status refusing it (naming the limit).
fn health_watch_slot(
    state: &Arc<GateState>,
    conn: Option<Arc<ConnState>>,
) -> Result<WatchSlot, tonic::Status> {
    let all = state.health_watches.fetch_add(1, Ordering::AcqRel);
    let on_conn = conn
        .as_ref()
        .map_or(0, |c| c.health_watches.fetch_add(1, Ordering::AcqRel));
    // From here the slot gives both counts back, whether it is kept or not.
    let slot = WatchSlot {
        state: Arc::clone(state),
        conn,
    };
    if on_conn >= MAX_HEALTH_WATCHES_PER_CONNECTION {
        return Err(tonic::Status::resource_exhausted(format!(
            "this connection already has {on_conn} health watches open (limit {MAX_HEALTH_WATCHES_PER_CONNECTION} per connection): one watch per service is enough, or use Check"
        )));
    }
    if all >= MAX_HEALTH_WATCHES {
        return Err(tonic::Status::resource_exhausted(format!(
            "the server already serves {all} health watches (limit {MAX_HEALTH_WATCHES}): use Check, or retry later"
        )));
    }
    Ok(slot)
}

/// tonic's codec refuses a message over the decoding limit with OUT_OF_RANGE; gRPC's convention
/// (and what clients retry on) is RESOURCE_EXHAUSTED.
fn correct_oversize(resp: &mut http::Response<Body>) {
    let headers = resp.headers_mut();
    let is_oversize = headers.get("grpc-status").is_some_and(|v| v == "11")
        && headers
            .get("grpc-message")
            .and_then(|m| m.to_str().ok())
            .is_some_and(|m| {
                m.contains("message%20length%20too%20large")
                    || m.contains("message length too large")
            });
    if is_oversize {
        let status = tonic::Status::resource_exhausted(format!(
            "the request message is larger than the server's limit of {MAX_REQUEST_BYTES} bytes: send smaller messages (PushGaze: at most {} samples per call)",
            crate::gaze::MAX_BATCH_SAMPLES
        ));
        headers.remove("grpc-status");
        headers.remove("grpc-message");
        // Err: only for a message that cannot be a header, which ours always can.
        let _ = status.add_header(headers);
    }
}

impl<S, B> Service<http::Request<B>> for Gate<S>
where
    S: Service<http::Request<Body>, Response = http::Response<Body>> + Clone + Send + 'static,
    S::Future: Send + 'static,
    S::Error: Send + 'static,
    B: http_body::Body<Data = tonic::codegen::Bytes> + Send + Unpin + 'static,
    B::Error: Into<Box<dyn std::error::Error + Send + Sync>>,
{
    type Response = http::Response<Body>;
    type Error = S::Error;
    type Future = Pin<Box<dyn Future<Output = Result<Self::Response, Self::Error>> + Send>>;

    fn poll_ready(&mut self, cx: &mut Context<'_>) -> Poll<Result<(), Self::Error>> {
        self.inner.poll_ready(cx)
    }

    fn call(&mut self, mut req: http::Request<B>) -> Self::Future {
        let path = req.uri().path().to_owned();
        let is_health = path.starts_with("/grpc.health.");
        // Health keeps answering (NOT_SERVING) during shutdown; everything else is refused at once.
        if self.state.shutdown.is_triggered() && !is_health {
            let status = tonic::Status::unavailable(
                "the server is shutting down: retry against another instance or after restart",
            );
            return Box::pin(std::future::ready(Ok(status.into_http())));
        }
        let authorization = req.headers().get(http::header::AUTHORIZATION);
        let caller = match auth::authorize(
            &self.state.tokens,
            &path,
            authorization.map(http::HeaderValue::as_bytes),
        ) {
            Ok(caller) => caller,
            Err(status) => {
                // Token guessing must show in the default logs, without flooding them: one
                // line per period with the count held back. Never the token itself.
                if let Some(held) = self.state.refused.check(Instant::now()) {
                    let peer = connection_of(&req).and_then(|c| c.remote);
                    tracing::info!(
                        ?peer,
                        method = %excerpt(&path, 96),
                        code = ?status.code(),
                        refused_since_last_line = held,
                        "call refused: missing, unknown or insufficient credentials"
                    );
                }
                return Box::pin(std::future::ready(Ok(status.into_http())));
            }
        };
        let watch_slot = if path == HEALTH_WATCH_PATH {
            match health_watch_slot(&self.state, connection_of(&req)) {
                Ok(slot) => Some(slot),
                Err(status) => return Box::pin(std::future::ready(Ok(status.into_http()))),
            }
        } else {
            None
        };
        req.extensions_mut().insert(caller);
        // Inside the grpc-web translation, so that a body's timeout or shutdown reaches a
        // browser with its own status code.
        let req = match req.extensions().get::<BodyPolicy>().cloned() {
            Some(policy) => req.map(|b| policy.apply(b)),
            None => req.map(Body::new),
        };
        self.state.in_progress.fetch_add(1, Ordering::AcqRel);
        let guard = InProgress(Arc::clone(&self.state));
        // The clone is the ready one's twin; the ready one serves this call (tower's rule).
        let clone = self.inner.clone();
        let mut inner = std::mem::replace(&mut self.inner, clone);
        Box::pin(async move {
            let _guard = guard;
            let mut resp = inner.call(req).await?;
            correct_oversize(&mut resp);
            Ok(match watch_slot {
                Some(slot) => resp.map(|b| Guarded::body(b, slot)),
                None => resp,
            })
        })
    }
}
