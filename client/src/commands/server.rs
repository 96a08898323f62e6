//! Where the server is, as the command line says it.

use std::path::PathBuf;

use super::CommandError;
use crate::ConnectOptions;

/// The server a command talks to: its address, the bearer token and the CA certificate file.
#[derive(Clone, Default)]
pub struct Server {
    /// The address (see [`crate::normalise_addr`]).
    pub addr: String,
    /// The bearer token; an empty one counts as none.
    pub token: Option<String>,
    /// The CA certificate (PEM) to trust for an `https://` address.
    pub ca: Option<PathBuf>,
}

// The token is a secret: never in a log line.
impl std::fmt::Debug for Server {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Server")
            .field("addr", &self.addr)
            .field("token", &self.token.as_ref().map(|_| "<set>"))
            .field("ca", &self.ca)
            .finish()
    }
}

impl Server {
    /// How to connect: the token, and the CA certificate read from its file.
    ///
    /// # Errors
    /// [`CommandError::ReadCa`] when the CA file cannot be read.
    pub fn options(&self) -> Result<ConnectOptions, CommandError> {
        let ca_pem = match &self.ca {
            Some(path) => Some(std::fs::read(path).map_err(|source| CommandError::ReadCa {
                path: path.clone(),
                source,
            })?),
            None => None,
        };
        Ok(ConnectOptions {
            token: self.token.clone().filter(|t| !t.is_empty()),
            ca_pem,
        })
    }

    /// Connects with [`Self::options`].
    ///
    /// # Errors
    /// As [`Self::options`] and [`crate::connect_with`].
    pub async fn connect(&self) -> Result<crate::Client, CommandError> {
        Ok(crate::connect_with(&self.addr, &self.options()?).await?)
    }
}
