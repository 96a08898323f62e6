//! Which `Host` and `Origin` a browser's request may carry (DNS rebinding, cross-site requests).
//!
//! A web page can point a name it controls at 127.0.0.1 (DNS rebinding) and then call the
//! server as if it were the page's own site: the browser sends `Host: evil.example`. A page can
//! also call `http://127.0.0.1:50051` directly from its own origin. Without tokens (the default
//! on loopback) either would let any page the user visits reconfigure the server or read its
//! frames. So every HTTP/1.x request, and every request that carries an `Origin` or is grpc-web,
//! must name an allowed host, and an `Origin`, when there is one, must be allowed:
//!
//! - `Host`: an IP address (a rebinding attack needs a name), `localhost` or a name under
//!   `.localhost` (browsers resolve these to loopback themselves), or the host of an
//!   `--allowed-origin`;
//! - `Origin`: the server's own (same scheme-less authority as `Host`), a loopback one (IP or
//!   `localhost`, any port: a viewer under development), or one given with `--allowed-origin`.
//!
//! Native gRPC clients over HTTP/2 send neither `Origin` nor grpc-web and are not checked: a
//! browser cannot speak gRPC, and a deployment may reach the server under any name.

use std::fmt;
use std::net::IpAddr;
use std::str::FromStr;

use tonic::codegen::http::{HeaderMap, Version, header};

use crate::limits::excerpt;

/// How much of a client's host or origin a message quotes.
const QUOTED: usize = 64;

/// An origin browsers may call from (`--allowed-origin`): `scheme://host[:port]`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct AllowedOrigin {
    scheme: String,
    host: String,
    port: Option<u16>,
}

impl AllowedOrigin {
    /// Its host, lower case.
    pub fn host(&self) -> &str {
        &self.host
    }
}

impl fmt::Display for AllowedOrigin {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}://{}", self.scheme, self.host)?;
        match self.port {
            Some(p) => write!(f, ":{p}"),
            None => Ok(()),
        }
    }
}

impl FromStr for AllowedOrigin {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        let explain = |why: &str| {
            format!(
                "allowed origin `{}`: {why}; write it as a browser sends it, e.g. `https://viewer.example.org` or `http://lab-pc.local:50051`",
                excerpt(s, QUOTED)
            )
        };
        let (scheme, host, port) = parse_origin(s.trim().trim_end_matches('/'))
            .ok_or_else(|| explain("expected `http://` or `https://`, a host and an optional port, and nothing else"))?;
        Ok(Self { scheme, host, port })
    }
}

/// `scheme://host[:port]` → (scheme, host in lower case with IPv6 brackets, port).
fn parse_origin(s: &str) -> Option<(String, String, Option<u16>)> {
    let (scheme, rest) = s.split_once("://")?;
    let scheme = scheme.to_ascii_lowercase();
    if scheme != "http" && scheme != "https" {
        return None;
    }
    let (host, port) = split_authority(rest)?;
    Some((scheme, host, port))
}

/// `host[:port]` (host possibly `[v6]`) → (host in lower case, port).
fn split_authority(s: &str) -> Option<(String, Option<u16>)> {
    if s.is_empty() || s.contains(['/', '?', '#', '@', ' ']) {
        return None;
    }
    let (host, port) = if let Some(rest) = s.strip_prefix('[') {
        let (v6, after) = rest.split_once(']')?;
        let port = match after {
            "" => None,
            p => Some(p.strip_prefix(':')?.parse().ok()?),
        };
        (format!("[{v6}]"), port)
    } else {
        match s.rsplit_once(':') {
            Some((h, p)) => (h.to_owned(), Some(p.parse().ok()?)),
            None => (s.to_owned(), None),
        }
    };
    if host.is_empty() || host.contains(':') && !host.starts_with('[') {
        return None;
    }
    Some((host.to_ascii_lowercase(), port))
}

fn ip_of(host: &str) -> Option<IpAddr> {
    host.trim_start_matches('[')
        .trim_end_matches(']')
        .parse()
        .ok()
}

