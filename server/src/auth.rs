//! Roles by bearer token.
//!
//! Three roles, because the three kinds of client need different trust: a viewer only reads
//! (WatchFrames, GetScene, GetStatus, reflection), a gaze bridge only writes gaze (StreamGaze,
//! PushGaze), and only an operator may replace or control the scene (Configure, Pause, Resume,
//! Step, Restart). `admin` may call everything.
//! The health service is always open, so that orchestrators can probe the server without a secret.
//!
//! Tokens come from `FOVEAL_VIEWER_TOKEN`, `FOVEAL_GAZE_TOKEN`, `FOVEAL_ADMIN_TOKEN` or a tokens
//! file (`--tokens PATH`, one `role token` or `role=token` per line, `#` comments). With no token
//! at all the server is open, which [`crate::run`] allows on loopback only (or with `--insecure`).

use std::fmt;
use std::path::Path;

/// Shortest token accepted: anything shorter can be guessed over the network.
pub const MIN_TOKEN_LEN: usize = 16;

/// What a caller may do.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Role {
    /// Read frames, the scene and the status.
    Viewer,
    /// Send gaze.
    Gaze,
    /// Everything, Configure included.
    Admin,
}

impl Role {
    /// Every role, in the order they are listed in messages.
    pub const ALL: [Self; 3] = [Self::Viewer, Self::Gaze, Self::Admin];

    /// The role's name in tokens files, logs and messages.
    pub fn name(self) -> &'static str {
        match self {
            Self::Viewer => "viewer",
            Self::Gaze => "gaze",
            Self::Admin => "admin",
        }
    }

    /// The role named `s`, if any.
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|r| r.name() == s)
    }

    /// Whether a caller with this role may call a method that needs `needed`.
    pub fn allows(self, needed: Self) -> bool {
        self == Self::Admin || self == needed
    }

    /// "a `viewer` (or `admin`) token", "an `admin` token": what a method needing this role
    /// asks for in a message.
    pub fn token_phrase(self) -> String {
        match self {
            Self::Admin => "an `admin` token".into(),
            r => format!("a `{r}` (or `admin`) token"),
        }
    }

    /// "the `gaze` role (or `admin`)", "the `admin` role".
    pub fn role_phrase(self) -> String {
        match self {
            Self::Admin => "the `admin` role".into(),
            r => format!("the `{r}` role (or `admin`)"),
        }
    }

    /// The environment variable a token of this role is read from.
    pub fn env_var(self) -> &'static str {
        match self {
            Self::Viewer => "FOVEAL_VIEWER_TOKEN",
            Self::Gaze => "FOVEAL_GAZE_TOKEN",
            Self::Admin => "FOVEAL_ADMIN_TOKEN",
        }
    }
}

impl fmt::Display for Role {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Why the tokens could not be loaded.
#[derive(Debug, thiserror::Error)]
pub enum TokenError {
    /// The tokens file could not be read.
    #[error("reading the tokens file {path}: {source}")]
    Read {
        /// The file.
        path: String,
        /// The I/O error.
        #[source]
        source: std::io::Error,
    },
    /// A line of the tokens file is not `role token`.
    #[error("tokens file line {line}: {reason}")]
    Line {
        /// 1-based line number.
        line: usize,
        /// What is wrong with it.
        reason: String,
    },
    /// A token is too short or contains characters a header cannot carry.
    #[error("the {role} token from {origin}: {reason}")]
    Weak {
        /// Its role.
        role: Role,
        /// Where it came from (a variable or a file line).
        origin: String,
        /// What is wrong with it.
        reason: String,
    },
}

/// The configured tokens; empty means authentication is off.
#[derive(Clone, Default, PartialEq, Eq)]
pub struct Tokens {
    entries: Vec<(Role, String)>,
}

// Tokens are secrets: never in a log line or a panic message.
impl fmt::Debug for Tokens {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let roles: Vec<_> = self.entries.iter().map(|(r, _)| r.name()).collect();
        f.debug_struct("Tokens").field("roles", &roles).finish()
    }
}

fn check_token(role: Role, origin: &str, token: &str) -> Result<(), TokenError> {
    let weak = |reason: String| TokenError::Weak {
        role,
        origin: origin.to_owned(),
        reason,
    };
    if token.len() < MIN_TOKEN_LEN {
        return Err(weak(format!(
            "is {} characters long; use at least {MIN_TOKEN_LEN} (e.g. `openssl rand -hex 16`)",
            token.len()
        )));
    }
    if !token.bytes().all(|b| b.is_ascii_graphic()) {
        return Err(weak(
            "contains spaces or non-ASCII characters, which an `authorization` header cannot carry"
                .into(),
        ));
    }
    Ok(())
}

impl Tokens {
    /// No tokens: authentication off.
    pub fn none() -> Self {
        Self::default()
    }

