//! The standard gRPC health check (`grpc.health.v1.Health/Check`), as used by container health
//! checks: one call with a short timeout, so that a hung server counts as unhealthy rather than
//! hanging the probe.

use std::time::Duration;

use tonic_health::pb::HealthCheckRequest;
use tonic_health::pb::health_client::HealthClient;

pub use tonic_health::pb::health_check_response::ServingStatus;

use crate::{ClientError, ConnectOptions, endpoint};

/// The service name of the foveal service in the health registry; `""` asks about the server
/// as a whole.
pub const FOVEAL_SERVICE: &str = "foveal.v1.Foveal";

/// Asks the server at `addr` whether `service` is serving, allowing `timeout` for the
/// connection and again for the call.
///
/// A service the server does not know comes back as [`ServingStatus::ServiceUnknown`] rather
/// than as an error, so that the caller has one answer to turn into an exit code.
///
/// # Errors
/// [`ClientError::InvalidAddress`], [`ClientError::Connect`] or [`ClientError::Rpc`] (including
/// a timed-out call).
pub async fn check(
    addr: &str,
    service: &str,
    timeout: Duration,
) -> Result<ServingStatus, ClientError> {
    check_with(addr, service, timeout, &ConnectOptions::default()).await
}

/// [`check`] for a server behind TLS (health needs no token, only the CA).
///
/// # Errors
/// As [`check`], and [`ClientError::InvalidOption`] for `https://` without a usable CA.
pub async fn check_with(
    addr: &str,
    service: &str,
    timeout: Duration,
    options: &ConnectOptions,
) -> Result<ServingStatus, ClientError> {
    let endpoint = crate::secure(addr, endpoint(addr, timeout)?.timeout(timeout), options)?;
    let channel = crate::open(addr, endpoint).await?;
    let request = HealthCheckRequest {
        service: service.to_owned(),
    };
    match HealthClient::new(channel).check(request).await {
        Ok(response) => {
            Ok(ServingStatus::try_from(response.into_inner().status)
                .unwrap_or(ServingStatus::Unknown))
        }
        Err(status) if status.code() == tonic::Code::NotFound => Ok(ServingStatus::ServiceUnknown),
        Err(status) => Err(ClientError::Rpc {
            rpc: "Health/Check",
            status,
        }),
    }
}
