//! The browser viewer, served on the gRPC port.
//!
//! The page talks grpc-web (through [`tonic_web`]) to the same `foveal.v1.Foveal` service every
//! other client uses, so `cargo run -p foveal-server` and a browser is all a user needs. The
//! built assets (`web/dist`, produced by `npm run build` in `web/` and committed) are embedded in
//! the binary with `include_bytes!`: the Rust-only path needs no Node at build or run time.
//!
//! [`ViewerLayer`] sits in front of every service: a `GET` or `HEAD` that is not gRPC is answered
//! from the embedded assets (404 for an unknown path); everything else goes through the grpc-web
//! translation (which passes plain gRPC over HTTP/2 through untouched) to the services.
//!
//! Before either, a browser's request must name an allowed `Host` and come from an allowed
//! `Origin` ([`crate::origin`]): a refused page request gets 403 with the reason, a refused
//! grpc-web call PERMISSION_DENIED with the same reason.

use std::future::Future;
use std::pin::Pin;
use std::sync::Arc;
use std::task::{Context, Poll};
use std::time::Instant;

use axum::http::{HeaderValue, Method, Request, Response, StatusCode, header};
use tonic::body::Body;
use tonic_web::{GrpcWebLayer, GrpcWebService};
use tower_layer::Layer;
use tower_service::Service;

use crate::origin::Origins;
use crate::psych::Psych;
use crate::transport::{Every, LOG_EVERY};

/// One embedded file.
#[derive(Debug)]
struct Asset {
    path: &'static str,
    content_type: &'static str,
    bytes: &'static [u8],
}

macro_rules! asset {
    ($path:literal, $file:literal, $type:literal) => {
        Asset {
            path: $path,
            content_type: $type,
            bytes: include_bytes!(concat!(env!("CARGO_MANIFEST_DIR"), "/../web/dist/", $file)),
        }
    };
}

/// The viewer's files, by request path.
const ASSETS: &[Asset] = &[
    asset!("/", "index.html", "text/html; charset=utf-8"),
    asset!("/index.html", "index.html", "text/html; charset=utf-8"),
    asset!("/viewer.js", "viewer.js", "text/javascript; charset=utf-8"),
    asset!("/viewer.css", "viewer.css", "text/css; charset=utf-8"),
    // The psychophysics experiments (`crate::psych`).
    asset!("/psych", "psych.html", "text/html; charset=utf-8"),
    asset!("/psych.js", "psych.js", "text/javascript; charset=utf-8"),
    asset!("/psych.css", "psych.css", "text/css; charset=utf-8"),
];

/// The layer that puts the viewer (page and grpc-web) in front of the gRPC services, behind
/// the browsers' allow-list.
#[derive(Debug, Clone)]
pub struct ViewerLayer {
    origins: Arc<Origins>,
    refusals: Arc<Every>,
    psych: Arc<Psych>,
}

impl ViewerLayer {
    /// The viewer, answering browsers allowed by `origins`, and the experiments' results
    /// endpoint `psych`.
    pub fn new(origins: Origins, psych: Arc<Psych>) -> Self {
        Self {
            origins: Arc::new(origins),
            refusals: Arc::new(Every::new(LOG_EVERY)),
            psych,
        }
    }
}

impl<S> Layer<S> for ViewerLayer {
    type Service = ViewerService<S>;

    fn layer(&self, inner: S) -> Self::Service {
        ViewerService {
            inner: GrpcWebLayer::new().layer(inner),
            origins: Arc::clone(&self.origins),
            refusals: Arc::clone(&self.refusals),
            psych: Arc::clone(&self.psych),
        }
    }
}

/// See [`ViewerLayer`].
#[derive(Debug, Clone)]
pub struct ViewerService<S> {
    inner: GrpcWebService<S>,
    origins: Arc<Origins>,
    refusals: Arc<Every>,
    psych: Arc<Psych>,
}

type BoxFuture<T, E> = Pin<Box<dyn Future<Output = Result<T, E>> + Send>>;

impl<S, B> Service<Request<B>> for ViewerService<S>
where
    GrpcWebService<S>: Service<Request<B>, Response = Response<Body>>,
    <GrpcWebService<S> as Service<Request<B>>>::Future: Send + 'static,
    <GrpcWebService<S> as Service<Request<B>>>::Error: Send + 'static,
    B: http_body::Body<Data = hyper::body::Bytes> + Send + Unpin + 'static,
    B::Error: Into<Box<dyn std::error::Error + Send + Sync>>,
{
    type Response = Response<Body>;
    type Error = <GrpcWebService<S> as Service<Request<B>>>::Error;
    type Future = BoxFuture<Self::Response, Self::Error>;

    fn poll_ready(&mut self, cx: &mut Context<'_>) -> Poll<Result<(), Self::Error>> {
        self.inner.poll_ready(cx)
    }

    fn call(&mut self, request: Request<B>) -> Self::Future {
        let authority = request.uri().authority().map(|a| a.as_str());
        if let Err(why) = self
            .origins
            .check(request.version(), authority, request.headers())
        {
            if let Some(held) = self.refusals.check(Instant::now()) {
                let peer = crate::transport::connection_of(&request).and_then(|c| c.remote);
                tracing::info!(?peer, refused_since_last_line = held, reason = %why, "browser request refused");
            }
            return Box::pin(std::future::ready(Ok(refusal(&request, why))));
        }
        // Behind the browsers' allow-list like the page; its own role check (see `psych`).
        if request.uri().path().starts_with(crate::psych::http::PREFIX) {
            let psych = Arc::clone(&self.psych);
            return Box::pin(async move { Ok(psych.handle(request).await) });
        }
        if is_page_request(&request) {
            let response = asset_response(request.method(), request.uri().path());
            return Box::pin(std::future::ready(Ok(response)));
        }
        Box::pin(self.inner.call(request))
    }
}