    /// Whether no token is configured (authentication off).
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// Add a token for `role`; `origin` names where it came from for the error message.
    pub fn add(&mut self, role: Role, token: &str, origin: &str) -> Result<(), TokenError> {
        check_token(role, origin, token)?;
        self.entries.push((role, token.to_owned()));
        Ok(())
    }

    /// Tokens from a tokens file's text: `role token` or `role=token` per line, `#` comments.
    pub fn parse(text: &str) -> Result<Self, TokenError> {
        let mut tokens = Self::none();
        for (i, raw) in text.lines().enumerate() {
            let line = raw.split('#').next().unwrap_or_default().trim();
            if line.is_empty() {
                continue;
            }
            let (role, token) = line
                .split_once('=')
                .or_else(|| line.split_once(char::is_whitespace))
                .ok_or_else(|| TokenError::Line {
                    line: i + 1,
                    reason: "expected `role token` or `role=token`".into(),
                })?;
            // The word is never quoted: a line written backwards (`<token> admin`) has the
            // token there, and start-up errors end up in logs.
            let role = Role::from_name(role.trim()).ok_or_else(|| TokenError::Line {
                line: i + 1,
                reason: "the first word is not a role (viewer, gaze or admin); write `role token` (the word is not shown: it may be a token)".into(),
            })?;
            tokens.add(role, token.trim(), &format!("line {}", i + 1))?;
        }
        Ok(tokens)
    }

    /// Tokens from a tokens file.
    pub fn from_file(path: &Path) -> Result<Self, TokenError> {
        let text = std::fs::read_to_string(path).map_err(|source| TokenError::Read {
            path: path.display().to_string(),
            source,
        })?;
        Self::parse(&text)
    }

    /// The role of a presented token, if it is one of ours. Every configured token is compared in
    /// full, so the time taken does not tell how much of a guess was right.
    pub fn role_of(&self, presented: &str) -> Option<Role> {
        let mut found = None;
        for (role, token) in &self.entries {
            if constant_time_eq(token.as_bytes(), presented.as_bytes()) && found.is_none() {
                found = Some(*role);
            }
        }
        found
    }
}

fn constant_time_eq(a: &[u8], b: &[u8]) -> bool {
    if a.len() != b.len() {
        return false;
    }
    a.iter().zip(b).fold(0u8, |acc, (x, y)| acc | (x ^ y)) == 0
}

/// What a gRPC path needs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Access {
    /// Anyone (health, and anything that is not one of our services).
    Open,
    /// A token of this role (or admin).
    Role(Role),
}

/// The access a request path (`/package.Service/Method`) needs.
pub fn access_for(path: &str) -> Access {
    if let Some(method) = path.strip_prefix("/foveal.v1.Foveal/") {
        Access::Role(match method {
            "StreamGaze" | "PushGaze" => Role::Gaze,
            "Configure" | "Pause" | "Resume" | "Step" | "Restart" => Role::Admin,
            _ => Role::Viewer,
        })
    } else if path.starts_with("/grpc.reflection.") {
        // The schema is not secret, but listing services is reconnaissance: viewers and up.
        Access::Role(Role::Viewer)
    } else {
        Access::Open
    }
}

/// The caller of a request, as authentication found it (in the request's extensions).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Caller {
    /// The caller's role; `None` when authentication is off.
    pub role: Option<Role>,
}

impl Caller {
    /// The role's name for logs (`open` when authentication is off).
    pub fn role_name(&self) -> &'static str {
        self.role.map_or("open", Role::name)
    }
}