fn is_localhost_name(host: &str) -> bool {
    host == "localhost" || host.ends_with(".localhost")
}

/// The default port of a scheme, for comparing origins with and without one.
fn default_port(scheme: &str) -> u16 {
    if scheme == "https" { 443 } else { 80 }
}

/// The allow-list a server checks browsers' requests against.
#[derive(Debug, Clone, Default)]
pub struct Origins {
    extra: Vec<AllowedOrigin>,
}

impl Origins {
    /// Loopback, IP addresses and the server's own origin, plus `extra`.
    pub fn new(extra: Vec<AllowedOrigin>) -> Self {
        Self { extra }
    }

    fn host_allowed(&self, host: &str) -> bool {
        ip_of(host).is_some()
            || is_localhost_name(host)
            || self.extra.iter().any(|o| o.host == host)
    }

    /// Check a request: `Err` carries the message to refuse it with. `authority` is the
    /// request's target authority (HTTP/2's `:authority`), if any.
    pub fn check(
        &self,
        version: Version,
        authority: Option<&str>,
        headers: &HeaderMap,
    ) -> Result<(), String> {
        let origin = headers.get(header::ORIGIN);
        let grpc_web = headers
            .get(header::CONTENT_TYPE)
            .and_then(|v| v.to_str().ok())
            .is_some_and(|v| v.starts_with("application/grpc-web"));
        let browser_like = version < Version::HTTP_2 || origin.is_some() || grpc_web;
        if !browser_like {
            return Ok(());
        }
        let host_value = headers
            .get(header::HOST)
            .and_then(|v| v.to_str().ok())
            .or(authority);
        let Some(host_value) = host_value else {
            return Err(
                "refused: the request names no host (`Host` header); browsers always send one"
                    .into(),
            );
        };
        let Some((host, port)) = split_authority(host_value) else {
            return Err(format!(
                "refused: the `Host` header `{}` is not a host and optional port",
                excerpt(host_value, QUOTED)
            ));
        };
        if !self.host_allowed(&host) {
            return Err(format!(
                "refused: this server does not answer browsers at the name `{}` (DNS rebinding protection). It answers at IP addresses, `localhost` and the hosts of --allowed-origin: start it with `--allowed-origin http://{}` (or https) to allow this name",
                excerpt(&host, QUOTED),
                excerpt(host_value, QUOTED)
            ));
        }
        let Some(origin) = origin else {
            return Ok(());
        };
        let origin = origin.to_str().unwrap_or("");
        let allowed = parse_origin(origin).is_some_and(|(scheme, o_host, o_port)| {
            let o_port = o_port.unwrap_or_else(|| default_port(&scheme));
            let same = o_host == host && port.is_none_or(|p| p == o_port);
            let loopback =
                is_localhost_name(&o_host) || ip_of(&o_host).is_some_and(|ip| ip.is_loopback());
            let listed = self.extra.iter().any(|a| {
                a.scheme == scheme
                    && a.host == o_host
                    && a.port.unwrap_or_else(|| default_port(&a.scheme)) == o_port
            });
            same || loopback || listed
        });
        if allowed {
            Ok(())
        } else {
            Err(format!(
                "refused: pages from the origin `{}` may not call this server (cross-site request). Allowed: the server's own address, loopback origins, and --allowed-origin: start it with `--allowed-origin {}` to allow that page",
                excerpt(origin, QUOTED),
                excerpt(origin, QUOTED)
            ))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use tonic::codegen::http::HeaderValue;

    fn headers(host: Option<&str>, origin: Option<&str>, grpc_web: bool) -> HeaderMap {
        let mut h = HeaderMap::new();
        if let Some(v) = host {
            h.insert(header::HOST, HeaderValue::from_str(v).expect("header"));
        }
        if let Some(v) = origin {
            h.insert(header::ORIGIN, HeaderValue::from_str(v).expect("header"));
        }
        if grpc_web {
            h.insert(
                header::CONTENT_TYPE,
                HeaderValue::from_static("application/grpc-web+proto"),
            );
        }
        h
    }

    #[test]
    fn loopback_and_ip_hosts_pass_and_other_names_need_the_flag() {
        let o = Origins::default();
        let h1 = Version::HTTP_11;
        for host in [
            "127.0.0.1:50051",
            "localhost:50051",
            "localhost",
            "viewer.localhost:8080",
            "[::1]:50051",
            "192.168.1.20:50051",
        ] {
            assert_eq!(
                o.check(h1, None, &headers(Some(host), None, false)),
                Ok(()),
                "{host}"
            );
        }
        let e = o
            .check(
                h1,
                None,
                &headers(
                    Some("rebind.evil.example"),
                    Some("http://rebind.evil.example"),
                    true,
                ),
            )
            .expect_err("rebinding");
        assert!(
            e.contains("rebind.evil.example") && e.contains("--allowed-origin"),
            "{e}"
        );
        assert!(o.check(h1, None, &headers(None, None, false)).is_err());
        let listed = Origins::new(vec!["http://lab-pc.local:50051".parse().expect("origin")]);
        assert_eq!(
            listed.check(
                h1,
                None,
                &headers(
                    Some("lab-pc.local:50051"),
                    Some("http://lab-pc.local:50051"),
                    true
                )
            ),
            Ok(())
        );
        // HTTP/2 gRPC from a native client is not a browser's: any authority.
        assert_eq!(
            o.check(
                Version::HTTP_2,
                Some("foveal.internal:50051"),
                &HeaderMap::new()
            ),
            Ok(())
        );
        // ... but grpc-web over HTTP/2 is.
        assert!(
            o.check(
                Version::HTTP_2,
                Some("evil.example"),
                &headers(None, None, true)
            )
            .is_err()
        );
    }

    #[test]
    fn origins_must_be_the_servers_own_loopback_or_listed() {
        let o = Origins::default();
        let h1 = Version::HTTP_11;
        let check =
            |host: &str, origin: &str| o.check(h1, None, &headers(Some(host), Some(origin), true));
        assert_eq!(check("127.0.0.1:50051", "http://127.0.0.1:50051"), Ok(()));
        assert_eq!(check("127.0.0.1:50051", "http://localhost:5173"), Ok(()));
        assert_eq!(
            check("192.168.1.20:50051", "http://192.168.1.20:50051"),
            Ok(())
        );
        assert_eq!(check("10.0.0.2", "https://10.0.0.2"), Ok(()));
        let e = check("127.0.0.1:50051", "http://evil.example").expect_err("cross-site");
        assert!(e.contains("evil.example"), "{e}");
        assert!(check("127.0.0.1:50051", "null").is_err());
        assert!(check("192.168.1.20:50051", "http://192.168.1.20:8080").is_err());
        let listed = Origins::new(vec!["https://viewer.example.org".parse().expect("origin")]);
        assert_eq!(
            listed.check(
                h1,
                None,
                &headers(
                    Some("127.0.0.1:50051"),
                    Some("https://viewer.example.org"),
                    true
                )
            ),
            Ok(())
        );
        assert!(
            listed
                .check(
                    h1,
                    None,
                    &headers(
                        Some("127.0.0.1:50051"),
                        Some("http://viewer.example.org"),
                        true
                    )
                )
                .is_err(),
            "the scheme is part of the origin"
        );
    }

    #[test]
    fn allowed_origins_parse_or_explain() {
        let o: AllowedOrigin = "HTTPS://Viewer.Example.org/".parse().expect("origin");
        assert_eq!(o.to_string(), "https://viewer.example.org");
        assert_eq!(o.host(), "viewer.example.org");
        let o: AllowedOrigin = "http://[::1]:8080".parse().expect("v6");
        assert_eq!(o.to_string(), "http://[::1]:8080");
        for bad in [
            "viewer.example.org",
            "ftp://x",
            "http://x/path",
            "http://x:port",
            "http://",
        ] {
            let e = bad.parse::<AllowedOrigin>().expect_err(bad);
            assert!(e.contains("https://viewer.example.org"), "{e}");
        }
    }
}