/// A browser fetching a file: `GET` or `HEAD`, and not any flavour of gRPC.
fn is_page_request<B>(request: &Request<B>) -> bool {
    let grpc = request
        .headers()
        .get(header::CONTENT_TYPE)
        .and_then(|v| v.to_str().ok())
        .is_some_and(|v| v.starts_with("application/grpc"));
    !grpc && (request.method() == Method::GET || request.method() == Method::HEAD)
}

/// The answer to a request the allow-list refused: PERMISSION_DENIED for gRPC of any flavour
/// (a grpc-web client shows the message), 403 with the message for anything else.
fn refusal<B>(request: &Request<B>, why: String) -> Response<Body> {
    let content_type = request.headers().get(header::CONTENT_TYPE).cloned();
    if content_type
        .as_ref()
        .and_then(|v| v.to_str().ok())
        .is_some_and(|v| v.starts_with("application/grpc"))
    {
        let mut response = tonic::Status::permission_denied(why).into_http::<Body>();
        if let Some(ct) = content_type {
            response.headers_mut().insert(header::CONTENT_TYPE, ct);
        }
        return response;
    }
    let mut response = Response::new(Body::new(axum::body::Body::from(format!("{why}\n"))));
    *response.status_mut() = StatusCode::FORBIDDEN;
    response.headers_mut().insert(
        header::CONTENT_TYPE,
        HeaderValue::from_static("text/plain; charset=utf-8"),
    );
    response
}

fn asset_response(method: &Method, path: &str) -> Response<Body> {
    let Some(asset) = ASSETS.iter().find(|a| a.path == path) else {
        return plain(
            StatusCode::NOT_FOUND,
            "not found: the viewer is at / (gRPC clients use foveal.v1.Foveal on this port)\n",
        );
    };
    let body = if method == Method::HEAD {
        Body::empty()
    } else {
        Body::new(axum::body::Body::from(asset.bytes))
    };
    let mut response = Response::new(body);
    let headers = response.headers_mut();
    headers.insert(
        header::CONTENT_TYPE,
        HeaderValue::from_static(asset.content_type),
    );
    // The assets change with the binary, not while it runs; a reload after an upgrade must not
    // mix an old script with a new page.
    headers.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-cache"));
    headers.insert(header::CONTENT_LENGTH, HeaderValue::from(asset.bytes.len()));
    response
}

fn plain(status: StatusCode, text: &'static str) -> Response<Body> {
    let mut response = Response::new(Body::new(axum::body::Body::from(text)));
    *response.status_mut() = status;
    response.headers_mut().insert(
        header::CONTENT_TYPE,
        HeaderValue::from_static("text/plain; charset=utf-8"),
    );
    response
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_asset_is_embedded_and_the_page_loads_its_script() {
        for a in ASSETS {
            assert!(
                !a.bytes.is_empty(),
                "{} is empty: run `npm run build` in web/",
                a.path
            );
        }
        let page = std::str::from_utf8(ASSETS[0].bytes).expect("index.html is UTF-8");
        assert!(page.contains("viewer.js"), "index.html loads viewer.js");
        let psych = ASSETS
            .iter()
            .find(|a| a.path == "/psych")
            .expect("the psychophysics page is served");
        let psych = std::str::from_utf8(psych.bytes).expect("psych.html is UTF-8");
        assert!(psych.contains("psych.js"), "psych.html loads psych.js");
    }

    #[test]
    fn only_non_grpc_gets_are_page_requests() {
        let get = Request::get("/").body(()).expect("request");
        assert!(is_page_request(&get));
        let web = Request::post("/foveal.v1.Foveal/GetStatus")
            .header(header::CONTENT_TYPE, "application/grpc-web+proto")
            .body(())
            .expect("request");
        assert!(!is_page_request(&web));
        let odd = Request::get("/x")
            .header(header::CONTENT_TYPE, "application/grpc")
            .body(())
            .expect("request");
        assert!(!is_page_request(&odd));
        let head = asset_response(&Method::HEAD, "/viewer.js");
        assert_eq!(head.status(), StatusCode::OK);
        assert_eq!(
            asset_response(&Method::GET, "/nope").status(),
            StatusCode::NOT_FOUND
        );
    }
}