/// Decide a request: the caller, or the status to answer with. `authorization` is the header's
/// value, if any.
pub fn authorize(
    tokens: &Tokens,
    path: &str,
    authorization: Option<&[u8]>,
) -> Result<Caller, tonic::Status> {
    let Access::Role(needed) = access_for(path) else {
        return Ok(Caller { role: None });
    };
    if tokens.is_empty() {
        return Ok(Caller { role: None });
    }
    let method = path.rsplit('/').next().unwrap_or(path);
    let Some(header) = authorization else {
        return Err(tonic::Status::unauthenticated(format!(
            "{method} needs {}: send metadata `authorization: Bearer <token>` (foveal: --token or FOVEAL_TOKEN)",
            needed.token_phrase()
        )));
    };
    let presented = std::str::from_utf8(header)
        .ok()
        .and_then(|h| {
            h.strip_prefix("Bearer ")
                .or_else(|| h.strip_prefix("bearer "))
        })
        .map(str::trim);
    let Some(presented) = presented else {
        return Err(tonic::Status::unauthenticated(
            "the `authorization` metadata must be `Bearer <token>`",
        ));
    };
    match tokens.role_of(presented) {
        None => Err(tonic::Status::unauthenticated(
            "the bearer token is not one this server knows: check the token for this server",
        )),
        Some(role) if role.allows(needed) => Ok(Caller { role: Some(role) }),
        Some(role) => Err(tonic::Status::permission_denied(format!(
            "{method} needs {}; this token has the `{role}` role",
            needed.role_phrase()
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const V: &str = "viewer-token-0123456789";
    const G: &str = "gaze-token-0123456789";
    const A: &str = "admin-token-0123456789";

    fn tokens() -> Tokens {
        Tokens::parse(&format!(
            "# roles\nviewer {V}\ngaze={G}\n\nadmin {A} # operator\n"
        ))
        .expect("valid file")
    }

    fn code(r: Result<Caller, tonic::Status>) -> tonic::Code {
        r.map_or_else(|s| s.code(), |_| tonic::Code::Ok)
    }

    #[test]
    fn roles_gate_methods() {
        let t = tokens();
        let bearer = |tok: &str| format!("Bearer {tok}");
        let call = |path: &str, tok: Option<&str>| {
            let h = tok.map(bearer);
            authorize(&t, path, h.as_deref().map(str::as_bytes))
        };
        use tonic::Code::{Ok, PermissionDenied, Unauthenticated};
        assert_eq!(code(call("/foveal.v1.Foveal/WatchFrames", Some(V))), Ok);
        assert_eq!(code(call("/foveal.v1.Foveal/GetStatus", Some(A))), Ok);
        assert_eq!(
            code(call("/foveal.v1.Foveal/StreamGaze", Some(V))),
            PermissionDenied
        );
        assert_eq!(code(call("/foveal.v1.Foveal/StreamGaze", Some(G))), Ok);
        assert_eq!(
            code(call("/foveal.v1.Foveal/Configure", Some(G))),
            PermissionDenied
        );
        assert_eq!(code(call("/foveal.v1.Foveal/Configure", Some(A))), Ok);
        // The loop's controls are the admin's, as Configure; inspecting a body is a viewer's.
        for method in ["Pause", "Resume", "Step", "Restart"] {
            let path = format!("/foveal.v1.Foveal/{method}");
            assert_eq!(code(call(&path, Some(V))), PermissionDenied, "{method}");
            assert_eq!(code(call(&path, Some(G))), PermissionDenied, "{method}");
            assert_eq!(code(call(&path, Some(A))), Ok, "{method}");
        }
        assert_eq!(code(call("/foveal.v1.Foveal/InspectBody", Some(V))), Ok);
        assert_eq!(
            code(call("/foveal.v1.Foveal/InspectBody", Some(G))),
            PermissionDenied
        );
        assert_eq!(
            code(call("/foveal.v1.Foveal/GetScene", None)),
            Unauthenticated
        );
        assert_eq!(
            code(call(
                "/foveal.v1.Foveal/GetScene",
                Some("wrong-token-0123456789")
            )),
            Unauthenticated
        );
        assert_eq!(code(call("/grpc.health.v1.Health/Check", None)), Ok);
        assert_eq!(
            call("/foveal.v1.Foveal/PushGaze", Some(A))
                .ok()
                .map(|c| c.role),
            Some(Some(Role::Admin))
        );
        // Messages read as English for every role.
        let m = |r: Result<Caller, tonic::Status>| {
            r.err().map(|s| s.message().to_owned()).unwrap_or_default()
        };
        let configure = m(call("/foveal.v1.Foveal/Configure", None));
        assert!(
            configure.contains("Configure needs an `admin` token:"),
            "{configure}"
        );
        let watch = m(call("/foveal.v1.Foveal/WatchFrames", None));
        assert!(
            watch.contains("needs a `viewer` (or `admin`) token"),
            "{watch}"
        );
        let denied = m(call("/foveal.v1.Foveal/Configure", Some(V)));
        assert!(denied.contains("needs the `admin` role;"), "{denied}");
        let denied = m(call("/foveal.v1.Foveal/PushGaze", Some(V)));
        assert!(
            denied.contains("needs the `gaze` role (or `admin`);"),
            "{denied}"
        );
        // Authentication off: everything open.
        assert_eq!(
            code(authorize(
                &Tokens::none(),
                "/foveal.v1.Foveal/Configure",
                None
            )),
            Ok
        );
    }

    #[test]
    fn bad_files_and_weak_tokens_are_refused_with_the_line() {
        let e = Tokens::parse("viewer short").expect_err("weak");
        assert!(e.to_string().contains("at least 16"), "{e}");
        let e = Tokens::parse("\nroot 0123456789abcdef0123").expect_err("role");
        assert!(e.to_string().contains("line 2"), "{e}");
        assert!(Tokens::parse("viewer").is_err());
        // A line written backwards: the error must not carry the token.
        let secret = "0123456789abcdef-very-secret";
        for line in [format!("{secret} admin"), format!("{secret}=admin")] {
            let e = Tokens::parse(&line).expect_err("backwards");
            let text = e.to_string();
            assert!(
                text.contains("line 1") && text.contains("role token"),
                "{text}"
            );
            assert!(!text.contains("0123456789abcdef"), "{text}");
        }
        assert!(
            !format!("{:?}", tokens()).contains(V),
            "secrets stay out of Debug"
        );
    }
}
