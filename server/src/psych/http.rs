//! The results endpoint's HTTP side: routes, the role check, bounded bodies and JSON answers.
//!
//! Every refusal is JSON, `{"error": MESSAGE, "field": FIELD}`, with a status a browser's
//! `fetch` shows as it is: 400 a malformed request (the field named), 401/403 the token, 404 an
//! unknown session or design, 409 a trial out of order or a session that exists, 413 a body over
//! [`MAX_BODY_BYTES`], 415 a body that is not JSON.

use std::sync::Arc;

use axum::http::{HeaderValue, Method, Request, Response, StatusCode, header};
use hyper::body::Bytes;
use serde_json::{Value, json};
use tonic::body::Body;

use super::store::{Refusal, SessionRequest, Store};
use super::trial::TrialRecord;
use crate::auth::{Role, Tokens};
use crate::transport::BodyPolicy;

/// Largest request body: a trial with [`super::trial::MAX_FRAMES`] timestamps fits many times.
pub const MAX_BODY_BYTES: usize = 64 * 1024;

/// Where the endpoint's paths begin.
pub const PREFIX: &str = "/psych/api/";

/// The role that may run an experiment and write its results. Not `viewer`, which only reads,
/// and not only `admin`, which a participant's machine must not hold: like a gaze bridge, the
/// experiment's page sends what a viewer's eyes and answers produce and can neither watch nor
/// reconfigure the scene.
pub const WRITER: Role = Role::Gaze;

/// The results endpoint.
#[derive(Debug)]
pub struct Psych {
    store: Store,
    tokens: Tokens,
}

impl Psych {
    /// The endpoint over `store`, admitting callers with the [`WRITER`] role (or `admin`) among
    /// `tokens` (everyone when there are none).
    pub fn new(store: Store, tokens: Tokens) -> Arc<Self> {
        Arc::new(Self { store, tokens })
    }

    /// Answer `request` (a path under [`PREFIX`]).
    pub async fn handle<B>(self: Arc<Self>, request: Request<B>) -> Response<Body>
    where
        B: http_body::Body<Data = Bytes> + Send + Unpin + 'static,
        B::Error: Into<Box<dyn std::error::Error + Send + Sync>>,
    {
        match self.route(request).await {
            Ok((status, value)) => json_response(status, &value),
            Err(r) => {
                let status = StatusCode::from_u16(r.status).unwrap_or(StatusCode::BAD_REQUEST);
                json_response(status, &json!({ "error": r.message, "field": r.field }))
            }
        }
    }

    async fn route<B>(self: Arc<Self>, request: Request<B>) -> Result<(StatusCode, Value), Refusal>
    where
        B: http_body::Body<Data = Bytes> + Send + Unpin + 'static,
        B::Error: Into<Box<dyn std::error::Error + Send + Sync>>,
    {
        self.authorize(request.headers())?;
        let path = request.uri().path().trim_start_matches(PREFIX).to_owned();
        let query = request.uri().query().unwrap_or_default().to_owned();
        let parts: Vec<&str> = path.split('/').collect();
        let method = request.method().clone();
        match (&method, parts.as_slice()) {
            (&Method::GET, ["design"]) => {
                let name = query
                    .split('&')
                    .find_map(|kv| kv.strip_prefix("name="))
                    .unwrap_or(super::design::DEFAULT_DESIGN)
                    .to_owned();
                let design = self.store.designs().load(&name).map_err(|e| {
                    let status = if matches!(e, super::design::DesignError::Unknown { .. }) {
                        404
                    } else {
                        422
                    };
                    Refusal::field(status, "design", e.to_string())
                })?;
                let d = self.store.display();
                Ok((
                    StatusCode::OK,
                    json!({
                        "design": design,
                        "trials": design.trials(),
                        "display": {
                            "width_px": d.width_px,
                            "height_px": d.height_px,
                            "diagonal_in": d.diagonal_in,
                            "viewing_distance_cm": d.viewing_distance_cm,
                        },
                        "version": env!("CARGO_PKG_VERSION"),
                    }),
                ))
            }
            (&Method::POST, ["sessions"]) => {
                let body = read_json(request).await?;
                let started = blocking(move || {
                    let req = SessionRequest::from_json(&body)?;
                    self.store.start(&req)
                })
                .await?;
                let file = std::path::Path::new(&started.csv)
                    .file_name()
                    .map(|n| n.to_string_lossy().into_owned());
                Ok((
                    StatusCode::CREATED,
                    json!({ "session": started.id, "results": file }),
                ))
            }
            (&Method::POST, ["sessions", id, "trials"]) => {
                let id = (*id).to_owned();
                let body = read_json(request).await?;
                let trial = blocking(move || {
                    let trial = TrialRecord::from_json(&body)?;
                    self.store.append(&id, &trial)
                })
                .await?;
                Ok((StatusCode::CREATED, json!({ "trial": trial })))
            }
            (&Method::POST, ["sessions", id, "finish"]) => {
                let id = (*id).to_owned();
                let body = read_json(request).await?;
                let stored = blocking(move || {
                    let mut f = super::fields::Fields::parse(&body)?;
                    let completed: bool = f.req("completed", "true or false")?;
                    f.done()?;
                    self.store.finish(&id, completed)
                })
                .await?;
                Ok((StatusCode::OK, json!({ "trials_stored": stored })))
            }
            (_, ["design"] | ["sessions"] | ["sessions", _, "trials" | "finish"]) => {
                Err(Refusal::plain(
                    405,
                    format!(
                        "{method} is not allowed here: GET {PREFIX}design, POST {PREFIX}sessions, POST {PREFIX}sessions/ID/trials and POST {PREFIX}sessions/ID/finish"
                    ),
                ))
            }
            _ => Err(Refusal::plain(
                404,
                format!(
                    "no such endpoint: GET {PREFIX}design, POST {PREFIX}sessions, POST {PREFIX}sessions/ID/trials and POST {PREFIX}sessions/ID/finish (docs/PROTOCOL.md)"
                ),
            )),
        }
    }

