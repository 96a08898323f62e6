//! `foveal health`: the server's gRPC health, printed and turned into the exit status.

use std::time::Duration;

use super::{CommandError, Outcome, Server};
use crate::health::{self, ServingStatus};

/// Asks the server about `service` ("" for the whole server) within `timeout` and prints the
/// answer (`SERVING`, `NOT_SERVING`, ...), or `UNREACHABLE` with the error on stderr: success
/// only when serving.
///
/// # Errors
/// [`CommandError::ReadCa`] only; an unreachable server is an [`Outcome::Failure`].
pub async fn health(
    server: &Server,
    service: &str,
    timeout: Duration,
) -> Result<Outcome, CommandError> {
    let options = server.options()?;
    match health::check_with(&server.addr, service, timeout, &options).await {
        Ok(status) => {
            println!("{}", status.as_str_name());
            Ok(if status == ServingStatus::Serving {
                Outcome::Success
            } else {
                Outcome::Failure
            })
        }
        Err(err) => {
            println!("UNREACHABLE");
            eprintln!("error: {err}");
            Ok(Outcome::Failure)
        }
    }
}