    /// The caller must hold the writer's role (or `admin`) when the server has tokens.
    fn authorize(&self, headers: &axum::http::HeaderMap) -> Result<(), Refusal> {
        if self.tokens.is_empty() {
            return Ok(());
        }
        let presented = headers
            .get(header::AUTHORIZATION)
            .and_then(|h| h.to_str().ok())
            .and_then(|h| {
                h.strip_prefix("Bearer ")
                    .or_else(|| h.strip_prefix("bearer "))
            })
            .map(str::trim);
        let Some(presented) = presented else {
            return Err(Refusal::plain(
                401,
                format!(
                    "the psychophysics endpoint needs {}: open the page as /psych#token=TOKEN",
                    WRITER.token_phrase()
                ),
            ));
        };
        match self.tokens.role_of(presented) {
            None => Err(Refusal::plain(
                401,
                "the bearer token is not one this server knows: check the token for this server",
            )),
            Some(role) if role.allows(WRITER) => Ok(()),
            Some(role) => Err(Refusal::plain(
                403,
                format!(
                    "the psychophysics endpoint needs {}; this token has the `{role}` role",
                    WRITER.role_phrase()
                ),
            )),
        }
    }
}

/// Run the store's blocking work (file writes and syncs) off the async workers.
async fn blocking<T: Send + 'static>(
    f: impl FnOnce() -> Result<T, Refusal> + Send + 'static,
) -> Result<T, Refusal> {
    tokio::task::spawn_blocking(f)
        .await
        .map_err(|e| Refusal::plain(500, format!("the results writer failed: {e}")))?
}

/// The request's body, at most [`MAX_BODY_BYTES`], which must be JSON.
async fn read_json<B>(request: Request<B>) -> Result<Bytes, Refusal>
where
    B: http_body::Body<Data = Bytes> + Send + Unpin + 'static,
    B::Error: Into<Box<dyn std::error::Error + Send + Sync>>,
{
    let json = request
        .headers()
        .get(header::CONTENT_TYPE)
        .and_then(|v| v.to_str().ok())
        .is_some_and(|v| v.trim_start().starts_with("application/json"));
    if !json {
        return Err(Refusal::plain(
            415,
            "the body must be JSON (`content-type: application/json`)",
        ));
    }
    let declared = request
        .headers()
        .get(header::CONTENT_LENGTH)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.parse::<u64>().ok());
    if declared.is_some_and(|n| n > MAX_BODY_BYTES as u64) {
        return Err(too_large());
    }
    // The transport's idle-body timeout and shutdown apply here as to every call.
    let body = match request.extensions().get::<BodyPolicy>().cloned() {
        Some(policy) => policy.apply(request.into_body()),
        None => Body::new(request.into_body()),
    };
    axum::body::to_bytes(axum::body::Body::new(body), MAX_BODY_BYTES)
        .await
        .map_err(|e| {
            let length_limit = std::error::Error::source(&e)
                .is_some_and(|s| s.to_string().contains("length limit"));
            if length_limit || e.to_string().contains("length limit") {
                too_large()
            } else {
                Refusal::plain(400, format!("reading the body: {e}"))
            }
        })
}

fn too_large() -> Refusal {
    Refusal::field(
        413,
        "body",
        format!("the body is larger than {MAX_BODY_BYTES} bytes"),
    )
}

fn json_response(status: StatusCode, value: &Value) -> Response<Body> {
    let text = format!("{value}\n");
    let length = text.len();
    let mut response = Response::new(Body::new(axum::body::Body::from(text)));
    *response.status_mut() = status;
    let headers = response.headers_mut();
    headers.insert(
        header::CONTENT_TYPE,
        HeaderValue::from_static("application/json"),
    );
    headers.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store"));
    headers.insert(header::CONTENT_LENGTH, HeaderValue::from(length));
    response
}
